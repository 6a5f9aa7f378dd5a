"""Kinematics: part of :class:`al2py_runtime.model.model.Model`.

Positions (reversing and chaining), velocities and accelerations (given, formed or differentiated), orientations and angular velocities, and the two-point formulas (``V2pts``, ``A2pts``, ``V1pt``, ``A1pt``, deferred when a term is not known yet).
"""

from __future__ import annotations

from collections import deque
from typing import Any

import sympy as sp
from sympy.physics.vector import (
    Dyadic,
    Point,
    ReferenceFrame,
    Vector,
    time_derivative,
)

from .. import walks
from . import kinematics as kin
from .arrange import solve_speeds
from .state import ModelPart, command, t

__all__ = ["Kinematics"]


def _vector_sum(vectors: list[Vector]) -> Vector:
    """``Vector(0) + v1 + v2 + ...``, the same vector: sympy's sum of two
    vectors is a new vector of both's components, those in one frame
    added (the earlier matrix first), a component in a new frame appended,
    and then every component that is zero dropped; a component that is
    dropped and reappears is appended again.  Here the components are kept
    in one dictionary from step to step, and only those a step changed are
    tested for zero (sympy tests all of them at every step)."""
    found: dict = {}
    for v in vectors:
        for m, frame in v.args:
            found[frame] = found[frame] + m if frame in found else m
        for _, frame in v.args:
            if not found[frame] != walks.ZERO_MEASURES:
                del found[frame]
    return walks.vector([(m, frame) for frame, m in found.items()])


