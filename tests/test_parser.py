"""Tests for al2py.parser: Autolev text -> typed IR."""

from __future__ import annotations

import dataclasses
import keyword
import random
from pathlib import Path

import pytest
import sympy
from conftest import SHARED as TUTORIAL

from al2py import ir
from al2py.errors import ParseError
from al2py.parser import parse, span_text

SYMPY_EXAMPLES = Path(sympy.__file__).parent / "parsing" / "autolev" / "test-examples"

TUTORIAL_FILES = sorted(TUTORIAL.glob("*.al"))
SYMPY_FILES = sorted(SYMPY_EXAMPLES.rglob("*.al"))

S = ir.Span("<t>", 0, 0)  # placeholder span used in expected trees


def strip(node):
    """Replace every span in an IR tree by ``S`` so trees compare by shape."""
    if isinstance(node, tuple):
        return tuple(strip(x) for x in node)
    if not isinstance(node, ir.Node):
        return node
    changes = {}
    for name, value in ir.content(node):
        if name == "span":
            changes["span"] = S
        elif name != "lines":
            changes[name] = strip(value)
    return dataclasses.replace(node, **changes)


def one(text: str) -> ir.Stmt:
    """Parse a one-statement script and return the statement."""
    stmts = parse(text, "<t>").statements
    assert len(stmts) == 1, stmts
    return stmts[0]


def expr(text: str) -> ir.Expr:
    stmt = one(text)
    assert isinstance(stmt, ir.ExprStmt), stmt
    return strip(stmt.expr)


def N(name: str, primes: int = 0) -> ir.Name:
    return ir.Name(S, name, primes)


def Num(text: str) -> ir.Number:
    return ir.Number(S, text)


def Bin(op: str, left, right) -> ir.BinOp:
    return ir.BinOp(S, op, left, right)


def load(name: str) -> ir.Script:
    path = TUTORIAL / name
    return parse(path.read_text(encoding="utf-8"), str(path))


def find_line(script: ir.Script, lineno: int) -> ir.Stmt:
    matches = [s for s in script.statements if s.span.line == lineno]
    assert len(matches) == 1, matches
    return matches[0]


def walk(node):
    """Yield every IR node in a tree."""
    if isinstance(node, tuple):
        for x in node:
            yield from walk(x)
        return
    if not isinstance(node, ir.Node):
        return
    yield node
    for name, value in ir.content(node):
        if name not in ("span", "lines"):
            yield from walk(value)


# ---------------------------------------------------------------- whole files


def test_example_files_are_present():
    assert len(TUTORIAL_FILES) >= 15
    assert len(SYMPY_FILES) >= 16


@pytest.mark.parametrize("path", TUTORIAL_FILES + SYMPY_FILES, ids=lambda p: p.name)
def test_example_file_parses(path: Path):
    text = path.read_text(encoding="utf-8")
    script = parse(text, str(path))
    assert isinstance(script, ir.Script)
    assert script.lines == tuple(text.splitlines())
    assert script.statements
    # Every statement span points at real text; non-comment statements
    # start with the first non-blank character of their line.
    for stmt in script.statements:
        assert stmt.span.file == str(path)
        line = script.lines[stmt.span.line - 1]
        assert stmt.span.col == len(line) - len(line.lstrip()) + 1
        assert span_text(script.lines, stmt.span).strip()


def test_tutor1_structure():
    script = load("tutor1.al")
    kinds = [type(s).__name__ for s in script.statements]
    assert kinds.count("Assign") == 26
    assert kinds.count("ExprStmt") == 4
    assert kinds.count("Declaration") == 2
    assert kinds.count("Comment") == 18
    decl = script.statements[4]
    assert strip(decl) == ir.Declaration(
        S,
        "VARIABLES",
        (ir.DeclItem(S, N("X", 1)), ir.DeclItem(S, N("Y", 1))),
    )
    # The 'Dt = Dt( E )' line: a name that is also a function.
    dt = find_line(script, 15)
    assert strip(dt) == ir.Assign(
        S, N("Dt"), "=", ir.Call(S, "Dt", (N("E"),)), comment="Total derivative wrt. t"
    )


