"""The runtime's calls that record what a module told sympy (issue 33):
variables, bodies, two-point velocities, gravity and named vectors."""

from __future__ import annotations

import pytest
import sympy as sp
from al2py_runtime import Workspace, dynamicsymbols, t
from sympy.physics.mechanics import Particle, RigidBody
from sympy.physics.mechanics import dynamicsymbols as sympy_dynamicsymbols
from sympy.physics.mechanics.loads import gravity
from sympy.physics.vector import Dyadic, Point, ReferenceFrame, Vector


def test_dynamicsymbols_are_sympys():
    u1, u2 = dynamicsymbols("U1 U2", real=True)
    assert [u1, u2] == sympy_dynamicsymbols("U1 U2", real=True)
    assert hash(u1) == hash(sympy_dynamicsymbols("U1", real=True))
    assert dynamicsymbols("Q", 2) == sympy_dynamicsymbols("Q", 2)


def test_declared_variables_are_the_modules_functions():
    al = Workspace("v.al")
    q, u = dynamicsymbols("Q U", real=True)
    al.declare_variables(q, u, primes=(1, 0), line=1)
    assert al.symbol("Q") is q
    assert al.symbol("Q'") == q.diff(t)
    assert al.kind("U") == "variable"
    s = sympy_dynamicsymbols("S", real=True)  # sympy's own: accepted
    al.declare_specified(s, primes=1, line=2)
    assert al.symbol("S") == s
    assert al.kind("S") == "specified"
    with pytest.raises(ValueError, match="real"):
        al.declare_variables(sympy_dynamicsymbols("W"), line=3)  # no assumptions


def test_signed_constants_keep_their_sign():
    al = Workspace("c.al")
    m, n = sp.symbols("M", nonnegative=True), sp.symbols("N", nonpositive=True)
    al.declare_constants(m, n, line=1)
    assert al.table.entries["M"].sign == "+"
    assert al.table.entries["N"].sign == "-"
    with pytest.raises(ValueError):
        al.declare_constants(sp.Symbol("K", positive=True), line=2)


def test_vectors_are_named_by_keyword():
    al = Workspace("v.al")
    n = ReferenceFrame("N")
    al.model.declare_newtonian(n)
    v = al.assign_vector(UVEC=3 * n.x, line=1)
    assert v == 3 * n.x and al["UVEC>"] == 3 * n.x
    d = al.assign_dyadic(I=n.x | n.x, line=2)
    assert al["I>>"] == d
    al.update_vector(UVEC=n.y, line=3)
    assert al["UVEC>"] == n.y
    with pytest.raises(TypeError, match="one name"):
        al.assign_vector(A=n.x, B=n.y, line=4)


def _pendulum(al: Workspace):
    n, a = ReferenceFrame("N"), ReferenceFrame("A")
    al.model.declare_newtonian(n)
    ao = Point("AO")
    body = RigidBody("A", ao, a, 0, (Dyadic(0), ao))
    al.model.declare_bodies(body)
    o, p = Point("O"), Point("P")
    al.model.declare_points(o)
    particle = Particle("P", p, 0)
    al.model.declare_particles(particle)
    q, u = dynamicsymbols("Q U", real=True)
    al.declare_variables(q, u, primes=1, line=1)
    lc, m, mp = sp.symbols("L M MP", real=True)
    al.declare_constants(lc, m, mp, line=2)
    al.kd(sp.Eq(q.diff(t), u / lc), line=3)
    a.orient_axis(n, n.z, q)
    al.model.given_orientation(a, n, line=4)
    p.set_pos(o, lc * a.x)
    al.model.given_pos(p, o, line=5)
    o.set_vel(n, Vector(0))
    al.model.given_vel(o, n, line=6)
    return n, a, o, p, body, particle, q, u, lc, m, mp


def test_a_body_is_the_modules_rigid_body():
    al = Workspace("b.al")
    n, a, o, p, body, particle, q, u, lc, m, mp = _pendulum(al)
    assert al.model.frame("A") is a
    assert al.model.point("AO") is body.masscenter
    body.mass = m
    al.model.given_masses(body, line=7)
    assert al.model.mass_of(a) == m
    assert al.model.rigid_body(a) is body


def test_formed_velocity_is_autolevs():
    """After sympy's v2pt_theory the velocity is in the speeds (QA' = U/L
    substituted), as the runtime's V2pts forms it."""
    al = Workspace("v.al")
    n, a, o, p, body, particle, q, u, lc, m, mp = _pendulum(al)
    p.v2pt_theory(o, n, a)
    v = al.model.formed_vel(p, n, line=8)
    assert v == u * a.y
    assert p.vel(n) == u * a.y
    assert al.model.vel(p, n) == u * a.y
    other = Workspace("w.al")
    n2, a2, o2, p2, *_ = _pendulum(other)
    assert other.model.v2pts(n2, a2, o2, p2, line=8) == u * a2.y


def test_gravity_loads_are_sympys():
    al = Workspace("g.al")
    n, a, o, p, body, particle, q, u, lc, m, mp = _pendulum(al)
    particle.mass = mp
    al.model.given_masses(particle, line=7)
    g = sp.Symbol("G", real=True)
    al.model.loads.extend(gravity(g * n.x, particle))
    al.model.given_gravity(g * n.x)
    assert al.model.force_on(p) == mp * g * n.x
    other = Workspace("h.al")
    n2, *_, particle2, _, _, _, _, mp2 = _pendulum(other)
    particle2.mass = mp2
    other.model.given_masses(particle2, line=7)
    other.model.gravity(g * n2.x)  # Autolev's rule: the same load
    assert list(other.model.loads) == [(particle2.point, mp2 * g * n2.x)]
    assert list(al.model.loads) == [(p, mp * g * n.x)]
