"""Each line of the ``.al`` appears once in its module (issue 33, point 5).

The module holds no copy of the source: the transcript reads it back from
the ``# al>`` comments, so every line must come back exactly as the
transcript shows it (stripped), whatever it holds.
"""

from __future__ import annotations

import re

from al2py_runtime.safety import echo_lines, echoed_source

from al2py import convert

TRICKY = [
    "Constants A, B   % a comment",
    "",
    "   ",
    "%      File:  x.al      [indented comment]",
    "E = A + &",
    "    B  % continued",
    "\tF = A\t+ B\t% tabs inside",
    "G = A " + "+ A " * 40 + "% a line far longer than a comment may be",
    "H = " + "X" * 200,
    "% a form feed \x0c and a bell \x07 in a comment",
    '% quotes \' " and a backslash \\ and """',
    "% unicode: é ü ∂",
    "T= [" + " " * 46 + "\t" * 5 + "     \t& % a long run of blanks and tabs",
    "X = 1" + " " * 120 + "% blanks past a comment's width",
]


def test_echo_lines_give_each_line_back():
    """Also after black, which strips the blanks that end a comment."""
    import black

    module = [c for line in TRICKY for c in echo_lines(line)]
    assert echoed_source(module) == [line.strip() for line in TRICKY]
    for c in module:
        assert c == c.rstrip() and len(c.expandtabs(8)) <= 88, c
    code = black.format_str("x = 1\n" + "\n".join(module) + "\n", mode=black.Mode())
    assert echoed_source(code.splitlines()) == [line.strip() for line in TRICKY]


def test_words_are_not_split_in_the_echo():
    line = "G = A " + "+ ALPHA " * 30
    pieces = echo_lines(line)
    assert len(pieces) > 1
    assert all(p.startswith("# al+ ") for p in pieces[1:])  # cut before a space


def test_module_holds_each_line_once(tmp_path):
    src = "\n".join(
        [
            "% a script",
            "Constants A, B",
            "",
            "E = A + &",
            "  B  % continued",
            "F = A; G = B",
            "% the end",
        ]
    )
    code = convert(src + "\n", "once.al").code
    assert "AL_SOURCE" not in code
    for text in ("% a script", "Constants A, B", "F = A; G = B", "% the end"):
        assert code.count(text) == 1, text
    assert echoed_source(code.splitlines()) == [
        line.strip() for line in src.split("\n")
    ]


def test_help_text_reads_whole():
    """The baked ``--help`` is one string: no word is split across pieces."""
    code = convert(
        "Constants K\nInput K = 1 n/m\nOutput K\nCODE Algebraic() x.m\n", "h.al"
    ).code
    start = code.index('sys.stdout.write("""')
    block = code[start : code.index('""")', start)]
    assert "--zero-missing" in block
    assert re.search(r'^\s*"', block.split("\n", 1)[1], re.M) is None
