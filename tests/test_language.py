"""Language coverage: every mathematical command of the tutorial's Summary.

Each case is a tiny ``.al`` snippet, converted with :func:`al2py.convert`,
imported, and checked mathematically through ``module.AUTOLEV``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp
from al2py_runtime.safety import module_source
from conftest import load_module

from al2py import convert

t = sp.Symbol("t")


# ------------------------------------------------------------------ helpers


def run(src: str, tmp_path: Path, name: str = "snip", **kw):
    """Convert ``src`` (as ``tmp_path/name.al``) and import the module."""
    path = tmp_path / f"{name}.al"
    path.write_text(src)
    result = convert(src, str(path), **kw)
    return load_module(result.code, tmp_path, f"{name}_mod")


def value(module, key: str):
    return module.AUTOLEV[key]


def same(got, want, tol: float = 1e-9) -> bool:
    """Mathematical equality of scalars or matrices (numbers within ``tol``)."""
    if isinstance(want, (list, tuple)):
        want = sp.Matrix(want)
    if isinstance(want, sp.MatrixBase) or isinstance(got, sp.MatrixBase):
        got, want = sp.Matrix(got), sp.Matrix(want)
        return got.shape == want.shape and all(
            same(g, w, tol) for g, w in zip(got, want, strict=True)
        )
    got, want = sp.sympify(got), sp.sympify(want)
    if got.is_number and want.is_number:
        return abs(complex(got.evalf(30)) - complex(want.evalf(30))) <= tol
    diff = sp.simplify(sp.expand(got - want).doit())
    return diff == 0


def check(module, key: str, want, tol: float = 1e-9) -> None:
    got = value(module, key)
    assert same(got, want, tol), f"AUTOLEV[{key!r}] = {got!r}, expected {want!r}"


# The snippets below declare these names; the expected values are written as
# functions of the module, whose attributes are the sympy symbols.
DECL = "Constants A, B, C\nVariables X', Y'\n"


# ------------------------------------------------- operators and functions

NUMERIC = [
    ("add_sub_mul_div_pow", "E = 2^3 - 7/2 + 3*4", 33 / 2),
    ("precedence", "E = -2^2 + 2*3^2/6", -1),
    ("abs", "E = Abs(-3)", 3),
    ("cos", "E = Cos(0)", 1),
    ("sin", "E = Sin(PI/6)", 0.5),
    ("tan", "E = Tan(PI/4)", 1),
    ("cosh", "E = Cosh(0)", 1),
    ("sinh", "E = Sinh(1)", float(sp.sinh(1))),
    ("tanh", "E = Tanh(1)", float(sp.tanh(1))),
    ("acos", "E = Acos(0)", float(sp.pi / 2)),
    ("asin", "E = Asin(1)", float(sp.pi / 2)),
    ("atan", "E = Atan(1)", float(sp.pi / 4)),
    ("atan2", "E = Atan2(1, -1)", float(3 * sp.pi / 4)),
    ("log", "E = Log(Exp(2))", 2),
    ("log10", "E = Log10(1000)", 3),
    ("exp", "E = Exp(0) + Exp(1)", 1 + float(sp.E)),
    ("sqr", "E = Sqr(3)", 9),
    ("sqrt", "E = Sqrt(16)", 4),
    ("factorial", "E = Factorial(5)", 120),
    ("ceil", "E = Ceil(2.3)", 3),
    ("ceil_negative", "E = Ceil(-2.3)", -2),
    ("floor", "E = Floor(2.7)", 2),
    ("floor_negative", "E = Floor(-2.7)", -3),
    ("int", "E = Int(2.7)", 2),
    ("int_truncates", "E = Int(-2.7)", -2),
    ("round", "E = Round(2.4)", 2),
    ("round_up", "E = Round(2.6)", 3),
    ("max", "E = Max(3, 7)", 7),
    ("min", "E = Min(3, 7)", 3),
    ("sign_negative", "E = Sign(-4)", -1),
    ("sign_zero", "E = Sign(0)", 0),
    ("sign_positive", "E = Sign(5)", 1),
    ("pi", "E = PI", float(sp.pi)),
    ("i", "Imaginary i\nE = i^2", -1),
    ("decimal", "E = 9.81*2", 19.62),
    ("scientific", "E = 1.5E3", 1500),
]


@pytest.mark.parametrize(
    "name, line, expected", NUMERIC, ids=[case[0] for case in NUMERIC]
)
def test_numeric_operator_or_function(name, line, expected, tmp_path):
    m = run(line + "\n", tmp_path)
    check(m, "E", expected)


SYMBOLIC = [
    ("abs", "E = Abs(A)", lambda m: sp.Abs(m.A)),
    (
        "trig",
        "E = Sin(A) + Cos(X) - Tan(B)",
        lambda m: sp.sin(m.A) + sp.cos(m.X) - sp.tan(m.B),
    ),
    (
        "hyperbolic",
        "E = Cosh(A)*Sinh(B)/Tanh(C)",
        lambda m: sp.cosh(m.A) * sp.sinh(m.B) / sp.tanh(m.C),
    ),
    (
        "inverse_trig",
        "E = Acos(A) + Asin(B) + Atan(C)",
        lambda m: sp.acos(m.A) + sp.asin(m.B) + sp.atan(m.C),
    ),
    ("atan2", "E = Atan2(A, B)", lambda m: sp.atan2(m.A, m.B)),
    ("log_exp", "E = Log(A) + Exp(B)", lambda m: sp.log(m.A) + sp.exp(m.B)),
    ("log10", "E = Log10(A)", lambda m: sp.log(m.A) / sp.log(10)),
    ("sqr_sqrt", "E = Sqr(A) + Sqrt(X)", lambda m: m.A**2 + sp.sqrt(m.X)),
    ("power_division", "E = (A + B)^3 / C", lambda m: (m.A + m.B) ** 3 / m.C),
    ("unary_minus", "E = -A*(-X)", lambda m: m.A * m.X),
    (
        "derivative_prime",
        "E = X' + 2*Y'",
        lambda m: sp.diff(m.X, t) + 2 * sp.diff(m.Y, t),
    ),
    ("time", "E = A*T^2", lambda m: m.A * t**2),
]


@pytest.mark.parametrize(
    "name, line, expected", SYMBOLIC, ids=[case[0] for case in SYMBOLIC]
)
def test_symbolic_operator_or_function(name, line, expected, tmp_path):
    m = run(DECL + line + "\n", tmp_path)
    check(m, "E", expected(m))


def test_time_is_the_sympy_time_symbol(tmp_path):
    m = run("Variables X\nE = T\nF = X\n", tmp_path)
    check(m, "E", t)
    assert value(m, "F").args == (t,)
    assert value(m, "F").free_symbols == {t}


# ------------------------------------------------------------ assignments

COMPOUND = [
    ("plus", "S += 2", lambda m: m.A + 2),
    ("minus", "S -= 2", lambda m: m.A - 2),
    ("times", "S *= 3", lambda m: 3 * m.A),
    ("divide", "S /= 2", lambda m: m.A / 2),
    ("power", "S ^= 2", lambda m: m.A**2),
    ("overwrite", "S := B + 1", lambda m: m.B + 1),
    ("self_reference", "S = S*S + 1", lambda m: m.A**2 + 1),
]


@pytest.mark.parametrize("name, line, expected", COMPOUND, ids=[c[0] for c in COMPOUND])
def test_compound_assignment(name, line, expected, tmp_path):
    m = run(DECL + "S = A\n" + line + "\n", tmp_path)
    check(m, "S", expected(m))


def test_compound_assignments_in_sequence(tmp_path):
    m = run("S = 1\nS += 2\nS -= 1\nS *= 6\nS /= 4\nS ^= 2\nR = S\nS := 7\n", tmp_path)
    check(m, "R", 9)
    check(m, "S", 7)


def test_compound_assignment_on_matrix_element(tmp_path):
    m = run("M = [1, 2; 3, 4]\nM[2,1] += 10\nM[1,2] *= 3\n", tmp_path)
    check(m, "M", [[1, 6], [13, 4]])


def test_reassignment_and_overwrite_setting(tmp_path):
    m = run("Overwrite OFF\nE = 1\nE = 2\nOverwrite ON\nE = E + 3\n", tmp_path)
    check(m, "E", 5)


def test_assigned_scalar_stays_a_name(tmp_path):
    m = run(DECL + "E = A + B\nF = 2*E\n", tmp_path)
    # F is expressed with the name E, whose value is A + B
    check(m, "F", 2 * m.E)
    check(m, "E", m.A + m.B)


# ---------------------------------------------------------- declarations


def test_constants_signs_and_values(tmp_path):
    m = run("Constants A, B+, C-, G = 9.81, K=3\nE = G*K\n", tmp_path)
    assert m.A.is_real
    assert m.B.is_nonnegative
    assert m.C.is_nonpositive
    check(m, "G", sp.Rational(981, 100))
    check(m, "K", 3)
    check(m, "E", sp.Rational(2943, 100))


def test_variables_primes_and_indices(tmp_path):
    m = run("Variables X'', U{3}', Q{1:2,1:2}\nE = X'' + U3' + Q21\n", tmp_path)
    for name in ["X", "U1", "U2", "U3", "Q11", "Q12", "Q21", "Q22"]:
        v = value(m, name)
        assert isinstance(v, sp.Function) or v.func.__name__ == name
        assert str(v.func) == name and v.args == (t,)
    assert "Q3" not in m.AUTOLEV and "U4" not in m.AUTOLEV
    check(
        m,
        "E",
        sp.diff(value(m, "X"), t, 2) + sp.diff(value(m, "U3"), t) + value(m, "Q21"),
    )


def test_variables_index_range(tmp_path):
    m = run("Variables V{2:4}\nE = V2 + V4\n", tmp_path)
    assert "V1" not in m.AUTOLEV and "V5" not in m.AUTOLEV
    check(m, "E", value(m, "V2") + value(m, "V4"))


def test_specified_with_definition(tmp_path):
    m = run(
        "Constants A\nSpecified F\nF = A*T^2\nE = Dt(F)\nG = Explicit(F')\n", tmp_path
    )
    check(m, "F", m.A * t**2)
    check(m, "E", 2 * m.A * t)
    check(m, "G", 2 * m.A * t)


def test_imaginary_declaration(tmp_path):
    m = run("Imaginary j\nE = j^2\nF = (1 + j)*(1 - j)\n", tmp_path)
    check(m, "E", -1)
    check(m, "F", 2)


def test_declared_i_and_pi(tmp_path):
    # Autolev has no predefined imaginary unit: `Imaginary i` declares it.
    m = run("Imaginary i\nE = Exp(i*PI)\nF = i*i*PI\n", tmp_path)
    check(m, "E", -1)
    check(m, "F", -sp.pi)


def test_case_insensitive_lookup(tmp_path):
    m = run("Constants Abc\nxyz = 2*aBC\n", tmp_path)
    check(m, "XYZ", 2 * m.Abc)
    check(m, "xyz", 2 * m.Abc)


# ---------------------------------------------------------------- matrices


def test_matrix_literals_and_element_reads(tmp_path):
    m = run(
        "R = [1, 2, 3]\nC = [4; 5; 6]\nM = [1, 2; 3, 4]\n"
        "E1 = R[2]\nE2 = C[3]\nE3 = M[2,1]\nE4 = M[1,2]\n",
        tmp_path,
    )
    check(m, "R", [[1, 2, 3]])
    check(m, "C", [[4], [5], [6]])
    check(m, "E1", 2)
    check(m, "E2", 6)
    check(m, "E3", 3)
    check(m, "E4", 2)
    check(m, "M[2,1]", 3)
    check(m, "C[2]", 5)


def test_matrix_growth(tmp_path):
    m = run(DECL + "Zero[1] = X - A\nZero[3] = Y\nE = Zero[2]\n", tmp_path)
    check(m, "ZERO", [[m.X - m.A], [0], [m.Y]])
    check(m, "E", 0)
    check(m, "ZERO[3]", m.Y)


def test_matrix_element_growth_pads_with_zeros(tmp_path):
    m = run("M = [1, 2; 3, 4]\nM[3,3] = 9\n", tmp_path)
    check(m, "M", [[1, 2, 0], [3, 4, 0], [0, 0, 9]])


def test_block_matrix(tmp_path):
    m = run("M = [1, 2; 3, 4]\nB = [M, [5; 6]]\n", tmp_path)
    check(m, "B", [[1, 2, 5], [3, 4, 6]])


def test_matrix_operators(tmp_path):
    m = run(
        "M = [1, 2; 3, 4]\nN = [0, 1; 1, 0]\nS = M + N\nD = M - N\nP = M*N\nK = 2*M\n",
        tmp_path,
    )
    check(m, "S", [[1, 3], [4, 4]])
    check(m, "D", [[1, 1], [2, 4]])
    check(m, "P", [[2, 1], [4, 3]])
    check(m, "K", [[2, 4], [6, 8]])


MATRIX_COMMANDS = [
    ("cols_count", "E = Cols([1, 2, 3; 4, 5, 6])", 3),
    (
        "cols_select",
        "E = Cols([1, 2, 3, 4; 5, 6, 7, 8], 1, 3, 4)",
        [[1, 3, 4], [5, 7, 8]],
    ),
    ("det", "E = Det([1, 2; 3, 4])", -2),
    ("diagmat_square", "E = DiagMat(3, 7)", sp.diag(7, 7, 7)),
    ("diagmat_rect", "E = DiagMat(2, 3, 5)", [[5, 0, 0], [0, 5, 0]]),
    ("eig_values", "E = Eig([2, 1; 1, 2])", [[1], [3]]),
    ("element", "E = Element([1, 2, 3; 4, 5, 6], 2, 3)", 6),
    (
        "inv",
        "E = Inv([1, 2; 3, 4])",
        [[-2, 1], [sp.Rational(3, 2), -sp.Rational(1, 2)]],
    ),
    ("rows_count", "E = Rows([1, 2, 3; 4, 5, 6])", 2),
    (
        "rows_select",
        "E = Rows([1; 2; 3; 4; 5; 6; 7], 1:3, 5:7)",
        [[1], [2], [3], [5], [6], [7]],
    ),
    ("trace", "E = Trace([1, 2; 3, 4])", 5),
    ("transpose", "E = Transpose([1, 2, 3])", [[1], [2], [3]]),
]


@pytest.mark.parametrize(
    "name, line, expected", MATRIX_COMMANDS, ids=[c[0] for c in MATRIX_COMMANDS]
)
def test_matrix_command(name, line, expected, tmp_path):
    m = run(line + "\n", tmp_path)
    check(m, "E", expected)


def test_symbolic_matrix_commands(tmp_path):
    m = run(
        DECL + "M = [A, B; C, 0]\nD1 = Det(M)\nI1 = Inv(M)\nT1 = Trace(M)\n"
        "M[2,2] := X\nD2 = Det(M)\n",
        tmp_path,
    )
    check(m, "D1", -m.B * m.C)
    check(m, "I1", sp.Matrix([[m.A, m.B], [m.C, 0]]).inv())
    check(m, "T1", m.A)
    check(m, "D2", m.A * m.X - m.B * m.C)


def test_eig_with_eigenvectors(tmp_path):
    m = run("M = [2, 1; 1, 2]\nEig(M, LAM, VEC)\n", tmp_path)
    check(m, "LAM", [[1], [3]])
    vec = sp.Matrix(value(m, "VEC"))
    mat = sp.Matrix([[2, 1], [1, 2]])
    for k, lam in enumerate([1, 3]):
        row = vec[k, :].T  # eigenvectors are the rows
        assert same(row.norm(), 1, 1e-9)
        assert same(mat * row - lam * row, [[0], [0]], 1e-9)


def test_eig_numeric_sorted(tmp_path):
    m = run("E = Eig([4, 0, 0; 0, -1, 0; 0, 0, 2])\n", tmp_path)
    check(m, "E", [[-1], [2], [4]])


# ---------------------------------------------------- mathematical commands


def test_partial_and_total_derivatives(tmp_path):
    m = run(DECL + "E = A*X^2*Y\nD1 = D(E, X)\nD2 = D(E, A)\nD3 = Dt(E)\n", tmp_path)
    X, Y = value(m, "X"), value(m, "Y")
    check(m, "D1", 2 * m.A * X * Y)
    check(m, "D2", X**2 * Y)
    check(m, "D3", sp.diff(m.A * X**2 * Y, t))


def test_d_of_a_matrix_with_respect_to_a_matrix(tmp_path):
    m = run(DECL + "P = [A*X + B*Y; X*Y]\nJ = D(P, [X, Y])\n", tmp_path)
    X, Y = value(m, "X"), value(m, "Y")
    check(m, "J", [[m.A, m.B], [Y, X]])


def test_evaluate(tmp_path):
    m = run(
        DECL + "E = A*X + B\nF = Evaluate(E, A=2, X=3)\nG = Evaluate(E, A=X)\n",
        tmp_path,
    )
    check(m, "F", 6 + m.B)
    check(m, "G", value(m, "X") ** 2 + m.B)


def test_evaluate_with_derivatives(tmp_path):
    m = run(
        DECL + "E = X*X' + Y\nF = Evaluate(E, X'=0)\nG = Evaluate(E, X=2, X'=3)\n",
        tmp_path,
    )
    check(m, "F", value(m, "Y"))
    check(m, "G", 6 + value(m, "Y"))


def test_evaluate_matrix(tmp_path):
    m = run(DECL + "M = [A, B; C, 0]\nN = Evaluate(M, A=1, B=2, C=3)\n", tmp_path)
    check(m, "N", [[1, 2], [3, 0]])


def test_polynomial_both_ways(tmp_path):
    m = run(
        DECL + "P = Polynomial([A, B, C], X)\nQ = Polynomial(A*X^2 + B*X + C, X, 2)\n"
        "R = Polynomial([1; 2; 3], X)\n",
        tmp_path,
    )
    X = value(m, "X")
    check(m, "P", m.A * X**2 + m.B * X + m.C)
    check(m, "Q", [[m.A], [m.B], [m.C]])
    check(m, "R", X**2 + 2 * X + 3)


def test_roots_of_coefficients(tmp_path):
    m = run("R = Roots([1, 0, -4])\nS = Roots([1; 2; 3; 4])\n", tmp_path)
    check(m, "R", [[-2], [2]])
    roots = [complex(r) for r in value(m, "S")]
    assert len(roots) == 3
    for r in roots:
        assert abs(r**3 + 2 * r**2 + 3 * r + 4) < 1e-6


def test_roots_of_polynomial(tmp_path):
    m = run(
        DECL + "R = Roots(X^2 - 5*X + 6, X)\nS = Roots(A*X^2 + B*X + C, X, 2)\n",
        tmp_path,
    )
    check(m, "R", [[2], [3]])
    X = value(m, "X")
    for r in value(m, "S"):
        assert same((m.A * X**2 + m.B * X + m.C).subs(X, r), 0)


def test_solve_assigns_unknowns(tmp_path):
    m = run(
        "Variables X, Y\nZero[1] = -37 + 3*X + 4*Y\nZero[2] = 2 + 4*X - 2*Y\n"
        "Solve(Zero, X, Y)\nS = X + Y\n",
        tmp_path,
    )
    check(m, "X", 3)
    check(m, "Y", 7)
    check(m, "S", 10)


def test_solve_symbolic(tmp_path):
    m = run(DECL + "EQ = [A*X + B*Y - 1; C*X - Y]\nSolve(EQ, X, Y)\n", tmp_path)
    den = m.A + m.B * m.C
    check(m, "X", 1 / den)
    check(m, "Y", m.C / den)


def test_solve_assigns_derivatives(tmp_path):
    m = run(
        "Variables U{2}'\nEQ[1] = U1' + U2' - 3\nEQ[2] = U1' - U2' - 1\n"
        "Solve(EQ, U{1:2}')\nS = U1' - U2'\n",
        tmp_path,
    )
    check(m, "U1'", 2)
    check(m, "U2'", 1)
    check(m, "S", 1)


TAYLOR = [
    ("range", "E = Taylor(Sin(X), 0:3, X=0)", lambda X, m: X - X**3 / 6),
    ("order_only", "E = Taylor(Cos(X), 2, X=0)", lambda X, m: 1 - X**2 / 2),
    (
        "about_a_point",
        "E = Taylor(Exp(X), 0:2, X=A)",
        lambda X, m: sp.exp(m.A) * (1 + (X - m.A) + (X - m.A) ** 2 / 2),
    ),
    (
        "two_variables",
        "E = Taylor(X*Cos(Y), 0:3, X=0, Y=0)",
        lambda X, m: X - X * m.AUTOLEV["Y"] ** 2 / 2,
    ),
]


@pytest.mark.parametrize("name, line, expected", TAYLOR, ids=[c[0] for c in TAYLOR])
def test_taylor(name, line, expected, tmp_path):
    m = run(DECL + line + "\n", tmp_path)
    check(m, "E", expected(value(m, "X"), m))


def test_taylor_perturbation_form(tmp_path):
    m = run(
        DECL + "Variables dX', dA\n"
        "E = Taylor(X^2, 0:2, X=A:dA)\n"
        "F = Taylor(Sin(X) + X', 1, X=0:dX, X'=0:dX')\n"
        "G = Taylor(X*X', 1, X=0:dX, X'=0:dX')\n",
        tmp_path,
    )
    dA, dX = value(m, "DA"), value(m, "DX")
    check(m, "E", (m.A + dA) ** 2)
    check(m, "F", dX + sp.diff(dX, t))
    check(m, "G", 0)


# ------------------------------------------------- simplification commands


def test_dual_functions_alone(tmp_path):
    m = run(
        DECL + "E = (X + 2*Y)^2\nExpand(E)\n"
        "F = A*X + B*X + A\nFactor(F, X)\n"
        "G = A*X^2 + B*X^2 + C*X + A*X\nArrange(G, 2, X)\n"
        "H = X + A\nK = 2*H\nExplicit(K)\n"
        "Z = A*X + B\nZee(Z)\n",
        tmp_path,
    )
    X, Y = value(m, "X"), value(m, "Y")
    e = value(m, "E")
    check(m, "E", X**2 + 4 * X * Y + 4 * Y**2)
    assert isinstance(e, sp.Add), e  # expanded
    check(m, "F", m.A + (m.A + m.B) * X)
    check(m, "G", (m.A + m.B) * X**2 + (m.A + m.C) * X)
    check(m, "K", 2 * X + 2 * m.A)
    assert m.H not in value(m, "K").free_symbols  # explicit: H is gone
    check(m, "Z", m.A * X + m.B)


def test_expand_degree_range(tmp_path):
    m = run(DECL + "E = (X + 1)^3\nF = Expand(E, 2:3)\nG = Expand(E, 0:1)\n", tmp_path)
    X = value(m, "X")
    check(m, "F", X**3 + 3 * X**2)
    check(m, "G", 3 * X + 1)


def test_dual_functions_on_the_right(tmp_path):
    m = run(
        DECL + "E = (A + B)*(X + 1)\nF = Expand(E)\nG = Factor(A*X + B*X, X)\n"
        "H = Arrange(A*X + B*X + C, 1, X)\nK = Explicit(F)\nZ = Zee(A*X + A, X)\n",
        tmp_path,
    )
    X = value(m, "X")
    check(m, "F", m.A * X + m.A + m.B * X + m.B)
    check(m, "G", (m.A + m.B) * X)
    check(m, "H", (m.A + m.B) * X + m.C)
    check(m, "K", (m.A + m.B) * (X + 1))
    check(m, "Z", m.A * (X + 1))


SIMPLIFY = [
    ("coef", "E = Coef(A*X + B*Y + C, X)", lambda m: m.A),
    ("exclude", "E = Exclude(A*X + B*Y*X + C, X)", lambda m: m.C),
    ("include", "E = Include(A*X + B*Y + C, X)", lambda m: m.A * m.X),
    ("replace", "E = Replace(A*Sin(X) + B, Sin(X)=3)", lambda m: 3 * m.A + m.B),
    ("epsilon", "E = Epsilon(1.00001*A + 2.99, 0.1)", lambda m: m.A + 3),
    ("autoz_function", "E = AutoZ(A*X + 1, X)", lambda m: m.A * m.X + 1),
    ("zee_with_x", "E = Zee(A*X + B*X, X)", lambda m: (m.A + m.B) * m.X),
]


@pytest.mark.parametrize("name, line, expected", SIMPLIFY, ids=[c[0] for c in SIMPLIFY])
def test_simplification_command(name, line, expected, tmp_path):
    m = run(DECL + line + "\n", tmp_path)
    check(m, "E", expected(m))


def test_rhs(tmp_path):
    m = run(DECL + "E = A + B\nF = RHS(E)\nG = 2*E\n", tmp_path)
    check(m, "F", m.A + m.B)
    check(m, "G", 2 * m.E)


# ---------------------------------------------------------------- settings


def test_degrees_on(tmp_path):
    m = run(
        "Degrees ON\nConstants X\nS = SIN(30)\nC = ACOS(0.5)\nA2 = Atan2(1, 1)\n"
        "T1 = Tan(45)\nK = Evaluate(Cos(X), X=60)\nSy = Sin(X)\n",
        tmp_path,
    )
    check(m, "S", 0.5)
    check(m, "C", 60)
    check(m, "A2", 45)
    check(m, "T1", 1)
    check(m, "K", 0.5)
    assert value(m, "SY").has(sp.sin)


def test_degrees_off_again(tmp_path):
    m = run("Degrees ON\nS = Sin(90)\nDegrees OFF\nR = Acos(0.5)\n", tmp_path)
    check(m, "S", 1)
    check(m, "R", float(sp.pi / 3))


def test_digits_changes_the_transcript(tmp_path):
    m = run("Digits 3\nE = 1/3\nDigits 10\nF = 2/3\nG = PI\n", tmp_path)
    lines = m.al.transcript(module_source(m.__file__))
    responses = [line for line in lines if line.startswith("->")]
    assert responses[0].endswith("E = 0.333")
    assert responses[1].endswith("F = 0.6666666667")
    assert responses[2].endswith("G = 3.141592654")
    check(m, "E", sp.Rational(1, 3))


def test_default_digits(tmp_path):
    m = run("E = 1/3\n", tmp_path)
    lines = m.al.transcript(module_source(m.__file__))
    assert lines == ["(1) E = 1/3", "-> (2) E = 0.3333333"]


@pytest.mark.parametrize(
    "setting, c_value, d_keeps_c",
    [("OFF", "A + B", True), ("ON", "7 + B", True), ("ALL", "7 + B", False)],
)
def test_autorhs(setting, c_value, d_keeps_c, tmp_path):
    m = run(
        f"AutoRHS {setting}\nConstants B\nA = 7\nC = A + B\nD = C*SIN(C)\n", tmp_path
    )
    want_c = sp.sympify(c_value, locals={"A": m.A, "B": m.B})
    check(m, "C", want_c)
    d = value(m, "D")
    if d_keeps_c:
        assert m.C in d.free_symbols
        check(m, "D", m.C * sp.sin(m.C))
    else:
        check(m, "D", (7 + m.B) * sp.sin(7 + m.B))


def test_factoring(tmp_path):
    m = run(
        "Factoring OFF\nConstants A, B, C\nX = A*B + A*C + A^2\n"
        "Factoring ON\nY = A*B + A*C + A^2\nZ = A/C + B/C\n",
        tmp_path,
    )
    assert isinstance(value(m, "X"), sp.Add)
    assert isinstance(value(m, "Y"), sp.Mul)
    check(m, "X", m.A * (m.A + m.B + m.C))
    check(m, "Y", m.A * (m.A + m.B + m.C))
    z = value(m, "Z")
    check(m, "Z", (m.A + m.B) / m.C)
    assert sp.fraction(z)[1] == m.C


def test_autoepsilon(tmp_path):
    m = run(
        "Constants X\nAutoEpsilon 0.01\nE = 2.001*X\nAutoEpsilon 1e-7\nF = 2.001*X\n",
        tmp_path,
    )
    check(m, "E", 2 * m.X)
    check(m, "F", sp.Rational(2001, 1000) * m.X)


def test_complex_setting(tmp_path):
    m = run("Complex ON\nConstants Z\nComplex OFF\nConstants W\n", tmp_path)
    assert m.Z.is_real is None
    assert m.W.is_real is True


def test_autoz_and_overwrite_are_accepted(tmp_path):
    m = run(
        "Constants A\nVariables X\nAutoZ ON\nE = Zee(A*X + 1)\nAutoZ OFF\n"
        "Overwrite ON\nF = E\nOverwrite OFF\n",
        tmp_path,
    )
    check(m, "E", m.A * value(m, "X") + 1)


# ---------------------------------------------------- files: RUN, SAVE, macros


def test_run_other_file(tmp_path):
    (tmp_path / "other.al").write_text("Constants K\nW = K + 1\n")
    m = run("Constants A\nRUN other.al\nV = W*A\n", tmp_path, name="main")
    check(m, "W", m.K + 1)
    check(m, "V", m.W * m.A)


def test_save_writes_transcript_only_when_run(tmp_path):
    src = "Constants A\nE = A + 1\nSave x.all\n"
    (tmp_path / "saver.al").write_text(src)
    code = convert(src, str(tmp_path / "saver.al")).code
    work = tmp_path / "work"
    work.mkdir()
    (work / "saver.py").write_text(code)
    imp = subprocess.run(
        [sys.executable, "-c", "import saver"],
        capture_output=True,
        text=True,
        cwd=work,
        timeout=300,
    )
    assert imp.returncode == 0, imp.stderr
    assert not (work / "x.all").exists()
    run_ = subprocess.run(
        [sys.executable, "saver.py"],
        capture_output=True,
        text=True,
        cwd=work,
        timeout=300,
    )
    assert run_.returncode == 0, run_.stderr
    saved = (work / "x.all").read_text()
    assert "(2) E = A + 1" in saved
    assert "-> (3) E = 1 + A" in saved or "-> (3) E = A + 1" in saved
    assert run_.stdout.splitlines()[:3] == saved.splitlines()[:3]


MACRO = """% MK.A: assigns #2#N
if( #NUM_ARGS# == 2 )
  { #2#N = #NUM_ARGS# }
else
  { #2#N = 10*(#1#) }
"""


def test_a_macro_with_num_args_and_if_else(tmp_path):
    (tmp_path / "mk.a").write_text(MACRO)
    m = run("Constants A\nMK(A, P)\nMK(A, Q, 3)\n", tmp_path, name="macros")
    check(m, "PN", 2)
    check(m, "QN", 10 * m.A)


def test_r_macro_returns_a_value(tmp_path):
    (tmp_path / "twice.r").write_text("% TWICE.R\n2*(#1#)\n")
    m = run("Constants A\nE = TWICE(A + 1)\n", tmp_path, name="rmac")
    check(m, "E", 2 * m.A + 2)


def test_tutorial_power_macro(tmp_path):
    (tmp_path / "power.a").write_text("#2#SQ = (#1#)^2\n#2#CUBE = (#1#)^3\n")
    m = run("POWER(3,A)\nConstants A,B\nPOWER(A+B,ED)\n", tmp_path, name="pw")
    check(m, "ASQ", 9)
    check(m, "ACUBE", 27)
    check(m, "EDSQ", (m.A + m.B) ** 2)
    check(m, "EDCUBE", (m.A + m.B) ** 3)


def test_autolevpath_lookup(tmp_path, monkeypatch):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "twice.r").write_text("2*(#1#)\n")
    script = tmp_path / "script"
    script.mkdir()
    src = "Constants A\nE = TWICE(A)\n"
    monkeypatch.setenv("AUTOLEVPATH", str(lib))
    m = run(src, script, name="pathed")
    check(m, "E", 2 * m.A)
    monkeypatch.delenv("AUTOLEVPATH")
    from al2py.errors import AutolevError

    with pytest.raises(AutolevError):
        convert(src, str(script / "pathed.al"))


def test_exit_ends_the_script(tmp_path):
    m = run("E = 1\nExit\nF = 2\n", tmp_path)
    check(m, "E", 1)
    assert "F" not in m.AUTOLEV


def test_continuation_line(tmp_path):
    m = run(DECL + "E = A + &\n    B\n", tmp_path)
    check(m, "E", m.A + m.B)
