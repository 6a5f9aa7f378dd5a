"""Shortcuts of the model's derivation (issue 35, ``docs/kinematics-speed.md``):
each gives sympy's (or the long path's) result, the same objects in the
same order, checked on random expressions."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model import kinematics as kin
from random_exprs import written_tree
from sympy.physics.mechanics import ReferenceFrame, dynamicsymbols

Q = dynamicsymbols("q1:5")
C = sp.symbols("c1:4", real=True)


def _entry(rng: random.Random, book: Intermediates) -> sp.Expr:
    """A random entry: zero, a number, a trigonometric term, a sum, or an
    intermediate (or its negative) naming one."""
    kind = rng.randrange(7)
    q = rng.choice(Q)
    if kind == 0:
        return sp.S.Zero
    if kind == 1:
        return sp.Integer(rng.choice([1, -1, 2]))
    if kind == 2:
        return rng.choice([sp.cos, sp.sin])(q)
    if kind == 3:
        return sp.cos(q) * rng.choice(C) - sp.sin(rng.choice(Q)) * rng.choice(C)
    z = book.name(
        sp.cos(q) * sp.sin(rng.choice(Q)) + rng.choice(C) * sp.cos(rng.choice(Q))
    )
    return -z if kind == 4 else z


def _matrix(rng: random.Random, book: Intermediates) -> sp.Matrix:
    m = sp.Matrix(3, 3, lambda i, j: _entry(rng, book))
    # sympy's own sparse orders: a transpose and a product reorder the rows
    if rng.random() < 0.3:
        m = m.T
    if rng.random() < 0.3:
        m = m * sp.Matrix(3, 3, lambda i, j: _entry(rng, book))
    if rng.random() < 0.4:  # sympy's frames keep both kinds
        m = sp.ImmutableMatrix(m)
    return m


def _dok(m: sp.Matrix) -> list:
    return [(ij, written_tree(v)) for ij, v in m.todok().items()]


class _Recorder:
    """``book.name``, recording the order of the calls."""

    def __init__(self, book: Intermediates) -> None:
        self.book, self.calls = book, []

    def __call__(self, e):
        self.calls.append(e)
        return self.book.name(e)


@pytest.mark.parametrize("seed", range(100))
def test_named_product_is_sympys_product_named_in_its_order(seed):
    rng = random.Random(seed)
    books = Intermediates("Z"), Intermediates("Z")
    mats = [[_matrix(random.Random(seed * 7 + k), b) for k in range(2)] for b in books]
    long_name, short_name = _Recorder(books[0]), _Recorder(books[1])
    want = (mats[0][0] * mats[0][1]).applyfunc(long_name)
    got = kin.named_product(mats[1][0], mats[1][1], short_name)
    assert type(got) is type(want)
    # the same entries in sympy's sparse order (a later product reads it),
    # written alike (two books: their intermediates are of two classes)
    assert _dok(got) == _dok(want)
    assert _dok(got.T) == _dok(want.T)
    # named in the same order: the intermediates are numbered the same
    assert [written_tree(e) for e in short_name.calls] == [
        written_tree(e) for e in long_name.calls
    ]
    assert len(books[1]) > 0
    assert _definitions(books[1]) == _definitions(books[0])
    assert rng.random() >= 0  # (the seed drives the matrices above)


def test_named_product_keeps_sympys_infinities():
    """An infinite entry: sympy's product (``0 * oo`` is ``nan``)."""
    book = Intermediates()
    a = sp.Matrix([[sp.oo, 0, 0], [0, 1, 0], [0, 0, sp.cos(Q[0])]])
    b = sp.Matrix([[0, 1, 0], [1, 0, 0], [0, 0, sp.sin(Q[1])]])
    want = (a * b).applyfunc(book.name)
    got = kin.named_product(a, b, book.name)
    assert got.has(sp.nan) and want.has(sp.nan)
    assert _dok(got) == _dok(want)


@pytest.mark.parametrize("seed", range(40))
def test_zero_times_an_entry_is_sympys(seed):
    """``_zero_times_is_zero`` answers as sympy's ``0 * x == 0`` for random
    entries, with sympy's infinities among their parts or not."""
    rng = random.Random(seed)
    book = Intermediates()
    specials = [sp.oo, -sp.oo, sp.zoo, sp.nan, sp.Integer(3), sp.pi]
    for _ in range(30):
        x = _entry(rng, book)
        if rng.random() < 0.5:
            x = x * _entry(rng, book) + rng.choice(specials) * _entry(rng, book)
        if rng.random() < 0.3:
            x = sp.sqrt(x + rng.choice(C) ** 2) / (1 + rng.choice(specials))
        assert kin._zero_times_is_zero(x) is (sp.S.Zero * x == sp.S.Zero), x


