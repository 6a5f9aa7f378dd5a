"""The script's model as sympy's ``KanesMethod``.

:class:`KaneInputs` is what ``KanesMethod`` takes -- the Newtonian frame,
coordinates, speeds, kinematical differential equations, bodies, loads and
motion constraints -- built from an Autolev script by
``Workspace.kane_inputs()``.  :func:`kanes_method` returns a ``KanesMethod``
whose equations the runtime's engine,
:class:`~al2py_runtime.model.fastkane.FastKane`, derives from these inputs,
written out as plain expressions (sympy's own ``kanes_equations`` derivation
is not used).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import KanesMethod, RigidBody
from sympy.physics.vector import Dyadic, ReferenceFrame, Vector, dynamicsymbols

from . import kinematics as kin
from .fastkane import FastKane

t = dynamicsymbols._t

__all__ = ["KaneInputs", "kane_inputs", "kanes_method"]


@dataclass
class KaneInputs:
    """Everything ``KanesMethod`` needs, as sympy objects.

    ``bodies`` are ``RigidBody``/``Particle`` objects whose mass centers know
    their velocities and accelerations in ``frame``; ``loads`` are
    ``(Point, Vector)`` forces and ``(ReferenceFrame, Vector)`` torques.
    ``speed_names`` maps each speed to its Autolev spelling (a speed that is a
    coordinate's derivative, ``Q1'``, is a new function ``Q1_U``)."""

    frame: ReferenceFrame
    q_ind: list[Any]
    u_ind: list[Any]
    kd_eqs: list[Any]
    bodies: list[Any]
    loads: list[tuple[Any, Any]]
    u_dependent: list[Any] = field(default_factory=list)
    velocity_constraints: list[Any] = field(default_factory=list)
    u_auxiliary: list[Any] = field(default_factory=list)
    speed_names: dict[Any, str] = field(default_factory=dict)

    @property
    def q(self) -> list[Any]:
        return list(self.q_ind)

    @property
    def u(self) -> list[Any]:
        return [*self.u_ind, *self.u_dependent]


class _DerivedKanesMethod(KanesMethod):
    """sympy's ``KanesMethod`` whose Kane's equations are derived by the
    runtime's engine, :class:`~al2py_runtime.model.fastkane.FastKane`.

    The constructor is ``KanesMethod``'s own (the kinematical differential
    equations and the velocity constraints solved for ``q'`` and the
    dependent speeds).  :meth:`kanes_equations` derives with FastKane and
    stores the results, intermediates written out, where ``KanesMethod``'s
    properties and ``to_linearizer()`` read them: ``mass_matrix``,
    ``forcing``, ``mass_matrix_full``, ``forcing_full``, ``auxiliary_eqs``,
    ``rhs()`` and ``linearize()`` are then those of ``KanesMethod``."""

    def __init__(self, inputs: KaneInputs) -> None:
        kw: dict[str, Any] = {}
        if inputs.u_dependent:
            kw["u_dependent"] = inputs.u_dependent
            kw["velocity_constraints"] = inputs.velocity_constraints
            # Stand-ins: kanes_equations stores FastKane's acceleration
            # constraints (sympy would differentiate the velocity
            # constraints here, the larger part of its whole derivation).
            kw["acceleration_constraints"] = [u.diff(t) for u in inputs.u_dependent]
        if inputs.u_auxiliary:
            kw["u_auxiliary"] = inputs.u_auxiliary
        super().__init__(
            inputs.frame,
            q_ind=inputs.q_ind,
            u_ind=inputs.u_ind,
            kd_eqs=inputs.kd_eqs,
            **kw,
        )
        self._derive_from = inputs

    def kanes_equations(self, bodies: Any = None, loads: Any = None) -> Any:
        """``(Fr, Fr*)`` as ``KanesMethod.kanes_equations`` returns them (with
        auxiliary speeds, their rows follow), derived by FastKane."""
        bodies = list(self.bodies if bodies is None else bodies)
        if loads is None:
            loads = self.loads
        loads = list(loads or [])
        _constant_masses(bodies)
        fk = _engine(self._derive_from)
        aux = bool(self._derive_from.u_auxiliary)
        if aux:
            # Fr's auxiliary rows alone: the same engine without bodies
            # (velocities and intermediates are shared with the next call).
            fk.kanes_equations([], loads)
            fr_aux = fk.auxiliary_eqs
        fr, frstar = fk.kanes_equations(bodies, loads)
        p = fr.rows
        mass, forcing, fr, frstar = _written_out(
            fk, [fk.mass_matrix, fk.forcing, fr, frstar]
        )
        self._bodylist, self._forcelist = bodies, loads or None
        self._k_d, self._f_d = mass[:p, :], -forcing[:p, :]
        self._k_dnh, self._f_dnh = mass[p:, :], -forcing[p:, :]
        if aux:
            fr_aux, eqs = _written_out(fk, [fr_aux, fk.auxiliary_eqs])
            self._aux_eq = eqs
            fr, frstar = fr.col_join(fr_aux), frstar.col_join(eqs - fr_aux)
        self._fr, self._frstar = fr, frstar
        return fr, frstar


def _engine(inputs: KaneInputs) -> FastKane:
    """FastKane with the inputs' kinematics and constraints (no bodies)."""
    return FastKane(
        inputs.frame,
        inputs.q_ind,
        inputs.u_ind,
        kd_eqs=inputs.kd_eqs,
        u_dependent=inputs.u_dependent or None,
        velocity_constraints=inputs.velocity_constraints or None,
        u_auxiliary=inputs.u_auxiliary or None,
    )


