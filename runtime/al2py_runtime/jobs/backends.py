"""Numeric backends: sympy equations of motion -> a fast ``f(t, y)``.

A :class:`DynamicsSpec` holds what a ``CODE Dynamics``/``ODE`` job
integrates, as sympy expressions of the time, the states ``y``, the
accelerations ``ud`` found from ``M ud = f`` and the parameters ``p``:

* ``mass`` (row-major, ``n x n``) and ``forcing`` (``n``): ``M ud = f``;
* ``derivs``: ``y'``, one per state (they may contain ``ud``);
* ``outputs``: one list of expressions per output table;
* ``intermediates``: optional ``(symbol, expr)`` pairs, in evaluation order,
  that the other expressions may use.

:func:`compile_dynamics` turns it into a :class:`Compiled` object;
``compiled.bind(p)`` gives ``rhs(t, y) -> ndarray`` for ``solve_ivp`` and
``outputs(t, y) -> list of rows`` (one per table).  Backends:

``c``
    C99 from :mod:`sympy.codegen` (``ccode`` after ``cse``), with the linear
    solve (Gaussian elimination, partial pivoting) in the same C function;
    built with the system C compiler (``$CC``, ``cc``, ``gcc`` or ``clang``)
    into a shared library, loaded with :mod:`ctypes`, cached by content hash
    in the user cache folder (:func:`cache_dir`).  One compiled call per
    right-hand-side evaluation.
``llvm``
    SymEngine's ``Lambdify`` with its LLVM backend for ``M``, ``f`` and the
    derivatives (no C compiler needed); the solve is ``numpy.linalg.solve``.
``lambdify``
    ``sympy.lambdify(cse=True, modules="math")`` and ``numpy.linalg.solve``:
    always available.

``auto`` (the default) takes the first of these that is available and can
print the equations, and says in one line on stderr why when it has to fall
back to ``lambdify``.  ``AL2PY_BACKEND`` sets the default for a process.
"""

from __future__ import annotations

import ctypes
import hashlib
import math
import os
import platform
import shutil
import subprocess
import sys
import tempfile
import threading
from collections.abc import Callable, Generator, Iterable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import sympy as sp
from sympy.core.mul import _keep_coeff
from sympy.printing.c import C99CodePrinter
from sympy.printing.precedence import PRECEDENCE, PRECEDENCE_FUNCTIONS, precedence

from .. import progress
from ..vocabulary import numeric_namespace
from .kutta import ADVANCE_C, StepError

if TYPE_CHECKING:  # numpy is imported where it is used (issue 35)
    import numpy as np

__all__ = [
    "BACKENDS",
    "BackendError",
    "Compiled",
    "DynamicsSpec",
    "SingularMatrixError",
    "available",
    "cache_dir",
    "choose",
    "c_model_source",
    "compile_dynamics",
    "find_compiler",
]

#: Backend names, fastest first; ``auto`` picks the first available.
BACKENDS = ("c", "llvm", "lambdify")


class BackendError(RuntimeError):
    """A backend cannot be used (no compiler, unsupported function, ...)."""


class SingularMatrixError(ArithmeticError):
    """The mass matrix is singular at the time ``t``."""

    def __init__(self, t: float) -> None:
        super().__init__(f"singular mass matrix at t = {t:g}")
        self.t = t


@dataclass
class DynamicsSpec:
    """Equations of a Dynamics/ODE job; see the module docstring."""

    time: Any
    states: list[Any]
    accels: list[Any]
    params: list[Any]
    mass: list[Any]
    forcing: list[Any]
    derivs: list[Any]
    outputs: list[list[Any]] = field(default_factory=list)
    intermediates: list[tuple[Any, Any]] = field(default_factory=list)
    #: the free symbols of its expressions, remembered while it is compiled
    #: (:func:`free_symbols_of`'s memo): its own
    free: dict = field(default_factory=dict, repr=False, compare=False)

    def __post_init__(self) -> None:
        n = len(self.accels)
        if len(self.mass) != n * n or len(self.forcing) != n:
            raise ValueError("mass must be n*n and forcing n for n accelerations")
        if len(self.derivs) != len(self.states):
            raise ValueError("one derivative per state")


class Bound:
    """A compiled job with its parameter values: ``rhs`` and ``outputs``."""

    rhs: Callable[[float, np.ndarray], np.ndarray]

    def outputs(self, t: float, y: Sequence[float]) -> list[list[float]]:
        raise NotImplementedError  # pragma: no cover

    def table(self, times: Sequence[float], ys: np.ndarray, clock: list) -> np.ndarray:
        """Every output (all tables side by side) at each time, the states
        ``ys[:, i]``; ``clock[0]`` is the time being evaluated."""
        import numpy as np

        rows = []
        for i, tt in enumerate(times):
            clock[0] = float(tt)
            rows.append([x for row in self.outputs(clock[0], ys[:, i]) for x in row])
        return np.array(rows, dtype=float).reshape(len(rows), -1)

    def stepper(
        self, t0: float, y0: Sequence[float], step: float, abserr: float, relerr: float
    ) -> CStepper | None:
        """Kutta-Merson compiled with the equations, or None (``run()``
        then steps in Python: :class:`.kutta.KuttaMerson`)."""
        return None


@dataclass
class Compiled:
    """What :func:`compile_dynamics` returns."""

    backend: str
    bind: Callable[[Sequence[float]], Bound]
    #: seconds spent generating code and compiling (0 for a cache hit build)
    build_seconds: float = 0.0
    cache_hit: bool = False
    note: str | None = None


# ------------------------------------------------------------------ choice


def find_compiler() -> str | None:
    """The C compiler: ``$CC`` if set, else ``cc``, ``gcc`` or ``clang``."""
    env = os.environ.get("CC")
    if env:
        return shutil.which(env.split()[0]) and env
    for name in ("cc", "gcc", "clang"):
        if shutil.which(name):
            return name
    return None


def _has_llvm() -> bool:
    try:
        import symengine as se
    except ImportError:
        return False
    try:
        x = se.Symbol("x")
        se.Lambdify([x], [x], backend="llvm")
    except Exception:  # noqa: BLE001 - a wheel built without LLVM
        return False
    return True


_AVAILABLE: dict[str, bool] = {}


def available(backend: str) -> bool:
    """Whether ``backend`` can be used on this machine."""
    if backend not in _AVAILABLE:
        if backend == "c":
            _AVAILABLE[backend] = find_compiler() is not None
        elif backend == "llvm":
            _AVAILABLE[backend] = _has_llvm()
        else:
            _AVAILABLE[backend] = backend == "lambdify"
    return _AVAILABLE[backend]


def choose(requested: str | None = None) -> str:
    """``requested``, else ``$AL2PY_BACKEND``, else ``auto``; checked."""
    name = (requested or os.environ.get("AL2PY_BACKEND") or "auto").strip().lower()
    if name != "auto" and name not in BACKENDS:
        raise BackendError(
            f"unknown backend {name!r}; choose one of auto, {', '.join(BACKENDS)}"
        )
    return name


_SAID: set[str] = set()


def say_once(line: str) -> None:
    """Print ``al2py: note: line`` on stderr, once per process."""
    if line not in _SAID:
        _SAID.add(line)
        print(f"al2py: note: {line}", file=sys.stderr)


def compile_dynamics(spec: DynamicsSpec, backend: str | None = None) -> Compiled:
    """Build ``spec`` with ``backend`` (``auto``, ``c``, ``llvm`` or
    ``lambdify``; ``None`` reads ``$AL2PY_BACKEND``).  An explicit backend
    that cannot be used raises :class:`BackendError`; ``auto`` falls back."""
    name = choose(backend)
    canonical: list[DynamicsSpec] = []

    def form(candidate: str) -> DynamicsSpec:
        if candidate == "c":
            return spec  # printed with names (_c_form): no substitution
        if not canonical:
            canonical.append(_canonical(spec))
        return canonical[0]

    builders = {
        "c": lambda: _build_c(form("c")),
        "llvm": lambda: _build_llvm(form("llvm")),
        "lambdify": lambda: _build_lambdify(form("lambdify")),
    }
    if name != "auto":
        if not available(name):
            raise BackendError(_unavailable(name))
        return builders[name]()
    reasons = []
    for candidate in BACKENDS:
        if not available(candidate):
            reasons.append(_unavailable(candidate))
            continue
        try:
            compiled = builders[candidate]()
        except BackendError as exc:
            reasons.append(str(exc))
            continue
        if candidate == "lambdify" and reasons:
            compiled.note = "using the lambdify backend (slower): " + "; ".join(reasons)
            say_once(compiled.note)
        return compiled
    raise BackendError("; ".join(reasons))  # pragma: no cover - lambdify works


