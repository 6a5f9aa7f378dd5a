"""Tests for al2py.macros: finding and expanding .a/.r macro files."""

from __future__ import annotations

import os

import pytest
from conftest import SHARED as TUTORIAL

from al2py import ir
from al2py.errors import MacroError
from al2py.macros import MacroExpansion, expand_macro, find_macro
from al2py.parser import parse, span_text


def expand(text, args, *, newtonian="N", degrees=False, path="m.a"):
    return expand_macro(
        text, list(args), newtonian=newtonian, degrees=degrees, path=path
    )


# ------------------------------------------------------------------ lookup


def test_find_tutorial_macros_case_insensitively():
    assert find_macro("POWER", "a", TUTORIAL, "") == TUTORIAL / "power.a"
    assert find_macro("Sum", "r", TUTORIAL, "") == TUTORIAL / "sum.r"
    assert find_macro("sum", "a", TUTORIAL, "") is None
    assert find_macro("nothing", "a", TUTORIAL, "") is None


def test_find_uses_autolevpath(tmp_path, monkeypatch):
    here = tmp_path / "script"
    lib1 = tmp_path / "lib1"
    lib2 = tmp_path / "lib2"
    for d in (here, lib1, lib2):
        d.mkdir()
    (lib2 / "KIN.A").write_text("X = 1\n")
    (lib1 / "other.r").write_text("1\n")
    path = os.pathsep.join([str(tmp_path / "missing"), str(lib1), str(lib2)])
    assert find_macro("kin", "a", here, path) == lib2 / "KIN.A"
    assert find_macro("OTHER", "r", here, path) == lib1 / "other.r"
    # the script directory wins over AUTOLEVPATH
    (here / "kin.a").write_text("X = 2\n")
    assert find_macro("kin", "a", here, path) == here / "kin.a"
    # default: the environment variable
    monkeypatch.setenv("AUTOLEVPATH", str(lib1))
    assert find_macro("other", "r", here) == lib1 / "other.r"
    monkeypatch.delenv("AUTOLEVPATH")
    assert find_macro("other", "r", here) is None


def test_find_in_missing_directory(tmp_path):
    assert find_macro("x", "a", tmp_path / "nope", None) is None


# --------------------------------------------------------------- expansion


def test_power_macro():
    text = (TUTORIAL / "power.a").read_text()
    assert expand(text, ["3", "A"]) == MacroExpansion("ASQ = (3)^2\nACUBE = (3)^3")
    result = expand(text, ["A+B", "ED"])
    assert result.text == "EDSQ = (A+B)^2\nEDCUBE = (A+B)^3"
    assert result.echoes == ()
    # the expansion is valid Autolev
    stmts = parse(result.text).statements
    assert [s.target.name for s in stmts] == ["EDSQ", "EDCUBE"]


def test_power_macro_with_argument_text_from_a_call():
    script = parse("POWER((A+B)*2, ED)")
    call = script.statements[0].expr
    args = [span_text(script.lines, a.span) for a in call.args]
    assert args == ["(A+B)*2", "ED"]
    text = (TUTORIAL / "power.a").read_text()
    assert expand(text, args).text.splitlines()[0] == "EDSQ = ((A+B)*2)^2"


def test_sum_macro_if_else_and_echo():
    text = (TUTORIAL / "sum.r").read_text()
    assert expand(text, ["3", "5"]) == MacroExpansion("3 + 5")
    result = expand(text, ["3"])
    assert result.text == ""
    assert result.echoes == ("Error: wrong number of arguments to the SUM command",)


def test_special_symbols_are_case_insensitive():
    text = "X = #num_args#\nY> = #NEWTONIAN#1>\nZ = #Degrees#\nW = #NUM_ARGS#"
    result = expand(text, ["a", "b"], newtonian="N", degrees=True)
    assert result.text == "X = 2\nY> = N1>\nZ = ON\nW = 2"
    assert expand("Z = #DEGREES#", [], degrees=False).text == "Z = OFF"


def test_comment_lines_are_dropped():
    text = "% help text\n   %% more help\nA = #1#\n\n  B = 2\n"
    assert expand(text, ["7"]).text == "A = 7\nB = 2"