def test_taylor_call():
    stmt = find_line(load("tutor1.al"), 16)
    assert strip(stmt) == ir.Assign(
        S,
        N("TY"),
        "=",
        ir.Call(
            S,
            "Taylor",
            (
                Bin("*", N("X"), ir.Call(S, "COS", (N("Y"),))),
                ir.Range(S, Num("0"), Num("7")),
                ir.Equation(S, N("X"), Num("0")),
                ir.Equation(S, N("Y"), Num("0")),
            ),
        ),
        comment="Multi-variable Taylor series",
    )


def test_nested_matrix_literal():
    stmt = find_line(load("tutor1.al"), 34)
    block = ir.MatrixLit(S, ((Num("1"), Num("2")), (Num("3"), Num("4"))))
    assert strip(stmt) == ir.Assign(
        S,
        N("M1"),
        "=",
        ir.MatrixLit(S, ((N("M0"), block),)),
        comment="Elements of matrices can be matrices",
    )


def test_element_assignments():
    script = load("tutor1.al")
    m0 = find_line(script, 33)
    assert strip(m0.target) == ir.Element(S, N("M0"), (Num("2"), Num("2")))
    assert m0.op == ":="
    zero = find_line(script, 25)
    assert strip(zero.target) == ir.Element(S, N("Zero"), (Num("1"),))


def test_tutor8_linearization():
    script = load("tutor8.al")
    perturb = find_line(script, 66)
    assert isinstance(perturb, ir.Assign)
    assert perturb.span.end_line == 67  # `&` continuation
    call = perturb.value
    assert isinstance(call, ir.Call) and call.key == "TAYLOR"
    assert len(call.args) == 8
    assert strip(call.args[2]) == ir.Equation(S, N("X"), ir.Range(S, Num("0"), N("dX")))
    assert strip(call.args[7]) == ir.Equation(
        S, N("U2", 1), ir.Range(S, Num("0"), N("dU2", 1))
    )
    solve = find_line(script, 68)
    assert strip(solve) == ir.ExprStmt(
        S,
        ir.Call(
            S, "Solve", (N("PERTURB"), ir.IndexedNames(S, "dU", ((1, 2),), primes=1))
        ),
    )
    specified = next(
        s
        for s in script.statements
        if isinstance(s, ir.Declaration) and s.keyword == "SPECIFIED"
    )
    item = specified.items[0]
    assert strip(item.target) == N("F")
    assert strip(item.values[0]) == Bin(
        "+",
        Bin(
            "+",
            Bin("+", Bin("*", N("K1"), N("X")), Bin("*", N("K2"), N("THETA"))),
            Bin("*", N("K3"), N("U1")),
        ),
        Bin("*", N("K4"), N("U2")),
    )


def test_tutor2_commands():
    script = load("tutor2.al")
    code = next(s for s in script.statements if isinstance(s, ir.CodeStmt))
    assert strip(code) == ir.CodeStmt(
        S,
        "ALGEBRAIC",
        (),
        ir.Sweep(
            S,
            N("PHI"),
            ir.UnitExpr(S, (("deg", 1),), "deg"),
            Num("0"),
            Num("360"),
            Num("1"),
        ),
        "tutor2.c",
    )
    mass = next(
        s
        for s in script.statements
        if isinstance(s, ir.Declaration) and s.keyword == "MASS"
    )
    assert strip(mass.items) == (
        ir.DeclItem(S, N("A"), (N("M"), Num("12"))),
        ir.DeclItem(S, N("B"), (N("M"),)),
        ir.DeclItem(S, N("C"), (N("M"),)),
    )
    assert strip(script.statements[3]) == ir.Setting(
        S, "DEGREES", "ON", comment="Online calculations of PHI in degrees"
    )
    save = script.statements[-1]
    assert strip(save) == ir.FileCommand(S, "SAVE", "tutor2.all")
    output = next(s for s in script.statements if isinstance(s, ir.OutputStmt))
    assert [(strip(i.expr), i.unit.text) for i in output.items] == [
        (N("PHI"), "degrees"),
        (N("DISTANCE"), "meters"),
        (N("GYRATION"), "meters"),
    ]
    units = next(s for s in script.statements if isinstance(s, ir.UnitSystemStmt))
    assert units.units == ("kg", "meter", "sec")