def _unavailable(name: str) -> str:
    if name == "c":
        return "no C compiler found (set CC)"
    if name == "llvm":
        return "symengine with LLVM is not installed"
    return f"backend {name} is not available"  # pragma: no cover


# ------------------------------------------------------------ canonical form


def _canonical(spec: DynamicsSpec) -> DynamicsSpec:
    """The same spec with plain symbols ``t, y0.., ud0.., p0.., z0..`` so that
    every backend (and the C printer) sees predictable names."""
    table: dict[Any, Any] = {spec.time: sp.Symbol("t", real=True)}
    names = []
    for prefix, objs in (("y", spec.states), ("ud", spec.accels), ("p", spec.params)):
        out = []
        for k, obj in enumerate(objs):
            s = sp.Symbol(f"{prefix}[{k}]", real=True)
            table[obj] = s
            out.append(s)
        names.append(out)
    inter = []
    for k, (sym, expr) in enumerate(spec.intermediates):
        s = sp.Symbol(f"z{k}", real=True)
        inter.append((s, sp.sympify(expr).xreplace(table)))
        table[sym] = s

    def sub(e: Any) -> Any:
        return sp.sympify(e).xreplace(table)

    return DynamicsSpec(
        table[spec.time],
        names[0],
        names[1],
        names[2],
        [sub(e) for e in spec.mass],
        [sub(e) for e in spec.forcing],
        [sub(e) for e in spec.derivs],
        [[sub(e) for e in row] for row in spec.outputs],
        inter,
    )


def _split_derivs(spec: DynamicsSpec) -> tuple[list[int], list[int]]:
    """Indices of derivatives free of ``ud`` and of those that use it."""
    uses = reading(spec.intermediates, spec.derivs, set(spec.accels), spec.free)
    return [i for i in range(len(spec.derivs)) if i not in uses], uses


def reading(
    intermediates: Sequence[tuple[Any, Any]],
    exprs: Sequence[Any],
    symbols: set,
    memo: dict | None = None,
) -> list[int]:
    """The indices of ``exprs`` that read one of ``symbols``, themselves or
    through the intermediates they use (each defined before its uses, so
    one pass finds the intermediates that read them at any depth);
    ``memo``: :func:`free_symbols_of`'s."""
    reads = set(symbols)
    for sym, expr in intermediates:
        if free_symbols_of(expr, memo) & reads:
            reads.add(sym)
    return [i for i, e in enumerate(exprs) if free_symbols_of(e, memo) & reads]


# ----------------------------------------------------------------- lambdify


def _inline(spec: DynamicsSpec, exprs: list[Any]) -> list[Any]:
    """``exprs`` with the intermediates substituted (last to first)."""
    for sym, expr in reversed(spec.intermediates):
        exprs = [e.xreplace({sym: expr}) for e in exprs]
    return exprs


def needed(
    intermediates: Sequence[tuple[Any, Any]],
    exprs: Iterable[Any],
    memo: dict | None = None,
) -> list[tuple[Any, Any]]:
    """The intermediates that ``exprs`` use, in order; ``memo``:
    :func:`free_symbols_of`'s."""
    want: set[Any] = set()
    for e in exprs:
        want |= free_symbols_of(e, memo)
    keep = []
    known = {} if memo is None else memo
    for sym, expr in reversed(list(intermediates)):
        if sym in want:
            keep.append((sym, expr))
            found = known.get(expr)  # (most are remembered)
            want |= free_symbols_of(expr, memo) if found is None else found
    return keep[::-1]


def free_symbols_of(expr: Any, memo: dict | None = None) -> frozenset:
    """``sympify(expr).free_symbols``.  ``memo`` (a dict its owner keeps,
    say the program being formed: :attr:`..codegen.program.Program.free`)
    remembers each answer: forming and printing a program ask it of the
    same intermediates and equations again and again, and sympy walks the
    whole expression each time.  Its owner's expressions alone meet in it,
    so it never holds another program's equal expressions (each found
    would cost a comparison of the two, node by node) and goes with its
    owner."""
    if not isinstance(expr, sp.Basic):
        return frozenset(sp.sympify(expr).free_symbols)
    if memo is None:
        return frozenset(expr.free_symbols)
    return _free_of_parts(expr, memo)


#: ``Basic.free_symbols``: a class whose own is this one's unites its
#: arguments' (the others bind symbols, or are symbols)
_UNITED = sp.Basic.free_symbols


def _free_of_parts(expr: Any, memo: dict) -> frozenset:
    """:func:`free_symbols_of` with ``memo``: each part's, remembered (a
    program's expressions share their parts: sin(q4), a product, ...)."""
    found = memo.get(expr)
    if found is not None:
        return found
    return _free_of_new(expr, memo)


def _free_of_new(expr: Any, memo: dict) -> frozenset:
    """:func:`_free_of_parts` of a part not in ``memo``."""
    args = expr.args
    if type(expr).free_symbols is not _UNITED or not args:
        found = frozenset(expr.free_symbols)
    else:
        out: set[Any] = set()
        for a in args:
            if a.is_Symbol:
                out.add(a)
            elif type(a) is sp.Mul and _names_after_number(a.args):
                # (most terms of a sum: a product of names, after a number
                # or not; its names at once, not remembered apart)
                out.update(a.args if a.args[0].is_Symbol else a.args[1:])
            elif a.args or type(a).free_symbols is not _UNITED:
                part = memo.get(a)  # (a shared part: found before)
                out |= _free_of_new(a, memo) if part is None else part
        found = frozenset(out)
    memo[expr] = found
    return found


def _names_after_number(args: tuple) -> bool:
    """Whether ``args`` (a product's) are names, after a number or not: the
    product's free symbols are those names."""
    first = 1 if args[0].is_Number else 0
    for a in args[first:]:
        if type(a) is not sp.Symbol:
            return False
    return True


def cse_with(intermediates: Sequence[tuple[Any, Any]]) -> Any:
    """``lambdify``'s ``cse`` argument: the intermediates the expressions
    need, in order, then sympy's common subexpressions of the rest."""
    if not intermediates:
        return True

    def cse(exprs: Any) -> tuple[list, Any]:
        first = needed(intermediates, exprs)
        reps, reduced = sp.cse(exprs, list=False)
        return first + list(reps), reduced

    return cse


def lambdify_job(
    args: list[Any],
    exprs: list[Any],
    intermediates: Sequence[tuple[Any, Any]] = (),
    numbers: str = "math",
) -> Callable[..., list[float]]:
    """A scalar function ``f(*args) -> list of floats`` (math module, CSE);
    ``intermediates`` (``(symbol, expr)`` in order) are computed first.
    With ``numbers="numpy"`` the function takes arrays and computes every
    element at once (:func:`~al2py_runtime.jobs.run.evaluate_rows`)."""
    if not exprs:
        return lambda *a: []
    args, exprs, intermediates = _undummied(args, list(exprs), intermediates)
    return sp.lambdify(
        args, exprs, modules=[numeric_namespace(), numbers], cse=cse_with(intermediates)
    )


def _undummied(
    args: list[Any], exprs: list[Any], intermediates: Sequence[tuple[Any, Any]]
) -> tuple[list[Any], list[Any], list[tuple[Any, Any]]]:
    """Plain symbols with fresh names for the ``Dummy`` arguments and
    intermediates.  With one ``Dummy`` argument ``lambdify`` renames every
    argument by substituting into all expressions and all common
    subexpressions once per argument, which is quadratic for a model with
    thousands of intermediates."""
    dummies = [a for a in args if isinstance(a, sp.Dummy)]
    dummies += [s for s, _ in intermediates if isinstance(s, sp.Dummy)]
    if not dummies:
        return args, exprs, list(intermediates)
    taken = {
        s.name
        for e in [*exprs, *(body for _, body in intermediates)]
        if isinstance(e, sp.Basic)
        for s in e.free_symbols
        if not isinstance(s, sp.Dummy)
    }
    rule: dict[Any, Any] = {}
    for i, d in enumerate(dummies):
        name = f"a{i}"
        while name in taken:
            name = "_" + name
        rule[d] = sp.Symbol(name)

    def plain(e: Any) -> Any:
        return e.xreplace(rule) if isinstance(e, sp.Basic) else e

    return (
        [rule.get(a, a) for a in args],
        [plain(e) for e in exprs],
        [(rule.get(s, s), plain(body)) for s, body in intermediates],
    )


