"""Speeds: part of :class:`al2py_runtime.model.model.Model`.

Generalized speeds and coordinates as Autolev identifies them (docs/semantics.md, "Generalized speeds"), kinematical differential equations, partial velocities.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef, ArgumentIndexError
from sympy.physics.vector import (
    Dyadic,
    Vector,
)

from ..walks import allow_deep_recursion
from . import kinematics as kin
from .state import SPEED_NAME, ModelPart, command, mentions, t

__all__ = ["SpeedPartials", "Speeds"]


class Speeds(ModelPart):
    """Generalized speeds and coordinates as Autolev identifies them (docs/semantics.md, "Generalized speeds"), kinematical differential equations, partial velocities."""

    # ------------------------------------------------------- speeds

    @command
    def motion_variables(self, *names: str, line: int | None = None) -> Any:
        """``MotionVariables' Q{2}'', U{2}'``: variables (as ``Variables``)
        that also describe the motion (see :meth:`generalized_speeds`)."""
        out = self.script.variables(*names, line=line)
        objs = out if isinstance(out, tuple) else (out,)
        st = self.registry
        st.motion.extend(o for o in objs if o not in st.motion)
        return out

    def generalized_speeds(self) -> list:
        """Generalized speeds.

        The declared variables U1, U2... in order, if there are any (one with
        a right-hand side of its own, not from Constrain, names an expression
        and is left out).  Otherwise
        the motion variables (``MotionVariables'``) say, in declaration order:
        one with a right-hand side of its own (``OMEGA = THETA'``) is a name
        for an expression, not a speed; one whose derivative has a right-hand
        side (``POSITION' = SPEED``, a kinematical equation) is a coordinate
        whose speeds are in that equation; one appearing in such an equation
        (``SPEED``) is a speed; any other (``THETA''``) is a coordinate whose
        first derivative ``THETA'`` serves as the generalized speed.  Speeds
        solved by Constrain keep their place."""
        if self.registry.speeds is not None:
            return list(self.registry.speeds)
        st = self.registry
        solved = set(st.dependent) | set(st.auxiliary)
        # Constrain gives their derivatives right-hand sides too
        solved |= {sp.Derivative(u, t) for u in solved}
        rhs = self.table.rhs
        found = []
        for name, entry in self.table.entries.items():
            m = SPEED_NAME.match(name)
            if m and entry.kind == "variable":
                # ``U1 = Dot(W_A_N>, A1>)`` names an expression: not a speed
                # (unless Constrain solved it), as for motion variables
                if entry.obj in rhs and entry.obj not in solved:
                    continue
                found.append((int(m.group(1)), entry.obj))
        if found:
            return [obj for _, obj in sorted(found, key=lambda x: x[0])]
        kin_eqs = [rhs[dq] for dq in self.kinematical_equations()]
        out = []
        for q in st.motion:
            dq = sp.Derivative(q, t)
            if q in rhs and q not in solved:
                continue
            if dq in rhs and dq not in solved:
                continue
            if self.table.entries[self.script.name_of(q)].order == 1 or any(
                sp.sympify(e).has(q) for e in kin_eqs
            ):
                out.append(q)
            else:
                out.append(dq)
        return out

    @command
    def speed_matrix(self, which: str, primes: int = 0) -> sp.Matrix:
        """Autolev's reserved ``U_INDEPENDENT``, ``U_DEPENDENT``,
        ``U_AUXILIARY`` and ``U_PARTIALS`` (tutorial 2.4): a column of the
        generalized speeds of that class in declaration order (``U_PARTIALS``:
        the independent and auxiliary ones, whose partial velocities form
        Fr and Fr*); ``primes`` 1 gives their time derivatives.  The speeds
        are symbols, never their solutions, so ``Exclude(Zero,
        [U_INDEPENDENT'; G])`` removes the terms in the speeds' derivatives."""
        st = self.registry
        speeds = self.generalized_speeds()
        which = which.upper().removeprefix("U_")
        dependent, auxiliary = set(st.dependent), set(st.auxiliary)
        chosen = {
            "INDEPENDENT": [
                u for u in speeds if u not in dependent and u not in auxiliary
            ],
            "DEPENDENT": [u for u in speeds if u in dependent],
            "AUXILIARY": [u for u in speeds if u in auxiliary],
            "PARTIALS": [u for u in speeds if u not in dependent],
        }[which]
        if not chosen:
            raise ValueError(
                f"U_{which} is empty: there are no {which.lower()} generalized "
                "speeds here"
            )
        return sp.Matrix([sp.diff(u, t, primes) if primes else u for u in chosen])

    def with_kindiffs(self, x: Any) -> Any:
        """``x`` with the kinematical differential equations applied (each
        ``Q'`` replaced by its right-hand side), as Autolev forms velocities in
        terms of the generalized speeds."""
        speeds = set(self.generalized_speeds())
        table = {
            dq: self.table.rhs[dq]
            for dq in self.kinematical_equations()
            if dq.expr not in speeds and dq not in speeds
        }
        if not table or not mentions(x, list(table)):
            return x
        return self.tidier.vector(kin.vmap(x, lambda e: sp.sympify(e).xreplace(table)))

    def kinematical_equations(self) -> list:
        """The derivatives ``Q'`` of declared variables (motion variables or
        not) that have a right-hand side while ``Q`` itself has none: the
        kinematical differential equations ``Q' = ...``, in declaration
        order."""
        rhs = self.table.rhs
        solved = set(self.registry.dependent) | set(self.registry.auxiliary)
        out = []
        for entry in self.table.entries.values():
            q = entry.obj
            if entry.kind != "variable" or q is t or q in rhs:
                continue
            dq = sp.Derivative(q, t)
            if dq in rhs and dq not in solved and q not in solved:
                out.append(dq)
        return out

    def fr_speeds(self) -> list:
        """Speeds with a row in Fr/Fr*: independent and auxiliary speeds."""
        dep = set(self.registry.dependent)
        return [u for u in self.generalized_speeds() if u not in dep]

    def fix_fr_speeds(self, what: str) -> list:
        """:meth:`fr_speeds` for ``Fr()``/``FrStar()``, fixed from then on:
        an error when there are none (never an empty, silently zero
        ``ZERO``)."""
        speeds = self.fr_speeds()
        if speeds and self.registry.speeds is None:
            # Fixed from now on: a later Solve(Zero, OMEGA') gives OMEGA' a
            # right-hand side, which must not make OMEGA a coordinate.
            self.registry.speeds = self.generalized_speeds()
        if not speeds:
            raise ValueError(
                f"{what}: there are no generalized speeds; declare them with"
                " Variables U{n}' or MotionVariables' (with kinematical"
                " differential equations such as Q' = U)"
            )
        self.registry.fr_speeds = speeds
        return speeds

    def displayed(self, value: Any) -> Any:
        """A response value simplified for printing (cosmetic, size-gated)."""
        if not isinstance(value, sp.Basic | Vector | Dyadic | sp.MatrixBase):
            return value
        gens = self.rates_and_speeds()
        return kin.vmap(value, lambda e: self.tidier(e, gens))

    def rates_and_speeds(self) -> list:
        """The generalized speeds' derivatives, then the speeds: what
        simplification and named intermediates collect terms in."""
        us = self.generalized_speeds()
        return [sp.Derivative(u, t) for u in us] + us

    def partial_velocities(self, v: Vector, speeds: list) -> list:
        """The partial (angular) velocities of ``v`` with respect to each of
        ``speeds``, with every other right-hand side substituted."""
        keep = speeds + [sp.Derivative(u, t) for u in speeds]
        v = self.actual_value(v, keep)
        partials = SpeedPartials(speeds)
        return [
            kin.vmap(v, lambda e, k=k: partials.of(e)[k]) for k in range(len(speeds))
        ]

    @command
    def partials(self, v: Any, *speeds: Any) -> Any:
        """``Partials(V_P_N>, U1, U2)``: partial velocities (no speeds: with
        respect to each independent/auxiliary speed).  One speed gives one
        vector; several give a tuple of vectors, in order."""
        speeds = list(speeds) or self.fr_speeds()
        out = [
            self.tidier.vector(x)
            for x in self.partial_velocities(self.script.val(v), speeds)
        ]
        return out[0] if len(out) == 1 else tuple(out)

    @command
    def remainder(self, v: Any) -> Vector:
        """``Remainder(V_P_N>)``: the part of ``v>`` free of speeds."""
        speeds = self.fr_speeds()
        v = self.actual_value(self.script.val(v), speeds)
        return self.tidier.vector(
            kin.vmap(v, lambda e: e.xreplace(dict.fromkeys(speeds, 0)))
        )


class SpeedPartials:
    """``sp.diff(e, u)`` for each of some speeds ``u``: the same expressions,
    each part of ``e`` differentiated once.

    sympy's ``diff`` by a function of time puts a dummy symbol for it,
    walks the whole expression for each derivative it takes (``has``,
    ``free_symbols``) and substitutes the function back; a velocity
    resolved through dependent speeds (``Constrain``) shares large parts
    that it differentiates again at each use.  Here each distinct part is
    differentiated once per speed, and a part that holds no speed is 0 at
    once.  A part is differentiated by sympy's own rules, with sympy's
    constructors, so the result is sympy's expression: a sum term by term
    (``Add._eval_derivative``), a product by the Leibniz rule
    (``Mul._eval_derivative_n_times``: the sum of the products with one
    factor differentiated), a power with a constant exponent as
    ``Pow._eval_derivative`` (``b**x * (db*x/b)``), a function of one or
    more arguments as ``Function._eval_derivative`` (``fdiff`` times the
    argument's derivative).  Anything else that holds a speed (a
    derivative, a function of time of a speed, a power with a speed in its
    exponent) is left to ``sp.diff``.

    >>> from sympy.physics.vector import dynamicsymbols
    >>> u1, u2, q = dynamicsymbols("u1 u2 q")
    >>> e = 2 * u1 * sp.sin(q) + u2 * (u1 + q) ** 2 / (q + u1) + sp.cos(u2 * q)
    >>> SpeedPartials([u1, u2]).of(e) == [sp.diff(e, u1), sp.diff(e, u2)]
    True
    """

    __slots__ = ("_index", "_speeds", "_held", "_done", "_derived")

    def __init__(self, speeds: list) -> None:
        self._speeds = list(speeds)
        self._index = {u: k for k, u in enumerate(self._speeds)}
        #: a part -> the numbers of the speeds anywhere in it
        self._held: dict[Any, frozenset[int]] = {}
        #: an expression -> its partials
        self._done: dict[Any, list[Any]] = {}
        #: for each speed, a part -> its derivative
        self._derived: list[dict[Any, Any]] = [{} for _ in self._speeds]

    def of(self, e: Any) -> list[Any]:
        """``[sp.diff(e, u) for u in speeds]``."""
        e = sp.sympify(e)
        found = self._done.get(e)
        if found is None:
            allow_deep_recursion()
            found = [self._d(e, k) for k in range(len(self._speeds))]
            self._done[e] = found
        return found

    def _d(self, e: Any, k: int) -> Any:
        """``sp.diff(e, speeds[k])``."""
        if k not in self._holds(e):
            return sp.S.Zero
        memo = self._derived[k]
        found = memo.get(e)
        if found is None:
            found = memo[e] = self._new_d(e, k)
        return found

    def _new_d(self, e: Any, k: int) -> Any:
        if self._index.get(e) == k:
            return sp.S.One
        args = e.args
        if e.is_Add:
            return sp.Add(*[self._d(a, k) for a in args])
        if e.is_Mul and not any(a.is_Number and not a.is_finite for a in args):
            terms = []
            for i, a in enumerate(args):
                if k in self._holds(a):
                    terms.append(sp.Mul(*args[:i], self._d(a, k), *args[i + 1 :]))
            return sp.Add(*terms)
        if e.is_Pow and k not in self._holds(e.exp):
            base, x = args
            return e * (self._d(base, k) * x / base)
        if isinstance(e, sp.Function) and not isinstance(e, AppliedUndef):
            terms = []
            for i, a in enumerate(args, 1):
                if k not in self._holds(a):
                    continue  # (its derivative is 0)
                try:
                    df = e.fdiff(i)
                except ArgumentIndexError:
                    df = sp.Function.fdiff(e, i)
                terms.append(df * self._d(a, k))
            return sp.Add(*terms)
        return sp.diff(e, self._speeds[k])

    def _holds(self, f: Any) -> frozenset[int]:
        """The numbers of the speeds anywhere in ``f``."""
        found = self._held.get(f)
        if found is None:
            k = self._index.get(f)
            out: set[int] = set() if k is None else {k}
            for a in f.args:
                out |= self._holds(a)
            found = self._held[f] = frozenset(out)
        return found
