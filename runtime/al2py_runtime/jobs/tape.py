"""A quantity at many points at once with numpy, without compiling: what a
sweep of a large quantity over a few points runs.

Compiling a large quantity (a bicycle's ``AMAT``: 5,000 intermediates)
costs seconds: its numeric form, the printed C, the compiler.  A sweep of a
hundred points in a fresh process needs none of that: here the quantity's
entries and its intermediates are walked once, in order, into a *tape* of
numpy operations (each intermediate once, each on whole arrays), and the
tape runs on every point of the grid at once.  The values are the compiled
function's (the same expressions, evaluated in double precision, within
rounding: ``tests/test_research.py`` checks 1e-12).

The expressions are those :func:`~.run.numeric_entries` makes (the job's
right-hand sides substituted but those of the names given directly and of
the constants whose Input counts; intermediates taken at other variables
rebased), walked without renaming.  A node the tape cannot take (a
derivative of an expression, a complex number, a function numpy lacks)
gives ``None``: the quantity is then compiled as usual.

The choice between the tape and a compiled function is
:func:`~.quantities.takes_tape`'s (it reads no cache: a call gives the same
numbers in any process).  The tape's digest (:meth:`Tape.digest`) also keys
the compiled function on disk (:mod:`.fingerprint`).
"""

from __future__ import annotations

import operator
import threading
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from ..intermediates import autoz
from ..vocabulary import numeric_namespace

__all__ = ["CHUNK", "Tape", "TapeKernel", "build_tape", "tape_kernel_for"]

#: points evaluated together (the tape holds one array per node and point)
CHUNK = 1024


class Unsupported(Exception):
    """A node the tape does not take: the quantity is compiled instead."""


@dataclass
class Tape:
    """Operations ``(function, slot, slot or -1, result slot)`` over slots
    holding constants, the time, the parameters (``leaves``, in argument
    order) and the results; ``outs`` are the entries' slots."""

    size: int
    consts: list[tuple[int, float]]
    time: int
    leaves: list[int]
    ops: list[tuple[Any, int, int, int]]
    outs: list[int]
    #: each operation's name (``add``, ``sin``, a sympy class), each
    #: constant's exact text: with the slots, what :meth:`digest` hashes
    names: list[str]
    texts: list[str]
    #: how many intermediates the tape evaluates
    zs: int = 0

    def digest(self) -> str:
        """What the tape computes, as text that is the same in every process
        (sha256): equal digests, equal functions of the leaves."""
        import hashlib

        h = hashlib.sha256()
        h.update(repr((self.size, self.time, self.leaves, self.outs, self.zs)).encode())
        h.update("\0".join(self.names).encode())
        h.update("\0".join(self.texts).encode())
        slots = np.fromiter(
            (k for op in self.ops for k in op[1:]), np.int64, 3 * len(self.ops)
        )
        h.update(slots.tobytes())
        h.update(np.fromiter((c[0] for c in self.consts), np.int64).tobytes())
        return h.hexdigest()

    def run(self, times: np.ndarray, params: np.ndarray) -> np.ndarray:
        """The entries at each row: ``times`` (N,), ``params`` (N, n);
        (N, entries).  Not finite where a value is not (numpy's warnings
        are silenced: the caller evaluates such points exactly)."""
        from ..collector import paused

        with paused():
            return self._run(times, params)

    def _run(self, times: np.ndarray, params: np.ndarray) -> np.ndarray:
        vals: list[Any] = [None] * self.size
        for slot, number in self.consts:
            vals[slot] = number
        vals[self.time] = times
        for j, slot in enumerate(self.leaves):
            vals[slot] = params[:, j]
        with np.errstate(all="ignore"):
            for fn, a, b, out in self.ops:
                vals[out] = fn(vals[a], vals[b]) if b >= 0 else fn(vals[a])
        result = np.empty((len(times), len(self.outs)))
        for i, slot in enumerate(self.outs):
            result[:, i] = vals[slot]
        return result

    def __getstate__(self) -> dict[str, Any]:
        # the functions travel as their names (numpy's, sympy classes')
        state = dict(self.__dict__)
        state["ops"] = [op[1:] for op in self.ops]
        return state

    def __setstate__(self, state: dict[str, Any]) -> None:
        slots = state.pop("ops")
        self.__dict__.update(state)
        self.ops = [
            (_named(name, 1 if b < 0 else 2), a, b, out)
            for name, (a, b, out) in zip(self.names, slots, strict=True)
        ]


