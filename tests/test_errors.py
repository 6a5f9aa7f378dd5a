"""Acceptance tests: input errors are reported precisely, and never as tracebacks.

Every error in the input prints ``FILE.al:LINE:COL: error: message`` as the
first line on stderr, then the source line, then a caret under column COL, and
exits with status 2.  Also: nothing in a script can inject Python code into the
generated module.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from al2py import cli, convert
from al2py.errors import AutolevError

ROOT = Path(__file__).resolve().parents[1]

# (name, source, line, col, fragment of the message)
CASES = [
    # syntax errors
    ("end_of_input", "Constants A\nE = A + 1 +\n", 2, 12, "unexpected end of input"),
    ("bad_character", "Constants A\nE = 3 $ 4\n", 2, 7, "unexpected character '$'"),
    # the stray character, not the operator the parser then trips on
    ("bad_character_after_operator", "Variables X\nY = X + $ + X\n", 2, 9, "'$'"),
    ("two_names", "Constants A B\n", 1, 13, "unexpected 'B'"),
    ("unclosed_paren", "E = ((((1\n", 1, 10, "missing ')'"),
    ("unterminated_string", 'Save x"y.all\n', 1, 7, "unterminated string"),
    ("string_as_value", 'E = "abc"\n', 1, 5, "a string is not a value"),
    # undeclared names, including in the middle of a line
    ("undeclared_middle", "Constants A\nE = A + Q + 1\n", 2, 9, "undeclared name 'Q'"),
    ("undeclared_end", "Variables X\nE = X + Y\n", 2, 9, "undeclared name 'Y'"),
    ("undeclared_first", "E = Q\n", 1, 5, "undeclared name 'Q'"),
    (
        "undeclared_in_argument",
        "Constants A, B\nE = Sin(A) + Cos(B*Z3)\n",
        2,
        20,
        "undeclared name 'Z3'",
    ),
    (
        "undeclared_continued",
        "Constants A\nE = A + &\n  Q\n",
        3,
        3,
        "undeclared name 'Q'",
    ),
    ("undeclared_after_tab", "Constants A\nE = A +\tQ\n", 2, 9, "undeclared name 'Q'"),
    # argument counts
    ("rows_no_args", "M = [1,2;3,4]\nN = Rows()\n", 2, 5, "Rows takes"),
    ("det_two_args", "M = [1,2;3,4]\nN = Det(M, M)\n", 2, 5, "Det takes exactly 1"),
    ("sin_two_args", "Constants A\nE = 2 + Sin(A, A)\n", 2, 9, "Sin takes exactly 1"),
    ("taylor_one_arg", "Constants A\nZ = Taylor(A)\n", 2, 5, "Taylor takes"),
    ("solve_indented", "Constants A\n  Solve(A)\n", 2, 3, "Solve takes"),
    # unknown functions
    ("unknown_function", "E = Foo(1)\n", 1, 5, "unknown function or command 'Foo'"),
    (
        "unknown_function_middle",
        "Constants A\nE = A*Bar(A, 2)\n",
        2,
        7,
        "unknown function or command 'Bar'",
    ),
    # type errors that are visible in the script
    ("matrix_plus_scalar", "M = [1,2]\nZ = M + 1\n", 2, 5, "cannot add"),
    ("index_a_scalar", "Constants A\nZ = A[1]\n", 2, 5, "'A' is not a matrix"),
    ("reserved_pi", "Pi = 2\n", 1, 1, "reserved"),
]

# Physics and CODE jobs are being built: each of these valid snippets either
# converts into a module that compiles, or stops with a precise
# "not supported yet" error at (line, col) -- never anything else.
PHYSICS_AND_CODE = [
    ("bodies", "Bodies A\n", 1, 1),
    ("bodies_indented", "   Bodies A\n", 1, 4),
    ("newtonian", "Newtonian N\n", 1, 1),
    ("frames", "Constants A\nFrames B\n", 2, 1),
    ("points", "Points P, Q\n", 1, 1),
    ("particles", "Particles C, D\n", 1, 1),
    ("v2pts", "Newtonian N\nBodies A\nPoints O, P\nV2pts(N,A,O,P)\n", 4, 1),
    ("kane", "Newtonian N\nKane()\n", 2, 1),
    ("code_ode", "Variables X'\nConstants K\nX' = -K*X\nCODE ODE() x.c\n", 4, 1),
    ("input", "Constants X\nInput X=1\n", 2, 1),
    ("output", "Output T\n", 1, 1),
    ("unitsystem", "UnitSystem kg,meter,sec\n", 1, 1),
    ("autotaylor", "Variables X\nAutoTaylor(0:1, X=0)\n", 2, 1),
    ("spline", "Variables X\nE = Spline(LINEAR, X, 1, 2)\n", 2, 5),
]


def _expected_block(src: str, line: int, col: int) -> tuple[str, str]:
    text = src.splitlines()[line - 1].expandtabs(1)
    return "    " + text, "    " + " " * (col - 1) + "^"


def _run_main(argv, capsys):
    status = cli.main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def _check_error(err: str, out: str, status: int, src: str, line, col, fragment):
    assert status == 2, err
    assert out == ""
    assert "Traceback" not in err
    lines = err.splitlines()
    head = f"bad.al:{line}:{col}: error: "
    assert lines[0].startswith(head), f"expected {head!r}, got:\n{err}"
    assert fragment in lines[0], err
    src_line, caret = _expected_block(src, line, col)
    assert lines[1] == src_line, err
    assert lines[2] == caret, err
    assert len(lines) == 3, err


@pytest.mark.parametrize(
    "name, src, line, col, fragment", CASES, ids=[c[0] for c in CASES]
)
def test_input_error_is_located(name, src, line, col, fragment, tmp_path, capsys):
    path = tmp_path / "bad.al"
    path.write_text(src)
    out_path = tmp_path / "bad.py"
    status, out, err = _run_main([str(path), "-o", str(out_path)], capsys)
    err = err.replace(str(path), "bad.al")
    _check_error(err, out, status, src, line, col, fragment)
    assert not out_path.exists()


@pytest.mark.parametrize(
    "name, src, line, col", PHYSICS_AND_CODE, ids=[c[0] for c in PHYSICS_AND_CODE]
)
def test_converts_or_says_not_supported_yet(name, src, line, col, tmp_path, capsys):
    path = tmp_path / "bad.al"
    path.write_text(src)
    status, out, err = _run_main([str(path)], capsys)
    if status == 0:
        assert err == ""
        compile(out, "bad.py", "exec")
        return
    err = err.replace(str(path), "bad.al")
    _check_error(err, out, status, src, line, col, "not supported yet")


def test_not_supported_yet_from_a_real_process(tmp_path):
    (tmp_path / "job.al").write_text("Variables X\nAutoTaylor(0:1, X=0)\n")
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "job.al", "-o", "job.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    if run.returncode == 0:  # AutoTaylor has been built meanwhile
        compile((tmp_path / "job.py").read_text(), "job.py", "exec")
        return
    assert run.returncode == 2
    assert run.stdout == ""
    first, src, caret = run.stderr.splitlines()
    assert first.startswith("job.al:2:1: error: ")
    assert "not supported yet" in first
    assert src == "    AutoTaylor(0:1, X=0)"
    assert caret == "    ^"
    assert not (tmp_path / "job.py").exists()


def test_error_format_from_a_real_process(tmp_path):
    """The same format through ``python -m al2py`` with a relative file name."""
    src = "Constants A, B\nE = A + B\nF = E*Q2 + 1\n"
    (tmp_path / "bad.al").write_text(src)
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "bad.al", "-o", "bad.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr.splitlines() == [
        "bad.al:3:7: error: undeclared name 'Q2'",
        "    F = E*Q2 + 1",
        "          ^",
    ]
    assert not (tmp_path / "bad.py").exists()


def test_convert_raises_autolev_error_with_span():
    with pytest.raises(AutolevError) as info:
        convert("Constants A\nE = A + Q + 1\n", "snippet.al")
    err = info.value
    assert (err.span.line, err.span.col) == (2, 9)
    assert str(err).splitlines()[0] == "snippet.al:2:9: error: undeclared name 'Q'"


def test_error_in_run_file_points_into_that_file(tmp_path, capsys):
    (tmp_path / "other.al").write_text("Constants K\nW = K + Nope\n")
    (tmp_path / "main.al").write_text("Constants A\nRUN other.al\nV = A\n")
    status, out, err = _run_main([str(tmp_path / "main.al")], capsys)
    assert status == 2
    assert out == ""
    assert "Traceback" not in err
    first = err.splitlines()[0]
    assert first.endswith("error: undeclared name 'Nope'")
    assert "other.al:2:9:" in first


def test_missing_run_file(tmp_path, capsys):
    (tmp_path / "main.al").write_text("Constants A\nRUN missing.al\n")
    status, out, err = _run_main([str(tmp_path / "main.al")], capsys)
    assert status == 2
    assert out == ""
    assert "Traceback" not in err
    assert f"{tmp_path / 'main.al'}:2:" in err.splitlines()[0]


def test_every_error_is_reported_in_order(tmp_path, capsys):
    (tmp_path / "bad.al").write_text("E = Q1\nF = Q2\n")
    status, _, err = _run_main([str(tmp_path / "bad.al")], capsys)
    assert status == 2
    lines = err.splitlines()
    assert "bad.al:1:5: error: undeclared name 'Q1'" in lines[0]
    assert any("bad.al:2:5: error: undeclared name 'Q2'" in x for x in lines)
    assert lines[-1] == "2 errors"


def test_three_unrelated_syntax_errors_all_reported(tmp_path, capsys):
    text = (
        "Constants a, b\n"
        "x = (a + \n"  # 2: missing operand
        "y = a b\n"  # 3: two operands in a row
        "z = a*b\n"
        "w = [a, b; a]]\n"  # 5: extra bracket
    )
    (tmp_path / "bad.al").write_text(text)
    status, out, err = _run_main([str(tmp_path / "bad.al")], capsys)
    assert status == 2 and out == ""
    heads = [x for x in err.splitlines() if ": error: " in x]
    assert [h.split(": error:")[0] for h in heads] == [
        f"{tmp_path / 'bad.al'}:2:10",
        f"{tmp_path / 'bad.al'}:3:7",
        f"{tmp_path / 'bad.al'}:5:14",
    ]
    carets = [x for x in err.splitlines() if x.strip() == "^"]
    assert len(carets) == 3
    assert "Traceback" not in err


def test_errors_after_a_failed_declaration_do_not_cascade(tmp_path, capsys):
    # The bad Constants line is skipped; its names are not re-reported.
    (tmp_path / "bad.al").write_text("Constants a, b +* c\nx = a + c\ny = zz\n")
    status, _, err = _run_main([str(tmp_path / "bad.al")], capsys)
    assert status == 2
    heads = [x for x in err.splitlines() if ": error: " in x]
    assert len(heads) == 2
    assert ":1:" in heads[0] and "undeclared name 'zz'" in heads[1]


# ---------------------------------------------------------------- injection

PAYLOAD = 'import os; os.system("touch PWNED"); open("PWNED2", "w")'

INJECTIONS = {
    "comment_triple_double": f'Constants A\n% """\n% {PAYLOAD}\n% """\nE = A\n',
    "comment_inline": f'Constants A\n% """; {PAYLOAD}\nE = A % """ ; {PAYLOAD}\n',
    "comment_triple_single": f"Constants A\nE = A % ''' \\n{PAYLOAD} #\n",
    "comment_backslashes": f"Constants A\n% \\\\ \\ \\n\\'\\\"{PAYLOAD}\nE = A\n",
    "comment_escape_newline": 'Constants A\n% \\"""\\n__import__("os").system("touch PWNED")\nE = A\n',
    "comment_nul_like": f"Constants A\n% \\x00 \\u0000 {PAYLOAD}\nE = A\n",
    "continuation_comment": f'Constants A\nE = A + &  % """ {PAYLOAD}\n 1\n',
    "keyword_names": (
        "Constants lambda, class, import, exec, None, print\n"
        "E = lambda + class + import + exec + None + print\n"
    ),
    "builtin_names": "open = 1\neval = open + 1\nglobals = eval*2\nos = 3\n",
    "module_names": "al = 1\nAUTOLEV = 2\nAL_SOURCE = 3\nmain = 4\nt2 = al + main\n",
    "save_quotes": "Constants A\nE = A\nSave x'y\".all\n",
    "save_backslash": "Constants A\nE = A\nSave x\\y.all\n",
    "save_triple_quote": 'Constants A\nE = A\nSave a""".all\n',
    "save_path_injection": 'Constants A\nE = A\nSave ");import os;os.system("touch PWNED");(".all\n',
}


