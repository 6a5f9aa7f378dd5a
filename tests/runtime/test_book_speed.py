"""What ``Intermediates._products_pd`` hands on for naming a derivative,
checked against the long way on random books.

A sum's negation (:meth:`Intermediates._products_opposite`, formed from the
chain rule's terms and their tuples) must be :func:`minus`'s and sympy's
``-d``, argument for argument; a single product's walk facts and sign must
be :meth:`Intermediates._walk`'s and :func:`minus_first`'s."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates
from sympy.physics.mechanics import dynamicsymbols

q1, q2, q3, u1 = dynamicsymbols("q1 q2 q3 u1")
L, M, K = sp.symbols("L M K")
P = sp.Symbol("P", positive=True)
t = dynamicsymbols._t
VARIABLES = [q1, q2, q3, u1, L, M, P, q1.diff(t)]
COEFFICIENTS = [1, 1, -1, -1, -1, 2, -2, sp.Rational(-3, 2), sp.Rational(1, 3)]


def _build(seed: int, book: Intermediates | None = None) -> Intermediates:
    """A book (``book``, else a new one) whose later definitions are sums
    (or single products) of products of earlier intermediates, symbols,
    sines and numbers."""
    rng = random.Random(seed)
    book = Intermediates() if book is None else book
    book.rates = frozenset([q1.diff(t)])
    leaves = [q1 * L, sp.sin(q2), sp.cos(q3) * M, u1, q1.diff(t) * P, q2 * q3]
    leaves += [sp.sin(q1) * K, q2 * sp.cos(q1)]
    zs: list = []
    for _ in range(80):
        if len(zs) < 8:
            pieces = leaves
        else:
            pieces = zs[-25:] + [L, M, K, P, q1, sp.sin(q3)]
        terms = []
        for _ in range(rng.randint(1, 6)):
            factors = rng.sample(pieces, rng.randint(1, 3))
            if rng.random() < 0.05:
                factors[0] = factors[0] ** 2
            terms.append(rng.choice(COEFFICIENTS) * sp.Mul(*factors))
        if rng.random() < 0.15:
            terms.append(sp.Integer(rng.choice([-2, 3, -1])))
        elif rng.random() < 0.2:
            terms = [rng.choice(COEFFICIENTS) * sp.Mul(*rng.sample(pieces, 3))]
        z = book.name(sp.Add(*terms))
        if not isinstance(z, book.Z):
            z = -z
        if isinstance(z, book.Z):
            zs.append(z)
    for z in zs[-30:]:
        for x in VARIABLES:
            book.derivative(z, x)
    return book


def _tree(e) -> str:
    """``e`` written out with its arguments in their order."""
    if not e.args:
        return sp.srepr(e)
    return f"{type(e).__name__}({', '.join(_tree(a) for a in e.args)})"


def _checked(book: Intermediates) -> dict:
    """Every definition's derivative by each of its variables, where the
    shortcut forms it: a sum's negation as :func:`minus` and sympy form
    it, a product's walk and sign as :meth:`_walk` and :func:`minus_first`
    find them.  How many of each were checked."""
    seen = {"opposite": 0, "product": 0, "positive product": 0}
    for k in range(1, len(book) + 1):
        variables, body = book.canonical(k)
        for x in variables:
            got = book._products_pd(body, x, book._pd_memos.setdefault(x, {}))
            if got is None or not got[1]:
                continue
            d, walked = got
            assert len(walked) == 7
            if d.is_Add:
                if walked[6] is not None:
                    assert walked[4] is True
                    negated = book._products_opposite(*walked[6])
                    # (one book: == compares the arguments in their order)
                    assert negated.args == autoz.minus(d).args, d
                    assert negated.args == (-d).args, d
                    seen["opposite"] += 1
                continue
            assert d.is_Mul and not autoz.trivial(d), d
            variables_, derivatives, bad, size = book._walk(d)
            assert (set(walked[0]), set(walked[1])) == (
                set(variables_),
                set(derivatives),
            )
            assert walked[2] == bad == [] and walked[3] == size
            assert walked[4] == autoz.minus_first(d), d
            assert walked[5] and book._split(d) is d
            assert walked[6] is None
            seen["product"] += 1
            seen["positive product"] += not walked[4]
    return seen


@pytest.mark.parametrize("seed", range(4))
def test_what_the_shortcut_hands_on_is_the_long_ways(seed):
    seen = _checked(_build(seed))
    assert seen["opposite"] > 40, seen
    assert 10 < seen["positive product"] < seen["product"], seen


def test_the_check_finds_a_wrong_negation(monkeypatch):
    """Terms of the negation left in the sum's own order (sympy orders
    ``-d``'s terms anew) are found."""

    def wrong(self, collected, number):
        terms = []
        for coeff, rest, *_ in collected.values():
            if coeff is sp.S.NegativeOne:
                terms.append(rest[0] if len(rest) == 1 else autoz._product(rest))
            elif coeff is not autoz._ZERO:
                terms.append(autoz._product((-coeff, *rest)))
        if number is not autoz._ZERO:
            terms.insert(0, -number)
        return sp.Add._from_args(terms, is_commutative=True)

    monkeypatch.setattr(Intermediates, "_products_opposite", wrong)
    with pytest.raises(AssertionError):
        for seed in range(4):
            _checked(_build(seed))


class _LongWay(Intermediates):
    """A book that takes every partial derivative the long way."""

    def _products_pd(self, e, x, memo):
        return None


@pytest.mark.parametrize("seed", range(2))
def test_the_names_agree_with_the_long_way(seed):
    """Books built with the shortcut and without it name the same
    definitions in the same order."""
    fast, slow = _build(seed), _build(seed, _LongWay())
    assert len(fast) > 150
    assert [_tree(fast.canonical(k)[1]) for k in range(1, len(fast) + 1)] == [
        _tree(slow.canonical(k)[1]) for k in range(1, len(slow) + 1)
    ]
