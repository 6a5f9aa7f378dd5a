"""Kane's equations with intermediate variables (Autolev's ``AutoZ``).

:class:`FastKane` takes the same inputs as sympy's
:class:`~sympy.physics.mechanics.KanesMethod` (inertial frame, independent and
dependent coordinates and speeds, kinematic differential equations, velocity
constraints, auxiliary speeds, bodies and loads) and returns the same mass
matrix and forcing vector, but written with *intermediate variables*: plain
symbols ``z1, z2, ...`` each defined by a short expression of the
coordinates, the speeds, the constants and earlier intermediates.

How it stays small (see ``docs/intermediates.md``):

* Every direction-cosine matrix between two frames is a product of the
  frames' own (short) matrices along the orientation tree; each entry of each
  product is named.
* Every velocity and angular velocity is kept as an explicit *linear form* in
  the generalized speeds, ``v = sum_r V_r u_r + V_t``, with each measure
  number of each ``V_r`` (a partial velocity) named.  Partial velocities are
  read off, never found by differentiating large expressions.
* The time derivative of an intermediate is another intermediate, defined by
  the chain rule through its (short) definition.  Accelerations are then
  ``a = sum_r V_r u_r' + sum_r V_r' u_r + V_t'`` with no differentiation of
  anything large.
* Nothing is ever expanded or simplified.

The formulas are those of ``KanesMethod`` (same rows, same signs, the same
reduction by the dependent speeds), so ``mass_matrix`` and ``forcing`` equal
``KanesMethod``'s once the intermediates are substituted.
"""

from __future__ import annotations

import random
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp
from sympy.physics.mechanics import (
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
)
from sympy.physics.vector import Vector
from sympy.printing.numpy import NumPyPrinter

from ..intermediates.autoz import minus_first
from ..intermediates.elimination import eliminate

__all__ = ["FastKane", "Motion", "active_rows", "inertia_rows"]

_T = dynamicsymbols._t


def _trivial(expr: Any) -> bool:
    """Not worth a name: numbers, symbols, ``-x``, ``2*x``, ``sin(q)``."""
    if expr.is_Atom:
        return True
    if expr.is_Mul and len(expr.args) == 2 and expr.args[0].is_Number:
        return expr.args[1].is_Atom
    if isinstance(expr, sp.sin | sp.cos) and expr.args[0].is_Atom:
        return True
    return False


def _matmul(a: sp.Matrix, b: sp.Matrix) -> sp.Matrix:
    """Plain product (sympy's own converts large entries to a domain first)."""
    return sp.Matrix(
        a.rows,
        b.cols,
        lambda i, j: sp.Add(
            *[a[i, k] * b[k, j] for k in range(a.cols) if a[i, k] != 0 and b[k, j] != 0]
        ),
    )


@dataclass(frozen=True)
class Motion:
    """A velocity (or an angular velocity) and its time derivative, as
    measure numbers in one frame: the shape in which Kane's equations are
    formed (:func:`inertia_rows`, :func:`active_rows`).

    ``partials[r]``: the partial velocity for row ``r`` (three entries, or
    ``None`` for zero); ``rates[s]``: the coefficient of speed ``s``'s
    derivative in the time derivative (``None``: zero); ``rest``: the rest
    of the time derivative.

    >>> m = Motion(partials=[[1, 0, 0]], rates=[[1, 0, 0]], rest=[0, 0, 0])
    >>> m.partials[0]
    [1, 0, 0]
    """

    partials: Sequence[Sequence[Any] | None]
    rates: Sequence[Sequence[Any] | None] = ()
    rest: Sequence[Any] = (0, 0, 0)


def dot3(a: Sequence[Any], b: Sequence[Any]) -> Any:
    """The dot product of two measure-number triples (zeros skipped)."""
    return sp.Add(*[x * y for x, y in zip(a, b, strict=True) if x != 0 and y != 0])


