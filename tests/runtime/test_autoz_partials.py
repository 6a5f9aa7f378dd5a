"""The shortcuts of ``D()`` over intermediates give what the long way gives.

A definition that is a sum of products of rational numbers, symbols and
canonical intermediates has its partial derivative formed and named by
``Intermediates._products_pd``; here random books are built twice, with and
without it, and must agree on every intermediate (number, variables and
definition) and every derivative; and the derivative it forms, and what it
says ``_walk`` finds in it, are checked one by one against ``_pd`` and
``_walk``.  Each check is shown to find a broken shortcut."""

from __future__ import annotations

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
P = sp.Symbol("P", positive=True)
t = dynamicsymbols._t
VARIABLES = [q1, q2, q3, u1, L, M, P, q1.diff(t)]
COEFFICIENTS = [1, 1, 1, -1, -1, 2, sp.Rational(-3, 2), sp.Rational(1, 3)]


def _new_book(shortcut: bool) -> Intermediates:
    """An empty book, which takes every partial the long way unless
    ``shortcut``."""
    book = Intermediates()
    if not shortcut:
        book._products_pd = lambda e, x, memo: None  # the long way
    return book


def _keep_named(book: Intermediates, zs: list, terms: list) -> None:
    """Name the sum of ``terms``, keeping it in ``zs`` when it is an
    intermediate or minus one."""
    z = book.name(sp.Add(*terms))
    if not isinstance(z, book.Z):
        z = -z
    if isinstance(z, book.Z):
        zs.append(z)


def _grown(book, rng, leaves, more, rounds, most, extra=None) -> list:
    """The intermediates named by ``rounds`` sums of 2 to ``most`` products
    of one to three pieces (the ``leaves`` until six are named, then the
    last twenty and ``more``), each times a coefficient; ``extra`` may add a
    factor to each product (:func:`_keep_named` keeps them)."""
    zs: list = []
    for _ in range(rounds):
        pieces = leaves if len(zs) < 6 else zs[-20:] + more
        terms = []
        for _ in range(rng.randint(2, most)):
            factors = rng.sample(pieces, rng.randint(1, 3))
            if extra is not None:
                extra(factors, pieces, zs)
            terms.append(rng.choice(COEFFICIENTS) * sp.Mul(*factors))
        _keep_named(book, zs, terms)
    return zs


def _build(seed: int, shortcut: bool = True) -> tuple[Intermediates, list]:
    """A book of intermediates whose later definitions are sums of
    products of earlier ones, symbols and numbers (some with a sine or a
    square, which the shortcut declines), then the partial derivatives of
    some by each variable: the book and the derivatives."""
    rng = random.Random(seed)
    book = _new_book(shortcut)
    book.rates = frozenset([q1.diff(t)])
    leaves = [q1 * L, sp.sin(q2), sp.cos(q3) * M, u1, q1.diff(t) * P, q2 * q3]
    zs: list = []
    for _ in range(70):
        if len(zs) < 8:
            pieces = leaves
        else:
            pieces = zs[-25:] + [L, M, K, P] + (leaves if rng.random() < 0.1 else [])
        terms = []
        for _ in range(rng.randint(2, 7)):
            factors = rng.sample(pieces, rng.randint(1, 3))
            if rng.random() < 0.05:
                factors[0] = factors[0] ** 2
            terms.append(rng.choice(COEFFICIENTS) * sp.Mul(*factors))
        if rng.random() < 0.1:
            terms.append(sp.Integer(rng.choice([-2, 3])))
        elif rng.random() < 0.15:
            terms = [sp.Mul(*rng.sample(pieces, rng.randint(2, 4)))]  # a product
        _keep_named(book, zs, terms)
    found = [book.derivative(z, x) for z in zs[-30:] for x in VARIABLES]
    return book, found


def _record(book: Intermediates) -> list:
    """Each intermediate's name, variables and definition."""
    return [
        (book.label_of(k), *map(written_tree, book.canonical(k)))
        for k in range(1, len(book) + 1)
    ]


@pytest.mark.parametrize("seed", range(6))
def test_the_shortcut_names_what_the_long_way_names(seed):
    fast = _build(seed)
    assert _written(fast) == _written(_build(seed, shortcut=False))
    assert len(fast[0]) > 150


