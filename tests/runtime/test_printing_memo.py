"""The transcript printer's remembered work gives what sympy and the printer
without memos give (issue 35: the same bytes, each subexpression formed once)."""

from __future__ import annotations

import random

import sympy as sp
from al2py_runtime.model import kinematics as kin
from al2py_runtime.names import printing
from al2py_runtime.names.printing import Printing, autolev_str, sort_key_in
from random_exprs import ExpressionMaker
from sympy.physics.mechanics import dynamicsymbols

t = dynamicsymbols._t
Q1, Q2, U1, U2, U3 = dynamicsymbols("Q1 Q2 U1 U2 U3")
A, B, C = sp.symbols("A B C", real=True)
ATOMS = [Q1, Q2, U1, U2, U3, A, B, C, U1.diff(t), U2.diff(t), Q1.diff(t)]
NUMBERS = [sp.Integer(2), sp.Integer(-3), sp.Rational(1, 2), sp.Float(0.25), sp.pi]


MAKER = ExpressionMaker(
    leaves=ATOMS + NUMBERS[:2],
    coefficients=NUMBERS,
    exponents=[2, 3, -1, sp.Rational(1, 2)],
    leaf_chance=0.2,
)


def nodes(expr: sp.Basic) -> list:
    return list(sp.preorder_traversal(expr))


def test_sort_keys_are_sympys():
    """Every node's key, products' read off their factors, is sympy's."""
    rng = random.Random(35)
    memo: dict = {}
    for _ in range(150):
        expr = MAKER.make(rng, 4)
        for node in nodes(expr):
            assert sort_key_in(node, memo) == sp.default_sort_key(node), node


def test_shared_subexpressions_formed_once(monkeypatch):
    """A sum whose terms share subtrees (as written-out intermediates do)
    prints each subexpression once, and prints what the printer without
    its memo prints."""
    expr = A + B
    for k in range(12):
        expr = expr * (expr + C) + k * U1
    formed: list = []
    form = printing._AutolevPrinter.form

    def counting(self, e, top):
        formed.append(e)
        return form(self, e, top)

    monkeypatch.setattr(printing._AutolevPrinter, "form", counting)
    text = Printing().autolev_str(expr)
    distinct = set(nodes(expr))
    assert len(formed) <= 2 * len(distinct) < 200  # not once per occurrence
    assert text.count("A+B") == 2**12

    small = A + B
    for k in range(5):
        small = small * (small + C) + k * U1
    remembered = Printing().autolev_str(small)

    def unremembered(self, e, top):
        if isinstance(e, sp.MatrixBase):
            return self.matrix(e), printing._ATOM
        return form(self, e, top)

    monkeypatch.setattr(printing._AutolevPrinter, "form", form)
    monkeypatch.setattr(printing._AutolevPrinter, "show", unremembered)
    assert autolev_str(small) == remembered


def test_collect_of_speeds_is_sympys():
    """tidy's collect on the speeds and their rates: sympy's dictionary, and
    as many of sympy's dummies made (their numbers order later sums)."""
    rng = random.Random(7)
    gens = [U1.diff(t), U2.diff(t), U1, U2, U3]
    fast = 0
    for _ in range(200):
        expr = sp.expand(MAKER.make(rng, 3))
        present = [g for g in gens if expr.has(g)]
        if not present:
            continue
        start = sp.Dummy._count
        ours = kin._collect(expr, present)
        made = sp.Dummy._count - start
        start = sp.Dummy._count
        theirs = sp.collect(expr, present, evaluate=False)
        assert sp.Dummy._count - start == made
        # the same entries; their order follows the names of the dummies,
        # compared as strings ("_Dummy_999" after "_Dummy_1000"), so it
        # depends on sympy's global dummy count (ours are made before
        # sympy's here) and not on our path; tidy rebuilds a sum of them,
        # whose order sympy fixes
        assert ours == theirs
        fast += kin._plain_for(expr, set(present))
    assert fast > 50  # most take the xreplace path; Q1' inside takes sympy's
    assert not kin._plain_for(sp.expand(U1 * Q1.diff(t)), {U1})
    assert not kin._plain_for(sp.Subs(U1 * A, A, 2), {U1})
