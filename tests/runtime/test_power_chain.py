"""The chain rule's shortcut over powers gives what the long way gives.

``Intermediates._products_pd`` also takes definitions whose products hold
powers of plain factors (``Z**-1``, ``Z**2``, ``cos(q)**-1``,
``(1 - Z**2)**(-1/2)``, ...) and products in which the derivative shares a
base with another factor (``Z*Z`` is ``Z**2``, ``Z**-1*Z`` is 1).  Random
books are built with and without the shortcut and must agree on every
intermediate (number, variables, definition) and every derivative; each
derivative it forms, and what it says ``_walk`` finds in it, is checked
against ``_pd`` and ``_walk``; the product of factors with common bases
(:meth:`Intermediates._merged`) and a product rebuilt with several
factors replaced (:func:`autoz.products_with`) against sympy's ``Mul``,
argument by argument in their order, and the tuples of
powers against ``Basic.compare``.  Each check is shown to find a broken
shortcut."""

from __future__ import annotations

import functools
import random

import pytest
import sympy as sp
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates
from conftest import tier_step
from random_exprs import written_tree
from sympy.physics.mechanics import dynamicsymbols

q1, q2, q3, u1 = dynamicsymbols("q1 q2 q3 u1")
L, M, K = sp.symbols("L M K")
t = dynamicsymbols._t
VARIABLES = [q1, q2, q3, u1, L, M, K, q1.diff(t)]
COEFFICIENTS = [1, 1, 1, -1, -1, 2, sp.Rational(-3, 2), sp.Rational(1, 3)]
EXPONENTS = [-1, -1, -2, 2, 2, 3, sp.Rational(-1, 2), sp.Rational(-3, 2), sp.S.Half]


def _new_book(shortcut: bool) -> Intermediates:
    book = Intermediates()
    book.rates = frozenset([q1.diff(t)])
    if not shortcut:
        book._products_pd = lambda e, x, memo: None  # the long way
    return book


def _powered(rng: random.Random, f):
    """``f`` to a random exponent now and then (a sum's power: rational)."""
    if rng.random() < 0.3:
        return f ** rng.choice(EXPONENTS)
    return f


def _build(seed: int, shortcut: bool = True) -> tuple[Intermediates, list]:
    """A book whose definitions are sums of products of earlier
    intermediates, symbols, sines, numbers, powers of these and of sums
    (some sharing a base with another factor), a constant intermediate and
    now and then the imaginary unit; then the partial derivatives of the
    last ones by each variable: the book and the derivatives."""
    rng = random.Random(seed)
    book = _new_book(shortcut)
    leaves = [q1 * L, sp.sin(q2), sp.cos(q3) * M, u1, q1.diff(t) * K, q2 * q3]
    leaves += [q1 * L**2 + M, 1 / (L + q2), sp.sqrt(1 - sp.sin(q3) ** 2)]
    constant = book.name(sp.sqrt(3) + sp.Rational(1, 2))
    zs: list = []
    for _ in range(70):
        if len(zs) < 8:
            pieces = leaves
        else:
            pieces = zs[-25:] + [L, M, K, sp.cos(q1), constant, sp.tan(L)]
            pieces += [sp.cos(L + q1), sp.sin(L + q2)]
            if rng.random() < 0.2:
                a, b = rng.sample(zs[-10:], 2)
                pieces.append(1 - a**2 + rng.choice(COEFFICIENTS) * b)
        terms = []
        for _ in range(rng.randint(2, 6)):
            factors = [_powered(rng, f) for f in rng.sample(pieces, rng.randint(1, 3))]
            if rng.random() < 0.1:
                factors.append(factors[0])  # a common base
            if rng.random() < 0.02:
                factors.append(sp.I)
            terms.append(rng.choice(COEFFICIENTS) * sp.Mul(*factors))
        if rng.random() < 0.1:
            terms.append(sp.Integer(rng.choice([-2, 3])))
        z = book.name(sp.Add(*terms))
        if not isinstance(z, book.Z):
            z = -z
        if isinstance(z, book.Z):
            zs.append(z)
    found = [book.derivative(z, x) for z in zs[-25:] for x in VARIABLES]
    return book, found