def _written_out(fk: FastKane, parts: list[Any]) -> list[Any]:
    """The matrices ``parts`` with FastKane's intermediates written out (one
    substitution for all)."""
    flat = fk.substitute(sp.Matrix([x for m in parts for x in m]))
    out, start = [], 0
    for m in parts:
        out.append(sp.Matrix(m.rows, m.cols, list(flat[start : start + len(m)])))
        start += len(m)
    return out


def _constant_masses(bodies: list) -> None:
    """FastKane takes constant masses and inertias: name a body whose mass
    or inertia varies in time (the runtime's FrStar, as Autolev's, is
    ``-m a``; sympy's derivation would add ``-m' v``, another model)."""
    for body in bodies:
        what = [("mass", body.mass)]
        if isinstance(body, RigidBody):
            what.append(("inertia", body.central_inertia.to_matrix(body.frame)))
        for kind, value in what:
            value = sp.sympify(value)
            if value.has(t):
                names = sorted(
                    {f.func.__name__ for f in value.atoms(AppliedUndef)}, key=str
                )
                why = ""
                if names:
                    many = len(names) > 1
                    why = (
                        f": {', '.join(names)} {'are' if many else 'is a'}"
                        f" function{'s' if many else ''} of time (declared with"
                        " Variables or Specified); declare a parameter with"
                        " Constants"
                    )
                raise ValueError(
                    f"kanes_method(): the {kind} of {body.name} varies in time"
                    f" ({value}){why}; the exported model takes constant masses"
                    " and inertias"
                )


def kanes_method(inputs: KaneInputs) -> KanesMethod:
    """A ``KanesMethod`` with its equations formed (``mass_matrix_full``,
    ``forcing_full``, ``fr``, ``frstar``) by the runtime's engine, FastKane,
    and written out (plain expressions of the coordinates, speeds and
    constants, as sympy's own derivation gives)."""
    km = _DerivedKanesMethod(inputs)
    km.kanes_equations(inputs.bodies, inputs.loads)
    return km


def _plain_dcms(frames: list, book: Any) -> None:
    """Write out the AutoZ intermediates in the frames' cached direction
    cosines (sympy's own operations on the frames then give plain
    expressions)."""
    for f in frames:
        for other, m in list(f._dcm_cache.items()):
            if any(isinstance(e, sp.Basic) and e.atoms(book.Z) for e in m):
                f._dcm_cache[other] = book.expand(m)


