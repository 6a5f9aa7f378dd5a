"""The fast paths of issue 21 give sympy's own results, object for object:
the walks over shared parts (``al2py_runtime.walks``), the sign of a sum
(``minus_first``), an intermediate's sort key and the chain rule's
products (``product_with``)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime import walks
from al2py_runtime.intermediates.autoz import (
    Intermediates,
    minus,
    minus_first,
    product_with,
)
from sympy.physics.vector import dynamicsymbols

T = dynamicsymbols._t
Q = dynamicsymbols("q1:5")
U = dynamicsymbols("u1:4")
C = sp.symbols("c1:6")


def _book_and_exprs(seed: int = 3) -> tuple[Intermediates, list]:
    rng = random.Random(seed)
    book = Intermediates()
    atoms = [*Q, *U, *C, *(u.diff(T) for u in U)]
    zs = []
    exprs = []
    for _ in range(60):
        parts = [rng.choice(atoms + zs) if zs else rng.choice(atoms) for _ in range(4)]
        e = (
            rng.choice([1, -1, 2, sp.Rational(-3, 2)]) * parts[0] * sp.cos(parts[1])
            + rng.choice([1, -1, 3]) * parts[2] * parts[3]
            - rng.choice(C) * sp.sin(rng.choice(Q)) ** 2
        )
        exprs.append(e)
        z = book.name(e.xreplace({u.diff(T): 0 for u in U}))
        if isinstance(z, book.Z):
            zs.append(z)
    exprs += [a * b - c for a, b, c in zip(zs, zs[1:], zs[2:], strict=False)]
    exprs += [sp.Add(*zs[i : i + 5]) * C[i % 5] for i in range(0, len(zs), 5)]
    return book, exprs


def test_walks_equal_sympys():
    _, exprs = _book_and_exprs()
    rules = [
        {Q[0]: Q[1] + 1},
        {U[0]: 0, U[1].diff(T): C[0]},
        {C[0]: sp.Float(0.5), Q[2]: sp.S.Zero},
        {sp.Integer(2): sp.Integer(3)},
    ]
    for e in exprs:
        for rule in rules:
            assert walks.xreplace(e, rule) == e.xreplace(rule)
        wanted = [*U, Q[3], C[4], U[2].diff(T)]
        assert walks.appearing(e, wanted) == {x for x in wanted if e.has(x)}
        assert walks.atoms(e, sp.Symbol, sp.Derivative) == e.atoms(
            sp.Symbol, sp.Derivative
        )

        def query(x):
            return isinstance(x, sp.cos)

        def value(x):
            return sp.sin(x.args[0] + 1)

        assert walks.replace(e, query, value) == e.replace(query, value)


def test_the_sign_of_a_sum_is_sympys():
    book, exprs = _book_and_exprs()
    sums = [e for e in exprs if e.is_Add]
    sums += [-e for e in sums]
    sums += [book.Z(*z.args) - w for z, w in zip(book._named.values(), C, strict=False)]
    for e in sums:
        assert minus_first(e, book._sort_key) == e.could_extract_minus_sign()
        assert minus_first(e) == e.could_extract_minus_sign()


def test_the_negation_of_a_sum_is_sympys():
    book, exprs = _book_and_exprs()
    rng = random.Random(5)
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    coefficients = [1, -1, 2, sp.Rational(-3, 2), sp.Float(0.25), sp.Float(-1.5)]
    coefficients += [sp.sqrt(2), -sp.sqrt(3), sp.pi, sp.I, -2 * sp.I, sp.E]
    factors = [*Q[:2], *C[:3], *zs[:6], sp.cos(Q[0]), Q[1] ** 2, 1 / C[0]]
    sums = [e for e in exprs if e.is_Add]
    for _ in range(300):
        terms = [
            rng.choice(coefficients) * sp.Mul(*rng.sample(factors, rng.randint(1, 3)))
            for _ in range(rng.randint(2, 5))
        ]
        terms += [rng.choice([0, 1, -2, sp.Rational(1, 3), sp.pi])]
        sums.append(sp.Add(*terms))
    checked = 0
    for e in sums + [-e for e in sums]:
        if e.is_Add:
            mine, sympys = minus(e), -e
            assert type(mine) is type(sympys) and mine.args == sympys.args, e
            checked += 1
    assert checked > 400


def test_an_intermediates_sort_key_is_sympys():
    book, _ = _book_and_exprs()
    for z in book._named.values():
        if isinstance(z, book.Z):
            assert book._sort_key(z) == sp.default_sort_key(z)


def test_a_sums_and_a_products_sort_key_is_sympys():
    """The kept keys of sums and products (made from their parts' kept
    keys) are ``default_sort_key``'s, numbers, powers, floats and sums as
    factors included."""
    book, exprs = _book_and_exprs()
    rng = random.Random(1)
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    pool = [*Q, *U, *C, *zs[:8], sp.cos(Q[0]), U[0].diff(T)]
    coefficients = [1, -1, 2, sp.Rational(-3, 4), sp.Float(0.5), sp.sqrt(2)]

    def product():
        factors = rng.sample(pool, rng.randint(1, 3))
        if rng.random() < 0.2:
            factors.append(rng.choice(pool) ** rng.choice([2, -1, sp.Rational(1, 2)]))
        if rng.random() < 0.15:
            factors.append(sp.Add(*rng.sample(pool, 2)))
        return rng.choice(coefficients) * sp.Mul(*factors)

    for _ in range(200):
        e = sp.Add(*[product() for _ in range(rng.randint(1, 4))])
        if rng.random() < 0.2:
            e = e * sp.Add(*rng.sample(pool, 2))
        if rng.random() < 0.1:
            e = e + rng.choice([1, sp.pi, -2])
        exprs += [e, -e]
    checked = 0
    for e in exprs:
        for part in sp.preorder_traversal(e):
            if isinstance(part, sp.Basic) and (part.is_Add or part.is_Mul):
                book._keys.pop(part, None)
                assert book._sort_key(part) == sp.default_sort_key(part), part
                checked += 1
    assert checked > 1500


def test_the_chain_rules_products_are_sympys():
    book, _ = _book_and_exprs()
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    products = [
        sp.Mul(zs[0], zs[1]),
        sp.Mul(2, zs[2], C[0], zs[3]),
        sp.Mul(sp.Rational(-1, 3), zs[4] ** 2, Q[0], sp.cos(Q[1])),
        sp.Mul(sp.sqrt(2), zs[5], C[1]),
        sp.Mul(C[2], zs[6] + zs[7], zs[8]),
        sp.Mul(sp.Float(1.5), zs[0], zs[1]),
    ]
    products += [
        sp.Mul(zs[0], Q[0] ** 2, sp.cos(Q[1])),
        sp.Mul(-2, zs[1] + zs[2], C[0]),
        sp.Mul(zs[3] + C[1], zs[4] + C[2]),
        sp.Mul(sp.Rational(1, 2), Q[2], 1 / C[3]),
    ]
    # factors sympy does more than sort: exp, non-commutative ones
    noncommutative = [sp.Symbol("A", commutative=False)]
    noncommutative.append(dynamicsymbols("p", commutative=False))
    products += [
        sp.Mul(zs[0], sp.exp(Q[0])),
        sp.Mul(zs[1], noncommutative[0]),
        sp.Mul(2, zs[2], noncommutative[1]),
    ]
    ds = [zs[0], zs[3], -zs[9], 3 * zs[4], zs[10], sp.Integer(2), C[3] * zs[2]]
    ds += [sp.S.One, sp.Integer(-1), sp.Rational(1, 3), sp.sin(Q[0]), -sp.cos(Q[1])]
    ds += [
        2 * sp.sin(Q[2]) * zs[5],
        Q[0],
        2 * Q[0] * C[4],
        C[0] + zs[1],
        sp.Float(0.5) * Q[1],
        sp.exp(Q[1]),
        sp.pi * zs[0],
        *noncommutative,
    ]
    for p in products:
        if not p.is_Mul:
            continue
        args = p.args
        for i in range(len(args)):
            for d in ds:
                mine = product_with(args, i, d)
                sympys = sp.Mul(*args[:i], d, *args[i + 1 :])
                assert type(mine) is type(sympys)
                assert mine.args == sympys.args


def test_linear_splits_by_the_books_walk_are_sympys():
    """``split_linear_named`` with the book (its derivative walk) gives the
    coefficients sympy's ``diff`` gives, intermediates and all."""
    from al2py_runtime.model.arrange import split_linear_named

    book, exprs = _book_and_exprs()
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    w = dynamicsymbols("w1:3")
    speeds = [w[0], w[1], w[1].diff(T)]
    eqs = [
        e * zs[k % len(zs)]
        + sum(
            (zs[(k + j) % len(zs)] * sp.cos(Q[j]) * s for j, s in enumerate(speeds)),
            sp.S.Zero,
        )
        for k, e in enumerate(exprs[:12])
    ]
    fast = split_linear_named(eqs, speeds, book)
    slow = split_linear_named(eqs, speeds)
    assert fast[0] == slow[0] and fast[1] == slow[1]
    assert any(x != 0 for x in fast[0])


