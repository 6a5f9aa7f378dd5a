"""``Intermediates.linear_split``: the split read from an expression
directly equals the split over placeholders (each variable substituted by
a symbol of its own), node for node, on many random expressions.

The direct reading is what ``name_linear`` (``Fr()``, ``FrStar()``, the
rates of a derivation) uses; the placeholder split is the one it replaces.
Also ``fastkane.times``, the products of named measure numbers that
``Fr()`` and ``FrStar()`` form, against sympy's own products."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates.autoz import Intermediates
from sympy.physics.mechanics import dynamicsymbols

t = dynamicsymbols._t
q1, q2, q3, u1, u2, u3 = dynamicsymbols("q1 q2 q3 u1 u2 u3")
a, b, c = sp.symbols("a b c")
SPEEDS = [u1, u2, u3]
RATES = [u.diff(t) for u in SPEEDS]


def _same(x, y) -> bool:
    """Equal as sympy objects and in their trees (``srepr``)."""
    if x is None or y is None:
        return x is None and y is None
    (cx, rx), (cy, ry) = x, y
    return (
        len(cx) == len(cy)
        and all(
            p == r and sp.srepr(p) == sp.srepr(r) for p, r in zip(cx, cy, strict=True)
        )
        and rx == ry
        and sp.srepr(rx) == sp.srepr(ry)
    )


def _random_expr(rng: random.Random, book: Intermediates, xs: list, depth: int):
    """A random sum of products: the variables ``xs`` as terms and factors
    (mostly), sometimes inside a function, a power or an intermediate."""
    plain = [a, b, c, sp.sin(q1), sp.cos(q2), q3, *book_zs(book)]
    numbers = [sp.Integer(2), sp.Integer(-1), sp.Rational(1, 3), sp.Float(0.25), 3]

    def leaf():
        r = rng.random()
        if r < 0.35:
            return rng.choice(xs)
        if r < 0.45:
            return rng.choice(numbers)
        if r < 0.5:  # a variable where it is not linear
            x = rng.choice(xs)
            return rng.choice([sp.sin(x), x**2, sp.cos(q1) * x * rng.choice(xs)])
        if r < 0.53:  # a speed's derivative or a speed inside a derivative
            return rng.choice([*RATES, *SPEEDS])
        return rng.choice(plain)

    def node(d: int):
        if d == 0:
            return leaf()
        kind = rng.random()
        parts = [node(d - 1) for _ in range(rng.randint(1, 3))]
        if kind < 0.45:
            return sp.Add(*parts)
        if kind < 0.85:
            return sp.Mul(*parts)
        if kind < 0.93:  # a number times a sum, kept a product (as Add does)
            return sp.Mul(rng.choice(numbers[:3]), sp.Add(*parts), evaluate=False)
        return book.name(sp.Add(*parts) * sp.sin(q2))

    return node(depth)


def book_zs(book: Intermediates) -> list:
    return [book.name(sp.sin(q1) * sp.cos(q2) + a), book.name(q3 * b + sp.cos(q1))]


@pytest.mark.parametrize("seed", range(12))
def test_direct_split_is_the_placeholder_split(seed):
    rng = random.Random(seed)
    book = Intermediates()
    direct_used = 0
    for _ in range(120):
        xs = rng.choice([SPEEDS, RATES, [u1, u2], SPEEDS + RATES])
        e = _random_expr(rng, book, xs, rng.randint(1, 4))
        e = sp.sympify(e)
        present = [x for x in xs if e.has(x)]
        if not present:
            continue
        one = book.linear_split(e, present)
        other = book.linear_split(e, present, direct=False)
        assert _same(one, other), (e, present, one, other)
        if one is not None:
            direct_used += 1
            coefs, rest = one
            back = rest + sum(k * x for k, x in zip(coefs, present, strict=True))
            assert sp.expand(book.expand(back - e)) == 0
    assert direct_used > 20  # the cases do reach the direct reading


def test_the_comparison_sees_a_product_of_a_number_and_a_sum():
    """``2*(a + b)`` kept a product is not ``2*a + 2*b``: the check is on
    the tree, not only on the value."""
    kept = sp.Mul(2, a + b, evaluate=False)
    assert not _same(([kept], sp.S.Zero), ([2 * a + 2 * b], sp.S.Zero))
    assert _same(([2 * a + 2 * b], sp.S.Zero), ([2 * (a + b)], sp.S.Zero))


def test_name_linear_names_the_parts():
    book = Intermediates()
    e = (a * sp.sin(q1) + b) * u1 + sp.cos(q2) * u2 + c
    out = book.name_linear(e, SPEEDS)
    assert out.coeff(u1) != 0 and out.coeff(u2) != 0
    assert sp.expand(book.expand(out) - e) == 0


def test_times_is_sympys_product():
    """``fastkane.times``: the product sympy forms (``==``, ``srepr`` and the
    arguments' order) for intermediates, numbers and other factors."""
    from al2py_runtime.model.fastkane import times

    rng = random.Random(3)
    book = Intermediates()
    zs = [
        book.name(sp.sin(q1) * q2 * k + q3 * sp.cos(q2) + sp.Rational(k, 3))
        for k in range(1, 40)
    ]
    other = [a, q1, sp.sin(q2), u1.diff(t), a + b, sp.Float(0.5), 2, -1]
    numbers = [sp.S.Zero, sp.S.One, sp.S.NegativeOne, sp.Integer(3), sp.Rational(-2, 7)]
    products = [-zs[0], 2 * zs[1] * zs[2], a * zs[3], zs[4] * sp.sin(q1), -zs[5] * u1]
    products += [sp.Rational(1, 3) * zs[6] * zs[7] * q2, zs[8] * (a + b), -zs[9] ** 2]
    pool = zs + zs + other + numbers + products
    cases = [(rng.choice(pool), rng.choice(pool)) for _ in range(4000)]
    cases += [(p, z) for p in products for z in zs[:12]]
    cases += [(z, p) for p in products for z in zs[:12]]
    cases += [(z, z) for z in zs[:5]] + [(z, -z) for z in zs[:5]]
    fast = 0
    for x, y in cases:
        got, want = times(x, y), sp.sympify(x) * sp.sympify(y)
        assert got == want and sp.srepr(got) == sp.srepr(want), (x, y)
        assert got.args == want.args
        fast += isinstance(x, type(zs[0])) and isinstance(y, type(zs[0]))
    assert fast > 500


def test_a_speeds_rate_is_kept_when_splitting_by_the_speed():
    """Splitting by ``u1`` keeps ``u1'`` (and ``u1''``) a variable of its
    own: a placeholder put for ``u1`` inside ``Derivative(u1, t)`` made it
    zero and lost the term (``a*u1' + u1`` split to rest ``a*Derivative(0,
    t)``)."""
    book = Intermediates()
    rate, second = u1.diff(t), u1.diff(t, 2)
    cases = [
        (a * rate + u1, [1], a * rate),
        (sp.sin(rate) + a * u1, [a], sp.sin(rate)),
        (u1 * rate**2 + a, [rate**2], a),
        (u1 * sp.sin(rate) + second, [sp.sin(rate)], second),
        (b * u1 + c * u2 + u2.diff(t) * u1, [b + u2.diff(t), c], sp.S.Zero),
    ]
    for e, coefs, rest in cases:
        xs = [x for x in (u1, u2) if e.has(x)]
        for direct in (True, False):
            got = book.linear_split(e, xs, direct=direct)
            assert got is not None, e
            assert [sp.expand(book.expand(k)) for k in got[0]] == coefs, e
            assert sp.expand(book.expand(got[1]) - rest) == 0, e
            assert not got[1].has(sp.Derivative(sp.S.Zero, t)), e