def test_tutor6_input_units():
    script = load("tutor6.al")
    inputs = [s for s in script.statements if isinstance(s, ir.InputStmt)]
    items = {i.name.name: i for s in inputs for i in s.items}
    assert items["C"].unit.factors == (("n", 1), ("sec", 1), ("m", -1))
    assert items["C"].unit.text == "n*sec/m"
    assert items["G"].unit.factors == (("m", 1), ("sec", -2))
    assert items["U1"].unit.factors == (("rad", 1), ("sec", -1))
    assert items["absErr"].unit is None
    assert strip(items["absErr"].value) == Num("1.0E-07")
    assert inputs[-1].comment == "Error tolerances"


def test_a_dot_multiplies_unit_words():
    script = parse("Constants I, P\nInput I = 2 KG.M^2/S, P = 1 M/KG.S\n")
    (stmt,) = [s for s in script.statements if isinstance(s, ir.InputStmt)]
    first, second = stmt.items
    assert first.unit.factors == (("KG", 1), ("M", 2), ("S", -1))
    assert first.unit.text == "KG.M^2/S"
    # the dot multiplies left to right, as * does: M/KG*S
    assert second.unit.factors == (("M", 1), ("KG", -1), ("S", 1))


# ----------------------------------------------------------- single statements


def test_comments():
    script = parse("% hello  \n%% to code\n\n   %   indented\nX = 1 % trailing \n")
    assert strip(script.statements) == (
        ir.Comment(S, "hello"),
        ir.Comment(S, "to code", code_comment=True),
        ir.Comment(S, "indented"),
        ir.Assign(S, N("X"), "=", Num("1"), comment="trailing"),
    )
    assert script.statements[2].span == ir.Span("<input>", 4, 4, 4, 16)
    assert script.statements[3].span == ir.Span("<input>", 5, 1, 5, 6)


def test_blank_and_empty_input():
    assert parse("").statements == ()
    assert parse("\n\n   \n").statements == ()


def test_continuation_with_comment():
    script = parse("E = A + &   % first part\n    B  % second part\nF = 1")
    e, f = script.statements
    assert strip(e) == ir.Assign(
        S, N("E"), "=", Bin("+", N("A"), N("B")), comment="first part second part"
    )
    assert e.span == ir.Span("<input>", 1, 1, 2, 6)
    assert span_text(script.lines, e.span) == "E = A + &   % first part\n    B"
    assert f.span.line == 3


def test_continuation_without_space():
    stmt = one("E = COS(X)&\n+ SIN(X)")
    assert strip(stmt.value) == Bin(
        "+", ir.Call(S, "COS", (N("X"),)), ir.Call(S, "SIN", (N("X"),))
    )


def test_crlf_line_endings():
    script = parse("X = 1\r\nY = 2 % c\r\n")
    assert [s.span.line for s in script.statements] == [1, 2]
    assert script.statements[1].comment == "c"


def test_names_and_primes():
    assert expr("X''") == N("X", 2)
    assert expr("V_P_N>") == N("V_P_N>")
    assert expr("I_B_P>>") == N("I_B_P>>")
    assert expr("A1>") == N("A1>")
    assert expr("0>") == N("0>")
    assert expr("1>>") == N("1>>")
    assert N("I_B_P>>").rank == 2


@pytest.mark.parametrize("text", ["3", "9.81", ".5", "1.0E-07", "1e7", "2."])
def test_numbers(text):
    assert expr(text) == Num(text)