def test_cross_products_and_inertia_matrices_are_sympys():
    """``kinematics.cross`` and ``kinematics.dyadic_matrix`` give sympy's
    own expressions (``a ^ b``, ``d.to_matrix(F)``), entry for entry."""
    import operator

    from al2py_runtime.model import kinematics
    from al2py_runtime.model.kinematics import cross, dyadic_matrix
    from sympy.physics.vector import ReferenceFrame, Vector, outer

    n = ReferenceFrame("N")
    a = n.orientnew("A", "Axis", [Q[0], n.z])
    b = a.orientnew("B", "Axis", [Q[1], a.x])
    rng = random.Random(7)
    frames = [n, a, b]
    pool = [*Q, *U, *C, sp.cos(Q[2]), U[0] * Q[1]]

    def vector():
        out = Vector(0)
        for _ in range(rng.randint(0, 3)):
            f = rng.choice(frames)
            out += rng.choice(pool) * rng.choice([f.x, f.y, f.z])
        return out

    for _ in range(60):
        v, w = vector(), vector()
        mine, sympys = cross(v, w), v ^ w
        assert len(mine.args) == len(sympys.args)
        for (m1, f1), (m2, f2) in zip(mine.args, sympys.args, strict=True):
            assert f1 == f2 and list(m1) == list(m2)
            assert [sp.srepr(x) for x in m1] == [sp.srepr(x) for x in m2]
    # With an infinity among the measure numbers (sympy's own cross then
    # makes a vector of one nan): the products are plain ``a * b``'s, so
    # a zero times an infinity is nan, as sympy's product is.
    finite = list(pool)
    pool += [C[0] + sp.oo, sp.zoo * Q[0]]
    found_nan = False
    for _ in range(40):
        v, w = vector(), vector()
        mine = cross(v, w)
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(kinematics, "_times", operator.mul)
            plain = cross(v, w)
        assert [(list(m), f) for m, f in mine.args] == [
            (list(m), f) for m, f in plain.args
        ]
        found_nan = found_nan or any(m.has(sp.nan) for m, _f in mine.args)
    assert found_nan  # an infinity met a zero
    pool[:] = finite
    for _ in range(30):
        f = rng.choice(frames)
        d = sum(
            (
                rng.choice(pool)
                * outer(rng.choice([f.x, f.y, f.z]), rng.choice([f.x, f.y, f.z]))
                for _ in range(rng.randint(1, 5))
            ),
            outer(f.x, f.x) * 0,
        )
        assert list(dyadic_matrix(d, f)) == list(d.to_matrix(f))


