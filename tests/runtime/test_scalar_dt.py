"""``Dt()`` of a scalar (``model.kinematics.scalar_dt``) is sympy's
``diff(e, t)``: the same expression, built alike (``srepr``), with the
intermediates named on the way in the same order, on random sums and
products of a book's intermediates, functions of time and their rates,
constants, ``t``, functions, powers of sums and numbers; an expression
holding an infinity is sympy's own."""

from __future__ import annotations

import random

import sympy as sp
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model.kinematics import scalar_dt
from sympy.physics.mechanics import dynamicsymbols

q1, q2, u1, u2 = dynamicsymbols("q1 q2 u1 u2")
L, M = sp.symbols("L M", real=True)
t = dynamicsymbols._t


def _same_tree(a, b) -> bool:
    return a == b and sp.srepr(a) == sp.srepr(b)


def _book_and_cases(seed: int, n: int = 150) -> tuple[Intermediates, list]:
    """A book of a few intermediates (made alike for every call with the
    same seed) and ``n`` random expressions over them."""
    rng = random.Random(seed)
    book = Intermediates()
    z1 = book.name(sp.cos(q1) * sp.sin(q2) * u1 + L * sp.cos(q2) * u2)
    z2 = book.name(z1**2 * M + sp.sin(q1) * u1.diff(t))
    z3 = book.name(sp.sqrt(1 - z1**2) * L + z2 * q2)
    atoms = [z1, z2, z3, q1, q2, u1, u2, u1.diff(t), L, M, t, sp.S(2)]
    atoms += [sp.Rational(-3, 2), sp.Float(0.25), sp.sin(q1), sp.cos(q2 + L)]
    atoms += [sp.sqrt(L**2 + q1**2), 1 / (z1 + q2), sp.exp(u1), q1**2]
    atoms += [(L + M * t) ** 3, sp.tan(z2)]
    cases = []
    for _ in range(n):
        e = rng.choice(atoms)
        for _ in range(rng.randint(1, 5)):
            part = sp.Mul(*rng.sample(atoms, rng.randint(1, 3)))
            e = e + part if rng.random() < 0.5 else e * (part + rng.choice(atoms))
        cases.append(e)
    return book, cases


def test_a_scalars_time_derivative_is_sympys():
    book, cases = _book_and_cases(5)
    nonzero = 0
    for e in cases:
        mine, sympys = scalar_dt(e), sp.diff(e, t)
        assert _same_tree(mine, sympys), e
        nonzero += mine != 0
    assert nonzero > 100  # most cases say something


def _definitions(book: Intermediates) -> list[str]:
    zs = [book.Z(k, *book.canonical(k)[0]) for k in range(1, len(book) + 1)]
    return [sp.srepr(book.definition(z)) for z in zs]


def test_the_intermediates_named_on_the_way_are_sympys():
    """The derivatives of intermediates are named as sympy's walk names
    them: two books made alike, one differentiated by each way, end with
    the same definitions in the same order (and the same results)."""
    ours, cases_ours = _book_and_cases(11, 60)
    theirs, cases_theirs = _book_and_cases(11, 60)
    before = len(ours)
    mine = [scalar_dt(e) for e in cases_ours]
    sympys = [sp.diff(e, t) for e in cases_theirs]
    assert len(ours) == len(theirs) > before  # derivatives were named
    assert _definitions(ours) == _definitions(theirs)
    assert [sp.srepr(e) for e in mine] == [sp.srepr(e) for e in sympys]


def test_an_infinity_is_sympys_own():
    """``0 * oo`` is ``nan``: a product holding an infinity whose factor's
    derivative is zero is sympy's (not the zero term left out)."""
    for e in (sp.oo * q1 * L + u1, sp.zoo * q1 * M * u1, q1 * (u1 + sp.nan)):
        assert _same_tree(scalar_dt(e), sp.diff(e, t))
    assert scalar_dt(sp.oo * q1 * M) is sp.nan  # (M's term is 0 * oo)
