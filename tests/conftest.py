"""Shared fixtures: convert an .al file and import the generated module."""

from __future__ import annotations

import importlib.util
import itertools
import sys
from pathlib import Path

import pytest

from al2py import convert

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "cases"
SHARED = ROOT.parent / "shared" / "tutorial"

_counter = itertools.count()


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
