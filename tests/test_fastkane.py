"""FastKane (Kane's method with intermediate variables) equals KanesMethod.

Each model is built directly in sympy mechanics; both formulations derive it,
and their mass matrices and forcing vectors are compared at random points."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.model.fastkane import FastKane
from sympy.physics import mechanics as me


def _numbers(symbols, seed):
    rng = random.Random(seed)
    return [rng.uniform(0.3, 1.7) for _ in symbols]


def _compare(model, seed=1, points=3, aux=False):
    """Both formulations from one ``model`` dict, compared at random points."""
    args = model["args"]
    km = me.KanesMethod(**model["kane"])
    km.kanes_equations(model["bodies"], model["loads"])
    fk = FastKane(**model["kane"])
    fk.kanes_equations(model["bodies"], model["loads"])
    wanted = [km.mass_matrix_full, km.forcing_full]
    got = [fk.mass_matrix_full, fk.forcing_full]
    if aux:
        wanted.append(km.auxiliary_eqs)
        got.append(fk.auxiliary_eqs)
    extra = sorted((me.find_dynamicsymbols(sp.Matrix(wanted[-1])) - set(args)), key=str)
    f_km = sp.lambdify(args + extra, wanted, cse=True)
    f_fk = fk.numeric(args + extra, got)
    for k in range(points):
        x = _numbers(args + extra, seed + k)
        for a, b in zip(f_fk(*x), f_km(*x), strict=True):
            a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
            assert a.shape == b.shape
            assert np.allclose(a, b, rtol=1e-11, atol=1e-11), (a, b)
    return fk


def double_pendulum():
    q1, q2 = me.dynamicsymbols("q1 q2")
    u1, u2 = me.dynamicsymbols("u1 u2")
    length, m, g, c = sp.symbols("l m g c")
    n = me.ReferenceFrame("N")
    a = n.orientnew("A", "Axis", [q1, n.z])
    b = n.orientnew("B", "Axis", [q2, n.z])
    a.set_ang_vel(n, u1 * n.z)
    b.set_ang_vel(n, u2 * n.z)
    o = me.Point("O")
    o.set_vel(n, 0)
    p = o.locatenew("P", length * a.x)
    r = p.locatenew("R", length * b.x)
    p.v2pt_theory(o, n, a)
    r.v2pt_theory(p, n, b)
    bodies = [me.Particle("pa", p, m), me.Particle("pb", r, 2 * m)]
    loads = [(p, -m * g * n.y), (r, -2 * m * g * n.y), (b, -c * u2 * n.z)]
    kane = dict(
        frame=n, q_ind=[q1, q2], u_ind=[u1, u2], kd_eqs=[q1.diff() - u1, q2.diff() - u2]
    )
    return dict(
        kane=kane, bodies=bodies, loads=loads, args=[q1, q2, u1, u2, length, m, g, c]
    )


def spatial_chain(nbodies):
    """Bodies joined by spherical joints, body-fixed 1-2-3 angles, speeds =
    angular velocity measure numbers (3 speeds per body)."""
    q = me.dynamicsymbols(f"q1:{3 * nbodies + 1}")
    u = me.dynamicsymbols(f"u1:{3 * nbodies + 1}")
    length, mass, ia, it, g, k = sp.symbols("L M IA IT G k")
    n = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(n, 0)
    parent, previous = n, origin
    bodies, loads, kd = [], [], []
    for j in range(nbodies):
        qs, us = q[3 * j : 3 * j + 3], u[3 * j : 3 * j + 3]
        frame = me.ReferenceFrame(f"B{j + 1}")
        frame.orient_body_fixed(parent, qs, "123")
        w = us[0] * frame.x + us[1] * frame.y + us[2] * frame.z
        kd += list((frame.ang_vel_in(parent) - w).to_matrix(frame))
        frame.set_ang_vel(parent, w)
        center = previous.locatenew(f"P{j + 1}", length * frame.z)
        center.v2pt_theory(previous, n, frame)
        inertia = me.inertia(frame, it, it + j * ia / 3, ia, ia / 7)
        bodies.append(me.RigidBody(f"R{j + 1}", center, frame, mass, (inertia, center)))
        loads.append((center, -mass * g * n.z))
        loads.append((frame, -k * qs[0] * parent.x))  # a spring torque
        parent, previous = frame, center
    kane = dict(frame=n, q_ind=q, u_ind=u, kd_eqs=kd)
    return dict(
        kane=kane, bodies=bodies, loads=loads, args=q + u + [length, mass, ia, it, g, k]
    )


def rolling_disc(dependent=True):
    """A thin disc rolling without slip on a plane.  With ``dependent``, the
    contact point's ground coordinates are coordinates and their rates are
    dependent speeds fixed by two nonholonomic constraints; otherwise the
    contact point's velocity is made of auxiliary speeds (to bring the contact
    forces into evidence)."""
    q1, q2, q3, q4, q5 = me.dynamicsymbols("q1:6")
    u1, u2, u3, u4, u5, u6 = me.dynamicsymbols("u1:7")
    f1, f2, f3 = me.dynamicsymbols("f1:4")
    r, m, g = sp.symbols("r m g")
    n = me.ReferenceFrame("N")
    y = n.orientnew("Y", "Axis", [q1, n.z])
    lean = y.orientnew("L", "Axis", [q2, y.x])
    disc = lean.orientnew("R", "Axis", [q3, lean.y])
    w_qd = disc.ang_vel_in(n)
    disc.set_ang_vel(n, u1 * lean.x + u2 * lean.y + u3 * lean.z)
    kd = [me.dot(disc.ang_vel_in(n) - w_qd, uv) for uv in lean]
    inertia = me.inertia(lean, m / 4 * r**2, m / 2 * r**2, m / 4 * r**2)
    c = me.Point("C")
    if dependent:
        c.set_vel(n, u4 * n.x + u5 * n.y)
        center = c.locatenew("Dmc", r * lean.z)
        center.set_vel(n, c.vel(n) + me.cross(lean.ang_vel_in(n), r * lean.z))
        contact = center.vel(n) + me.cross(disc.ang_vel_in(n), -r * lean.z)
        kd += [q4.diff() - u4, q5.diff() - u5]
        body = me.RigidBody("D", center, disc, m, (inertia, center))
        loads = [(center, -m * g * n.z)]
        kane = dict(
            frame=n,
            q_ind=[q1, q2, q3, q4, q5],
            u_ind=[u1, u2, u3],
            kd_eqs=kd,
            u_dependent=[u4, u5],
            velocity_constraints=[me.dot(contact, y.x), me.dot(contact, y.y)],
        )
        args = [q1, q2, q3, q4, q5, u1, u2, u3, u4, u5, r, m, g]
    else:
        c.set_vel(n, u4 * lean.x + u5 * me.cross(y.z, lean.x) + u6 * y.z)
        center = c.locatenew("Dmc", r * lean.z)
        center.v2pt_theory(c, n, disc)
        body = me.RigidBody("D", center, disc, m, (inertia, center))
        loads = [
            (center, -m * g * y.z),
            (c, f1 * lean.x + f2 * me.cross(y.z, lean.x) + f3 * y.z),
        ]
        kane = dict(
            frame=n,
            q_ind=[q1, q2, q3],
            u_ind=[u1, u2, u3],
            kd_eqs=kd,
            u_auxiliary=[u4, u5, u6],
        )
        args = [q1, q2, q3, u1, u2, u3, r, m, g, f1, f2, f3]
    return dict(kane=kane, bodies=[body], loads=loads, args=args)


def moving_support():
    """A pendulum whose support moves along N.x as a given function f(t)."""
    q, u, f = me.dynamicsymbols("q u f")
    length, m, g = sp.symbols("l m g")
    n = me.ReferenceFrame("N")
    a = n.orientnew("A", "Axis", [q, n.z])
    a.set_ang_vel(n, u * n.z)
    o = me.Point("O")
    o.set_vel(n, f.diff() * n.x)
    p = o.locatenew("P", length * a.x)
    p.v2pt_theory(o, n, a)
    bodies = [me.Particle("pa", p, m)]
    loads = [(p, -m * g * n.y)]
    kane = dict(frame=n, q_ind=[q], u_ind=[u], kd_eqs=[q.diff() - u])
    args = [q, u, length, m, g, f.diff(), f.diff(me.dynamicsymbols._t, 2)]
    return dict(kane=kane, bodies=bodies, loads=loads, args=args)


def test_moving_support_equals_kanesmethod():
    """Given functions of time in the kinematics (rheonomic constraints)."""
    fk = _compare(moving_support(), seed=5)
    assert fk.substitute(fk.forcing).has(
        me.dynamicsymbols("f").diff(me.dynamicsymbols._t, 2)
    )


def test_double_pendulum_equals_kanesmethod():
    fk = _compare(double_pendulum())
    # Intermediates come in evaluation order: each uses only earlier ones.
    seen = set()
    for z, e in fk.intermediates:
        assert not (e.free_symbols - seen) & {s for s, _ in fk.intermediates}
        seen.add(z)


def test_substitute_gives_full_expressions():
    model = double_pendulum()
    km = me.KanesMethod(**model["kane"])
    km.kanes_equations(model["bodies"], model["loads"])
    fk = FastKane(**model["kane"], bodies=model["bodies"], loads=model["loads"])
    full = fk.substitute(fk.mass_matrix)
    assert not full.free_symbols & {z for z, _ in fk.intermediates}
    assert sp.simplify(full - km.mass_matrix) == sp.zeros(2, 2)
    diff = fk.substitute(fk.forcing) - km.forcing
    assert sp.simplify(diff) == sp.zeros(2, 1)


@pytest.mark.parametrize("nbodies", [1, 3])
def test_spatial_chain_equals_kanesmethod(nbodies):
    _compare(spatial_chain(nbodies), seed=nbodies)


def test_rolling_disc_nonholonomic_equals_kanesmethod():
    fk = _compare(rolling_disc(dependent=True), seed=7)
    assert fk.mass_matrix.shape == (5, 5)


def test_rolling_disc_auxiliary_speeds_equal_kanesmethod():
    _compare(rolling_disc(dependent=False), seed=11, aux=True)


def test_velocities_not_linear_in_speeds_are_refused():
    q, u = me.dynamicsymbols("q u")
    n = me.ReferenceFrame("N")
    o, p = me.Point("O"), me.Point("P")
    o.set_vel(n, 0)
    p.set_vel(n, u**2 * n.x)
    with pytest.raises(ValueError, match="not linear"):
        FastKane(
            n,
            [q],
            [u],
            kd_eqs=[q.diff() - u],
            bodies=[me.Particle("p", p, 1)],
            loads=[],
        )


def belt_driven_cart():
    """Two carts joined by a belt whose speed is a given function of time:
    the velocity constraint ``u2 - u1 - f' = 0`` has a part without speeds
    (KanesMethod's ``f_nh``), which reaches the acceleration constraint."""
    q1, q2, u1, u2, f = me.dynamicsymbols("q1 q2 u1 u2 f")
    m1, m2, k = sp.symbols("m1 m2 k")
    n = me.ReferenceFrame("N")
    o = me.Point("O")
    o.set_vel(n, 0)
    p1 = o.locatenew("P1", q1 * n.x)
    p2 = o.locatenew("P2", q2 * n.x)
    p1.set_vel(n, u1 * n.x)
    p2.set_vel(n, u2 * n.x)
    bodies = [me.Particle("c1", p1, m1), me.Particle("c2", p2, m2)]
    loads = [(p1, -k * q1 * n.x), (p2, -k * q2 * n.x)]
    kane = dict(
        frame=n,
        q_ind=[q1, q2],
        u_ind=[u1],
        kd_eqs=[q1.diff() - u1, q2.diff() - u2],
        u_dependent=[u2],
        velocity_constraints=[u2 - u1 - f.diff()],
    )
    t = me.dynamicsymbols._t
    args = [q1, q2, u1, u2, m1, m2, k, f.diff(), f.diff(t, 2)]
    return dict(kane=kane, bodies=bodies, loads=loads, args=args)


def test_constraint_with_a_given_rate_equals_kanesmethod():
    fk = _compare(belt_driven_cart(), seed=13)
    t = me.dynamicsymbols._t
    # the acceleration constraint carries f'' (u2' - u1' - f'' = 0)
    assert fk.substitute(fk.forcing)[1].has(me.dynamicsymbols("f").diff(t, 2))


def test_fastkane_derives_with_the_runtimes_book():
    """FastKane is the runtime's engine: its intermediates are an AutoZ
    book's, and the plain symbols it shows stand for them one to one."""
    from al2py_runtime.intermediates.autoz import Intermediates

    model = double_pendulum()
    fk = FastKane(**model["kane"], bodies=model["bodies"], loads=model["loads"])
    assert isinstance(fk.book, Intermediates)
    assert len(fk.intermediates) == len(fk.book) > 0
    for z, _ in fk.intermediates[:5]:
        k = int(z.name[1:])
        _, body = fk.book.canonical(k)
        assert sp.simplify(fk.substitute(z) - fk.book.expand(body)) == 0
