"""Acceptance tests for the ``al2py`` command line (README "Quickstart").

The command is exercised both as a real process (``python -m al2py``) and
in-process through :func:`al2py.cli.main`.
"""

from __future__ import annotations

import io
import os
import re
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import al2py
from al2py import cli

SCRIPT = "Constants A, B\nE = (A + B)^2\nF = Expand(E)\n"
BAD_SCRIPT = "Constants A\nE = A + Q\n"  # Q is undeclared
ERROR_LINE = re.compile(r"^[^\n]+:\d+:\d+: error: ")


def run_cli(*args: str, cwd: Path, stdin: str | None = None):
    """Run the real ``al2py`` command; return the CompletedProcess."""
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        input=stdin,
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=300,
    )


def run_main(argv, capsys, monkeypatch, stdin: str | None = None):
    """Run ``al2py.cli.main`` in-process: (status, stdout, stderr)."""
    if stdin is not None:
        monkeypatch.setattr(sys, "stdin", io.StringIO(stdin))
    try:
        status = cli.main(list(argv))
    except SystemExit as exc:  # argparse: --help, --version, usage errors
        status = exc.code
    out, err = capsys.readouterr()
    return status, out, err


def files_in(directory: Path) -> set[str]:
    return {p.name for p in directory.iterdir()}


def assert_module_text(code: str) -> None:
    """``code`` is a generated module: it compiles and keeps the contract."""
    compile(code, "<generated>", "exec")
    assert code.startswith('"""Autolev script ')
    assert "\nAUTOLEV = " in code
    assert "\nAL_SOURCE = " not in code  # the # al> lines are the source
    assert 'if __name__ == "__main__":' in code


# ------------------------------------------------------------ help/version


