"""Shortcuts of the model's light simplification (issue 35): each gives
sympy's result, written alike (the same arguments in the same order),
checked on random expressions shaped like a named model's measure numbers.
Each test also counts how often the shortcut was taken, so it cannot pass
by always asking sympy."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model import kinematics as kin
from conftest import tier_step
from random_exprs import plain_factor, written_tree
from sympy.core.mul import _keep_coeff
from sympy.physics.mechanics import dynamicsymbols
from sympy.simplify.fu import TR10i

T = dynamicsymbols._t
U = dynamicsymbols("U1:5")
Q = dynamicsymbols("Q1:4")
S = [
    sp.Symbol("RF"),
    sp.Symbol("RR", positive=True),
    sp.Symbol("D1", real=True),
    sp.Symbol("K", negative=True),
]


def _book_atoms() -> list:
    book = Intermediates("Z")
    zs = [
        book.name(sp.cos(Q[0]) * sp.sin(Q[1]) + S[0] * sp.cos(Q[2])),
        book.name(sp.sin(Q[0]) * U[0] - S[1] * sp.cos(Q[1])),
        book.name(S[2] * sp.sin(Q[2]) + sp.cos(Q[0]) * sp.cos(Q[1])),
        book.name(U[1] * sp.cos(Q[2]) + S[0] * sp.sin(Q[1]) * S[1]),
    ]
    return zs


ZS = _book_atoms()
#: an intermediate and a function of time whose arguments hold a sum that
#: factor_terms factors (a Specified quantity's value: 10*sin(2*pi*t + pi/6))
ODD = [
    ZS[0].func(*ZS[0].args, 10 * sp.sin(2 * sp.pi * T + sp.pi / 6)),
    sp.Function("F")(2 * sp.pi * T + sp.pi / 6),
    sp.Function("G")(T, 2 * S[0] + 2 * S[2]),
]


def _plain(rng: random.Random) -> sp.Expr:
    """A factor ``factor_terms`` and ``TR10i`` leave alone."""
    return plain_factor(rng, (U, Q, S, ZS, T), ODD)


def _other(rng: random.Random) -> sp.Expr:
    """A factor of another kind (a power, a square root, an angle with
    ``pi``, a number)."""
    z = rng.choice(ZS)
    return rng.choice(
        [
            1 / sp.sqrt(1 - z**2),
            z**2,
            sp.sqrt(2),
            sp.sqrt(3),
            sp.Rational(1, 2),
            2,
            sp.sin(rng.choice(Q) + sp.pi / 4),
            sp.cos(rng.choice(Q)) ** 2,
            sp.sqrt(rng.choice(S[:2])),
        ]
    )


def _monomial(rng: random.Random, plain: float) -> sp.Expr:
    coef = rng.choice([1, 1, 1, 1, -1, -1, -1, 2, -3])
    factors = [_plain(rng) for _ in range(rng.randrange(1, 4))]
    if rng.random() > plain:
        factors.append(_other(rng))
    return coef * sp.Mul(*factors)


def _trig_pair(rng: random.Random) -> sp.Expr:
    """Two terms ``TR10i`` joins (or might)."""
    a, b = rng.sample(Q, 2)
    c = rng.choice([1, -1, sp.sqrt(3), rng.choice(S), rng.choice(ZS)])
    pairs = [
        sp.cos(a) * sp.cos(b) + sp.sin(a) * sp.sin(b),
        sp.cos(a) * sp.sin(b) - sp.sin(a) * sp.cos(b),
        sp.cos(a) + sp.sin(a),
        sp.sqrt(3) * sp.cos(a) + sp.sin(a),
        sp.cos(a) * rng.choice(U) + sp.sin(a) * rng.choice(U),
    ]
    return sp.expand(c * rng.choice(pairs))


def _expression(rng: random.Random) -> sp.Expr:
    plain = rng.choice([1.0, 1.0, 0.8, 0.5])
    terms = [_monomial(rng, plain) for _ in range(rng.randrange(1, 6))]
    if rng.random() < 0.4:  # a product with a sum (not expanded)
        inner = sp.Add(*[_monomial(rng, plain) for _ in range(rng.randrange(2, 4))])
        outer = rng.choice([1, -1]) * _plain(rng) * inner
        if rng.random() < 0.3:
            outer = outer / sp.sqrt(1 - rng.choice(ZS) ** 2)
        elif rng.random() < 0.3:  # as factor_terms writes -(a + b)
            outer = _keep_coeff(sp.S.NegativeOne, inner, sign=True)
        terms.append(outer)
    if rng.random() < 0.2:
        terms.append(_trig_pair(rng))
    if rng.random() < 0.1:  # all terms negative, or a common factor
        f = rng.choice([-1, _plain(rng)])
        return sp.expand(f * sp.Add(*terms))
    return sp.Add(*terms)


def _reference_tidy_one(expr: sp.Expr) -> sp.Expr:
    """``_tidy_one`` as it was, all sympy's."""
    if not isinstance(expr, sp.Expr) or expr.is_number:
        return expr
    if expr.has(sp.sin, sp.cos):
        ops = sp.count_ops(expr)
        if ops <= kin.TRIGSIMP_LIMIT:
            new = kin._trig(expr)
            if sp.count_ops(new) <= ops:
                expr = new
    return sp.factor_terms(expr)


