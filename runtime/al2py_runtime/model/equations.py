"""KaneEquations: part of :class:`al2py_runtime.model.model.Model`.

``Fr()``, ``FrStar()``, ``Constrain``, ``Kane()`` and the sympy ``KanesMethod`` of the model.
"""

from __future__ import annotations

import cmath
from typing import Any

import sympy as sp
from sympy.physics.vector import (
    ReferenceFrame,
    Vector,
)

from ..intermediates.elimination import SMALL
from . import kinematics as kin
from .arrange import arrange, solve_speeds
from .fastkane import (
    Motion,
    Splits,
    active_rows,
    form_rate,
    inertia_rows,
    linear_form,
    measure_split,
    named_measures,
    times,
)
from .state import ModelPart, command, query, t

__all__ = ["KaneEquations"]


def _same(expr: Any) -> Any:
    return expr


class KaneEquations(ModelPart):
    """``Fr()``, ``FrStar()``, ``Constrain``, ``Kane()`` and the sympy ``KanesMethod`` of the model."""

    # -------------------------------------------------- Fr and Fr*

    def _splits_of(self, book: Any) -> Splits:
        """The model's :class:`~.fastkane.Splits` of ``book`` (the
        script's): what :func:`~.fastkane.measure_split` formed with it."""
        memo = self.registry.splits
        if memo is None or memo.book is not book:
            memo = self.registry.splits = Splits(book)
        return memo

    def _zpartials(
        self, v: Vector, speeds: list, frame: ReferenceFrame, book: Any
    ) -> list[list[Any]]:
        """The partial velocities of ``v`` by ``speeds``: for each speed, the
        three named measure numbers in ``frame``."""
        keep = speeds + [sp.Derivative(u, t) for u in speeds]
        v = self.actual_value(v, keep)
        if v == Vector(0):
            return [[sp.S.Zero] * 3 for _ in speeds]
        split = measure_split(v, frame, speeds, book, memo=self._splits_of(book))
        if split is not None:
            return [[s[0][j] for s in split] for j in range(len(speeds))]
        measures = [book.name_linear(e, speeds) for e in v.to_matrix(frame)]
        return [[book.name(sp.diff(e, u)) for e in measures] for u in speeds]

    @command
    def fr(self) -> sp.Matrix:
        """``Fr()``: generalized active forces (one row per independent or
        auxiliary speed; dependent speeds are eliminated)."""
        n = self.newtonian_frame()
        st = self.registry
        speeds = self.fix_fr_speeds("Fr()")
        rows = [sp.Integer(0)] * len(speeds)
        book = self.script.intermediates
        loads = [(f, self.vel(p, n), n) for p, f in st.forces.items()]
        loads += [(tq, self.ang_vel(b, n), b) for b, tq in st.torques.items()]
        moved = False  # a loaded velocity depends on a speed
        for f, v, frame in loads:
            if f == Vector(0):
                continue
            if book is None:
                # vectors dotted as sympy does: the script's names and form
                # kept, as Autolev printed Fr() with AutoZ OFF
                parts = [
                    None if p == Vector(0) else p
                    for p in self.partial_velocities(v, speeds)
                ]
                moved = moved or any(p is not None for p in parts)
                dots = active_rows(
                    [(parts, f)],
                    len(speeds),
                    _same,
                    dot=lambda p, g: kin.exact_dot(g, p),
                )
            else:
                # Specified quantities stay names, as without AutoZ (Solve)
                keep = self.script.specified_inputs([])
                mf = named_measures(
                    self.actual_value(f, keep), frame, book, memo=self._splits_of(book)
                )
                parts = self._zpartials(v, speeds, frame, book)
                moved = moved or any(x != 0 for p in parts for x in p)
                dots = active_rows([(parts, mf)], len(speeds), book.name)
            rows = [r + d for r, d in zip(rows, dots, strict=True)]
        if not moved and not self._moves_with(speeds):
            names = ", ".join(self.script.name_of(u) for u in speeds)
            one = len(speeds) == 1
            raise ValueError(
                "Fr(): no velocity or angular velocity depends on the generalized"
                f" speed{'' if one else 's'} {names}, so every generalized active"
                " force would be 0; is a kinematical differential equation"
                " (Q' = ...) missing, or is a velocity written with a speed's"
                f" derivative ({names.split(', ')[0]}') instead of the speed?"
            )
        return sp.Matrix(rows)

    def _moves_with(self, speeds: list) -> bool:
        """Whether the velocity or angular velocity of a loaded or massive
        object depends on any of ``speeds`` (else ``Fr()`` is an error, as
        :meth:`frstar` is for each speed no velocity depends on)."""
        n = self.newtonian_frame()
        st = self.registry
        getters: list[Any] = [lambda p=p: self.vel(p, n) for p in st.forces]
        getters += [lambda b=b: self.ang_vel(b, n) for b in st.torques]
        for o in st.massive:
            getters.append(lambda o=o: self.vel(self.mass_center(o), n))
            if isinstance(o, ReferenceFrame):
                getters.append(lambda o=o: self.ang_vel(o, n))
        for get in getters:
            try:
                v = get()
            except ValueError:  # no velocity defined: it moves with no speed
                continue
            if any(p != Vector(0) for p in self.partial_velocities(v, speeds)):
                return True
        return False

    def _inertia_torque(self, b: ReferenceFrame, n: ReferenceFrame) -> Vector:
        inertia = self.central_inertia(b)
        w = self.actual_value(self.ang_vel(b, n))
        alf = self.actual_value(self.ang_acc(b, n))
        return -((inertia & alf) + kin.cross(w, inertia & w))

    # Accelerations from the velocities' linear forms (issue 21/22): with
    # v = sum c_j u_j + r (c_j, r named, measure numbers in one frame),
    # a = sum c_j u_j' + sum c_j' u_j + r', where each derivative is of a
    # short named quantity.  The result has short measure numbers, so Fr*
    # never splits a large acceleration.

    def _linear_form(self, vec: Vector, frame: ReferenceFrame, book: Any) -> Any:
        """``vec`` (a velocity or angular velocity, the auxiliary speeds
        kept) as the engine's :func:`~.fastkane.linear_form` in the
        generalized speeds."""
        v = self.actual_value(vec, self.auxiliary_kept())
        return linear_form(
            v, frame, self.generalized_speeds(), book, memo=self._splits_of(book)
        )

    def _rate(
        self, form: Any, frame: ReferenceFrame, book: Any, rates: tuple
    ) -> Vector:
        """The derivative in ``frame`` of a vector given by its linear form
        (:meth:`_linear_form`), by the engine's :func:`~.fastkane.form_rate`."""
        rate, memo = rates
        columns, _ = form
        speeds = self.generalized_speeds()
        rest = form_rate(form, speeds, book, rate, memo)
        out = [
            sp.Add(
                r,
                *[
                    times(col[i], sp.Derivative(u, t))
                    for col, u in zip(columns, speeds, strict=True)
                    if col[i] != 0
                ],
            )
            for i, r in enumerate(rest)
        ]
        return kin.frame_vector(frame, out)

    def _acceleration(
        self, p: Any, n: ReferenceFrame, form: Any, book: Any, rates: tuple
    ) -> Vector:
        """``A_P_N>`` for Fr*: from ``V_P_N>``'s linear form when that is
        the script's acceleration (checked at two random points), else the
        script's."""
        st = self.registry
        if form is None:
            return self.acc(p, n)
        fast = self._rate(form, n, book, rates)
        given = (p, n) in st.acc or (p, n) in st.deferred_acc
        if given and not self._same_vector(self.acc(p, n), fast, n, book):
            return self.acc(p, n)
        return fast

    def _angular_acceleration(
        self, b: ReferenceFrame, n: ReferenceFrame, form: Any, book: Any, rates: tuple
    ) -> Vector:
        """``ALF_B_N>`` for Fr*, as :meth:`_acceleration`."""
        st = self.registry
        if form is None:
            return self.ang_acc(b, n)
        fast = self._rate(form, b, book, rates)
        given = (b, n) in st.angacc or bool(st.angacc_given.get(b))
        if given and not self._same_vector(self.ang_acc(b, n), fast, b, book):
            return self.ang_acc(b, n)
        return fast

    def _time_rates(self, book: Any) -> tuple[Any, dict]:
        """The derivative of each variable (``Q'`` by its kinematical
        equation, the auxiliary speeds' kept), and the memo of
        ``book.time_derivative`` for these rates: made once per ``FrStar()``."""
        keep = self.auxiliary_kept()
        speeds = self.generalized_speeds()
        xs = [*speeds, *(sp.Derivative(u, t) for u in speeds)]
        cache: dict = {}

        def rate(x: Any) -> Any:
            found = cache.get(x)
            if found is None:
                d = sp.Derivative(x, t)
                if isinstance(x, sp.Derivative):
                    d = sp.Derivative(x.expr, (t, x.derivative_count + 1))
                found = book.name_linear(self.actual_value(d, keep), xs)
                cache[x] = found
            return found

        return rate, {}

    def _same_vector(
        self, a: Vector, b: Vector, frame: ReferenceFrame, book: Any
    ) -> bool:
        """Whether two vectors are equal at two random points (the speeds'
        derivatives random too), evaluated numerically term by term rather
        than by expressing either in ``frame``; False where a value cannot be
        formed."""
        parts = [self.actual_value(a).args, self.actual_value(b).args]
        scalars: list[Any] = []
        for args in parts:
            for comps, f in args:
                scalars += [*frame.dcm(f), *comps]
        for point in (1, 2):
            try:
                values = iter(book.values_at(scalars, point))
            except (ValueError, TypeError, ZeroDivisionError, OverflowError):
                return False
            sums = []
            for args in parts:
                out = [0j, 0j, 0j]
                for _ in args:
                    dcm = [next(values) for _ in range(9)]
                    vec = [next(values) for _ in range(3)]
                    for i in range(3):
                        out[i] += sum(dcm[3 * i + j] * vec[j] for j in range(3))
                sums.append(out)
            x, y = sums
            scale = max(1.0, *(abs(v) for v in x), *(abs(v) for v in y))
            if (
                not all(cmath.isfinite(v) for v in x)
                or max(abs(a - b) for a, b in zip(x, y, strict=True)) > 1e-9 * scale
            ):
                return False
        return True

    @command
    def tstar(self, b: ReferenceFrame, n: ReferenceFrame | None = None) -> Vector:
        """``TStar(B, N)``: inertia torque of body B in N."""
        return self.tidier.vector(self._inertia_torque(b, n or self.newtonian_frame()))

    @command
    def frstar(self) -> sp.Matrix:
        """``FrStar()``: generalized inertia forces (rows as :meth:`fr`).

        As sympy's KanesMethod does, accelerations are split into
        ``rest + sum(coef_k * Uk')`` before they are dotted with the partial
        velocities, so each row is built already arranged in the speeds'
        derivatives (large models never differentiate whole rows)."""
        n = self.newtonian_frame()
        st = self.registry
        speeds = self.fix_fr_speeds("FrStar()")
        accels = [sp.Derivative(u, t) for u in self.generalized_speeds()]

        # Both AutoZ settings derive over intermediates (issue 21).
        book = self.script.book
        rates = self._time_rates(book)

        index = {u: k for k, u in enumerate(self.generalized_speeds())}

        def motion(v: Vector, form: Any, acc: Vector, frame: ReferenceFrame) -> Motion:
            split = measure_split(acc, frame, accels, book, memo=self._splits_of(book))
            if split is None:  # pragma: no cover - linear in u'
                raise ValueError("FrStar(): an acceleration is not linear in U'")
            columns = [[s[0][j] for s in split] for j in range(len(accels))]
            if form is None:
                parts = self._zpartials(v, speeds, frame, book)
            else:
                parts = [form[0][index[u]] for u in speeds]
            return Motion(
                partials=[p if any(x != 0 for x in p) else None for p in parts],
                rates=[c if any(x != 0 for x in c) else None for c in columns],
                rest=[s[1] for s in split],
            )

        translations, rotations = [], []
        for o in st.massive:
            m = self.body_mass(o, strict=False)
            p = self.mass_center(o)
            if m != 0:
                try:
                    v = self.vel(p, n)
                except ValueError:  # at rest, with A_P_N> = 0 (tutor9's Ao)
                    v, form = None, None
                else:
                    form = self._linear_form(v, n, book)
                a = self.actual_value(self._acceleration(p, n, form, book, rates))
                if a != Vector(0):
                    v = self.vel(p, n) if v is None else v
                    translations.append((m, motion(v, form, a, n)))
            if (
                isinstance(o, ReferenceFrame)
                and self.body_record(o).inertia is not None
            ):
                w = self.ang_vel(o, n)
                form = self._linear_form(w, o, book)
                alf = self._angular_acceleration(o, n, form, book, rates)
                alf = self.actual_value(alf)
                inertia = kin.dyadic_matrix(self.central_inertia(o), o)
                imat = [[book.name(inertia[i, j]) for j in range(3)] for i in range(3)]
                omega = named_measures(
                    self.actual_value(w), o, book, memo=self._splits_of(book)
                )
                rotations.append((imat, omega, motion(w, form, alf, o)))
        moved = [
            any(mo.partials[k] is not None for _, mo in translations)
            or any(mo.partials[k] is not None for _, _, mo in rotations)
            for k in range(len(speeds))
        ]
        if st.massive and not all(moved):
            raise ValueError(self._unmoved(speeds, moved))
        mm, non = inertia_rows(
            translations, rotations, len(speeds), len(accels), book.name
        )
        return sp.Matrix(
            [
                sp.Add(
                    -book.name(rest),
                    *[-book.name(c) * a for c, a in zip(row, accels, strict=True)],
                )
                for row, rest in zip(mm, non, strict=True)
            ]
        )

    def _unmoved(self, speeds: list, moved: list) -> str:
        """The error for speeds that no velocity of a massive object depends
        on.  An auxiliary speed has no kinematical equation to forget: it is
        missing from the velocities that should carry it."""
        still = [u for u, m in zip(speeds, moved, strict=True) if not m]
        aux = [self.script.name_of(u) for u in still if u in self.registry.auxiliary]
        other = [
            self.script.name_of(u) for u in still if u not in self.registry.auxiliary
        ]
        head = "FrStar(): no velocity or angular velocity of a massive object"
        parts = []
        if other:
            parts.append(
                f"{head} depends on the generalized speed {', '.join(other)}; is"
                " a kinematical differential equation (Q' = ...) missing?"
            )
        if aux:
            n = self.newtonian_frame().name
            one = len(aux) == 1
            parts.append(
                f"{head} depends on the auxiliary speed{'' if one else 's'}"
                f" {', '.join(aux)}; give {'it' if one else 'them'} to the"
                " velocity of the point where the constraint force acts"
                f" (V_P_{n}> = ... + {aux[0]}*{n}1>) and form the massive"
                " objects' velocities from it (V2pts, or Dt of their positions)"
            )
        return "; ".join(parts)

    # ------------------------------------------------------ Constrain

    @command
    def constrain(self, which: str, speeds: Any, *, line: int | None = None) -> tuple:
        """``Constrain(DEPENDENT[U2, U3])`` or ``Constrain(AUXILIARY[...])``.

        Solves the equations ``DEPENDENT = 0`` (or ``AUXILIARY``) for the named
        speeds and assigns them; their derivatives too when declared (always
        kept for :meth:`kane`).  Dependent speeds get no row in Fr/Fr*;
        auxiliary speeds keep theirs (see :meth:`kane`)."""
        which = which.upper()
        if which not in ("DEPENDENT", "AUXILIARY"):
            raise ValueError("Constrain takes DEPENDENT[...] or AUXILIARY[...]")
        st = self.registry
        mat = self.table.stored.get(which)
        if not isinstance(mat, sp.MatrixBase):
            raise ValueError(f"Constrain: {which} has not been assigned")
        speeds = [sp.sympify(u) for u in speeds]
        eqs = [self.script.resolve(e, keep=self.generalized_speeds()) for e in mat]
        book = self.script.solver_book(len(speeds))
        if book is None:  # a closed form reads the equations' form
            eqs = [self.script.form(e) for e in eqs]
        sols = solve_speeds(eqs, speeds, book, self.configuration_variables())
        gens = self.rates_and_speeds()
        out = []
        for u, s in zip(speeds, sols, strict=True):
            out.append(self.script.assign(self.script.name_of(u), s, line=line))
        for u, s in zip(speeds, sols, strict=True):
            ds = self.resolved_dt(s, self.registry.newtonian)
            ds = self.tidier(ds, gens)
            du = sp.Derivative(u, t)
            st.speed_dt[du] = ds
            name = self.script.name_of(u)
            base = name.rstrip("'")
            if self.table.entries[base].order > len(name) - len(base):
                self.script.assign(name + "'", ds, line=line)
        target = st.dependent if which == "DEPENDENT" else st.auxiliary
        for u in speeds:
            if u not in target:
                target.append(u)
        return kin.one_or_tuple(out)

    def configuration_variables(self) -> list:
        """The coordinates (variables with a kinematical differential
        equation): 0 in the usual reference configuration, which is where
        pivots of symbolic eliminations must not vanish."""
        return [dq.expr for dq in self.kinematical_equations()]

    # ----------------------------------------------------------- Kane

    def _speed_subs(self, expr: Any) -> Any:
        """Substitute kinematical equations, constrained speeds and their
        derivatives (named quantities are kept)."""
        speeds = set(self.generalized_speeds())
        table = dict(self.registry.speed_dt)
        for k, v in self.table.rhs.items():
            if k in speeds:
                table[k] = v
            elif isinstance(k, sp.Derivative):
                name = self.table.by_obj.get(k.expr)
                if name is not None and self.table.entries[name].kind == "variable":
                    table[k] = v
        for _ in range(50):
            new = expr.xreplace(table)
            if new == expr:
                break
            expr = new
        return kin.doit_derivatives(expr)

    @command
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
        st = self.registry
        zero = self.table.stored.get("ZERO")
        if not isinstance(zero, sp.MatrixBase):
            raise ValueError("Kane: ZERO has not been assigned")
        speeds = st.fr_speeds if st.fr_speeds is not None else self.fr_speeds()
        rows = list(zero)
        if len(rows) != len(speeds):
            raise ValueError(
                f"Kane: ZERO has {len(rows)} rows for {len(speeds)} speeds"
            )
        aux = [u for u in speeds if u in st.auxiliary]
        ind = [u for u in speeds if u not in st.auxiliary]
        z = dict(
            zip(
                speeds,
                (self._speed_subs(self.script.val(r)) for r in rows),
                strict=True,
            )
        )
        combined = []
        for i in ind:
            row = z[i]
            for x in aux:
                c = sp.diff(self.script.resolve(self.table.rhs.get(x, x)), i)
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
        gens = self.rates_and_speeds()
        arranged = sp.Matrix(arrange(cleaned, accels, gens))
        self.script.update("ZERO", arranged, line=line)
        sols = ()
        if forces:
            eqs = [z[x] for x in aux]
            if len(eqs) != len(forces):
                raise ValueError(
                    f"Kane: {len(forces)} forces for {len(eqs)} auxiliary speeds"
                )
            # Few forces: closed form, as before, whatever AutoZ says.
            many = len(forces) > SMALL
            book = self.script.solver_book(len(forces)) if many else None
            if book is None:
                eqs = [self.script.form(e) for e in eqs]
            sols = solve_speeds(eqs, forces, book, self.configuration_variables())
            for f, s in zip(forces, sols, strict=True):
                self.script.assign(
                    self.script.name_of(f), self.tidier(s, gens), line=line
                )
        st.kane = {
            "speeds": ind,
            "dependent": list(st.dependent),
            "auxiliary": aux,
            "forces": forces,
            "accels": accels,
        }
        return arranged

    # ------------------------------------------------ sympy's KanesMethod

    def coordinates_of(self, keep: list) -> list:
        """Variables with a kinematical differential equation in the speeds
        (NiCheck's work variables and perturbation variables are not)."""
        checks = set(self.registry.checks)
        out = []
        for dq in self.kinematical_equations():
            q = dq.expr
            if q in checks or q in keep or dq in keep:
                continue
            rhs = self.actual_value(self.table.rhs[dq], keep)
            if sp.sympify(rhs).has(*keep):
                out.append((q, rhs))
        return out

    @command
    def kane_inputs(self) -> Any:
        """The script's model as ``KanesMethod`` inputs (see
        :func:`al2py_runtime.model.kane_inputs`)."""
        from .kane import kane_inputs

        return kane_inputs(self)

    @property
    @command
    def kd_eqs(self) -> list:
        """The kinematical differential equations ``Q' - rhs`` (coordinates
        in declaration order), as ``KanesMethod`` takes them."""
        speeds = self.generalized_speeds()
        return [sp.Derivative(q, t) - rhs for q, rhs in self.coordinates_of(speeds)]

    @query
    def kanes_method(self) -> Any:
        """``sympy.physics.mechanics.KanesMethod`` for this script, with its
        equations formed (``mass_matrix_full``, ``forcing_full``)."""
        from .kane import kanes_method

        return kanes_method(self.kane_inputs())