def test_help_subprocess(tmp_path):
    run = run_cli("--help", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert "usage: al2py" in run.stdout
    assert "-o" in run.stdout and "--version" in run.stdout
    assert run.stderr == ""


def test_version_subprocess(tmp_path):
    run = run_cli("--version", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == f"al2py {al2py.__version__}"


def test_help_and_version_in_process(capsys, monkeypatch):
    status, out, _ = run_main(["--help"], capsys, monkeypatch)
    assert status == 0
    assert "usage: al2py" in out
    status, out, _ = run_main(["--version"], capsys, monkeypatch)
    assert status == 0
    assert out.strip() == f"al2py {al2py.__version__}"


def test_no_arguments_is_a_usage_error(capsys, monkeypatch):
    status, out, err = run_main([], capsys, monkeypatch)
    assert status == 2
    assert "usage: al2py" in err
    assert "Traceback" not in out + err


# ------------------------------------------------------------- conversion


def test_convert_to_output_file_subprocess(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    run = run_cli("X.al", "-o", "X.py", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert run.stdout == "" and run.stderr == ""
    code = (tmp_path / "X.py").read_text()
    assert_module_text(code)
    assert files_in(tmp_path) == {"X.al", "X.py"}
    # the module works: importing it gives the values
    check = subprocess.run(
        [sys.executable, "-c", "import X; print(X.AUTOLEV['F'])"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert check.returncode == 0, check.stderr
    assert check.stdout.replace(" ", "").strip() in {
        "A**2+2*A*B+B**2",
        "A**2+B**2+2*A*B",
    }


def test_convert_to_output_file_in_process(tmp_path, capsys, monkeypatch):
    src = tmp_path / "X.al"
    src.write_text(SCRIPT)
    out_path = tmp_path / "X.py"
    status, out, err = run_main([str(src), "-o", str(out_path)], capsys, monkeypatch)
    assert status == 0, err
    assert out == "" and err == ""
    assert_module_text(out_path.read_text())


def test_long_option_and_dash_output_mean_stdout(tmp_path, capsys, monkeypatch):
    src = tmp_path / "X.al"
    src.write_text(SCRIPT)
    status, out, err = run_main([str(src), "--output", "-"], capsys, monkeypatch)
    assert status == 0, err
    assert_module_text(out)
    assert files_in(tmp_path) == {"X.al"}


def test_stdin_to_stdout_subprocess(tmp_path):
    run = run_cli("-", cwd=tmp_path, stdin=SCRIPT)
    assert run.returncode == 0, run.stderr
    assert_module_text(run.stdout)
    assert run.stderr == ""
    assert files_in(tmp_path) == set()


def test_stdin_to_stdout_in_process(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(["-"], capsys, monkeypatch, stdin=SCRIPT)
    assert status == 0, err
    assert_module_text(out)
    assert err == ""


def test_stdin_error_names_stdin(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(["-"], capsys, monkeypatch, stdin=BAD_SCRIPT)
    assert status == 2
    assert out == ""
    assert err.splitlines()[0] == "<stdin>:2:9: error: undeclared name 'Q'"


def test_without_output_prints_to_stdout(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    run = run_cli("X.al", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert_module_text(run.stdout)
    assert files_in(tmp_path) == {"X.al"}


def test_stdout_equals_file_output(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    to_stdout = run_cli("X.al", cwd=tmp_path)
    to_file = run_cli("X.al", "-o", "X.py", cwd=tmp_path)
    assert to_stdout.returncode == to_file.returncode == 0
    assert (tmp_path / "X.py").read_text() == to_stdout.stdout


def test_output_to_subdirectory(tmp_path, capsys, monkeypatch):
    (tmp_path / "X.al").write_text(SCRIPT)
    (tmp_path / "out").mkdir()
    monkeypatch.chdir(tmp_path)
    status, _, err = run_main(["X.al", "-o", "out/X.py"], capsys, monkeypatch)
    assert status == 0, err
    assert_module_text((tmp_path / "out" / "X.py").read_text())
    assert files_in(tmp_path / "out") == {"X.py"}


def test_overwrites_existing_output(tmp_path, capsys, monkeypatch):
    (tmp_path / "X.al").write_text(SCRIPT)
    (tmp_path / "X.py").write_text("old contents\n")
    monkeypatch.chdir(tmp_path)
    status, _, err = run_main(["X.al", "-o", "X.py"], capsys, monkeypatch)
    assert status == 0, err
    assert_module_text((tmp_path / "X.py").read_text())
    assert files_in(tmp_path) == {"X.al", "X.py"}


# ----------------------------------------------------- refusing the input


@pytest.mark.parametrize("target", ["X.al", "./X.al", "{tmp}/X.al", "link.al"])
def test_output_onto_input_is_refused(tmp_path, target):
    src = tmp_path / "X.al"
    src.write_text(SCRIPT)
    (tmp_path / "link.al").symlink_to("X.al")
    before = src.read_bytes()
    run = run_cli("X.al", "-o", target.format(tmp=tmp_path), cwd=tmp_path)
    assert run.returncode == 2
    assert run.stdout == ""
    assert "Traceback" not in run.stderr
    assert "input" in run.stderr
    assert src.read_bytes() == before
    assert files_in(tmp_path) == {"X.al", "link.al"}


def test_output_onto_input_refused_in_process(tmp_path, capsys, monkeypatch):
    src = tmp_path / "X.al"
    src.write_text(SCRIPT)
    before = src.read_bytes()
    status, out, err = run_main([str(src), "-o", str(src)], capsys, monkeypatch)
    assert status == 2
    assert out == ""
    assert len(err.strip().splitlines()) == 1
    assert src.read_bytes() == before


# ------------------------------------------------------------- atomicity


def test_failed_conversion_leaves_existing_target_unchanged(tmp_path):
    (tmp_path / "bad.al").write_text(BAD_SCRIPT)
    (tmp_path / "bad.py").write_text("# previous module\n")
    run = run_cli("bad.al", "-o", "bad.py", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr.splitlines()[0] == "bad.al:2:9: error: undeclared name 'Q'"
    assert (tmp_path / "bad.py").read_text() == "# previous module\n"
    assert files_in(tmp_path) == {"bad.al", "bad.py"}


def test_failed_conversion_creates_no_target(tmp_path, capsys, monkeypatch):
    (tmp_path / "bad.al").write_text("Constants A\nE = A*Foo(A)\n")
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(["bad.al", "-o", "bad.py"], capsys, monkeypatch)
    assert status == 2
    assert out == ""
    assert err.splitlines()[0] == (
        "bad.al:2:7: error: unknown function or command 'Foo' (did you mean Floor?)"
    )
    assert files_in(tmp_path) == {"bad.al"}


def test_failure_during_write_leaves_no_partial_file(tmp_path, capsys, monkeypatch):
    """If the final rename fails, the old target survives and no temp file stays."""
    (tmp_path / "X.al").write_text(SCRIPT)
    (tmp_path / "X.py").write_text("# previous module\n")

    def broken_replace(src, dst):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(cli.os, "replace", broken_replace)
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(["X.al", "-o", "X.py"], capsys, monkeypatch)
    assert status != 0
    assert "Traceback" not in out + err
    assert (tmp_path / "X.py").read_text() == "# previous module\n"
    assert files_in(tmp_path) == {"X.al", "X.py"}


def test_success_leaves_no_temp_files(tmp_path):
    (tmp_path / "X.al").write_text(SCRIPT)
    for _ in range(2):
        run = run_cli("X.al", "-o", "X.py", cwd=tmp_path)
        assert run.returncode == 0, run.stderr
    assert files_in(tmp_path) == {"X.al", "X.py"}


@pytest.mark.parametrize("umask", [0o022, 0o002])
def test_output_permissions_follow_umask(tmp_path, umask):
    (tmp_path / "X.al").write_text(SCRIPT)
    old = os.umask(umask)
    try:
        run = run_cli("X.al", "-o", "X.py", cwd=tmp_path)
    finally:
        os.umask(old)
    assert run.returncode == 0, run.stderr
    mode = stat.S_IMODE((tmp_path / "X.py").stat().st_mode)
    assert mode == 0o666 & ~umask
    assert mode != 0o600


# ----------------------------------------------------------- bad input


def test_missing_input_file_subprocess(tmp_path):
    run = run_cli("nothere.al", "-o", "nothere.py", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stdout == ""
    lines = run.stderr.splitlines()
    assert len(lines) == 1, run.stderr
    assert lines[0].startswith("al2py: error:")
    assert "nothere.al" in lines[0]
    assert "Traceback" not in run.stderr
    assert files_in(tmp_path) == set()


def test_missing_input_file_in_process(tmp_path, capsys, monkeypatch):
    missing = tmp_path / "nothere.al"
    status, out, err = run_main([str(missing)], capsys, monkeypatch)
    assert status == 2
    assert out == ""
    assert len(err.splitlines()) == 1
    assert "nothere.al" in err


def test_input_is_a_directory(tmp_path, capsys, monkeypatch):
    status, out, err = run_main([str(tmp_path)], capsys, monkeypatch)
    assert status == 2
    assert out == ""
    assert len(err.splitlines()) == 1
    assert err.startswith("al2py: error:")


def test_input_error_format_subprocess(tmp_path):
    (tmp_path / "bad.al").write_text(BAD_SCRIPT)
    run = run_cli("bad.al", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr.splitlines() == [
        "bad.al:2:9: error: undeclared name 'Q'",
        "    E = A + Q",
        "            ^",
    ]


def test_non_utf8_input_file_is_accepted(tmp_path, capsys, monkeypatch):
    """A Latin-1 byte in a comment does not crash the converter."""
    (tmp_path / "lat.al").write_bytes(b"Constants A\nE = A + 1 % caf\xe9\n")
    monkeypatch.chdir(tmp_path)
    status, out, err = run_main(["lat.al", "-o", "lat.py"], capsys, monkeypatch)
    assert status in (0, 2), err
    assert "internal error" not in err
    if status == 0:
        compile((tmp_path / "lat.py").read_text(), "lat.py", "exec")
    else:
        assert ERROR_LINE.match(err)


# ------------------------------------------------------------ interruption


class _InterruptedImport:
    """A finder that interrupts the import of one module, as a Ctrl-C does
    while Python imports it."""

    def __init__(self, name: str) -> None:
        self.name = name

    def find_spec(self, fullname, path=None, target=None):
        if fullname == self.name:
            raise KeyboardInterrupt
        return None


@pytest.mark.parametrize(
    "argv, module",
    [
        (["code", "tutor6.al"], "al2py.codegen_c"),
        (["check", "models/"], "al2py.batch"),
    ],
)
def test_an_interrupt_while_the_command_imports_ends_it_quietly(
    argv, module, capsys, monkeypatch
):
    """Ctrl-C while the command's own modules load (before its work starts)
    gives the same message and status as one during its work, never a
    traceback."""
    monkeypatch.delitem(sys.modules, module, raising=False)
    monkeypatch.delattr(al2py, module.rsplit(".", 1)[1], raising=False)
    monkeypatch.setattr(sys, "meta_path", [_InterruptedImport(module), *sys.meta_path])
    status, out, err = run_main(argv, capsys, monkeypatch)
    assert (status, out, err) == (130, "", "al2py: interrupted\n")