def _written(built: tuple[Intermediates, list]) -> tuple[list, list]:
    book, found = built
    record = [
        (book.label_of(k), *map(written_tree, book.canonical(k)))
        for k in range(1, len(book) + 1)
    ]
    return record, [written_tree(d) for d in found]


def _with_powers(e) -> bool:
    return any(f.is_Pow for term in sp.Add.make_args(e) for f in sp.Mul.make_args(term))


@pytest.mark.parametrize("seed", range(5))
def test_the_shortcut_names_what_the_long_way_names(seed, monkeypatch):
    """With powers among the factors: the same intermediates, numbers and
    derivatives with the shortcut and without; and the shortcut forms
    many derivatives of definitions with powers."""
    formed: list = []
    real = Intermediates._products_pd

    def counted(self, e, x, memo):
        got = real(self, e, x, memo)
        if got is not None and _with_powers(e):
            formed.append(e)
        return got

    monkeypatch.setattr(Intermediates, "_products_pd", counted)
    fast = _build(seed)
    monkeypatch.undo()
    assert len(formed) > 40
    assert _written(fast) == _written(_build(seed, shortcut=False))


def _checked(book: Intermediates, step: int = 1) -> int:
    """Every ``step``-th definition's derivative by each of its variables, by the
    shortcut (where it applies) and by ``_pd``, and what the shortcut says
    ``_walk`` finds, by ``_walk``, ``minus_first`` and ``_split``: how many
    the shortcut formed of definitions with powers."""
    formed = 0
    walked_powers = 0
    for k in range(1, len(book) + 1, step):
        variables, body = book.canonical(k)
        for x in variables:
            got = book._products_pd(body, x, book._pd_memos.setdefault(x, {}))
            if got is None:
                continue
            d, walked = got
            want = book._pd(body, x, {})
            assert written_tree(d) == written_tree(want), (body, x)
            formed += _with_powers(body)
            if walked:
                walked_powers += _with_powers(d)
                variables_, derivatives, bad, size = book._walk(d)
                assert (set(walked[0]), set(walked[1])) == (
                    set(variables_),
                    set(derivatives),
                ), d
                assert walked[2] == bad == [] and walked[3] == size, d
                if walked[4] is not None:
                    assert walked[4] == autoz.minus_first(d), d
                if walked[5]:
                    assert book._split(d) is d
    assert walked_powers > 20
    return formed


def test_the_shortcut_forms_pds_derivative_and_walk():
    """Every definition in the full tier (``make test-full``), every fourth
    in ``make test``."""
    assert _checked(_build(11)[0], tier_step(4)) > 60


def test_the_check_finds_a_wrong_size(monkeypatch):
    """A power's nodes left out of the walk's count are found."""
    real = Intermediates._rest_facts

    def fewer(self, rest):
        got = real(self, rest)
        return got if got is None else (*got[:4], 0)

    monkeypatch.setattr(Intermediates, "_rest_facts", fewer)
    book, _ = _build(11)
    with pytest.raises(AssertionError):
        _checked(book)


def test_the_check_finds_a_wrong_power_order(monkeypatch):
    """Powers ordered by their exponents the other way round are told
    apart from the long way."""
    real = Intermediates._power_key

    def wrong(self, f):
        key = real(self, f)
        if key is None:
            return key
        place, n, base, (c, m, *exp) = key
        return (place, n, base, (c, m, *[-e for e in exp]))

    monkeypatch.setattr(Intermediates, "_power_key", wrong)
    fast = [_build(seed) for seed in range(3)]
    monkeypatch.undo()
    slow = [_build(seed, shortcut=False) for seed in range(3)]
    assert any(_written(a) != _written(b) for a, b in zip(fast, slow, strict=True))


