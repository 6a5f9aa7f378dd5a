"""Generated modules are clean Python: black-formatted, lint-free, silent on import.

Each tutorial script and golden case either converts into such a module, or
stops with an ``AutolevError`` that says "not supported yet" (for parts of
the language still being built).
"""

from __future__ import annotations

import os
import subprocess
import sys
from functools import cache
from pathlib import Path

import black
import pytest
from conftest import GOLDEN, SHARED

from al2py import convert
from al2py.errors import AutolevError

RUFF = Path(sys.executable).with_name("ruff")

SCRIPTS = sorted(SHARED.glob("*.al")) + sorted(GOLDEN.glob("*.al"))
# (the assembled tutorial folder's name is a fresh temporary one: the ids
# name it "tutorial", so that every process collects the same tests)
IDS = [
    f"{'tutorial' if p.parent == SHARED else p.parent.name}/{p.name}" for p in SCRIPTS
]

# Scripts whose transcript ``python mod.py`` prints (no CODE jobs to run).
GOLDEN_SCRIPTS = sorted(GOLDEN.glob("*.al"))


@cache
def _convert(path: Path):
    """The module source for ``path``, or the AutolevError it raises."""
    try:
        return convert(path.read_text(encoding="utf-8"), str(path))
    except AutolevError as exc:
        return exc


def _converted_or_skip_unsupported(path: Path):
    """The conversion of ``path``; every tutorial and golden script converts."""
    result = _convert(path)
    assert not isinstance(result, AutolevError), str(result)
    return result


def test_there_are_scripts():
    assert len(SCRIPTS) >= 20
    failed = [p.name for p in SCRIPTS if isinstance(_convert(p), AutolevError)]
    # every script of the tutorial (mathematics, physics, CODE jobs) converts
    assert failed == []


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_converts_and_compiles(path):
    result = _convert(path)
    assert not isinstance(result, AutolevError), str(result)
    assert result.module == path.stem
    compile(result.code, str(path), "exec")


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_black_leaves_it_unchanged(path):
    code = _converted_or_skip_unsupported(path).code
    assert black.format_str(code, mode=black.Mode()) == code


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_black_check_command(path, tmp_path):
    code = _converted_or_skip_unsupported(path).code
    target = tmp_path / f"{path.stem}.py"
    target.write_text(code)
    run = subprocess.run(
        [sys.executable, "-m", "black", "--check", "--quiet", str(target)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_ruff_finds_nothing(path, tmp_path):
    code = _converted_or_skip_unsupported(path).code
    target = tmp_path / f"{path.stem}.py"
    target.write_text(code)
    ruff = [str(RUFF)] if RUFF.exists() else [sys.executable, "-m", "ruff"]
    run = subprocess.run(
        [*ruff, "check", "--isolated", "--select", "E,F,W,I", str(target)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout + run.stderr


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_import_is_silent_and_warning_free(path, tmp_path):
    result = _converted_or_skip_unsupported(path)
    (tmp_path / f"{result.module}.py").write_text(result.code)
    run = subprocess.run(
        [sys.executable, "-W", "error", "-c", f"import {result.module}"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout == ""
    assert run.stderr == ""
    # importing writes no file (Save only acts under 'python module.py')
    assert {p.name for p in tmp_path.iterdir() if p.name != "__pycache__"} == {
        f"{result.module}.py"
    }


@pytest.mark.parametrize("path", SCRIPTS, ids=IDS)
def test_conversion_is_deterministic(path):
    first = _converted_or_skip_unsupported(path).code
    again = convert(path.read_text(encoding="utf-8"), str(path)).code
    assert again == first


def test_deterministic_across_processes(tmp_path):
    """Hash randomisation must not change the output (set/dict ordering)."""
    path = GOLDEN / "tutor1.al"
    outputs = set()
    for seed in ("0", "1", "12345"):
        run = subprocess.run(
            [sys.executable, "-m", "al2py", str(path)],
            capture_output=True,
            text=True,
            cwd=tmp_path,
            timeout=300,
            env={**os.environ, "PYTHONHASHSEED": seed},
        )
        assert run.returncode == 0, run.stderr
        outputs.add(run.stdout)
    assert len(outputs) == 1


@pytest.mark.parametrize("path", GOLDEN_SCRIPTS, ids=lambda p: p.name)
def test_module_runs_as_a_script(path, tmp_path):
    """``python mod.py`` prints a numbered transcript and exits 0."""
    result = _converted_or_skip_unsupported(path)
    (tmp_path / f"{result.module}.py").write_text(result.code)
    run = subprocess.run(
        [sys.executable, "-W", "error", f"{result.module}.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert run.stderr == ""
    lines = run.stdout.splitlines()
    assert lines and lines[0].startswith("(1) ")
    assert any(line.startswith("-> (") for line in lines)


def test_import_leaves_the_process_as_it_found_it(tmp_path):
    """While a module derives, each statement pauses the garbage collector
    and then moves what it made out of the collector's sight (``gc.freeze``,
    as the end of the import does); the collector is left running at the
    thresholds it had, also when the import fails in a statement or outside
    one, and a statement that fails gives back what was frozen, so that the
    failed model is collected.  sympy's cache is left as the derivation
    leaves it, as after any sympy work: emptying it freed its expressions
    one by one (a third of a second of DAS3's import) and gave back no
    memory (docs/performance.md)."""
    result = _converted_or_skip_unsupported(SHARED / "tutor6.al")
    (tmp_path / f"{result.module}.py").write_text(result.code)
    broken = result.code.replace("al.names()", "1 / 0\nal.names()", 1)
    assert broken != result.code
    (tmp_path / "broken.py").write_text(broken)
    # a statement that fails (Solve: more equations than unknowns)
    script = tmp_path / "failing.al"
    script.write_text(
        "Variables X, Y\nZ = [X + Y - 1; X - Y; X + 2*Y]\nSolve(Z, X, Y)\n"
    )
    (tmp_path / "failing.py").write_text(_converted_or_skip_unsupported(script).code)
    probe = f"""
import gc
gc.set_threshold(900, 11, 12)
import {result.module}
assert gc.get_threshold() == (900, 11, 12), gc.get_threshold()
assert gc.isenabled()
assert gc.get_freeze_count() > 1000, gc.get_freeze_count()
try:
    import failing
except ValueError as exc:
    assert exc.line == 3, exc
else:
    raise AssertionError("failing imported")
assert gc.isenabled() and gc.get_threshold() == (900, 11, 12)
assert gc.get_freeze_count() == 0, gc.get_freeze_count()
try:
    import broken
except ZeroDivisionError:
    pass
assert gc.isenabled() and gc.get_threshold() == (900, 11, 12)
print("ok")
"""
    run = subprocess.run(
        [sys.executable, "-c", probe],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.stdout == "ok\n", run.stderr
