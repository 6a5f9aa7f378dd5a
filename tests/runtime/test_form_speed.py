"""The shorter ways of forming the C programs (issue 35, ninth pass) give
the same text:

* the C printer prints a plain statement (a sum, product, name or
  function's value) without walking it first, watching for the parts that
  make it not plain (``watches``, ``plain_calls``): one printer for all
  statements prints what ``backends.CPrinter``, afresh, prints;
* ``CPrinter.names_product`` reads each name's text by its spelling (the
  symbol checked by identity): the text each name's printing gives, also
  for two symbols of one name (other assumptions) printed apart.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen.c import _Printer as CProgramPrinter
from al2py_runtime.jobs import backends
from conftest import tier_cases
from random_exprs import ExpressionMaker

NAMES = list(sp.symbols("Q1 Q10 Q2 U4 z1 z12 z2 LAM ibxx IBxx", real=True))
NAMES += [sp.Symbol("z1"), sp.Symbol("a")]
X, Y = NAMES[0], NAMES[4]
MAKER = ExpressionMaker(
    leaves=NAMES + [sp.Integer(2), sp.Rational(1, 3), sp.Float(0.25)],
    coefficients=[-1, -1, 2, sp.Rational(-3, 2), sp.Float(1.5)],
    exponents=[2, 3, -1, -2, sp.Rational(1, 2), sp.Rational(-1, 2), 5],
    leaf_chance=0.3,
)


def _statement(rng: random.Random) -> sp.Expr:
    """A random statement, a third of them holding a part that makes it not
    plain (a number constant, ``re``, an element of an ``IndexedBase``),
    or a function's value alone."""
    v = sp.IndexedBase("v")
    special = [sp.pi * X, sp.re(sp.Symbol("a")), v[1] * Y, sp.E + Y, sp.sinc(X)]
    expr = MAKER.make(rng, 3)
    roll = rng.random()
    if roll < 0.35:
        part = rng.choice(special)
        expr = rng.choice([expr + part, expr * part, part, part + Y])
    elif roll < 0.5:
        expr = rng.choice([sp.sin, sp.cos, sp.Abs, sp.exp])(expr)
    return expr


@pytest.mark.parametrize("seed", range(2))
def test_watched_c_statements_print_as_the_backends(seed):
    rng = random.Random(seed)
    ours = CProgramPrinter()
    assert ours.watches and ours.plain_calls
    count = 0
    while count < tier_cases(900):
        expr = _statement(rng)
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            continue
        count += 1
        try:
            want = backends.CPrinter().doprint(expr)
        except Exception as exc:  # noqa: BLE001
            with pytest.raises(type(exc)):
                ours.doprint(expr)
            continue
        assert ours.doprint(expr) == want, expr
        assert ours.doprint(expr) == want, expr  # its parts remembered


def _names_product_as_before(printer: backends.CPrinter, expr: sp.Expr) -> str | None:
    """``names_product`` as it was: ``math_macros`` asked, the names split
    by ``signed_names``, each printed."""
    if expr in printer.math_macros:
        return None
    names = backends.signed_names(expr)
    if names is None:
        return None
    return names[0] + "*".join([printer.print_part(a) for a in names[1]])


def test_names_products_are_the_names_texts():
    """Two symbols of one spelling that print apart (``names`` renames the
    real one) are each printed as themselves, whichever comes first."""
    rng = random.Random(5)
    plain_x, real_x = sp.Symbol("x"), sp.Symbol("x", real=True)
    pool = NAMES + [plain_x, real_x, sp.sin(X), sp.Integer(3), X**2]
    for names in ({}, {real_x: "X_real", NAMES[1]: "Q_ten"}):
        ours, theirs = backends.CPrinter(names=names), backends.CPrinter(names=names)
        for _ in range(400):
            factors = rng.sample(pool, rng.randint(1, 4))
            if rng.random() < 0.4:
                factors.insert(0, sp.S.NegativeOne)
            expr = sp.Mul(*factors)
            if type(expr) is not sp.Mul:
                continue
            want = _names_product_as_before(theirs, expr)
            assert ours.names_product(expr) == want, expr
            assert ours.doprint(expr) == theirs.doprint(expr), expr


def test_free_symbols_with_a_memo_are_sympys():
    """One memo for many random expressions (products of names after a
    number read at once): each answer is sympy's ``free_symbols``."""
    rng = random.Random(11)
    leaves = NAMES + [sp.Dummy("d"), sp.Function("f")(X), sp.pi, sp.Integer(2)]
    maker = ExpressionMaker(
        leaves=leaves,
        coefficients=[-1, 2, sp.Rational(1, 2)],
        exponents=[2, -1],
        leaf_chance=0.3,
    )
    memo: dict = {}
    for _ in range(tier_cases(900)):
        expr = maker.make(rng, 3)
        if rng.random() < 0.3:
            expr = sp.Integral(expr, X) + Y
        assert backends.free_symbols_of(expr, memo) == expr.free_symbols, expr
