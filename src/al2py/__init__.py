"""al2py: convert Autolev (.al) scripts into readable Python modules.

>>> from al2py import convert
>>> code = convert("Constants A, B\\nX = 4*(A+B) - 3*(a-b)\\n", "intro.al").code
>>> 'al.assign("X"' in code
True

The transpiler (and sympy with it) is imported on first use of ``convert``,
and the version read on first use of ``__version__``, so ``al2py --version``
and ``--help`` start quickly.
"""

from __future__ import annotations

from typing import Any


def _version() -> str:
    """al2py's version, which is its runtime's: it is written once, in
    ``runtime/al2py_runtime/version.py``, and ``setup.py`` gives al2py the
    same version and pins al2py-runtime to it (``==``), so an install holds
    one number.  Read from there, not from the installed metadata:
    ``importlib.metadata`` and its search of the installed distributions
    cost each conversion about 0.07 s (112 M instructions)."""
    from al2py_runtime.version import __version__

    return __version__


__all__ = ["convert", "Conversion", "AutolevError", "InternalError", "__version__"]

_LAZY = {
    "convert": "transpile",
    "Conversion": "transpile",
    "AutolevError": "errors",
    "InternalError": "errors",
}


def __getattr__(name: str) -> Any:
    if name == "__version__":  # read from the metadata when first asked for
        globals()[name] = version = _version()
        return version
    module = _LAZY.get(name)
    if module is None:
        raise AttributeError(f"module 'al2py' has no attribute {name!r}")
    import importlib

    value = getattr(importlib.import_module(f"al2py.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
