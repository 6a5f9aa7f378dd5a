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
        assert kin.frame_path(b, a) == b._dict_list(a, 1)
        assert _same(kin.ang_vel_in(b, a), b.ang_vel_in(a))


@pytest.mark.parametrize("seed", range(8))
def test_the_path_among_cycles_is_sympys(seed):
    """Angular velocities given between distant frames (cycles, several
    shortest paths, some given one way only): sympy's first shortest
    path, and the same vector."""
    rng = random.Random(seed)
    frames = _tree(seed, 8)
    u = dynamicsymbols("u1:20")
    for k in range(rng.choice([2, 4, 7])):
        b, a = rng.sample(frames, 2)
        if rng.random() < 0.7:
            b.set_ang_vel(a, u[k] * a.z)
        else:
            b._ang_vel_dict[a] = u[k] * a.y  # one way only
    for b in frames:
        for a in frames:
            try:
                theirs = b._dict_list(a, 1)
            except ValueError:
                assert kin.frame_path(b, a) is None
                with pytest.raises(ValueError):
                    kin.ang_vel_in(b, a)
                continue
            assert kin.frame_path(b, a) == theirs
            assert _same(kin.ang_vel_in(b, a), b.ang_vel_in(a))


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
