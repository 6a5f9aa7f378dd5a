"""Never a silent wait: ``--help`` answers before deriving, and a long import
shows which statement it derives when standard error is a terminal."""

from __future__ import annotations

import io
import subprocess
import sys

import pytest
from conftest import SHARED, load_module

from al2py import convert

_PROBE = (
    "import runpy, sys\n"
    "sys.argv = [sys.argv[1], '--help']\n"
    "try:\n"
    "    runpy.run_path(sys.argv[0], run_name='__main__')\n"
    "except SystemExit as exc:\n"
    "    print('EXIT', exc.code, 'sympy' in sys.modules)\n"
)


def test_help_answers_before_sympy_loads(tmp_path):
    path = SHARED / "tutor6.al"
    module = tmp_path / "tutor6.py"
    module.write_text(convert(path.read_text(), str(path)).code)
    proc = subprocess.run(
        [sys.executable, "-c", _PROBE, str(module)],
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    help_text, last = proc.stdout.rsplit("\n", 2)[0], proc.stdout.splitlines()[-1]
    assert last == "EXIT 0 False"  # exit 0, and sympy was never imported
    assert help_text.startswith("usage: python tutor6.py [-h]")
    inputs = help_text.split("in these units):\n", 1)[1].split("Jobs (", 1)[0]
    assert "  QA = 20 deg  " in inputs  # the script's Input, as written
    assert "  tutor6: CODE Dynamics tutor6.c (line " in help_text
    assert proc.stderr == ""


def test_help_after_deriving_lists_the_same_options(tmp_path, capsys):
    path = SHARED / "tutor6.al"
    code = convert(path.read_text(), str(path)).code
    module = load_module(code, tmp_path, "tutor6")
    assert module.main(["--help"]) == 0
    derived = capsys.readouterr().out
    proc = subprocess.run(
        [sys.executable, str(tmp_path / "tutor6.py"), "--help"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    early = proc.stdout
    assert proc.returncode == 0
    option = [line.split()[0] for line in early.splitlines() if line[:4] == "  --"]
    assert option == [
        line.split()[0] for line in derived.splitlines() if line[:4] == "  --"
    ]
    assert "--zero-missing" in option and "--job" in option


class _Terminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def _slow_module(tmp_path):
    code = convert("Constants A\nB = A + 1\n", str(tmp_path / "slow.al")).code
    # a statement that takes a while (as a large Kane() would)
    code = code.replace(
        "# al> B = A + 1\n", "# al> B = A + 1\nimport time\ntime.sleep(0.6)\n"
    )
    assert "time.sleep" in code
    return code


@pytest.mark.parametrize("terminal", [True, False])
def test_long_import_names_the_statement_on_a_terminal_only(
    tmp_path, monkeypatch, terminal
):
    from al2py_runtime import progress

    stream = _Terminal() if terminal else io.StringIO()
    monkeypatch.setattr(sys, "stderr", stream)
    monkeypatch.setattr(progress, "AFTER", 0.1)
    monkeypatch.setattr(progress, "EVERY", 0.05)
    module = load_module(_slow_module(tmp_path), tmp_path, "slow")
    shown = stream.getvalue()
    if terminal:
        assert "slow.al: deriving B = A + 1 (" in shown
        assert shown.endswith("\r")  # the line is cleared when done
    else:
        assert shown == ""
    assert str(module.AUTOLEV["B"]) == "A + 1"