def test_precedence():
    assert expr("-X^2") == ir.UnaryOp(S, "-", Bin("^", N("X"), Num("2")))
    assert expr("2^-1") == Bin("^", Num("2"), ir.UnaryOp(S, "-", Num("1")))
    assert expr("A^B^C") == Bin("^", N("A"), Bin("^", N("B"), N("C")))
    assert expr("A-B-C") == Bin("-", Bin("-", N("A"), N("B")), N("C"))
    assert expr("A+B*C/D") == Bin(
        "+", N("A"), Bin("/", Bin("*", N("B"), N("C")), N("D"))
    )
    assert expr("(A+B)*C") == Bin("*", Bin("+", N("A"), N("B")), N("C"))
    assert expr("A*-B") == Bin("*", N("A"), ir.UnaryOp(S, "-", N("B")))


def test_parentheses_are_part_of_the_span():
    script = parse("POWER((A+B)*2, ED)")
    call = script.statements[0].expr
    assert span_text(script.lines, call.args[0].span) == "(A+B)*2"
    assert span_text(script.lines, call.args[0].left.span) == "(A+B)"


def test_calls_and_arguments():
    assert expr("Rows(M0, 2, 1:2)") == ir.Call(
        S, "Rows", (N("M0"), Num("2"), ir.Range(S, Num("1"), Num("2")))
    )
    assert expr("Kane( )") == ir.Call(S, "Kane", ())
    assert expr("Force(O/Q, v>)") == ir.Call(
        S, "Force", (Bin("/", N("O"), N("Q")), N("v>"))
    )
    assert expr("Replace(y, sin(x)=3)") == ir.Call(
        S, "Replace", (N("y"), ir.Equation(S, ir.Call(S, "sin", (N("x"),)), Num("3")))
    )
    assert expr("Constrain( DEPENDENT[U2,U3] )") == ir.Call(
        S, "Constrain", (ir.Element(S, N("DEPENDENT"), (N("U2"), N("U3"))),)
    )
    assert expr('ECHO("hi")') == ir.Call(S, "ECHO", (ir.String(S, "hi"),))
    assert expr("Units(n*m, lbf*ft)") == ir.Call(
        S, "Units", (Bin("*", N("n"), N("m")), Bin("*", N("lbf"), N("ft")))
    )


@pytest.mark.parametrize(
    "text, func",
    [
        ("Mass_A = Mass(A)", "Mass"),
        ("I_B_BO>> = Inertia(Bo,B)", "Inertia"),
        ("X = Input(Q)", "Input"),
        ("X = Output(Q)", "Output"),
        ("X = Code(Q)", "Code"),
        ("X = Points(Q)", "Points"),
    ],
)
def test_keywords_as_function_names(text, func):
    stmt = one(text)
    assert isinstance(stmt, ir.Assign)
    assert isinstance(stmt.value, ir.Call) and stmt.value.func == func


@pytest.mark.parametrize("text", ["Mass(A)", "Inertia(O)", "Input(X)", "Output(X)"])
def test_keyword_call_statement_is_expression(text):
    stmt = one(text)
    assert isinstance(stmt, ir.ExprStmt)
    assert isinstance(stmt.expr, ir.Call)


@pytest.mark.parametrize(
    "name", ["Mass_A", "InputX", "Code1", "Points2", "Constants_", "SaveIt", "Runner"]
)
def test_keywords_do_not_steal_names(name):
    assert strip(one(f"{name} = 1")) == ir.Assign(S, N(name), "=", Num("1"))
    assert expr(f"{name} + 1") == Bin("+", N(name), Num("1"))


@pytest.mark.parametrize("word", ["class", "lambda", "def", "None", "import", "if"])
def test_python_keywords_are_names(word):
    assert strip(one(f"{word} = {word}' + 1")) == ir.Assign(
        S, N(word), "=", Bin("+", N(word, 1), Num("1"))
    )


