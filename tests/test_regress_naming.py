"""Regression tests: Autolev names that shadow imported runtime functions."""

from __future__ import annotations

import subprocess
import sys

import pytest

from al2py import convert

CASES = {
    "assigned_cos": "cos = 4\nE = cos(0)\n",
    "assigned_exp": "Constants A\nexp = 4\nE = Exp(A)\n",
    "constant_sin": "Constants sin\nE = Sin(sin)\n",
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_name_spelled_like_runtime_function(name, tmp_path):
    code = convert(CASES[name], str(tmp_path / "n.al")).code
    (tmp_path / "n.py").write_text(code)
    run = subprocess.run(
        [sys.executable, "-c", "import n; print(n.AUTOLEV['E'])"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
