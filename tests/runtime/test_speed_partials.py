"""``SpeedPartials`` (``model/speeds.py``): the partial velocities without
AutoZ, each part of a measure number differentiated once per speed, are
exactly ``sp.diff``'s expressions (same tree, same order)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.model.speeds import SpeedPartials
from conftest import tier_cases
from sympy.physics.vector import dynamicsymbols

U = list(dynamicsymbols("u1:5"))
Q = list(dynamicsymbols("q1:4"))
L, M = sp.symbols("l m")


def _factor(rng: random.Random, depth: int, nonlinear: bool) -> sp.Expr:
    """A random factor free of speeds, or (``nonlinear``) one that may hold
    a speed anywhere: in a power, a function, a sum or a derivative."""
    pick = rng.randrange(13 if nonlinear else 6)
    q = rng.choice(Q)
    u = rng.choice(U)
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
        return u ** rng.choice([2, -1, sp.Rational(1, 2)])
    if pick == 7:
        return rng.choice([sp.sin, sp.cos, sp.exp, sp.tan])(u * q + L)
    if pick == 8:
        return sp.Derivative(u, q.args[0])
    if pick == 9:
        return rng.choice([u**q, q**u])
    if pick == 10:
        return sp.sqrt(L**2 + rng.choice(U) * u)
    if pick == 11:
        return sp.atan2(u, q + L)
    return 1 / (q + u * L)


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
    exprs = [_expression(rng, nonlinear) for _ in range(tier_cases(150))]
    exprs += [sp.S.Zero, sp.S(3), U[0], 2 * U[1], L * U[0], U[0] * U[1], -U[2]]
    partials = SpeedPartials(U)
    for e in exprs:
        found = partials.of(e)
        assert len(found) == len(U)
        for u, d in zip(U, found, strict=True):
            assert _same(d, sp.diff(e, u)), (e, u, d)


def test_each_part_is_differentiated_here(monkeypatch):
    """Sums, products, powers with constant exponents and functions are
    differentiated here; only what the rules do not cover (a derivative, a
    speed in an exponent) is left to ``sp.diff``, that part alone."""
    calls = []
    real = sp.diff

    def counted(e, u):
        calls.append((e, u))
        return real(e, u)

    e = L * U[0] * sp.sin(Q[0]) + 2 * U[1] * U[0] * sp.cos(Q[1]) - M * U[2] + Q[2]
    e += sp.sin(U[3] * Q[0]) * U[1] + sp.sqrt(1 + U[0] ** 2) / (Q[1] + U[2])
    expected = [real(e, u) for u in U]
    monkeypatch.setattr(sp, "diff", counted)
    found = SpeedPartials(U).of(e)
    assert all(_same(a, b) for a, b in zip(found, expected, strict=True))
    assert calls == []
    d = sp.Derivative(U[3], Q[0].args[0])
    SpeedPartials(U).of(e + d * U[1])
    assert calls == [(d, U[3])]