@pytest.mark.parametrize("op", ["=", ":=", "+=", "-=", "*=", "/=", "^="])
def test_assignment_operators(op):
    stmt = one(f"Force_P> {op} 5*a3>")
    assert stmt.op == op
    assert strip(stmt.target) == N("Force_P>")


def test_primed_assignment_target():
    assert strip(one("X'' = -X")) == ir.Assign(
        S, N("X", 2), "=", ir.UnaryOp(S, "-", N("X"))
    )


def test_declarations():
    stmt = one("Constants A, B=3, C+, D-, K{4}, a{1:2,1:2}, C{2,3}")
    assert stmt.keyword == "CONSTANTS"
    assert strip(stmt.items) == (
        ir.DeclItem(S, N("A")),
        ir.DeclItem(S, N("B"), (Num("3"),)),
        ir.DeclItem(S, N("C"), sign="+"),
        ir.DeclItem(S, N("D"), sign="-"),
        ir.DeclItem(S, ir.IndexedNames(S, "K", ((1, 4),))),
        ir.DeclItem(S, ir.IndexedNames(S, "a", ((1, 2), (1, 2)))),
        ir.DeclItem(S, ir.IndexedNames(S, "C", ((1, 2), (1, 3)))),
    )
    stmt = one("Variables X'', Y{3}', U{2}', R{2}''")
    assert [strip(i.target) for i in stmt.items] == [
        N("X", 2),
        ir.IndexedNames(S, "Y", ((1, 3),), primes=1),
        ir.IndexedNames(S, "U", ((1, 2),), primes=1),
        ir.IndexedNames(S, "R", ((1, 2),), primes=2),
    ]


@pytest.mark.parametrize(
    "text, keyword",
    [
        ("Constant A", "CONSTANTS"),
        ("CONSTANTS A", "CONSTANTS"),
        ("Variable A", "VARIABLES"),
        ("MotionVariables A", "VARIABLES"),
        ("MOTIONVARIABLES' Q{2}', U{2}'", "VARIABLES"),
        ("motionvariable A", "VARIABLES"),
        ("Specified F", "SPECIFIED"),
        ("Imaginary j", "IMAGINARY"),
        ("Newtonian N", "NEWTONIAN"),
        ("Frame B", "FRAMES"),
        ("Frames A, B", "FRAMES"),
        ("Body A", "BODIES"),
        ("Bodies B{2}", "BODIES"),
        ("Particle P", "PARTICLES"),
        ("Particles C,D", "PARTICLES"),
        ("Point O", "POINTS"),
        ("Points 0, P, Q", "POINTS"),
        ("Mass A=MA", "MASS"),
        ("Inertia A, I1, I2, I3", "INERTIA"),
    ],
)
def test_declaration_keywords(text, keyword):
    stmt = one(text)
    assert isinstance(stmt, ir.Declaration)
    assert stmt.keyword == keyword


def test_mass_and_inertia_declarations():
    stmt = one("Mass A=M=12, B=MA+")
    assert strip(stmt.items) == (
        ir.DeclItem(S, N("A"), (N("M"), Num("12"))),
        ir.DeclItem(S, N("B"), (N("MA"),), value_signs=("+",)),
    )
    stmt = one("Inertia B, IB=MB*L^2/12, 0, IB")
    assert strip(stmt.items) == (
        ir.DeclItem(S, N("B")),
        ir.DeclItem(
            S,
            N("IB"),
            (Bin("/", Bin("*", N("MB"), Bin("^", N("L"), Num("2"))), Num("12")),),
        ),
        ir.DeclItem(S, Num("0")),
        ir.DeclItem(S, N("IB")),
    )
    stmt = one("Inertia A, O, MA*LA^2/12, MA*LA^2/12")
    assert len(stmt.items) == 4
    assert isinstance(stmt.items[2].target, ir.BinOp)
    assert strip(one("Points 0").items[0].target) == Num("0")


