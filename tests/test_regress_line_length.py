"""Regression tests: long Autolev lines make the module fail ruff E501."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from al2py import convert


def test_long_source_line_is_lint_clean(tmp_path):
    src = (
        "Constants A\n"
        "E = A + 1  % this is a rather long comment that goes on and on and on and on past the line limit of black\n"
    )
    code = convert(src, str(tmp_path / "long.al")).code
    (tmp_path / "long.py").write_text(code)
    ruff = Path(sys.executable).with_name("ruff")
    run = subprocess.run(
        [str(ruff), "check", "--isolated", "--select", "E,F,W,I", "long.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stdout
