"""Line structure of real scripts, and what al2py says when they stop.

Small scripts of our own modelled on what public research scripts do: old
Mac line endings (a lone carriage return), two statements run together on
one line, a definition that was commented out, and a fragment that declares
nothing.  See "Line breaks and scripts that Autolev stops too" in
docs/semantics.md.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import load_module

from al2py import convert
from al2py.cli import main
from al2py.errors import AutolevError
from al2py.parser import parse, parse_partial


def run(src: str, tmp_path: Path, name: str = "snip"):
    path = tmp_path / f"{name}.al"
    result = convert(src, str(path))
    return load_module(result.code, tmp_path, f"{name}_mod")


def errors_of(src: str, tmp_path: Path) -> list[AutolevError]:
    with pytest.raises(AutolevError) as info:
        run(src, tmp_path)
    return list(getattr(info.value, "errors", [info.value]))


# ------------------------------------------------------- lone carriage return


def test_lone_carriage_return_ends_a_line():
    script = parse("Constants a\rb = 2*a\r\nc = b + 1\rd = c\n")
    assert [s.span.line for s in script.statements] == [1, 2, 3, 4]


def test_statements_on_carriage_return_lines_all_take_effect(tmp_path):
    mod = run("Constants a\rb = 2*a + 1\rc = 3*b\r", tmp_path)
    assert mod.AUTOLEV["B"] == 2 * mod.a + 1
    assert mod.AUTOLEV["C"] == 3 * mod.b
    assert mod.evaluate("C", A=0.5) == pytest.approx(6.0)


def test_error_after_mixed_line_endings_keeps_line_and_column(tmp_path, capsys):
    path = tmp_path / "mac.al"
    path.write_bytes(b"Constants a\rb = 2*a\r\nc = b a\rd = 1\n")
    out = tmp_path / "mac_out.py"
    assert main([str(path), "-o", str(out)]) == 2
    assert not out.exists()
    assert f"{path}:3:7: error: unexpected 'a'" in capsys.readouterr().err


def test_cli_reports_the_physical_line_of_a_carriage_return_file(tmp_path, capsys):
    path = tmp_path / "mac2.al"
    path.write_bytes(b"Constants a\rb = 2*a\rc = b a\r")
    assert main([str(path), "-o", str(tmp_path / "mac2_out.py")]) == 2
    err = capsys.readouterr().err
    assert f"{path}:3:7: error: unexpected 'a'" in err
    assert "    c = b a\n" in err and "\n          ^" in err


def test_run_file_with_carriage_returns(tmp_path):
    (tmp_path / "part.al").write_bytes(b"b = 2*a\rc = b - 1\r")
    mod = run("Constants a\nRun part.al\nd = c*c\n", tmp_path, "main")
    assert mod.AUTOLEV["B"] == 2 * mod.a
    assert mod.evaluate("D", A=2.0) == pytest.approx(9.0)


# ------------------------------------------------ two statements on one line


def test_two_statements_run_together_get_a_located_explanation(tmp_path):
    src = "Frames A\nConstants r\nV> = r*A1>W> = 2*V>\n"
    (err,) = errors_of(src, tmp_path)
    assert (err.span.line, err.span.col) == (3, 11)
    assert "unexpected 'W>'" in err.message
    assert "a line break or ';' is missing" in err.message


def test_juxtaposed_operands_keep_the_plain_message(tmp_path):
    # 'b' alone is not a statement of its own that could start there
    (err,) = errors_of("Constants a, b\nx = a b\n", tmp_path)
    assert err.message == "unexpected 'b'"
    assert (err.span.line, err.span.col) == (2, 7)


def test_declaration_run_into_an_assignment(tmp_path):
    (err,) = errors_of("Constants a\nx = a Constants k\n", tmp_path)
    assert err.span.col == 7 and "new one starts here" in err.message


def test_statements_separated_by_a_semicolon_both_take_effect(tmp_path):
    # the form the hint proposes really works, with the right values
    mod = run("Frames A\nConstants r\nV> = r*A1>; W> = 2*V>\n", tmp_path)
    frame_a = mod.A
    assert mod.AUTOLEV["W>"] == 2 * mod.r * frame_a.x


# ------------------------------------------ names Autolev would not know either


def test_commented_out_definition_is_pointed_at(tmp_path):
    src = "Constants a\nx = 2*a\n%y = 3*a\nPause\nz = [x; y]\n"
    (err,) = errors_of(src, tmp_path)
    assert (err.span.line, err.span.col) == (5, 9)
    assert err.message == (
        "undeclared name 'y' (line 3 assigns it, but that line is a comment)"
    )


def test_comment_after_the_use_is_not_a_definition(tmp_path):
    (err,) = errors_of("Constants a\nz = y\n%y = 3*a\n", tmp_path)
    assert err.message == "undeclared name 'y'"


def test_fragment_without_declarations_is_described(tmp_path):
    src = "x = Evaluate(D(Q4', Q4), Q4=0)\ny = Q4 + 1\nInput W=1.5\n"
    errs = errors_of(src, tmp_path)
    # Q4 is reported once, at its first use, with the hint; then W, plainly
    assert [(e.span.line, e.span.col) for e in errs] == [(1, 16), (3, 7)]
    assert "declares nothing" in errs[0].message
    assert errs[1].message == "undeclared name 'W'"


def test_declared_file_gets_no_fragment_hint(tmp_path):
    (err,) = errors_of("Constants a\nx = a + q\n", tmp_path)
    assert err.message == "undeclared name 'q'"


# ------------------------------------------------- errors on consecutive lines


def test_error_recovery_does_not_hide_the_next_lines_error():
    # the first line leaves ANTLR in error recovery; the second line's missing
    # ']' must still be reported (it was dropped, or crashed with a comment)
    src = ":= } =\nCode [ % note\nx = 1\n"
    script, errors = parse_partial(src, "f.al")
    assert [(e.span.line, e.message) for e in errors] == [
        (1, "unexpected ':='"),
        (2, "missing ']'"),
    ]
    assert [s.span.line for s in script.statements] == [3]
