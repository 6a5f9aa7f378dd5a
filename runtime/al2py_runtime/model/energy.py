"""Energy: part of :class:`al2py_runtime.model.model.Model`.

``KE()``, ``Momentum``, ``Gyrostat``, power and ``NiCheck()``.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import Point, ReferenceFrame, Vector

from ..names.variables import time_function
from .state import ModelPart, command, t

__all__ = ["Energy"]


class Energy(ModelPart):
    """``KE()``, ``Momentum``, ``Gyrostat``, power and ``NiCheck()``."""

    # ---------------------------------------------- energy and momentum

    @command
    def ke(self, *objs: Any) -> Any:
        """``KE()``: kinetic energy of all particles and bodies in N;
        ``KE(A, P)`` of the bodies and particles named."""
        n = self.newtonian_frame()
        total = sp.Integer(0)
        for o in self.massive_objects(objs):
            m = self.body_mass(o, strict=False)
            p = self.mass_center(o)
            if m != 0:
                v = self.actual_value(self.vel(p, n))
                total += m * v.dot(v) / 2
            if (
                isinstance(o, ReferenceFrame)
                and self.body_record(o).inertia is not None
            ):
                w = self.actual_value(self.ang_vel(o, n))
                total += w.dot(self.central_inertia(o) & w) / 2
        return self.tidier(total, self.rates_and_speeds())

    @command
    def momentum(self, kind: str, *objs: Any) -> Any:
        """``Momentum(LINEAR)``, ``Momentum(ANGULAR, P)`` (about P; default:
        the mass center of the system) or ``Momentum(GENERALIZED)`` (the
        column of dKE/dUr for the independent and auxiliary speeds).  Bodies
        and particles listed after (``Momentum(LINEAR, A, B)``,
        ``Momentum(ANGULAR, P, A)``) restrict it to them."""
        kind = kind.upper()
        n = self.newtonian_frame()
        p: Point | None = None
        if kind == "ANGULAR" and objs and isinstance(objs[0], Point):
            p, objs = objs[0], objs[1:]
        massive = self.massive_objects(tuple(objs))
        if kind == "GENERALIZED":
            ke = self.ke(*objs)
            return sp.Matrix([self.tidier(sp.diff(ke, u)) for u in self.fr_speeds()])
        if kind not in ("LINEAR", "ANGULAR"):
            raise ValueError("Momentum takes LINEAR, ANGULAR or GENERALIZED")
        out = Vector(0)
        for o in massive:
            m = self.body_mass(o, strict=False)
            c = self.mass_center(o)
            if kind == "LINEAR":
                if m != 0:
                    out += m * self.actual_value(self.vel(c, n))
                continue
            if m != 0:
                r = self.pos(p, c) if p is not None else self._from_cm(c)
                if r != Vector(0):
                    out += r ^ (m * self.actual_value(self.vel(c, n)))
            if (
                isinstance(o, ReferenceFrame)
                and self.body_record(o).inertia is not None
            ):
                w = self.actual_value(self.ang_vel(o, n))
                out += self.central_inertia(o) & w
        return self.tidier.vector(out)

    def _from_cm(self, c: Point) -> Vector:
        return -self.cm(c)

    @command
    def gyrostat(
        self, option: str, shape: str, a: ReferenceFrame, b: ReferenceFrame, j: Any
    ) -> Any:
        """``Gyrostat(FRSTAR|ANGMOM|KE, CYLINDER, A, B, J)``: the terms due to
        the spin ``W_B_A>`` of an axisymmetric rotor B (axial moment of inertia
        J) carried by A, whose inertia (``Inertia A``) is that of the whole
        gyrostat: ANGMOM is ``J*W_B_A>``, KE is
        ``J*Dot(W_A_N>, W_B_A>) + J*Magsq(W_B_A>)/2``, FRSTAR the generalized
        inertia forces of the rotor's relative spin."""
        if shape.upper() != "CYLINDER":
            raise ValueError("Gyrostat supports the CYLINDER rotor only")
        option = option.upper()
        n = self.newtonian_frame()
        wba = self.actual_value(self.ang_vel(b, a))
        wa = self.actual_value(self.ang_vel(a, n))
        if option == "ANGMOM":
            return self.tidier.vector(j * wba)
        if option == "KE":
            return self.tidier(
                j * wa.dot(wba) + j * wba.dot(wba) / 2, self.rates_and_speeds()
            )
        if option != "FRSTAR":
            raise ValueError("Gyrostat option must be FRSTAR, ANGMOM or KE")
        speeds = self.fr_speeds()
        self.registry.fr_speeds = speeds
        self.registry.gyrostat = True
        carrier = -j * (self.resolved_dt(wba, a) + (wa ^ wba))
        alf_b = self.resolved_dt(wa + wba, n)
        pa = self.partial_velocities(self.ang_vel(a, n), speeds)
        pba = self.partial_velocities(self.ang_vel(b, a), speeds)
        rows = []
        for r_a, r_ba in zip(pa, pba, strict=True):
            rows.append(carrier.dot(r_a) - j * alf_b.dot(r_ba))
        gens = self.rates_and_speeds()
        return sp.Matrix([self.tidier(r, gens) for r in rows])

    @command
    def power(self) -> Any:
        """Power of all forces and torques in N (actual motion)."""
        n = self.newtonian_frame()
        st = self.registry
        total = sp.Integer(0)
        for p, f in st.forces.items():
            if f != Vector(0):
                total += f.dot(self.actual_value(self.vel(p, n)))
        for b, tq in st.torques.items():
            if tq != Vector(0):
                total += tq.dot(self.actual_value(self.ang_vel(b, n)))
        return self.tidier(total, self.rates_and_speeds())

    @command
    def nicheck(self) -> Any:
        """``NiCheck()``: ``KE() - WORK`` where ``WORK`` is a new variable
        (``NICHECK_WORK``, initially 0) with ``WORK' = `` the power of all
        forces and torques; it stays constant along exact solutions."""
        name = "NICHECK_WORK"
        k = 1
        while name in self.table.entries:
            k += 1
            name = f"NICHECK_WORK{k}"
        work = time_function(name, real=True)
        self.registry.checks.append(work)
        self.table.declare(name, "variable", work, order=1)
        self.table.set_rhs(sp.Derivative(work, t), self.power())
        return self.ke() - work
