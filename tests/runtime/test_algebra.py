"""Tests for al2py_runtime.algebra (Autolev mathematical/simplification commands)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime import algebra as al
from sympy.physics.mechanics import dynamicsymbols

X, Y = dynamicsymbols("X Y")
U1, U2, THETA = dynamicsymbols("U1 U2 THETA")
DX, DU1, DU2, DTHETA = dynamicsymbols("DX DU1 DU2 DTHETA")
A, B, C, D, G = sp.symbols("A B C D G", real=True)
t = dynamicsymbols._t


def same(a, b) -> bool:
    """Equal symbolically (simplify) or at random numeric points."""
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        a, b = sp.Matrix(a), sp.Matrix(b)
        return a.shape == b.shape and all(same(p, q) for p, q in zip(a, b, strict=True))
    diff = sp.sympify(a) - sp.sympify(b)
    if sp.simplify(diff) == 0:
        return True
    atoms = sorted(
        diff.atoms(sp.Derivative) | diff.atoms(sp.Function) | diff.free_symbols,
        key=sp.default_sort_key,
        reverse=True,
    )
    rng = random.Random(1)
    for _ in range(3):
        table = {x: sp.Float(rng.uniform(0.3, 1.7)) for x in atoms if not x.is_number}
        value = complex(diff.xreplace(table).evalf())
        if abs(value) > 1e-9:
            return False
    return True


E = (X + 2 * Y) ** 2 + 3 * (7 + X) * (X + Y)


# ------------------------------------------------------------------ expand


def test_expand_tutor1():
    out = al.expand(E, (1, 2))
    assert sp.expand(out - (21 * X + 21 * Y + 4 * X**2 + 4 * Y**2 + 7 * X * Y)) == 0


def test_expand_degree_filter_uses_variables():
    y = A * (1 + X) ** 3
    assert sp.expand(al.expand(y, (2, 3)) - (3 * A * X**2 + A * X**3)) == 0
    assert al.expand(y, (0, 0)) == A
    # no variables: degrees in all symbols
    assert (
        sp.expand(al.expand((A + B) ** 2 + A, (2, 2)) - (A**2 + 2 * A * B + B**2)) == 0
    )


def test_expand_keeps_function_arguments_and_matrix():
    y = sp.sin(X * (X + 1)) * (A + B)
    out = al.expand(y)
    assert out == A * sp.sin(X * (X + 1)) + B * sp.sin(X * (X + 1))
    m = al.expand(sp.Matrix([(A + B) ** 2, A * (X + 1)]))
    assert m == sp.Matrix([A**2 + 2 * A * B + B**2, A * X + A])


def test_expand_range_errors():
    with pytest.raises(ValueError, match="range"):
        al.expand(E, (2, 1))


# ------------------------------------------------------------------ factor


def test_factor_on_x_tutor1():
    expanded = 21 * X + 21 * Y + 4 * X**2 + 4 * Y**2 + 7 * X * Y
    out = al.factor(expanded, X)
    assert out == 21 * Y + 4 * Y**2 + X * (21 + 4 * X + 7 * Y)
    assert same(out, expanded)


def test_factor_plain_and_several():
    assert al.factor(A * B + A * C + A**2) == A * (A + B + C)
    zero = G * A * sp.sin(X - Y) + G * B * sp.sin(X - Y) + C * sp.sin(X - Y) + D
    out = al.factor(zero, G, sp.sin(X - Y))
    assert same(out, zero)
    assert out.count(sp.sin(X - Y)) == 1
    assert out.count(G) == 1


def test_factor_keeps_derivatives_apart():
    y = A * X + B * X * X.diff() + C * X.diff()
    out = al.factor(y, X)
    assert same(out, y)
    assert out == C * X.diff() + X * (A + B * X.diff())


def test_factor_nested_and_matrix():
    y = A * (G * B + G * C + D)
    assert al.factor(y, G) == A * (D + G * (B + C))
    m = al.factor(sp.Matrix([G * A + G * B, G]), G)
    assert m == sp.Matrix([G * (A + B), G])


# ------------------------------------------------------------------ taylor


def test_taylor_tutor1():
    ty = al.taylor(X * sp.cos(Y), (0, 7), [(X, 0, None), (Y, 0, None)])
    expected = X * (720 + 30 * Y**4 - 360 * Y**2 - Y**6) / 720
    assert sp.expand(ty - expected) == 0
    f = ty.subs({X: 1, Y: sp.Rational(1, 2)})
    assert abs(float(f) - 0.8775825) < 5e-8


def test_taylor_single_order_and_nonzero_point():
    out = al.taylor(sp.exp(A), 2, [(A, 1, None)])
    expected = sp.E * (1 + (A - 1) + (A - 1) ** 2 / 2)
    assert same(out, expected)
    assert al.taylor(sp.sin(A) * B, (1, 1), [(A, 0, None)]) == A * B


def test_taylor_perturbation_with_derivatives():
    zero = sp.Matrix(
        [
            sp.sin(THETA) * U1**2 + U1.diff() * sp.cos(THETA) + G * sp.sin(THETA),
            U2.diff() * U1 + X * sp.cos(THETA) + U2,
        ]
    )
    points = [
        (X, 0, DX),
        (THETA, 0, DTHETA),
        (U1, 0, DU1),
        (U2, 0, DU2),
        (U1.diff(), 0, DU1.diff()),
        (U2.diff(), 0, DU2.diff()),
    ]
    out = al.taylor(zero, 1, points)
    assert same(out[0], DU1.diff() + G * DTHETA)
    assert same(out[1], DX + DU2)


def test_taylor_derivative_not_confused_with_variable():
    y = U1 + 3 * U1.diff()
    out = al.taylor(y, 1, [(U1, 2, None)])
    assert same(out, y)
    out = al.taylor(U1.diff() ** 2 * U1, (0, 1), [(U1, 0, DU1)])
    assert same(out, DU1 * U1.diff() ** 2)


def test_taylor_errors():
    with pytest.raises(ValueError):
        al.taylor(X, 2, [])
    with pytest.raises(ValueError):
        al.taylor(X, 2, [(X + Y, 0, None)])


# -------------------------------------------------------------- polynomial


def test_polynomial_both_ways():
    poly = al.polynomial(sp.Matrix([A, B, C]), X)
    assert poly == A * X**2 + B * X + C
    assert al.polynomial(poly, X) == sp.Matrix([A, B, C])
    assert al.polynomial(A * X + C, X, 3) == sp.Matrix([0, 0, A, C])
    assert al.polynomial(sp.expand((X.diff() + 1) ** 2), X.diff()) == sp.Matrix(
        [1, 2, 1]
    )
    with pytest.raises(ValueError, match="not a polynomial"):
        al.polynomial(sp.sin(X), X)
    with pytest.raises(ValueError, match="degree"):
        al.polynomial(X**3, X, 2)


# ------------------------------------------------------------------- roots


def test_roots_numeric_tutor1():
    r = al.roots(sp.Matrix([1, 2, 3, 4]))
    expected = [-1.650629, -0.1746854 - 1.546869j, -0.1746854 + 1.546869j]
    assert r.shape == (3, 1)
    for got, want in zip(r, expected, strict=True):
        assert abs(complex(got) - want) < 1e-6
    assert r[0].is_real


def test_roots_integer_and_leading_zero():
    assert al.roots(sp.Matrix([0, 1, -3, 2])) == sp.Matrix([1, 2])
    with pytest.raises(ValueError):
        al.roots(sp.Matrix([0, 5]))


def test_roots_symbolic_quadratic_tutor1():
    poly = C + B * X + A * X**2
    r = al.roots(poly, X, 2)
    disc = sp.sqrt(B**2 - 4 * A * C)
    assert same(r[0], (-B + disc) / (2 * A))
    assert same(r[1], (-B - disc) / (2 * A))
    for root in r:
        assert sp.simplify(poly.subs(X, root)) == 0


def test_roots_symbolic_linear_and_cubic():
    assert same(al.roots(A * X + B, X, 1)[0], -B / A)
    r = al.roots(X**3 - A**3, X, 3)
    assert len(r) == 3
    assert all(sp.simplify(root**3 - A**3) == 0 for root in r)
    # numeric coefficients in Roots(y, x, n) go through numpy
    assert al.roots(X**2 - 3 * X + 2, X, 2) == sp.Matrix([1, 2])


# --------------------------------------------------------------------- eig


def test_eig_tutor1():
    m9 = sp.Matrix([[1, 2], [3, 4]])
    lam = al.eig(m9)
    assert lam.shape == (2, 1)
    assert abs(lam[0] + 0.3722813) < 1e-7 and abs(lam[1] - 5.372281) < 1e-6
    values, vecs = al.eig_vectors(m9)
    assert values == lam
    expected = [[-0.8245648, 0.5657675], [-0.4159736, -0.9093767]]
    for i in range(2):
        for j in range(2):
            assert abs(vecs[i, j] - expected[i][j]) < 1e-7
        # row k is the eigenvector of value k
        v = vecs.row(i).T
        assert (m9 * v - values[i] * v).norm() < 1e-9


def test_eig_symmetric_clean_numbers():
    rot = sp.Matrix([[1, 2, 2], [2, 1, -2], [2, -2, 1]]) / 3
    inertia = rot * sp.diag(14, 5, 13) * rot.T
    values, vecs = al.eig_vectors(inertia)
    assert values == sp.Matrix([5, 13, 14])
    assert all(v.is_Integer for v in values)
    for k in range(3):
        v = vecs.row(k).T
        assert abs(v.norm() - 1) < 1e-12
        assert (inertia * v - values[k] * v).norm() < 1e-9


def test_eig_complex_and_symbolic():
    assert al.eig(sp.Matrix([[0, -1], [1, 0]])) == sp.Matrix([-sp.I, sp.I])
    lam = al.eig(sp.Matrix([[A, 1], [0, A]]))
    assert list(lam) == [A, A]
    values, vecs = al.eig_vectors(sp.Matrix([[A, 0], [0, B]]))
    assert set(values) == {A, B}
    for k in range(2):
        assert sp.simplify(vecs.row(k).norm() - 1) == 0
    with pytest.raises(ValueError, match="square"):
        al.eig(sp.Matrix([[1, 2]]))
    with pytest.raises(ValueError, match="defective"):
        al.eig_vectors(sp.Matrix([[A, 1], [0, A]]))


# ------------------------------------------------------------------- solve


def test_solve_tutor1():
    zero = sp.Matrix([A * X + B * Y - 1, C * X + D * Y - sp.pi])
    x, y = al.solve_linear(zero, [X, Y])
    assert same(x, -(sp.pi * B - D) / (A * D - B * C))
    assert same(y, (sp.pi * A - C) / (A * D - B * C))


def test_solve_numeric_and_derivatives():
    zero = sp.Matrix([-37 + 3 * X + 4 * Y, 2 + 4 * X - 2 * Y])
    assert al.solve_linear(zero, [X, Y]) == (3, 7)
    # unknowns that are derivatives; the variables themselves stay
    eqs = sp.Matrix([X.diff() + X - A, Y.diff() - 2 * X.diff() + Y])
    xd, yd = al.solve_linear(eqs, [X.diff(), Y.diff()])
    assert same(xd, A - X)
    assert same(yd, 2 * (A - X) - Y)


def test_solve_larger_system():
    xs = sp.symbols("x1:6")
    m = sp.Matrix(5, 5, lambda i, j: (i + 1) ** j + (i == j))
    b = sp.Matrix([1, 2, 3, 4, 5])
    sol = al.solve_linear(m * sp.Matrix(xs) - b, xs)
    assert sp.Matrix(sol) == m.solve(b)


def test_solve_errors():
    with pytest.raises(ValueError, match="not linear"):
        al.solve_linear(sp.Matrix([X**2 - 1, Y]), [X, Y])
    with pytest.raises(ValueError, match="singular"):
        al.solve_linear(sp.Matrix([X + Y - 1, 2 * X + 2 * Y]), [X, Y])
    with pytest.raises(ValueError, match="equations"):
        al.solve_linear(sp.Matrix([X + Y - 1]), [X, Y])


# ----------------------------------------------------- simplifications


def test_coef():
    y = A * X + B * Y + C * X.diff() + 1
    assert al.coef(y, X) == A
    assert al.coef(y, X.diff()) == C
    assert al.coef(y, sp.Matrix([X, Y])) == sp.Matrix([[A, B]])
    eqs = sp.Matrix([A * X + B * Y - 1, C * X + D * Y])
    assert al.coef(eqs, sp.Matrix([X, Y]).T) == sp.Matrix([[A, B], [C, D]])
    assert al.coef(eqs, X) == sp.Matrix([A, C])
    assert al.coef(A * sp.sin(X) + B, sp.sin(X)) == A
    with pytest.raises(ValueError, match="not linear"):
        al.coef(X**2, X)


def test_include_exclude():
    y = A * (X + B) + 3 + sp.sin(X) * C + X.diff()
    inc = al.include(y, X)
    exc = al.exclude(y, X)
    assert same(inc + exc, y)
    assert exc == A * B + 3 + X.diff()
    assert inc == A * X + C * sp.sin(X)
    m = al.exclude(sp.Matrix([X + A, Y]), X)
    assert m == sp.Matrix([A, Y])


def test_arrange():
    y = A * X + B * X + A * B + C * X**2
    out = al.arrange(y, 1, X)
    assert same(out, y)
    assert out == A * B + C * X**2 + X * (A + B)
    out2 = al.arrange(y, 2, X)
    assert same(out2, y)
    with pytest.raises(ValueError):
        al.arrange(y, -1, X)


def test_replace():
    y = sp.sin(X) ** 2 + X + X.diff()
    out = al.replace(y, [(sp.sin(X), 3)])
    assert out == 9 + X + X.diff()
    out = al.replace(y, [(X, A)])
    assert out == sp.sin(A) ** 2 + A + X.diff()
    out = al.replace(y, [(X.diff(), B), (X, A)])
    assert out == sp.sin(A) ** 2 + A + B
    assert al.replace(sp.Matrix([A, B]), [(A, B), (B, A)]) == sp.Matrix([B, A])


def test_epsilon():
    y = sp.Float("2.00001") * X + sp.Float("0.5") + sp.Float("0.99999") * Y
    out = al.epsilon(y, 0.001)
    assert out == 2 * X + sp.Float("0.5") + Y
    assert al.epsilon(sp.Rational(999, 1000) * A, sp.Rational(1, 100)) == A
    assert al.epsilon(sp.Matrix([sp.Float("3.05")]), 0.1) == sp.Matrix([3])
    assert al.epsilon(sp.Float("4.00000001") * X) == 4 * X
    with pytest.raises(ValueError):
        al.epsilon(y, -1)


def test_solve_large_singular():
    xs = sp.symbols("x1:5")
    eqs = [xs[0] + xs[1], 2 * xs[0] + 2 * xs[1] - 1, xs[2] - 1, xs[3]]
    with pytest.raises(ValueError, match="singular"):
        al.solve_linear(sp.Matrix(eqs), xs)


def test_doctests():
    import doctest

    assert doctest.testmod(al).failed == 0