class TapeKernel:
    """A :class:`Tape` in the place of a compiled :class:`~.quantities.Kernel`
    (``table(ts, P)``).  It pickles as the tape (operations by name, slots,
    constants), and a process that unpickles it makes it once
    (:func:`tape_kernel_for`, keyed by the tape's digest)."""

    backend = "numpy"
    vectorized = True

    def __init__(self, tape: Tape, n_params: int, n_out: int) -> None:
        self.tape = tape
        self.n_params = n_params
        self.n_out = n_out

    def table(self, ts: np.ndarray, params: np.ndarray) -> np.ndarray:
        ts = np.ascontiguousarray(ts, dtype=float).reshape(-1)
        params = np.asarray(params, dtype=float).reshape(len(ts), self.n_params)
        parts = [
            self.tape.run(ts[a : a + CHUNK], params[a : a + CHUNK])
            for a in range(0, len(ts), CHUNK)
        ]
        return np.concatenate(parts) if parts else np.empty((0, self.n_out))

    def __reduce__(self) -> Any:
        return (tape_kernel_for, (self.tape, self.n_params, self.n_out))


#: tape kernels unpickled in this process, by their tape's digest
_TAPES: dict[str, TapeKernel] = {}
_TAPES_LOCK = threading.Lock()


def tape_kernel_for(tape: Tape, n_params: int, n_out: int) -> TapeKernel:
    """The kernel of ``tape``, made once per process (what unpickling a
    :class:`TapeKernel` calls: a worker makes each model once)."""
    key = tape.digest()
    with _TAPES_LOCK:
        found = _TAPES.get(key)
        if found is None:
            found = _TAPES[key] = TapeKernel(tape, n_params, n_out)
    return found


def tapes_built() -> int:
    """How many tapes this process has received (and made kernels of)."""
    return len(_TAPES)


# ------------------------------------------------------------------ building


def _inverse_sqrt(a: Any) -> Any:
    return 1.0 / np.sqrt(a)


_FUNCS: dict[tuple[type, int], Any] = {}


def _function(tp: type, n: int) -> Any:
    """numpy's version of the function class ``tp`` of ``n`` arguments
    (numpy's own for the common ones, else ``lambdify``'s translation, with
    Autolev's functions), kept."""
    key = (tp, n)
    found = _FUNCS.get(key)
    if found is None and not _FUNCS:
        _FUNCS.update(
            {
                (sp.sin, 1): np.sin,
                (sp.cos, 1): np.cos,
                (sp.tan, 1): np.tan,
                (sp.asin, 1): np.arcsin,
                (sp.acos, 1): np.arccos,
                (sp.atan, 1): np.arctan,
                (sp.atan2, 2): np.arctan2,
                (sp.sinh, 1): np.sinh,
                (sp.cosh, 1): np.cosh,
                (sp.tanh, 1): np.tanh,
                (sp.exp, 1): np.exp,
                (sp.log, 1): np.log,
                (sp.Abs, 1): np.abs,
                (sp.sign, 1): np.sign,
            }
        )
        found = _FUNCS.get(key)
    if found is None:
        xs = sp.symbols(f"x0:{n}")
        try:
            template = tp(*xs)
        except Exception as exc:  # noqa: BLE001 - any class sympy may hold
            raise Unsupported(tp.__name__) from exc
        if type(template) is not tp:
            raise Unsupported(tp.__name__)
        func = sp.lambdify(xs, template, modules=[numeric_namespace(), "numpy"])
        found = _FUNCS[key] = func
    return found


def build_tape(entries: Iterable[Any], time: Any) -> tuple[Tape, list[Any]] | None:
    """The tape of ``entries`` (numeric expressions of the time ``time``,
    constants, functions of time, their derivatives and intermediates) and
    its parameters (the objects, in argument order); None if a node is one
    the tape does not take."""
    from ..collector import paused

    try:
        with paused():
            return _build(list(entries), time)
    except Unsupported:
        return None


#: a node on the walk's stack whose arguments are done
_READY = object()