def cross3(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    """The cross product of two measure-number triples."""
    return [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]


def inertia_rows(
    translations: Iterable[tuple[Any, Motion]],
    rotations: Iterable[tuple[Sequence[Sequence[Any]], Sequence[Any], Motion]],
    rows: int,
    columns: int,
    name: Any,
) -> tuple[list[list[Any]], list[Any]]:
    """Kane's generalized inertia forces, the one place they are formed (a
    script's ``FrStar()`` and :class:`FastKane` both call it):
    ``Fr*[r] = -(sum_s M[r][s] u_s' + N[r])``; returns ``(M, N)``.

    ``translations``: ``(mass, motion of the mass center)``, measure numbers
    in the inertial frame; ``rotations``: ``(central inertia matrix, angular
    velocity, motion)`` with measure numbers in the body's frame (there the
    rate of the angular velocity is the angular acceleration).  Each dot
    product is named by ``name``.

    >>> M, N = inertia_rows([(2, Motion([[1, 0, 0]], [[1, 0, 0]], [0, 3, 0]))],
    ...                     [], 1, 1, lambda e: e)
    >>> M, N
    ([[2]], [0])
    """
    mm: list[list[Any]] = [[sp.S.Zero] * columns for _ in range(rows)]
    non: list[Any] = [sp.S.Zero] * rows
    for mass, mo in translations:
        for r, vr in enumerate(mo.partials):
            if vr is None:
                continue
            for s, a in enumerate(mo.rates):
                if a is not None:
                    mm[r][s] += mass * name(dot3(vr, a))
            non[r] += mass * name(dot3(vr, mo.rest))
    for imat, omega, mo in rotations:
        i_omega = [name(dot3(imat[i], omega)) for i in range(3)]
        torque = [
            name(dot3(imat[i], mo.rest) + c)
            for i, c in enumerate(cross3(omega, i_omega))
        ]
        iw = [
            None if a is None else [name(dot3(imat[i], a)) for i in range(3)]
            for a in mo.rates
        ]
        for r, wr in enumerate(mo.partials):
            if wr is None:
                continue
            for s, a in enumerate(iw):
                if a is not None:
                    mm[r][s] += name(dot3(wr, a))
            non[r] += name(dot3(wr, torque))
    return mm, non


def active_rows(
    loads: Iterable[tuple[Sequence[Sequence[Any] | None], Sequence[Any]]],
    rows: int,
    name: Any,
) -> list[Any]:
    """Kane's generalized active forces, ``Fr[r] = sum V_r . F``: each load
    is ``(partials, force)``, the partial velocities (or partial angular
    velocities) of where it acts, per row, and the force (or torque), all as
    measure numbers in one frame.

    >>> import sympy as sp
    >>> m, g = sp.symbols("m g")
    >>> active_rows([([[0, 1, 0], None], [0, -m * g, 0])], 2, lambda e: e)
    [-g*m, 0]
    """
    fr: list[Any] = [sp.S.Zero] * rows
    for partials, force in loads:
        for r, vr in enumerate(partials):
            if vr is not None:
                fr[r] += name(dot3(vr, force))
    return fr


class FastKane:
    """Kane's equations of motion with intermediate variables.

    Parameters are those of ``KanesMethod`` (``frame``, ``q_ind``, ``u_ind``,
    ``kd_eqs``, ``q_dependent``, ``configuration_constraints``,
    ``u_dependent``, ``velocity_constraints``, ``acceleration_constraints``,
    ``u_auxiliary``), plus ``bodies`` and ``loads`` (or call
    :meth:`kanes_equations` later, as with ``KanesMethod``) and ``prefix``,
    the stem of the intermediates' names.

    After :meth:`kanes_equations`:

    * ``mass_matrix``, ``forcing`` (``KanesMethod``'s: the reduced dynamic rows
      followed by the acceleration constraints), ``mass_matrix_kin``,
      ``forcing_kin``, ``mass_matrix_full``, ``forcing_full`` and
      ``auxiliary_eqs``, written with intermediates;
    * ``intermediates``: the ordered list of ``(symbol, expression)``; each
      expression uses only coordinates, speeds, constants and earlier
      symbols, so numeric code evaluates them in order;
    * :meth:`substitute` gives fully substituted expressions;
    * :meth:`numeric` builds a numeric function that evaluates in order.

    Limitations: masses and inertia dyadics must be constant (no
    ``dynamicsymbols``), as in almost every model; ``KanesMethod``'s implicit
    kinematics option is not offered.
    """

    def __init__(
        self,
        frame: ReferenceFrame,
        q_ind: Sequence[Any],
        u_ind: Sequence[Any],
        kd_eqs: Sequence[Any] | None = None,
        q_dependent: Sequence[Any] | None = None,
        configuration_constraints: Sequence[Any] | None = None,
        u_dependent: Sequence[Any] | None = None,
        velocity_constraints: Sequence[Any] | None = None,
        acceleration_constraints: Sequence[Any] | None = None,
        u_auxiliary: Sequence[Any] | None = None,
        bodies: Sequence[Any] | None = None,
        loads: Sequence[Any] | None = None,
        prefix: str = "z",
    ) -> None:
        if not isinstance(frame, ReferenceFrame):
            raise TypeError("an inertial ReferenceFrame must be supplied")
        self._inertial = frame
        self._q = list(q_ind) + list(q_dependent or [])
        self._q_dep = list(q_dependent or [])
        self._u_ind = list(u_ind)
        self._u_dep = list(u_dependent or [])
        self._u = self._u_ind + self._u_dep
        self._u_aux = list(u_auxiliary or [])
        self._f_h = sp.Matrix(list(configuration_constraints or []))
        if len(self._f_h) != len(self._q_dep):
            raise ValueError(
                "there must be as many configuration constraints as dependent "
                "coordinates"
            )
        kd_eqs = list(kd_eqs or [])
        if len(kd_eqs) != len(self._q):
            raise ValueError(
                "there must be as many kinematic differential equations as "
                "coordinates"
            )
        vel = list(velocity_constraints or [])
        if len(vel) != len(self._u_dep):
            raise ValueError(
                "there must be as many velocity constraints as dependent speeds"
            )
        acc = list(acceleration_constraints or [])
        if acc and len(acc) != len(self._u_dep):
            raise ValueError(
                "there must be as many acceleration constraints as dependent speeds"
            )
        self._bodies = bodies
        self._loads = loads

        # Plain symbols stand for the coordinates, speeds and their
        # derivatives while deriving; results are mapped back at the end.
        self._qs = [sp.Dummy(f"q{k}") for k in range(len(self._q))]
        self._us = [sp.Dummy(f"u{k}") for k in range(len(self._u))]
        self._uas = [sp.Dummy(f"ua{k}") for k in range(len(self._u_aux))]
        self._qds = [sp.Dummy(f"qd{k}") for k in range(len(self._q))]
        self._uds = [sp.Dummy(f"ud{k}") for k in range(len(self._u))]
        self._uads = [sp.Dummy(f"uad{k}") for k in range(len(self._u_aux))]
        self._all_u = self._us + self._uas  # keys of linear forms
        self._to_plain: dict[Any, Any] = {}
        for f, s in zip(self._q, self._qs, strict=True):
            self._to_plain[f.diff(_T)] = None  # filled below (qdot map)
            self._to_plain[f] = s
        for f, s, d in zip(self._u, self._us, self._uds, strict=True):
            self._to_plain[f] = s
            self._to_plain[f.diff(_T)] = d
        for f, s, d in zip(self._u_aux, self._uas, self._uads, strict=True):
            self._to_plain[f] = s
            self._to_plain[f.diff(_T)] = d
        self._from_plain = {
            s: f for f, s in self._to_plain.items() if s is not None and s.is_Symbol
        }
        for f, s in zip(self._q, self._qds, strict=True):
            self._from_plain[s] = f.diff(_T)

        # Intermediates.
        self._prefix = prefix
        self._taken = self._names_in(kd_eqs, vel, acc)
        self._defs: dict[sp.Symbol, Any] = {}  # in creation order
        self._named: dict[Any, sp.Symbol] = {}
        self._dz: dict[Any, Any] = {}
        self._count = 0
        self._probes: dict[int, dict[Any, complex]] = {}
        self._dcms: dict[tuple[ReferenceFrame, ReferenceFrame], list] = {}
        self._lin_cache: dict[tuple[Any, ReferenceFrame], dict] = {}

        # Kinematic differential equations: q' = K u + k.
        self._qdot_map: dict[Any, Any] = {}  # q symbol -> linear form
        self._solve_kinematics(kd_eqs)
        # Velocity and acceleration constraints.
        self._solve_constraints(vel, acc)
        self._fr = self._frstar = None
        if bodies is not None:
            self.kanes_equations(bodies, loads)

    @classmethod
    def from_inputs(cls, inputs: Any, **kw: Any) -> FastKane:
        """Derive from an object with ``KanesMethod``'s inputs as attributes
        (``frame``, ``q_ind``, ``u_ind``, ``kd_eqs``, ``bodies``, ``loads`` and
        optionally ``q_dependent``, ``configuration_constraints``,
        ``u_dependent``, ``velocity_constraints``, ``u_auxiliary``), such as
        the runtime's ``KaneInputs``."""
        optional = (
            "q_dependent",
            "configuration_constraints",
            "u_dependent",
            "velocity_constraints",
            "acceleration_constraints",
            "u_auxiliary",
        )
        args = {name: getattr(inputs, name, None) for name in optional}
        return cls(
            inputs.frame,
            inputs.q_ind,
            inputs.u_ind,
            kd_eqs=inputs.kd_eqs,
            bodies=inputs.bodies,
            loads=inputs.loads,
            **{k: v for k, v in args.items() if v},
            **kw,
        )

    # ------------------------------------------------------------------
    # intermediates
    def _names_in(self, *groups: Iterable[Any]) -> set[str]:
        return {
            s.name
            for group in groups
            for e in group
            for s in sp.sympify(e).free_symbols
        }

    def _name(self, expr: Any) -> Any:
        """A symbol standing for ``expr`` (reused for the same expression)."""
        expr = sp.sympify(expr)
        if _trivial(expr):
            return expr
        if minus_first(expr):
            return -self._name(-expr)
        found = self._named.get(expr)
        if found is not None:
            return found
        while True:
            self._count += 1
            name = f"{self._prefix}{self._count}"
            if name not in self._taken:
                break
        z = sp.Symbol(name)
        self._defs[z] = expr
        self._named[expr] = z
        return z

    def _plain(self, expr: Any) -> Any:
        """``expr`` with coordinates, speeds and q' as plain symbols."""
        expr = sp.sympify(expr)
        if not expr.has(_T):
            return expr
        return expr.xreplace(self._to_plain_full)

    def _dt(self, expr: Any) -> Any:
        """Time derivative of a plain expression, by the chain rule.

        Walks the (short) expression itself for sums, products, powers, sine
        and cosine, which is several times faster than sympy's ``diff``; any
        other function falls back to ``diff`` by each symbol it contains."""
        expr = sp.sympify(expr)
        if expr.is_Symbol:
            return self._dt_symbol(expr)
        if expr.is_Number:
            return sp.S.Zero
        if expr.is_Add:
            return sp.Add(*[self._dt(a) for a in expr.args])
        if expr.is_Mul:
            args = expr.args
            terms = []
            for i, a in enumerate(args):
                d = self._dt(a)
                if d != 0:
                    terms.append(sp.Mul(*args[:i], d, *args[i + 1 :]))
            return sp.Add(*terms)
        if expr.is_Pow and expr.exp.is_Number:
            d = self._dt(expr.base)
            if d == 0:
                return sp.S.Zero
            return expr.exp * expr.base ** (expr.exp - 1) * d
        if isinstance(expr, sp.sin):
            return sp.cos(expr.args[0]) * self._dt(expr.args[0])
        if isinstance(expr, sp.cos):
            return -sp.sin(expr.args[0]) * self._dt(expr.args[0])
        out = sp.S.Zero
        for s in expr.free_symbols:
            if s == _T:
                out += expr.diff(_T)
            else:
                d = self._dt_symbol(s)
                if d != 0:
                    out += expr.diff(s) * d
        return out

    def _dt_symbol(self, s: Any) -> Any:
        if s in self._qdot_expr:
            return self._qdot_expr[s]
        if s in self._defs:
            return self._dz_of(s)
        if s in self._u_dot:
            return self._u_dot[s]
        if s == _T:
            return sp.S.One
        return sp.S.Zero

    def _dz_of(self, z: Any) -> Any:
        found = self._dz.get(z)
        if found is None:
            found = self._name(self._dt(self._defs[z]))
            self._dz[z] = found
        return found

    # ------------------------------------------------------------------
    # kinematics
    def _linear(self, expr: Any, keys: Sequence[Any]) -> tuple[list, Any]:
        """``expr = sum c_k key_k + rest``: coefficients and rest (unnamed)."""
        present = expr.free_symbols
        coefs = [expr.diff(k) if k in present else sp.S.Zero for k in keys]
        zero = {k: 0 for k in keys if k in present}
        rest = expr.xreplace(zero) if zero else expr
        return coefs, rest

    def _solve(self, a: list[list[Any]], b: list[list[Any]]) -> list[list[Any]]:
        """Solve ``a x = b`` by Gaussian elimination, naming each entry;
        pivots non-zero at the coordinates' zero (the usual reference
        configuration, e.g. an upright bicycle) if possible, constants
        random."""
        return eliminate(a, b, self._name, self._probe)

    def _probe(self, expr: Any, point: int) -> complex:
        """``expr``'s value at probe ``point`` (0: coordinates zero)."""
        cache = self._probes.setdefault(point, {})
        expr = sp.sympify(expr)
        if expr in cache:
            return cache[expr]
        values = {}
        for s in expr.free_symbols:
            if s in self._defs:
                values[s] = self._probe(self._defs[s], point)
            elif point == 0 and s in self._qs:
                values[s] = 0.0
            else:
                rng = random.Random(f"{point}:{s.name}")
                values[s] = rng.uniform(0.5, 1.5)
        try:
            out = complex(
                expr.xreplace(
                    {
                        k: sp.Float(v) if isinstance(v, float) else sp.sympify(v)
                        for k, v in values.items()
                    }
                )
            )
        except (TypeError, ValueError, ZeroDivisionError):
            out = complex("nan")
        if out != out:  # nan
            out = 0j
        cache[expr] = out
        return out

    def _solve_kinematics(self, kd_eqs: list[Any]) -> None:
        qdots = [q.diff(_T) for q in self._q]
        rule = {f: s for f, s in self._to_plain.items() if s is not None}
        rule.update(dict(zip(qdots, self._qds, strict=True)))
        eqs = [sp.sympify(e).xreplace(rule) for e in kd_eqs]
        self._taken |= self._names_in(eqs)
        n = len(eqs)
        a, b = [], []
        for e in eqs:
            ca, rest = self._linear(e, self._qds)
            cu, rest = self._linear(rest, self._all_u)
            if any(c.has(*self._qds, *self._all_u) for c in ca + cu):
                raise ValueError(
                    "the kinematic differential equations must be linear in "
                    "the speeds and the coordinates' derivatives"
                )
            a.append([self._name(c) for c in ca])
            b.append([self._name(-c) for c in cu] + [self._name(-rest)])
        x = self._solve(a, b) if n else []
        # q' as a linear form in the speeds, keyed by speed (None: the rest).
        self._qdot_form = []
        for i, s in enumerate(self._qs):
            form = {u: x[i][j] for j, u in enumerate(self._all_u) if x[i][j] != 0}
            if x[i][-1] != 0:
                form[None] = x[i][-1]
            self._qdot_map[s] = form
            self._qdot_form.append(form)
        self._qdot_expr = {
            s: self._form_expr(form, aux=True) for s, form in self._qdot_map.items()
        }
        self._u_dot = dict(
            zip(self._us + self._uas, self._uds + self._uads, strict=True)
        )
        # q' in user input is replaced by its form in the speeds.
        self._to_plain_full = {f: s for f, s in self._to_plain.items() if s is not None}
        self._to_plain_full.update(
            {qd: self._qdot_expr[s] for qd, s in zip(qdots, self._qs, strict=True)}
        )

    def _form_expr(self, form: dict, aux: bool = False) -> Any:
        keys = self._all_u if aux else self._us
        out = sum((form[u] * u for u in keys if u in form), sp.S.Zero)
        return out + form.get(None, sp.S.Zero)

    def _solve_constraints(self, vel: list[Any], acc: list[Any]) -> None:
        m, o = len(self._u_dep), len(self._u)
        p = o - m
        self._k_nh = sp.zeros(m, o)
        self._f_nh = sp.zeros(m, 1)
        self._k_dnh = sp.zeros(m, o)
        self._f_dnh = sp.zeros(m, 1)
        self._ars = sp.zeros(m, p)
        if not m:
            return
        for i, e in enumerate(vel):
            e = self._plain(e)
            coefs, rest = self._linear(e, self._us)
            self._k_nh[i, :] = sp.Matrix([[self._name(c) for c in coefs]])
            self._f_nh[i] = self._name(-rest)
        if acc:
            for i, e in enumerate(acc):
                e = self._plain(e)
                coefs, rest = self._linear(e, self._uds)
                self._k_dnh[i, :] = sp.Matrix([[self._name(c) for c in coefs]])
                self._f_dnh[i] = self._name(-rest)
        else:
            self._k_dnh = self._k_nh
            for i in range(m):
                d = sum(
                    (self._dt(self._k_nh[i, j]) * self._us[j] for j in range(o)),
                    sp.S.Zero,
                )
                self._f_dnh[i] = self._name(d + self._dt(self._f_nh[i]))
        b_ind = [[self._k_nh[i, j] for j in range(p)] for i in range(m)]
        b_dep = [[self._k_nh[i, j] for j in range(p, o)] for i in range(m)]
        x = self._solve(b_dep, b_ind)
        self._ars = sp.Matrix(m, p, lambda i, j: self._name(-x[i][j]))

    def _dcm(self, x: ReferenceFrame, f: ReferenceFrame) -> list[list[Any]]:
        """``X_C_F``: X measure numbers = ``X_C_F`` times F measure numbers."""
        if x is f:
            return [
                [sp.S.One if i == j else sp.S.Zero for j in range(3)] for i in range(3)
            ]
        key = (x, f)
        if key in self._dcms:
            return self._dcms[key]
        if (f, x) in self._dcms:
            t = self._dcms[(f, x)]
            out = [[t[j][i] for j in range(3)] for i in range(3)]
            self._dcms[key] = out
            return out
        if f in x._dcm_dict:
            local = x.dcm(f)
            out = [
                [self._name(self._plain(local[i, j])) for j in range(3)]
                for i in range(3)
            ]
        else:
            path = x._dict_list(f, 0)
            left = self._dcm(x, path[-2])
            right = self._dcm(path[-2], f)
            out = [
                [
                    self._name(
                        sum(
                            (left[i][k] * right[k][j] for k in range(3)),
                            sp.S.Zero,
                        )
                    )
                    for j in range(3)
                ]
                for i in range(3)
            ]
        self._dcms[key] = out
        return out

    def _express(self, vec: Vector, x: ReferenceFrame) -> list[Any]:
        """Measure numbers of a vector in ``x`` (plain expressions, named)."""
        out = [sp.S.Zero] * 3
        for comps, f in vec.args:
            c = self._dcm(x, f)
            m = [self._plain(comps[k]) for k in range(3)]
            for i in range(3):
                out[i] += sum((c[i][k] * m[k] for k in range(3)), sp.S.Zero)
        return [self._name(e) for e in out]

    def _forms(self, exprs: Sequence[Any]) -> list[dict[Any, Any]]:
        """Expressions linear in the speeds (and q') as linear forms.

        Each form is ``{speed: coefficient}`` with ``None`` for the rest; the
        coefficients are named.  The expressions (which sympy may have built
        large, e.g. through direction cosines of long chains) are first split
        by common-subexpression elimination; the forms are then propagated
        through the pieces in order, so nothing large is ever differentiated.
        """
        rule = {f: s for f, s in self._to_plain.items() if s is not None}
        rule.update({q.diff(_T): s for q, s in zip(self._q, self._qds, strict=True)})
        plain = [sp.sympify(e).xreplace(rule) for e in exprs]
        reps, reduced = sp.cse(
            plain, symbols=sp.numbered_symbols("c", cls=sp.Dummy), order="none"
        )
        forms: dict[Any, dict[Any, Any]] = {u: {u: sp.S.One} for u in self._all_u}
        for s, qd in zip(self._qs, self._qds, strict=True):
            forms[qd] = self._qdot_map[s]
        named: dict[Any, Any] = {}

        def form_of(e: Any) -> dict[Any, Any]:
            e = e.xreplace(named) if named else e
            speeds = [v for v in e.free_symbols if v in forms]
            if not speeds:
                return {None: self._name(e)} if e != 0 else {}
            out: dict[Any, Any] = {}
            rest = e.xreplace({v: 0 for v in speeds})
            if rest != 0:
                out[None] = rest
            for v in speeds:
                coef = e.diff(v)
                if any(w in forms for w in coef.free_symbols):
                    raise ValueError("a velocity is not linear in the speeds")
                coef = self._name(coef)
                for key, val in forms[v].items():
                    out[key] = out.get(key, sp.S.Zero) + coef * val
            return {k: self._name(v) for k, v in out.items() if v != 0}

        for s, e in reps:
            form = form_of(e)
            if set(form) <= {None}:
                named[s] = form.get(None, sp.S.Zero)
            else:
                forms[s] = form
        return [form_of(e) for e in reduced]

    def _lin_vec(self, vec: Vector, x: ReferenceFrame) -> dict[Any, list[Any]]:
        """A velocity as ``{speed: measure numbers in x}``; ``None``: the rest.

        Coordinate derivatives are replaced by their forms in the speeds;
        each measure number of each partial velocity is named."""
        try:
            key = (vec, x)
            if key in self._lin_cache:
                return self._lin_cache[key]
        except TypeError:  # unhashable
            key = None
        acc: dict[Any, list[Any]] = {}
        frames = [f for _, f in vec.args]
        exprs = [comps[k] for comps, _ in vec.args for k in range(3)]
        forms = self._forms(exprs)
        for j, f in enumerate(frames):
            c = self._dcm(x, f)
            for k in range(3):
                for u, coef in forms[3 * j + k].items():
                    row = acc.setdefault(u, [sp.S.Zero] * 3)
                    for i in range(3):
                        if c[i][k] != 0:
                            row[i] += c[i][k] * coef
        out = {u: [self._name(e) for e in row] for u, row in acc.items()}
        out = {u: row for u, row in out.items() if any(e != 0 for e in row)}
        if key is not None:
            self._lin_cache[key] = out
        return out

    # ------------------------------------------------------------------
    # Kane's equations
    def kanes_equations(
        self, bodies: Sequence[Any], loads: Sequence[Any] | None = None
    ) -> tuple[sp.Matrix, sp.Matrix]:
        """Form ``Fr`` and ``Fr*`` (returned like ``KanesMethod``'s)."""
        self._bodies, self._loads = list(bodies), list(loads or [])
        n_frame = self._inertial
        o, m = len(self._u), len(self._u_dep)
        p = o - m
        keys = self._us
        aux = self._uas

        rows = keys + aux

        # Fr, including auxiliary rows.
        loads_in = []
        for load in self._loads:
            where, what = load[0], load[1]
            if isinstance(where, Point):
                form = self._lin_vec(where.vel(n_frame), n_frame)
                force = self._express(what, n_frame)
            elif isinstance(where, ReferenceFrame):
                form = self._lin_vec(where.ang_vel_in(n_frame), where)
                force = self._express(what, where)
            else:
                raise TypeError(
                    f"a load acts on a Point or a ReferenceFrame, not {where!r}"
                )
            loads_in.append(([form.get(u) for u in rows], force))
        fr = active_rows(loads_in, len(rows), self._name)

        # Fr*: mass matrix (all speeds' derivatives) and the rest.
        translations, rotations = [], []
        for body in self._bodies:
            if isinstance(body, RigidBody):
                point, frame = body.masscenter, body.frame
            elif isinstance(body, Particle):
                point, frame = body.point, None
            else:
                raise TypeError("bodies must be RigidBody or Particle objects")
            mass = sp.sympify(body.mass)
            if mass.has(_T):
                raise NotImplementedError("masses that vary in time")
            v = self._lin_vec(point.vel(n_frame), n_frame)
            motion = Motion(
                partials=[v.get(u) for u in rows],
                rates=[v.get(u) for u in keys],
                rest=self._remainder(v, n_frame),
            )
            translations.append((mass, motion))
            if frame is None:
                continue
            inertia = body.central_inertia
            if any(sp.sympify(c).has(_T) for c, _, _ in inertia.args):
                raise NotImplementedError("inertia dyadics that vary in time")
            imat = self._inertia_matrix(inertia, frame)
            w = self._lin_vec(frame.ang_vel_in(n_frame), frame)
            omega = [
                self._name(e)
                for e in self._vec_sum(
                    [(w[u], u) for u in keys if u in w]
                    + ([(w[None], 1)] if None in w else [])
                )
            ]
            motion = Motion(
                partials=[w.get(u) for u in rows],
                rates=[w.get(u) for u in keys],
                rest=self._remainder(w, frame),
            )
            rotations.append((imat, omega, motion))
        mm, non = inertia_rows(translations, rotations, len(rows), o, self._name)

        mm_mat = sp.Matrix(mm[:o]) if o else sp.zeros(0, 0)
        non_mat = sp.Matrix(non[:o]) if o else sp.zeros(0, 1)
        fr_mat = sp.Matrix(fr[:o]) if o else sp.zeros(0, 1)
        if m:
            ars_t = self._ars.T
            mm_mat = mm_mat[:p, :] + _matmul(ars_t, mm_mat[p:, :])
            non_mat = non_mat[:p, :] + _matmul(ars_t, non_mat[p:, :])
            fr_mat = fr_mat[:p, :] + _matmul(ars_t, fr_mat[p:, :])
        udot = sp.Matrix(self._uds)
        self._k_d = mm_mat
        self._f_d = -(fr_mat - non_mat)
        self._fr_plain = fr_mat
        self._frstar_plain = -(_matmul(mm_mat, udot) + non_mat)
        if aux:
            na = len(aux)
            mma = sp.Matrix(mm[o:]) if o else sp.zeros(na, 0)
            self._aux_plain = sp.Matrix(fr[o:]) - (
                _matmul(mma, udot) + sp.Matrix(non[o:])
            )
        else:
            self._aux_plain = None
        self._fr = self._back(self._fr_plain)
        self._frstar = self._back(self._frstar_plain)
        return self._fr, self._frstar

    def _vec_sum(self, terms: list[tuple[list[Any], Any]]) -> list[Any]:
        return [sum((row[i] * c for row, c in terms), sp.S.Zero) for i in range(3)]

    def _remainder(
        self, form: dict[Any, list[Any]], frame: ReferenceFrame
    ) -> list[Any]:
        """The acceleration in ``frame`` without the speeds' derivatives.

        ``d/dt (sum V_r u_r + V_t) = sum V_r u_r' + sum V_r' u_r + V_t'`` with
        measure numbers in ``frame`` (for a frame's own angular velocity this
        is its angular acceleration; for a velocity in the inertial frame, the
        acceleration).  Auxiliary speeds are zero here."""
        out = [sp.S.Zero] * 3
        for u, row in form.items():
            if u is not None and u not in self._us:
                continue
            factor = sp.S.One if u is None else u
            for i in range(3):
                if row[i] != 0:
                    out[i] += self._dt_named(row[i]) * factor
        return [self._name(e) for e in out]

    def _dt_named(self, e: Any) -> Any:
        if e in self._defs:
            return self._dz_of(e)
        if minus_first(e) and -e in self._defs:
            return -self._dz_of(-e)
        return self._name(self._dt(e))

    def _inertia_matrix(self, dyadic: Any, frame: ReferenceFrame) -> list[list[Any]]:
        out = [[sp.S.Zero] * 3 for _ in range(3)]
        for coef, v1, v2 in dyadic.args:
            c1 = self._express(v1, frame)
            c2 = self._express(v2, frame)
            coef = self._plain(coef)
            for i in range(3):
                for j in range(3):
                    if c1[i] != 0 and c2[j] != 0:
                        out[i][j] += coef * c1[i] * c2[j]
        return [[self._name(e) for e in row] for row in out]

    # ------------------------------------------------------------------
    # results
    def _need(self) -> None:
        if self._fr is None:
            raise ValueError("call kanes_equations(bodies, loads) first")

    def _back(self, expr: Any) -> Any:
        return sp.sympify(expr).xreplace(self._from_plain)

    @property
    def q(self) -> sp.Matrix:
        return sp.Matrix(self._q)

    @property
    def u(self) -> sp.Matrix:
        return sp.Matrix(self._u)

    @property
    def mass_matrix(self) -> sp.Matrix:
        """``KanesMethod.mass_matrix``: reduced dynamic rows, then constraints."""
        self._need()
        return self._back(self._k_d.col_join(self._k_dnh))

    @property
    def forcing(self) -> sp.Matrix:
        self._need()
        return self._back((-self._f_d).col_join(-self._f_dnh))

    @property
    def mass_matrix_kin(self) -> sp.Matrix:
        return sp.eye(len(self._q))

    @property
    def forcing_kin(self) -> sp.Matrix:
        forms = [self._form_expr(f) for f in self._qdot_form]
        return self._back(sp.Matrix(forms))

    @property
    def mass_matrix_full(self) -> sp.Matrix:
        o, n = len(self._u), len(self._q)
        return self.mass_matrix_kin.row_join(sp.zeros(n, o)).col_join(
            sp.zeros(o, n).row_join(self.mass_matrix)
        )

    @property
    def forcing_full(self) -> sp.Matrix:
        return self.forcing_kin.col_join(self.forcing)

    @property
    def auxiliary_eqs(self) -> sp.Matrix:
        self._need()
        if self._aux_plain is None:
            raise ValueError("no auxiliary speeds have been declared")
        return self._back(self._aux_plain)

    @property
    def intermediates(self) -> list[tuple[sp.Symbol, Any]]:
        """``(symbol, expression)`` pairs in evaluation order."""
        return [(z, self._back(e)) for z, e in self._defs.items()]

    def substitute(self, expr: Any) -> Any:
        """``expr`` with every intermediate replaced by its full expression.

        One walk visits each shared subexpression once (``xreplace`` walks
        the written-out tree, which for a large model is far bigger than the
        graph of shared subexpressions it is made of)."""
        rule: dict[Any, Any] = dict(self._from_plain)
        done: dict[Any, Any] = {}

        def walk(e: Any) -> Any:
            found = rule.get(e)
            if found is not None or not e.args:
                return e if found is None else found
            found = done.get(e)
            if found is None:
                args = [walk(a) for a in e.args]
                same = all(a is b for a, b in zip(args, e.args, strict=True))
                found = done[e] = e if same else e.func(*args)
            return found

        for z, e in self._defs.items():
            rule[z] = walk(e)
        expr = sp.sympify(expr)
        if isinstance(expr, sp.MatrixBase):
            return expr.applyfunc(walk)
        return walk(expr)

    def numeric(self, args: Sequence[Any], exprs: Any):
        """A numpy function of ``args`` computing ``exprs`` (a matrix, an
        expression, or a list of them), evaluating the intermediates it needs
        in order.  ``args``: coordinates, speeds, constants, ...; every other
        symbol in ``exprs`` must be among them.  Complex arguments work (for
        complex-step derivatives)."""
        to_plain = {f: s for f, s in self._to_plain.items() if s is not None}
        plain_args = [sp.sympify(a).xreplace(to_plain) for a in args]
        rename = {a: sp.Symbol(f"_x{k}") for k, a in enumerate(plain_args)}
        rename.update({z: sp.Symbol(f"_{z.name}") for z in self._defs})

        def convert(e: Any) -> Any:
            if isinstance(e, list | tuple):
                return [convert(x) for x in e]
            e = sp.sympify(e)
            if isinstance(e, sp.MatrixBase):
                return e.applyfunc(lambda x: x.xreplace(to_plain).xreplace(rename))
            return e.xreplace(to_plain).xreplace(rename)

        plain = convert(exprs)
        used = self._used(plain)  # renamed symbols: look them up by name
        printer = NumPyPrinter({"order": "none", "fully_qualified_modules": True})
        lines = [f"def _numeric({', '.join(str(rename[a]) for a in plain_args)}):"]
        for z, e in self._defs.items():
            if rename[z] in used:
                lines.append(f"    {rename[z]} = {printer.doprint(e.xreplace(rename))}")

        def emit(e: Any) -> str:
            if isinstance(e, list):
                return "[" + ", ".join(emit(x) for x in e) + "]"
            if isinstance(e, sp.MatrixBase):
                rows = ", ".join(
                    "[" + ", ".join(printer.doprint(x) for x in e.row(i)) + "]"
                    for i in range(e.rows)
                )
                return f"numpy.array([{rows}])"
            return printer.doprint(e)

        lines.append(f"    return {emit(plain)}")
        namespace: dict[str, Any] = {"numpy": np}
        exec("\n".join(lines), namespace)  # noqa: S102  (generated from sympy)
        return namespace["_numeric"]

    def _used(self, expr: Any) -> set[Any]:
        """The intermediates ``expr`` needs, directly or through others."""
        if isinstance(expr, list | tuple):
            found: set[Any] = set()
            for e in expr:
                found |= sp.sympify(e).free_symbols
        else:
            found = sp.sympify(expr).free_symbols
        defs = {z: e for z, e in self._defs.items()}
        byname = {sp.Symbol(f"_{z.name}"): z for z in defs}
        todo = [byname.get(s, s) for s in found]
        todo = [s for s in todo if s in defs]
        seen: set[Any] = set()
        while todo:
            z = todo.pop()
            if z in seen:
                continue
            seen.add(z)
            todo.extend(s for s in self._defs[z].free_symbols if s in self._defs)
        return {sp.Symbol(f"_{z.name}") for z in seen}