def _checked(book: Intermediates, step: int = 1) -> tuple[int, int]:
    """Every ``step``-th definition's derivative by each of its variables, by the
    shortcut (where it applies) and by ``_pd``; and what the shortcut says
    ``_walk`` finds, by ``_walk``: (how many the shortcut formed, how many
    of them were sums)."""
    formed = sums = 0
    signs = {True: 0, False: 0}
    short = 0
    for k in range(1, len(book) + 1, step):
        variables, body = book.canonical(k)
        for x in variables:
            memo = book._pd_memos.setdefault(x, {})
            got = book._products_pd(body, x, memo)
            if got is None:
                continue
            formed += 1
            d, walked = got
            want = book._pd(body, x, {})
            assert written_tree(d) == written_tree(want), (body, x)
            if walked:
                sums += 1
                variables_, derivatives, bad, size = book._walk(d)
                assert (set(walked[0]), set(walked[1])) == (
                    set(variables_),
                    set(derivatives),
                )
                assert walked[2] == bad == [] and walked[3] == size
                if walked[4] is not None:
                    assert walked[4] == autoz.minus_first(d), d
                    signs[walked[4]] += 1
                if walked[5]:
                    assert book._split(d) is d
                    short += 1
            elif d.is_Add:  # a sum among its factors: walked when named
                assert any(
                    f.is_Add for term in d.args for f in sp.Mul.make_args(term)
                ), d
    assert signs[True] > 10 and signs[False] > 10 and short > 100
    return formed, sums


def test_the_shortcut_forms_pds_derivative_and_walk():
    """Every definition in the full tier (``make test-full``), every fourth
    in ``make test``."""
    book, _ = _build(11)
    formed, sums = _checked(book, tier_step(4))
    assert formed > 300 and sums > 150


def test_the_check_finds_a_wrong_order(monkeypatch):
    """Intermediates ordered by their numbers the other way round are
    found, by both checks."""
    real = Intermediates._plain_key

    def wrong(self, f):
        key = real(self, f)
        if key is not None and type(f) is self.Z:
            return (*key[:2], -key[2])
        return key

    monkeypatch.setattr(Intermediates, "_plain_key", wrong)
    books = [_build(seed) for seed in range(1, 4)]
    with pytest.raises(AssertionError):
        _checked(books[0][0])
    monkeypatch.undo()
    slow = [_build(seed, shortcut=False) for seed in range(1, 4)]
    assert any(_written(a) != _written(b) for a, b in zip(books, slow, strict=True))


def _written(built: tuple[Intermediates, list]) -> tuple[list, list]:
    book, found = built
    return _record(book), [written_tree(d) for d in found]


def test_the_check_finds_wrong_variables(monkeypatch):
    """Variables read off only the symbols (not the intermediates) are
    found."""
    real = Intermediates._met
    monkeypatch.setattr(
        Intermediates,
        "_products_pd",
        _without_shared(Intermediates._products_pd, real),
    )
    book, _ = _build(2)
    with pytest.raises(AssertionError):
        _checked(book)


def _without_shared(products_pd, met):
    def wrong(self, e, x, memo):
        got = products_pd(self, e, x, memo)
        if got is None or not got[1]:
            return got
        d, walked = got
        symbols = {a for a in d.atoms(sp.Symbol)}
        return d, (*met(self, symbols, set(), set()), *walked[2:])

    return wrong


def test_coefficients_collect_and_cancel():
    """Like products collect (and cancel) as sympy's sum collects them."""
    book = Intermediates()
    a = book.name(sp.sin(q1) * sp.cos(q1) * L + M * q2 * q3)
    b = book.name(-sp.sin(q1) * sp.cos(q1) * L + K * q2 * q3)
    c = book.name(sp.cos(q2) * L + q2 * M * sp.sin(q3))
    assert all(isinstance(z, book.Z) for z in (a, b, c))
    formed = 0
    for body in [a * c + b * c, a * c + b * c + 2 * a, a * c - K * b + b * c + 1]:
        body = book.canonical(autoz._number(book.name(body)))[1]
        for x in [q1, q2, q3, L, M, K]:
            got = book._products_pd(body, x, {})
            want = book._pd(body, x, {})
            if got is not None:
                assert got[0] == want, (body, x)
                formed += 1
    assert formed >= 12
    assert book._products_pd(a * c + b * c, q1, {})[0] == 0  # cancelled