@pytest.mark.parametrize("name", sorted(INJECTIONS))
def test_nothing_is_injected(name, tmp_path):
    src = INJECTIONS[name]
    (tmp_path / "inj.al").write_text(src)
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "inj.al", "-o", "inj.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert "Traceback" not in run.stderr
    if run.returncode == 2:  # a clean input error is acceptable
        assert ":" in run.stderr.splitlines()[0]
        assert "error:" in run.stderr.splitlines()[0]
        assert not (tmp_path / "inj.py").exists()
        return
    assert run.returncode == 0, run.stderr
    code = (tmp_path / "inj.py").read_text()
    compile(code, "inj.py", "exec")
    # importing and running the module executes nothing that was injected
    for argv in (["-c", "import inj"], ["inj.py"]):
        done = subprocess.run(
            [sys.executable, *argv],
            capture_output=True,
            text=True,
            cwd=tmp_path,
            timeout=300,
        )
        assert done.returncode == 0, done.stderr
        assert not (tmp_path / "PWNED").exists()
        assert not (tmp_path / "PWNED2").exists()
    # the comments and lines come back verbatim in the transcript
    for line in src.splitlines():
        if line.strip():
            assert line.strip() in done.stdout, (line, done.stdout)


def test_comment_text_is_preserved_not_executed(tmp_path):
    src = 'Constants A\n% """\nimport_os = 1\n% """\nE = A\n'
    code = convert(src, str(tmp_path / "c.al")).code
    compile(code, "c.py", "exec")
    # the comment lines appear only as Python comments or string data
    for line in code.splitlines():
        stripped = line.strip()
        if stripped.startswith('"""') and stripped != '"""':
            continue
        assert stripped != "import os"


