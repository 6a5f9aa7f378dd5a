"""Shared fixtures: convert an .al file and import the generated module."""

from __future__ import annotations

import atexit
import importlib.util
import itertools
import shutil
import sys
import tempfile
from pathlib import Path

import pytest

from al2py import convert

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "cases"
#: The tutorial's own examples that no golden case holds (the rest are in
#: ``tests/golden/cases`` and ``examples/``).
TUTORIAL_EXAMPLES = ROOT / "tests" / "tutorial"
#: Where the workplace keeps the tutorial (not needed: see ``SHARED``).
SHARED_TUTORIAL = ROOT.parent / "shared" / "tutorial"


def _tutorial_files() -> dict[str, Path]:
    """The tutorial's example files, by name, from the project's own copies:
    its scripts, macro files and transcripts, as ``shared/tutorial`` holds
    them (``test_the_tutorial_copies_are_the_tutorials`` checks the copies
    against it when it is there)."""
    files = {p.name: p for p in TUTORIAL_EXAMPLES.glob("*.al")}
    for p in GOLDEN.iterdir():
        # a golden case's transcript and macros are the tutorial's; its .al
        # was rebuilt from the transcript, except tutor1's
        if p.suffix in {".all", ".a", ".r"} or p.name == "tutor1.al":
            files[p.name] = p
    files["tutor6.al"] = ROOT / "examples" / "tutor6.al"
    return files


def _assemble_tutorial() -> Path:
    folder = Path(tempfile.mkdtemp(prefix="al2py-tutorial-"))
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    for name, path in _tutorial_files().items():
        shutil.copyfile(path, folder / name)
    return folder


#: A folder laid out as the tutorial's (``shared/tutorial``), assembled from the
#: project's copies, so that the tests need nothing outside the checkout.
SHARED = _assemble_tutorial()

_counter = itertools.count()

_FULL = False


def pytest_addoption(parser):
    parser.addoption(
        "--full",
        action="store_true",
        default=False,
        help="also run the full tier (tests marked 'full', and the full sizes of "
        "the fuzz and determinism runs): make test-full",
    )


def pytest_configure(config):
    global _FULL
    _FULL = bool(config.getoption("--full", default=False))


def pytest_collection_modifyitems(config, items):
    if _FULL:
        return
    skip = pytest.mark.skip(reason="full tier: run with make test-full (pytest --full)")
    for item in items:
        if "full" in item.keywords:
            item.add_marker(skip)


def full_tier() -> bool:
    """Whether this run is the full tier (``pytest --full``, ``make test-full``):
    tests that scale read it at run time."""
    return _FULL


def tier_cases(n: int) -> int:
    """``n`` random cases in the full tier (``make test-full``), a third of
    them in ``make test``."""
    return n if _FULL else n // 3


def tier_step(step: int) -> int:
    """Every case (a step of 1) in the full tier, every ``step``-th in
    ``make test``."""
    return 1 if _FULL else step


def load_module(code: str, directory: Path, name: str):
    """Write ``code`` as ``name.py`` in ``directory`` and import it freshly."""
    path = directory / f"{name}.py"
    path.write_text(code, encoding="utf-8")
    unique = f"_al2py_test_{name}_{next(_counter)}"
    spec = importlib.util.spec_from_file_location(unique, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[unique] = module
    try:
        spec.loader.exec_module(module)
    finally:
        sys.modules.pop(unique, None)
    return module


@pytest.fixture
def convert_and_import(tmp_path):
    """``convert_and_import(path) -> (module, code)`` for a .al file."""

    def run(path: Path):
        result = convert(path.read_text(encoding="utf-8"), str(path))
        return load_module(result.code, tmp_path, result.module), result.code

    return run


_tutorial_modules: dict[str, object] = {}


@pytest.fixture
def tutorial(convert_and_import):
    """``tutorial("tutor6")``: the converted tutorial module, imported once per run."""

    def get(name: str):
        if name not in _tutorial_modules:
            _tutorial_modules[name], _ = convert_and_import(SHARED / f"{name}.al")
        return _tutorial_modules[name]

    return get
