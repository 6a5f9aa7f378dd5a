"""Each line of the ``.al`` appears once in its module (issue 33, point 5).

The module holds no copy of the source: the transcript reads it back from
the ``# al>`` comments, so every line must come back exactly as the
transcript shows it (stripped), whatever it holds.
"""

from __future__ import annotations

import re

import black
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


def test_echo_ends_the_statement_line_when_it_fits():
    """``code  # al> line`` when black's 88 columns hold both, else the echo
    keeps its own line above; the transcript reads both back, and a
    ``# al>`` inside a string is no echo."""
    src = [
        "Newtonian N",
        "Frames A",
        "Variables QA'",
        "Simprot(N, A, 3, QA)",
        "% a comment keeps its line",
        "LONG_NAME_OF_A_QUANTITY = QA*QA + QA*QA*QA + QA*QA*QA*QA  % and a long comment",
    ]
    code = convert("\n".join(src) + "\n", "e.al").code
    lines = code.splitlines()
    assert "A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)" in lines
    assert "# al> % a comment keeps its line" in lines
    assert f"# al> {src[-1]}" in lines  # too long to end its statement's line
    assert all(len(line) <= 88 for line in lines)
    assert echoed_source(lines) == src
    assert black.format_str(code, mode=black.Mode()) == code
    quoted = ['x = "# al> not an echo"', "y = 1  # al> Q' = U", "# al> % c"]
    assert echoed_source(quoted) == ["Q' = U", "% c"]


def test_a_failure_names_the_line_of_an_echo_at_the_end(tmp_path):
    """A run-time error of a statement whose echo ends its line names that
    statement's ``.al`` line."""
    from al2py_runtime.safety import al_line, echo_above

    lines = [
        "# al> Constants A",
        "A = 1  # al> Q = 1",
        "# al> % a comment",
        "B = f(A)  # al> B = F(A)",
        "g(B)",
    ]
    path = tmp_path / "m.py"
    path.write_text("\n".join(lines) + "\n")
    assert echo_above(lines, 2) == (1, "Q = 1")
    assert echo_above(lines, 5) == (3, "B = F(A)")
    assert al_line(str(path), 5) == (4, "B = F(A)")
    assert al_line(str(path), 2) == (2, "Q = 1")