def _solve(n: int, v: list[float], t: float) -> list[float]:
    """``M ud = f`` from ``v = [*M (row-major), *f, ...]``."""
    import numpy as np

    if n == 0:
        return []
    if n == 1:
        if v[0] == 0:
            raise SingularMatrixError(t)
        return [v[1] / v[0]]
    nn = n * n
    try:
        return np.linalg.solve(np.array(v[:nn]).reshape(n, n), v[nn : nn + n]).tolist()
    except np.linalg.LinAlgError:
        raise SingularMatrixError(t) from None


class _PyBound(Bound):
    """Shared by ``lambdify`` and ``llvm``: ``mf(t, y, p) -> [M, f, free]``,
    ``late(t, y, ud, p) -> derivatives using ud``."""

    def __init__(self, n, ny, mf, late, plan, outs, p) -> None:
        import numpy as np

        p = list(p)
        nf = n * n + n

        def rhs(t: float, y: np.ndarray) -> np.ndarray:
            y = np.asarray(y, dtype=float)
            v = mf(t, y, p)
            ud = _solve(n, v, t)
            out = np.empty(ny)
            free = v[nf:]
            later = late(t, y, ud, p) if late is not None else ()
            for i, (early, k) in enumerate(plan):
                out[i] = free[k] if early else later[k]
            return out

        def accel(t: float, y: Sequence[float]) -> list[float]:
            return _solve(n, mf(t, np.asarray(y, dtype=float), p), t)

        self.rhs = rhs
        self._accel = accel
        self._outs = outs
        self._p = p

    def outputs(self, t: float, y: Sequence[float]) -> list[list[float]]:
        ud = self._accel(t, y)
        yl = list(y)
        return [list(f(t, *yl, *ud, *self._p)) for f in self._outs]


def _plan(spec: DynamicsSpec) -> tuple[list[int], list[int], list[tuple[bool, int]]]:
    free, uses = _split_derivs(spec)
    plan: list[tuple[bool, int]] = [(True, 0)] * len(spec.derivs)
    for k, i in enumerate(free):
        plan[i] = (True, k)
    for k, i in enumerate(uses):
        plan[i] = (False, k)
    return free, uses, plan


def _build_lambdify(spec: DynamicsSpec) -> Compiled:
    import time

    start = time.perf_counter()
    free, uses, plan = _plan(spec)
    y, ud, p, t = spec.states, spec.accels, spec.params, spec.time
    z = spec.intermediates
    first = [*spec.mass, *spec.forcing, *(spec.derivs[i] for i in free)]
    step = lambdify_job([t, *y, *p], first, z)
    late_f = lambdify_job([t, *y, *ud, *p], [spec.derivs[i] for i in uses], z)
    outs = [lambdify_job([t, *y, *ud, *p], row, z) for row in spec.outputs]
    n, ny = len(ud), len(y)

    def mf(tt, yy, pp):
        return step(tt, *yy.tolist(), *pp)

    late = None
    if uses:

        def late(tt, yy, uu, pp):
            return late_f(tt, *yy.tolist(), *uu, *pp)

    def bind(values: Sequence[float]) -> Bound:
        return _PyBound(n, ny, mf, late, plan, outs, values)

    return Compiled("lambdify", bind, time.perf_counter() - start)


# --------------------------------------------------------------------- llvm


#: symengine's Lambdify takes whole expressions: beyond this many
#: intermediates (AutoZ) inlining them costs more than it saves
_LLVM_INLINE = 200


def _build_llvm(spec: DynamicsSpec) -> Compiled:
    import time

    import numpy as np
    import symengine as se

    start = time.perf_counter()
    if len(spec.intermediates) > _LLVM_INLINE:
        raise BackendError(
            "llvm backend: too many intermediates to inline"
            f" ({len(spec.intermediates)})"
        )
    free, uses, plan = _plan(spec)
    y, ud, p, t = spec.states, spec.accels, spec.params, spec.time
    first = _inline(spec, [*spec.mass, *spec.forcing, *(spec.derivs[i] for i in free)])
    later = _inline(spec, [spec.derivs[i] for i in uses])
    try:
        step = se.Lambdify([t, *y, *p], first, backend="llvm", cse=True)
        late_f = (
            se.Lambdify([t, *y, *ud, *p], later, backend="llvm", cse=True)
            if later
            else None
        )
    except Exception as exc:  # noqa: BLE001 - symengine cannot take a function
        raise BackendError(
            f"llvm backend cannot compile the equations: {exc}"
        ) from None
    outs = [lambdify_job([t, *y, *ud, *p], _inline(spec, row)) for row in spec.outputs]
    n, ny, np_ = len(ud), len(y), len(p)
    buf = np.empty(1 + ny + np_)

    def mf(tt, yy, pp):
        buf[0] = tt
        buf[1 : 1 + ny] = yy
        buf[1 + ny :] = pp
        return step(buf).tolist() if first else []

    late = None
    if late_f is not None:

        def late(tt, yy, uu, pp):
            return late_f([tt, *yy.tolist(), *uu, *pp]).tolist()

    def bind(values: Sequence[float]) -> Bound:
        return _PyBound(n, ny, mf, late, plan, outs, values)

    return Compiled("llvm", bind, time.perf_counter() - start)


# ------------------------------------------------------------------------ C


def _hoisting(method: Callable[..., str]) -> Callable[..., str]:
    """A printing method of a sympy function, through ``hoisted_call``."""

    def printed(self: CPrinter, expr: Any, **kwargs: Any) -> str:
        return self.hoisted_call(expr, method(self, expr, **kwargs))

    return printed


def _sympys_hoisting(name: str) -> Callable[..., str]:
    """sympy's printing method ``name`` of a function (``_print_sin``),
    found as sympy's printers find it, through ``hoisted_call``."""
    return _hoisting(getattr(C99CodePrinter, name))