@pytest.mark.parametrize("seed", range(20))
def test_frame_dyadic_is_sympys_sum(seed):
    """``frame_dyadic`` gives the dyadic sympy's sum of ``m[i, j] * (u_i |
    u_j)`` gives: the same terms, coefficients and unit vectors, in order."""
    rng = random.Random(seed)
    book = Intermediates()
    n = ReferenceFrame("N")
    m = sp.Matrix(3, 3, lambda i, j: _entry(rng, book) if rng.random() < 0.7 else 0)
    want = sp.S.Zero * (n.x | n.x)
    for i, u in enumerate((n.x, n.y, n.z)):
        for j, v in enumerate((n.x, n.y, n.z)):
            if m[i, j] != 0:
                want += m[i, j] * (u | v)
    got = kin.frame_dyadic(n, m)
    assert [(sp.srepr(c), a, b) for c, a, b in got.args] == [
        (sp.srepr(c), a, b) for c, a, b in want.args
    ]


def test_named_product_of_numbers_is_sympys():
    book = Intermediates()
    a = sp.Matrix([[0, 1, 0], [-1, 0, 0], [0, 0, 1]])
    b = sp.Matrix([[0, 0, 1], [0, 1, 0], [-1, 0, 0]])
    got = kin.named_product(a, b, book.name)
    assert _dok(got) == _dok(a * b)


def test_named_dcms_of_a_chain_of_frames_are_sympys():
    """A chain of simple rotations, each new frame's direction cosines to
    the others formed as model/points.py ``_name_dcms`` forms them: equal
    to sympy's."""
    rng = random.Random(5)
    frames = [ReferenceFrame("N")]
    book = Intermediates()
    for k in range(6):
        a = frames[-1]
        axis = getattr(a, rng.choice(["x", "y", "z"]))
        f = a.orientnew(f"F{k}", "Axis", [Q[k % 4], axis])
        step = a.dcm(f)
        for g in frames[:-1]:
            m = kin.named_product(g.dcm(a), step, book.name)
            assert sp.simplify(book.expand(m) - g.dcm(f)) == sp.zeros(3, 3)
            g._dcm_cache[f] = m
            f._dcm_cache[g] = m.T
        frames.append(f)
    assert len(book) > 20


def _big(rng: random.Random, book: Intermediates, depth: int = 0) -> sp.Expr:
    """A random expression large enough to be named in parts: sums of
    products of intermediates, functions of time, symbols, numbers and
    smaller sums."""
    zs = [
        book.name(sp.cos(q) * sp.sin(p) + c * sp.cos(p))
        for q, p, c in zip(Q[:3], Q[1:], C, strict=True)
    ]
    atoms = [*zs, *Q, *C, sp.sin(Q[0]), sp.cos(Q[2])]
    terms = []
    for _ in range(rng.randint(3, 7)):
        factors = rng.sample(atoms, rng.randint(1, 4))
        if depth < 2 and rng.random() < 0.4:
            factors.append(_big(rng, book, depth + 1))
        if rng.random() < 0.3:
            factors.append(sp.Integer(rng.choice([-1, 2, -3])))
        terms.append(sp.Mul(*factors))
    return sp.Add(*terms)


def _definitions(book: Intermediates) -> list:
    return [written_tree(book.canonical(k)) for k in range(1, len(book) + 1)]


@pytest.mark.parametrize("seed", range(30))
def test_named_in_parts_as_sympy_rebuilds_them(seed, monkeypatch):
    """``Intermediates._split`` rebuilds a part whose arguments were named
    with ``substitute``'s constructors (``product_with``, ``total``): the
    same expressions and intermediates as sympy's ``e.func(*args)``."""
    from al2py_runtime.intermediates import autoz

    fast = Intermediates()
    got = [fast.name(_big(random.Random(seed * 11 + k), fast)) for k in range(4)]
    with monkeypatch.context() as m:
        m.setattr(autoz, "_rebuilt", lambda e, new, changed: e.func(*new))
        slow = Intermediates()
        want = [slow.name(_big(random.Random(seed * 11 + k), slow)) for k in range(4)]
    assert [written_tree(e) for e in got] == [written_tree(e) for e in want]
    assert _definitions(fast) == _definitions(slow)
    assert len(fast) > 8  # named in parts


U = dynamicsymbols("u1:4")


def _linear(rng: random.Random, book: Intermediates) -> sp.Expr:
    """A random expression in the speeds ``U`` and their derivatives:
    mostly linear, with coefficients and a rest of every kind a velocity or
    an acceleration has (sums, products, numbers, floats, a derivative of
    a speed inside a coefficient, a product of two speeds)."""
    xs = [*U, *(u.diff() for u in U)]
    terms = []
    for _ in range(rng.randint(1, 6)):
        coef = _big(rng, book) if rng.random() < 0.5 else _entry(rng, book)
        kind = rng.randrange(10)
        if kind == 0:
            coef = sp.Float(rng.choice([0.5, 2.0]))
        elif kind == 1:
            coef = coef * U[0].diff()  # an acceleration in a coefficient
        elif kind == 2:
            coef = sp.Integer(rng.choice([1, -1, 3]))
        x = rng.choice(xs)
        terms.append(coef * x * (rng.choice(U) if rng.random() < 0.05 else 1))
    if rng.random() < 0.7:
        terms.append(_big(rng, book) if rng.random() < 0.5 else _entry(rng, book))
    return sp.Add(*terms)


