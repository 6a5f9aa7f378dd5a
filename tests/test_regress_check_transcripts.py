"""``al2py check`` never passes a transcript it could not use (issue 32).

An empty ``.all``, 2,000 random bytes or mangled ``(n)`` numbers each
reported "passed 0/0" with exit 0; a transcript cut off mid-line passed
with no note.
"""

from __future__ import annotations

import random
import shutil
from pathlib import Path

import pytest

from al2py import batch, cli

GOLDEN = Path(__file__).resolve().parent / "golden" / "cases"


def _folder(tmp_path: Path, transcript: bytes) -> Path:
    folder = tmp_path / "lib"
    folder.mkdir()
    shutil.copy(GOLDEN / "tutor1.al", folder / "tutor1.al")
    (folder / "tutor1.all").write_bytes(transcript)
    return folder


def _reference() -> bytes:
    return (GOLDEN / "tutor1.all").read_bytes()


def _mangled() -> bytes:
    text = _reference().decode()
    return text.replace("(", "(#").encode()


BROKEN = {
    "empty": (lambda: b"", "is empty"),
    "random bytes": (
        lambda: random.Random(32).randbytes(2000),
        "not an Autolev transcript",
    ),
    "mangled numbers": (_mangled, "no numbered line"),
    "only input lines": (
        lambda: b"(1) Variables X', Y'\n(2) Constants A,B,C,D\n",
        "no response",
    ),
}


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_an_unusable_transcript_fails_the_check(name, tmp_path, capsys):
    make, words = BROKEN[name]
    folder = _folder(tmp_path, make())
    status = cli.main(["check", "-q", str(folder)])
    out = capsys.readouterr().out
    assert status == 2, out
    assert "passed" not in out.split("\n\n")[0], out
    assert "0 passed, 0 failed, 1 errored" in out
    assert words in out and "tutor1.all: error:" in out


def test_a_transcript_cut_off_mid_line_is_noted(tmp_path, capsys):
    text = _reference()
    cut = text[: text.index(b"-> (24)") + len(b"-> (24) F = 0.87")]
    folder = _folder(tmp_path, cut)
    status = cli.main(["check", "-q", str(folder)])
    out = capsys.readouterr().out
    table = out.split("\n\n")[0]
    assert status == 2  # F = 0.87 differs from 0.8775825
    assert "note: the transcript ends in the middle of a line" in table
    assert "note: the transcript ends early" in table
    assert "not compared in full" in out


def test_a_transcript_that_ends_early_is_noted_even_when_it_passes(tmp_path):
    text = _reference()
    cut = text[: text.index(b"(25) POLY")]  # after a complete line
    folder = _folder(tmp_path, cut)
    result = batch.check_file(folder / "tutor1.al")
    assert result.status == batch.PASSED, result.message
    assert result.total > 0
    assert len(result.notes) == 1
    assert "ends early" in result.notes[0] and "line 18" in result.notes[0]
    table = batch.format_table([result])
    assert "note: the transcript ends early" in table


def test_a_whole_transcript_passes_without_notes(tmp_path):
    result = batch.check_file(_folder(tmp_path, _reference()) / "tutor1.al")
    assert result.status == batch.PASSED, result.message
    assert result.total == 36 and result.notes == []


class _Ws:
    def __init__(self, lines):
        from al2py_runtime.names.settings import Response

        self.responses = [Response(n, "X", 1, 7) for n in lines]


def test_verdict_of_a_transcript_of_a_script_without_responses():
    from al2py.checking import parse_transcript, transcript_verdict

    text = "(1) Constants A\n"
    assert transcript_verdict(text, parse_transcript(text), _Ws([])) == ("", [])


def test_verdict_notes_numbers_that_go_back():
    from al2py.checking import parse_transcript, transcript_verdict

    text = "(1) X = 1\n-> (2) X = 1\n(1) X = 1\n-> (2) X = 1\n"
    source = ["X = 1", "X = 1"]
    error, notes = transcript_verdict(text, parse_transcript(text), _Ws([1, 2]), source)
    assert error == "" and len(notes) == 1 and "numbers go back" in notes[0]


def test_verdict_notes_response_lines_without_a_number():
    from al2py.checking import parse_transcript, transcript_verdict

    text = "(1) X = 1\n-> (2) X = 1\n(3) Y = 2\n-> (4x) Y = 2\n"
    source = ["X = 1", "Y = 2"]
    error, notes = transcript_verdict(text, parse_transcript(text), _Ws([1, 2]), source)
    assert error == "" and len(notes) == 1, notes
    assert "1 response line" in notes[0] and "line 4" in notes[0]