class CPrinter(C99CodePrinter):
    """C99 with small integer powers as products and Autolev's functions;
    with ``z_array`` the intermediates ``zK`` are the elements ``z[K]``."""

    def __init__(
        self,
        z_array: bool = False,
        names: dict[Any, str] | None = None,
        hoist: tuple[set[Any], int] | None = None,
    ) -> None:
        super().__init__(
            {
                "strict": True,
                "user_functions": {"trunc": "trunc"},
                # Strict C99 has no M_PI, M_SQRT2, ...: print numbers.
                "math_macros": {sp.Symbol("_al2py_none_"): "_AL2PY_NONE_"},
                # Terms in sympy's own argument order: sorting them for print
                # is half the printing time of a large model.
                "order": "none",
            }
        )
        self._z_array = z_array
        self._names = names or {}
        self._hoist = hoist
        #: with ``hoist = (symbols, base)``: each call of a function of those
        #: symbols alone, printed, and the element ``z[base + k]`` it is kept in
        self.hoisted: dict[str, str] = {}
        #: whether a product may be one of ``math_macros`` (none is here)
        self._macro_products = any(type(k) is sp.Mul for k in self.math_macros)
        #: a name's text, by its spelling: (the symbol, its text), for
        #: :meth:`names_product` (a str key: no sympy hash per factor)
        self._name_texts: dict[str, tuple[Any, str]] = {}

    def hoisted_call(self, expr: Any, text: str) -> str:
        """``text``, the call ``expr`` printed, or where it is kept."""
        if self._hoist is None or not expr.free_symbols <= self._hoist[0]:
            return text
        found = self.hoisted.get(text)
        if found is None:
            found = f"z[{self._hoist[1] + len(self.hoisted)}]"
            self.hoisted[text] = found
        return found

    def _print_Symbol(self, expr: Any) -> str:
        name = self._names.get(expr, expr.name)
        if self._z_array and name[:1] == "z" and name[1:].isdigit():
            return f"z[{name[1:]}]"  # an intermediate kept in the array z
        if expr in self._names:
            return name
        return super()._print_Symbol(expr)

    _print_Dummy = _print_Symbol

    def _handle_UnevaluatedExpr(self, expr: Any) -> Any:  # noqa: N802 - sympy's
        return expr if without_re(expr) else super()._handle_UnevaluatedExpr(expr)

    def print_part(self, expr: Any) -> str:
        """The text of ``expr``, a part of the statement being printed (the
        program printers remember it: :mod:`..codegen.printers`)."""
        return self._print(expr)

    def parenthesize(self, item: Any, level: int, strict: bool = False) -> str:
        # sympy's (StrPrinter) computes the precedence twice, and finds a
        # symbol's by walking its class's bases: a fifth of printing time
        prec = _precedence(item)
        if prec < level or (not strict and prec <= level):
            return f"({self.print_part(item)})"
        return self.print_part(item)

    def _print_Add(self, expr: Any, order: Any = None) -> str:
        # StrPrinter._print_Add (terms in their own order) with precedences
        # kept per class: sympy's precedence() of a product forms its
        # negative to compare (a third of printing a large model)
        return join_sum(
            self, expr.args, _precedence(expr), _precedence, self.names_product
        )

    def names_product(self, expr: Any) -> str | None:
        """:meth:`_print_Mul`'s text of a product of names (after -1 or
        nothing), each as it is; None for any other product."""
        named = signed_names(expr)
        if named is None:
            return None
        sign, args = named
        if self._macro_products and expr in self.math_macros:
            return None
        # (each name's text as print_part gives it: a name's text depends
        # on the printer's settings alone)
        texts = self._name_texts
        out = []
        for a in args:
            found = texts.get(a.name)
            if found is None or found[0] is not a:
                found = texts[a.name] = (a, self.print_part(a))
            out.append(found[1])
        return sign + "*".join(out)

    def _print_Mul(self, expr: Any, **kwargs: Any) -> str:
        # C89CodePrinter._print_Mul: CodePrinter._print_Mul (factors in
        # their own order) with precedences kept per class
        if self._macro_products and expr in self.math_macros:
            return super()._print_Mul(expr, **kwargs)
        names = self.names_product(expr)
        if names is not None:  # most products: each name as it is
            return names
        sign, a_str, b_str = product_parts(self, expr, _precedence(expr))[::2]
        return join_product(sign, a_str, b_str)

    def _print_Pi(self, expr: Any) -> str:
        return repr(math.pi)

    def _print_Exp1(self, expr: Any) -> str:
        return repr(math.e)

    def _print_Pow(self, expr: Any) -> str:
        base, exp = expr.args
        if exp.is_Integer and 2 <= abs(int(exp)) <= 4:
            b = self.parenthesize(base, 1000)  # a product needs its own parens
            prod = "*".join([b] * abs(int(exp)))
            return f"({prod})" if exp > 0 else f"(1.0/({prod}))"
        return super()._print_Pow(expr)

    def _print_nint(self, expr: Any) -> str:
        x = self._print(expr.args[0])
        return f"copysign(floor(fabs({x}) + 0.5), {x})"

    @_hoisting
    def _print_sign(self, expr: Any) -> str:
        x = self._print(expr.args[0])
        return f"(double)(((({x}) > 0) - (({x}) < 0)))"

    # Every printing method of a sympy function (sin, cos, ..., and the
    # general one) goes through hoisted_call (tests/test_codegen_c.py checks
    # that none is missing).
    _print_Abs = _sympys_hoisting("_print_Abs")
    _print_Function = _sympys_hoisting("_print_Function")
    _print_Heaviside = _sympys_hoisting("_print_Heaviside")
    _print_Mod = _sympys_hoisting("_print_Mod")
    _print_Piecewise = _sympys_hoisting("_print_Piecewise")
    _print_WildFunction = _sympys_hoisting("_print_WildFunction")
    _print_acos = _sympys_hoisting("_print_acos")
    _print_acosh = _sympys_hoisting("_print_acosh")
    _print_asin = _sympys_hoisting("_print_asin")
    _print_asinh = _sympys_hoisting("_print_asinh")
    _print_atan = _sympys_hoisting("_print_atan")
    _print_atan2 = _sympys_hoisting("_print_atan2")
    _print_atanh = _sympys_hoisting("_print_atanh")
    _print_ceiling = _sympys_hoisting("_print_ceiling")
    _print_cos = _sympys_hoisting("_print_cos")
    _print_cosh = _sympys_hoisting("_print_cosh")
    _print_erf = _sympys_hoisting("_print_erf")
    _print_erfc = _sympys_hoisting("_print_erfc")
    _print_exp = _sympys_hoisting("_print_exp")
    _print_floor = _sympys_hoisting("_print_floor")
    _print_gamma = _sympys_hoisting("_print_gamma")
    _print_log = _sympys_hoisting("_print_log")
    _print_loggamma = _sympys_hoisting("_print_loggamma")
    _print_sin = _sympys_hoisting("_print_sin")
    _print_sinh = _sympys_hoisting("_print_sinh")
    _print_tan = _sympys_hoisting("_print_tan")
    _print_tanh = _sympys_hoisting("_print_tanh")


_PRECEDENCE: dict[type, int] = {}


def precedence_of(item: Any) -> int:
    """sympy's ``precedence(item)``, kept per class where it can be."""
    return _precedence(item)


def product_parts(
    printer: Any,
    expr: Any,
    prec: int,
    order: Callable[[list], list] | None = None,
    *,
    rationals: bool = False,
    lone_minus: bool = True,
    inverses: dict | None = None,
) -> tuple[str, list, list, list, list]:
    """``CodePrinter._print_Mul``'s split of a product, shared by the C,
    Fortran and MATLAB printers: ``(sign, numerator factors, their texts,
    denominator factors, their texts)``.

    ``order`` orders the factors of the product without its sign (given as
    :func:`magnitude_factors`; None: as they are); ``rationals`` puts a
    rational's denominator below the line (MATLAB); ``lone_minus``
    parenthesizes a single negated factor as a power's level (C,
    Fortran); ``inverses``: a memo of each power's inverse (a negative
    power's in the denominator), kept by the printer."""
    sign, items = magnitude_factors(expr)
    if order is not None:
        items = order(items)
    a: list = []  # the numerator's factors
    b: list = []  # the denominator's
    pow_paren = []  # powers -1 of products of more than one factor
    for item in items:
        if (
            item.is_Pow
            and item.is_commutative
            and item.exp.is_Rational
            and item.exp.is_negative
        ):
            if item.exp != -1:
                inverse = None if inverses is None else inverses.get(item)
                if inverse is None:
                    inverse = sp.Pow(item.base, -item.exp, evaluate=False)
                    if inverses is not None:
                        inverses[item] = inverse
                b.append(inverse)
            else:
                if len(item.args[0].args) != 1 and isinstance(item.base, sp.Mul):
                    pow_paren.append(item)
                inverse = None if inverses is None else inverses.get(item)
                if inverse is None:
                    inverse = sp.Pow(item.base, -item.exp)
                    if inverses is not None:
                        inverses[item] = inverse
                b.append(inverse)
        elif rationals and item.is_Rational and item is not sp.S.Infinity:
            if item.p != 1:
                a.append(sp.Rational(item.p))
            if item.q != 1:
                b.append(sp.Rational(item.q))
        else:
            a.append(item)
    a = a or [sp.S.One]
    if lone_minus and len(a) == 1 and sign == "-":
        level = 0.5 * (PRECEDENCE["Pow"] + PRECEDENCE["Mul"])
        a_str = [printer.parenthesize(a[0], level)]
    else:
        a_str = [printer.parenthesize(x, prec) for x in a]
    b_str = [printer.parenthesize(x, prec) for x in b]
    for item in pow_paren:
        if item.base in b:
            b_str[b.index(item.base)] = f"({b_str[b.index(item.base)]})"
    return sign, a, a_str, b, b_str


def signed_names(expr: Any) -> tuple[str, tuple] | None:
    """A product of names alone, or of -1 and names (most of a program's
    products): ``(sign, names)`` as :func:`product_parts` splits it (``"-"``
    for -1, the names in their order, none of them parenthesized: a name's
    precedence is an atom's), else None."""
    args = expr.args
    sign = ""
    if args and args[0] is sp.S.NegativeOne:
        sign, args = "-", args[1:]
    if not args or any(type(a) is not sp.Symbol for a in args):
        return None
    return sign, args


def magnitude_factors(expr: Any) -> tuple[str, list]:
    """The sign of the product ``expr`` as ``CodePrinter._print_Mul`` prints
    it (``"-"`` or ``""``) and the arguments of the product it prints after
    the sign (``_keep_coeff(-c, e)`` of ``expr.as_coeff_Mul()`` when ``c``
    is negative, else ``expr``), read off ``expr``'s arguments where sympy's
    canonical product makes them those (a number first, at most one), and
    formed as sympy forms them otherwise."""
    args = expr.args
    c = args[0] if args else sp.S.One
    # a rational's sign without sympy's comparison (which sympifies the 0)
    if not c.is_Number or not (c.is_extended_negative if c.is_Rational else c < 0):
        return "", list(args)
    rest = args[1:]
    magnitude = -c
    if len(rest) > 1 and not rest[0].is_Number:
        # _keep_coeff: the product of the rest, or the magnitude put first
        if magnitude is sp.S.One:
            return "-", list(rest)
        return "-", [magnitude, *rest]
    if len(rest) == 1 and magnitude is sp.S.One:
        return "-", list(sp.Mul.make_args(rest[0]))
    c, e = expr.as_coeff_Mul()
    return "-", list(sp.Mul.make_args(_keep_coeff(-c, e)))


