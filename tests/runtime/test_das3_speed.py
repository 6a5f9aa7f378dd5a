"""Shortcuts of the script's substitutions and kinematics (issue 35, DAS3's
import): each gives sympy's own result, the same objects, checked against
sympy on random expressions."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates.autoz import power as _power
from sympy.physics.mechanics import dynamicsymbols

Q = dynamicsymbols("q1:4")
X = sp.Symbol("x")
R = sp.symbols("r1:3", real=True)
P = sp.Symbol("p", positive=True)
N = sp.Symbol("n", negative=True)
Z = sp.Symbol("z", zero=True)
W = sp.Symbol("w", infinite=True)
V = sp.Symbol("v", extended_real=True, infinite=True)
K = sp.Symbol("k", integer=True)
M = sp.Symbol("m", commutative=False)
IU = sp.S.ImaginaryUnit

#: atoms of the random terms: every kind sympy's powers of sums treat apart
#: (infinities, the imaginary unit, numbers, assumptions, non-commutative)
ATOMS = [
    *Q,
    X,
    *R,
    P,
    N,
    Z,
    W,
    V,
    K,
    M,
    sp.oo,
    -sp.oo,
    sp.zoo,
    sp.nan,
    IU,
    sp.pi,
    sp.E,
    sp.sqrt(2),
    sp.Integer(2),
    sp.Integer(-3),
    sp.Rational(1, 2),
    sp.Float(0.5),
    sp.Float(-1.25),
]

EXPONENTS = [
    sp.S.Zero,
    sp.S.One,
    sp.S.NegativeOne,
    sp.Integer(2),
    sp.Integer(3),
    sp.Integer(-2),
    sp.Rational(1, 2),
    sp.Rational(-1, 2),
    sp.Rational(3, 2),
    sp.Rational(1, 3),
    sp.Float(0.5),
    sp.Float(2.0),
    X,
    K,
    sp.oo,
    sp.zoo,
    IU,
    K + 1,
    sp.pi,
]


def _term(rng: random.Random, depth: int = 0) -> sp.Expr:
    """A random term: an atom, a product, a power, a function or a sum."""
    kind = rng.randrange(8 if depth < 2 else 1)
    if kind <= 2:
        return rng.choice(ATOMS)
    if kind == 3:
        return sp.Mul(_term(rng, depth + 1), _term(rng, depth + 1))
    if kind == 4:
        return rng.choice(ATOMS) * IU
    if kind == 5:
        return sp.Pow(_term(rng, depth + 1), rng.choice(EXPONENTS[:10]))
    if kind == 6:
        return rng.choice([sp.sin, sp.cos, sp.exp, sp.log])(_term(rng, depth + 1))
    return sp.Add(_term(rng, depth + 1), _term(rng, depth + 1))


def _base(rng: random.Random) -> sp.Expr:
    if rng.random() < 0.1:  # an unevaluated sum: its terms may be sums
        return sp.Add(_term(rng), _term(rng), evaluate=False)
    return sp.Add(*[_term(rng) for _ in range(rng.choice([2, 2, 2, 3]))])


@pytest.mark.parametrize("seed", range(8))
def test_power_is_sympys_power(seed):
    """``_power`` (the resolver's power of a replaced base) is sympy's
    ``Pow``: the same tree, for sums with and without infinite terms, the
    imaginary unit, numbers and every kind of exponent."""
    rng = random.Random(seed)
    fast = 0
    for _ in range(400):
        base, exp = _base(rng), rng.choice(EXPONENTS)
        with sp.core.parameters.evaluate(True):
            want = sp.Pow(base, exp)
        got = _power(base, exp)
        assert sp.srepr(got) == sp.srepr(want), (base, exp)
        assert type(got) is type(want)
        assert got.is_commutative == want.is_commutative
        fast += type(base) is sp.Add and exp.is_Rational and exp not in (0, 1)
    assert fast > 40  # the shortcut itself was checked


def test_power_with_infinite_terms():
    """The cases that decide the shortcut: a literal ``a + I*b`` with an
    infinite term has a value (sympy's, so no shortcut); without ``I`` a
    sum with an infinite term stays a power, as with none."""
    a, b = sp.Symbol("a", real=True), sp.Symbol("b", real=True)
    bases = (
        V + IU * b,
        IU * V + a,
        V + 2 * IU,
        W + IU * b,
        V + b,
        sp.oo * a + b,
        V + Q[0],
    )
    exps = (sp.Integer(-1), sp.Integer(2), sp.Rational(1, 2), sp.Rational(-3, 2))
    for base in bases:
        for exp in exps:
            assert sp.srepr(_power(base, exp)) == sp.srepr(sp.Pow(base, exp))
    # sympy's values, kept: oo + I*b is infinite in any power
    assert _power(V + IU * b, sp.Integer(-1)) == 0
    assert _power(IU * V + a, sp.Integer(2)) == sp.zoo


def _scalar(rng: random.Random) -> sp.Expr:
    """A random entry over shared parts, sometimes with a float (one that
    Autolev's rounding turns into an integer or a fraction, or keeps)."""
    e = sp.Add(*[rng.choice(Q) * rng.choice(R) for _ in range(rng.randrange(1, 4))])
    e = e * sp.sin(rng.choice(Q)) + X
    if rng.random() < 0.15:
        e = e * rng.choice([sp.Float(0.5), sp.Float(2.0000000001), sp.Float(0.1234567)])
    return e


@pytest.mark.parametrize("seed", range(6))
def test_normalize_looks_for_floats_once(tmp_path, seed):
    """A matrix, a vector, a dyadic or a list is normalized entry by entry
    as before (its floats made exact numbers), though its floats are looked
    for once in all its entries (``_may_hold_floats``)."""
    from al2py_runtime import Workspace
    from sympy.physics.vector import ReferenceFrame

    al = Workspace("snip.al", str(tmp_path / "snip.py"))
    rng = random.Random(seed)
    frame_a, frame_b = ReferenceFrame("A"), ReferenceFrame("B")
    changed = 0
    for _ in range(30):
        entries = [_scalar(rng) for _ in range(6)]
        alone = [al.normalize(e) for e in entries]
        changed += alone != entries
        m = al.normalize(sp.Matrix(2, 3, entries))
        assert [sp.srepr(x) for x in m] == [sp.srepr(x) for x in alone]
        lst = al.normalize(list(entries))
        assert [sp.srepr(x) for x in lst] == [sp.srepr(x) for x in alone]
        v = al.normalize(
            entries[0] * frame_a.x + entries[1] * frame_a.y + entries[2] * frame_b.z
        )
        want = alone[0] * frame_a.x + alone[1] * frame_a.y + alone[2] * frame_b.z
        assert sp.srepr(v.args) == sp.srepr(want.args)
        d = al.normalize(entries[3] * (frame_a.x | frame_b.y))
        assert sp.srepr(d.args) == sp.srepr((alone[3] * (frame_a.x | frame_b.y)).args)
    assert changed > 5  # floats were met, and made exact
    # a Python float in a list is a float too
    assert list(al.normalize([0.5, X])) == [sp.Rational(1, 2), X]


@pytest.mark.parametrize("seed", range(6))
def test_vector_sum_is_sympys_sum(seed):
    """``_vector_sum`` (a chain of positions, ``pos``) is sympy's
    ``Vector(0) + v1 + v2 + ...``: the same components, in the same
    order, also where a frame's component cancels and comes back."""
    from al2py_runtime.model.points import _vector_sum
    from sympy.physics.vector import ReferenceFrame, Vector

    rng = random.Random(seed)
    frames = [ReferenceFrame(n) for n in "ABCD"]
    pool = [sp.S.Zero, sp.Integer(1), X, *R, Q[0], sp.cos(Q[1])]
    reordered = 0
    for _ in range(200):
        vectors, previous = [], []
        for _ in range(rng.randrange(0, 7)):
            if previous and rng.random() < 0.3:  # cancels an earlier one
                v = -rng.choice(previous)
            else:
                v = Vector(0)
                for f in rng.sample(frames, rng.randrange(0, 3)):
                    v += sum(rng.choice(pool) * e for e in (f.x, f.y, f.z))
            previous.append(v)
            vectors.append(v)
        want = Vector(0)
        for v in vectors:
            want += v
        got = _vector_sum(vectors)
        assert [f for _, f in got.args] == [f for _, f in want.args]
        assert sp.srepr([m for m, _ in got.args]) == sp.srepr([m for m, _ in want.args])
        once = {}
        for v in vectors:
            for _, f in v.args:
                once.setdefault(f, len(once))
        reordered += [f for _, f in want.args] != sorted(
            [f for _, f in want.args], key=once.get
        )
    assert reordered > 3  # components that cancelled and came back were met


def _with_derivatives(rng: random.Random, depth: int = 0) -> sp.Expr:
    """A random expression over shared parts, with derivatives kept
    (``q1'``) and to evaluate (of a product, of a sum)."""
    t = dynamicsymbols._t
    kind = rng.randrange(6 if depth < 3 else 2)
    if kind == 0:
        return rng.choice([*Q, X, *R])
    if kind == 1:
        return sp.Derivative(rng.choice(Q), t)
    if kind == 2:
        inner = rng.choice(Q) * rng.choice([*Q, *R])
        return sp.Derivative(inner, t) if rng.random() < 0.2 else sp.cos(inner)
    if kind == 3:
        return sp.Derivative(_with_derivatives(rng, depth + 1), t, evaluate=False)
    parts = [_with_derivatives(rng, depth + 1) for _ in range(2)]
    return sp.Add(*parts) if kind == 4 else sp.Mul(*parts)


@pytest.mark.parametrize("seed", range(6))
def test_derivatives_done_is_doit_derivatives(seed):
    """The resolver's last step (``_derivatives_done``, remembering parts
    with no derivative to evaluate) gives ``doit_derivatives``' result, for
    a run of expressions sharing parts."""
    from al2py_runtime.model.kinematics import doit_derivatives
    from al2py_runtime.workspace import _derivatives_done

    rng = random.Random(seed)
    done: set = set()
    kept = evaluated = 0
    for _ in range(150):
        e = _with_derivatives(rng)
        want = doit_derivatives(e)
        got = _derivatives_done(e, done)
        assert sp.srepr(got) == sp.srepr(want)
        kept += want is e
        evaluated += want is not e
    assert kept > 20 and evaluated > 20


@pytest.mark.parametrize("seed", range(4))
def test_vector_is_sympys_vector(seed):
    """``walks.vector(pairs)`` (the kinematics' vectors: resolved, summed) is
    sympy's ``Vector(pairs)``: each frame's measure numbers summed, in the
    order the frames come, zero sums dropped."""
    from al2py_runtime.walks import vector as _vector
    from sympy.physics.vector import ReferenceFrame, Vector

    rng = random.Random(seed)
    frames = [ReferenceFrame(n) for n in "ABC"]
    pool = [sp.S.Zero] * 6 + [sp.Integer(1), X, -X, R[0], sp.Float(0.0)]
    dropped = 0
    for _ in range(300):
        pairs = [
            (
                sp.ImmutableMatrix([rng.choice(pool) for _ in range(3)]),
                rng.choice(frames),
            )
            for _ in range(rng.randrange(0, 5))
        ]
        want, got = Vector(pairs), _vector(pairs)
        assert type(got) is Vector
        assert [f for _, f in got.args] == [f for _, f in want.args]
        assert sp.srepr([m for m, _ in got.args]) == sp.srepr([m for m, _ in want.args])
        dropped += len(want.args) < len({f for _, f in pairs})
    assert dropped > 20