def _undone(e: sp.Expr) -> sp.Expr:
    """The rest of :func:`kin._trig` after ``TR10i``."""
    return e.replace(
        lambda f: isinstance(f, sp.sin | sp.cos) and f.args[0].has(sp.pi),
        lambda f: sp.expand_trig(f),
    )


def _seeds(n: int) -> range:
    """``n`` seeds in the full tier, every third of them in ``make test``."""
    return range(0, n, tier_step(3))


SEEDS = _seeds(600)


def test_tidy_one_is_sympys():
    fast = 0
    for seed in SEEDS:
        e = _expression(random.Random(seed))
        assert written_tree(kin._tidy_one(e)) == written_tree(_reference_tidy_one(e)), (
            seed,
            e,
        )
        fast += kin._factors_fixed(e) or kin._tr10i_fixed(sp.expand(e))
    assert fast > len(SEEDS) // 3


def test_tr10i_fixed_means_unchanged():
    fixed = declined = 0
    for seed in SEEDS:
        e = sp.expand(_expression(random.Random(seed)))
        if kin._tr10i_fixed(e):
            fixed += 1
            assert written_tree(_undone(TR10i(e))) == written_tree(e), (seed, e)
        else:
            declined += 1
    assert fixed > len(SEEDS) // 2 and declined > len(SEEDS) // 10


def test_factors_fixed_means_unchanged():
    fixed = declined = 0
    for seed in SEEDS:
        e = _expression(random.Random(seed))
        if kin._factors_fixed(e):
            fixed += 1
            assert written_tree(sp.factor_terms(e)) == written_tree(e), (seed, e)
        else:
            declined += 1
    assert fixed > len(SEEDS) // 15 and declined > len(SEEDS) // 12


def _plain_sum(rng: random.Random, depth: int) -> sp.Expr:
    """A sum of products of plain factors, -1 or none, and (``depth`` > 0)
    sums of the same kind; now and then all negative, or with a common
    factor, or written as factor_terms writes ``-(a + b)``."""
    terms = []
    for _ in range(rng.randrange(1, 5)):
        factors = [_plain(rng) for _ in range(rng.randrange(1, 3))]
        if depth and rng.random() < 0.5:
            factors.append(_plain_sum(rng, depth - 1))
        terms.append(rng.choice([1, 1, -1]) * sp.Mul(*factors))
    e = sp.Add(*terms)
    r = rng.random()
    if r < 0.1:
        return sp.expand(-e) if e.is_Add else -e
    if r < 0.2:
        return sp.expand(rng.choice(ZS[::2]) * e)
    if r < 0.3 and e.is_Add:
        return _keep_coeff(sp.S.NegativeOne, e, sign=True)
    return e


def test_factors_fixed_on_nested_sums():
    fixed = declined = 0
    seeds = _seeds(600)
    for seed in seeds:
        e = _plain_sum(random.Random(seed), 2)
        if kin._factors_fixed(e):
            fixed += 1
            assert written_tree(sp.factor_terms(e)) == written_tree(e), (seed, e)
        else:
            declined += 1
        assert written_tree(kin._tidy_one(e)) == written_tree(_reference_tidy_one(e)), (
            seed,
            e,
        )
    assert fixed > len(seeds) // 5 and declined > len(seeds) // 12


@pytest.mark.parametrize(
    "expr",
    [
        -U[0] * ZS[0] - U[1] * ZS[2],  # all negative: -1 is taken out
        U[0] * ZS[0] + U[1] * ZS[0],  # a common factor
        sp.cos(Q[0]) * U[0] + sp.sin(Q[0]) * U[0],  # joined by TR10i
    ],
)
def test_declined_where_sympy_changes(expr):
    assert written_tree(kin._tidy_one(expr)) == written_tree(_reference_tidy_one(expr))
    assert written_tree(kin._tidy_one(expr)) != written_tree(expr)


