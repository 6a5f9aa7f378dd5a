"""The converter imports no sympy, numpy or scipy (issue 35).

Converting a script reads the runtime's tables (the vocabulary, the CODE
options, the settings...) but evaluates nothing, so ``al2py x.al -o x.py``,
``al2py check``'s conversion and ``al2py code``'s conversion start without
the 0.4 s that sympy takes to import.  Each check runs in a fresh
interpreter, since this test process has imported sympy long ago.
"""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

TUTOR6 = Path(__file__).parents[1] / "examples" / "tutor6.al"
HEAVY = ("sympy", "numpy", "scipy", "mpmath")

_REPORT = (
    "import json, sys\n"
    "print(json.dumps([m for m in {heavy!r} if m in sys.modules]))\n"
)


def _fresh(code: str, tmp_path: Path) -> str:
    """What ``code`` prints, run in a fresh interpreter in ``tmp_path``
    (it must succeed)."""
    proc = subprocess.run(
        [sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=120,
    )
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def _loaded(program: str, tmp_path: Path) -> list[str]:
    """The heavy modules loaded once ``program`` has run, in a fresh
    interpreter in ``tmp_path``."""
    out = _fresh(program + _REPORT.format(heavy=HEAVY), tmp_path)
    return json.loads(out.splitlines()[-1])


def test_convert_imports_no_sympy(tmp_path):
    program = (
        "from al2py import convert\n"
        f"code = convert(open({str(TUTOR6)!r}).read(), 'tutor6.al').code\n"
        "assert 'al.model.kane' in code or 'kanes_method' in code, code[:200]\n"
    )
    assert _loaded(program, tmp_path) == []


@pytest.mark.parametrize("command", [["-o", "tutor6.py"], ["check"]])
def test_the_command_line_converts_without_sympy(tmp_path, command):
    """``al2py tutor6.al -o tutor6.py`` and ``al2py check tutor6.al`` (no
    transcript beside it: conversion only)."""
    (tmp_path / "tutor6.al").write_text(TUTOR6.read_text())
    argv = ["check", "tutor6.al"] if command == ["check"] else ["tutor6.al", *command]
    program = (
        "import contextlib, io\n"
        "from al2py.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        f"    assert main({argv!r}) == 0\n"
    )
    assert _loaded(program, tmp_path) == []
    if command != ["check"]:
        assert "def " in (tmp_path / "tutor6.py").read_text()


def test_code_export_writes_its_programs_without_numpy(tmp_path):
    """``al2py code`` derives and prints (sympy), but never evaluates: the
    0.2 s numpy takes to import is not on its way (issue 35), neither in
    the process that derives nor in the copies that write the programs
    (the same imports in one process, ``-j 1``)."""
    (tmp_path / "tutor6.al").write_text(TUTOR6.read_text())
    program = (
        "import contextlib, io\n"
        "from al2py.codegen_c import main\n"
        "with contextlib.redirect_stdout(io.StringIO()):\n"
        "    assert main(['tutor6.al', '-j', '1']) == 0\n"
    )
    loaded = _loaded(program, tmp_path)
    assert "sympy" in loaded and "numpy" not in loaded, loaded
    assert (tmp_path / "tutor6.c").read_text().count("main") >= 1


def test_the_runtime_exports_its_names_on_first_use(tmp_path):
    """``import al2py_runtime`` alone loads no sympy; its exported names are
    all there (``dir``, ``__all__``) and import the workspace when used."""
    program = (
        "import al2py_runtime\n"
        "names = set(dir(al2py_runtime))\n"
        "assert set(al2py_runtime.__all__) <= names, names\n"
    )
    assert _loaded(program, tmp_path) == []
    program = (
        "from al2py_runtime import Workspace, dynamicsymbols, t\n"
        "import al2py_runtime, sympy\n"
        "for name in al2py_runtime.__all__:\n"
        "    getattr(al2py_runtime, name)\n"
        "assert isinstance(t, sympy.Symbol) and Workspace.__name__ == 'Workspace'\n"
        "assert dynamicsymbols('q').diff(t).has(t)\n"
        "try:\n"
        "    al2py_runtime.nothing\n"
        "except AttributeError:\n"
        "    pass\n"
        "else:\n"
        "    raise SystemExit('no AttributeError')\n"
    )
    assert "sympy" in _loaded(program, tmp_path)


#: the runtime's parts a program may import first, each in a fresh interpreter
#: (the package exports lazily, so no module may rely on another having been
#: imported before it: ``codegen`` first once met a cycle through ``autoz``)
FIRST_IMPORTS = [
    "al2py_runtime.codegen",
    "al2py_runtime.jobs.run",
    "al2py_runtime.intermediates.autoz",
    "al2py_runtime.model",
    "al2py_runtime.linear",
    "al2py_runtime.names.printing",
    "al2py_runtime.matrices",
    "al2py_runtime.workspace",
]


@pytest.mark.parametrize("module", FIRST_IMPORTS)
def test_each_part_of_the_runtime_imports_first(module, tmp_path):
    _fresh(f"import {module}", tmp_path)
