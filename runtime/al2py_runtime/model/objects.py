"""Objects: part of :class:`al2py_runtime.model.model.Model`.

Declarations of frames, bodies, particles and points; mass and inertia; Autolev's syntactical forms (``P_O_Q>``, ``V_P_N>``, ``N_A``...) read and assigned.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import (
    Dyadic,
    Point,
    ReferenceFrame,
    Vector,
)

from . import kinematics as kin
from .state import BodyRecord, as_dyadic, command

__all__ = ["Objects"]


class Objects:
    """Declarations of frames, bodies, particles and points; mass and inertia; Autolev's syntactical forms (``P_O_Q>``, ``V_P_N>``, ``N_A``...) read and assigned."""

    def _new_point(self, name: str, kind: str = "point") -> Point:
        st = self._mech
        p = Point(name.upper())
        st.points[name.upper()] = p
        st.edges.setdefault(p, {})
        self.ws.table.declare(name, kind, p)
        return p

    def _new_frame(self, name: str, kind: str) -> ReferenceFrame:
        st = self._mech
        f = ReferenceFrame(name.upper())
        st.frames[name.upper()] = f
        self.ws.table.declare(name, kind, f)
        origin = self._new_point(name.upper() + "O", "point")
        st.fixed_in[origin] = f
        return f

    # ---------------------------------------------------------- declarations

    @command
    def newtonian(self, name: str) -> ReferenceFrame:
        """``Newtonian N``: frame N and point NO fixed in N."""
        f = self._new_frame(name, "newtonian")
        self._mech.newtonian = f
        return f

    @command
    def frames(self, *names: str) -> Any:
        """``Frames A, B``: frames and their fixed points AO, BO."""
        return kin.one_or_tuple([self._new_frame(n, "frame") for n in names])

    @command
    def bodies(self, *names: str) -> Any:
        """``Bodies A, B``: frames and mass centers AO, BO."""
        out = []
        st = self._mech
        for n in names:
            f = self._new_frame(n, "body")
            st.bodies[f] = BodyRecord(f, self.point(n.upper() + "O"))
            st.massive.append(f)
            out.append(f)
        return kin.one_or_tuple(out)

    @command
    def particles(self, *names: str) -> Any:
        """``Particles P, Q``: massive points."""
        out = []
        st = self._mech
        for n in names:
            p = self._new_point(n, "particle")
            st.particles[p] = None
            st.massive.append(p)
            out.append(p)
        return kin.one_or_tuple(out)

    @command
    def points(self, *names: str) -> Any:
        """``Points O, P``."""
        return kin.one_or_tuple([self._new_point(n) for n in names])

    @command
    def point(self, name: str) -> Point:
        """The declared point, particle or mass center named ``name``."""
        try:
            return self._mech.points[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a point, particle or mass center") from None

    @command
    def frame(self, name: str) -> ReferenceFrame:
        """The declared frame, body or Newtonian frame named ``name``."""
        try:
            return self._mech.frames[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a frame or body") from None

    def newtonian_frame(self) -> ReferenceFrame:
        n = self._mech.newtonian
        if n is None:
            raise ValueError("no Newtonian frame has been declared")
        return n

    def _scalar(self, value: Any) -> Any:
        return self.ws.normalize(value)

    @command
    def set_mass(self, obj: Any, value: Any) -> None:
        """``Mass A=12.5``: the mass of body ``A`` (frame) or particle (point)."""
        st = self._mech
        value = self._scalar(value)
        if isinstance(obj, ReferenceFrame) and obj in st.bodies:
            st.bodies[obj].mass = value
        elif isinstance(obj, Point) and obj in st.particles:
            st.particles[obj] = value
        else:
            raise ValueError(f"{obj} is not a body or particle; it has no mass")

    @command
    def set_inertia(
        self,
        body: ReferenceFrame,
        i11: Any,
        i22: Any = 0,
        i33: Any = 0,
        i12: Any = 0,
        i23: Any = 0,
        i31: Any = 0,
        *,
        about: Point | None = None,
        basis: ReferenceFrame | None = None,
    ) -> Dyadic:
        """``Inertia A, I11, I22, I33, I12, I23, I31``: the inertia dyadic of
        body ``A`` about its mass center, or about point ``about`` (the central
        dyadic then follows from the transfer theorem when needed).
        ``Inertia A(B), ...`` gives the scalars in frame ``basis``'s basis."""
        b = self._body(body)
        m = sp.Matrix([[i11, i12, i31], [i12, i22, i23], [i31, i23, i33]]).applyfunc(
            self._scalar
        )
        b.inertia = kin.frame_dyadic(basis if basis is not None else body, m)
        b.inertia_point = about if about is not None else b.point
        return b.inertia

    def _body(self, body: Any) -> BodyRecord:
        try:
            return self._mech.bodies[body]
        except (KeyError, TypeError):
            raise ValueError(f"{body} is not a body") from None

    # --------------------------------------------------- syntactical forms

    def _parse_form(self, name: str) -> tuple | None:
        if "_" not in name:
            return None
        st = self._mech
        base = name.rstrip(">")
        arrows = len(name) - len(base)
        parts = base.split("_")
        pts, frs = st.points, st.frames
        if arrows == 0 and len(parts) == 2:
            if parts[0] in frs and parts[1] in frs:
                return ("DCM", frs[parts[0]], frs[parts[1]])
            return None
        head = parts[0]
        if arrows == 1 and len(parts) == 3:
            a, b = parts[1], parts[2]
            if head == "P" and a in pts and b in pts:
                return ("POS", pts[a], pts[b])
            if head in ("V", "A") and a in pts and b in frs:
                return ("VEL" if head == "V" else "ACC", pts[a], frs[b])
            if head in ("W", "ALF") and a in frs and b in frs:
                return ("ANGVEL" if head == "W" else "ANGACC", frs[a], frs[b])
            return None
        if arrows == 1 and len(parts) == 2:
            if head == "FORCE" and parts[1] in pts:
                return ("FORCE", pts[parts[1]])
            if head == "TORQUE" and parts[1] in frs:
                return ("TORQUE", frs[parts[1]])
            return None
        if arrows == 2 and len(parts) == 3 and head == "I":
            if parts[1] in frs and frs[parts[1]] in st.bodies and parts[2] in pts:
                return ("INERTIA", frs[parts[1]], pts[parts[2]])
            if parts[1] in pts and pts[parts[1]] in st.particles and parts[2] in pts:
                return ("INERTIA", pts[parts[1]], pts[parts[2]])
        return None

    def assign_form(self, key: Any, value: Any, *, line: int | None) -> Any:
        """Store a syntactical form (``P_O_Q>``, ``V_P_N>``, ``N_A``...).

        Return the Python binding, or ``NotImplemented`` if ``key`` is not a
        syntactical form of declared frames/points/bodies."""
        form = self._parse_form(key.name)
        if form is None:
            return NotImplemented
        if key.primes or key.index:
            raise ValueError(f"cannot assign to {key}: assign all of {key.name}")
        kind, *objs = form
        return self._set_form(kind, objs, value, key.name, line)

    def _set_form(
        self, kind: str, objs: list, value: Any, label: str, line: int | None
    ) -> Any:
        """Give a frame, point or body one of its kinematic or mass
        properties (``value`` already normalized) and respond with ``label``."""
        st = self._mech
        if isinstance(value, Vector | Dyadic):
            value = kin.vmap(value, self.ws.normalize)
        if kind == "DCM":
            a, b = objs
            m = sp.Matrix(value)
            if m.shape != (3, 3):
                raise ValueError(f"{label} must be a 3x3 matrix")
            b.orient_explicit(a, m)
            self.ws.respond(label, m, line=line)
            return m
        if kind == "INERTIA":
            body, p = objs
            value = as_dyadic(value)
            b = self._body(body)
            b.inertia, b.inertia_point = value, p
            self.ws.respond(label, value, line=line)
            return value
        value = kin.as_vector(value)
        if kind == "POS":
            self._set_pos(objs[0], objs[1], value)
        elif kind == "VEL":
            st.vel[(objs[0], objs[1])] = value
            objs[0].set_vel(objs[1], value)
        elif kind == "ACC":
            st.acc[(objs[0], objs[1])] = value
        elif kind == "ANGVEL":
            objs[0].set_ang_vel(objs[1], value)
        elif kind == "ANGACC":
            st.angacc[(objs[0], objs[1])] = value
            st.angacc[(objs[1], objs[0])] = -value
        elif kind == "FORCE":
            st.forces[objs[0]] = value
        elif kind == "TORQUE":
            st.torques[objs[0]] = value
        self.ws.respond(label, value, line=line)
        return value

    def _set(self, kind: str, objs: list, value: Any, label: str, line: Any) -> Any:
        value = self.ws.normalize(value, rearrange=self.ws.settings.factoring)
        return self._set_form(kind, objs, value, label, line)

    # Autolev's assignments to syntactical forms, named after the sympy
    # calls they make (``P_O_P> = v`` is ``set_pos(P, O, v)``: sympy's
    # ``P.set_pos(O, v)``).  Each also records Autolev's response.

    @command
    def set_pos(self, p: Point, o: Point, value: Any, *, line=None) -> Vector:
        """``P_O_P> = v``: P's position from O (``P.set_pos(O, v)``); Autolev
        positions reverse and chain."""
        return self._set("POS", [o, p], value, f"P_{o.name}_{p.name}>", line)

    @command
    def set_vel(self, p: Point, frame: ReferenceFrame, value: Any, *, line=None):
        """``V_P_N> = v`` (``P.set_vel(N, v)``)."""
        return self._set("VEL", [p, frame], value, f"V_{p.name}_{frame.name}>", line)

    @command
    def set_acc(self, p: Point, frame: ReferenceFrame, value: Any, *, line=None):
        """``A_P_N> = v`` (``P.set_acc(N, v)``)."""
        return self._set("ACC", [p, frame], value, f"A_{p.name}_{frame.name}>", line)

    @command
    def set_ang_vel(self, b: ReferenceFrame, a: ReferenceFrame, value, *, line=None):
        """``W_B_A> = w`` (``B.set_ang_vel(A, w)``)."""
        return self._set("ANGVEL", [b, a], value, f"W_{b.name}_{a.name}>", line)

    @command
    def set_ang_acc(self, b: ReferenceFrame, a: ReferenceFrame, value, *, line=None):
        """``ALF_B_A> = v`` (``B.set_ang_acc(A, v)``)."""
        return self._set("ANGACC", [b, a], value, f"ALF_{b.name}_{a.name}>", line)

    @command
    def set_force(self, p: Point, value: Any, *, line=None) -> Vector:
        """``Force_P> = v``: the resultant force on P (a load ``(P, v)``)."""
        return self._set("FORCE", [p], value, f"FORCE_{p.name}>", line)

    @command
    def set_torque(self, b: ReferenceFrame, value: Any, *, line=None) -> Vector:
        """``Torque_B> = v``: the resultant torque on B (a load ``(B, v)``)."""
        return self._set("TORQUE", [b], value, f"TORQUE_{b.name}>", line)

    @command
    def set_dcm(self, a: ReferenceFrame, b: ReferenceFrame, value, *, line=None):
        """``A_B = M`` (``B.orient_explicit(A, M)``)."""
        return self._set("DCM", [a, b], value, f"{a.name}_{b.name}", line)

    @command
    def set_inertia_about(self, body: Any, p: Point, value: Any, *, line=None):
        """``I_B_P>> = d``: the inertia dyadic of body B about P."""
        return self._set("INERTIA", [body, p], value, f"I_{body.name}_{p.name}>>", line)

    def form_value(self, key: Any) -> Any:
        """The value of a syntactical form, or ``NotImplemented``."""
        if key.name == "0>":
            return Vector(0)
        if key.name == "1>>":
            return self.unit_dyadic()
        form = self._parse_form(key.name)
        if form is None:
            return NotImplemented
        kind, *objs = form
        getter = {
            "DCM": self.dcm,
            "POS": self.pos,
            "VEL": self.vel,
            "ACC": self.acc,
            "ANGVEL": self.ang_vel,
            "ANGACC": self.ang_acc,
            "FORCE": self.force_on,
            "TORQUE": self.torque_on,
            "INERTIA": self.inertia_dyadic,
        }[kind]
        try:
            value = getter(*objs)
        except ValueError as exc:
            raise KeyError(f"{key.name}: {exc}") from None
        if kind == "DCM" and key.index:
            if len(key.index) != 2:
                raise KeyError(f"{key}: use two indices")
            i, j = key.index
            return value[i - 1, j - 1]
        if key.index or key.primes:
            raise KeyError(f"{key}: not an element of {key.name}")
        return value