def kane_inputs(model: Any) -> KaneInputs:
    """A script's model (``al.model``, see :class:`~al2py_runtime.model.model.Model`) as
    :class:`KaneInputs`: the one place where the script becomes
    ``KanesMethod``'s inputs.

    Velocities, accelerations, masses, inertias and loads are the actual
    ones, with every right-hand side substituted except the speeds; the
    sympy points and frames of the script are given these velocities
    (``mod.Q.vel(mod.N)`` is ``V_Q_N>``)."""
    n = model.newtonian_frame()
    st = model.registry
    if st.gyrostat:
        raise ValueError(
            "kanes_method(): Gyrostat(FRSTAR, ...) terms have no sympy"
            " RigidBody; the model would miss the rotor"
        )
    speeds = model.generalized_speeds()
    if not speeds:
        raise ValueError(
            "kanes_method(): there are no generalized speeds; declare them"
            " with Variables U{n}' or MotionVariables'"
        )
    # Speeds that are derivatives (MotionVariables' Q'') become functions.
    swap: dict = {}
    names: dict = {}
    for u in speeds:
        if isinstance(u, sp.Derivative):
            q = u.expr
            new = dynamicsymbols(f"{model.script.name_of(q)}_U", real=True)
            swap[sp.Derivative(q, (t, 2))] = sp.Derivative(new, t)
            swap[u] = new
            names[new] = model.script.name_of(u)
        else:
            names[u] = model.script.name_of(u)

    # Constraint forces solved by Kane(F1, F2) stay unknowns: their
    # right-hand sides hold the accelerations.
    keep = [*speeds, *(st.kane["forces"] if st.kane else ())]

    # sympy's KanesMethod (and PyDy, Linearizer) take plain expressions: the
    # AutoZ intermediates are written out.
    book = model.script.book_if_made()
    if book is not None:
        _plain_dcms(list(st.frames.values()) + [n], book)

    def fix(x: Any) -> Any:
        x = model.actual_value(x, keep)
        if book is not None:
            x = book.expand(x)
        return kin.vmap(x, lambda e: sp.sympify(e).xreplace(swap)) if swap else x

    # Autolev's AUXILIARY speeds that the constraints make zero are sympy's
    # auxiliary speeds; the others (tutor7c's U2, U3) are dependent speeds.
    zero_aux = [
        u for u in st.auxiliary if model.script.resolve(model.table.rhs.get(u, u)) == 0
    ]
    solved = [u for u in speeds if u in st.dependent or u in st.auxiliary]
    solved = [u for u in solved if u not in zero_aux]
    us = [swap.get(u, u) for u in speeds]
    dep = [swap.get(u, u) for u in solved]
    aux = [swap.get(u, u) for u in zero_aux]
    ind = [u for u in us if u not in dep and u not in aux]
    coords = model.coordinates_of(speeds)
    q_ind = [q for q, _rhs in coords]
    kd_eqs = [sp.Derivative(q, t) - fix(rhs) for q, rhs in coords]
    for u, new in swap.items():
        if isinstance(u, sp.Derivative) and u.derivative_count == 1:
            q_ind.append(u.expr)
            kd_eqs.append(u - new)
    constraints = [swap.get(u, u) - fix(model.table.rhs[u]) for u in solved]
    bodies = []
    for o in st.massive:
        m = fix(model.body_mass(o, strict=False))
        p = model.mass_center(o)
        # Accelerations are the velocities' derivatives with every speed
        # kept (an Autolev A2pts result has dependent speeds' derivatives
        # substituted, which KanesMethod's constraints would count twice).
        v = fix(model.vel(p, n))
        p.set_vel(n, v)
        p.set_acc(n, v.dt(n))
        if isinstance(o, ReferenceFrame):
            w = fix(model.ang_vel(o, n))
            o.set_ang_vel(n, w)
            o.set_ang_acc(n, w.dt(o))
            inertia = fix(model.central_inertia(o))
            if inertia == 0:
                inertia = Dyadic(0)
            body = st.sympy_bodies[o]  # the module's RigidBody, actual values
            body.mass, body.inertia = m, (inertia, p)
        else:
            body = st.sympy_bodies[o]
            body.mass = m
        bodies.append(body)
    # Loads are values of the actual motion, where the auxiliary speeds are
    # zero (a force formed after Constrain, tutor6f's damping through
    # STRETCH', keeps them as symbols; KanesMethod zeroes them only in the
    # inertia forces).
    zero = {sp.Derivative(u, t): 0 for u in aux} | dict.fromkeys(aux, 0)

    def actual(x: Any) -> Any:
        return kin.vmap(fix(x), lambda e: sp.sympify(e).xreplace(zero))

    loads = []
    for p, f in st.forces.items():
        if f != Vector(0):
            p.set_vel(n, fix(model.vel(p, n)))
            loads.append((p, actual(f)))
    for b, tq in st.torques.items():
        if tq != Vector(0):
            b.set_ang_vel(n, fix(model.ang_vel(b, n)))
            loads.append((b, actual(tq)))
    return KaneInputs(
        frame=n,
        q_ind=q_ind,
        u_ind=ind,
        kd_eqs=kd_eqs,
        bodies=bodies,
        loads=loads,
        u_dependent=dep,
        velocity_constraints=constraints,
        u_auxiliary=aux,
        speed_names=names,
    )
