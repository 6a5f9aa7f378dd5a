"""``al2py code`` as its own process ends itself once its output is
flushed (:func:`al2py.codegen_c.end_process`): the same files, lines and
status as ``main`` called in-process, which returns."""

from __future__ import annotations

import subprocess
import sys

from conftest import ROOT

from al2py.cli import main as al2py_main

TUTOR6 = ROOT / "examples" / "tutor6.al"


def _process(*args: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        capture_output=True,  # pipes: the output is buffered until flushed
        text=True,
        cwd=cwd,
        timeout=600,
    )


def test_the_process_writes_what_main_writes(tmp_path, capsys):
    assert al2py_main(["code", str(TUTOR6), "-o", str(tmp_path / "a")]) == 0
    inprocess = capsys.readouterr().out
    done = _process("code", str(TUTOR6), "-o", "b", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout == inprocess.replace(str(tmp_path / "a"), "b")
    assert done.stdout.count("Wrote ") == 2
    written = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert written == ["tutor6.c", "tutor6.in"]
    for name in written:
        assert (tmp_path / "b" / name).read_bytes() == (
            tmp_path / "a" / name
        ).read_bytes()


def test_the_process_ends_with_main_s_status(tmp_path, capsys):
    (tmp_path / "none.al").write_text("constants a\nb = a + 1\n")
    assert al2py_main(["code", str(tmp_path / "none.al")]) == 2
    said = capsys.readouterr().err
    done = _process("code", "none.al", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr == said.replace(str(tmp_path / "none.al"), "none.al")
    assert "has no CODE statement" in done.stderr
