"""AutoZ intermediates (al2py_runtime.intermediates.autoz): chain rule, numbers, solves.

Every check compares with the written-out expression at random points."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates, has_intermediates
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols

q1, q2, u1 = dynamicsymbols("q1 q2 u1")
L, M = sp.symbols("L M")
t = dynamicsymbols._t


def _point(seed: int) -> dict:
    rng = random.Random(seed)
    point = {x: sp.Float(rng.uniform(0.2, 1.3)) for x in (q1, q2, u1, L, M, t)}
    dq = {x.diff(t): sp.Float(rng.uniform(-1, 1)) for x in (q1, q2, u1)}
    return {**dq, **point}


def _close(a, b, seed=0) -> None:
    at = _point(seed)
    x = complex(sp.N(sp.sympify(a).xreplace(at)))
    y = complex(sp.N(sp.sympify(b).xreplace(at)))
    assert abs(x - y) <= 1e-10 * max(1.0, abs(y)), (x, y)


@pytest.fixture
def book():
    b = Intermediates()
    z1 = b.name(sp.cos(q1) * sp.sin(q2) + L * sp.cos(q2) + sp.atan2(q1, L))
    z2 = b.name(z1**2 * M + sp.sin(q1) * t + sp.exp(q2 * t) + sp.sqrt(1 + z1**2))
    return b, z1, z2


def test_names_are_reused_and_printed(book):
    b, z1, z2 = book
    assert str(z1) == "Z1" and str(z2) == "Z2"
    assert b.name(b.definition(z1)) == z1  # the same expression, the same name
    assert b.name(sp.cos(q1)) == sp.cos(q1)  # trivial: no name
    assert b.name(-b.definition(z2)) == -z2


@pytest.mark.parametrize("var", [t, q1, q2, L, M, u1])
def test_derivatives_follow_the_chain_rule(book, var):
    """d/dt is total (q' appears), d/dq is partial, d/dt of explicit time
    terms counted once."""
    b, _z1, z2 = book
    e = z2 * u1 + z2**2
    got = e.diff(var)
    assert has_intermediates(got) or got == 0
    for seed in range(3):
        _close(b.expand(got), b.expand(e).diff(var), seed)


def test_has_sees_the_variables(book):
    _b, z1, z2 = book
    assert z2.has(q1) and z2.has(L) and z1.has(q2)
    assert not z1.has(M) and not z1.has(u1)


def test_solve_names_and_solves(book):
    b, z1, z2 = book
    a = sp.Matrix([[z1, sp.cos(q1), L], [sp.sin(q1), z2, 1], [q2, 1, z1 * z2]])
    rhs = sp.Matrix([1, L, M])
    x = b.solve(a, rhs, [q1, q2])
    assert all(has_intermediates(e) or e.is_Atom for e in x)
    residual = b.expand(a * x - rhs)
    for seed in range(3):
        for e in residual:
            _close(e, 0, seed)


def test_numbers_evaluate_in_order(book):
    b, z1, z2 = book
    at = _point(5)
    expr = z2 / z1 + u1 * z2
    want = complex(sp.N(b.expand(expr).xreplace(at)))
    env = {k: complex(v) for k, v in at.items()}
    assert abs(autoz.number(expr, env) - want) < 1e-12 * abs(want)
    # evalf with numbers for the variables gives the same value
    assert abs(complex(sp.N(expr.xreplace(at))) - want) < 1e-12 * abs(want)


def test_flatten_is_cse_form(book):
    b, z1, z2 = book
    reps, reduced = b.flatten([z2 + z1, z1])
    assert [str(s) for s, _ in reps] == ["_z0", "_z1"]  # z1 before z2
    f = sp.lambdify([q1, q2, L, M, t], reduced, cse=lambda e: (reps, e))
    at = _point(2)
    got = f(*(float(at[x]) for x in (q1, q2, L, M, t)))
    want = [complex(sp.N(b.expand(e).xreplace(at))).real for e in (z2 + z1, z1)]
    assert got == pytest.approx(want, rel=1e-12)


def test_substituted_variable_is_rebased(book):
    """An intermediate taken at another point (a speed replaced by its
    expression) gets an intermediate of its own, with the same value."""
    b, _z1, _z2 = book
    z3 = b.name(u1 * sp.cos(q1) + L * u1**2)
    moved = z3.xreplace({u1: q2 * L})
    rebased = b.rebase(moved)
    assert b._canonical(rebased)
    _close(b.expand(rebased), b.expand(moved))


def test_zee_not_stays_explicit():
    """ZEE_NOT quantities are never hidden inside an intermediate."""
    b = Intermediates()
    f = dynamicsymbols("f")
    b.exclude = frozenset({f})
    e = b.name(f * (sp.cos(q1) * sp.sin(q2) + L) + sp.sin(q1) * sp.cos(q2) * M)
    assert e.has(f)
    assert all(not z.has(f) for z in e.atoms(autoz.Intermediate))
    full = f * (sp.cos(q1) * sp.sin(q2) + L) + sp.sin(q1) * sp.cos(q2) * M
    _close(b.expand(e).xreplace({f: sp.Float(0.7)}), full.xreplace({f: sp.Float(0.7)}))


@pytest.mark.parametrize("var", [q1, q2, L, M, u1, q1.diff(t)])
def test_walked_derivative_equals_sympys(book, var):
    """``derivative`` (the walk D() uses) against sympy's diff of the
    written-out expression; q' is a variable of its own."""
    b, z1, z2 = book
    e = z2 * u1 + z2**2 + z1 * q1.diff(t) ** 2
    memo: dict = {}
    got = b.derivative(e, var, memo)
    assert b.derivative(e, var, memo) == got  # the memo is reused
    for seed in range(3):
        _close(b.expand(got), b.expand(e).diff(var), seed)


@pytest.mark.parametrize("orders", [(0, 1), (1, 1), (0, 0)])
def test_taylor_at_a_point_equals_the_written_out_one(book, orders):
    """First-order Taylor about q1 = 0, q2 = 1/2, u1 = L (the steps stay
    visible, so COEF can read them) against sympy's series of the
    written-out expression; q1' is not moved."""
    from al2py_runtime.algebra import taylor

    b, z1, z2 = book
    y = sp.Matrix([z2 * u1 + z1 * q1.diff(t), z1 + sp.sin(q2)])
    points = [(q1, 0, None), (q2, sp.Rational(1, 2), None), (u1, L, None)]
    got = taylor(y, orders, points)
    want = taylor(y.applyfunc(b.expand), orders, points)
    for g, w in zip(got, want, strict=True):
        for seed in range(3):
            _close(b.expand(g), w, seed)
    if orders == (1, 1):
        # the first-order term is linear in the steps, outside any name:
        # the names are taken at the point (no q1 among their arguments)
        c = got[0].coeff(q1)
        assert c != 0 and not c.xreplace({q1.diff(t): M}).has(q1)


def test_long_expressions_are_named_in_parts():
    """A long expression gets short definitions (no longer than LIMIT
    nodes, as Autolev's Z's), the same name when met again, and the same
    value written out."""
    b = Intermediates()
    inner = sp.cos(q1) * sp.sin(q2) * L + M * sp.sqrt(1 + sp.sin(q1 - q2) ** 2)
    big = sum(sp.sin(k * inner + q2) ** 2 * (k + L * q1) for k in range(1, 6)) / inner
    z = b.name(big)
    assert isinstance(z, b.Z) and len(b) > 3
    assert b.name(big) == z

    def size(e):  # tree nodes, a name counting one
        if isinstance(e, b.Z | AppliedUndef) or not e.args:
            return 1
        return 1 + sum(size(a) for a in e.args)

    for k in range(1, len(b) + 1):
        assert all(size(part) <= b.LIMIT for part in b.canonical(k)[1].args)
    for seed in range(3):
        _close(b.expand(z), big, seed)
        _close(b.expand(z.diff(q1)), big.diff(q1), seed)


def _same_tree(a, b) -> bool:
    """Equal and built alike (the printers see the arguments' order)."""
    return a == b and sp.srepr(a) == sp.srepr(b)


def test_minus_and_total_are_sympys_own():
    """``minus`` and ``total`` give the objects sympy's ``-expr`` and
    ``Add(*terms)`` give, also for terms with a sum among their factors
    (kept as products: ``-(2*(a + b))`` is ``-2*(a + b)``), a term that
    becomes a bare sum (``-(-(a + b))``, whose terms join the sum) and
    like terms that collect."""
    b = Intermediates()
    z1 = b.name(sp.cos(q1) * sp.sin(q2) + L * sp.cos(q2))
    z2 = b.name(z1**2 * M + sp.sin(q1))
    s = L + M
    neg = sp.Mul(-1, s, evaluate=False)
    sums = [
        z1 * s + 3 * z2,
        2 * s * z1 - z2 * (L + sp.sin(q1)) + 4,
        sp.Add(neg, z1, evaluate=False),
        sp.Add(sp.Mul(2, s, evaluate=False), z2, evaluate=False),
        -z1 * z2 * s - sp.Rational(1, 2) * M,
    ]
    for e in sums:
        assert _same_tree(autoz.minus(e), -e), e
    groups = [
        [2 * z1 * L, 3 * z2, -z1 * M],
        [2 * z1 * L, -2 * z1 * L, z2],  # cancel
        [2 * z1 * L, z1 * L, z2 * s],  # collect
        [sp.S(3), z1, -sp.S(3), 5 * z1 * z2 * s],
        [sp.Mul(2, s, evaluate=False), z1],
    ]
    for terms in groups:
        assert _same_tree(autoz.total(terms), sp.Add(*terms)), terms


def test_substitute_is_sympys_xreplace():
    """``substitute`` (the workspace's right-hand sides, ``name_linear``'s
    plain symbols) gives the objects sympy's ``xreplace`` gives: a product
    with one factor replaced is formed by ``product_with``, a sum by
    ``total``, and values that are numbers, sums, products, powers or
    another factor of the same product go to sympy's own rules."""
    b = Intermediates()
    z1 = b.name(sp.cos(q1) * sp.sin(q2) + L * sp.cos(q2))
    z2 = b.name(z1**2 * M + sp.sin(q1) * u1)
    x, y = sp.symbols("x y")
    exprs = [
        2 * z1 * u1 + 3 * z2 * q1.diff() - L * u1 * M,
        -u1 * z1 * sp.sin(q2) + (L + u1) * z2 + u1**2 * M + sp.S(4),
        sp.Mul(3, L + u1, evaluate=False) + z1 * u1 * q1.diff(),
    ]
    rules = [
        {u1: x},
        {u1: x, q1.diff(): y},
        {u1: sp.S.Zero},
        {u1: sp.S(2)},
        {u1: L + M},
        {u1: -2 * L * z1},
        {u1: L},  # combines with the product's own L
        {u1: z1},  # combines with z1: a power
        {u1: sp.sqrt(2)},
        {L: M, u1: x * y},
    ]
    for e in exprs:
        for rule in rules:
            assert _same_tree(autoz.substitute(e, rule), e.xreplace(rule)), (e, rule)
    memo: dict = {}
    for e in exprs:  # a memo shared by calls with one rule
        assert _same_tree(autoz.substitute(e, rules[1], memo), e.xreplace(rules[1]))


def test_partial_derivatives_share_one_memo_per_variable(book):
    """Every ``D()`` by one variable reuses the book's memo: the same
    results as fresh walks, and an intermediate's partial named once."""
    b, z1, z2 = book
    e = z2 * u1 + z2**2
    first = b.derivative(e, q1)
    assert b.derivative(e, q1) is first
    count = len(b)
    fresh = b.derivative(e, q1, {})
    assert fresh == first and len(b) == count
    assert b.derivative(e * L, q1) == L * first
    for seed in range(3):
        _close(b.expand(first), b.expand(e).diff(q1), seed)
