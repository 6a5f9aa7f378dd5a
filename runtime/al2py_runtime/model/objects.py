"""Objects: part of :class:`al2py_runtime.model.model.Model`.

Declarations of frames, bodies, particles and points; mass and inertia; Autolev's syntactical forms (``P_O_Q>``, ``V_P_N>``, ``N_A``...) read and assigned.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.mechanics import Force, Inertia, Particle, RigidBody, Torque
from sympy.physics.vector import (
    Dyadic,
    Point,
    ReferenceFrame,
    Vector,
)

from ..vocabulary import Decl, Form, match
from . import kinematics as kin
from .state import BodyRecord, ModelPart, command

__all__ = ["Objects"]


class Objects(ModelPart):
    """Declarations of frames, bodies, particles and points; mass and inertia; Autolev's syntactical forms (``P_O_Q>``, ``V_P_N>``, ``N_A``...) read and assigned."""

    def _new_point(
        self, name: str, kind: Decl = Decl.POINT, p: Point | None = None
    ) -> Point:
        st = self.registry
        p = Point(name.upper()) if p is None else p
        st.points[name.upper()] = p
        self.table.declare(name, kind, p)
        return p

    def _new_frame(
        self,
        name: str,
        kind: Decl,
        f: ReferenceFrame | None = None,
        origin: Point | None = None,
    ) -> ReferenceFrame:
        st = self.registry
        f = ReferenceFrame(name.upper()) if f is None else f
        st.frames[name.upper()] = f
        self.table.declare(name, kind, f)
        origin = self._new_point(name.upper() + "O", Decl.POINT, origin)
        st.fixed_in[origin] = f
        return f

    # ---------------------------------------------------------- declarations

    @command
    def newtonian(self, name: str) -> ReferenceFrame:
        """``Newtonian N``: frame N and point NO fixed in N."""
        f = self._new_frame(name, Decl.NEWTONIAN)
        self.registry.newtonian = f
        return f

    @command
    def frames(self, *names: str) -> Any:
        """``Frames A, B``: frames and their fixed points AO, BO."""
        return kin.one_or_tuple([self._new_frame(n, Decl.FRAME) for n in names])

    # The module's own sympy objects (``N = ReferenceFrame("N")``), declared
    # under their names as the commands above declare new ones.

    @command
    def declare_newtonian(self, frame: ReferenceFrame) -> ReferenceFrame:
        """After ``N = ReferenceFrame("N")`` (``Newtonian N``): N and NO."""
        self.registry.newtonian = self._new_frame(frame.name, Decl.NEWTONIAN, frame)
        return frame

    @command
    def declare_frames(self, *frames: ReferenceFrame) -> None:
        """After ``A = ReferenceFrame("A")`` (``Frames A``): A and AO."""
        for f in frames:
            self._new_frame(f.name, Decl.FRAME, f)

    @command
    def declare_points(self, *points: Point) -> None:
        """After ``O = Point("O")`` (``Points O``)."""
        for p in points:
            self._new_point(p.name, Decl.POINT, p)

    @command
    def declare_particles(self, *particles: Particle) -> None:
        """After ``P_particle = Particle("P", P, 0)`` (``Particles P``): the
        massive point P, whose mass ``Mass P=MP`` gives."""
        st = self.registry
        for body in particles:
            p = self._new_point(body.point.name, Decl.PARTICLE, body.point)
            st.particles.add(p)
            st.massive.append(p)
            st.sympy_bodies[p] = body

    @command
    def declare_bodies(self, *bodies: RigidBody) -> None:
        """After ``A = ReferenceFrame("A")``, ``Ao = Point("AO")`` and
        ``A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))`` (``Bodies A``):
        the body A (its frame) with its mass center AO, whose mass and
        inertia ``Mass`` and ``Inertia`` give."""
        st = self.registry
        for body in bodies:
            f = body.frame
            self._new_frame(f.name, Decl.BODY, f, origin=body.masscenter)
            st.bodies[f] = BodyRecord(f, body.masscenter)
            st.massive.append(f)
            st.sympy_bodies[f] = body

    @command
    def bodies(self, *names: str) -> Any:
        """``Bodies A, B``: frames and mass centers AO, BO."""
        out = []
        st = self.registry
        for n in names:
            f = self._new_frame(n, Decl.BODY)
            st.bodies[f] = BodyRecord(f, self.point(n.upper() + "O"))
            st.massive.append(f)
            st.sympy_bodies[f] = RigidBody(
                f.name,
                st.bodies[f].point,
                f,
                sp.S.Zero,
                (Dyadic(0), st.bodies[f].point),
            )
            out.append(f)
        return kin.one_or_tuple(out)

    @command
    def particles(self, *names: str) -> Any:
        """``Particles P, Q``: massive points."""
        out = []
        st = self.registry
        for n in names:
            p = self._new_point(n, Decl.PARTICLE)
            st.particles.add(p)
            st.massive.append(p)
            st.sympy_bodies[p] = Particle(p.name, p, sp.S.Zero)
            out.append(p)
        return kin.one_or_tuple(out)

    @command
    def rigid_body(self, frame: ReferenceFrame) -> RigidBody:
        """The sympy ``RigidBody`` of a declared body: its frame, mass center,
        and the mass and central inertia as declared (kept up to date by
        ``Mass`` and ``Inertia``)."""
        self.body_record(frame)
        return self.registry.sympy_bodies[frame]

    @command
    def particle(self, point: Point) -> Particle:
        """The sympy ``Particle`` of a declared particle (its point and its
        mass as declared)."""
        if point not in self.registry.particles:
            raise ValueError(f"{point} is not a particle")
        return self.registry.sympy_bodies[point]

    def _sync_sympy_body(self, obj: Any) -> None:
        """Give the module's ``RigidBody`` the central inertia of the
        inertia as declared (when its position and mass are known)."""
        st = self.registry
        body = st.sympy_bodies[obj]
        if isinstance(obj, ReferenceFrame):
            try:
                central = self.central_inertia(obj)
            except (ValueError, KeyError):
                # Inertia about a point whose position (or the mass) is not
                # given yet: kanes_method() gives the body its actual values.
                return
            if not _holds_inertia(body, central):
                body.inertia = (central, body.masscenter)

    @command
    def points(self, *names: str) -> Any:
        """``Points O, P``."""
        return kin.one_or_tuple([self._new_point(n) for n in names])

    @command
    def point(self, name: str) -> Point:
        """The declared point, particle or mass center named ``name``."""
        try:
            return self.registry.points[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a point, particle or mass center") from None

    @command
    def frame(self, name: str) -> ReferenceFrame:
        """The declared frame, body or Newtonian frame named ``name``."""
        try:
            return self.registry.frames[name.upper()]
        except KeyError:
            raise KeyError(f"{name} is not a frame or body") from None

    def newtonian_frame(self) -> ReferenceFrame:
        """The frame declared with ``Newtonian`` (an error before it is)."""
        n = self.registry.newtonian
        if n is None:
            raise ValueError("no Newtonian frame has been declared")
        return n

    @command
    def set_mass(self, obj: Any, value: Any) -> None:
        """``Mass A=12.5``: the mass of body ``A`` (frame) or particle (point)."""
        st = self.registry
        value = self.script.normalize(value)
        if not (
            (isinstance(obj, ReferenceFrame) and obj in st.bodies)
            or (isinstance(obj, Point) and obj in st.particles)
        ):
            raise ValueError(f"{obj} is not a body or particle; it has no mass")
        st.sympy_bodies[obj].mass = value  # the mass is the sympy body's
        st.mass_given[obj] = None
        self._sync_sympy_body(obj)

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
        b = self.body_record(body)
        m = sp.Matrix([[i11, i12, i31], [i12, i22, i23], [i31, i23, i33]]).applyfunc(
            self.script.normalize
        )
        b.inertia = kin.frame_dyadic(basis if basis is not None else body, m)
        b.inertia_point = about if about is not None else b.point
        self._sync_sympy_body(body)
        return b.inertia

    @command
    def given_masses(self, *bodies: RigidBody | Particle, line=None) -> None:
        """After ``P_particle.mass = MP`` (``Mass P=MP``): the masses as
        Autolev keeps them (normalized; a body's central inertia follows)."""
        for body in bodies:
            obj = body.frame if isinstance(body, RigidBody) else body.point
            self.set_mass(obj, body.mass)

    @command
    def given_inertia(self, body: RigidBody, *, line=None) -> Dyadic:
        """After ``B_body.central_inertia = inertia(B, ...)`` (``Inertia B,
        ...``): the inertia as Autolev keeps it (about the mass center, in
        B's basis, each scalar normalized)."""
        frame = body.frame
        m = kin.dyadic_matrix(body.central_inertia, frame)
        return self.set_inertia(
            frame, m[0, 0], m[1, 1], m[2, 2], m[0, 1], m[1, 2], m[2, 0]
        )

    def body_record(self, body: Any) -> BodyRecord:
        """What the model holds of a body (given its frame): mass center,
        mass and inertia; an error for anything that is not a body."""
        try:
            return self.registry.bodies[body]
        except (KeyError, TypeError):
            raise ValueError(f"{body} is not a body") from None

    # --------------------------------------------------- syntactical forms

    def _parse_form(self, name: str) -> tuple | None:
        """``(form, *objects)`` for a syntactical form of declared objects
        (:func:`al2py_runtime.vocabulary.match`), else None."""
        st = self.registry
        pts, frs = st.points, st.frames

        def is_body(n: str) -> bool:
            return (n in frs and frs[n] in st.bodies) or (
                n in pts and pts[n] in st.particles
            )

        found = match(name, frs.__contains__, pts.__contains__, is_body)
        if found is None or found.kind is Form.UNIT:
            return None
        objs = [
            frs[part] if role == "f" or (role == "b" and part in frs) else pts[part]
            for role, part in zip(found.row.roles, found.parts, strict=True)
        ]
        return (found.kind, *objs)

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
        self, kind: Form, objs: list, value: Any, label: str, line: int | None
    ) -> Any:
        """Give a frame, point or body one of its kinematic or mass
        properties (``value`` already normalized) and respond with ``label``."""
        st = self.registry
        if isinstance(value, Vector | Dyadic):
            value = kin.vmap(value, self.script.normalize)
        if kind is Form.DCM:
            a, b = objs
            m = sp.Matrix(value)
            if m.shape != (3, 3):
                raise ValueError(f"{label} must be a 3x3 matrix")
            b.orient_explicit(a, m)
            self.script.respond(label, m, line=line)
            return m
        if kind is Form.INERTIA:
            body, p = objs
            value = kin.as_dyadic(value)
            b = self.body_record(body)
            b.inertia, b.inertia_point = value, p
            self.script.respond(label, value, line=line)
            return value
        value = kin.as_vector(value)
        if kind is Form.POS:
            self.add_position(objs[0], objs[1], value)
        elif kind is Form.VEL:
            self.keep_given("V", objs[0], objs[1], value)
        elif kind is Form.ACC:
            self.keep_given("A", objs[0], objs[1], value)
        elif kind is Form.ANGVEL:
            objs[0].set_ang_vel(objs[1], value)
        elif kind is Form.ANGACC:
            st.angacc[(objs[0], objs[1])] = value
            st.angacc[(objs[1], objs[0])] = -value
            st.angacc_given.setdefault(objs[0], []).append((objs[1], value))
        elif kind is Form.FORCE:
            _replace_loads(st.loads, objs[0], Force(objs[0], value))
        elif kind is Form.TORQUE:
            _replace_loads(st.loads, objs[0], Torque(objs[0], value))
        self.script.respond(label, value, line=line)
        return value

    def _set(self, kind: Form, objs: list, value: Any, line: Any) -> Any:
        value = self.script.normalize(value, rearrange=self.settings.factoring)
        label = kind.row.spell(*(o.name for o in objs))
        return self._set_form(kind, objs, value, label, line)

    # Autolev's assignments to syntactical forms, named after the sympy
    # calls they make (``P_O_P> = v`` is ``set_pos(P, O, v)``: sympy's
    # ``P.set_pos(O, v)``).  Each also records Autolev's response.

    @command
    def set_pos(self, p: Point, o: Point, value: Any, *, line=None) -> Vector:
        """``P_O_P> = v``: P's position from O (``P.set_pos(O, v)``); Autolev
        positions reverse and chain."""
        return self._set(Form.POS, [o, p], value, line)

    @command
    def set_vel(self, p: Point, frame: ReferenceFrame, value: Any, *, line=None):
        """``V_P_N> = v`` (``P.set_vel(N, v)``)."""
        return self._set(Form.VEL, [p, frame], value, line)

    @command
    def set_acc(self, p: Point, frame: ReferenceFrame, value: Any, *, line=None):
        """``A_P_N> = v`` (``P.set_acc(N, v)``)."""
        return self._set(Form.ACC, [p, frame], value, line)

    @command
    def set_ang_vel(self, b: ReferenceFrame, a: ReferenceFrame, value, *, line=None):
        """``W_B_A> = w`` (``B.set_ang_vel(A, w)``)."""
        return self._set(Form.ANGVEL, [b, a], value, line)

    @command
    def set_ang_acc(self, b: ReferenceFrame, a: ReferenceFrame, value, *, line=None):
        """``ALF_B_A> = v`` (``B.set_ang_acc(A, v)``)."""
        return self._set(Form.ANGACC, [b, a], value, line)

    @command
    def set_force(self, p: Point, value: Any, *, line=None) -> Vector:
        """``Force_P> = v``: the resultant force on P (a load ``(P, v)``)."""
        return self._set(Form.FORCE, [p], value, line)

    @command
    def set_torque(self, b: ReferenceFrame, value: Any, *, line=None) -> Vector:
        """``Torque_B> = v``: the resultant torque on B (a load ``(B, v)``)."""
        return self._set(Form.TORQUE, [b], value, line)

    @command
    def set_dcm(self, a: ReferenceFrame, b: ReferenceFrame, value, *, line=None):
        """``A_B = M`` (``B.orient_explicit(A, M)``)."""
        return self._set(Form.DCM, [a, b], value, line)

    @command
    def set_inertia_about(self, body: Any, p: Point, value: Any, *, line=None):
        """``I_B_P>> = d``: the inertia dyadic of body B about P."""
        return self._set(Form.INERTIA, [body, p], value, line)

    # What a module told sympy directly (``P.set_pos(O, v)``...): the
    # runtime takes the value back from the sympy object, applies Autolev's
    # rules to it (the same as the setters above: normalized, kept for
    # Autolev's chains) and records Autolev's response.

    @command
    def given_pos(self, p: Point, o: Point, *, line=None) -> Vector:
        """After ``P.set_pos(O, v)`` (``P_O_P> = v``): Autolev's response."""
        return self._set(Form.POS, [o, p], p.pos_from(o), line)

    @command
    def given_vel(self, p: Point, frame: ReferenceFrame, *, line=None) -> Vector:
        """After ``P.set_vel(N, v)`` (``V_P_N> = v``): Autolev's response."""
        return self._set(Form.VEL, [p, frame], p.vel(frame), line)

    @command
    def given_acc(self, p: Point, frame: ReferenceFrame, *, line=None) -> Vector:
        """After ``P.set_acc(N, v)`` (``A_P_N> = v``): Autolev's response."""
        return self._set(Form.ACC, [p, frame], p.acc(frame), line)

    @command
    def given_force(self, p: Point, *, line=None) -> Vector:
        """After ``loads.append(Force(P, v))`` (``Force_P> += v``): P's
        resultant force, kept as one load, and Autolev's response."""
        return self._set(Form.FORCE, [p], self.force_on(p), line)

    @command
    def given_torque(self, b: ReferenceFrame, *, line=None) -> Vector:
        """After ``loads.append(Torque(B, v))`` (``Torque_B> += v``): B's
        resultant torque, kept as one load, and Autolev's response."""
        return self._set(Form.TORQUE, [b], self.torque_on(b), line)

    @command
    def given_ang_vel(self, b: ReferenceFrame, a: ReferenceFrame, *, line=None):
        """After ``B.set_ang_vel(A, w)`` (``W_B_A> = w``): Autolev's response."""
        return self._set(Form.ANGVEL, [b, a], kin.ang_vel_in(b, a), line)

    @command
    def given_ang_acc(self, b: ReferenceFrame, a: ReferenceFrame, *, line=None):
        """After ``B.set_ang_acc(A, v)`` (``ALF_B_A> = v``): Autolev's response."""
        return self._set(Form.ANGACC, [b, a], b.ang_acc_in(a), line)

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
        getter = getattr(self, kind.row.getter)
        try:
            value = getter(*objs)
        except ValueError as exc:
            raise KeyError(f"{key.name}: {exc}") from None
        if kind is Form.DCM and key.index:
            if len(key.index) != 2:
                raise KeyError(f"{key}: use two indices")
            i, j = key.index
            return value[i - 1, j - 1]
        if key.index or key.primes:
            raise KeyError(f"{key}: not an element of {key.name}")
        return value