def test_specified_with_value_and_prime():
    assert strip(one("Specified STRETCH'")) == ir.Declaration(
        S, "SPECIFIED", (ir.DeclItem(S, N("STRETCH", 1)),)
    )
    stmt = one("Specified FP = -D*QA'")
    assert strip(stmt.items[0]) == ir.DeclItem(
        S, N("FP"), (Bin("*", ir.UnaryOp(S, "-", N("D")), N("QA", 1)),)
    )


def test_input_statement():
    stmt = one(
        "Input LA=1 m, QA=30 deg, G=9.81 m/sec^2, U1=0 rad/sec, absErr=1.0E-07,"
        " X = 30 DEG, Y = 3.14, K{2}=1, QA'=-2"
    )
    assert isinstance(stmt, ir.InputStmt)
    got = [
        (strip(i.name), strip(i.value), i.unit.factors if i.unit else None)
        for i in stmt.items
    ]
    assert got == [
        (N("LA"), Num("1"), (("m", 1),)),
        (N("QA"), Num("30"), (("deg", 1),)),
        (N("G"), Num("9.81"), (("m", 1), ("sec", -2))),
        (N("U1"), Num("0"), (("rad", 1), ("sec", -1))),
        (N("absErr"), Num("1.0E-07"), None),
        (N("X"), Num("30"), (("DEG", 1),)),
        (N("Y"), Num("3.14"), None),
        (ir.IndexedNames(S, "K", ((1, 2),)), Num("1"), None),
        (N("QA", 1), ir.UnaryOp(S, "-", Num("2")), None),
    ]
    stmt = one("Input C=300 n*sec/m")
    unit = stmt.items[0].unit
    assert unit.text == "n*sec/m"
    assert span_text(parse("Input C=300 n*sec/m").lines, unit.span) == "n*sec/m"


def test_output_statement():
    stmt = one("Output T, STRETCH m, QA deg, ECHECK joules, CONFIG[1], x'")
    got = [(strip(i.expr), i.unit.text if i.unit else None) for i in stmt.items]
    assert got == [
        (N("T"), None),
        (N("STRETCH"), "m"),
        (N("QA"), "deg"),
        (N("ECHECK"), "joules"),
        (ir.Element(S, N("CONFIG"), (Num("1"),)), None),
        (N("x", 1), None),
    ]
    stmt = one("Output T sec, X+Y m")
    assert strip(stmt.items[1].expr) == Bin("+", N("X"), N("Y"))


def test_unit_system():
    assert strip(one("UnitSystem kg,meter,sec")) == ir.UnitSystemStmt(
        S, ("kg", "meter", "sec")
    )


@pytest.mark.parametrize(
    "text, option, nargs, filename",
    [
        ("CODE Dynamics() tutor6.c", "DYNAMICS", 0, "tutor6.c"),
        ("CODE Nonlinear(CONFIG,QB,QC) tutor3.for", "NONLINEAR", 3, "tutor3.for"),
        ("CODE ODE() odexy.c", "ODE", 0, "odexy.c"),
        (
            "CODE ALGEBRAIC(EQN, X, Y) some_filename.c",
            "ALGEBRAIC",
            3,
            "some_filename.c",
        ),
        ("code dynamics()", "DYNAMICS", 0, None),
        ("CODE Nonlinear( Zero, QA,QB,QC ) tutor5.m", "NONLINEAR", 4, "tutor5.m"),
    ],
)
def test_code_statement(text, option, nargs, filename):
    stmt = one(text)
    assert isinstance(stmt, ir.CodeStmt)
    assert (stmt.option, len(stmt.args), stmt.filename) == (option, nargs, filename)
    assert stmt.sweep is None


@pytest.mark.parametrize(
    "text, command, filename",
    [
        ("Save tutor2.all", "SAVE", "tutor2.all"),
        ("SAVE filename.al", "SAVE", "filename.al"),
        ("Run michele.al", "RUN", "michele.al"),
        ("run ../lib/kin.al", "RUN", "../lib/kin.al"),
    ],
)
def test_file_commands(text, command, filename):
    assert strip(one(text)) == ir.FileCommand(S, command, filename)