def join_sum(
    printer: Any,
    terms: Iterable[Any],
    prec: int,
    precedence: Callable[[Any], int],
    names_text: Callable[[Any], str | None] | None = None,
) -> str:
    """``StrPrinter._print_Add``'s text of a sum of ``terms`` in that order,
    with ``precedence`` the printer's (shared by the C, Fortran and MATLAB
    printers, each term printed by their ``print_part``).

    ``names_text``: the printer's text of a product of names (after -1),
    None for any other product (most terms of a program are such
    products: printed by it at once).  Such a product is never put in
    parentheses in a sum: its precedence is a product's, or a sum's after
    -1."""
    out = []
    direct = names_text is not None and prec <= PRECEDENCE["Add"]
    for term in terms:
        if direct and type(term) is sp.Mul:
            t = names_text(term)  # type: ignore[misc]
            if t is not None:
                if t.startswith("-"):
                    out.extend(["-", t[1:]])
                else:
                    out.extend(["+", t])
                continue
        t = printer.print_part(term)
        if t.startswith("-") and not term.is_Add:
            sign = "-"
            t = t[1:]
        else:
            sign = "+"
        if precedence(term) < prec or term.is_Add:
            out.extend([sign, f"({t})"])
        else:
            out.extend([sign, t])
    sign = out.pop(0)
    if sign == "+":
        sign = ""
    return sign + " ".join(out)


def join_product(sign: str, a_str: list, b_str: list) -> str:
    """A product's text from :func:`product_parts` (C and Fortran)."""
    if not b_str:
        return sign + "*".join(a_str)
    if len(b_str) == 1:
        return sign + "*".join(a_str) + "/" + b_str[0]
    return sign + "*".join(a_str) + "/({})".format("*".join(b_str))


def _precedence(item: Any) -> int:
    """sympy's ``precedence``, kept per class where it depends on the class
    alone (not for numbers, products and the like, whose sign matters)."""
    cls = type(item)
    found = _PRECEDENCE.get(cls)
    if cls is sp.Mul:
        return _precedence_mul(item)
    if found is None:
        found = precedence(item)
        if not hasattr(cls, "precedence") and not any(
            c.__name__ in PRECEDENCE_FUNCTIONS for c in cls.__mro__
        ):
            _PRECEDENCE[cls] = found
    return found


def _precedence_mul(item: Any) -> int:
    """sympy's ``precedence_Mul`` without forming ``-item``: its
    ``could_extract_minus_sign`` asks ``item == -item`` (false whenever the
    leading factor is a negative number, the only case it matters) and then
    whether the leading factor is a negative number."""
    mul = PRECEDENCE["Mul"]
    for arg in item.args:
        prec = getattr(arg, "precedence", None)
        if prec is not None and isinstance(arg, sp.Function) and prec < mul:
            return mul
    c = item.args[0]
    return PRECEDENCE["Add"] if c.is_Number and c.is_extended_negative else mul


def without_re(expr: Any) -> bool:
    """Whether ``expr`` holds no ``re``: then sympy's
    ``CodePrinter._handle_UnevaluatedExpr`` (``re(...)`` of an
    ``UnevaluatedExpr``), which rebuilds the whole expression, would give it
    back unchanged, and a printer skips it (a tenth of printing a large
    model)."""
    return isinstance(expr, sp.Basic) and not expr.has(sp.re)


def c_expression(expr: Any, printer: CPrinter) -> str:
    try:
        return printer.doprint(expr)
    except Exception as exc:  # noqa: BLE001 - PrintMethodNotImplementedError, ...
        what = str(exc).split("\n")[0]
        raise BackendError(f"the C backend cannot print {expr}: {what}") from None


def _block(
    exprs: list[Any], targets: list[str], printer: CPrinter, prefix: str, indent: str
) -> list[str]:
    """C statements assigning ``exprs`` to ``targets`` after common
    subexpression elimination (temporaries ``double {prefix}N``)."""
    if not exprs:
        return []
    temps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix), order="none")
    lines = [
        f"{indent}const double {s} = {c_expression(e, printer)};" for s, e in temps
    ]
    for target, e in zip(targets, reduced, strict=True):
        lines.append(f"{indent}{target} = {c_expression(e, printer)};")
    return lines


SOLVE_C = r"""
/* Solve a x = b (n x n, row-major) by Gaussian elimination with partial
   pivoting; a and b are overwritten, x is left in b.  Returns 1 if a is
   singular (an exactly zero pivot, as LAPACK reports), else 0. */
static int al_solve(int n, double *a, double *b)
{
    for (int k = 0; k < n; k++) {
        int piv = k;
        double big = fabs(a[k * n + k]);
        for (int i = k + 1; i < n; i++) {
            double v = fabs(a[i * n + k]);
            if (v > big) {
                big = v;
                piv = i;
            }
        }
        if (big == 0.0) return 1;
        if (piv != k) {
            for (int j = k; j < n; j++) {
                double s = a[k * n + j];
                a[k * n + j] = a[piv * n + j];
                a[piv * n + j] = s;
            }
            double s = b[k];
            b[k] = b[piv];
            b[piv] = s;
        }
        double d = a[k * n + k];
        for (int i = k + 1; i < n; i++) {
            double l = a[i * n + k] / d;
            if (l == 0.0) continue;
            for (int j = k + 1; j < n; j++) a[i * n + j] -= l * a[k * n + j];
            b[i] -= l * b[k];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = b[i];
        for (int j = i + 1; j < n; j++) s -= a[i * n + j] * b[j];
        b[i] = s / a[i * n + i];
    }
    return 0;
}
"""


def c_model_source(spec: DynamicsSpec, api: str = "") -> str:
    """C99 for ``spec`` (canonical form): ``al_rhs``, ``al_out`` and helpers.

    ``int al_rhs(double t, const double *y, const double *p, double *dy)``
    writes ``y'`` and returns 0, 1 for a singular mass matrix, 2 for a value
    that is not finite.  ``int al_out(double t, const double *y,
    const double *p, double *out)`` writes every output, table after table.
    ``api`` prefixes both (``static`` for a standalone program)."""
    spec, names = _c_form(spec)
    return _source(spec, CPrinter(names=names), api)


def _source(
    spec: DynamicsSpec,
    printer: CPrinter,
    api: str,
    mf: tuple[list[str], list[str]] | None = None,
) -> str:
    """:func:`c_model_source` of a spec in C form (``mf``: see
    :func:`_rhs_lines`)."""
    lines = _rhs_lines(spec, printer, api, "static ", mf)
    lines += _out_head(spec, api)
    all_out = [e for row in spec.outputs for e in row]
    lines += _intermediates(spec, all_out, printer, "    ")
    lines += _out_tail(spec, printer)
    return "\n".join(lines)


def _header(spec: DynamicsSpec) -> list[str]:
    n, ny, nout = len(spec.accels), len(spec.states), sum(map(len, spec.outputs))
    lines = [
        "#include <math.h>",
        "",
        f"#define AL_NY {ny}  /* states */",
        f"#define AL_NU {n}  /* accelerations solved from M ud = f */",
        f"#define AL_NP {len(spec.params)}  /* parameters */",
        f"#define AL_NOUT {nout}  /* outputs, all tables */",
    ]
    if n:
        lines.append(SOLVE_C)
    return lines


_MF = (
    "void al_mf(double t, const double *y, const double *p,"
    " double *m, double *f, double *dy)"
)


def _mf_exprs(spec: DynamicsSpec) -> tuple[list[Any], list[str]]:
    """What ``al_mf`` computes (``M``, ``f``, the state derivatives free of
    ``ud``) and where it writes them."""
    n = len(spec.accels)
    free = _plan(spec)[0]
    targets = [f"m[{k}]" for k in range(n * n)] + [f"f[{k}]" for k in range(n)]
    targets += [f"dy[{i}]" for i in free]
    exprs = [*spec.mass, *spec.forcing, *(spec.derivs[i] for i in free)]
    return exprs, targets


