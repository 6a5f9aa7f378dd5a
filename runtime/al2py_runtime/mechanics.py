"""Physical entities and Kane's method (tutorial §3, §4.4-4.5, §5.2-5.9).

:class:`MechanicsMixin` adds the physics commands to :class:`Workspace`.

Objects.  A frame or body *is* its ``sympy.physics.vector.ReferenceFrame``
(named with the Autolev name, ``A1>`` is ``A.x``); points, particles and mass
centers *are* ``Point``s (``"O"``, ``"AO"``).  Masses, inertias, positions,
velocities, accelerations, forces and torques live in a registry kept by the
workspace (orientations and angular velocities are stored on the sympy frames
themselves, so sympy's frame algebra -- ``dcm``, ``express``, ``dot`` --
works).

Kinematic rules (as Autolev):

* Position vectors reverse and chain: ``P_R_Q>`` is ``-P_Q_R>`` and
  ``P_O_Q>`` is found along any chain of given positions ``O -> P -> Q``.
* A velocity that was not given (or formed by ``V2pts``...) is the velocity of
  the nearest point (along given positions) whose velocity in that frame is
  known, plus the time derivative of the position from it.  The origin of a
  frame (``NO``, ``AO``...) has zero velocity in its frame.
* Accelerations not given are time derivatives of velocities; angular
  velocities not given come from the direction cosine matrices; angular
  accelerations not given are time derivatives of angular velocities.

Internally every derivative is taken after substituting all right-hand sides
(``QA' = U1/LA``, dependent speeds, named quantities), so results are correct
whatever is kept symbolic in the responses.
"""

from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.physics.vector import (
    Dyadic,
    Point,
    ReferenceFrame,
    Vector,
    dynamicsymbols,
    time_derivative,
)

from . import kinematics as kin
from .kane import arrange, solve_speeds

__all__ = ["MechanicsMixin"]

t = dynamicsymbols._t

_SPEED = re.compile(r"U(\d+)$")


@dataclass
class _Body:
    frame: ReferenceFrame
    point: Point
    mass: Any = None
    inertia: Any = None  # Dyadic about ``inertia_point`` (None: not given)
    inertia_point: Point | None = None


@dataclass
class _State:
    newtonian: ReferenceFrame | None = None
    frames: dict = field(default_factory=dict)  # name -> ReferenceFrame
    points: dict = field(default_factory=dict)  # name -> Point
    fixed_in: dict = field(default_factory=dict)  # Point -> frame (origins)
    bodies: dict = field(default_factory=dict)  # ReferenceFrame -> _Body
    particles: dict = field(default_factory=dict)  # Point -> mass or None
    massive: list = field(default_factory=list)  # bodies' frames and particles
    edges: dict = field(default_factory=dict)  # Point -> {Point: P_from_to>}
    vel: dict = field(default_factory=dict)  # (Point, frame) -> Vector
    acc: dict = field(default_factory=dict)
    angacc: dict = field(default_factory=dict)  # (B, A) -> Vector
    forces: dict = field(default_factory=dict)  # Point -> Vector
    torques: dict = field(default_factory=dict)  # frame -> Vector
    dependent: list = field(default_factory=list)
    auxiliary: list = field(default_factory=list)
    speed_dt: dict = field(default_factory=dict)  # U' -> expression (Constrain)
    deferred_vel: dict = field(default_factory=dict)  # (P, N) -> (A, O): V2pts
    deferred_acc: dict = field(default_factory=dict)  # (P, N) -> (A, O): A2pts
    motion: list = field(default_factory=list)  # MotionVariables, in order
    fr_speeds: list | None = None
    kane: dict | None = None


def _undef(label: str) -> KeyError:
    return KeyError(f"{label} is not defined")