@pytest.mark.parametrize(
    "text, name, value",
    [
        ("Digits 7", "DIGITS", "7"),
        ("AutoZ ON", "AUTOZ", "ON"),
        ("Factoring OFF", "FACTORING", "OFF"),
        ("Degrees ON", "DEGREES", "ON"),
        ("AutoRHS ALL", "AUTORHS", "ALL"),
        ("AutoEpsilon 1.0E-7", "AUTOEPSILON", "1.0E-7"),
        ("Complex ON", "COMPLEX", "ON"),
        ("Overwrite OFF", "OVERWRITE", "OFF"),
        ("Beepsound ON", "BEEPSOUND", "ON"),
        ("Pause 0", "PAUSE", "0"),
    ],
)
def test_settings(text, name, value):
    assert strip(one(text)) == ir.Setting(S, name, value)


def test_lone_word_is_expression():
    assert strip(one("Exit")) == ir.ExprStmt(S, N("Exit"))
    assert strip(one("X")) == ir.ExprStmt(S, N("X"))


def test_expression_statements():
    for text in ["Solve(Zero, X, Y)", "V2pts(N, A, O, P)", "Expand(E, 1:2)"]:
        assert isinstance(one(text), ir.ExprStmt)
    assert strip(one("POWER(3,A)")) == ir.ExprStmt(
        S, ir.Call(S, "POWER", (Num("3"), N("A")))
    )
    assert expr("Gravity(G*N1>)") == ir.Call(
        S, "Gravity", (Bin("*", N("G"), N("N1>")),)
    )
    assert expr("X+Y") == Bin("+", N("X"), N("Y"))


def test_matrix_literals():
    assert expr("[1; 2; 3]") == ir.MatrixLit(S, ((Num("1"),), (Num("2"),), (Num("3"),)))
    assert expr("[A, B; C, 0]") == ir.MatrixLit(
        S, ((N("A"), N("B")), (N("C"), Num("0")))
    )


def test_spans_are_exact():
    text = "  Force_P> += 5*a3>   % add\nM0[2,2] := D"
    script = parse(text, "f.al")
    first, second = script.statements
    assert first.span == ir.Span("f.al", 1, 3, 1, 20)
    assert span_text(script.lines, first.span) == "Force_P> += 5*a3>"
    assert span_text(script.lines, first.value.span) == "5*a3>"
    assert first.value.right.span == ir.Span("f.al", 1, 17, 1, 20)
    assert span_text(script.lines, second.target.span) == "M0[2,2]"
    assert second.target.base.span == ir.Span("f.al", 2, 1, 2, 3)


@pytest.mark.parametrize("path", TUTORIAL_FILES, ids=lambda p: p.name)
def test_span_text_round_trips(path: Path):
    """Re-parsing the text of every assigned value gives the same tree."""
    script = parse(path.read_text(encoding="utf-8"))
    for stmt in script.statements:
        if not isinstance(stmt, ir.Assign):
            continue
        text = span_text(script.lines, stmt.value.span)
        again = one(f"Q = {text}")
        assert strip(again.value) == strip(stmt.value), text
        for node in walk(stmt.value):
            assert span_text(script.lines, node.span)


# ---------------------------------------------------------------- errors