def _rhs_lines(
    spec: DynamicsSpec,
    printer: CPrinter,
    api: str,
    mf_api: str,
    mf: tuple[list[str], list[str]] | None = None,
) -> list[str]:
    """The header, ``al_mf`` (``M``, ``f`` and the state derivatives free of
    ``ud``) and ``al_rhs``.  ``mf``: the declarations that precede ``al_mf``
    and its body (:func:`_mf_parts`), when it is not printed here."""
    n = len(spec.accels)
    _free, uses, _plan_ = _plan(spec)
    lines = _header(spec)
    if mf is not None:
        lines += mf[0]
    lines += [
        "/* M (row-major), f, and the state derivatives that do not need ud */",
        mf_api + _MF,
        "{",
        "    (void)t; (void)y; (void)p; (void)m; (void)f; (void)dy;",
    ]
    if mf is None:
        exprs, targets = _mf_exprs(spec)
        lines += _intermediates(spec, exprs, printer, "    ")
        lines += _block(exprs, targets, printer, "x", "    ")
    else:
        lines += mf[1]
    lines += ["}", ""]
    lines += [
        f"{api}int al_rhs(double t, const double *y, const double *p, double *dy)",
        "{",
        *_m_decl(n),
        "    al_mf(t, y, p, m, ud, dy);",
    ]
    if n:
        lines.append(f"    if (al_solve({n}, m, ud)) return 1;")
    if uses:
        late = [spec.derivs[i] for i in uses]
        lines += ["    {", *_intermediates(spec, late, printer, "        ")]
        lines += _block(late, [f"dy[{i}]" for i in uses], printer, "w", "        ")
        lines.append("    }")
    lines += [
        "    for (int i = 0; i < AL_NY; i++)",
        "        if (!isfinite(dy[i])) return 2;",
        "    return 0;",
        "}",
        ADVANCE_C,
    ]
    return lines


def _m_decl(n: int) -> list[str]:
    return (
        [f"    double m[{n * n}], ud[{n}];"] if n else ["    double *m = 0, *ud = 0;"]
    )


def _out_head(spec: DynamicsSpec, api: str) -> list[str]:
    """``al_out`` up to its outputs: ``M``, ``f`` and ``ud`` at the point."""
    n, ny = len(spec.accels), len(spec.states)
    lines = [
        f"{api}int al_out(double t, const double *y, const double *p, double *out)",
        "{",
        *_m_decl(n),
        f"    double dy[{max(ny, 1)}];",
        "    (void)t; (void)y; (void)p; (void)out; (void)ud;",
        "    al_mf(t, y, p, m, ud, dy);",
    ]
    if n:
        lines.append(f"    if (al_solve({n}, m, ud)) return 1;")
    return lines


def _out_tail(spec: DynamicsSpec, printer: CPrinter) -> list[str]:
    all_out = [e for row in spec.outputs for e in row]
    targets = [f"out[{k}]" for k in range(len(all_out))]
    lines = _block(all_out, targets, printer, "o", "    ")
    return [*lines, "    return 0;", "}", ""]


#: ``al_out`` needing more intermediates than this is compiled apart from
#: the right-hand side: in parts, in parallel, with ``OUT_FLAGS``.
SPLIT = 400
#: ``al_mf`` (the right-hand side but the accelerations) needing more
#: intermediates than this is compiled in parts, in parallel, with -O2.  gcc
#: compiles a function of up to about 650 of the Whipple bicycle's
#: intermediates in about 1.4 ms each (processor time), and grows faster
#: beyond: all 855 in 3.3 s, in parts 1.3-1.9 s shared by two cores.  The
#: parts keep the intermediates in an array, and an evaluation takes about
#: 20% more instructions: below this, one function is worth its wait
RHS_SPLIT = 600
#: above this many elements the array of the right-hand side's intermediates
#: (on the stack of ``al_mf``) is too large: the right-hand side stays whole
_RHS_STACK = 1 << 15
#: intermediates per part of the right-hand side: two parts or more (the
#: two compile side by side, the first while the second is printed), four
#: at most
_RHS_PART = 400
#: statements per C function in the parts of the right-hand side (at most:
#: each part has one function or more)
_RHS_CHUNK = 100
#: statements per C function in the parts (compile time grows faster than
#: the size of a function)
_CHUNK = 50
#: the outputs are evaluated once per printed row, not per step: compiling
#: thousands of their statements with -O2 took most of a large model's
#: first run (the Whipple bicycle's Encode'd Jacobians: 10 s of 12).  gcc
#: and clang compile them with -Og in about 3/4 of -O1's time, and Moore's
#: Whipple runs as fast (its warm run() is 0.020 s either way).
OUT_FLAGS = ("-Og",)


def c_model_units(
    spec: DynamicsSpec, split: int | None = None, rhs_split: int | None = None
) -> list[tuple[str, tuple[str, ...]]]:
    """See :func:`c_model_stream`, as a list."""
    return list(c_model_stream(spec, split, rhs_split))