def test_save_file_name_is_used_verbatim(tmp_path):
    """``Save`` writes exactly the named file, inside the working directory."""
    name = "we\\ird\\n.all"
    src = f"Constants A\nE = A\nSave {name}\n"
    (tmp_path / "s.al").write_text(src)
    conv = subprocess.run(
        [sys.executable, "-m", "al2py", "s.al", "-o", "s.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert conv.returncode == 0, conv.stderr
    before = {p.name for p in tmp_path.iterdir()}
    run = subprocess.run(
        [sys.executable, "s.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    created = {p.name for p in tmp_path.iterdir()} - before
    assert created == {name}
    assert "E = A" in (tmp_path / name).read_text()


def test_a_long_line_is_shown_around_the_column(tmp_path, capsys):
    """A source line longer than 120 characters is shown cut around the
    column (``...`` where cut), with the caret under the culprit."""
    source = "Variables X\nY = " + "X + " * 100 + "$" + " + X" * 100 + "\n"
    path = tmp_path / "long.al"
    path.write_text(source)
    status, _out, err = _run_main([str(path), "-o", str(tmp_path / "long.py")], capsys)
    assert status == 2
    first, shown, caret = err.splitlines()[:3]
    assert first.endswith("long.al:2:405: error: unexpected character '$'")
    assert shown.startswith("    ...") and shown.endswith("...")
    assert len(shown) <= 4 + 120 + 6
    assert shown[caret.index("^")] == "$"
