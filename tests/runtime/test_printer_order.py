"""The transcript printer's own orderings are sympy's (issue 35: the same bytes).

The printer orders a sum's terms and a product's factors by keys it reads off
what it already knows (each factor's key, an integer's number as a Python
int) rather than calling sympy for each; tidy's node walks count without
sympy's generators.  Each is checked against sympy's own on many random
expressions, with intermediates' shape (``Z(number, variables...)``) among
them, and the printer's text against a printer that asks sympy for each key.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.model import kinematics as kin
from al2py_runtime.names import printing
from al2py_runtime.names.printing import Printing, sort_key_in
from random_exprs import ExpressionMaker
from sympy.physics.mechanics import dynamicsymbols

t = dynamicsymbols._t
Q1, Q2, U1, U2 = dynamicsymbols("Q1 Q2 U1 U2")
A, B, C = sp.symbols("A B C", real=True)
Z = sp.Function("Z")
#: intermediates' shape: their keys differ in their first argument's number
ZS = [Z(sp.Integer(n), A, Q1) for n in (3, 12, 711, 715, 10**20)] + [Z(7, B)]
ATOMS = [Q1, Q2, U1, U2, A, B, C, U1.diff(t), Q1.diff(t), *ZS]
NUMBERS = [
    sp.Integer(2),
    sp.Integer(-3),
    sp.Integer(715),
    sp.Rational(1, 2),
    sp.Float(0.25),
    sp.Float(2.0),
    sp.pi,
    sp.oo,
]


MAKER = ExpressionMaker(
    leaves=ATOMS + NUMBERS[:3],
    coefficients=NUMBERS[:6],
    exponents=[2, 3, -1, -2, sp.Rational(1, 2)],
    leaf_chance=0.25,
    intermediate=lambda rng, parts: Z(
        sp.Integer(rng.choice([5, 711, 715])), *parts[:2]
    ),
)


def expressions(seed: int, count: int, depth: int = 4) -> list[sp.Expr]:
    rng = random.Random(seed)
    return [MAKER.make(rng, depth) for _ in range(count)]


def test_keys_equal_and_order_as_sympys():
    """Every node's key equals sympy's, and sorting by them gives sympy's
    order, numbers of every kind and intermediates' numbers among them."""
    memo: dict = {}
    for expr in expressions(35, 150):
        found = list(sp.preorder_traversal(expr)) + NUMBERS + ZS
        for node in found:
            assert sort_key_in(node, memo) == sp.default_sort_key(node), node
        ours = sorted(found, key=lambda e: sort_key_in(e, memo))
        assert ours == sorted(found, key=sp.default_sort_key)
        assert [str(e) for e in ours] == [
            str(e) for e in sorted(found, key=sp.default_sort_key)
        ]


class _SympysKeys(printing._AutolevPrinter):
    """The printer with each ordering key asked of sympy (the orderings as
    the printer defines them, without anything remembered)."""

    def factor_key(self, factor):
        base = factor.as_base_exp()[0]
        return (isinstance(base, sp.Add), sp.default_sort_key(factor))

    def sorted_factors(self, factors):
        return sorted(factors, key=self.factor_key)

    def term_key(self, term):
        degree = 0
        args = term.args if term.is_Mul else (term,)
        factors = []
        for factor in args:
            if factor.is_number:
                continue
            factors.append(factor)
            _, exp = factor.as_base_exp()
            power = int(exp) if exp.is_Integer else 0
            degree += power if power > 0 else 1
        if len(factors) == len(args):
            rest = term if len(args) > 1 else factors[0]
        elif len(factors) < 2:
            rest = factors[0] if factors else sp.S.One
        else:
            rest = sp.Mul._from_args(factors)
        return (degree, len(factors), sp.default_sort_key(rest))


def test_terms_and_factors_ordered_as_with_sympys_keys():
    ours = printing._AutolevPrinter(7)
    theirs = _SympysKeys(7)
    compared = 0
    for expr in expressions(7, 300):
        for node in sp.preorder_traversal(expr):
            if node.is_Add:
                assert sorted(node.args, key=ours.term_key) == sorted(
                    node.args, key=theirs.term_key
                )
                compared += 1
            if node.is_Mul:
                factors = list(node.args)
                assert ours.sorted_factors(factors) == theirs.sorted_factors(factors)
                compared += 1
    assert compared > 1000


def test_printed_as_with_sympys_keys():
    """The text, shared memos and all, is the text with sympy's keys."""
    exprs = expressions(11, 300)
    shared = Printing()
    ours = [shared.autolev_str(e) for e in exprs]
    theirs = [_SympysKeys(7).text(e, True) for e in exprs]
    assert ours == theirs


def test_tidy_walks_count_as_sympys():
    for expr in expressions(3, 200, depth=5):
        assert kin._nodes(expr) == set(sp.preorder_traversal(expr))
        size = sum(1 for _ in sp.preorder_traversal(expr))
        for limit in (size - 1, size, size + 1, 160):
            assert kin.is_small(expr, limit) == (size <= limit)


@pytest.mark.parametrize("seed", [1, 2])
def test_tidy_remembered_is_tidy(seed):
    """The model's ``Tidier`` forms each result once, and it is what tidy
    forms without it (the second time: from memory)."""
    gens = [U1.diff(t), U2.diff(t), U1, U2]
    exprs = [sp.expand(e) for e in expressions(seed, 60, depth=3)]
    plain = [kin.tidy(e, gens) for e in exprs]
    tidier = kin.Tidier()
    remembered = [tidier(e, gens) for e in exprs + exprs]
    assert remembered == plain + plain
    assert [tidier(e) for e in exprs] == [kin.tidy(e) for e in exprs]


def test_products_ordered_as_with_sympys_keys():
    """Sums of products of two and three names (the terms tie on degree and
    count of factors: their order is their keys'), intermediates among
    them."""
    rng = random.Random(5)
    names = [Q1, Q2, U1, A, B, C, *ZS, sp.sin(Q1), sp.cos(Q2)]
    for _ in range(100):
        terms = [sp.Mul(*rng.sample(names, rng.choice([2, 2, 3]))) for _ in range(6)]
        expr = sp.Add(*terms)
        assert printing._AutolevPrinter(7).text(expr, True) == _SympysKeys(7).text(
            expr, True
        )
        ours = printing._AutolevPrinter(7)
        assert sorted(expr.args, key=ours.term_key) == sorted(
            expr.args, key=_SympysKeys(7).term_key
        )
