"""``LinearPartials`` (``model/speeds.py``): the partial velocities without
AutoZ, one reading of each measure number for all the speeds, give exactly
``sp.diff``'s expressions (same tree, same order), and take the short way
for measure numbers linear in the speeds."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.model.speeds import LinearPartials
from sympy.physics.vector import dynamicsymbols

U = list(dynamicsymbols("u1:5"))
Q = list(dynamicsymbols("q1:4"))
L, M = sp.symbols("l m")


def _factor(rng: random.Random, depth: int, nonlinear: bool) -> sp.Expr:
    """A random factor free of speeds, or (``nonlinear``) one that may
    hold a speed the way the short way must decline (power, function,
    sum, derivative)."""
    pick = rng.randrange(8 if nonlinear else 6)
    q = rng.choice(Q)
    if pick == 0:
        return sp.sin(q)
    if pick == 1:
        return sp.cos(q)
    if pick == 2:
        return rng.choice([L, M])
    if pick == 3:
        return sp.Rational(rng.choice([-3, -1, 2, 5]), rng.choice([1, 2]))
    if pick == 4 and depth < 2:
        return sp.Add(*[_term(rng, depth + 1, nonlinear) for _ in range(2)])
    if pick == 5:
        return q
    if pick == 6:
        return rng.choice(U) ** 2
    return rng.choice([sp.sin(rng.choice(U)), sp.Derivative(rng.choice(U), q.args[0])])


def _term(rng: random.Random, depth: int, nonlinear: bool) -> sp.Expr:
    factors = [_factor(rng, depth, nonlinear) for _ in range(rng.randrange(1, 4))]
    factors += rng.sample(U, rng.randrange(0, 3))
    return sp.Mul(*factors)


def _expression(rng: random.Random, nonlinear: bool) -> sp.Expr:
    return sp.Add(*[_term(rng, 0, nonlinear) for _ in range(rng.randrange(1, 6))])


def _same(a: sp.Expr, b: sp.Expr) -> bool:
    return a == b and sp.srepr(a) == sp.srepr(b)


@pytest.mark.parametrize("nonlinear", [False, True])
def test_the_partials_are_sympys_diff(nonlinear):
    rng = random.Random(20261128 + nonlinear)
    exprs = [_expression(rng, nonlinear) for _ in range(150)]
    exprs += [sp.S.Zero, sp.S(3), U[0], 2 * U[1], L * U[0], U[0] * U[1], -U[2]]
    partials = LinearPartials(U)
    for e in exprs:
        found = partials.of(e)
        assert len(found) == len(U)
        for u, d in zip(U, found, strict=True):
            assert _same(d, sp.diff(e, u)), (e, u, d)


def test_a_linear_measure_number_takes_the_short_way(monkeypatch):
    """Linear in the speeds, nothing is left to ``sp.diff``; a speed inside
    a function is, for that speed only."""
    calls = []
    real = sp.diff

    def counted(e, u):
        calls.append(u)
        return real(e, u)

    e = L * U[0] * sp.sin(Q[0]) + 2 * U[1] * U[0] * sp.cos(Q[1]) - M * U[2] + Q[2]
    expected = [real(e, u) for u in U]
    monkeypatch.setattr(sp, "diff", counted)
    assert all(
        _same(a, b) for a, b in zip(LinearPartials(U).of(e), expected, strict=True)
    )
    assert calls == []
    f = e + sp.sin(U[3]) * U[1]
    LinearPartials(U).of(f)
    assert calls == [U[3]]