@pytest.mark.parametrize("seed", range(60))
def test_name_linear_terms_is_linear_terms_of_name_linear(seed):
    """The engine's split of a measure number (``fastkane._split_named``):
    read off the named parts, the same coefficients, rest and
    intermediates as splitting the named sum again."""
    from al2py_runtime.linear import linear_terms

    choices = [[*U], [*(u.diff() for u in U)], [*U, *(u.diff() for u in U)]]
    fast, slow = Intermediates(), Intermediates()
    if seed % 2:  # the speeds' derivatives are named (Q' as speeds)
        fast.rates = slow.rates = frozenset(u.diff() for u in U)
    for k in range(5):
        rng = random.Random(seed * 13 + k)
        xs = rng.choice(choices)
        if k == 4:
            xs = [*xs, xs[0]]  # a repeated x
        got = fast.name_linear_terms(_linear(random.Random(seed * 13 + k), fast), xs)
        e = _linear(random.Random(seed * 13 + k), slow)
        want = linear_terms(slow.name_linear(e, xs), xs)
        if want is None:
            assert got is None
            continue
        assert got is not None
        assert [written_tree(c) for c in got[0]] == [written_tree(c) for c in want[0]]
        assert written_tree(got[1]) == written_tree(want[1])
    assert _definitions(fast) == _definitions(slow)


def test_name_linear_terms_keeps_zee_not_quantities_in_the_rest():
    """``ZEE_NOT`` quantities are split off by ``name_linear`` but are not
    among the ``xs``: the rest is the named sum's (the long path)."""
    from al2py_runtime.linear import linear_terms

    f = sp.Symbol("F")
    fast, slow = Intermediates(), Intermediates()
    for b in (fast, slow):
        b.exclude = frozenset({f})
    e = sp.cos(Q[0]) * sp.sin(Q[1]) * U[0] + f * U[1] * sp.cos(Q[2]) + sp.sin(Q[3]) * f
    got = fast.name_linear_terms(e, [U[0], U[1]])
    want = linear_terms(slow.name_linear(e, [U[0], U[1]]), [U[0], U[1]])
    assert (
        want is None
        and got is None
        or (
            [written_tree(c) for c in got[0]] == [written_tree(c) for c in want[0]]
            and written_tree(got[1]) == written_tree(want[1])
        )
    )
    assert _definitions(fast) == _definitions(slow)


@pytest.mark.parametrize("seed", range(20))
def test_doit_derivatives_is_sympys_replace(seed):
    """``doit_derivatives`` (every resolution's last step): sympy's
    ``replace`` of each derivative of an expression by its value, the
    derivatives of functions of time kept; an expression with none to
    evaluate is returned as it is, without the rebuilding walk."""
    rng = random.Random(seed)
    book = Intermediates()
    e = _big(rng, book) * U[0] + _entry(rng, book) * U[1].diff()
    if seed % 2:
        inner = rng.choice([sp.sin(Q[0]) * C[0], Q[1] ** 2, _entry(rng, book) + Q[2]])
        e = e + sp.Derivative(inner, dynamicsymbols._t) * rng.choice(U)
    want = e.replace(
        lambda x: isinstance(x, sp.Derivative)
        and not isinstance(x.expr, sp.core.function.AppliedUndef),
        lambda x: x.doit(),
    )
    got = kin.doit_derivatives(e)
    assert written_tree(got) == written_tree(want)
    if not seed % 2:
        assert got is e


def test_autorhs_on_substitutes_the_current_numbers(tmp_path):
    """AutoRHS ON's numeric right-hand sides are found once while the
    right-hand sides do not change (``Workspace._simple_rhs``): a changed
    or new one is substituted from then on, in scalars and matrices."""
    from al2py_runtime import Workspace

    al = Workspace("snip.al", str(tmp_path / "snip.py"))
    al.settings.set("Autorhs", "ON")
    b = sp.Symbol("B", real=True)
    al.declare_constants(b, line=2)
    a = al.assign("A", 7, line=3)
    al.assign("C", a + b, line=4)
    al.assign("M", sp.Matrix([a, a * b]), line=5)
    assert al["C"] == 7 + b
    assert list(al["M"]) == [7, 7 * b]
    a = al.assign("A", 8, line=6)
    al.assign("D", a + b, line=7)
    e = al.assign("E", 5, line=8)
    al.assign("N", sp.Matrix([a + e, b]), line=9)
    assert al["D"] == 8 + b
    assert list(al["N"]) == [13, b]
