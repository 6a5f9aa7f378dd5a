"""The program printers (``codegen/printers.py``: each part printed once, a
plain assignment printed without ``doprint``, a sum's terms ordered from its
factors' bases and exponents) print what sympy's printers print, statement
by statement (issue 35: ``al2py code`` faster, the same bytes).

The reference is sympy's own printer (MATLAB, Fortran) or the C backend's
printer through sympy's dispatch and ``doprint`` (C), one per program as
the program printers are (Fortran names a symbol when it first prints it),
on random expressions of a program's shape and on the statements of the
programs ``al2py code`` writes for tutor6 and, when the corpus is there,
Moore's Whipple bicycle."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
import sympy as sp
from al2py_runtime.codegen import form
from al2py_runtime.codegen.c import _Printer as CProgramPrinter
from al2py_runtime.codegen.fortran import _Printer as FortranPrinter
from al2py_runtime.codegen.octave import _Printer as OctavePrinter
from al2py_runtime.codegen.printers import _ordered_terms
from al2py_runtime.codegen.program import one_based_target
from al2py_runtime.jobs.backends import CPrinter
from conftest import ROOT
from random_exprs import ExpressionMaker
from sympy.printing.fortran import FCodePrinter
from sympy.printing.octave import OctaveCodePrinter

from al2py.transpile import convert

FORTRAN = {"source_format": "fixed", "standard": 95, "strict": True}


class SympysFortran(FCodePrinter):
    """sympy's Fortran printer with the program's ``sign`` (sympy's needs
    a ``merge`` of integers)."""

    _print_sign = FortranPrinter._print_sign


#: language -> (the program printer, the reference printer), each new
PRINTERS = {
    "c": (CProgramPrinter, CPrinter),
    "m": (
        lambda: OctavePrinter({"strict": True}),
        lambda: OctaveCodePrinter({"strict": True}),
    ),
    "f": (FortranPrinter, lambda: SympysFortran(FORTRAN)),
}

SYMBOLS = list(sp.symbols("Q1 Q2 U1 U2 z3 z12 z117 LAM MA", real=True))
#: a plain symbol named as another, and one that prints as another in
#: Fortran (names there are one whatever their case)
SYMBOLS += [sp.Symbol("z3"), sp.Symbol("q1", real=True)]
NUMBERS = [
    sp.Integer(2),
    sp.Integer(-3),
    sp.Rational(1, 2),
    sp.Rational(-3, 7),
    sp.Float(0.25),
    sp.Float(-1.5),
]
MAKER = ExpressionMaker(
    leaves=SYMBOLS + NUMBERS[:2] + [sp.sin(SYMBOLS[0]), sp.cos(SYMBOLS[2])],
    coefficients=[*NUMBERS, -1, sp.pi],
    exponents=[2, 3, -1, -2, sp.Rational(1, 2), sp.Rational(-3, 2)],
    leaf_chance=0.25,
)


def _statements(seed: int, n: int) -> list[sp.Expr]:
    """Random statements sharing parts as a program's do (a later one holds
    an earlier one, or one's parts), and a Float alone (printed with its
    zeros) and within."""
    rng = random.Random(seed)
    out: list[sp.Expr] = [sp.Float(1.5), SYMBOLS[0] + sp.Float(1.5), sp.Float(1.5)]
    while len(out) < n:
        expr = MAKER.make(rng, 4)
        if rng.random() < 0.3:
            expr = expr + rng.choice(out) * rng.choice(SYMBOLS)
        if rng.random() < 0.2:
            expr = rng.choice([*out[-1].args, expr])
        if not expr.has(sp.zoo, sp.nan, sp.oo, -sp.oo):
            out.append(expr)
    return out


def _target(lang: str, k: int) -> object:
    if k % 4 == 0:
        return f"dy({k})"
    return sp.Symbol(f"z{k}", real=True) if lang == "f" else f"z{k}"


def _same(lang: str, pairs: list[tuple[sp.Expr, object]]) -> None:
    """Each statement printed by a program printer and by the reference."""
    ours, theirs = (make() for make in PRINTERS[lang])
    for expr, target in pairs:
        if lang == "c":
            want, got = theirs.doprint(expr), ours.doprint(expr)
        else:
            want = theirs.doprint(expr, assign_to=target)
            got = ours.doprint(expr, assign_to=target)
        assert got == want, (lang, expr, target)


@pytest.mark.parametrize("lang", ["c", "m", "f"])
def test_random_statements_print_as_sympys(lang):
    statements = _statements(35, 300)
    _same(lang, [(e, _target(lang, k)) for k, e in enumerate(statements)])


def test_sums_are_ordered_as_sympys():
    """A sum's terms, ordered from their factors' bases and exponents (or
    by sympy's ``as_terms`` where that does not decide), in sympy's order."""
    rng = random.Random(7)
    factors = [*SYMBOLS, sp.sin(SYMBOLS[1]), 1 - SYMBOLS[5] ** 2, sp.sqrt(2)]
    for _ in range(1500):
        terms = []
        for _ in range(rng.randint(2, 7)):
            powers = [
                rng.choice(factors) ** rng.choice([1, 1, 2, 3, -1, sp.Rational(-3, 2)])
                for _ in range(rng.randint(0, 4))
            ]
            terms.append(rng.choice([*NUMBERS, 1, -1]) * sp.Mul(*powers))
        expr = sp.Add(*terms)
        if expr.is_Add:
            assert _ordered_terms(expr, {}, {}, {}) == expr.as_ordered_terms(), expr


def _programs(script: Path, lang: str) -> list:
    """The programs ``al2py code --lang lang`` forms for ``script``."""
    code = convert(script.read_text(), str(script), formatted=False).code
    module = Path(script).with_suffix(".py")
    namespace: dict = {"__name__": script.stem, "__file__": str(module)}
    exec(compile(code, str(module), "exec"), namespace)  # noqa: S102
    programs = []
    for job in namespace["al"].numerics.jobs:
        formed = form(job, lang, None)
        assert formed.error is None, formed.error
        programs.append(formed.program)
    return programs


def _program_statements(program, lang: str) -> list[tuple[sp.Expr, object]]:
    pairs = []
    for a in [*program.eqns, *program.outputs]:
        if a.target[0] == "ud":
            continue  # written by the program, not printed
        target = one_based_target(a)
        if lang == "f" and "(" not in target:
            target = sp.Symbol(target, real=True)
        pairs.append((sp.sympify(a.expr), target))
    return pairs


@pytest.mark.parametrize("lang", ["c", "m", "f"])
def test_tutor6_statements_print_as_sympys(lang):
    for program in _programs(ROOT / "examples" / "tutor6.al", lang):
        pairs = _program_statements(program, lang)
        assert len(pairs) > 10
        _same(lang, pairs)


WHIPPLE = (
    ROOT.parent
    / "corpus"
    / "moorepants__AutolevToolKit"
    / "models"
    / "Whipple"
    / "Whipple.al"
)


@pytest.mark.slow
@pytest.mark.skipif(not WHIPPLE.exists(), reason=f"needs the corpus ({WHIPPLE})")
@pytest.mark.parametrize("lang", ["c", "m", "f"])
def test_whipple_statements_print_as_sympys(lang, tmp_path):
    script = tmp_path / "Whipple.al"
    script.write_text(WHIPPLE.read_text())
    programs = _programs(script, lang)
    assert len(programs) == 3
    for program in programs:
        # the first statements of each routine (sympy's own printers take
        # long over all of them)
        pairs = _program_statements(program, lang)
        assert len(pairs) > 900
        _same(lang, pairs[:600] + pairs[-300:])


def test_equal_numbers_of_two_classes_keep_their_own_text():
    """sympy's ``==`` holds between a Float and Fortran's ``literal_dp`` of
    one value, which print apart: a part's text is remembered with a
    number's class."""
    from sympy.codegen.fnodes import literal_dp

    printer = FortranPrinter()
    assert sp.Float(1.0) == literal_dp(1)
    first = printer.print_part(sp.Float(1.0))
    assert printer.print_part(literal_dp(1)) == "1d0" != first
