"""MassAndLoads: part of :class:`al2py_runtime.model.model.Model`.

Mass distribution (``Mass()``, ``CM``, inertia dyadics and the transfer theorem) and loads (``Force_P>``, ``Torque_B>``, ``Force(O/Q, v>)``, ``Gravity``).
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.mechanics import Force, Torque
from sympy.physics.vector import (
    Dyadic,
    Point,
    ReferenceFrame,
    Vector,
)

from . import kinematics as kin
from .state import ModelPart, command

__all__ = ["MassAndLoads"]


class MassAndLoads(ModelPart):
    """Mass distribution (``Mass()``, ``CM``, inertia dyadics and the transfer theorem) and loads (``Force_P>``, ``Torque_B>``, ``Force(O/Q, v>)``, ``Gravity``)."""

    # ------------------------------------------------- mass distribution

    def body_mass(self, obj: Any, *, strict: bool = True) -> Any:
        """The mass of a body (its frame) or particle (its point); one not
        declared is an error, or zero when ``strict`` is false."""
        st = self.registry
        if not (
            (isinstance(obj, ReferenceFrame) and obj in st.bodies)
            or (isinstance(obj, Point) and obj in st.particles)
        ):
            raise ValueError(f"{obj} is not a body or particle")
        if obj not in st.mass_given:
            if strict:
                raise ValueError(f"the mass of {obj} has not been declared")
            return sp.Integer(0)
        return st.sympy_bodies[obj].mass  # the RigidBody's or Particle's

    def massive_objects(self, objs: tuple) -> list:
        """``objs``, or when none are given every body and particle in
        declaration order (``Mass()``, ``KE()``...)."""
        return list(objs) if objs else list(self.registry.massive)

    def mass_center(self, obj: Any) -> Point:
        """The mass center of a body (given its frame); a particle is its own."""
        if isinstance(obj, ReferenceFrame):
            return self.body_record(obj).point
        return obj

    @command
    def mass_of(self, *objs: Any) -> Any:
        """``Mass(A, B)``; ``Mass()`` is the total mass."""
        return sum(
            (self.body_mass(o, strict=bool(objs)) for o in self.massive_objects(objs)),
            sp.Integer(0),
        )

    @command
    def cm(self, p: Point, *objs: Any) -> Vector:
        """``CM(P, A, B)``: position vector from P to the mass center."""
        total = sp.Integer(0)
        r = Vector(0)
        for o in self.massive_objects(objs):
            m = self.body_mass(o, strict=bool(objs))
            if m == 0:
                continue
            total += m
            r += m * self.pos(p, self.mass_center(o))
        if total == 0:
            raise ValueError("CM: the system has no mass")
        return kin.vmap(r, lambda e: self.tidier(e / total))

    def _transfer(self, r: Vector, frame: ReferenceFrame) -> Dyadic:
        one = (frame.x | frame.x) + (frame.y | frame.y) + (frame.z | frame.z)
        return self.tidier(r.dot(r)) * one - (r | r)

    @command
    def central_inertia(self, body: ReferenceFrame) -> Dyadic:
        """``I_B_Bo>>``: the central inertia dyadic of a body."""
        b = self.body_record(body)
        if b.inertia is None:
            return Dyadic(0)
        if b.inertia_point is None or b.inertia_point is b.point:
            return b.inertia
        m = self.body_mass(body)
        r = self.pos(b.inertia_point, b.point)
        return self.tidier.vector(b.inertia - m * self._transfer(r, body))

    @command
    def inertia_dyadic(self, body: Any, p: Point) -> Dyadic:
        """``I_B_P>>``: inertia dyadic of body (or particle) B about point P."""
        if isinstance(body, Point):
            return self.inertia(p, body)
        b = self.body_record(body)
        if b.inertia is not None and p is b.inertia_point:
            return b.inertia
        central = self.central_inertia(body)
        if p is b.point:
            return central
        m = self.body_mass(body)
        r = self.pos(p, b.point)
        return self.tidier.vector(central + m * self._transfer(r, body))

    @command
    def inertia(self, p: Point, *objs: Any) -> Dyadic:
        """``Inertia(P, A, B)``: inertia dyadic of the objects about P
        (no objects: the whole system)."""
        out = Dyadic(0)
        st = self.registry
        for o in self.massive_objects(objs):
            if isinstance(o, ReferenceFrame):
                out += self.inertia_dyadic(o, p)
            else:
                m = self.body_mass(o, strict=bool(objs))
                if m != 0:
                    r = self.pos(p, o)
                    frame = st.newtonian or (
                        r.args[0][1] if r.args else ReferenceFrame("_")
                    )
                    out += m * self._transfer(r, frame)
        return self.tidier.vector(out)

    # --------------------------------------------------------- loads

    @command
    def force_on(self, p: Point) -> Vector:
        """``Force_P>`` (the zero vector if none was applied)."""
        return self.registry.forces.get(p, Vector(0))

    @command
    def torque_on(self, b: ReferenceFrame) -> Vector:
        """``Torque_B>`` (the zero vector if none was applied)."""
        return self.registry.torques.get(b, Vector(0))

    @property
    def loads(self) -> list:
        """The model's loads, sympy ``Force``/``Torque`` objects in order:
        the list a module appends to (``loads.append(Force(P, v))``) and
        the one that ``Fr()``, ``kanes_method()`` and ``Force_P>`` read."""
        return self.registry.loads

    @command
    def add_force(self, p: Point, v: Any) -> Vector:
        self.registry.loads.append(Force(p, kin.as_vector(v)))
        return self.force_on(p)

    @command
    def add_torque(self, b: ReferenceFrame, v: Any) -> Vector:
        self.registry.loads.append(Torque(b, kin.as_vector(v)))
        return self.torque_on(b)

    @command
    def force_between(self, o: Point, q: Point, v: Any) -> None:
        """``Force(O/Q, v>)``: -v> on O and +v> on Q."""
        v = kin.as_vector(v)
        self.add_force(o, -v)
        self.add_force(q, v)

    @command
    def torque_between(self, a: ReferenceFrame, b: ReferenceFrame, v: Any) -> None:
        """``Torque(A/B, v>)``: -v> on A and +v> on B."""
        v = kin.as_vector(v)
        self.add_torque(a, -v)
        self.add_torque(b, v)

    @command
    def given_gravity(self, vec: Any) -> None:
        """After ``loads += gravity(G*N.x, P_particle, Q_particle)``
        (``Gravity(G*N1>)``, the bodies and particles with a mass so far):
        the direction is kept for the animation's scene."""
        self.registry.gravity.append(kin.as_vector(vec))

    @command
    def gravity(self, vec: Any, *objs: Any, line: int | None = None) -> None:
        """``Gravity(G*N1>)``: adds mass*vec to every particle and mass center
        (those whose mass has been declared); ``Gravity(G*N1>, A, B)`` to the
        listed bodies and particles only.  Each is a sympy ``Force`` appended
        to :attr:`loads` (``Force(P, MP*G*N.x)``), as sympy's
        ``gravity(G*N.x, *bodies)`` gives them for the bodies with a mass."""
        vec = kin.as_vector(vec)
        self.registry.gravity.append(vec)
        for o in self.massive_objects(objs):
            m = self.body_mass(o, strict=False)
            if m != 0:
                self.add_force(self.mass_center(o), m * vec)