@pytest.mark.parametrize(
    "text, line, col, message",
    [
        ("X = (A+B", 1, 9, "missing ')'"),
        ("X = A+B)", 1, 8, "unexpected ')'"),
        ("M = [1,2\nY = 3", 1, 9, "missing ']'"),
        ("A{1:2", 1, 6, "missing '}'"),
        ('X = "abc', 1, 5, "unterminated string"),
        ("Y = 1\nX = A $ B", 2, 7, "unexpected character '$'"),
        ("X = A B", 1, 7, "unexpected 'B'"),
        ("X = A +\nY = 2", 1, 8, "unexpected end of line"),
        ("X = A +", 1, 8, "unexpected end of input"),
        ("X = f(a]", 1, 8, "unexpected ']'; missing ')'"),
        ("= 3", 1, 1, "unexpected '='"),
        (
            "X = A &B",
            1,
            7,
            "'&' (line continuation) must be the last character on a line",
        ),
        ("Variables U{0}", 1, 13, "empty index range 1:0"),
        ("Constants K{1.5}", 1, 13, "index bounds must be integers"),
        ("Input X=3 m^2.5", 1, 13, "unit exponents must be integers"),
        ("X = []", 1, 6, "unexpected ']'"),
        ("% c\n\tX = (1 +\n", 2, 10, "unexpected end of input"),
        ("X = 1\nY = (2 * &\n 3", 3, 3, "missing ')'"),
    ],
)
def test_syntax_errors(text, line, col, message):
    with pytest.raises(ParseError) as info:
        parse(text, "bad.al")
    err = info.value
    assert err.message == message
    assert (err.span.file, err.span.line, err.span.col) == ("bad.al", line, col)


def test_first_error_is_reported():
    with pytest.raises(ParseError) as info:
        parse("X = 1\nY = )\nZ = (\n")
    assert (info.value.span.line, info.value.message) == (2, "unexpected ')'")


def test_error_formatting_shows_caret():
    with pytest.raises(ParseError) as info:
        parse("E = (X+2*Y", "t.al")
    assert (
        str(info.value)
        == "t.al:1:11: error: missing ')'\n    E = (X+2*Y\n              ^"
    )


def test_antlr_prints_nothing(capsys):
    for text in ["X = (", "X = $", 'Y = "', "Constants ,"]:
        with pytest.raises(ParseError):
            parse(text)
    captured = capsys.readouterr()
    assert captured.out == captured.err == ""


# ----------------------------------------------------------- property test

_PIECES = (
    list("()[]{}=+-*/^'&%\",;:.<>#$\t \n")
    + keyword.kwlist
    + [
        "0>",
        "1>>",
        "&\n",
        "Input",
        "Mass",
        "CODE",
        "{1:2}",
        "1e",
        "\r",
    ]
)


def _mutate(rng: random.Random, text: str) -> str:
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(5)
        i = rng.randrange(len(text) + 1)
        j = min(len(text), i + rng.randint(1, 8))
        if op == 0:  # delete
            text = text[:i] + text[j:]
        elif op == 1:  # insert
            text = text[:i] + rng.choice(_PIECES) + text[i:]
        elif op == 2 and len(text) > 2:  # swap two characters
            a, b = sorted(rng.sample(range(len(text)), 2))
            text = text[:a] + text[b] + text[a + 1 : b] + text[a] + text[b + 1 :]
        elif op == 3:  # truncate
            text = text[:i]
        else:  # swap two lines
            lines = text.split("\n")
            a, b = rng.randrange(len(lines)), rng.randrange(len(lines))
            lines[a], lines[b] = lines[b], lines[a]
            text = "\n".join(lines)
    return text


def test_random_mutations_give_script_or_parse_error():
    rng = random.Random(20240607)
    sources = [p.read_text(encoding="utf-8") for p in TUTORIAL_FILES]
    outcomes = {"ok": 0, "error": 0}
    for _ in range(300):
        text = _mutate(rng, rng.choice(sources))
        try:
            script = parse(text, "fuzz.al")
        except ParseError as err:
            assert err.span is not None and err.span.line >= 1 and err.span.col >= 1
            assert err.message
            outcomes["error"] += 1
        else:
            assert isinstance(script, ir.Script)
            for stmt in script.statements:
                span_text(script.lines, stmt.span)
            outcomes["ok"] += 1
    assert outcomes["ok"] > 0 and outcomes["error"] > 0


def test_deep_nesting_is_a_parse_error_or_script():
    text = "X = " + "(" * 400 + "1" + ")" * 400
    try:
        parse(text)
    except ParseError as err:
        assert err.message == "expression nested too deeply"
