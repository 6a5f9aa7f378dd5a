"""Linearized equations of motion of a ``CODE Dynamics`` job.

``model.linearize()`` gives ``x' = A x + B r`` about an operating point:
``x`` the job's states (each integrated variable and its lower
derivatives, in declaration order: what ``run()`` integrates), ``r`` its
inputs (the Specified quantities with no equation, or the names asked for).
It does what a script's ``D(Xp, Xm)`` does, on the job's own equations:

* explicit equations ``x_i' = g_i(x, ud, r)`` and the implicit ones
  ``ZERO(x, ud, r) = 0`` (linear in the accelerations ``ud``) are
  differentiated by each state and input with the intermediates' chain
  rule (:meth:`~..intermediates.autoz.Intermediates.derivative`: the
  partial derivative of a named intermediate is named once and reused),
  never by writing the equations out as sympy's ``Linearizer`` does;
* at the point, ``ud`` solves ``ZERO = 0`` and
  ``dud/dx = -M^-1 dZERO/dx`` with ``M = dZERO/dud``, so that
  ``A = dg/dx + dg/dud dud/dx`` (and ``B`` alike, by ``r``).

Numbers come from the intermediates evaluated once each, in order
(:func:`~..intermediates.autoz.number`), in internal units (SI, radians).
Values follow the rule of a run: Inputs, then the values given (in the
Input's units), a Specified quantity or variable nobody gives is 0 (noted),
a constant without a value stops with its name unless ``zero_missing``.
``symbolic=True`` keeps the constants as symbols: sympy matrices, the
intermediates written out (fit for small models).

>>> from al2py_runtime import Workspace
>>> al = Workspace("spring.al")
>>> k, m = al.constants("K", "M")
>>> f = al.specified("F")
>>> x, v = al.variables("X'", "V'")
>>> _ = al.assign("X'", v)
>>> _ = al.assign("V'", (-k * x + f) / m)
>>> al.numerics.input({"K": 4, "M": 2})
>>> _ = al.numerics.code("ODE", file="spring.c")
>>> lin = al.numerics.linearize()
>>> lin.states, lin.inputs
(['X', 'V'], ['F'])
>>> lin.A.tolist(), lin.B.tolist()
([[0.0, 1.0], [-2.0, 0.0]], [[0.0], [0.5]])
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from types import SimpleNamespace
from typing import Any

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from ..intermediates import autoz
from ..progress import Steps
from .records import Job, NumericsError, normalize_name

__all__ = ["Linearization", "linearize_job"]


@dataclass
class Linearization:
    """``x' = A x + B r`` about :attr:`point`: ``A`` (n x n) and ``B``
    (n x m) as numpy arrays (sympy matrices with ``symbolic=True``);
    :attr:`states` and :attr:`inputs` name their rows and columns.
    ``A, B = model.linearize()`` unpacks the two matrices."""

    A: Any
    B: Any
    states: list[str]
    inputs: list[str]
    #: the operating point, internal units: states, inputs and accelerations
    point: dict[str, float] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def __iter__(self) -> Iterator[Any]:
        yield self.A
        yield self.B

    def eigenvalues(self) -> np.ndarray:
        """The eigenvalues of ``A`` (numeric ``A`` only)."""
        if isinstance(self.A, sp.MatrixBase):
            raise NumericsError("eigenvalues() needs the numeric A (symbolic=False)")
        return np.linalg.eigvals(np.asarray(self.A, dtype=float))

    def __repr__(self) -> str:
        kind = "symbolic " if isinstance(self.A, sp.MatrixBase) else ""
        return (
            f"<{kind}Linearization: A {self.A.shape[0]}x{self.A.shape[1]} over"
            f" {', '.join(self.states)}; B over {', '.join(self.inputs) or 'no input'}>"
        )


def linearize_job(
    job: Job,
    overrides: Mapping[str, Any] | None = None,
    *,
    inputs: Sequence[str] | None = None,
    symbolic: bool = False,
    zero_missing: bool | None = None,
) -> Linearization:
    """``job``'s equations of motion linearized about the point its Inputs
    and ``overrides`` give (see the module docstring).  ``inputs`` names
    the columns of ``B`` (default: the Specified quantities with no
    equation that the equations use, in declaration order)."""
    from .run import (
        check_overrides,
        dynamics_layout,
        initial_state,
        input_values,
        label_of,
    )

    if job.kind not in ("DYNAMICS", "ODE"):
        raise NumericsError(f"{job.where}: CODE {job.kind} has no equations of motion")
    overrides = dict(overrides or {})
    check_overrides(job, overrides)
    vals, keep = input_values(job, overrides, zero_missing)
    formed = dynamics_layout(job, frozenset(keep))
    xs, uds = formed.state_objs, formed.ud_objs
    rates = [sp.sympify(e) for e in formed.rates()]
    zero = list(formed.zero) if formed.zero is not None else []
    exprs = [*rates, *zero]
    rs = _inputs(job, exprs, inputs, formed.table)
    names = [label_of(x, job.names) for x in xs]
    input_names = [label_of(r, job.names) for r in rs]

    diff = _Differ(autoz.book_of(*exprs))
    by = [*xs, *rs]
    with Steps(f"linearizing {job.stem}", len(by) + 1) as steps:
        g_u = [[diff(e, u) for u in uds] for e in rates]
        m = [[diff(e, u) for u in uds] for e in zero]
        steps.advance()
        g_x, z_x = [], []
        for v in by:
            g_x.append([diff(e, v) for e in rates])
            z_x.append([diff(e, v) for e in zero])
            steps.advance()
    bad = [
        label_of(u, job.names)
        for u in uds
        if any(_has(e, uds) for row in m for e in row)
    ]
    if bad:
        raise NumericsError(f"{job.where}: ZERO is not linear in {', '.join(bad)}")

    # The operating point: the run's values (states at TINITIAL).
    c = SimpleNamespace(state_objs=xs, state_names=names)
    y0 = initial_state(job, c, vals)
    known: dict[Any, Any] = dict(zip(xs, y0, strict=True))
    params = _parameters(exprs, set(xs) | set(uds))
    vals.require(params)
    for obj in params:
        known.setdefault(obj, vals.param(obj))
    t0 = float(vals.values.get("TINITIAL", 0.0))
    point = {n: float(v) for n, v in zip(names, y0, strict=True)}
    point.update(
        {label_of(r, job.names): float(known.get(r, 0.0)) for r in rs if r in known}
    )
    notes = list(dict.fromkeys(vals.notes))
    if symbolic:
        a, b = _symbolic(
            job, diff.book, known, t0, rates, zero, uds, g_u, m, g_x, z_x, len(xs)
        )
        return Linearization(a, b, names, input_names, point, notes)

    env0 = _env(known, t0)
    env0.update(dict.fromkeys(uds, 0j))
    mass = _numbers(m, env0)
    z0 = np.array([_number(e, env0) for e in zero], dtype=complex)
    try:
        ud0 = np.linalg.solve(mass, -z0) if uds else np.zeros(0)
    except np.linalg.LinAlgError:
        raise NumericsError(
            f"{job.where}: the coefficient matrix of "
            + ", ".join(label_of(u, job.names) for u in uds)
            + " in ZERO is singular at the operating point"
        ) from None
    env = _env(known, t0)
    env.update(zip(uds, ud0.tolist(), strict=True))
    point.update(
        {label_of(u, job.names): float(v.real) for u, v in zip(uds, ud0, strict=True)}
    )
    gu = _numbers(g_u, env, (len(rates), len(uds)))
    gx = _numbers(g_x, env, (len(by), len(rates))).T
    zx = _numbers(z_x, env, (len(by), len(zero))).T
    dud = -np.linalg.solve(mass, zx) if uds else np.zeros((0, len(by)))
    full = gx + gu @ dud
    full = _real(full, job)
    n = len(xs)
    return Linearization(full[:, :n], full[:, n:], names, input_names, point, notes)


class _Differ:
    """``D(e, x)`` with one memo per variable: the book's walk (named
    partial derivatives of intermediates), or sympy's ``diff``."""

    def __init__(self, book: Any) -> None:
        self.book = book
        self.memos: dict[Any, dict] = {}

    def __call__(self, e: Any, x: Any) -> Any:
        if not isinstance(e, sp.Basic):
            return sp.S.Zero
        if self.book is None or not self.book.is_variable(x):
            return sp.diff(e, x)
        return self.book.derivative(e, x, self.memos.setdefault(x, {}))