def _pool(book: Intermediates) -> list:
    """Plain factors and powers of them, several of one base."""
    zs = [book.name(e) for e in [q1 * L + M, sp.sin(q2) * K + u1, q3 * M + L * u1]]
    bases = [*zs, L, M, q1, u1, sp.sin(q1), sp.cos(q2), q1.diff(t)]
    bases += [L + zs[0], 1 - zs[1] ** 2, -zs[0] - zs[2]]
    exponents = [1, 1, -1, 2, -2, 3, sp.S.Half, sp.Rational(-1, 2), sp.Rational(-3, 2)]
    return [b**e for b in bases for e in exponents]


def _merge_cases(book: Intermediates, n: int = 600) -> list:
    """``n`` seeded pairs of canonical products (as argument tuples, no
    coefficient), sharing bases now and then."""
    rng = random.Random(5)
    pool = _pool(book)
    cases = []
    while len(cases) < n:
        rest = sp.Mul(*rng.sample(pool, rng.randint(0, 4)))
        new = sp.Mul(*rng.sample(pool, rng.randint(1, 3)))
        parts = []
        for e in (rest, new):
            if e.is_Number:
                break
            args = sp.Mul.make_args(e)
            if args[0].is_Number:
                break  # (a sum's power with a sign taken out)
            parts.append(args)
        if len(parts) == 2:
            cases.append(tuple(parts))
    return cases


def _merge_mismatches(book: Intermediates, cases: list) -> tuple[list, int]:
    """The cases where ``_merged`` gives another product than sympy's
    ``Mul``, and how many it formed (it declines the others)."""
    key_of = book._plain_key
    wrong, formed = [], 0
    for rest, news in cases:
        rest_keys = tuple(key_of(f) for f in rest)
        new_keys = tuple(key_of(f) for f in news)
        assert None not in rest_keys + new_keys
        bases = frozenset(autoz._base_key(k) for k in rest_keys)
        got = book._merged(rest, rest_keys, bases, news, new_keys)
        if got is None:
            continue
        formed += 1
        args, keys = got
        assert keys == tuple(key_of(f) for f in args)
        mine = args[0] if len(args) == 1 else autoz._product(args) if args else 1
        if written_tree(mine) != written_tree(sp.Mul(*rest, *news)):
            wrong.append((rest, news))
    return wrong, formed


def test_merged_is_sympys_mul():
    book = Intermediates()
    cases = _merge_cases(book)
    wrong, formed = _merge_mismatches(book, cases)
    assert wrong == []
    assert formed > 500
    # common bases: squares, cancellations, sums to a power
    assert sum(1 for rest, news in cases if set(rest) & set(news)) > 20


def test_the_merge_check_finds_uncombined_powers(monkeypatch):
    """A merge that only sorts the factors (a common base's exponents not
    added) is told apart from sympy's ``Mul``."""

    def sorted_only(self, rest, rest_keys, bases, news, new_keys):
        both = zip(rest + news, rest_keys + new_keys, strict=True)
        pairs = sorted(both, key=lambda p: p[1])
        return tuple(p[0] for p in pairs), tuple(p[1] for p in pairs)

    book = Intermediates()
    cases = _merge_cases(book, 300)
    monkeypatch.setattr(Intermediates, "_merged", sorted_only)
    wrong, _ = _merge_mismatches(book, cases)
    assert len(wrong) > 20


