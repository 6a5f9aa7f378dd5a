"""Tests for al2py_runtime.names.printing (Autolev-syntax responses)."""

from __future__ import annotations

import random
import re

import pytest
import sympy as sp
from al2py_runtime import algebra as al
from al2py_runtime import matrices as mt
from al2py_runtime.names.printing import autolev_str, format_number, format_response
from sympy.physics.mechanics import dynamicsymbols
from sympy.physics.vector import ReferenceFrame

X, Y = dynamicsymbols("X Y")
A, B, C, D = sp.symbols("A B C D", real=True)
M0 = sp.Matrix([[A, B], [C, D]])
t = dynamicsymbols._t

_FUNCS = {
    name: getattr(sp, name.lower())
    for name in (
        "SIN",
        "COS",
        "TAN",
        "ASIN",
        "ACOS",
        "ATAN",
        "ATAN2",
        "LOG",
        "EXP",
        "SIGN",
    )
}
_FUNCS.update(ABS=sp.Abs, MAX=sp.Max, MIN=sp.Min, CEIL=sp.ceiling, FLOOR=sp.floor)


def parse_back(text: str) -> sp.Expr:
    """Read Autolev text back: names -> symbols, X' -> symbol X_d1."""
    code = re.sub(r"([A-Z][A-Z0-9_]*)('+)", lambda m: f"{m[1]}_d{len(m[2])}", text)
    code = code.replace("^", "**")
    names = set(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", code)) - set(_FUNCS) - {"i"}
    local = {n: sp.Symbol(n) for n in names}
    local.update(_FUNCS, i=sp.I)
    return sp.sympify(code, locals=local)


def plain(expr: sp.Expr) -> sp.Expr:
    """Replace variables and derivatives by the symbols parse_back makes."""
    table = {}
    for d in expr.atoms(sp.Derivative):
        table[d] = sp.Symbol(f"{d.expr.func.__name__}_d{d.derivative_count}")
    for f in expr.atoms(sp.core.function.AppliedUndef):
        table[f] = sp.Symbol(f.func.__name__)
    table[t] = sp.Symbol("T")
    return expr.xreplace(table)


def round_trip(expr: sp.Expr, tol: float = 1e-6) -> bool:
    text = autolev_str(expr)
    back = parse_back(text)
    want = plain(sp.sympify(expr))
    syms = sorted(back.free_symbols | want.free_symbols, key=str)
    names = sorted({s.name for s in syms})
    rng = random.Random(2)
    for _ in range(3):
        values = {n: sp.Float(rng.uniform(0.2, 0.9)) for n in names}
        table = {s: values[s.name] for s in syms}
        got = complex(back.xreplace(table).evalf())
        exp = complex(want.xreplace(table).evalf())
        if abs(got - exp) > tol * max(1.0, abs(exp)):
            return False
    return True


def line(label: str, value) -> str:
    (text,) = format_response(label, value)
    return text


# ------------------------------------------------------- tutor1 responses


def test_tutor1_expressions():
    e = (X + 2 * Y) ** 2 + sp.Mul(3, 7 + X, X + Y)
    assert line("E", e) == "E = (X+2*Y)^2 + 3*(7+X)*(X+Y)"
    expanded = al.expand(e, (1, 2))
    assert line("E", expanded) == "E = 21*X + 21*Y + 4*X^2 + 4*Y^2 + 7*X*Y"
    autolev_factored = (
        21 * Y + 4 * Y**2 + 4 * X * (sp.Rational(21, 4) + X + sp.Rational(7, 4) * Y)
    )
    assert line("E", autolev_factored) == "E = 21*Y + 4*Y^2 + 4*X*(5.25+X+1.75*Y)"
    factored = al.factor(expanded, X)
    assert line("E", factored) == "E = 21*Y + 4*Y^2 + X*(21+4*X+7*Y)"
    assert line("DY", factored.diff(Y)) == "DY = 21 + 7*X + 8*Y"
    assert round_trip(autolev_factored.diff(t))


def test_tutor1_taylor_and_evaluate():
    ty = sp.factor_terms(al.taylor(X * sp.cos(Y), (0, 7), [(X, 0, None), (Y, 0, None)]))
    text = autolev_str(ty)
    assert "0.001388889" in text or "0.5*Y^2" in text
    assert round_trip(ty)
    assert autolev_str(
        sp.Rational(1, 720) * X * (720 - 360 * Y**2 + 30 * Y**4 - Y**6)
    ) == ("0.001388889*X*(720-360*Y^2+30*Y^4-Y^6)")
    f = ty.subs({X: 1, Y: sp.Rational(1, 2)})
    assert line("F", f) == "F = 0.8775825"


def test_tutor1_polynomial_and_roots():
    poly = al.polynomial(sp.Matrix([A, B, C]), X)
    assert line("POLY", poly) == "POLY = C + B*X + A*X^2"
    assert line("ROOT1", al.roots(sp.Matrix([1, 2, 3, 4]))) == (
        "ROOT1 = [-1.650629; -0.1746854 - 1.546869*i; -0.1746854 + 1.546869*i]"
    )
    assert format_response("ROOT2", al.roots(poly, X, 2)) == [
        "ROOT2[1] = -0.5*(B-(B^2-4*A*C)^0.5)/A",
        "ROOT2[2] = -0.5*(B+(B^2-4*A*C)^0.5)/A",
    ]


def test_tutor1_matrices_and_zero():
    assert line("ROWMATRIX", sp.Matrix([[1, 2, 3, 4]])) == "ROWMATRIX = [1, 2, 3, 4]"
    assert line("COLMATRIX", sp.Matrix([1, 2, 3, 4])) == "COLMATRIX = [1; 2; 3; 4]"
    assert line("ZERO[1]", A * X + B * Y - 1) == "ZERO[1] = -1 + A*X + B*Y"
    assert line("ZERO[2]", C * X + D * Y - sp.pi) == "ZERO[2] = -3.141593 + C*X + D*Y"
    zero = sp.Matrix([A * X + B * Y - 1, C * X + D * Y - sp.pi])
    x, y = al.solve_linear(zero, [X, Y])
    assert line("X", x) == "X = -(3.141593*B-D)/(A*D-B*C)"
    assert line("Y", y) == "Y = (3.141593*A-C)/(A*D-B*C)"


def test_tutor1_matrix_commands():
    assert line("M0", sp.Matrix([[A, B], [C, 0]])) == "M0 = [A, B; C, 0]"
    assert line("M0[2,2]", D) == "M0[2,2] = D"
    m1 = mt.block([[M0, sp.Matrix([[1, 2], [3, 4]])]])
    assert line("M1", m1) == "M1 = [A, B, 1, 2; C, D, 3, 4]"
    assert line("M2", M0 + M0) == "M2 = [2*A, 2*B; 2*C, 2*D]"
    m3 = sp.Matrix([[A**2 + B * C, B * (A + D)], [C * (A + D), B * C + D**2]])
    assert autolev_str(m3) in (
        "[A^2 + B*C, B*(A+D); C*(A+D), B*C + D^2]",
        "[A^2 + B*C, B*(A+D); C*(A+D), D^2 + B*C]",
    )
    assert line("M4", mt.transpose(M0)) == "M4 = [A, C; B, D]"
    assert format_response("M5", mt.inv(M0)) == [
        "M5[1,1] = D/(A*D-B*C)",
        "M5[1,2] = -B/(A*D-B*C)",
        "M5[2,1] = -C/(A*D-B*C)",
        "M5[2,2] = A/(A*D-B*C)",
    ]
    assert line("M6", mt.diagmat(3, 1)) == "M6 = [1, 0, 0; 0, 1, 0; 0, 0, 1]"
    assert line("M7", mt.cols(M0, 1)) == "M7 = [A; C]"
    assert line("M8", mt.rows(M0, 2, (1, 2))) == "M8 = [C, D; A, B; C, D]"
    assert line("N1", mt.rows(M0)) == "N1 = 2"
    assert line("N2", mt.det(M0)) == "N2 = A*D - B*C"
    m9 = M0.subs({A: 1, B: 2, C: 3, D: 4})
    assert line("M9", m9) == "M9 = [1, 2; 3, 4]"
    assert line("LAMBDA", al.eig(m9)) == "LAMBDA = [-0.3722813; 5.372281]"
    values, vecs = al.eig_vectors(m9)
    assert line("EIGVALUE", values) == "EIGVALUE = [-0.3722813; 5.372281]"
    assert (
        line("EIGVEC", vecs)
        == "EIGVEC = [-0.8245648, 0.5657675; -0.4159736, -0.9093767]"
    )


# ------------------------------------------------------------- numbers


@pytest.mark.parametrize(
    "value, text",
    [
        (sp.pi, "3.141593"),
        (sp.Rational(1, 720), "0.001388889"),
        (sp.Rational(1, 12), "0.08333333"),
        (sp.Rational(21, 4), "5.25"),
        (sp.cos(sp.Rational(1, 2)), "0.8775826"),
        (sp.Integer(123456789), "123456789"),
        (sp.Float(5.0), "5"),
        (sp.Float(1e-7), "1.0E-07"),
        (sp.Float(1.5e9), "1.5E+09"),
        (-sp.sqrt(2), "-1.414214"),
        (sp.Float(12.5), "12.5"),
    ],
)
def test_numbers(value, text):
    assert autolev_str(value) == text


def test_number_digits_and_complex():
    assert autolev_str(sp.pi, digits=3) == "3.14"
    assert format_number(sp.E, 10) == "2.718281828"
    assert autolev_str(-0.1746854 - 1.546869 * sp.I) == "-0.1746854 - 1.546869*i"
    assert autolev_str(sp.I) == "i"
    assert autolev_str(-2 * sp.I) == "-2*i"
    assert autolev_str(3 * sp.I * A) == "3*i*A"
    assert autolev_str((1 + 2 * sp.I) * A) == "(1+2*i)*A"
    assert autolev_str(sp.Matrix([1 + sp.I, A])) == "[1 + i; A]"
    with pytest.raises(ValueError):
        autolev_str(A, digits=0)


def test_numeric_subexpressions_collapse():
    assert autolev_str(-sp.pi + C * X) == "-3.141593 + C*X"
    assert autolev_str(sp.pi * A / 2) == "1.570796*A"
    assert autolev_str(sp.sqrt(2) * A + sp.sin(1)) == "0.841471 + 1.414214*A"
    assert autolev_str(A / (2 * B)) == "0.5*A/B"


# ------------------------------------------------------ expression forms


def test_names_variables_derivatives():
    q = dynamicsymbols("qa")
    assert autolev_str(q) == "QA"
    assert autolev_str(X.diff(t)) == "X'"
    assert autolev_str(X.diff(t, 2)) == "X''"
    assert autolev_str(t * A) == "A*T"
    assert autolev_str(sp.Symbol("mass_a")) == "MASS_A"
    assert autolev_str(sp.Derivative(sp.sin(X), t)) == "DT(SIN(X))"


def test_functions():
    assert autolev_str(sp.sin(X - Y) * A) == "A*SIN(X-Y)"
    assert autolev_str(sp.cos(X)) == "COS(X)"
    assert autolev_str(sp.acos(A)) == "ACOS(A)"
    assert autolev_str(sp.atan2(A, B)) == "ATAN2(A, B)"
    assert autolev_str(sp.log(A) + sp.exp(B)) in ("LOG(A) + EXP(B)", "EXP(B) + LOG(A)")
    assert autolev_str(sp.Abs(X)) == "ABS(X)"
    assert autolev_str(sp.sign(X)) == "SIGN(X)"
    assert autolev_str(sp.Max(A, B, C)) == "MAX(A, MAX(B, C))"
    from al2py_runtime.functions import nint, trunc

    assert autolev_str(trunc(A) + nint(B)) in ("INT(A) + ROUND(B)", "ROUND(B) + INT(A)")


def test_powers_and_quotients():
    assert autolev_str(sp.sqrt(A)) == "A^0.5"
    assert autolev_str(1 / sp.sqrt(A)) in ("1/A^0.5", "A^-0.5")
    assert autolev_str(A**-2) == "1/A^2"
    assert autolev_str(A / (B * C)) == "A/(B*C)"
    assert autolev_str(-A / B) == "-A/B"
    assert autolev_str(A * B / (C + D) ** 2) == "A*B/(C+D)^2"
    assert autolev_str(X ** (A + B)) == "X^(A+B)"
    assert autolev_str((A * B) ** C) == "(A*B)^C"
    assert autolev_str((-A) ** B) == "(-A)^B"
    assert autolev_str(2 ** (-X)) == "2^(-X)"
    assert autolev_str((X**A) ** B) == "(X^A)^B"


@pytest.mark.parametrize(
    "expr",
    [
        (X + 2 * Y) ** 2 - 3 * (7 + X) * (X + Y) / (A - B),
        -(A - B) / (C - D) ** 3 + sp.sqrt(A**2 + B**2),
        sp.sin(X - Y) ** 2 / (1 - sp.cos(A) * B) - X.diff() * Y.diff(t, 2),
        A ** (-B) * (C - D) ** sp.Rational(-1, 3) - sp.pi / (A * B),
        sp.atan2(A - B, C) * sp.exp(-X) + sp.log(A + 2),
        -A * B * C / (D * X) - (A - 1) * (B - 2) / ((C - 3) * (D - 4)),
        (A - B) ** 3 * (-1) - 1 / (1 - A),
    ],
)
def test_round_trip(expr):
    assert round_trip(expr)


def test_round_trip_matrix_elements():
    m = mt.inv(sp.Matrix([[A, B, 1], [C, D, 2], [1, X, 3]]))
    lines = format_response("M", m)
    assert len(lines) == 9
    for k, text in enumerate(lines):
        label, rhs = text.split(" = ")
        assert label == f"M[{k // 3 + 1},{k % 3 + 1}]"
        assert round_trip(m[k // 3, k % 3])


def test_format_response_width():
    long_row = sp.Matrix([[A * B * C * D * X * Y * (k + 1) for k in range(6)]])
    lines = format_response("V", long_row)
    assert len(lines) == 6 and lines[0] == "V[1] = A*B*C*D*X*Y"
    assert format_response("V", long_row, width=1000)[0].startswith("V = [")
    assert format_response("S", A + B) == ["S = A + B"]
    assert format_response("Z", sp.zeros(2, 1)) == ["Z = [0; 0]"]


# ------------------------------------------------- vectors and dyadics


def test_vectors():
    a, b, c = ReferenceFrame("A"), ReferenceFrame("B"), ReferenceFrame("C")
    la, lb, u1, u2 = sp.symbols("LA LB U1 U2")
    assert autolev_str(la * u1 * a.y + lb * u2 * b.y) == "LA*U1*A2> + LB*U2*B2>"
    assert autolev_str(0 * a.x) == "0>"
    assert autolev_str(a.x) == "A1>"
    assert autolev_str(-A * c.y + (A + B) * c.z) == "-A*C2> + (A+B)*C3>"
    assert autolev_str(A * a.x - B * a.z) == "A*A1> - B*A3>"


def test_dyadics_points_frames():
    from sympy.physics.vector import Point

    b = ReferenceFrame("B")
    i, j, ell, mb = sp.symbols("I J L MB")
    dyad = (
        i * (b.x | b.x)
        + (i - mb * ell**2) * (b.y | b.y)
        + (j - mb * ell**2) * (b.z | b.z)
    )
    text = autolev_str(dyad)
    assert text in (
        "I*B1>*B1> + (I-MB*L^2)*B2>*B2> + (J-MB*L^2)*B3>*B3>",
        "I*B1>*B1> + (I-L^2*MB)*B2>*B2> + (J-L^2*MB)*B3>*B3>",
    )
    assert autolev_str(0 * (b.x | b.y)) == "0>>"
    assert autolev_str(Point("BO")) == "BO"
    assert autolev_str(b) == "B"


def test_doctests():
    import doctest

    from al2py_runtime.names import printing

    assert doctest.testmod(printing).failed == 0
