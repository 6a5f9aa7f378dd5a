"""Issue 12: the ``al2py`` command never damages files, never shows a
traceback and starts quickly (items 1, 3, 7, 12 and the ``-o`` name rule)."""

from __future__ import annotations

import doctest
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import al2py
from al2py import batch, cli

SCRIPT = "Constants A, B\nE = (A + B)^2\nF = Expand(E)\n"


def run_cli(*args: str, cwd: Path, **kw):
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=300,
        **kw,
    )


# ------------------------------------------------- item 1: special targets


def test_output_onto_a_named_pipe_is_refused(tmp_path):
    (tmp_path / "x.al").write_text(SCRIPT)
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    run = run_cli("x.al", "-o", "pipe", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stderr.strip() == (
        "al2py: error: cannot write pipe: it exists and is not a regular file "
        "(use '-o -' for standard output)"
    )
    assert fifo.is_fifo()  # still a pipe, not an ordinary file
    assert {p.name for p in tmp_path.iterdir()} == {"x.al", "pipe"}


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
def test_output_onto_a_device_is_refused(tmp_path):
    (tmp_path / "x.al").write_text(SCRIPT)
    before = os.stat("/dev/full")
    run = run_cli("x.al", "-o", "/dev/full", cwd=tmp_path)
    assert run.returncode == 2
    assert "not a regular file" in run.stderr
    assert "Traceback" not in run.stderr
    after = os.stat("/dev/full")
    assert after.st_rdev == before.st_rdev and after.st_ino == before.st_ino


def test_write_atomically_refuses_a_special_file(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    with pytest.raises(OSError, match="not a regular file"):
        batch.write_atomically(fifo, "x = 1\n")
    assert fifo.is_fifo()


def test_dash_output_is_standard_output(tmp_path):
    (tmp_path / "x.al").write_text(SCRIPT)
    run = run_cli("x.al", "-o", "-", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith('"""Autolev script x.al')
    assert not (tmp_path / "-").exists()


# ----------------------------------------- item 16: importable output names


def test_output_name_that_cannot_be_imported_is_refused(tmp_path):
    (tmp_path / "x.al").write_text(SCRIPT)
    run = run_cli("x.al", "-o", "x.al.py", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stderr.strip() == (
        "al2py: error: cannot write x.al.py: 'x.al' is not a Python identifier, "
        "so 'import x.al' cannot load it; name the output x_al.py"
    )
    assert not (tmp_path / "x.al.py").exists()
    ok = run_cli("x.al", "-o", "x_al.py", cwd=tmp_path)
    assert ok.returncode == 0, ok.stderr
    imported = subprocess.run(
        [sys.executable, "-c", "import x_al; print(x_al.AUTOLEV['F'])"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert imported.stdout.strip() == "A**2 + 2*A*B + B**2", imported.stderr


# ------------------------------------------------- item 3: temporary files


def test_stale_temp_files_of_dead_processes_are_removed(tmp_path):
    (tmp_path / "x.al").write_text(SCRIPT)
    dead = subprocess.run(
        [sys.executable, "-c", "import os; print(os.getpid())"],
        capture_output=True,
        text=True,
    )
    dead_pid = int(dead.stdout)  # that process has exited
    stale = tmp_path / f".x.py.{dead_pid}.abc123.tmp"
    stale.write_text("partial")
    old_style = tmp_path / ".x.py.q1w2e3r4.tmp"  # no process id: old once aged
    old_style.write_text("partial")
    past = time.time() - 2 * batch.STALE_AFTER
    os.utime(old_style, (past, past))
    live = tmp_path / f".x.py.{os.getpid()}.zzz999.tmp"  # a live writer's file
    live.write_text("in progress")
    other = tmp_path / ".y.py.1.abc.tmp"  # another target's: not ours to touch
    other.write_text("x")
    run = run_cli("x.al", "-o", "x.py", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert not stale.exists() and not old_style.exists()
    assert live.exists() and other.exists()
    assert (tmp_path / "x.py").read_text().startswith('"""Autolev script x.al')


def test_sigterm_during_write_removes_the_temp_file(tmp_path, monkeypatch, capsys):
    """A conversion terminated mid-write leaves neither a temp file nor a
    partial target."""
    (tmp_path / "x.al").write_text(SCRIPT)
    monkeypatch.chdir(tmp_path)
    real_fdopen = os.fdopen

    class SlowFile:
        def __init__(self, f):
            self.f = f

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.f.close()

        def write(self, text):
            self.f.write(text[:10])
            os.kill(os.getpid(), signal.SIGTERM)  # killed mid-write
            self.f.write(text[10:])

    monkeypatch.setattr(
        batch.os, "fdopen", lambda *a, **k: SlowFile(real_fdopen(*a, **k))
    )
    status = cli.main(["x.al", "-o", "x.py"])
    err = capsys.readouterr().err
    assert status == 128 + signal.SIGTERM
    assert err.strip() == "al2py: terminated"
    assert {p.name for p in tmp_path.iterdir()} == {"x.al"}
    assert signal.getsignal(signal.SIGTERM) is signal.SIG_DFL


# ------------------------------------------------------ item 7: broken pipe


def test_output_into_a_closed_pipe_exits_quietly(tmp_path):
    big = "Constants A\n" + "".join(f"E{i} = A^{i}\n" for i in range(1, 400))
    (tmp_path / "big.al").write_text(big)
    proc = subprocess.Popen(
        [sys.executable, "-m", "al2py", "big.al"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    first = proc.stdout.readline()
    proc.stdout.close()  # like `| head -1`
    err = proc.stderr.read().decode()
    proc.wait(timeout=120)
    assert first.startswith(b'"""Autolev script big.al')
    assert "Traceback" not in err and "BrokenPipe" not in err
    assert proc.returncode == 0


# ------------------------------------------------------- item 12: start-up


def test_version_and_help_do_not_import_sympy(tmp_path):
    code = (
        "import sys; from al2py import cli\n"
        "for argv in (['--version'], ['--help'], ['check', '--help']):\n"
        "    try: cli.main(argv)\n"
        "    except SystemExit: pass\n"
        "heavy = sorted(m for m in ('sympy', 'black', 'jinja2', 'numpy', 'antlr4',"
        " 'al2py.transpile') if m in sys.modules)\n"
        # the version is the runtime's (al2py_runtime/version.py): its package
        # and that module, nothing else of the runtime
        "heavy += sorted(m for m in sys.modules if m.startswith('al2py_runtime.')"
        " and m != 'al2py_runtime.version')\n"
        "print('HEAVY', heavy, file=sys.stderr)\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path
    )
    assert "HEAVY []" in run.stderr, run.stderr


def test_lazy_package_attributes_still_work():
    from al2py import AutolevError, Conversion, InternalError, convert

    assert al2py.convert is convert
    assert issubclass(AutolevError, Exception) and issubclass(InternalError, Exception)
    assert isinstance(convert("Constants A\nE = A+A\n", "e.al"), Conversion)
    with pytest.raises(AttributeError):
        al2py.no_such_thing  # noqa: B018


def test_package_doctest_passes():
    """Item 16: the package's own doctest (it failed on the quote style)."""
    failures, tried = doctest.testmod(al2py, verbose=False)
    assert tried >= 3 and failures == 0