# ------------------------------------------------- a body's inertia again


def _body_state(body) -> tuple:
    inertia = body.inertia
    return (
        [(written_tree(c), v.args, w.args) for c, v, w in inertia.dyadic.args],
        inertia.point,
        [(written_tree(c), v.args, w.args) for c, v, w in body.central_inertia.args],
    )


def test_holds_inertia_means_setting_again_changes_nothing():
    from al2py_runtime.model.objects import _holds_inertia
    from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody, inertia

    held = 0
    seeds = _seeds(200)
    for seed in seeds:
        rng = random.Random(seed)
        n = ReferenceFrame("N")
        b = n.orientnew("B", "Axis", [Q[0], n.z])
        o, p = Point("O"), Point("P")
        p.set_pos(o, S[0] * b.x + S[1] * n.y)
        body = RigidBody("C", o, b, sp.Symbol("M"))
        scalars = [rng.choice([0, 1, *S, *ZS[:1]]) for _ in range(6)]
        frame = rng.choice([b, n])
        first = inertia(frame, *scalars)
        body.inertia = (first, rng.choice([o, o, p]))
        if rng.random() < 0.5:
            body.mass = sp.Symbol("M2")  # a mass given later
        if rng.random() < 0.3:
            body.masscenter = rng.choice([o, p])
        again = rng.choice(
            [first, inertia(frame, *scalars), inertia(b, *scalars[::-1])]
        )
        if rng.random() < 0.3:  # the same dyadic written with other unit vectors
            again = again.express(n, n) if frame is b else again.express(b, b)
        if _holds_inertia(body, again):
            held += 1
            before = _body_state(body)
            body.inertia = (again, body.masscenter)
            assert _body_state(body) == before, seed
    assert held > len(seeds) * 3 // 20


def test_holds_inertia_reads_unit_vectors_as_written():
    from al2py_runtime.model.objects import _holds_inertia
    from sympy.physics.mechanics import Point, ReferenceFrame, RigidBody
    from sympy.physics.vector import Dyadic

    n = ReferenceFrame("N")
    b = n.orientnew("B", "Axis", [Q[0], n.z])
    o = Point("O")
    body = RigidBody("C", o, b, sp.Symbol("M"))
    body.inertia = (Dyadic([(S[0], n.x, n.x)]), o)
    c = n.orientnew("C", "Axis", [0, n.z])
    nx = c.x  # equal to N1> (Vector's ==), written in another frame
    assert nx == n.x
    again = Dyadic([(S[0], nx, nx)])
    assert not _holds_inertia(body, again)
    before = _body_state(body)
    body.inertia = (again, o)
    assert _body_state(body) != before


# ---------------------------------------------------------- vector sums


def _vector_args(v) -> list:
    return [(type(m).__name__, written_tree(tuple(m)), f) for m, f in v.args]


def test_add_vectors_is_sympys_sum():
    from sympy.physics.mechanics import ReferenceFrame
    from sympy.physics.vector import Vector

    n = ReferenceFrame("N")
    a = n.orientnew("A", "Axis", [Q[0], n.z])
    b = a.orientnew("B", "Axis", [Q[1], a.x])
    frames = [n, a, b]
    entries = [0, 0, 1, -1, *S, *ZS, *U, sp.Float(0.0), sp.cos(Q[2])]
    sums = cancelled = 0
    for seed in range(400):
        rng = random.Random(seed)

        def vector(rng: random.Random = rng):
            kind = rng.randrange(4)
            if kind == 0:
                return Vector(0)
            if kind == 1:  # a sympy unit vector, times a number
                return rng.choice([1, -1, 2]) * rng.choice(frames).x
            parts = [
                (sp.Matrix([rng.choice(entries) for _ in range(3)]), rng.choice(frames))
                for _ in range(rng.randrange(1, 4))
            ]
            v = Vector(parts)
            if kind == 3:  # opposite terms: a frame's sum is zero
                v = v + Vector([(-m, f) for m, f in parts[: rng.randrange(1, 3)]])
            return v

        want = got = Vector(0)
        for _ in range(rng.randrange(1, 5)):
            v = vector()
            if want.args and rng.random() < 0.3:  # cancels a frame's sum
                m, f = rng.choice(want.args)
                v = Vector([(-m, f)]) + v
            want = want + v
            got = kin.add_vectors(got, v)
            sums += bool(v.args)
            cancelled += len(want.args) < len({f for _, f in want.args + v.args})
        assert _vector_args(got) == _vector_args(want), seed
    assert sums > 400 and cancelled > 30