def _build(entries: list[Any], time: Any) -> tuple[Tape, list[Any]]:
    # Nodes are keyed by themselves: a dict finds the same object by
    # identity before it compares, and equal nodes share a slot.
    slots: dict[Any, int] = {}
    consts: list[tuple[int, float]] = []
    texts: list[str] = []
    leaves: list[int] = []
    params: list[Any] = []
    ops: list[tuple[Any, int, int, int]] = []
    names: list[str] = []
    count = [0]

    def new() -> int:
        count[0] += 1
        return count[0] - 1

    def put(e: Any, slot: int) -> None:
        slots[e] = slot

    def number(value: float, text: str) -> int:
        slot = new()
        consts.append((slot, value))
        texts.append(text)
        return slot

    def leaf(e: Any) -> None:
        put(e, new())
        leaves.append(slots[e])
        params.append(e)

    put(time, new())
    zs = 0
    Z = autoz.Intermediate
    outs = []
    for root in entries:
        stack: list[tuple[Any, Any]] = [(root, None)]
        while stack:
            e, body = stack.pop()
            if e in slots:
                continue
            if body is _READY:  # its arguments done
                put(e, _operation(e, slots, ops, names, new))
                continue
            if body is not None:  # an intermediate, its definition done
                put(e, slots[body])
                zs += 1
                continue
            if isinstance(e, Z):
                body = e.book.definition(e)
                stack.append((e, body))
                stack.append((body, None))
                continue
            args = e.args
            if not args:
                if e.is_Symbol:
                    leaf(e)
                elif e.is_Number or e.is_NumberSymbol:
                    try:
                        value = float(e)
                    except (TypeError, ValueError):
                        raise Unsupported(str(e)) from None
                    put(e, number(value, _text(e)))
                else:
                    raise Unsupported(str(e))
                continue
            if isinstance(e, AppliedUndef) or (
                isinstance(e, sp.Derivative) and isinstance(e.expr, AppliedUndef)
            ):
                leaf(e)
                continue
            missing = [(a, None) for a in args if a not in slots]
            if missing:
                stack.append((e, _READY))
                stack.extend(missing)
                continue
            put(e, _operation(e, slots, ops, names, new))
        outs.append(slots[root])
    tape = Tape(count[0], consts, 0, leaves, ops, outs, names, texts, zs)
    return tape, params


def _text(e: Any) -> str:
    """A number's exact text (a float's binary digits, a fraction)."""
    if isinstance(e, sp.Float):
        return f"F{e._mpf_}"
    if isinstance(e, sp.Rational):
        return f"Q{e.p}/{e.q}"
    return f"{type(e).__name__}"  # pi, E, oo...


def _operation(e: Any, slots: dict, ops: list, names: list, new: Any) -> int:
    """The operations of the node ``e``, whose arguments have slots; its
    result's slot."""
    if not isinstance(e, sp.Expr) or isinstance(e, sp.Derivative):
        raise Unsupported(type(e).__name__)
    args = [slots[a] for a in e.args]
    if e.is_Add or e.is_Mul:
        # operator's functions: no Python frame per operation
        fn, name = (operator.add, "add") if e.is_Add else (operator.mul, "mul")
        acc = args[0]
        for b in args[1:]:
            out = new()
            ops.append((fn, acc, b, out))
            names.append(name)
            acc = out
        return acc
    if e.is_Pow:
        base, exp = args
        if e.exp.is_Number:
            if e.exp == 1:  # x**1, unevaluated
                return base
            power = _POWERS.get(e.exp)
            if power is not None:
                out = new()
                ops.append((_OPS[power], base, -1, out))
                names.append(power)
                return out
        out = new()
        ops.append((np.power, base, exp, out))
        names.append("power")
        return out
    if len(args) > 2:
        raise Unsupported(type(e).__name__)  # rare: compiled instead
    tp = type(e)
    func = _function(tp, len(args))
    out = new()
    ops.append((func, args[0], args[1] if len(args) == 2 else -1, out))
    names.append(f"{tp.__module__}.{tp.__qualname__}")
    return out


#: powers with a function of their own (the same numbers as ``x**2``,
#: ``x**-1``...)
_POWERS = {2: "square", -1: "reciprocal", sp.S.Half: "sqrt", -sp.S.Half: "inverse_sqrt"}

#: operations by their names in a tape
_OPS = {
    "add": operator.add,
    "mul": operator.mul,
    "power": np.power,
    "square": np.square,
    "reciprocal": np.reciprocal,
    "sqrt": np.sqrt,
    "inverse_sqrt": _inverse_sqrt,
}


def _named(name: str, n: int) -> Any:
    """The function of the operation ``name`` (of ``n`` arguments): one of
    :data:`_OPS`, or a sympy function class's, ``module.class``."""
    found = _OPS.get(name)
    if found is not None:
        return found
    import importlib

    module, _, qualname = name.rpartition(".")
    try:
        tp = getattr(importlib.import_module(module), qualname)
    except (ImportError, AttributeError) as exc:
        raise Unsupported(name) from exc
    return _function(tp, n)
