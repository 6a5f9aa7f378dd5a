"""Only a line break ends a line, as Autolev read it (issue 32).

Python's ``str.splitlines()`` also breaks at a form feed, NEL (U+0085) and
U+2028: inside a ``%`` comment that ended the comment, so that the rest of
the line (``Constants HIDDEN``) became code, and the transcript numbered a
4-line script as 7 lines.
"""

from __future__ import annotations

import pytest
from al2py_runtime.safety import module_source
from conftest import load_module

from al2py import convert
from al2py.checking import parse_transcript
from al2py.errors import AutolevError
from al2py.lines import split_lines

BREAKS = {"form feed": "\x0c", "NEL": "\x85", "U+2028": "\u2028", "VT": "\x0b"}


def _script(char: str) -> str:
    return f"Constants A\n% note {char} Constants HIDDEN\nB = A + 1\nB = A + 2\n"


@pytest.mark.parametrize("name", sorted(BREAKS))
def test_a_comment_holding_a_break_character_stays_a_comment(name, tmp_path):
    text = _script(BREAKS[name])
    result = convert(text, "hidden.al")
    code_lines = [
        ln for ln in result.code.splitlines() if not ln.lstrip().startswith("#")
    ]
    assert [ln for ln in code_lines if "HIDDEN" in ln] == []  # only in the echo
    module = load_module(result.code, tmp_path, result.module)
    assert "HIDDEN" not in module.AUTOLEV
    transcript = module.al.transcript(module_source(module.__file__))
    # 4 input lines and 2 responses, numbered as Autolev did: 1 to 6
    assert [line.split(")")[0] for line in transcript] == [
        "(1",
        "(2",
        "(3",
        "-> (4",
        "(5",
        "-> (6",
    ]
    assert transcript[1] == f"(2) % note {BREAKS[name]} Constants HIDDEN"
    compile(result.code, "hidden.py", "exec")


def test_the_comment_echo_shows_the_character_as_a_blank():
    result = convert(_script("\u2028"), "hidden.al")
    assert "\u2028" not in result.code and "\x0c" not in result.code


@pytest.mark.parametrize("name", sorted(BREAKS))
def test_a_break_character_in_code_is_located_on_its_own_line(name):
    text = f"Constants A\nB = A {BREAKS[name]} Constants H2\nC = A +\n"
    with pytest.raises(AutolevError) as info:
        convert(text, "s.al")
    lines = [e.span.line for e in getattr(info.value, "errors", [info.value])]
    # the last statement is on line 3 of a 3-line script, not line 4
    assert max(lines) == 3, lines


def test_a_transcript_line_holding_a_form_feed_is_one_line():
    entries = parse_transcript("(1) % a\x0c(2) B = 1\n-> (3) B = 1\n")
    assert [(e.number, e.line) for e in entries] == [(1, 1), (3, 2)]


def test_split_lines_breaks_only_at_line_breaks():
    assert split_lines("a\r\nb\rc\nd\x0ce\x85f\u2028g\u2029h\n") == [
        "a",
        "b",
        "c",
        "d\x0ce\x85f\u2028g\u2029h",
    ]
    assert split_lines("") == [] and split_lines("\n") == [""]
    assert split_lines("a\n\nb") == ["a", "", "b"]
