"""The committed ANTLR parser must match grammar/Autolev.g4."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from al2py import _grammar_stamp

ROOT = Path(__file__).resolve().parents[1]
GRAMMAR_DIR = ROOT / "grammar"
ANTLR_DIR = ROOT / "src" / "al2py" / "_antlr"


def _antlr_command() -> str | None:
    local = ROOT / ".venv" / "bin" / "antlr4"
    if local.is_file():
        return str(local)
    return shutil.which("antlr4")


def test_stamp_matches_grammar():
    assert _grammar_stamp.GRAMMAR_PATH == GRAMMAR_DIR / "Autolev.g4"
    assert _grammar_stamp.read_stamp() == _grammar_stamp.grammar_sha256()
    assert _grammar_stamp.is_fresh()
    assert _grammar_stamp.main(["--check"]) == 0


def test_stale_stamp_is_detected(tmp_path):
    grammar = tmp_path / "G.g4"
    stamp = tmp_path / "STAMP"
    grammar.write_text("grammar G;\n")
    _grammar_stamp.write_stamp(grammar, stamp)
    assert _grammar_stamp.is_fresh(grammar, stamp)
    grammar.write_text("grammar G; // edited\n")
    assert not _grammar_stamp.is_fresh(grammar, stamp)


def test_generated_parser_is_up_to_date(tmp_path):
    antlr = _antlr_command()
    if antlr is None or shutil.which("java") is None:
        pytest.skip("java or antlr4 is not installed")
    out = tmp_path / "gen"
    # Same command as `make grammar`, run from the grammar directory so the
    # "Generated from Autolev.g4" headers are identical.
    subprocess.run(
        [
            antlr,
            "-Dlanguage=Python3",
            "-visitor",
            "-no-listener",
            "-o",
            str(out),
            "-Xexact-output-dir",
            "Autolev.g4",
        ],
        cwd=GRAMMAR_DIR,
        check=True,
        capture_output=True,
        timeout=300,
    )
    generated = sorted(p.name for p in out.glob("*.py"))
    committed = sorted(
        p.name for p in ANTLR_DIR.glob("*.py") if p.name != "__init__.py"
    )
    assert generated == committed
    for name in generated:
        fresh = (out / name).read_text(encoding="utf-8")
        ours = (ANTLR_DIR / name).read_text(encoding="utf-8")
        assert fresh == ours, f"{name} is stale: run `make grammar`"