def test_the_factors_tuples_order_as_compare():
    """``_plain_key`` orders factors as ``Basic.compare`` (sympy's order of
    a product's factors and of a sum's terms), and is equal exactly for
    equal factors."""
    import functools

    book, _ = _build(3)
    zs = [book.Z(k, *book.canonical(k)[0]) for k in range(1, len(book) + 1)]
    f = sp.Function("f")
    x = sp.Symbol("x", real=True)
    plain = [L, M, K, P, x, sp.Symbol("x"), q1, q2, u1, f(t), f(L), q1.diff(t)]
    plain += [q2.diff(t), u1.diff(t, 2), sp.sin(q1), sp.cos(q1), sp.sin(L)]
    plain += [sp.cos(P), sp.sin(x), sp.cos(f(t)), *zs[:40]]
    # sums of such factors and of products of them (a factor of a product)
    plain += [L + M, L - M, q1 + L, 2 * L + M * q1, zs[0] + zs[1], zs[1] + zs[2]]
    plain += [zs[2] * L - 3 * zs[5], zs[2] * L - 3 * zs[6], zs[3] + 1, zs[3] - 1]
    plain += [sp.sin(q1) + zs[7] * zs[8] * M, sp.Rational(1, 2) * zs[4] + K + q2]
    numbers = [sp.Integer(2), sp.Integer(-1), sp.Rational(1, 2), sp.Rational(-3, 4)]
    keys = {e: book._plain_key(e) for e in plain}
    assert None not in keys.values()
    by_compare = functools.cmp_to_key(sp.Basic.compare)
    rng = random.Random(8)
    for _ in range(300):
        chosen = rng.sample(plain, rng.randint(2, 8))
        assert sorted(chosen, key=keys.__getitem__) == sorted(chosen, key=by_compare)
        args = [rng.choice(numbers), *chosen]
        key = autoz._plain_atom_key(args[0])
        assert (key < keys[chosen[0]]) == (sp.Basic.compare(args[0], chosen[0]) < 0)
    assert len(set(keys.values())) == len(plain)
    for bad in [
        sp.sin(q1 * L),
        q1**L,
        q1**2.5,
        sp.exp(q1),
        L**K + M,
        zs[0] * sp.cos(q1 * L) + 1,
        sp.Symbol("A", commutative=False),
    ]:
        assert book._plain_key(bad) is None


def _build_declining(seed: int, shortcut: bool = True) -> tuple[Intermediates, list]:
    """A book as :func:`_build` makes, whose leaves also give partials that
    the shortcut cannot place: ``q1*L**2.5`` and ``q2*K**1.5`` (powers to
    a float, by ``q1`` and ``q2``); ``L*M*q3`` against a factor ``M`` (a square of ``M``, by
    ``L``, which it forms); and sums with factors that hold none of the
    variables asked (skipped)."""
    rng = random.Random(seed)
    book = _new_book(shortcut)
    sums = [q1 * L**2.5 + M, L * M * q3 + q2, sp.sin(q2) * K + q1, q1 * q3 + u1]
    sums.append(q2 * K**1.5 + L)
    leaves = [book.name(e) for e in sums] + [M * L, K]
    zs = _grown(book, rng, leaves, [L, M, K, sp.cos(q1)], 60, 6)
    found = [book.derivative(z, x) for z in zs[-25:] for x in [q1, q2, q3, L, M, K]]
    return book, found


def _shortcut_calls(monkeypatch, kept) -> list:
    """The definitions whose ``_products_pd`` call ``kept(book, e, got)``
    holds of, while ``monkeypatch`` wraps it (until ``monkeypatch.undo``)."""
    calls: list = []
    real = Intermediates._products_pd

    def counted(self, e, x, memo):
        got = real(self, e, x, memo)
        if kept(self, e, got):
            calls.append(e)
        return got

    monkeypatch.setattr(Intermediates, "_products_pd", counted)
    return calls