def _has(e: Any, objs: Sequence[Any]) -> bool:
    return isinstance(e, sp.Basic) and bool(objs) and e.has(*objs)


def _inputs(
    job: Job, exprs: Sequence[Any], asked: Sequence[str] | None, table: Mapping
) -> list[Any]:
    """The objects of the columns of B: the names asked for, else the
    Specified quantities with no equation that ``exprs`` use."""
    if asked is not None:
        out = []
        for name in asked:
            entry = job.entries.get(normalize_name(name))
            if entry is None or not isinstance(entry[1], sp.Basic):
                raise NumericsError(f"{name} is not a declared scalar of the script")
            out.append(entry[1])
        return out
    used: set[Any] = set()
    for e in exprs:
        if isinstance(e, sp.Basic):
            used |= e.atoms(AppliedUndef)
    return [
        obj
        for name, obj, _order in job.variables
        if job.entries.get(name, ("",))[0] == "specified"
        and obj in used
        and obj not in table
    ]


def _parameters(exprs: Sequence[Any], states: set[Any]) -> list[Any]:
    """What the equations need a value for besides the states and
    accelerations: constants, specified quantities, other variables and
    derivatives, in a fixed order."""
    found: set[Any] = set()
    for e in exprs:
        if not isinstance(e, sp.Basic):
            continue
        found |= {
            a
            for a in e.atoms(sp.Symbol, AppliedUndef, sp.Derivative)
            if not isinstance(a, autoz.Intermediate)
        }
    from .run import t

    out = [a for a in found if a not in states and a != t and not a.is_Dummy]
    return sorted(out, key=sp.default_sort_key)