def test_the_chain_rules_sums_are_sympys():
    """``autoz.total`` (the sums of ``Intermediates._pd``) is ``sp.Add``:
    like terms collected, cancelled terms dropped, the number first, the
    rest in sympy's order; what it does not take goes to sympy."""
    from al2py_runtime.intermediates.autoz import total

    book, _ = _book_and_exprs()
    rng = random.Random(3)
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    pool = [*Q, *U, *C, *zs[:10], sp.cos(Q[0]), U[0].diff(T), Q[1] ** 2, 1 / C[0]]
    coefficients = [1, -1, 2, sp.Rational(1, 3), sp.Float(0.5), sp.sqrt(2), sp.pi]
    for _ in range(1500):
        terms = []
        for _ in range(rng.randint(0, 6)):
            if rng.random() < 0.15:
                terms.append(sp.sympify(rng.choice(coefficients)))
            else:
                factors = rng.sample(pool, rng.randint(1, 3))
                terms.append(rng.choice(coefficients) * sp.Mul(*factors))
        if terms and rng.random() < 0.3:
            terms.append(-terms[0])
        if rng.random() < 0.3:  # a sum among the terms (the chain rule's)
            parts = rng.sample(pool, 2)
            terms.insert(0, parts[0] * sp.Float(0.1) + parts[1] + sp.Float(0.2))
        if rng.random() < 0.05:
            terms.append(sp.oo)
        mine, sympys = total(terms), sp.Add(*terms)
        assert type(mine) is type(sympys) and mine.args == sympys.args, terms