@pytest.mark.parametrize("seed", range(4))
def test_a_declined_shortcut_leaves_the_long_ways_numbers(seed, monkeypatch):
    """Where the shortcut declines after taking some factors' partials (a
    derivative that is a power, or squares a factor), the long way takes
    the rest in the same order: the same intermediates, the same numbers."""
    declined = _shortcut_calls(
        monkeypatch, lambda book, e, got: got is None and book._plans.get(e)
    )
    fast = _build_declining(seed)
    monkeypatch.undo()
    assert len(declined) > 5
    assert _written(fast) == _written(_build_declining(seed, shortcut=False))


def test_the_check_finds_partials_taken_in_another_order(monkeypatch):
    """A plan whose factors' partials are taken in the reverse order (so
    the intermediates named on the way get other numbers) is told apart."""
    real = Intermediates._products_plan

    def reversed_plan(self, e):
        plan = real(self, e)
        return None if plan is None else (plan[0][::-1], plan[1][::-1])

    monkeypatch.setattr(Intermediates, "_products_plan", reversed_plan)
    fast = [_build(seed) for seed in range(2)]
    monkeypatch.undo()
    slow = [_build(seed, shortcut=False) for seed in range(2)]
    assert any(_written(a) != _written(b) for a, b in zip(fast, slow, strict=True))


def test_the_check_finds_a_wrong_place_of_a_variable(monkeypatch):
    """An intermediate's partial by the variable next to the one asked is
    told apart (the places of the variables, :meth:`_variable_places`)."""
    real = Intermediates._variable_places

    def shifted(self, z):
        places = real(self, z)
        n = len(places)
        return {v: (j + 1) % n for v, j in places.items()}

    monkeypatch.setattr(Intermediates, "_variable_places", shifted)
    fast = _build(1)
    monkeypatch.undo()
    assert _written(fast) != _written(_build(1, shortcut=False))


def _build_sums(seed: int, shortcut: bool = True) -> tuple[Intermediates, list]:
    """A book as :func:`_build` makes, whose products also have sums among
    their factors (of intermediates, symbols and products of them), some
    alone with a number (which sympy distributes)."""
    rng = random.Random(seed)
    book = _new_book(shortcut)
    leaves = [q1 * L + u1, sp.sin(q2) * K + q3, sp.cos(q3) * M + q1 * q2, u1 * P]

    def with_a_sum(factors: list, pieces: list, zs: list) -> None:
        if rng.random() < 0.4 and len(zs) > 6:
            a, b = rng.sample(pieces, 2)
            factors.append(a + rng.choice(COEFFICIENTS) * b)

    zs = _grown(book, rng, leaves, [L, M, K, sp.sin(q1)], 45, 5, with_a_sum)
    found = [book.derivative(z, x) for z in zs[-12:] for x in VARIABLES]
    return book, found


@pytest.mark.parametrize("seed", range(3))
def test_sums_among_the_factors_name_what_the_long_way_names(seed, monkeypatch):
    """Products with sums among their factors, by the shortcut and the
    long way: the same intermediates, numbers and derivatives; and each
    derivative the shortcut forms is ``_pd``'s."""
    with_sums = _shortcut_calls(
        monkeypatch, lambda book, e, got: got and got[0].is_Add and not got[1]
    )
    fast = _build_sums(seed)
    monkeypatch.undo()
    assert len(with_sums) > 20
    assert _written(fast) == _written(_build_sums(seed, shortcut=False))
    book = fast[0]
    mine: dict = {}
    theirs: dict = {}
    for k in range(1, len(book) + 1):
        variables, body = book.canonical(k)
        for x in variables:
            got = book._products_pd(body, x, mine.setdefault(x, {}))
            if got is not None:
                want = book._pd(body, x, theirs.setdefault(x, {}))
                # (one book: == compares the arguments in their order)
                assert got[0] == want, (body, x)


def test_the_check_finds_a_wrong_order_among_sums(monkeypatch):
    """Sums placed before the other factors of a product (sympy places them
    after) are told apart (a sum's tuple, :meth:`_sum_key`)."""
    real = Intermediates._sum_key

    def wrong(self, f):
        key = real(self, f)
        return None if key is None else ((-key[0][0], ""), *key[1:])

    monkeypatch.setattr(Intermediates, "_sum_key", wrong)
    fast = [_build_sums(seed) for seed in range(3)]
    monkeypatch.undo()
    slow = [_build_sums(seed, shortcut=False) for seed in range(3)]
    assert any(_written(a) != _written(b) for a, b in zip(fast, slow, strict=True))
