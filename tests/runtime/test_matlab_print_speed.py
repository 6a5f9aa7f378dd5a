"""The MATLAB printer's shorter ways (issue 35: ``al2py code`` faster, the
same bytes) give sympy's order and text: names ordered by name before the
other items of a sum's generators or a product's factors
(``printers.key_order``, a lone other item's key not formed), on seeded
random sums and products compared with sympy's ``default_sort_key``,
``as_ordered_terms`` and ``OctaveCodePrinter``."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen.octave import _Printer as OctavePrinter
from al2py_runtime.codegen.printers import _head, _key, _ordered_terms, key_order
from conftest import tier_cases
from random_exprs import ExpressionMaker
from sympy.printing.octave import OctaveCodePrinter

#: names that sort apart by digits and case, one name twice with other
#: assumptions (two keys alike)
NAMES = list(sp.symbols("Q1 Q10 Q2 U4 z1 z12 z2 LAM ibxx IBxx", real=True))
NAMES += [sp.Symbol("z1"), sp.Symbol("a")]
X, Y = NAMES[0], NAMES[4]
#: items whose keys begin above a name's, and some that do not (powers of
#: names, number constants, a dummy, numbers)
OTHERS = [
    sp.sin(X),
    sp.cos(X + Y),
    sp.exp(Y),
    sp.Abs(X),
    sp.tan(sp.Symbol("LAM", real=True)),
    sp.Function("f")(X),
    1 - Y**2,
    X + Y + 1,
    sp.sqrt(1 - Y**2),
    (X + Y) ** sp.Rational(3, 2),
    X**2,
    Y ** sp.Rational(1, 2),
    sp.pi,
    sp.Dummy("d"),
    sp.Integer(3),
    sp.Rational(-1, 2),
]


def _items(rng: random.Random) -> list:
    pool = NAMES * 2 + OTHERS
    return [rng.choice(pool) for _ in range(rng.randint(1, 7))]


def test_heads_are_sympys():
    for item in NAMES + OTHERS:
        assert _head(item, {}) == sp.default_sort_key(item)[0], item
        keys: dict = {}
        sp.default_sort_key(item)
        assert _head(item, keys) == _head(item, keys), item


def test_key_order_is_sympys():
    rng = random.Random(35)
    for _ in range(tier_cases(3000)):
        items = _items(rng)
        want = sorted(items, key=sp.default_sort_key)
        got = key_order(items, {})
        assert [sp.srepr(x) for x in got] == [sp.srepr(x) for x in want], items
        keyed = [sp.default_sort_key(x) for x in want]
        alike = any(a == b for a, b in zip(keyed, keyed[1:], strict=False))
        distinct = key_order(items, {}, True)
        if alike:
            assert distinct is None, items
        else:
            assert distinct == got, items


def test_key_order_with_keys_known():
    # one memo for all: a key found before is read, not formed again
    rng = random.Random(36)
    keys: dict = {}
    for _ in range(tier_cases(1000)):
        items = _items(rng)
        want = sorted(items, key=sp.default_sort_key)
        assert key_order(items, keys) == want, items


def test_sums_are_ordered_as_sympys():
    rng = random.Random(37)
    factors = NAMES + OTHERS[:12]
    for _ in range(tier_cases(2000)):
        terms = []
        for _ in range(rng.randint(2, 8)):
            powers = [
                rng.choice(factors) ** rng.choice([1, 1, 1, 2, -1, -2])
                for _ in range(rng.randint(0, 4))
            ]
            terms.append(
                rng.choice([1, 1, -1, 2, sp.Rational(-3, 2)]) * sp.Mul(*powers)
            )
        expr = sp.Add(*terms)
        if not expr.is_Add or expr.has(sp.zoo, sp.nan):
            continue
        for named in (True, False):
            got = _ordered_terms(expr, {}, {}, {}, named)
            assert got == expr.as_ordered_terms(), expr


MAKER = ExpressionMaker(
    leaves=NAMES + OTHERS[:8] + [sp.Integer(2), sp.Float(0.25)],
    coefficients=[sp.Integer(2), sp.Integer(-3), sp.Rational(1, 2), -1],
    exponents=[2, 3, -1, -2, sp.Rational(1, 2), sp.Rational(-3, 2)],
    leaf_chance=0.25,
)


def test_random_statements_print_as_sympys():
    rng = random.Random(38)
    ours = OctavePrinter({"strict": True})
    count = 0
    while count < tier_cases(600):
        expr = MAKER.make(rng, 4)
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or expr.has(sp.Function("f")):
            continue
        count += 1
        theirs = OctaveCodePrinter({"strict": True})
        target = f"z{count}"
        assert ours.doprint(expr, assign_to=target) == theirs.doprint(
            expr, assign_to=target
        ), expr


def _with_special(rng: random.Random) -> sp.Expr:
    """A random statement, a third of them holding a part that makes it not
    plain (a number constant, ``re``, an element of an ``IndexedBase``),
    or ``sinc`` (printed with ``pi``, held by none of its parts)."""
    v = sp.IndexedBase("v")
    special = [sp.pi * X, sp.re(sp.Symbol("a")), v[1] * Y, sp.E + Y, sp.sinc(X)]
    expr = MAKER.make(rng, 3)
    if rng.random() < 0.35:
        part = rng.choice(special)
        expr = rng.choice([expr + part, expr * part, part, part + Y])
    return expr


def test_watched_statements_print_as_sympys():
    """One printer for all statements (the plain ones printed watching for
    the parts that make a statement not plain, each part's text
    remembered), sympy's printer afresh for each; a statement sympy cannot
    print raises in both."""
    rng = random.Random(39)
    ours = OctavePrinter({"strict": True})
    count = 0
    while count < tier_cases(800):
        expr = _with_special(rng)
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or expr.has(sp.Function("f")):
            continue
        count += 1
        target = rng.choice([f"z{count}", sp.Symbol(f"z{count}"), None])
        if _prints_as_sympy(ours, expr, target):
            # again: the statement's parts remembered
            _prints_as_sympy(ours, expr, target)


def _prints_as_sympy(ours: OctavePrinter, expr: sp.Expr, target: object) -> bool:
    """Our statement is sympy's printer's, afresh, or raises as it does
    (then False)."""
    try:
        want = OctaveCodePrinter({"strict": True}).doprint(expr, assign_to=target)
    except Exception as exc:  # noqa: BLE001
        with pytest.raises(type(exc)):
            ours.doprint(expr, assign_to=target)
        return False
    assert ours.doprint(expr, assign_to=target) == want, expr
    return True


def _sums_of_names(rng: random.Random) -> sp.Expr:
    """A sum of names and products of names (after a number): names that
    sort apart by digits and case, one name twice with other assumptions,
    a name that does not commute, a name after every other (its first
    character the last one), a product holding a name twice."""
    odd = [sp.Symbol("z1"), sp.Symbol("nc", commutative=False)]
    odd += [sp.Symbol("\U0010ffffw"), sp.Mul(X, X, evaluate=False)]
    pool = NAMES[:10] * 3 + odd

    def term() -> sp.Expr:
        coefficient = rng.choice([1, 1, 1, -1, -1, 2, sp.Rational(-1, 2)])
        return sp.Mul(coefficient, *rng.sample(pool, rng.randrange(1, 4)))

    expr = sp.Add(*[term() for _ in range(rng.randrange(1, 8))])
    return expr + rng.choice([0, 0, 0, 1, sp.Rational(3, 2)])


def test_sums_of_names_print_as_sympys():
    """Sums of names printed from each name's entry, kept by one printer
    for all statements, as sympy prints them."""
    rng = random.Random(40)
    ours = OctavePrinter({"strict": True})
    for k in range(tier_cases(3000)):
        expr = _sums_of_names(rng)
        want = OctaveCodePrinter({"strict": True}).doprint(expr, assign_to="r")
        assert ours.doprint(expr, assign_to="r") == want, expr
        for part in expr.args[:2]:
            want = OctaveCodePrinter({"strict": True}).doprint(part, assign_to="r")
            assert ours.doprint(part, assign_to="r") == want, (k, part)


def test_function_statements_print_as_sympys():
    """A statement of a function's value (printed as a plain statement by
    a strict printer), with Floats within (printed without their zeros
    below the statement's own part), as sympy prints it; a ``Piecewise``,
    ``re`` and the functions strict MATLAB cannot print as sympy's
    printer does."""
    rng = random.Random(41)
    f = sp.Float(1.5)
    calls = [
        lambda e: sp.sin(e),
        lambda e: sp.cos(e * f),
        lambda e: sp.exp(e + f),
        lambda e: sp.Abs(e),
        lambda e: sp.sign(e),
        lambda e: sp.floor(e),
        lambda e: sp.atan2(e, f),
        lambda e: sp.Max(e, f),
        lambda e: sp.sinc(e),
        lambda e: sp.re(e),
        lambda e: sp.Heaviside(e),
        lambda e: sp.Piecewise((e, X > 0), (f, True)),
        lambda e: sp.Function("g")(e),
        lambda e: sp.tan(sp.pi * e),
    ]
    ours = OctavePrinter({"strict": True})
    for k in range(tier_cases(600)):
        expr = rng.choice(calls)(MAKER.make(rng, 2))
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not isinstance(expr, sp.Function):
            continue
        target = rng.choice([f"z{k}", sp.Symbol(f"z{k}"), None])
        _prints_as_sympy(ours, expr, target)


def test_keys_of_sums_are_sympys():
    """A sum's key and a power of a sum's, formed with the printer's order
    of the sum's terms, equal sympy's; their class key is read off."""
    rng = random.Random(42)
    keys: dict = {}
    sums = ({}, {})
    count = 0
    while count < tier_cases(800):
        expr = MAKER.make(rng, 3)
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or not expr.is_Add:
            continue
        count += 1
        power = sp.Pow(expr, rng.choice([-1, 2, sp.Rational(1, 2), sp.Rational(-3, 2)]))
        for item in (expr, power):
            want = sp.default_sort_key(item)
            assert _head(item, {}) == want[0], item
            assert _key(item, {}, ({}, {})) == want, item
            assert _key(item, keys, sums) == want, item  # memos shared


def test_products_of_sums_print_as_sympys():
    """Products of names, sums and powers of sums (their factors ordered
    by the sums' keys formed by the printer)."""
    rng = random.Random(43)
    ours = OctavePrinter({"strict": True})
    sums = [MAKER.make(rng, 2) for _ in range(40)]
    sums = [e for e in sums if e.is_Add and not e.has(sp.zoo, sp.nan, sp.Function("f"))]
    for k in range(1500):
        factors = rng.sample(NAMES[:8], rng.randrange(0, 3))
        for _ in range(rng.randrange(1, 4)):
            factors.append(
                rng.choice(sums) ** rng.choice([1, 1, -1, 2, sp.Rational(-3, 2)])
            )
        expr = rng.choice([1, -1, 2]) * sp.Mul(*factors)
        expr = expr + rng.choice([0, X * Y, sp.sin(X) * rng.choice(sums)])
        if expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            continue
        want = OctaveCodePrinter({"strict": True}).doprint(expr, assign_to="r")
        assert ours.doprint(expr, assign_to="r") == want, (k, expr)