def test_the_canonical_order_is_sympys():
    """``autoz._compare`` (the order in which the chain rule's sums and
    products are sorted) answers as ``Basic.compare`` for every pair of
    parts: numbers, symbols with assumptions, functions of time, their
    derivatives, intermediates (canonical or not), powers, sums, products,
    classes named in ``ordering_of_classes`` and classes that are not."""
    from al2py_runtime.intermediates.autoz import _compare

    book, exprs = _book_and_exprs()
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    other = Intermediates()
    extra = [
        zs[0].xreplace({Q[0]: Q[1]}),
        other.name(Q[0] * sp.cos(Q[1]) + U[0] * U[1]),
        sp.Symbol("c1", positive=True),
        sp.Dummy("c1"),
        sp.Float(0.5),
        sp.Float(0.5, 30),
        sp.Rational(-3, 4),
        sp.pi,
        sp.sqrt(2),
        sp.exp(Q[0]),
        sp.Abs(C[0]),
        sp.FiniteSet(1, 2),
        sp.Tuple(1, C[0]),
        Q[0].diff(T, 2),
        sp.Derivative(U[0], T),
    ]
    parts = set(extra)
    for e in exprs:
        parts.update(p for p in sp.preorder_traversal(e) if isinstance(p, sp.Basic))
    parts = sorted(parts, key=sp.default_sort_key)
    rng = random.Random(5)
    pairs = [(a, b) for a in parts for b in parts]
    rng.shuffle(pairs)
    for a, b in pairs[:40000]:
        assert _compare(a, b) == sp.Basic.compare(a, b), (a, b)
    assert len(pairs) > 40000


def test_intermediates_by_name_are_in_the_keys_order():
    """``_by_name`` (numbers first, the arguments' text only among instances
    of one number) orders as sorting by the full key does, either way."""
    book, _ = _book_and_exprs()
    zs = [z for z in book._named.values() if isinstance(z, book.Z)]
    others = [z.xreplace({Q[0]: Q[1], Q[1]: Q[0]}) for z in zs[:6]]
    others += [z.xreplace({U[0]: C[0]}) for z in zs[:6]]
    pool = zs + [z for z in others if z not in zs]
    assert len({z.args[0] for z in pool}) < len(pool)  # instances share numbers
    rng = random.Random(7)
    for _ in range(20):
        sample = rng.sample(pool, 25)
        for reverse in (False, True):
            expected = sorted(sample, key=book._name_key, reverse=reverse)
            assert book._by_name(sample, reverse=reverse) == expected