class MechanicsMixin:
    """Frames, bodies, points, kinematics, mass, loads and Kane's method."""

    # ------------------------------------------------------------ registry

    @property
    def _mech(self) -> _State:
        st = self.__dict__.get("_mech_state")
        if st is None:
            st = self.__dict__["_mech_state"] = _State()
        return st

    def _new_point(self, name: str, kind: str = "point") -> Point:
        st = self._mech
        p = Point(name.upper())
        st.points[name.upper()] = p
        st.edges.setdefault(p, {})
        self._declare(name, kind, p)
        return p

    def _new_frame(self, name: str, kind: str) -> ReferenceFrame:
        st = self._mech
        f = ReferenceFrame(name.upper())
        st.frames[name.upper()] = f
        self._declare(name, kind, f)
        origin = self._new_point(name.upper() + "O", "point")
        st.fixed_in[origin] = f
        return f

    # ---------------------------------------------------------- declarations

    def newtonian(self, name: str) -> ReferenceFrame:
        """``Newtonian N``: frame N and point NO fixed in N."""
        f = self._new_frame(name, "newtonian")
        self._mech.newtonian = f
        return f

    def frames(self, *names: str) -> Any:
        """``Frames A, B``: frames and their fixed points AO, BO."""
        return kin.one_or_tuple([self._new_frame(n, "frame") for n in names])

    def bodies(self, *names: str) -> Any:
        """``Bodies A, B``: frames and mass centers AO, BO."""
        out = []
        st = self._mech
        for n in names:
            f = self._new_frame(n, "body")
            st.bodies[f] = _Body(f, self.point(n.upper() + "O"))
            st.massive.append(f)
            out.append(f)
        return kin.one_or_tuple(out)

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

    def points(self, *names: str) -> Any:
        """``Points O, P``."""
        return kin.one_or_tuple([self._new_point(n) for n in names])

    def point(self, name: str) -> Point:
        """The declared point, particle or mass center named ``name``."""
        try:
            return self._mech.points[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a point, particle or mass center") from None

    def frame(self, name: str) -> ReferenceFrame:
        """The declared frame, body or Newtonian frame named ``name``."""
        try:
            return self._mech.frames[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a frame or body") from None

    def _n(self) -> ReferenceFrame:
        n = self._mech.newtonian
        if n is None:
            raise ValueError("no Newtonian frame has been declared")
        return n

    def _scalar(self, value: Any) -> Any:
        return self.normalize(value)

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

    def _body(self, body: Any) -> _Body:
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

    def _assign_form(self, key: Any, value: Any, *, line: int | None) -> Any:
        """Store a syntactical form (``P_O_Q>``, ``V_P_N>``, ``N_A``...).

        Return the Python binding, or ``NotImplemented`` if ``key`` is not a
        syntactical form of declared frames/points/bodies."""
        form = self._parse_form(key.name)
        if form is None:
            return NotImplemented
        if key.primes or key.index:
            raise ValueError(f"cannot assign to {key}: assign all of {key.name}")
        kind, *objs = form
        st = self._mech
        if isinstance(value, Vector | Dyadic):
            value = kin.vmap(value, self.normalize)
        if kind == "DCM":
            a, b = objs
            m = sp.Matrix(value)
            if m.shape != (3, 3):
                raise ValueError(f"{key.name} must be a 3x3 matrix")
            b.orient_explicit(a, m)
            self.respond(key.name, m, line=line)
            return m
        if kind == "INERTIA":
            body, p = objs
            value = _as_dyadic(value)
            b = self._body(body)
            b.inertia, b.inertia_point = value, p
            self.respond(key.name, value, line=line)
            return value
        value = kin.as_vector(value)
        if kind == "POS":
            self._set_pos(objs[0], objs[1], value)
        elif kind == "VEL":
            st.vel[(objs[0], objs[1])] = value
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
        self.respond(key.name, value, line=line)
        return value

    def _form_value(self, key: Any) -> Any:
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

    # --------------------------------------------------------- positions

    def _set_pos(self, p: Point, q: Point, v: Vector) -> None:
        st = self._mech
        st.edges.setdefault(p, {})[q] = v
        st.edges.setdefault(q, {})[p] = -v
        q.set_pos(p, v)

    def _path(self, p: Point, q: Point) -> list[Point] | None:
        """Shortest chain of given positions from p to q."""
        edges = self._mech.edges
        prev = {p: None}
        todo = deque([p])
        while todo:
            r = todo.popleft()
            if r is q:
                path = [r]
                while prev[path[-1]] is not None:
                    path.append(prev[path[-1]])
                return path[::-1]
            for s in edges.get(r, {}):
                if s not in prev:
                    prev[s] = r
                    todo.append(s)
        return None

    def pos(self, p: Point, q: Point) -> Vector:
        """``P_P_Q>``: position vector from ``p`` to ``q``."""
        if p is q:
            return Vector(0)
        path = self._path(p, q)
        if path is None:
            raise ValueError(f"P_{p.name}_{q.name}> is not defined")
        edges = self._mech.edges
        out = Vector(0)
        for a, b in zip(path, path[1:], strict=False):
            out += edges[a][b]
        return out

    # ------------------------------------------------------- resolution

    def _actual(self, x: Any, keep: Any = ()) -> Any:
        """``x`` with every right-hand side substituted (except ``keep``)."""
        keep = list(keep)
        return kin.vmap(x, self._resolver(keep))

    def _dt(self, v: Any, frame: ReferenceFrame) -> Any:
        v = self._actual(v)
        if isinstance(v, Vector | Dyadic):
            out = time_derivative(v, frame)
        else:
            out = sp.diff(v, t)
        return self._actual(out)

    # --------------------------------------------------------- velocities

    def _known_vel(self, p: Point, frame: ReferenceFrame) -> Vector | None:
        st = self._mech
        if (p, frame) in st.vel:
            return st.vel[(p, frame)]
        if (p, frame) in st.deferred_vel:
            return self._deferred("V", p, frame)
        if st.fixed_in.get(p) is frame:
            return Vector(0)
        return None

    def vel(self, p: Point, frame: ReferenceFrame) -> Vector:
        """``V_P_N>``: given, formed, or the derivative of a position from the
        nearest point whose velocity in ``frame`` is known."""
        known = self._known_vel(p, frame)
        if known is not None:
            return known
        edges = self._mech.edges
        seen = {p}
        todo = deque([p])
        while todo:
            r = todo.popleft()
            for s in edges.get(r, {}):
                if s in seen:
                    continue
                seen.add(s)
                v = self._known_vel(s, frame)
                if v is not None:
                    return kin.tidy_vector(v + self._dt(self.pos(s, p), frame))
                todo.append(s)
        raise ValueError(f"V_{p.name}_{frame.name}> is not defined")

    def acc(self, p: Point, frame: ReferenceFrame) -> Vector:
        """``A_P_N>``: given, formed, or the derivative of ``V_P_N>``."""
        st = self._mech
        if (p, frame) in st.acc:
            return st.acc[(p, frame)]
        if st.fixed_in.get(p) is frame:
            return Vector(0)
        if (p, frame) in st.deferred_acc:
            return self._deferred("A", p, frame)
        try:
            v = self.vel(p, frame)
        except ValueError:
            raise ValueError(f"A_{p.name}_{frame.name}> is not defined") from None
        return kin.tidy_vector(self._dt(v, frame))

    def ang_vel(self, b: ReferenceFrame, a: ReferenceFrame) -> Vector:
        """``W_B_A>``: given, or from the direction cosine matrices."""
        if a is b:
            return Vector(0)
        try:
            return b.ang_vel_in(a)
        except ValueError:
            raise ValueError(f"W_{b.name}_{a.name}> is not defined") from None

    def ang_acc(self, b: ReferenceFrame, a: ReferenceFrame) -> Vector:
        """``ALF_B_A>``: given, or the derivative of ``W_B_A>`` in ``a``."""
        if a is b:
            return Vector(0)
        st = self._mech
        if (b, a) in st.angacc:
            return st.angacc[(b, a)]
        return kin.tidy_vector(self._dt(self.ang_vel(b, a), a))

    def dcm(self, a: ReferenceFrame, b: ReferenceFrame) -> sp.Matrix:
        """``A_B``: element [i,j] is Dot(Ai>, Bj>)."""
        try:
            m = a.dcm(b)
        except ValueError:
            raise ValueError(f"{a.name}_{b.name} is not defined") from None
        return sp.Matrix(m).applyfunc(kin.tidy)

    # --------------------------------------------------- rotation commands

    def _orient(self, a: ReferenceFrame, b: ReferenceFrame, m: sp.Matrix) -> None:
        b.orient_explicit(a, m)

    def simprot(
        self, a: ReferenceFrame, b: ReferenceFrame, axis: Any, angle: Any, *, line=None
    ) -> sp.Matrix:
        """``Simprot(A, B, 3, Q)``: B rotated relative to A about A3 (= B3).

        The axis may also be a vector (``Simprot(N, A, N1>, X)``, or any
        direction): B is rotated by ``angle`` about it, right-handed."""
        axis = self.val(axis)
        if isinstance(axis, Vector):
            if axis == Vector(0):
                raise ValueError("Simprot: the axis vector is zero")
            m = kin.axis_dcm(axis.to_matrix(a), angle)
            b.orient_explicit(a, m)
            rate = sp.diff(sp.sympify(angle), t)
            b.set_ang_vel(a, kin.vmap(axis.normalize(), lambda e: e * rate))
        else:
            m = kin.simprot_dcm(int(axis), angle)
            unit = (a.x, a.y, a.z)[abs(int(axis)) - 1]
            b.orient_axis(a, unit if int(axis) > 0 else -unit, angle)
        self.respond(f"{a.name}_{b.name}", m, line=line)
        return m

    def dircos(
        self, a: ReferenceFrame, b: ReferenceFrame, kind: str, *qs: Any, line=None
    ) -> sp.Matrix:
        """``Dircos(A, B, BODY123, Q1, Q2, Q3)`` (also SPACEijk, EULER with 4
        parameters, RODRIGUES): forms ``A_B``."""
        m = kin.rotation_dcm(kind, list(qs))
        kind = kind.upper()
        if kind.startswith("BODY"):
            b.orient_body_fixed(a, tuple(qs), kind[4:])
        elif kind.startswith("SPACE"):
            b.orient_space_fixed(a, tuple(qs), kind[5:])
        else:
            self._orient(a, b, m)
        self.respond(f"{a.name}_{b.name}", m, line=line)
        return m

    def _dcm_angvel(self, a, b, kind, qs) -> list:
        """B measure numbers of the angular velocity implied by the
        orientation (sympy's closed forms for Euler angles)."""
        kind = kind.upper()
        if kind.startswith(("BODY", "SPACE")) and len(qs) == 3:
            pa, pb = ReferenceFrame("_PA"), ReferenceFrame("_PB")
            if kind.startswith("BODY"):
                pb.orient_body_fixed(pa, tuple(qs), kind[4:])
            else:
                pb.orient_space_fixed(pa, tuple(qs), kind[5:])
            w = pb.ang_vel_in(pa)
            return [kin.simplify_small(w.dot(e)) for e in (pb.x, pb.y, pb.z)]
        m = kin.rotation_dcm(kind, list(qs))
        return kin.angvel_from_dcm(m)

    def angvel(
        self,
        a: ReferenceFrame,
        b: ReferenceFrame,
        kind: str | None = None,
        *qs: Any,
        line=None,
    ) -> Vector:
        """``Angvel(A, B, BODY123, Q1, Q2, Q3)``: forms ``W_B_A>`` (in B).
        ``Angvel(A, B)`` shows the angular velocity ``W_B_A>`` of B in A."""
        if kind is None:
            w = self.ang_vel(b, a)
            self.respond(f"W_{b.name}_{a.name}>", w, line=line)
            return w
        w = kin.frame_vector(b, self._dcm_angvel(a, b, kind, qs))
        b.set_ang_vel(a, w)
        self.respond(f"W_{b.name}_{a.name}>", w, line=line)
        return w

    def kindiffs(
        self, a: ReferenceFrame, b: ReferenceFrame, kind: str, *qs: Any, line=None
    ) -> tuple:
        """``Kindiffs(A, B, BODY123, Q1, Q2, Q3)``: assigns ``Q1'``... so that
        the angular velocity of B in A implied by the orientation equals the
        given ``W_B_A>`` (if it was given in terms of other quantities) or
        else ``U1*B1> + U2*B2> + U3*B3>``."""
        wq = self._dcm_angvel(a, b, kind, qs)
        given = None
        try:
            given = self._actual(b.ang_vel_in(a))
        except ValueError:
            pass
        qdots = [sp.Derivative(q, t) for q in qs]
        if given is not None and not any(given.to_matrix(b).has(d) for d in qdots):
            w = [kin.tidy(given.dot(e)) for e in (b.x, b.y, b.z)]
        else:
            speeds = self._speeds()
            if len(speeds) < 3:
                raise ValueError("Kindiffs needs W_B_A> or speeds U1, U2, U3")
            w = speeds[:3]
            b.set_ang_vel(a, kin.frame_vector(b, w))
        if kind.upper() == "EULER":
            rates = kin.euler_parameter_rates(list(qs), w)
        else:
            eqs = [wq[i] - w[i] for i in range(3)]
            rates = solve_speeds(eqs, qdots)
        out = []
        for q, r in zip(qs, rates, strict=True):
            r = kin.simplify_small(r)
            out.append(self.assign(self.name_of(q) + "'", r, line=line))
        return tuple(out)

    # ------------------------------------------------- velocity formulas

    def _v2pts(self, n, a, o, p) -> Vector:
        v = self.vel(o, n) + (self.ang_vel(a, n) ^ self.pos(o, p))
        return kin.tidy_vector(v)

    def _a2pts(self, n, a, o, p) -> Vector:
        w = self.ang_vel(a, n)
        r = self.pos(o, p)
        v = self.acc(o, n) + (self.ang_acc(a, n) ^ r) + (w ^ (w ^ r))
        return kin.tidy_vector(v)

    def _deferred(self, which: str, p: Point, n: ReferenceFrame) -> Vector:
        """A velocity/acceleration stated by ``V2pts``/``A2pts`` before the
        other point's was known: formed now (an error if it still is not)."""
        st = self._mech
        table = st.deferred_vel if which == "V" else st.deferred_acc
        a, o = table.pop((p, n))  # no cycles: each rule is used once
        try:
            v = (self._v2pts if which == "V" else self._a2pts)(n, a, o, p)
        except ValueError:
            table[(p, n)] = (a, o)
            raise ValueError(
                f"{which}_{p.name}_{n.name}> is not defined: {which}2pts("
                f"{n.name}, {a.name}, {o.name}, {p.name}) needs "
                f"{which}_{o.name}_{n.name}>, P_{o.name}_{p.name}> and "
                f"W_{a.name}_{n.name}>"
            ) from None
        table[(p, n)] = (a, o)
        return v

    def _two_points(self, which: str, n, a, o, p, line) -> Vector | None:
        try:
            v = (self._v2pts if which == "V" else self._a2pts)(n, a, o, p)
        except ValueError:
            # Not all of it is known yet (the other point's motion, the
            # position, W_A_N>): keep the relation and form the value when it
            # is used (an error then if it still cannot be formed).
            st = self._mech
            table = st.deferred_vel if which == "V" else st.deferred_acc
            table[(p, n)] = (a, o)
            (st.vel if which == "V" else st.acc).pop((p, n), None)
            return None
        return self._set_formed(which, p, n, v, line)

    def v2pts(self, n, a, o, p, *, line=None) -> Vector | None:
        """``V2pts(N, A, O, P)``: O and P fixed on A;
        ``V_P_N> = V_O_N> + Cross(W_A_N>, P_O_P>)``.  If a term is not
        known yet (``V_O_N>``...) the relation is kept (no response) and
        used when ``V_P_N>`` is needed."""
        return self._two_points("V", n, a, o, p, line)

    def a2pts(self, n, a, o, p, *, line=None) -> Vector | None:
        """``A2pts(N, A, O, P)``: O and P fixed on A (deferred as V2pts)."""
        return self._two_points("A", n, a, o, p, line)

    def v1pt(self, n, a, o, p, *, line=None) -> Vector:
        """``V1pt(N, A, O, P)``: O fixed on A, P moving on A."""
        r = self.pos(o, p)
        vpa = self._mech.vel.get((p, a))
        if vpa is None:
            vpa = self._dt(r, a)
        v = self.vel(o, n) + vpa + (self.ang_vel(a, n) ^ r)
        return self._set_formed("V", p, n, kin.tidy_vector(v), line)

    def a1pt(self, n, a, o, p, *, line=None) -> Vector:
        """``A1pt(N, A, O, P)``: O fixed on A, P moving on A."""
        st = self._mech
        r = self.pos(o, p)
        vpa = st.vel.get((p, a))
        if vpa is None:
            vpa = self._dt(r, a)
        apa = st.acc.get((p, a))
        if apa is None:
            apa = self._dt(vpa, a)
        w = self.ang_vel(a, n)
        v = (
            self.acc(o, n)
            + apa
            + 2 * (w ^ vpa)
            + (self.ang_acc(a, n) ^ r)
            + (w ^ (w ^ r))
        )
        return self._set_formed("A", p, n, kin.tidy_vector(v), line)

    def _set_formed(self, which, p, n, v, line) -> Vector:
        table = self._mech.vel if which == "V" else self._mech.acc
        table[(p, n)] = v
        self.respond(f"{which}_{p.name}_{n.name}>", v, line=line)
        return v

    # ------------------------------------------------ vector operations

    def express(self, v: Any, frame: ReferenceFrame) -> Any:
        """``Express(v>, A)``: ``v>`` in terms of A1>, A2>, A3>.  The unit
        dyadic ``1>>`` is the identity in every frame, whether or not A is
        oriented relative to the frame it was written in."""
        if isinstance(v, Vector):
            return kin.tidy_vector(v.express(frame))
        if isinstance(v, Dyadic):
            if kin.is_unit_dyadic(v):
                return kin.unit_dyadic(frame)
            return kin.vmap(v.express(frame, frame), kin.tidy)
        return v

    def represent(self, x: Any, frame: ReferenceFrame) -> Any:
        """``Represent(x, A)``: a vector -> the row matrix of its A measure
        numbers, a dyadic -> the 3x3 matrix; and back: a 3-element matrix ->
        vector, a 3x3 matrix -> dyadic."""
        x = self.val(x)
        if isinstance(x, Vector):
            return sp.Matrix(
                [[kin.tidy(x.dot(e)) for e in (frame.x, frame.y, frame.z)]]
            )
        if isinstance(x, Dyadic):
            return x.to_matrix(frame).applyfunc(kin.tidy)
        if isinstance(x, sp.MatrixBase):
            if x.shape == (3, 3):
                return kin.frame_dyadic(frame, x)
            if len(x) == 3:
                return kin.frame_vector(frame, list(x))
        if x == 0:
            return sp.zeros(1, 3)
        raise TypeError(f"cannot represent {x!r} in {frame}")

    def matrix(self, frame: ReferenceFrame, x: Any) -> sp.Matrix:
        """``Matrix(A, v>)``: see :meth:`represent`."""
        x = self.val(x)
        if not isinstance(x, Vector | Dyadic) and x != 0:
            raise TypeError("Matrix(A, x) needs a vector or dyadic")
        return self.represent(x, frame)

    def vector(self, frame: ReferenceFrame, *m: Any) -> Vector:
        """``Vector(A, x, y, z)`` or ``Vector(A, M)``."""
        if len(m) == 1:
            m = list(self.val(m[0]))
        return kin.frame_vector(frame, m)

    def dyadic(self, frame: ReferenceFrame, *m: Any) -> Dyadic:
        """``Dyadic(A, M)`` (3x3), nine scalars (row by row) or three (diagonal)."""
        if len(m) == 1:
            mat = sp.Matrix(self.val(m[0]))
        elif len(m) == 9:
            mat = sp.Matrix(3, 3, list(m))
        elif len(m) == 3:
            mat = sp.diag(*m)
        else:
            raise ValueError("Dyadic(A, ...) takes a 3x3 matrix, 9 or 3 scalars")
        if mat.shape != (3, 3):
            raise ValueError("Dyadic(A, M) needs a 3x3 matrix")
        return kin.frame_dyadic(frame, mat)

    def dot(self, a: Any, b: Any) -> Any:
        a, b = self.val(a), self.val(b)
        if isinstance(a, kin.VectorMatrix) or isinstance(b, kin.VectorMatrix):
            return kin.vdot_matrix(a, b).applyfunc(kin.tidy)
        return kin.tidy(kin.vdot(a, b))

    def cross(self, a: Any, b: Any) -> Any:
        return kin.vmap(kin.vcross(self.val(a), self.val(b)), kin.tidy)

    def magsq(self, v: Any) -> Any:
        v = self.val(v)
        if isinstance(v, Vector):
            return kin.tidy(v.dot(v))
        return sp.sympify(v) ** 2

    def mag(self, v: Any) -> Any:
        v = self.val(v)
        if isinstance(v, Vector):
            return sp.sqrt(self.magsq(v))
        return sp.Abs(sp.sympify(v))

    def unitvec(self, v: Any) -> Vector:
        v = self.val(v)
        m = self.mag(v)
        if m == 0:
            raise ValueError("UnitVec of the zero vector")
        return kin.vmap(v, lambda e: e / m)

    def unit_dyadic(self) -> Dyadic:
        """``1>>``, expressed in the Newtonian frame (without one, in the first
        declared frame; ``Express(1>>, A)`` gives it in any frame)."""
        st = self._mech
        n = st.newtonian or next(iter(st.frames.values()), None)
        if n is None:
            raise ValueError("1>> needs a frame: declare one first")
        return kin.unit_dyadic(n)

    def vector_matrix(self, rows: list) -> kin.VectorMatrix:
        """A matrix literal of vectors, ``[V1>; V2>]`` (an argument of Dot)."""
        return kin.VectorMatrix([[kin.as_vector(self.val(e)) for e in r] for r in rows])

    def trace(self, y: Any) -> Any:
        """``Trace(A)`` of a matrix or a dyadic."""
        y = self.val(y)
        if isinstance(y, Dyadic):
            if not y.args:
                return sp.Integer(0)
            frame = y.args[0][1].args[0][1]
            return kin.tidy(y.to_matrix(frame).trace())
        from .matrices import trace

        return trace(y)

    def _vector_d(self, y: Any, x: Any, frame: Any) -> Any:
        """``D(v>, x, A)``: partial derivative of a vector in frame A."""
        if frame is None:
            frame = self._mech.newtonian
        if isinstance(y, Dyadic):
            if frame is None:
                return kin.vmap(y, lambda e: sp.diff(e, x))
            return kin.vmap(y.express(frame, frame), lambda e: sp.diff(e, x))
        if not isinstance(y, Vector):
            return sp.diff(y, x)
        if frame is None:
            return kin.vmap(y, lambda e: sp.diff(e, x))
        return kin.tidy_vector(y.diff(x, frame))

    def _vector_dt(self, y: Any, frame: Any) -> Any:
        """``Dt(v>, A)``: time derivative in frame A (default: Newtonian)."""
        if frame is None:
            frame = self._n()
        if not isinstance(y, Vector | Dyadic):
            return self._dt(y, frame)
        return kin.vmap(self._dt(y, frame), kin.tidy)

    # ------------------------------------------------- mass distribution

    def _mass(self, obj: Any, *, strict: bool = True) -> Any:
        st = self._mech
        if isinstance(obj, ReferenceFrame) and obj in st.bodies:
            m = st.bodies[obj].mass
        elif isinstance(obj, Point) and obj in st.particles:
            m = st.particles[obj]
        else:
            raise ValueError(f"{obj} is not a body or particle")
        if m is None:
            if strict:
                raise ValueError(f"the mass of {obj} has not been declared")
            return sp.Integer(0)
        return m

    def _objects(self, objs: tuple) -> list:
        return list(objs) if objs else list(self._mech.massive)

    def _center(self, obj: Any) -> Point:
        if isinstance(obj, ReferenceFrame):
            return self._body(obj).point
        return obj

    def mass_of(self, *objs: Any) -> Any:
        """``Mass(A, B)``; ``Mass()`` is the total mass."""
        return sum(
            (self._mass(o, strict=bool(objs)) for o in self._objects(objs)),
            sp.Integer(0),
        )

    def cm(self, p: Point, *objs: Any) -> Vector:
        """``CM(P, A, B)``: position vector from P to the mass center."""
        total = sp.Integer(0)
        r = Vector(0)
        for o in self._objects(objs):
            m = self._mass(o, strict=bool(objs))
            if m == 0:
                continue
            total += m
            r += m * self.pos(p, self._center(o))
        if total == 0:
            raise ValueError("CM: the system has no mass")
        return kin.vmap(r, lambda e: kin.tidy(e / total))

    def _transfer(self, r: Vector, frame: ReferenceFrame) -> Dyadic:
        one = (frame.x | frame.x) + (frame.y | frame.y) + (frame.z | frame.z)
        return kin.tidy(r.dot(r)) * one - (r | r)

    def central_inertia(self, body: ReferenceFrame) -> Dyadic:
        """``I_B_Bo>>``: the central inertia dyadic of a body."""
        b = self._body(body)
        if b.inertia is None:
            return Dyadic(0)
        if b.inertia_point is None or b.inertia_point is b.point:
            return b.inertia
        m = self._mass(body)
        r = self.pos(b.inertia_point, b.point)
        return kin.vmap(b.inertia - m * self._transfer(r, body), kin.tidy)

    def inertia_dyadic(self, body: Any, p: Point) -> Dyadic:
        """``I_B_P>>``: inertia dyadic of body (or particle) B about point P."""
        if isinstance(body, Point):
            return self.inertia(p, body)
        b = self._body(body)
        if b.inertia is not None and p is b.inertia_point:
            return b.inertia
        central = self.central_inertia(body)
        if p is b.point:
            return central
        m = self._mass(body)
        r = self.pos(p, b.point)
        return kin.vmap(central + m * self._transfer(r, body), kin.tidy)

    def inertia(self, p: Point, *objs: Any) -> Dyadic:
        """``Inertia(P, A, B)``: inertia dyadic of the objects about P
        (no objects: the whole system)."""
        out = Dyadic(0)
        st = self._mech
        for o in self._objects(objs):
            if isinstance(o, ReferenceFrame):
                out += self.inertia_dyadic(o, p)
            else:
                m = self._mass(o, strict=bool(objs))
                if m != 0:
                    r = self.pos(p, o)
                    frame = st.newtonian or (
                        r.args[0][1] if r.args else ReferenceFrame("_")
                    )
                    out += m * self._transfer(r, frame)
        return kin.vmap(out, kin.tidy)

    # --------------------------------------------------------- loads

    def force_on(self, p: Point) -> Vector:
        """``Force_P>`` (the zero vector if none was applied)."""
        return self._mech.forces.get(p, Vector(0))

    def torque_on(self, b: ReferenceFrame) -> Vector:
        """``Torque_B>`` (the zero vector if none was applied)."""
        return self._mech.torques.get(b, Vector(0))

    def add_force(self, p: Point, v: Any) -> Vector:
        st = self._mech
        st.forces[p] = self.force_on(p) + kin.as_vector(v)
        return st.forces[p]

    def add_torque(self, b: ReferenceFrame, v: Any) -> Vector:
        st = self._mech
        st.torques[b] = self.torque_on(b) + kin.as_vector(v)
        return st.torques[b]

    def force_between(self, o: Point, q: Point, v: Any) -> None:
        """``Force(O/Q, v>)``: -v> on O and +v> on Q."""
        v = kin.as_vector(v)
        self.add_force(o, -v)
        self.add_force(q, v)

    def torque_between(self, a: ReferenceFrame, b: ReferenceFrame, v: Any) -> None:
        """``Torque(A/B, v>)``: -v> on A and +v> on B."""
        v = kin.as_vector(v)
        self.add_torque(a, -v)
        self.add_torque(b, v)

    def gravity(self, vec: Any, *objs: Any, line: int | None = None) -> None:
        """``Gravity(G*N1>)``: adds mass*vec to every particle and mass center
        (those whose mass has been declared); ``Gravity(G*N1>, A, B)`` to the
        listed bodies and particles only."""
        vec = kin.as_vector(vec)
        for o in self._objects(objs):
            m = self._mass(o, strict=False)
            if m != 0:
                self.add_force(self._center(o), m * vec)

    # ------------------------------------------------------- speeds

    def motion_variables(self, *names: str) -> Any:
        """``MotionVariables' Q{2}'', U{2}'``: variables (as ``Variables``)
        that also describe the motion (see :meth:`_speeds`)."""
        out = self.variables(*names)
        objs = out if isinstance(out, tuple) else (out,)
        st = self._mech
        st.motion.extend(o for o in objs if o not in st.motion)
        return out

    def _speeds(self) -> list:
        """Generalized speeds.

        The declared variables U1, U2... in order, if there are any.  Otherwise
        the motion variables (``MotionVariables'``) say, in declaration order:
        one with a right-hand side of its own (``OMEGA = THETA'``) is a name
        for an expression, not a speed; one whose derivative has a right-hand
        side (``POSITION' = SPEED``, a kinematical equation) is a coordinate
        whose speeds are in that equation; one appearing in such an equation
        (``SPEED``) is a speed; any other (``THETA''``) is a coordinate whose
        first derivative ``THETA'`` serves as the generalized speed.  Speeds
        solved by Constrain keep their place."""
        found = []
        for name, entry in self._names.items():
            m = _SPEED.match(name)
            if m and entry.kind == "variable":
                found.append((int(m.group(1)), entry.obj))
        if found:
            return [obj for _, obj in sorted(found, key=lambda x: x[0])]
        st = self._mech
        solved = set(st.dependent) | set(st.auxiliary)
        rhs = self._rhs
        kin_eqs = [
            rhs[sp.Derivative(q, t)]
            for q in st.motion
            if q not in rhs
            and sp.Derivative(q, t) in rhs
            and sp.Derivative(q, t) not in solved
        ]
        out = []
        for q in st.motion:
            dq = sp.Derivative(q, t)
            if q in rhs and q not in solved:
                continue
            if dq in rhs and dq not in solved:
                continue
            if any(sp.sympify(e).has(q) for e in kin_eqs):
                out.append(q)
            else:
                out.append(dq)
        return out

    def _fr_speeds(self) -> list:
        """Speeds with a row in Fr/Fr*: independent and auxiliary speeds."""
        dep = set(self._mech.dependent)
        return [u for u in self._speeds() if u not in dep]

    def _display(self, value: Any) -> Any:
        """A response value simplified for printing (cosmetic, size-gated)."""
        if not isinstance(value, sp.Basic | Vector | Dyadic | sp.MatrixBase):
            return value
        gens = self._gens()
        return kin.vmap(value, lambda e: kin.tidy(e, gens))

    def _gens(self) -> list:
        us = self._speeds()
        return [sp.Derivative(u, t) for u in us] + us

    def _partials(self, v: Vector, speeds: list) -> list:
        keep = speeds + [sp.Derivative(u, t) for u in speeds]
        v = self._actual(v, keep)
        return [kin.vmap(v, lambda e, u=u: sp.diff(e, u)) for u in speeds]

    def partials(self, v: Any, *speeds: Any) -> Any:
        """``Partials(V_P_N>, U1, U2)``: partial velocities (no speeds: with
        respect to each independent/auxiliary speed).  One speed gives one
        vector; several give a tuple of vectors, in order."""
        speeds = list(speeds) or self._fr_speeds()
        out = [kin.tidy_vector(x) for x in self._partials(self.val(v), speeds)]
        return out[0] if len(out) == 1 else tuple(out)

    def remainder(self, v: Any) -> Vector:
        """``Remainder(V_P_N>)``: the part of ``v>`` free of speeds."""
        speeds = self._fr_speeds()
        v = self._actual(self.val(v), speeds)
        return kin.tidy_vector(
            kin.vmap(v, lambda e: e.xreplace(dict.fromkeys(speeds, 0)))
        )

    # -------------------------------------------------- Fr and Fr*

    def _dot_rows(self, vec: Vector, partials: list) -> list:
        return [vec.dot(p) if p != Vector(0) else 0 for p in partials]

    def fr(self) -> sp.Matrix:
        """``Fr()``: generalized active forces (one row per independent or
        auxiliary speed; dependent speeds are eliminated)."""
        n = self._n()
        st = self._mech
        speeds = self._fr_speeds()
        st.fr_speeds = speeds
        rows = [sp.Integer(0)] * len(speeds)
        for p, f in st.forces.items():
            if f == Vector(0):
                continue
            parts = self._partials(self.vel(p, n), speeds)
            rows = [r + d for r, d in zip(rows, self._dot_rows(f, parts), strict=True)]
        for b, tq in st.torques.items():
            if tq == Vector(0):
                continue
            parts = self._partials(self.ang_vel(b, n), speeds)
            rows = [r + d for r, d in zip(rows, self._dot_rows(tq, parts), strict=True)]
        return sp.Matrix(rows)

    def _inertia_torque(self, b: ReferenceFrame, n: ReferenceFrame) -> Vector:
        inertia = self.central_inertia(b)
        w = self._actual(self.ang_vel(b, n))
        alf = self._actual(self.ang_acc(b, n))
        return -((inertia & alf) + (w ^ (inertia & w)))

    def tstar(self, b: ReferenceFrame, n: ReferenceFrame | None = None) -> Vector:
        """``TStar(B, N)``: inertia torque of body B in N."""
        return kin.tidy_vector(self._inertia_torque(b, n or self._n()))

    def frstar(self) -> sp.Matrix:
        """``FrStar()``: generalized inertia forces (rows as :meth:`fr`).

        As sympy's KanesMethod does, accelerations are split into
        ``rest + sum(coef_k * Uk')`` before they are dotted with the partial
        velocities, so each row is built already arranged in the speeds'
        derivatives (large models never differentiate whole rows)."""
        n = self._n()
        st = self._mech
        speeds = self._fr_speeds()
        st.fr_speeds = speeds
        accels = [sp.Derivative(u, t) for u in self._speeds()]
        rows: list[list[Any]] = [[] for _ in speeds]

        def add(vec: Vector, parts: list) -> None:
            rest, coefs = kin.split_linear_vector(vec, accels)
            for r, part in zip(rows, parts, strict=True):
                if part == Vector(0):
                    continue
                r.append(rest.dot(part))
                r.extend(c.dot(part) * a for a, c in coefs.items())

        for o in st.massive:
            m = self._mass(o, strict=False)
            p = self._center(o)
            if m != 0:
                a = self._actual(self.acc(p, n))
                if a != Vector(0):
                    add(-m * a, self._partials(self.vel(p, n), speeds))
            if isinstance(o, ReferenceFrame) and self._body(o).inertia is not None:
                tq = self._inertia_torque(o, n)
                add(tq, self._partials(self.ang_vel(o, n), speeds))
        return sp.Matrix([sp.Add(*r) for r in rows])

    # ------------------------------------------------------ Constrain

    def constrain(self, which: str, speeds: Any, *, line: int | None = None) -> tuple:
        """``Constrain(DEPENDENT[U2, U3])`` or ``Constrain(AUXILIARY[...])``.

        Solves the equations ``DEPENDENT = 0`` (or ``AUXILIARY``) for the named
        speeds and assigns them; their derivatives too when declared (always
        kept for :meth:`kane`).  Dependent speeds get no row in Fr/Fr*;
        auxiliary speeds keep theirs (see :meth:`kane`)."""
        which = which.upper()
        if which not in ("DEPENDENT", "AUXILIARY"):
            raise ValueError("Constrain takes DEPENDENT[...] or AUXILIARY[...]")
        st = self._mech
        mat = self._values.get(which)
        if not isinstance(mat, sp.MatrixBase):
            raise ValueError(f"Constrain: {which} has not been assigned")
        speeds = [sp.sympify(u) for u in speeds]
        eqs = [self.resolve(e, keep=self._speeds()) for e in mat]
        sols = solve_speeds(eqs, speeds)
        gens = self._gens()
        out = []
        for u, s in zip(speeds, sols, strict=True):
            out.append(self.assign(self.name_of(u), s, line=line))
        for u, s in zip(speeds, sols, strict=True):
            ds = self._dt(s, self._mech.newtonian)
            ds = kin.tidy(ds, gens)
            du = sp.Derivative(u, t)
            st.speed_dt[du] = ds
            name = self.name_of(u)
            base = name.rstrip("'")
            if self._names[base].order > len(name) - len(base):
                self.assign(name + "'", ds, line=line)
        target = st.dependent if which == "DEPENDENT" else st.auxiliary
        for u in speeds:
            if u not in target:
                target.append(u)
        return kin.one_or_tuple(out)

    # ----------------------------------------------------------- Kane

    def _speed_subs(self, expr: Any) -> Any:
        """Substitute kinematical equations, constrained speeds and their
        derivatives (named quantities are kept)."""
        speeds = set(self._speeds())
        table = dict(self._mech.speed_dt)
        for k, v in self._rhs.items():
            if k in speeds:
                table[k] = v
            elif isinstance(k, sp.Derivative):
                name = self._entries_by_obj.get(k.expr)
                if name is not None and self._names[name].kind == "variable":
                    table[k] = v
        for _ in range(50):
            new = expr.xreplace(table)
            if new == expr:
                break
            expr = new
        return kin.doit_derivatives(expr)

    def kane(self, *forces: Any, line: int | None = None) -> sp.Matrix:
        """``Kane()`` / ``Kane(F1, F2)``: arrange ``ZERO`` for integration.

        ``ZERO`` (from ``Fr() + FrStar()``, one row per independent and
        auxiliary speed) becomes one row per independent speed::

            ZERO[i] = F[i] + M[i,1]*U1' + ... + M[i,n]*Un'

        with kinematical equations, dependent and auxiliary speeds and their
        derivatives substituted.  The rows of auxiliary speeds are combined
        into the independent rows with the coefficients of the constraint
        solution (so the constraint forces cancel), and, when force measure
        numbers are named, solved for them (assigned as their RHS)."""
        st = self._mech
        zero = self._values.get("ZERO")
        if not isinstance(zero, sp.MatrixBase):
            raise ValueError("Kane: ZERO has not been assigned")
        speeds = st.fr_speeds if st.fr_speeds is not None else self._fr_speeds()
        rows = list(zero)
        if len(rows) != len(speeds):
            raise ValueError(
                f"Kane: ZERO has {len(rows)} rows for {len(speeds)} speeds"
            )
        aux = [u for u in speeds if u in st.auxiliary]
        ind = [u for u in speeds if u not in st.auxiliary]
        z = dict(
            zip(speeds, (self._speed_subs(self.val(r)) for r in rows), strict=True)
        )
        combined = []
        for i in ind:
            row = z[i]
            for x in aux:
                c = sp.diff(self.resolve(self._rhs.get(x, x)), i)
                if c != 0:
                    row += c * z[x]
            combined.append(row)
        forces = [sp.sympify(f) for f in forces]
        cleaned = []
        for row in combined:
            for f in forces:
                c = sp.diff(row, f)
                if c != 0 and sp.simplify(c) == 0:
                    row = sp.expand(row).xreplace({f: 0})
            cleaned.append(row)
        accels = [sp.Derivative(u, t) for u in ind]
        gens = self._gens()
        arranged = sp.Matrix(arrange(cleaned, accels, gens))
        self.update("ZERO", arranged, line=line)
        sols = ()
        if forces:
            eqs = [z[x] for x in aux]
            if len(eqs) != len(forces):
                raise ValueError(
                    f"Kane: {len(forces)} forces for {len(eqs)} auxiliary speeds"
                )
            sols = solve_speeds(eqs, forces)
            for f, s in zip(forces, sols, strict=True):
                self.assign(self.name_of(f), kin.tidy(s, gens), line=line)
        st.kane = {
            "speeds": ind,
            "dependent": list(st.dependent),
            "auxiliary": aux,
            "forces": forces,
            "accels": accels,
        }
        return arranged

    # ---------------------------------------------- energy and momentum

    def ke(self, *objs: Any) -> Any:
        """``KE()``: kinetic energy of all particles and bodies in N;
        ``KE(A, B)`` of the listed ones."""
        n = self._n()
        total = sp.Integer(0)
        for o in self._objects(objs):
            m = self._mass(o, strict=False)
            p = self._center(o)
            if m != 0:
                v = self._actual(self.vel(p, n))
                total += m * v.dot(v) / 2
            if isinstance(o, ReferenceFrame) and self._body(o).inertia is not None:
                w = self._actual(self.ang_vel(o, n))
                total += w.dot(self.central_inertia(o) & w) / 2
        return kin.tidy(total, self._gens())

    def momentum(self, kind: str, *objs: Any) -> Any:
        """``Momentum(LINEAR)``, ``Momentum(ANGULAR, P)`` (about P; default:
        the mass center of the system) or ``Momentum(GENERALIZED)`` (the
        column of dKE/dUr for the independent and auxiliary speeds).  Bodies
        and particles listed after (``Momentum(LINEAR, A, B)``,
        ``Momentum(ANGULAR, P, A)``) restrict it to them."""
        kind = kind.upper()
        n = self._n()
        p: Point | None = None
        if kind == "ANGULAR" and objs and isinstance(objs[0], Point):
            p, objs = objs[0], objs[1:]
        massive = self._objects(tuple(objs))
        if kind == "GENERALIZED":
            ke = self.ke(*objs)
            return sp.Matrix([kin.tidy(sp.diff(ke, u)) for u in self._fr_speeds()])
        if kind not in ("LINEAR", "ANGULAR"):
            raise ValueError("Momentum takes LINEAR, ANGULAR or GENERALIZED")
        out = Vector(0)
        for o in massive:
            m = self._mass(o, strict=False)
            c = self._center(o)
            if kind == "LINEAR":
                if m != 0:
                    out += m * self._actual(self.vel(c, n))
                continue
            if m != 0:
                r = self.pos(p, c) if p is not None else self._from_cm(c)
                if r != Vector(0):
                    out += r ^ (m * self._actual(self.vel(c, n)))
            if isinstance(o, ReferenceFrame) and self._body(o).inertia is not None:
                w = self._actual(self.ang_vel(o, n))
                out += self.central_inertia(o) & w
        return kin.tidy_vector(out)

    def _from_cm(self, c: Point) -> Vector:
        return -self.cm(c)

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
        n = self._n()
        wba = self._actual(self.ang_vel(b, a))
        wa = self._actual(self.ang_vel(a, n))
        if option == "ANGMOM":
            return kin.tidy_vector(j * wba)
        if option == "KE":
            return kin.tidy(j * wa.dot(wba) + j * wba.dot(wba) / 2, self._gens())
        if option != "FRSTAR":
            raise ValueError("Gyrostat option must be FRSTAR, ANGMOM or KE")
        speeds = self._fr_speeds()
        self._mech.fr_speeds = speeds
        carrier = -j * (self._dt(wba, a) + (wa ^ wba))
        alf_b = self._dt(wa + wba, n)
        pa = self._partials(self.ang_vel(a, n), speeds)
        pba = self._partials(self.ang_vel(b, a), speeds)
        rows = []
        for r_a, r_ba in zip(pa, pba, strict=True):
            rows.append(carrier.dot(r_a) - j * alf_b.dot(r_ba))
        gens = self._gens()
        return sp.Matrix([kin.tidy(r, gens) for r in rows])

    def power(self) -> Any:
        """Power of all forces and torques in N (actual motion)."""
        n = self._n()
        st = self._mech
        total = sp.Integer(0)
        for p, f in st.forces.items():
            if f != Vector(0):
                total += f.dot(self._actual(self.vel(p, n)))
        for b, tq in st.torques.items():
            if tq != Vector(0):
                total += tq.dot(self._actual(self.ang_vel(b, n)))
        return kin.tidy(total, self._gens())

    def nicheck(self) -> Any:
        """``NiCheck()``: ``KE() - WORK`` where ``WORK`` is a new variable
        (``NICHECK_WORK``, initially 0) with ``WORK' = `` the power of all
        forces and torques; it stays constant along exact solutions."""
        name = "NICHECK_WORK"
        k = 1
        while name in self._names:
            k += 1
            name = f"NICHECK_WORK{k}"
        work = dynamicsymbols(name, real=True)
        self._declare(name, "variable", work, order=1)
        self._rhs[sp.Derivative(work, t)] = self.power()
        return self.ke() - work


# ---------------------------------------------------------------- helpers


def _as_dyadic(value: Any) -> Dyadic:
    if isinstance(value, Dyadic):
        return value
    if value == 0:
        return Dyadic(0)
    raise TypeError(f"expected a dyadic, not {value!r}")