def _env(known: Mapping[Any, Any], t0: float) -> dict[Any, complex]:
    from .run import t as time_symbol

    env = {k: complex(v) for k, v in known.items()}
    env[time_symbol] = complex(t0)
    return env


def _number(e: Any, env: dict) -> complex:
    if not isinstance(e, sp.Basic):
        return complex(e)
    if e.is_Number:
        return complex(float(e))
    try:
        return autoz.number(e, env)
    except ValueError as exc:  # pragma: no cover - a value found missing
        raise NumericsError(f"cannot evaluate the linearization: {exc}") from None


def _numbers(
    rows: Sequence[Sequence[Any]], env: dict, shape: tuple[int, int] | None = None
) -> np.ndarray:
    out = np.array([[_number(e, env) for e in row] for row in rows], dtype=complex)
    if shape is not None:
        out = out.reshape(shape)
    return out


def _real(values: np.ndarray, job: Job) -> np.ndarray:
    if values.size and np.max(np.abs(values.imag)) > 1e-9 * max(
        1.0, float(np.max(np.abs(values.real)))
    ):
        raise NumericsError(
            f"{job.where}: the linearization is not real at the operating point"
        )
    return values.real.astype(float)


def _symbolic(
    job: Job,
    book: Any,
    known: Mapping[Any, Any],
    t0: float,
    rates: list[Any],
    zero: list[Any],
    uds: list[Any],
    g_u: list[list[Any]],
    m: list[list[Any]],
    g_x: list[list[Any]],
    z_x: list[list[Any]],
    n: int,
) -> tuple[sp.Matrix, sp.Matrix]:
    """A and B with the constants kept: the intermediates written out and
    the operating point substituted (states, inputs, time)."""
    from .run import t as time_symbol

    def exact(v: Any) -> Any:
        v = float(v)
        return sp.Integer(int(v)) if v.is_integer() else sp.Float(v)

    point = {
        k: exact(v)
        for k, v in known.items()
        if not (isinstance(k, sp.Symbol) and not isinstance(k, sp.Dummy))
    }
    point[time_symbol] = exact(t0)

    def at(e: Any, extra: Mapping[Any, Any] | None = None) -> Any:
        e = book.expand(e) if book is not None else sp.sympify(e)
        # derivatives first: Q' is not d(value of Q)/dt
        e = e.xreplace({k: v for k, v in point.items() if isinstance(k, sp.Derivative)})
        e = e.xreplace({**point, **(extra or {})})
        return e

    zeros0 = dict.fromkeys(uds, sp.S.Zero)
    mass = sp.Matrix(len(zero), len(uds), lambda i, j: at(m[i][j], zeros0))
    z0 = sp.Matrix([at(e, zeros0) for e in zero])
    ud0 = mass.LUsolve(-z0) if uds else sp.zeros(0, 1)
    with_ud = dict(zip(uds, list(ud0), strict=True))
    gu = sp.Matrix(len(rates), len(uds), lambda i, j: at(g_u[i][j], with_ud))
    gx = sp.Matrix(len(g_x), len(rates), lambda i, j: at(g_x[i][j], with_ud)).T
    zx = sp.Matrix(len(z_x), len(zero), lambda i, j: at(z_x[i][j], with_ud)).T
    dud = -mass.LUsolve(zx) if uds else sp.zeros(0, len(g_x))
    full = gx + gu * dud
    return full[:, :n], full[:, n:]