def c_model_stream(
    spec: DynamicsSpec, split: int | None = None, rhs_split: int | None = None
) -> Iterator[tuple[str, tuple[str, ...]]]:
    """``spec`` as C translation units with their optimisation flags: the
    right-hand side (``-O2``), and when the outputs need more than ``split``
    (:data:`SPLIT`) intermediates, ``al_out`` and its intermediates in parts
    (kept in one array ``z``, functions of :data:`_CHUNK` statements).  When
    ``al_mf`` needs more than ``rhs_split`` (:data:`RHS_SPLIT`)
    intermediates, they are computed likewise, in parts compiled with -O2
    before the unit of the right-hand side."""
    split = SPLIT if split is None else split
    rhs_split = RHS_SPLIT if rhs_split is None else rhs_split
    spec, names = _c_form(spec)
    printer = CPrinter(names=names)
    all_out = [e for row in spec.outputs for e in row]
    zs = needed(spec.intermediates, all_out, spec.free)
    mf = yield from _mf_parts(spec, names, rhs_split)
    if len(zs) <= split:
        if mf is None:
            yield (c_model_source(spec), ("-O2",))
        else:
            yield (_source(spec, printer, "", mf), ("-O2",))
        return
    yield ("\n".join(_rhs_lines(spec, printer, "", "", mf)), ("-O2",))
    size = _z_size(zs, names)
    # sin(q1) and the like, used all over the parts: computed once, first
    hoist = {spec.time, *spec.states, *spec.params}
    arrays = CPrinter(z_array=True, names=names, hoist=(hoist, size))
    args = "double t, const double *y, const double *p, const double *ud, double *z"
    count = -(-len(zs) // _CHUNK)  # functions
    # up to 4 parts, whatever the cores: each is compiled while the next is
    # printed, so that the compiler starts early and the last part is short
    parts = max(1, min(4, len(zs) // 1000))
    voids = "    (void)t; (void)y; (void)p; (void)ud;"
    head = f"al_z{{}}({args})"
    yield from _z_units(zs, arrays, head, voids, (parts, _CHUNK), OUT_FLAGS)
    tail = _out_tail(spec, arrays)
    size += len(arrays.hoisted)
    main = _header(spec)
    main += ["#include <stdlib.h>", "", f"{_MF};"]
    main += [f"void al_z{j}({args});" for j in range(count)]
    main += _out_head(spec, "")
    main += [
        f"    double *z = malloc({size} * sizeof(double));",
        "    if (!z) return 2;",
        *(f"    {at} = {text};" for text, at in arrays.hoisted.items()),
        *(f"    al_z{j}(t, y, p, ud, z);" for j in range(count)),
    ]
    main += [*tail[:-3], "    free(z);", *tail[-3:]]
    yield ("\n".join(main), OUT_FLAGS)


def _z_size(zs: list[tuple[Any, Any]], names: dict[Any, str]) -> int:
    """The length of an array ``z`` that holds the intermediates ``zs``."""
    return max(int(names.get(s, str(s))[1:]) for s, _e in zs) + 1


def _z_units(
    zs: list[tuple[Any, Any]],
    arrays: CPrinter,
    head: str,
    voids: str,
    split: tuple[int, int],
    flags: tuple[str, ...],
) -> Iterator[tuple[str, tuple[str, ...]]]:
    """Translation units (``split = (parts, chunk)``: ``parts`` of them, with
    ``flags``) of the functions ``head`` (numbered ``0, 1, ...``) that store
    the intermediates ``zs`` in the array ``z``, ``chunk`` statements each;
    each unit is given as soon as it is printed."""
    parts, chunk = split
    count = -(-len(zs) // chunk)  # functions
    per = -(-count // parts)  # functions per part
    bodies: list[str] = []
    for j, k in enumerate(range(0, len(zs), chunk)):
        lines = [f"void {head.format(j)}", "{", voids]
        for sym, expr in zs[k : k + chunk]:
            lines.append(
                f"    {c_expression(sym, arrays)} = {c_expression(expr, arrays)};"
            )
        bodies.append("\n".join([*lines, "}", ""]))
        if len(bodies) % per == 0 or j == count - 1:
            first = (len(bodies) - 1) // per * per
            yield ("#include <math.h>\n\n" + "\n".join(bodies[first:]), flags)


def _mf_parts(
    spec: DynamicsSpec, names: dict[Any, str], rhs_split: int
) -> Generator[tuple[str, tuple[str, ...]], None, tuple[list[str], list[str]] | None]:
    """When ``al_mf`` needs more than ``rhs_split`` intermediates: the units
    (-O2) of functions ``al_rK`` that store them in an array ``z`` on the
    stack of ``al_mf``, each given as soon as it is printed; then returns
    the declarations and the body of ``al_mf`` (for :func:`_rhs_lines`),
    which computes the functions of the states and parameters alone first,
    once, calls the parts, and assembles ``M``, ``f`` and ``dy`` as
    :func:`_block` does.  Else gives nothing and returns ``None``."""
    exprs, targets = _mf_exprs(spec)
    zs = needed(spec.intermediates, exprs, spec.free)
    if len(zs) <= rhs_split or _z_size(zs, names) > _RHS_STACK:
        return None
    size = _z_size(zs, names)
    hoist = {spec.time, *spec.states, *spec.params}
    arrays = CPrinter(z_array=True, names=names, hoist=(hoist, size))
    args = "double t, const double *y, const double *p, double *z"
    parts = max(2, min(4, len(zs) // _RHS_PART))
    chunk = min(_RHS_CHUNK, -(-len(zs) // parts))
    count = -(-len(zs) // chunk)  # functions
    voids = "    (void)t; (void)y; (void)p;"
    head = f"al_r{{}}({args})"
    yield from _z_units(zs, arrays, head, voids, (parts, chunk), ("-O2",))
    block = _block(exprs, targets, arrays, "x", "    ")
    size += len(arrays.hoisted)
    decls = [f"void al_r{j}({args});" for j in range(count)]
    body = [
        f"    double z[{size}];",
        *(f"    {at} = {text};" for text, at in arrays.hoisted.items()),
        *(f"    al_r{j}(t, y, p, z);" for j in range(count)),
        *block,
    ]
    return [*decls, ""], body


def _intermediates(
    spec: DynamicsSpec, exprs: list[Any], printer: CPrinter, indent: str
) -> list[str]:
    """Declarations of the intermediates that ``exprs`` need, in order."""
    return [
        f"{indent}const double {c_expression(s, printer)} = {c_expression(e, printer)};"
        for s, e in needed(spec.intermediates, exprs, spec.free)
    ]


def _c_form(spec: DynamicsSpec) -> tuple[DynamicsSpec, dict[Any, str]]:
    """``spec`` and the C names of its symbols (``t``, ``y[k]``, ``ud[k]``,
    ``p[k]``, ``zK``) when they all are symbols (a job's are), so that the
    printer names them and no expression is rebuilt; else the canonical form
    (:func:`_canonical`) and no names."""
    if _is_canonical(spec):
        return spec, {}
    groups = (("y", spec.states), ("ud", spec.accels), ("p", spec.params))
    objs = [spec.time, *(o for _p, g in groups for o in g)]
    objs += [z for z, _e in spec.intermediates]
    if not all(isinstance(o, sp.Symbol) for o in objs):
        return _canonical(spec), {}
    names: dict[Any, str] = {spec.time: "t"}
    for prefix, group in groups:
        names.update((o, f"{prefix}[{k}]") for k, o in enumerate(group))
    names.update((z, f"z{k}") for k, (z, _e) in enumerate(spec.intermediates))
    if len(names) != len(objs):  # one symbol in two roles
        return _canonical(spec), {}
    return spec, names


def _is_canonical(spec: DynamicsSpec) -> bool:
    return (
        isinstance(spec.time, sp.Symbol)
        and spec.time.name == "t"
        and all(getattr(s, "name", "") == f"y[{k}]" for k, s in enumerate(spec.states))
        and all(getattr(s, "name", "") == f"p[{k}]" for k, s in enumerate(spec.params))
        and all(getattr(s, "name", "") == f"ud[{k}]" for k, s in enumerate(spec.accels))
    )


def cache_dir() -> Path:
    """Where compiled models are kept: ``$AL2PY_CACHE_DIR``, else the
    platform's user cache folder (``$XDG_CACHE_HOME/al2py`` or
    ``~/.cache/al2py`` on Linux, ``~/Library/Caches/al2py`` on macOS,
    ``%LOCALAPPDATA%\\al2py`` on Windows)."""
    env = os.environ.get("AL2PY_CACHE_DIR")
    if env:
        return Path(env)
    home = Path.home()
    if sys.platform == "win32":
        base = Path(os.environ.get("LOCALAPPDATA") or home / "AppData" / "Local")
    elif sys.platform == "darwin":
        base = home / "Library" / "Caches"
    else:
        base = Path(os.environ.get("XDG_CACHE_HOME") or home / ".cache")
    return base / "al2py"


C_FLAGS = ("-O2", "-std=c99", "-fPIC", "-fno-math-errno", "-shared")
_UNIT_FLAGS = ("-std=c99", "-fPIC", "-fno-math-errno")


def build_shared(source: str) -> tuple[Path, bool]:
    """Compile ``source`` into a shared library in :func:`cache_dir`, named
    by the hash of the source, compiler and flags.  Returns (path, cache hit)."""
    return build_units([(source, ("-O2",))])


def build_units(units: Sequence[tuple[str, Sequence[str]]]) -> tuple[Path, bool]:
    """Compile C translation units ``(source, flags)`` into one shared
    library in :func:`cache_dir`, named by the hash of the sources, compiler
    and flags; several units compile in parallel.  Returns (path, cache hit)."""
    cc = find_compiler()
    if cc is None:
        raise BackendError(_unavailable("c"))
    text = [cc, *C_FLAGS, sys.platform, platform.machine()]
    for source, flags in units:
        text += [source, *flags]
    key = hashlib.sha256("\0".join(text).encode()).hexdigest()[:24]
    folder = _cache_folder()
    lib = folder / f"al2py_{key}{_SUFFIX}"
    if lib.exists():
        return lib, True
    with (
        tempfile.TemporaryDirectory(dir=folder) as tmp,
        progress.task("compiling the C code") as task,
    ):
        task.doing(f"{len(units)} unit{'s' if len(units) > 1 else ''}")
        out = Path(tmp) / f"model{_SUFFIX}"
        if len(units) == 1:
            src = Path(tmp) / "model.c"
            src.write_text(units[0][0], encoding="utf-8")
            flags = [*units[0][1], *C_FLAGS[1:]]
            _run_compiler([[*cc.split(), *flags, "-o", str(out), str(src), "-lm"]])
        else:
            objs, cmds = [], []
            for k, (source, flags) in enumerate(units):
                src = Path(tmp) / f"model{k}.c"
                src.write_text(source, encoding="utf-8")
                objs.append(str(src.with_suffix(".o")))
                cmds.append(
                    [*cc.split(), *flags, *_UNIT_FLAGS, "-c", "-o", objs[-1], str(src)]
                )
            _run_compiler(cmds)
            _run_compiler([[*cc.split(), "-shared", "-o", str(out), *objs, "-lm"]])
        os.replace(out, lib)  # atomic: concurrent builds of one model are safe
    return lib, False


_SUFFIX = ".dll" if sys.platform == "win32" else ".so"


def cache_folder() -> Path:
    """:func:`cache_dir`, made if need be (a temporary folder of the user's
    when it cannot be)."""
    return _cache_folder()


def _cache_folder() -> Path:
    folder = cache_dir()
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError:
        user = getattr(os, "getuid", lambda: "user")()
        folder = Path(tempfile.gettempdir()) / f"al2py-{user}"
        folder.mkdir(parents=True, exist_ok=True)
    return folder


def build_stream(units: Iterable[tuple[str, Sequence[str]]]) -> tuple[Path, bool]:
    """:func:`build_units` (the same library, the same name) for units that
    are still being printed: each unit is compiled as soon as it comes, while
    the next one is printed, into an object kept in the cache under the hash
    of its own source (so that a process that finds the library cached has
    nothing to compile either)."""
    cc = find_compiler()
    if cc is None:
        raise BackendError(_unavailable("c"))
    folder = _cache_folder()
    text = [cc, *C_FLAGS, sys.platform, platform.machine()]
    objs: list[Path] = []
    started: list[tuple[subprocess.Popen, Path, Path]] = []
    with (
        tempfile.TemporaryDirectory(dir=folder) as tmp,
        progress.task("compiling the C code", unit="units") as task,
    ):
        try:
            for k, (source, flags) in enumerate(units):
                task.doing(f"printing unit {k + 1}")
                text += [source, *flags]
                cmd = [*cc.split(), *flags, *_UNIT_FLAGS, "-c"]
                own = [*cmd, sys.platform, platform.machine(), source]
                key = hashlib.sha256("\0".join(own).encode()).hexdigest()[:24]
                objs.append(folder / f"al2py_{key}.o")
                if objs[-1].exists():
                    continue
                src, obj = Path(tmp) / f"unit{k}.c", Path(tmp) / f"unit{k}.o"
                src.write_text(source, encoding="utf-8")
                with open(Path(tmp) / f"unit{k}.err", "w") as err:
                    proc = subprocess.Popen(
                        [*cmd, "-o", str(obj), str(src)],
                        stdout=subprocess.DEVNULL,
                        stderr=err,
                    )
                started.append((proc, obj, objs[-1]))
            key = hashlib.sha256("\0".join(text).encode()).hexdigest()[:24]
            lib = folder / f"al2py_{key}{_SUFFIX}"
            if lib.exists():
                return lib, True
            task.doing("")
            task.update(len(objs) - len(started), len(objs))
            for k, (proc, obj, kept) in enumerate(started):
                if proc.wait(timeout=600):
                    error = (obj.with_suffix(".err")).read_text(errors="replace")
                    raise BackendError(_compiler_error(error))
                task.advance()
                os.replace(obj, kept)  # atomic, as the library
                started[k] = (proc, obj, obj)
            out = Path(tmp) / f"model{_SUFFIX}"
            link = [*cc.split(), "-shared", "-o", str(out), *map(str, objs), "-lm"]
            task.doing("linking")
            _run_compiler([link])
            os.replace(out, lib)
            return lib, False
        except (OSError, subprocess.TimeoutExpired) as exc:
            raise BackendError(f"the C compiler failed: {exc}") from None
        finally:
            for proc, _obj, _kept in started:
                if proc.poll() is None:
                    proc.kill()
                    proc.wait()


def _compiler_error(err: str) -> str:
    lines = err.strip().splitlines() or ["(no message)"]
    first = next((ln for ln in lines if "error" in ln), lines[0])
    return f"the C compiler failed: {first}"


def _run_compiler(cmds: list[list[str]]) -> None:
    """Run the compiler commands side by side; the first error is raised."""
    procs = []
    try:
        for cmd in cmds:
            procs.append(
                subprocess.Popen(
                    cmd,
                    stdout=subprocess.DEVNULL,
                    stderr=subprocess.PIPE,
                    text=True,
                )
            )
        errors = [proc.communicate(timeout=600)[1] for proc in procs]
    except (OSError, subprocess.TimeoutExpired) as exc:
        for proc in procs:
            proc.kill()
            proc.wait()
        raise BackendError(f"the C compiler failed: {exc}") from None
    for proc, err in zip(procs, errors, strict=True):
        if proc.returncode != 0:
            raise BackendError(_compiler_error(err))


class _CBound(Bound):
    def __init__(self, lib: Any, ny: int, nout: int, rows: list[int], p) -> None:
        import numpy as np

        self._p = np.ascontiguousarray(p, dtype=float).reshape(-1)
        self._pp = self._p.ctypes.data if self._p.size else None
        self._lib = lib
        c_rhs, c_out = lib.al_rhs, lib.al_out
        pp = self._pp
        asarray = np.ascontiguousarray
        empty = np.empty

        # The closures hold the parameter array and the library: ``pp`` is a
        # bare address, valid only while the array lives.
        keep = (self._p, lib)

        def rhs(t: float, y: np.ndarray, _keep: Any = keep) -> np.ndarray:
            y = asarray(y, dtype=float)
            dy = empty(ny)
            code = c_rhs(t, y.ctypes.data, pp, dy.ctypes.data)
            if code:
                _raise(code, t)
            return dy

        def outs(t: float, y: Sequence[float], _keep: Any = keep) -> list[list[float]]:
            yy = asarray(y, dtype=float)
            out = empty(max(nout, 1))
            code = c_out(t, yy.ctypes.data, pp, out.ctypes.data)
            if code:
                _raise(code, t)
            values = out.tolist()
            result, k = [], 0
            for r in rows:
                result.append(values[k : k + r])
                k += r
            return result

        self.rhs = rhs
        self._outs = outs
        self._nout = nout

    def outputs(self, t: float, y: Sequence[float]) -> list[list[float]]:
        return self._outs(t, y)

    def table(self, times: Sequence[float], ys: np.ndarray, clock: list) -> np.ndarray:
        import numpy as np

        out = np.empty((len(times), max(self._nout, 1)))
        yt = np.ascontiguousarray(ys.T, dtype=float)
        c_out, pp = self._lib.al_out, self._pp
        size, rows = out.itemsize * out.shape[1], yt.itemsize * yt.shape[1]
        o, y = out.ctypes.data, yt.ctypes.data
        for i, tt in enumerate(times):
            clock[0] = t = float(tt)
            code = c_out(t, y + i * rows, pp, o + i * size)
            if code:
                _raise(code, t)
        return out[:, : self._nout]

    def stepper(
        self, t0: float, y0: Sequence[float], step: float, abserr: float, relerr: float
    ) -> CStepper:
        """Kutta-Merson from ``(t0, y0)`` inside the library."""
        return CStepper(self._lib, self._p, t0, y0, step, abserr, relerr)


#: ``al_advance`` keeps its budget in static variables: one call at a time
_ADVANCE_LOCK = threading.Lock()


class CStepper:
    """The library's ``al_advance`` (:data:`.kutta.ADVANCE_C`): ``advance``
    integrates ``y`` from ``t`` to a target time in one compiled call.
    ``max_evals`` and ``seconds`` (processor time, 0: none) bound the call;
    ``evals`` counts the evaluations so far."""

    def __init__(self, lib, p, t0, y0, step, abserr, relerr) -> None:
        import numpy as np

        self._lib, self._p = lib, p  # the array stays alive for its address
        self._pp = p.ctypes.data if p.size else None
        self.y = np.array(y0, dtype=float)
        self._s = np.array([t0, 0.0, t0, 0.0])  # t, sub-step, failure, seconds
        self._n = np.array([20, 0, 0], dtype=np.int64)  # cuts, evals, budget
        self._args = (float(step), float(abserr), float(relerr))
        self.max_evals = 5_000_000
        self.seconds = 0.0

    @property
    def t(self) -> float:
        return float(self._s[0])

    @property
    def evals(self) -> int:
        return int(self._n[1])

    def advance(self, target: float) -> None:
        self._s[3] = self.seconds
        self._n[2] = self.max_evals
        with _ADVANCE_LOCK:
            code = self._lib.al_advance(
                float(target),
                *self._args,
                self._pp,
                self.y.ctypes.data,
                self._s.ctypes.data,
                self._n.ctypes.data,
            )
        if code == 1:
            _raise(code, float(self._s[2]))
        if code:
            raise StepError(code, float(self._s[2]))


#: a compiled evaluation whose value is not finite
NOT_FINITE = "a value is not finite (division by zero or a math domain error)"


def _raise(code: int, t: float) -> None:
    if code == 1:
        raise SingularMatrixError(t)
    raise ValueError(NOT_FINITE)


def load_library(path: Path) -> Any:
    """The compiled model at ``path`` (``ctypes``), its functions typed."""
    try:
        lib = ctypes.CDLL(str(path))
    except OSError as exc:
        raise BackendError(f"cannot load the compiled model {path}: {exc}") from None
    for name in ("al_rhs", "al_out"):
        fn = getattr(lib, name)
        fn.argtypes = [
            ctypes.c_double,
            ctypes.c_void_p,
            ctypes.c_void_p,
            ctypes.c_void_p,
        ]
        fn.restype = ctypes.c_int
    lib.al_advance.argtypes = [ctypes.c_double] * 4 + [ctypes.c_void_p] * 4
    lib.al_advance.restype = ctypes.c_int
    return lib


def _build_c(spec: DynamicsSpec) -> Compiled:
    import time

    start = time.perf_counter()
    path, hit = build_stream(c_model_stream(spec))
    lib = load_library(path)
    ny = len(spec.states)
    nout = sum(map(len, spec.outputs))
    rows = [len(r) for r in spec.outputs]

    def bind(values: Sequence[float]) -> Bound:
        return _CBound(lib, ny, nout, rows, values)

    return Compiled("c", bind, time.perf_counter() - start, cache_hit=hit)
