"""The model's remembered substitutions (``model/resolutions.py``) answer as
the script's own resolver does, and forget when a right-hand side changes;
the splits ``Fr()``/``FrStar()`` remember (``model/fastkane.py``) make no
intermediate twice."""

from __future__ import annotations

import sympy as sp
from al2py_runtime import Workspace
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model.fastkane import measure_split
from sympy.physics.vector import ReferenceFrame, dynamicsymbols


def _script():
    al = Workspace("resolutions.al")
    n = al.model.newtonian("N")
    a = al.model.frames("A")
    q1, q2 = al.variables("Q1'", "Q2'")
    u1, u2 = al.variables("U1", "U2")
    c = al.constants("C")
    al.model.simprot(n, a, 3, q1, line=5)
    al.assign("Q1'", u1, line=6)
    al.assign("Q2'", u2 + c, line=7)
    return al, n, a, q1, q2, u1, u2, c


def test_resolutions_equal_the_scripts_and_follow_new_right_hand_sides():
    al, n, a, q1, q2, u1, u2, c = _script()
    t = dynamicsymbols._t
    model = al.model
    vec = q2.diff(t) * a.x + q1.diff(t) * n.y
    for keep in ([], [u1], [q1.diff(t)], [u1, u2.diff(t)]):
        want = al.resolver(keep)
        got = model.actual_value(vec, keep)
        for (m1, f1), (m2, f2) in zip(
            got.args, model.actual_value(vec, keep).args, strict=True
        ):
            assert f1 is f2 and m1 == m2
        for (m, f), (m0, f0) in zip(got.args, vec.args, strict=True):
            assert f is f0
            assert list(m) == [want(x) for x in m0]
    # a kept quantity with no right-hand side shares the answer of keeping
    # nothing, and keeping one with a right-hand side does not
    assert model.actual_value(q2.diff(t), [u1]) == u2 + c
    assert model.actual_value(q2.diff(t), [q2.diff(t)]) == q2.diff(t)
    # a new right-hand side is seen at once (nothing stale is answered)
    assert model.actual_value(q2.diff(t)) == u2 + c
    al.assign("Q2'", 2 * u2, line=8)
    assert model.actual_value(q2.diff(t)) == 2 * u2
    al.assign("C", 3, line=9)
    assert model.actual_value(sp.sin(c) * q1.diff(t)) == sp.sin(3) * u1


def test_a_vector_split_again_names_nothing_and_gives_the_same_answer():
    q, u1, u2 = dynamicsymbols("q u1 u2")
    n = ReferenceFrame("N")
    a = n.orientnew("A", "Axis", [q, n.z])
    book = Intermediates("z")
    vec = (u1 * sp.cos(q) ** 2 + u2 * sp.sin(q) * q) * a.x + (u2 * q**3 + q) * n.y
    first = measure_split(vec, n, [u1, u2], book)
    made = len(book)
    again = measure_split(vec, n, [u1, u2], book)
    assert len(book) == made and made > 0
    assert again == first and again is not first
    # each measure number is sum c_j u_j + rest, with the book's names
    full = vec.to_matrix(n)
    for (coefs, rest), m in zip(first, full, strict=True):
        formed = book.expand(rest + coefs[0] * u1 + coefs[1] * u2)
        assert sp.simplify(formed - m) == 0
    # the same vector in another frame is split anew
    other = measure_split(vec, a, [u1, u2], book)
    for (coefs, rest), m in zip(other, vec.to_matrix(a), strict=True):
        formed = book.expand(rest + coefs[0] * u1 + coefs[1] * u2)
        assert sp.simplify(formed - m) == 0


def test_resolvers_are_kept_until_a_right_hand_side_is_written():
    al, n, a, q1, q2, u1, u2, c = _script()
    t = dynamicsymbols._t
    resolutions = al.model.resolutions
    first = resolutions.resolver([u1])
    assert resolutions.resolver([u1]) is first  # nothing written: kept
    assert first(q2.diff(t)) == u2 + c
    al.table.set_rhs(q2.diff(t), 3 * u2)  # the table's one writer
    again = resolutions.resolver([u1])
    assert again is not first
    assert again(q2.diff(t)) == 3 * u2
    # a right-hand side that may change in place is never remembered
    al.table.set_rhs(c, sp.Matrix([1]))
    assert resolutions.resolver([u1]) is not resolutions.resolver([u1])
