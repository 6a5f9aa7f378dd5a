"""The chain rule's sums and products (``autoz.product_with``,
``autoz.total``) are the objects sympy's own ``Mul`` and ``Add`` make:
equal and built alike (``srepr``), so that every transcript, program and
intermediate's number stays as sympy's constructors would give it.

Checked on random products and sums over a book's intermediates, functions
of time, symbols, sums, powers and numbers, and on every call that the
derivatives of a small model make; and the check itself is shown to find a
deliberately wrong product and sum."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates
from sympy.physics.mechanics import dynamicsymbols

q1, q2, q3, u1, u2 = dynamicsymbols("q1 q2 q3 u1 u2")
L, M = sp.symbols("L M")
t = dynamicsymbols._t


def _same_tree(a, b) -> bool:
    """Equal and built alike (the printers see the arguments' order)."""
    return a == b and sp.srepr(a) == sp.srepr(b)


@pytest.fixture(scope="module")
def pools():
    """A book and what products, derivatives and sums are made of."""
    b = Intermediates()
    z1 = b.name(sp.cos(q1) * sp.sin(q2) + L * sp.cos(q2))
    z2 = b.name(z1**2 * M + sp.sin(q1) * u1)
    z3 = b.name(z2 * sp.cos(q3) - z1 * u2 + L * M * q2)
    z4 = b.name(z3 * z1 + sp.sin(q3) ** 2 * u1 * u2)
    factors = [
        z1, z2, z3, z4, q1, q2, u1, u2, L, M, q1.diff(t),
        sp.sin(q1), sp.cos(q2), L + M, z1 + q1, z2**2, L**2,
        sp.sqrt(L), sp.exp(q1), sp.sqrt(2),
        # powers of sums (a resolved length; the factor I: sympy's rules)
        sp.sqrt(L**2 + M**2), 1 / (z1 + q1), (L + M) ** sp.Rational(-3, 2),
        (L + sp.I * M) ** 2, (z2 - sp.I * z1 * L) ** sp.Rational(1, 3),
    ]  # fmt: skip
    derivatives = [
        z1, z2, z3, z4, sp.S.Zero, sp.S.One, sp.S.NegativeOne, sp.S(2),
        sp.Rational(-3, 2), 2 * z1 * L, -z2 * M, L + z1, q1 + M * z2,
        -(L + z1), 3 * (L + M), sp.Mul(2, L + M, evaluate=False),
        sp.sin(q1), -sp.sin(q2), u1, L, M, z1**2, sp.sqrt(2), sp.Float(0.5),
        z1 * (L + M), sp.S.Half * z3 * u2,
    ]  # fmt: skip
    return b, factors, derivatives


def _products(rng: random.Random, factors: list, n: int) -> list:
    out = []
    while len(out) < n:
        chosen = rng.sample(factors, rng.randint(2, 5))
        if rng.random() < 0.5:
            chosen.append(rng.choice([sp.S(2), sp.S.NegativeOne, sp.Rational(1, 3)]))
        p = sp.Mul(*chosen)
        if p.is_Mul:
            out.append(p)
    return out


def _product_cases(pools, n: int = 600, seed: int = 1) -> list:
    _, factors, derivatives = pools
    rng = random.Random(seed)
    cases = []
    for p in _products(rng, factors, n):
        args = p.args
        places = [i for i, a in enumerate(args) if not a.is_Number]
        i = rng.choice(places)
        d = rng.choice(derivatives + [a for a in args if not a.is_Number])
        cases.append((args, i, d))
    return cases


def _sum_cases(pools, n: int = 600, seed: int = 2) -> list:
    _, factors, derivatives = pools
    rng = random.Random(seed)
    cases = []
    for _ in range(n):
        terms = _products(rng, factors, rng.randint(0, 4))
        terms += rng.sample(derivatives, rng.randint(0, 3))
        if terms and rng.random() < 0.5:  # like terms that collect or cancel
            like = rng.choice(terms)
            terms.append(rng.choice([like, -like, 2 * like, sp.Rational(-1, 2) * like]))
        rng.shuffle(terms)
        cases.append(terms)
    return cases


def _product_mismatches(product_with, cases) -> list:
    """The cases where ``product_with`` differs from sympy's ``Mul``, asked
    without and with the product's kept factor facts (as the chain rule
    asks it)."""
    out = []
    for args, i, d in cases:
        want = sp.Mul(*args[:i], d, *args[i + 1 :])
        if not _same_tree(product_with(args, i, d), want):
            out.append((args, i, d))
        elif not _same_tree(product_with(args, i, d, autoz._Factors(args)), want):
            out.append((args, i, d, "factors"))
    return out


def _sum_mismatches(total, cases) -> list:
    return [terms for terms in cases if not _same_tree(total(terms), sp.Add(*terms))]


def test_product_with_is_sympys_mul(pools):
    cases = _product_cases(pools)
    assert _product_mismatches(autoz.product_with, cases) == []


def test_total_is_sympys_add(pools):
    cases = _sum_cases(pools)
    assert _sum_mismatches(autoz.total, cases) == []


def test_the_checks_find_a_wrong_product_and_sum(pools):
    """A product whose new factor is put last (not in sympy's order), and a
    sum that keeps its terms' order, are found."""

    def last(args, i, d, factors=None):
        rest = [a for j, a in enumerate(args) if j != i]
        return (
            sp.Mul._from_args((*rest, d))
            if rest and not d.is_Number
            else sp.Mul(*rest, d)
        )

    def unsorted(terms):
        kept = [x for x in terms if x is not sp.S.Zero]
        if len(kept) < 2 or any(x.is_Add or x.is_Number for x in kept):
            return sp.Add(*terms)
        return sp.Add._from_args(kept)

    assert _product_mismatches(last, _product_cases(pools, 200))
    assert _sum_mismatches(unsorted, _sum_cases(pools, 200))


def test_the_calls_of_a_models_derivatives_are_sympys(pools, monkeypatch):
    """Every ``product_with`` and ``total`` call that the partial derivatives
    of a chain of intermediates make (by each coordinate, speed, constant and
    by time), against sympy's ``Mul`` and ``Add``.  Powers and sums among
    the factors: the sums of plain products go by ``_products_pd``, held to
    these calls in ``test_autoz_partials.py``."""
    b = Intermediates()
    rng = random.Random(3)
    pool = [q1, q2, q3, u1, u2, L, M, sp.sin(q1), sp.cos(q2), sp.sin(q3)]
    pool += [q1**2, 1 / (L + q2), sp.sqrt(1 - sp.sin(q3) ** 2), u1 + L * u2]
    top = []
    for _ in range(40):
        terms = [
            sp.Rational(rng.randint(-3, 3) or 1, rng.randint(1, 2))
            * sp.Mul(*rng.sample(pool, rng.randint(1, 3)))
            for _ in range(rng.randint(2, 4))
        ]
        z = b.name(sp.Add(*terms))
        pool.append(z)
        top.append(z)
    products, sums = [], []
    real_product_with, real_total = autoz.product_with, autoz.total

    def product_with(args, i, d, factors=None):
        products.append((args, i, d))
        return real_product_with(args, i, d, factors)

    def total(terms):
        sums.append(list(terms))
        return real_total(terms)

    monkeypatch.setattr(autoz, "product_with", product_with)
    monkeypatch.setattr(autoz, "total", total)
    e = sp.Add(*[z * rng.choice(pool) for z in top[-10:]])
    for x in (q1, q2, q3, u1, u2, L, M, q1.diff(t)):
        b.derivative(e, x)
    b.total_dt(e)
    monkeypatch.undo()
    # (powers of plain factors go by ``_products_pd`` too, held to the long
    # way in ``test_power_chain.py``)
    assert len(products) > 100 and len(sums) > 100
    assert _product_mismatches(autoz.product_with, products) == []
    assert _sum_mismatches(autoz.total, sums) == []
