"""Regression tests: al2py CLI bugs."""

from __future__ import annotations

import subprocess
import sys

SCRIPT = "Constants A\nE = A + 1\n"


def _run(args, cwd, stdin=None):
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        input=stdin,
        capture_output=True,
        cwd=cwd,
        timeout=300,
    )


def _assert_clean_input_error(run):
    err = run.stderr.decode("utf-8", "replace")
    assert run.returncode == 2, err
    assert "internal error" not in err
    assert "Traceback" not in err
    assert len(err.strip().splitlines()) == 1, err


def test_output_is_a_directory(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    (tmp_path / "outdir").mkdir()
    run = _run(["X.al", "-o", "outdir"], tmp_path)
    _assert_clean_input_error(run)
    assert {p.name for p in tmp_path.iterdir()} == {"X.al", "outdir"}


def test_output_directory_missing(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    run = _run(["X.al", "-o", "nodir/X.py"], tmp_path)
    _assert_clean_input_error(run)


def test_non_utf8_stdin(tmp_path):
    run = _run(["-"], tmp_path, stdin=b"Constants A\nE = A + 1 % caf\xe9\n")
    err = run.stderr.decode("utf-8", "replace")
    assert run.returncode in (0, 2), err
    assert "internal error" not in err
    if run.returncode == 0:
        compile(run.stdout, "<stdin>", "exec")
