"""The model's own searches of sympy's frame graphs give sympy's answers
(issue 35): :func:`kinematics.ang_vel_in` is ``ReferenceFrame.ang_vel_in``,
the same vector term for term, on random trees of frames (oriented by
axes, body-fixed angles or given angular velocities), and where the
angular velocities form a cycle or are given one way only (sympy's
search then)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.model import kinematics as kin
from sympy.physics.vector import ReferenceFrame, Vector, dynamicsymbols


def _tree(seed: int, n: int) -> list[ReferenceFrame]:
    """``n`` frames, each oriented from a random earlier one."""
    rng = random.Random(seed)
    qs = dynamicsymbols(f"q1:{3 * n + 1}")
    frames = [ReferenceFrame("F0")]
    for i in range(1, n):
        parent = rng.choice(frames)
        f = ReferenceFrame(f"F{i}")
        kind = rng.choice(["axis", "body", "given"])
        if kind == "axis":
            f.orient_axis(parent, rng.choice([parent.x, parent.y, parent.z]), qs[i])
        elif kind == "body":
            f.orient_body_fixed(parent, tuple(qs[3 * i - 3 : 3 * i]), "123")
        else:
            f.orient_axis(parent, parent.z, qs[i])
            f.set_ang_vel(parent, qs[i].diff() * parent.x + qs[i - 1] * f.y)
        frames.append(f)
    return frames


def _same(a: Vector, b: Vector) -> bool:
    """Equal vectors, formed alike (the same components in the same
    frames, in the same order)."""
    return a == b and [f for _, f in a.args] == [f for _, f in b.args]


@pytest.mark.parametrize("seed", range(6))
def test_angular_velocity_in_a_tree_of_frames_is_sympys(seed):
    frames = _tree(seed, 9)
    rng = random.Random(100 + seed)
    for _ in range(30):
        b, a = rng.choice(frames), rng.choice(frames)
        assert kin._tree_path(b, a) is not None  # the walk is used
        assert _same(kin.ang_vel_in(b, a), b.ang_vel_in(a))


def test_a_cycle_or_a_one_way_velocity_is_left_to_sympy():
    frames = _tree(7, 6)
    u = dynamicsymbols("u")
    # a cycle: two paths between F0 and F5 (sympy picks the shorter)
    frames[5].set_ang_vel(frames[0], u * frames[0].z)
    assert kin._tree_path(frames[5], frames[1]) is None
    for b in frames:
        for a in frames:
            assert _same(kin.ang_vel_in(b, a), b.ang_vel_in(a))
    # given one way only
    c, d = ReferenceFrame("C"), ReferenceFrame("D")
    c._ang_vel_dict[d] = u * d.x
    assert kin._tree_path(c, d) is None
    assert _same(kin.ang_vel_in(c, d), c.ang_vel_in(d))


def test_no_path_is_sympys_error():
    a, b = ReferenceFrame("A"), ReferenceFrame("B")
    with pytest.raises(ValueError, match="No connecting"):
        kin.ang_vel_in(a, b)
    assert kin.ang_vel_in(a, a) == Vector(0)


def test_time_derivative_in_a_tree_is_sympys():
    """``frame_dt`` (which takes the angular velocities this way) is
    sympy's ``dt`` of vectors with components in several frames."""
    frames = _tree(3, 7)
    rng = random.Random(3)
    q = dynamicsymbols("q1:4")
    for _ in range(10):
        v = sum(
            (
                rng.choice(q) * rng.choice([f.x, f.y, f.z])
                for f in rng.sample(frames, 3)
            ),
            Vector(0),
        )
        n = rng.choice(frames)
        mine = kin.frame_dt(v, n, lambda e: sp.diff(e, dynamicsymbols._t))
        assert (mine - v.dt(n)).simplify() == Vector(0)


@pytest.mark.parametrize("seed", range(3))
def test_dot_product_is_sympys_node_for_node(seed):
    """``kinematics.dot`` of vectors with components in several frames of
    a tree is sympy's ``a & b``, the same expression node for node."""
    frames = _tree(seed, 6)
    rng = random.Random(seed)
    q = dynamicsymbols("q1:4")
    coefs = [1, -2, sp.Rational(1, 3), *q, q[0] * q[1]]

    def vector():
        return sum(
            (
                rng.choice(coefs) * rng.choice([f.x, f.y, f.z])
                for f in rng.sample(frames, rng.choice([1, 2, 3]))
            ),
            Vector(0),
        )

    for _ in range(15):
        a, b = vector(), vector()
        assert sp.srepr(kin.dot(a, b)) == sp.srepr(a & b)
    assert kin.dot(Vector(0), frames[1].x) == 0
