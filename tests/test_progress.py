"""Progress on every long wait (issue 35): what is being done and how far
along, on standard error when it is a terminal, and nothing anywhere else.

The commands run under a pseudo-terminal (``os.openpty``) with
``AL2PY_PROGRESS_AFTER=0`` so that a quick wait shows its line too."""

from __future__ import annotations

import io
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from al2py_runtime import progress
from conftest import ROOT

from al2py import convert

TUTOR6 = ROOT / "examples" / "tutor6.al"
LIBRARY = ROOT / "tests" / "library"


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _run(cmd: list[str], cwd: Path, terminal: bool, env: dict | None = None):
    """Run ``cmd`` with standard error on a pseudo-terminal (or a pipe);
    returns (exit status, what standard error received)."""
    env = {**os.environ, "AL2PY_PROGRESS_AFTER": "0", **(env or {})}
    if not terminal:
        proc = subprocess.run(
            cmd,
            cwd=cwd,
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            text=True,
            timeout=600,
        )
        return proc.returncode, proc.stderr
    master, slave = os.openpty()
    proc = subprocess.Popen(
        cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=slave
    )
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:  # the other end closed
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    return proc.wait(timeout=600), b"".join(chunks).decode(errors="replace")


@pytest.fixture(scope="module")
def tutor6(tmp_path_factory):
    folder = tmp_path_factory.mktemp("tutor6")
    shutil.copy(TUTOR6, folder / "tutor6.al")
    code = convert(TUTOR6.read_text(), "tutor6.al").code
    (folder / "tutor6.py").write_text(code)
    return folder


# --------------------------------------------------------------- the module


def test_a_counted_task_shows_what_and_how_far_then_clears():
    stream = _Terminal()
    with progress.task("sweeping", total=4, unit="points", stream=stream) as p:
        p.advance(3)
        line = p.line()
    assert line.startswith("sweeping 3 of 4 points (75%), ")
    assert line.endswith(" s")
    p.doing("point 4")
    assert p.line().startswith("sweeping 3 of 4 points (75%): point 4, ")


def test_the_line_appears_after_the_wait_and_is_cleared(monkeypatch):
    monkeypatch.setattr(progress, "AFTER", 0.05)
    monkeypatch.setattr(progress, "EVERY", 0.02)
    stream = _Terminal()
    with progress.task("linearizing", total=2, stream=stream) as p:
        p.advance()
        time.sleep(0.3)
    shown = stream.getvalue()
    assert "\rlinearizing 1 of 2 (50%), 0 s" in shown
    assert shown.endswith("\r") and shown.rstrip("\r").endswith(" ")  # cleared


def test_a_quick_task_shows_nothing(monkeypatch):
    stream = _Terminal()
    with progress.task("quick", total=1, stream=stream) as p:
        p.advance()
    assert stream.getvalue() == ""


def test_no_line_when_not_a_terminal(monkeypatch):
    monkeypatch.setattr(progress, "AFTER", 0.0)
    monkeypatch.setattr(progress, "EVERY", 0.01)
    stream = io.StringIO()
    with progress.task("sweeping", total=2, stream=stream) as p:
        time.sleep(0.05)
        p.advance(2)
    progress.echo("a line", stream=stream)
    assert stream.getvalue() == "a line\n"


def test_nested_tasks_show_the_innermost_and_echo_clears_first(monkeypatch):
    monkeypatch.setattr(progress, "AFTER", 0.0)
    stream = _Terminal()
    with progress.task("outer", stream=stream):
        with progress.task("inner", stream=stream):
            progress.echo("a report", stream=stream)
    shown = stream.getvalue()
    assert "\router, 0 s" in shown and "\rinner, 0 s" in shown
    # the report starts on a cleared line, never after the progress text
    before = shown.split("a report\n")[0]
    assert before.endswith("\r") and before.split("\r")[-2].strip() == ""
    after = shown.split("a report\n")[1]
    assert after == "" or after.endswith("\r")  # nothing left on the screen


# ------------------------------------------------------------ the commands


@pytest.mark.parametrize("terminal", [True, False])
def test_converting_a_script(tmp_path, terminal):
    shutil.copy(TUTOR6, tmp_path / "tutor6.al")
    status, err = _run(
        [sys.executable, "-m", "al2py", "tutor6.al", "-o", "t6.py"],
        cwd=tmp_path,
        terminal=terminal,
    )
    assert status == 0
    assert (tmp_path / "t6.py").read_text() == convert(
        TUTOR6.read_text(), "tutor6.al"
    ).code
    if terminal:
        for k, step in enumerate(["parsing", "expanding", "analysing", "generating"]):
            assert f"\rconverting tutor6.al {k} of 5 steps ({20 * k}%): {step}," in err
        assert err.endswith("\r")  # cleared
    else:
        assert err == ""


@pytest.mark.parametrize("terminal", [True, False])
def test_printing_a_transcript(tutor6, terminal):
    status, err = _run(
        [sys.executable, "tutor6.py", "--no-run"], cwd=tutor6, terminal=terminal
    )
    assert status == 0
    if terminal:
        assert "\rprinting the transcript" in err
        assert err.endswith("\r")  # cleared
    else:
        assert err == ""


@pytest.mark.parametrize("terminal", [True, False])
def test_al2py_code(tutor6, terminal):
    out = tutor6 / f"code_{terminal}"
    status, err = _run(
        [sys.executable, "-m", "al2py", "code", "tutor6.al", "-o", str(out)],
        cwd=tutor6,
        terminal=terminal,
    )
    assert status == 0
    assert (out / "tutor6.c").exists()
    if terminal:
        assert "writing programs 0 of 1 (0%): tutor6.c (" in err
    else:
        assert err == ""


@pytest.mark.skipif(shutil.which("cc") is None, reason="needs a C compiler")
@pytest.mark.parametrize("terminal", [True, False])
def test_compiling(tutor6, tmp_path, terminal):
    env = {"AL2PY_BACKEND": "c", "XDG_CACHE_HOME": str(tmp_path / "cache")}
    status, err = _run(
        [sys.executable, "tutor6.py", "--outdir", str(tmp_path)],
        cwd=tutor6,
        terminal=terminal,
        env=env,
    )
    assert status == 0
    assert (tmp_path / "tutor6.1").exists()
    if terminal:
        assert "compiling the C code" in err
    else:
        assert "compiling" not in err


@pytest.mark.parametrize("terminal", [True, False])
def test_al2py_check(tmp_path, terminal):
    lib = tmp_path / "library"
    shutil.copytree(LIBRARY / "algebra", lib)
    status, err = _run(
        [sys.executable, "-m", "al2py", "check", "."], cwd=lib, terminal=terminal
    )
    assert status == 0
    n = len(list(lib.glob("*.al")))
    assert f"[{n}/{n}]" in err  # the report lines, as before
    if terminal:
        assert f"checking 0 of {n} scripts (0%)" in err
    else:
        assert "checking" not in err