def _replace_loads(loads: list, where: Any, load: Any) -> None:
    """``Force_P> = v``: ``load`` takes the place of the loads on ``where``
    (at the first one's place, else at the end)."""
    at = [i for i, old in enumerate(loads) if old[0] is where]
    for i in reversed(at[1:]):
        del loads[i]
    if at:
        loads[at[0]] = load
    else:
        loads.append(load)


def _holds_inertia(body: Any, central: Any) -> bool:
    """Whether ``body.inertia = (central, body.masscenter)`` would leave a
    sympy ``RigidBody`` as it is: it holds that inertia about its mass
    center already, and its central inertia is that dyadic too (the same
    terms in the same order, each unit vector by its measure numbers and
    frame: a Vector's == is mathematical equality).

    sympy's setter keeps the pair and takes as the central inertia the
    dyadic less the inertia of a point mass at the pair's point, which is
    zero at the mass center whatever the mass: ``Dyadic(central.args)``,
    which is ``central`` itself when ``central`` is the body's central
    inertia (a ``Dyadic`` made by sympy's constructor, which forms it
    again unchanged).  A mass given later (``Mass C=MC`` after ``Inertia
    C, ...``) changes nothing."""
    if type(body).inertia is not RigidBody.inertia:
        return False
    held = body.inertia
    if not isinstance(held, Inertia) or held.point is not body.masscenter:
        return False
    return _same_terms(held.dyadic, central) and _same_terms(
        body.central_inertia, central
    )


def _same_terms(a: Dyadic, b: Dyadic) -> bool:
    """``a`` and ``b`` have the same terms in the same order, written alike."""
    if a is b:
        return True
    return len(a.args) == len(b.args) and all(
        x[0] == y[0] and x[1].args == y[1].args and x[2].args == y[2].args
        for x, y in zip(a.args, b.args, strict=True)
    )