def test_else_if_chain_and_nesting():
    text = """
if( #NUM_ARGS# == 1 ) {
  A = #1#
} else if (#NUM_ARGS# >= 3) {
  if (#DEGREES# == on) { ECHO("deg") } else { ECHO(\\n"rad #NUM_ARGS#"\\p) }
  B = #3#
} else
{
  C = #Newtonian#1>
}
D = U{3}
"""
    assert expand(text, ["x"]) == MacroExpansion("A = x\nD = U{3}")
    assert expand(text, ["x", "y", "z"]) == MacroExpansion(
        "B = z\nD = U{3}", ("rad 3",)
    )
    assert expand(text, ["x", "y", "z"], degrees=True).echoes == ("deg",)
    assert expand(text, ["x", "y"]).text == "C = N1>\nD = U{3}"


@pytest.mark.parametrize(
    "cond, expected",
    [
        ("2 == 2", True),
        ("2 != 2", False),
        ("1 < 2", True),
        ("10 > 9", True),
        ("3 <= 3", True),
        ("3 >= 4", False),
        ("ON == on", True),
        ("#1# == ED", True),
        ("#1# != ED", False),
        ('#2# == "A+B"', True),
    ],
)
def test_conditions(cond, expected):
    text = f"if ({cond}) {{ YES }} else {{ NO }}"
    assert expand(text, ["ed", "A+B"]).text == ("YES" if expected else "NO")


def test_untaken_branch_may_reference_missing_arguments():
    text = "if (#NUM_ARGS# < 3) { X = #1# } else { X = #3# }"
    assert expand(text, ["q"]).text == "X = q"


def test_if_without_else_keeps_following_lines():
    text = "if (1 == 2) { X = 1 }\nY = 2\nif (1 == 1) { Z = 3 }\nW = 4"
    assert expand(text, []).text == "Y = 2\nZ = 3\nW = 4"


@pytest.mark.parametrize(
    "text, fragment",
    [
        ("A = #5#", "#5# refers to argument 5 but 2 arguments were given"),
        ("A = #0#", "#0# refers to argument 0"),
        ("A = #FOO#", "unknown placeholder #FOO#"),
        ("A = # B", "stray '#'"),
        ("if (1 == 1 { X }", "missing ')' after 'if' condition"),
        ("if (1 == 1) X", "expected '{'"),
        ("if (1 == 1) { X", "missing '}'"),
        ("X }", "'}' without a matching '{'"),
        ("else { X }", "'else' without a matching 'if'"),
        ("if (1 ~ 2) { X }", "malformed if condition"),
        ('if (1 == 1) { ECHO("x" }', "missing ')' after ECHO("),
    ],
)
def test_malformed_macros(text, fragment):
    with pytest.raises(MacroError) as info:
        expand(text, ["a", "b"], path="lib/bad.a")
    assert fragment in info.value.message
    assert "lib/bad.a" in info.value.message
    assert info.value.span is None


def test_newtonian_required_when_used():
    with pytest.raises(MacroError, match="no Newtonian frame"):
        expand("V> = #Newtonian#1>", [], newtonian=None)


def test_expansion_parses_as_autolev():
    text = (TUTORIAL / "sum.r").read_text()
    result = expand(text, ["X^2", "Y"])
    stmt = parse(f"PLUS = {result.text}").statements[0]
    assert isinstance(stmt, ir.Assign)
    assert isinstance(stmt.value, ir.BinOp) and stmt.value.op == "+"


def test_labels_of_statements_from_run_files_and_macros_are_their_own(tmp_path):
    """An Output or a bare expression in a RUN file (or a macro) is labelled
    with its own text, not the text at the same place in the main file."""
    from conftest import load_module

    from al2py import convert

    (tmp_path / "part.al").write_text("Variables X'\nX' = -2*X\nOutput X, X'/2\n")
    (tmp_path / "show.a").write_text("Y2 = X^2\nY2 + 1\n")
    main = tmp_path / "main.al"
    main.write_text(
        "% one\n% two\nRUN part.al\nshow()\n"
        "Input X=1, TFINAL=1, INTEGSTP=0.5\nCODE ODE() m.c\n"
    )
    module = load_module(convert(main.read_text(), str(main)).code, tmp_path, "m")
    result = module.run()
    assert result.tables[0].names == ["X", "X'/2"]
    assert result.tables[0]["X'/2"] == pytest.approx(-result["X"])
    labels = [r.label for r in module.al.responses]
    assert "Y2+1" in labels
