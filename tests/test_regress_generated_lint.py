"""Regression tests: generated modules that fail ruff E,F,W,I."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from al2py import convert

RUFF = Path(sys.executable).with_name("ruff")


def _ruff(code, tmp_path):
    (tmp_path / "m.py").write_text(code)
    return subprocess.run(
        [
            str(RUFF),
            "check",
            "--isolated",
            "--select",
            "E,F,W,I",
            "--output-format",
            "concise",
            "m.py",
        ],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )


@pytest.mark.parametrize(
    "src",
    [
        "Constants A\nE = A*T\n",  # I001: from al2py_runtime import t, Workspace
        "Constants O, I, l\nE = O + I + l\n",  # E741 x3, F811 (I vs sympy.I)
    ],
)
def test_snippet_ruff_clean(src, tmp_path):
    run = _ruff(convert(src, str(tmp_path / "s.al")).code, tmp_path)
    assert run.returncode == 0, run.stdout