class Kinematics(ModelPart):
    """Positions (reversing and chaining), velocities and accelerations (given, formed or differentiated), orientations and angular velocities, and the two-point formulas (``V2pts``, ``A2pts``, ``V1pt``, ``A1pt``, deferred when a term is not known yet)."""

    # --------------------------------------------------------- positions

    def add_position(self, p: Point, q: Point, v: Vector) -> None:
        """Record ``P_P_Q> = v``: sympy's ``Q.set_pos(P, v)``, which keeps it
        both ways (``P_Q_P>`` is ``-v``), as an edge of the position chains
        :meth:`pos` follows."""
        q.set_pos(p, v)

    def _path(self, p: Point, q: Point) -> list[Point] | None:
        """Shortest chain of given positions from p to q (breadth first, in
        the order the positions were given: see docs/semantics.md,
        "Kinematics stored on the sympy objects")."""
        prev = {p: None}
        todo = deque([p])
        while todo:
            r = todo.popleft()
            if r is q:
                path = [r]
                while prev[path[-1]] is not None:
                    path.append(prev[path[-1]])
                return path[::-1]
            for s in r._pos_dict:
                if s not in prev:
                    prev[s] = r
                    todo.append(s)
        return None

    @command
    def pos(self, p: Point, q: Point) -> Vector:
        """``P_P_Q>``: position vector from ``p`` to ``q``."""
        if p is q:
            return Vector(0)
        path = self._path(p, q)
        if path is None:
            raise ValueError(f"P_{p.name}_{q.name}> is not defined")
        steps = zip(path, path[1:], strict=False)
        return _vector_sum([b._pos_dict[a] for a, b in steps])  # P_A_B>, as given

    # ------------------------------------------------------- resolution

    def actual_value(self, x: Any, keep: Any = ()) -> Any:
        """``x`` with every right-hand side substituted (except ``keep``)."""
        resolve = self.resolutions.resolver(keep)
        return walks.vmap(x, resolve)

    def _tidyv(self, v: Any) -> Any:
        """Light simplification of a result, skipped while AutoZ is ON (it is
        cosmetic, and large models are why AutoZ is on)."""
        return v if self.settings.autoz else self.tidier.vector(v)

    def _tidy(self, e: Any) -> Any:
        return e if self.settings.autoz else self.tidier(e)

    def auxiliary_kept(self) -> list:
        """The auxiliary speeds and their derivatives: what formed quantities
        keep as symbols although Constrain gave them values (they are needed
        for the partial velocities; docs/semantics.md, "AUXILIARY")."""
        aux = self.registry.auxiliary
        return [*aux, *(sp.Derivative(u, t) for u in aux)]

    def resolved_dt(self, v: Any, frame: ReferenceFrame) -> Any:
        """The time derivative of a scalar, vector or dyadic in ``frame``,
        taken after substituting every right-hand side (but the auxiliary
        speeds); under AutoZ its coefficients of the speeds are named."""
        # Everything is substituted except the auxiliary speeds: a velocity
        # formed after Constrain(AUXILIARY[U1]) must still depend on U1, as
        # one formed before it does (U1 is set to zero in the equations).
        keep = self.auxiliary_kept()
        v = self.actual_value(v, keep)
        book = self.script.book
        if isinstance(v, Dyadic):
            out = time_derivative(v, frame)
        elif isinstance(v, Vector):
            out = kin.frame_dt(v, frame, book.total_dt)
        else:
            out = book.total_dt(v)
        out = self.actual_value(out, keep)
        # Name the coefficients of the speeds and their derivatives (and the
        # rest), so later derivatives stay short (either AutoZ setting).
        speeds = self.generalized_speeds()
        xs = [*speeds, *(sp.Derivative(u, t) for u in speeds)]
        return kin.vmap(out, lambda e: book.name_linear(e, xs))

    # --------------------------------------------------------- velocities

    def _known_vel(self, p: Point, frame: ReferenceFrame) -> Vector | None:
        st = self.registry
        if (p, frame) in st.vel_given:
            return p.vel(frame)
        if (p, frame) in st.deferred_vel:
            return self._deferred("V", p, frame)
        if st.fixed_in.get(p) is frame:
            return Vector(0)
        return None

    @command
    def vel(self, p: Point, frame: ReferenceFrame) -> Vector:
        """``V_P_N>``: given, formed, or the derivative of a position from the
        nearest point whose velocity in ``frame`` is known."""
        known = self._known_vel(p, frame)
        if known is not None:
            return known
        seen = {p}
        todo = deque([p])
        while todo:
            r = todo.popleft()
            for s in r._pos_dict:
                if s in seen:
                    continue
                seen.add(s)
                v = self._known_vel(s, frame)
                if v is not None:
                    return self._tidyv(v + self.resolved_dt(self.pos(s, p), frame))
                todo.append(s)
        raise ValueError(f"V_{p.name}_{frame.name}> is not defined")

    @command
    def acc(self, p: Point, frame: ReferenceFrame) -> Vector:
        """``A_P_N>``: given, formed, or the derivative of ``V_P_N>``."""
        st = self.registry
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
        return self._tidyv(self.resolved_dt(v, frame))

    @command
    def ang_vel(self, b: ReferenceFrame, a: ReferenceFrame) -> Vector:
        """``W_B_A>``: given, or from the direction cosine matrices."""
        if a is b:
            return Vector(0)
        try:
            return kin.ang_vel_in(b, a)
        except ValueError:
            raise ValueError(f"W_{b.name}_{a.name}> is not defined") from None

    @command
    def ang_acc(self, b: ReferenceFrame, a: ReferenceFrame) -> Vector:
        """``ALF_B_A>``: given; else, where the script gave B's angular
        acceleration in another frame C (``ALF_B_C> = ...``), composed as
        Autolev does, ``ALF_C_A> + ALF_B_C> + W_C_A> x W_B_C>``; else the
        derivative of ``W_B_A>`` in ``a``."""
        return self._ang_acc(b, a, frozenset())

    def _ang_acc(self, b: ReferenceFrame, a: ReferenceFrame, seen: frozenset) -> Vector:
        if a is b:
            return Vector(0)
        st = self.registry
        if (b, a) in st.angacc:
            return st.angacc[(b, a)]
        for c, given in reversed(st.angacc_given.get(b, [])):
            if c is a or c in seen:
                continue
            try:
                w_ca, w_bc = self.ang_vel(c, a), self.ang_vel(b, c)
            except ValueError:
                continue
            inner = self._ang_acc(c, a, seen | {b})
            return self._tidyv(inner + given + kin.cross(w_ca, w_bc))
        return self._tidyv(self.resolved_dt(self.ang_vel(b, a), a))

    @command
    def dcm(self, a: ReferenceFrame, b: ReferenceFrame) -> sp.Matrix:
        """``A_B``: element [i,j] is Dot(Ai>, Bj>)."""
        try:
            m = a.dcm(b)
        except ValueError:
            raise ValueError(f"{a.name}_{b.name} is not defined") from None
        return sp.Matrix(m).applyfunc(self.tidier)

    # --------------------------------------------------- rotation commands

    def _orient(self, a: ReferenceFrame, b: ReferenceFrame, m: sp.Matrix) -> None:
        b.orient_explicit(a, m)
        self._name_dcms(b)

    def _name_dcms(self, b: ReferenceFrame) -> None:
        """Give ``b`` direction cosines to every frame connected to it,
        each entry named (the product along the tree of short matrices), in
        sympy's own cache, so that dot products, ``express`` and time
        derivatives work with short expressions."""
        book = self.script.book
        if len(b._dcm_dict) != 1:
            return
        (a,) = b._dcm_dict
        step = a._dcm_dict[b]  # a.dcm(b)
        finite = kin.finite_entries(step)  # (asked once of each product)
        seen = {a, b}
        todo = [a]
        while todo:
            f = todo.pop()
            for g in f._dcm_dict:
                if g in seen:
                    continue
                seen.add(g)
                todo.append(g)
                m = kin.named_product(g.dcm(a), step, book.name, finite_b=finite)
                g._dcm_cache[b] = m
                b._dcm_cache[g] = m.T

    @command
    def simprot(
        self, a: ReferenceFrame, b: ReferenceFrame, axis: Any, angle: Any, *, line=None
    ) -> sp.Matrix:
        """``Simprot(A, B, 3, Q)``: B rotated relative to A about A3 (= B3).

        The axis may also be a vector (``Simprot(N, A, N1>, X)``, or any
        direction): B is rotated by ``angle`` about it, right-handed."""
        axis = self.script.val(axis)
        if isinstance(axis, Vector):
            if axis == Vector(0):
                raise ValueError("Simprot: the axis vector is zero")
            m = kin.axis_dcm(axis.to_matrix(a), angle)
            # orient_explicit(a, m) without its angular velocity (sympy
            # differentiates the matrix, expands and trigsimps: minutes for
            # a musculoskeletal model's axes), which is set here instead
            b._dcm(a, m)
            b._var_dict.clear()
            rate = sp.diff(sp.sympify(angle), t)
            b.set_ang_vel(a, kin.vmap(axis.normalize(), lambda e: e * rate))
        else:
            m = kin.simprot_dcm(int(axis), angle)
            unit = (a.x, a.y, a.z)[abs(int(axis)) - 1]
            b.orient_axis(a, unit if int(axis) > 0 else -unit, angle)
        self._name_dcms(b)
        self.script.respond(f"{a.name}_{b.name}", m, line=line)
        return m

    @command
    def given_orientation(
        self, b: ReferenceFrame, a: ReferenceFrame, *, line=None
    ) -> sp.Matrix:
        """After ``B.orient_axis(A, ...)`` or ``B.orient_body_fixed(A, ...)``
        (``Simprot``, ``Dircos``): B's direction cosines to every connected
        frame are named (as :meth:`simprot` does) and Autolev's response
        ``A_B`` is recorded."""
        m = sp.Matrix(a.dcm(b))
        self._name_dcms(b)
        self.script.respond(f"{a.name}_{b.name}", m, line=line)
        return m

    @command
    def dircos(
        self, a: ReferenceFrame, b: ReferenceFrame, kind: str, *qs: Any, line=None
    ) -> sp.Matrix:
        """``Dircos(A, B, BODY123, Q1, Q2, Q3)`` (also SPACEijk, EULER with 4
        parameters, RODRIGUES): forms ``A_B``."""
        m = kin.rotation_dcm(kind, list(qs))
        kind = kind.upper()
        self._note_unit_norm(kind, qs)
        if kind.startswith("BODY"):
            b.orient_body_fixed(a, tuple(qs), kind[4:])
        elif kind.startswith("SPACE"):
            b.orient_space_fixed(a, tuple(qs), kind[5:])
        else:
            self._orient(a, b, m)
        self._name_dcms(b)
        self.script.respond(f"{a.name}_{b.name}", m, line=line)
        return m

    def _note_unit_norm(self, kind: str, qs: tuple) -> None:
        """Euler parameters have unit norm (for ``al2py check``'s points)."""
        if kind.upper() == "EULER" and len(qs) == 4:
            if tuple(qs) not in self.unit_norms:
                self.unit_norms.append(tuple(qs))

    def _dcm_angvel(self, a, b, kind, qs) -> list:
        """B measure numbers of the angular velocity implied by the
        orientation (sympy's closed forms for Euler angles)."""
        self._note_unit_norm(kind, qs)
        kind = kind.upper()
        if kind.startswith(("BODY", "SPACE")) and len(qs) == 3:
            pa, pb = ReferenceFrame("_PA"), ReferenceFrame("_PB")
            if kind.startswith("BODY"):
                pb.orient_body_fixed(pa, tuple(qs), kind[4:])
            else:
                pb.orient_space_fixed(pa, tuple(qs), kind[5:])
            w = pb.ang_vel_in(pa)
            return [kin.simplify_small(w.dot(e)) for e in (pb.x, pb.y, pb.z)]
        if kind == "EULER" and len(qs) == 4:
            return kin.euler_parameter_angvel(list(qs))
        m = kin.rotation_dcm(kind, list(qs))
        return kin.angvel_from_dcm(m)

    @command
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
            w = self.with_kindiffs(self.ang_vel(b, a))
            self.script.respond(f"W_{b.name}_{a.name}>", w, line=line)
            return w
        w = self.with_kindiffs(kin.frame_vector(b, self._dcm_angvel(a, b, kind, qs)))
        b.set_ang_vel(a, w)
        self.script.respond(f"W_{b.name}_{a.name}>", w, line=line)
        return w

    @command
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
            given = self.actual_value(kin.ang_vel_in(b, a))
        except ValueError:
            pass
        qdots = [sp.Derivative(q, t) for q in qs]
        if given is not None and not any(given.to_matrix(b).has(d) for d in qdots):
            w = [self._tidy(given.dot(e)) for e in (b.x, b.y, b.z)]
        else:
            speeds = self.generalized_speeds()
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
            r = r if self.settings.autoz else kin.simplify_small(r)
            out.append(self.script.assign(self.script.name_of(q) + "'", r, line=line))
        return tuple(out)

    # ------------------------------------------------- velocity formulas

    def _v2pts(self, n, a, o, p) -> Vector:
        v = self.vel(o, n) + kin.cross(self.ang_vel(a, n), self.pos(o, p))
        return self._tidyv(v)

    def _a2pts(self, n, a, o, p) -> Vector:
        w = self.ang_vel(a, n)
        r = self.pos(o, p)
        v = _vector_sum(
            [
                self.acc(o, n),
                kin.cross(self.ang_acc(a, n), r),
                kin.cross(w, kin.cross(w, r)),
            ]
        )
        return self._tidyv(v)

    def _deferred(self, which: str, p: Point, n: ReferenceFrame) -> Vector:
        """A velocity/acceleration stated by ``V2pts``/``A2pts`` before the
        other point's was known: formed now (an error if it still is not)."""
        st = self.registry
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
            st = self.registry
            table = st.deferred_vel if which == "V" else st.deferred_acc
            table[(p, n)] = (a, o)
            if which == "V":
                st.vel_given.pop((p, n), None)
                p._vel_dict.pop(n, None)  # sympy has no unset
            else:
                st.acc.pop((p, n), None)
            return None
        return self._set_formed(which, p, n, v, line)

    @command
    def v2pts(self, n, a, o, p, *, line=None) -> Vector | None:
        """``V2pts(N, A, O, P)``: O and P fixed on A;
        ``V_P_N> = V_O_N> + Cross(W_A_N>, P_O_P>)``.  If a term is not
        known yet (``V_O_N>``...) the relation is kept (no response) and
        used when ``V_P_N>`` is needed."""
        return self._two_points("V", n, a, o, p, line)

    @command
    def a2pts(self, n, a, o, p, *, line=None) -> Vector | None:
        """``A2pts(N, A, O, P)``: O and P fixed on A (deferred as V2pts)."""
        return self._two_points("A", n, a, o, p, line)

    @command
    def v1pt(self, n, a, o, p, *, line=None) -> Vector:
        """``V1pt(N, A, O, P)``: O fixed on A, P moving on A."""
        r = self.pos(o, p)
        vpa = p.vel(a) if (p, a) in self.registry.vel_given else None
        if vpa is None:
            vpa = self.resolved_dt(r, a)
        v = self.vel(o, n) + vpa + kin.cross(self.ang_vel(a, n), r)
        return self._set_formed("V", p, n, self._tidyv(v), line)

    @command
    def a1pt(self, n, a, o, p, *, line=None) -> Vector:
        """``A1pt(N, A, O, P)``: O fixed on A, P moving on A."""
        st = self.registry
        r = self.pos(o, p)
        vpa = p.vel(a) if (p, a) in st.vel_given else None
        if vpa is None:
            vpa = self.resolved_dt(r, a)
        apa = st.acc.get((p, a))
        if apa is None:
            apa = self.resolved_dt(vpa, a)
        w = self.ang_vel(a, n)
        v = (
            self.acc(o, n)
            + apa
            + 2 * kin.cross(w, vpa)
            + kin.cross(self.ang_acc(a, n), r)
            + kin.cross(w, kin.cross(w, r))
        )
        return self._set_formed("A", p, n, self._tidyv(v), line)

    @command
    def formed_vel(self, p: Point, n: ReferenceFrame, *, line=None) -> Vector:
        """After ``P.v2pt_theory(O, N, A)`` (``V2pts(N, A, O, P)``, with
        ``V_O_N>``, ``W_A_N>`` and ``P_O_P>`` known): sympy's velocity as
        Autolev keeps it (the kinematical differential equations applied,
        lightly simplified) and its response."""
        st = self.registry
        st.deferred_vel.pop((p, n), None)
        return self._set_formed("V", p, n, self._tidyv(p.vel(n)), line)

    def keep_given(self, which: str, p: Point, n: ReferenceFrame, v: Vector) -> None:
        """``V_P_N> = v`` (``which`` is ``"V"``) or ``A_P_N> = v`` (``"A"``),
        given or formed: a velocity is stored on the sympy point
        (``P.set_vel(N, v)``) and marked as Autolev's own; an acceleration is
        kept by the model (see :class:`~.state.ModelState`)."""
        st = self.registry
        if which == "V":
            p.set_vel(n, v)
            st.vel_given[(p, n)] = None
        else:
            st.acc[(p, n)] = v

    def _set_formed(self, which, p, n, v, line) -> Vector:
        v = self.with_kindiffs(v)
        self.keep_given(which, p, n, v)
        self.script.respond(f"{which}_{p.name}_{n.name}>", v, line=line)
        return v
