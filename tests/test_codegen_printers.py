"""The program printers' faster paths print what sympy's printers print
(issue 35): the MATLAB and Fortran printers remember sort keys, number
tests and precedences; the C printer reads a product's precedence from its
leading factor."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen.c import _Printer as CProgramPrinter
from al2py_runtime.codegen.fortran import _Printer as FortranPrinter
from al2py_runtime.codegen.octave import _Printer as OctavePrinter
from al2py_runtime.jobs.backends import CPrinter, precedence_of
from sympy.printing.c import C99CodePrinter
from sympy.printing.fortran import FCodePrinter
from sympy.printing.octave import OctaveCodePrinter
from sympy.printing.precedence import precedence

X, Y, Z, W = sp.symbols("x y z w", real=True)
A, B = sp.symbols("a b")


def _expressions(n: int, seed: int) -> list[sp.Expr]:
    """Random sums, products and powers of a few symbols, functions and
    numbers (negative, rational, float, imaginary)."""
    rng = random.Random(seed)
    atoms = [X, Y, Z, W, A, B, sp.Integer(2), sp.Rational(-3, 7), sp.Float(1.5)]
    atoms += [sp.pi, -sp.Integer(1), sp.I * 3]

    def grow(depth: int) -> sp.Expr:
        if depth == 0:
            return rng.choice(atoms)
        kind = rng.randrange(6)
        if kind == 0:
            return sp.Add(*[grow(depth - 1) for _ in range(rng.randrange(2, 5))])
        if kind == 1:
            return sp.Mul(*[grow(depth - 1) for _ in range(rng.randrange(2, 4))])
        if kind == 2:
            return grow(depth - 1) ** rng.choice([-1, 2, -2, sp.Rational(1, 2), 3])
        if kind == 3:
            return rng.choice([sp.sin, sp.cos, sp.exp, sp.Abs])(grow(depth - 1))
        if kind == 4:
            return -grow(depth - 1)
        return grow(depth - 1) / grow(depth - 1)

    out = [grow(rng.randrange(1, 5)) for _ in range(n)]
    return [e for e in out if not e.has(sp.zoo, sp.nan, sp.oo, -sp.oo)]


EXPRS = _expressions(300, 35)


def test_precedence_of_products_is_sympys():
    products = [
        -X * Y,
        2 * X,
        -2 * X,
        X * sp.sin(Y),
        -sp.oo * X,
        sp.zoo * X,
        sp.Rational(-1, 2) * X,
        -X / Y,
        sp.I * X,
        -sp.I * X,
    ]
    products += [e for e in EXPRS if isinstance(e, sp.Mul)]
    assert len(products) > 50
    for e in products:
        assert precedence_of(e) == precedence(e), e


#: our MATLAB and Fortran printers, sympy's, and the settings they share
MATLAB_AND_FORTRAN = pytest.mark.parametrize(
    ("ours", "theirs", "settings"),
    [
        (OctavePrinter, OctaveCodePrinter, {"strict": True}),
        (
            lambda s: FortranPrinter(),
            FCodePrinter,
            {"source_format": "fixed", "standard": 95, "strict": True},
        ),
    ],
    ids=["matlab", "fortran"],
)


@MATLAB_AND_FORTRAN
def test_matlab_and_fortran_print_as_sympy(ours, theirs, settings):
    mine = ours(settings)
    for e in EXPRS:
        if e.has(sp.I) and theirs is FCodePrinter:
            continue  # complex numbers: sympy's own path, unchanged
        assert mine.doprint(e, assign_to="r") == theirs(settings).doprint(
            e, assign_to="r"
        ), e


def test_c_prints_as_sympy_without_order():
    mine = CPrinter()
    theirs = C99CodePrinter({"strict": True, "order": "none"})
    for e in EXPRS:
        if e.has(sp.I) or e.has(sp.pi) or e.has(sp.Pow):
            continue  # CPrinter's own powers, functions and numbers
        assert mine.doprint(e) == theirs.doprint(e), e


def _shared_parts() -> list[sp.Expr]:
    """Statements sharing parts in different places: a Float alone (printed
    with its zeros) and inside a sum (without), a number constant that
    Fortran declares in front of each statement using it, the random
    expressions and their parts again."""
    f = sp.Float(1.5)
    shared = [f, X + f, f, sp.GoldenRatio * X, Y + sp.GoldenRatio * X]
    shared += [sp.sin(X) * f, sp.sin(X) * f + Y, -sp.sin(X) * f]
    # re(...) in a statement: sympy's own handling of the statement
    shared += [sp.sin(X) + sp.re(A), sp.sin(X), sp.re(A) * Y, sp.re(A)]
    for e in EXPRS[:120]:
        shared += [e, *e.args, e + Y, e]
    return shared


@MATLAB_AND_FORTRAN
def test_parts_printed_once_print_as_sympy(ours, theirs, settings):
    # one printer for all statements (each part's text remembered), sympy's
    # printer afresh for each
    mine = ours(settings)
    for e in _shared_parts():
        if e.has(sp.I, sp.re) and theirs is FCodePrinter:
            continue  # strict Fortran cannot print re (nor can sympy's)
        if e.has(sp.GoldenRatio) and theirs is OctaveCodePrinter:
            continue  # strict MATLAB cannot print it (nor can sympy's)
        want = theirs(settings).doprint(e, assign_to="r")
        assert mine.doprint(e, assign_to="r") == want, e
        # without a target the statement's own part is printed first (a
        # Float alone with its zeros)
        assert mine.doprint(e) == theirs(settings).doprint(e), e


def test_c_parts_printed_once_print_as_the_backends():
    mine = CProgramPrinter()
    for e in _shared_parts():
        if e.has(sp.GoldenRatio, sp.re):
            continue  # strict C99 cannot print them
        assert mine.doprint(e) == CPrinter().doprint(e), e


def test_c_statements_with_re_handled_as_the_backends():
    mine = CProgramPrinter()
    u = sp.UnevaluatedExpr(X)
    for e in [sp.sin(A) + sp.re(u), sp.sin(A), sp.re(u) * A, sp.re(A), X + A]:
        assert mine._handle_UnevaluatedExpr(e) == CPrinter()._handle_UnevaluatedExpr(
            e
        ), e


def _sums_of_names(n: int, seed: int, clashing: bool = True) -> list[sp.Expr]:
    """Random products of names (after -1 or another number) and sums of
    them, what most of a program's statements are: names that sort apart
    by digits (``Q1 < Q10 < Q2``), terms of one monomial, a lone name, a
    number term; ``clashing``: names alike without case (``ibxx``,
    ``IBxx``) and a name twice with other assumptions (which Fortran's
    printer names apart, in the order it first meets them)."""
    rng = random.Random(seed)
    names = [sp.Symbol(s, real=True) for s in ("Q1", "Q10", "Q2", "z1", "z12", "z2")]
    names += [sp.Symbol("ibxx", real=True), A, B]
    if clashing:
        names += [sp.Symbol("IBxx", real=True), sp.Symbol("a", real=True)]

    def term() -> sp.Expr:
        coefficient = rng.choice([1, 1, 1, -1, -1, 2, sp.Rational(-1, 2)])
        return sp.Mul(coefficient, *rng.sample(names, rng.randrange(1, 5)))

    out = []
    for _ in range(n):
        e = sp.Add(*[term() for _ in range(rng.randrange(1, 7))])
        out.append(e + rng.choice([0, 0, 0, 1, sp.Rational(3, 2)]))
    return out


@MATLAB_AND_FORTRAN
def test_sums_of_products_of_names_print_as_sympy(ours, theirs, settings):
    # the products of names (and -1) and the order of sums of them that
    # the program printers form at once (printers._ordered_by_names)
    mine = ours(settings)
    for e in _sums_of_names(3000, 7, clashing=theirs is not FCodePrinter):
        assert mine.doprint(e, assign_to="r") == theirs(settings).doprint(
            e, assign_to="r"
        ), e


def test_c_products_of_names_print_as_sympy():
    mine, program = CPrinter(), CProgramPrinter()
    theirs = C99CodePrinter({"strict": True, "order": "none"})
    for e in _sums_of_names(1000, 8):
        for part in [e, *e.args]:
            assert mine.doprint(part) == theirs.doprint(part), part
            assert program.doprint(part) == theirs.doprint(part), part


def test_holds_instance_is_sympys_walk():
    """``holds_instance`` (each part asked once per memo) answers as
    sympy's walk of every part, for the printers' kinds (names are never
    one of them) and for names themselves."""
    from al2py_runtime.codegen.printers import _SPECIAL, holds_instance
    from sympy.core.traversal import iterargs

    rng = random.Random(12)
    base = sp.IndexedBase("v")
    extra = [sp.re(A), sp.pi * X, base[1], sp.E + Y, sp.GoldenRatio]
    exprs = list(EXPRS) + [e * rng.choice(extra) for e in EXPRS[:150]]
    exprs += [e + rng.choice(extra) for e in EXPRS[150:]]
    for kinds in (_SPECIAL, (sp.Symbol,), (sp.cos, sp.Float)):
        memo: dict = {}
        for e in exprs:
            want = any(isinstance(x, kinds) for x in iterargs(e))
            assert holds_instance(e, kinds, memo) is want, (e, kinds)