def test_the_tuples_of_powers_order_as_compare():
    """``_plain_key`` orders powers among plain factors as
    ``Basic.compare``, equal exactly for equal factors; a power of a
    product, a number or to a symbol's exponent has none."""
    book = Intermediates()
    pool = _pool(book)
    pool += [book.name(sp.sqrt(2) + 1), book.name(sp.sqrt(2) + 1) ** -1]
    pool += [sp.tan(L), sp.tan(q1), sp.cos(L + q1), sp.sin(L + q1), sp.tan(L + M)]
    pool += [sp.sin(L + q1) ** 2, sp.sin(L - M), sp.cos(q1 + 2 * q2) ** -1]
    keys = {f: book._plain_key(f) for f in pool}
    assert None not in keys.values()
    assert len(set(keys.values())) == len(keys)
    by_compare = functools.cmp_to_key(sp.Basic.compare)
    rng = random.Random(9)
    for _ in range(400):
        chosen = rng.sample(list(keys), rng.randint(2, 8))
        assert sorted(chosen, key=keys.__getitem__) == sorted(chosen, key=by_compare)
    unkeyed = [L**K, (L * M) ** sp.S.Half, sp.sqrt(2) ** L, q1 ** sp.Float(2.5)]
    for bad in [*unkeyed, sp.sin(L * q1), sp.tan(sp.tan(L)), sp.cos(L + sp.exp(M))]:
        assert book._plain_key(bad) is None


def _replaced_cases(n: int = 700) -> list:
    """``n`` seeded products (their arguments) with two or more factors
    replaced: by intermediates, symbols, dummies, numbers (0, rationals, a
    float, infinity, ``I``), products with coefficients, sums and powers,
    now and then one of the product's other factors (a common base)."""
    book = Intermediates()
    rng = random.Random(12)
    zs = [book.name(e) for e in [q1 * L + M, sp.sin(q2) * K + u1, q3 * M + L * u1]]
    zs += [book.Z(sp.Integer(2), sp.Dummy("a"), q2, q3, L, u1)]
    pool = [*zs, L, M, K, q1, u1, sp.sin(q1), sp.cos(q2), sp.Dummy("b"), L + M]
    pool += [zs[0] ** 2, zs[1] ** -1, (L + zs[0]) ** sp.Rational(-1, 2), 2 * L + M]
    numbers = [sp.S.Zero, sp.S.One, sp.S.NegativeOne, sp.Rational(3, 2), sp.Float(2)]
    numbers += [sp.oo, sp.I]
    cases = []
    while len(cases) < n:
        product = rng.choice([1, 1, 2, -1, sp.Rational(-1, 3), sp.Float(1.5)]) * sp.Mul(
            *rng.sample(pool, rng.randint(2, 5))
        )
        if not product.is_Mul:
            continue
        args = product.args
        changed = sorted(
            rng.sample(range(len(args)), rng.randint(2, min(3, len(args))))
        )
        new = list(args)
        for i in changed:
            kind = rng.random()
            if kind < 0.15:
                new[i] = rng.choice(numbers)
            elif kind < 0.3:
                new[i] = rng.choice(COEFFICIENTS) * rng.choice(pool)
            elif kind < 0.4:
                new[i] = rng.choice(args)
            else:
                new[i] = rng.choice(pool)
        cases.append((args, new, changed))
    return cases


def _replaced_mismatches(products_with, cases: list) -> list:
    return [
        (args, new)
        for args, new, changed in cases
        if written_tree(products_with(args, new, changed)) != written_tree(sp.Mul(*new))
    ]


def test_products_with_is_sympys_mul(monkeypatch):
    """A product rebuilt with several factors replaced (as ``substitute``
    rebuilds one) is sympy's ``Mul`` of the new arguments; most are formed
    without it."""
    cases = _replaced_cases()
    formed = []
    real = autoz._product

    def counted(args):
        formed.append(args)
        return real(args)

    monkeypatch.setattr(autoz, "_product", counted)
    assert _replaced_mismatches(autoz.products_with, cases) == []
    assert len(formed) > 150


def test_the_replaced_check_finds_unsorted_factors():
    """A rebuild that keeps the factors in their places is found."""

    def unsorted(args, new, changed):
        kept = [a for a in new if a is not sp.S.One]
        if any(a.is_Number or a.is_Mul or a.is_Add for a in kept) or len(kept) < 2:
            return sp.Mul(*new)
        return sp.Mul._from_args(kept)

    assert len(_replaced_mismatches(unsorted, _replaced_cases(300))) > 20
