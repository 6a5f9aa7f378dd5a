"""Shortcuts of the derivation (issue 35, seventh pass): each gives sympy's
result, written alike (the same arguments in the same order), checked on
random expressions; each test also counts how often the shortcut was
taken, so it cannot pass by always asking sympy."""

from __future__ import annotations

import random

import sympy as sp
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model import kinematics as kin
from random_exprs import plain_factor, written_tree
from sympy.core.mul import _keep_coeff
from sympy.physics.mechanics import dynamicsymbols

T = dynamicsymbols._t
U = dynamicsymbols("U1:5")
Q = dynamicsymbols("Q1:4")
S = [sp.Symbol("RF"), sp.Symbol("RR", positive=True), sp.Symbol("D1", real=True)]
_BOOK = Intermediates("Z")
ZS = [
    _BOOK.name(sp.cos(Q[0]) * sp.sin(Q[1]) + S[0] * sp.cos(Q[2])),
    _BOOK.name(sp.sin(Q[0]) * U[0] - S[1] * sp.cos(Q[1])),
    _BOOK.name(U[1] * sp.cos(Q[2]) + S[0] * sp.sin(Q[1]) * S[1]),
]
#: factors whose arguments hold a sum factor_terms factors
ODD = [
    ZS[0].func(*ZS[0].args, 10 * sp.sin(2 * sp.pi * T + sp.pi / 6)),
    sp.Function("F")(2 * sp.pi * T + sp.pi / 6),
]


def _plain(rng: random.Random) -> sp.Expr:
    """A factor ``factor_terms`` leaves alone."""
    return plain_factor(rng, (U, Q, S, ZS, T))


SEEDS = range(300)


def _power(rng: random.Random, depth: int) -> sp.Expr:
    """A power of a plain factor or of a sum, at a rational exponent."""
    base = _plain(rng) if depth == 0 or rng.random() < 0.5 else _sum(rng, depth - 1)
    e = rng.choice(
        [2, 3, -1, -2, sp.Rational(1, 2), sp.Rational(-1, 2), sp.Rational(3, 2)]
    )
    return base**e


def _factor(rng: random.Random, depth: int) -> sp.Expr:
    r = rng.random()
    if r < 0.45:
        return _plain(rng)
    if r < 0.8:
        return _power(rng, depth)
    if r < 0.93 and depth:
        return _sum(rng, depth - 1)
    return rng.choice([2, sp.Rational(1, 3), sp.sqrt(2), sp.pi, ODD[0], ODD[1]])


def _sum(rng: random.Random, depth: int) -> sp.Expr:
    """A sum of products of factors and powers, -1 or none, now and then
    with the number 1 (or another), all negative or a common factor."""
    terms = []
    for _ in range(rng.randrange(1, 5)):
        factors = [_factor(rng, depth) for _ in range(rng.randrange(1, 4))]
        terms.append(rng.choice([1, 1, -1]) * sp.Mul(*factors))
    if rng.random() < 0.4:
        terms.append(rng.choice([1, 1, 1, 1, 1, -1, 2]))
    e = sp.Add(*terms)
    r = rng.random()
    if r < 0.08:
        return sp.expand(-e) if e.is_Add else -e
    if r < 0.16:
        return sp.expand(rng.choice(ZS + U) ** rng.choice([1, 2, -1]) * e)
    if r < 0.22 and e.is_Add:
        return _keep_coeff(sp.S.NegativeOne, e, sign=True)
    return e


def test_factors_fixed_with_powers_and_ones():
    fixed = declined = powers = 0
    for seed in SEEDS:
        rng = random.Random(seed)
        e = _sum(rng, 1)
        if rng.random() < 0.3:
            e = _power(rng, 1) * e
        if kin._factors_fixed(e):
            fixed += 1
            powers += e.has(sp.Pow)
            assert written_tree(sp.factor_terms(e)) == written_tree(e), (seed, e)
        else:
            declined += 1
        assert written_tree(kin.factor_terms(e)) == written_tree(sp.factor_terms(e)), (
            seed,
            e,
        )
    assert fixed > 40 and declined > 100 and powers > 30, (fixed, declined, powers)


def test_common_power_base_is_declined():
    z, u = ZS[0], U[0]
    for e in [
        u * z + U[1] * z**2,  # z is taken out
        u / (1 - z**2) + U[1] / sp.sqrt(1 - z**2),
        -(z**2) - u**2,  # all negative
        z**2 * u + z * U[1] + z,
    ]:
        assert not kin._factors_fixed(e), e
        assert written_tree(kin.factor_terms(e)) == written_tree(sp.factor_terms(e))
    e = -u * (U[1] * sp.cos(Q[0]) - U[2] * z) / sp.sqrt(1 - z**2) + U[3]
    assert kin._factors_fixed(e)
    assert written_tree(sp.factor_terms(e)) == written_tree(e)
