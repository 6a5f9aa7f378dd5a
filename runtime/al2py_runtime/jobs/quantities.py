"""Named quantities compiled once: ``evaluate()`` at the speed of a
right-hand side.

``model.evaluate("AMAT", U6=-4/0.3)`` used to substitute and walk the
quantity's intermediates at every call.  Here a quantity is turned into a
numeric function once, by the machinery that compiles a job's right-hand
side (:mod:`.backends`): its entries become the outputs of a
:class:`~.backends.DynamicsSpec` with no states, whose parameters are every
constant, variable, specified quantity and derivative it needs, and its
named intermediates are evaluated once each, in order.  Later calls only
gather the values and call that function: microseconds for the C backend.

Any value may be a numpy array: the values are broadcast together, and the
result carries their shape in front of the quantity's own
(:func:`evaluate_compiled`).

A :class:`Kernel` (the compiled function) pickles as its source (C
translation units, or the Python ``lambdify`` wrote), never as sympy trees,
and a process that unpickles it builds it once (:func:`kernel_for`): what a
sweep sends to the workers of an executor (:mod:`.sweep`).

>>> import numpy as np
>>> from al2py_runtime import Workspace
>>> al = Workspace("q.al")
>>> a, b = al.constants("A", "B")
>>> x = al.variables("X")
>>> _ = al.assign("E", a * x**2 + b)
>>> al.numerics.input({"A": 2, "B": 1})
>>> al.numerics.evaluate_name("E", X=3)
19.0
>>> al.numerics.evaluate_name("E", X=np.array([0.0, 1.0, 2.0]))
array([1., 3., 9.])
"""

from __future__ import annotations

import hashlib
import inspect
import json
import os
import tempfile
import threading
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import sympy as sp

from ..vocabulary import numeric_namespace
from . import backends
from .records import INTEGRATION_DEFAULTS, Job, NumericsError, normalize_name

__all__ = [
    "CompiledQuantity",
    "Kernel",
    "compile_quantity",
    "evaluate_compiled",
    "kernel_for",
    "kernels_built",
    "split_given",
]

#: up to this many intermediates a quantity is compiled by ``lambdify`` (a
#: few milliseconds, no compiler started); beyond it by the C backend when
#: there is a compiler (a bicycle's ``aMat``: 17 us a call instead of 1.3 ms)
SMALL = 300


# ------------------------------------------------------------------ kernels


class Kernel:
    """``f(t, p) -> values``, compiled: ``table(ts, P)`` evaluates it at
    every row of ``P`` (one parameter vector per row).

    It pickles as ``(backend, source)``: the C translation units or the
    Python source that ``lambdify`` wrote.  Unpickled in another process it
    is built once there (:func:`kernel_for`, keyed by the source's hash)."""

    def __init__(
        self,
        backend: str,
        source: Any,
        n_params: int,
        n_out: int,
        key: str,
        source_file: Path | None = None,
    ) -> None:
        self.backend = backend
        self._source = source
        #: where the source is kept (a kernel loaded from the disk cache
        #: reads it only when it is sent to a worker)
        self._source_file = source_file
        self.n_params = n_params
        self.n_out = n_out
        self.key = key
        #: the compiled library (the C backend), once built or loaded
        self.library: Path | None = None
        self._call: Any = None
        self._lock = threading.Lock()

    @property
    def source(self) -> Any:
        """The C translation units ``[(text, flags)]`` or the Python source."""
        if self._source is None and self._source_file is not None:
            units = json.loads(self._source_file.read_text(encoding="utf-8"))
            self._source = [(text, tuple(flags)) for text, flags in units]
        return self._source

    def __reduce__(self) -> tuple:
        return (kernel_for, (self.backend, self.source, self.n_params, self.n_out))

    def load(self) -> Any:
        """Build (or load) the compiled function, once; returns it."""
        with self._lock:
            if self._call is None:
                if self.backend == "c":
                    self._call, self.library = _load_c(self.source, self.n_out)
                else:
                    self._call = _load_python(self.source)
                _BUILT[0] += 1
        return self._call

    def attach(self, func: Any) -> None:
        """Use ``func``, the function just built from :attr:`source` (it
        need not be built again)."""
        with self._lock:
            if self._call is None:
                self._call = func

    def table(self, ts: np.ndarray, params: np.ndarray) -> np.ndarray:
        """The values at each row: ``ts`` (N,), ``params`` (N, n_params);
        returns (N, n_out)."""
        call = self._call if self._call is not None else self.load()
        ts = np.ascontiguousarray(ts, dtype=float).reshape(-1)
        params = np.ascontiguousarray(params, dtype=float).reshape(
            len(ts), self.n_params
        )
        if self.backend == "c":
            return call(ts, params)
        out = np.empty((len(ts), self.n_out))
        for i, (tt, row) in enumerate(zip(ts.tolist(), params.tolist(), strict=True)):
            try:
                out[i] = call(tt, *row)
            except (ValueError, ZeroDivisionError, OverflowError):
                out[i] = np.nan  # the exact path says what went wrong
        return out


#: kernels built in this process, by the hash of their source
_KERNELS: dict[str, Kernel] = {}
_KERNELS_LOCK = threading.Lock()
#: how many kernels this process has built from their source
_BUILT = [0]


def kernels_built() -> int:
    """How many kernels this process has built (or loaded) from their
    source, numpy tapes too: once per model and worker, whatever the number
    of chunks."""
    from .tape import tapes_built

    return _BUILT[0] + tapes_built()


def _key(backend: str, source: Any) -> str:
    digest = hashlib.sha256(backend.encode())
    parts = source if isinstance(source, list | tuple) else [(source, ())]
    for text, flags in parts:
        digest.update(b"\0" + text.encode() + b"\0" + " ".join(flags).encode())
    return digest.hexdigest()[:24]


def kernel_for(backend: str, source: Any, n_params: int, n_out: int) -> Kernel:
    """The kernel of ``source``, built once per process (what unpickling a
    :class:`Kernel` calls: a worker builds each model once, not per task)."""
    key = _key(backend, source)
    with _KERNELS_LOCK:
        found = _KERNELS.get(key)
        if found is None:
            found = _KERNELS[key] = Kernel(backend, source, n_params, n_out, key)
    return found


def _load_c(units: Sequence[tuple[str, Sequence[str]]], n_out: int) -> Any:
    path, _hit = backends.build_stream(iter(units))
    return _open_c(path, n_out), path


def _open_c(path: Any, n_out: int) -> Any:
    """The compiled library at ``path`` as ``call(ts, params) -> rows``."""
    lib = backends.load_library(path)
    c_out = lib.al_out
    width = max(n_out, 1)
    dummy = np.zeros(1)

    def call(ts: np.ndarray, params: np.ndarray, _keep: Any = lib) -> np.ndarray:
        out = np.empty((len(ts), width))
        stride_p = params.itemsize * params.shape[1]
        stride_o = out.itemsize * width
        p0, o0, y = params.ctypes.data, out.ctypes.data, dummy.ctypes.data
        for i, tt in enumerate(ts.tolist()):
            code = c_out(tt, y, p0 + i * stride_p, o0 + i * stride_o)
            if code:
                out[i] = np.nan
        return out[:, :n_out]

    return call


def _load_python(source: str) -> Any:
    """The function ``lambdify`` wrote, from its source, in the namespace
    ``lambdify`` gives (the math module and Autolev's functions)."""
    space = dict(_namespace())
    exec(compile(source, "<al2py quantity>", "exec"), space)  # noqa: S102
    return space["_lambdifygenerated"]


def _namespace() -> dict[str, Any]:
    probe = sp.lambdify([], [], modules=[numeric_namespace(), "math"])
    return probe.__globals__


def build_kernel(
    time: Any,
    params: Sequence[Any],
    exprs: Sequence[Any],
    intermediates: Sequence[tuple[Any, Any]],
    backend: str | None = None,
) -> Kernel:
    """Compile ``exprs`` (of ``time``, ``params`` and ``intermediates``).

    ``backend``: ``"c"`` or ``"lambdify"``; ``None``/``"auto"`` (or
    ``$AL2PY_BACKEND``) takes ``lambdify`` up to :data:`SMALL`
    intermediates and C beyond when a compiler is there.  ``llvm`` compiles
    whole expressions only, so a quantity takes ``lambdify`` for it."""
    name = backends.choose(backend)
    if name == "auto":
        big = len(intermediates) > SMALL
        name = "c" if big and backends.available("c") else "lambdify"
    if name == "c":
        spec = backends.DynamicsSpec(
            time, [], [], list(params), [], [], [], [list(exprs)], list(intermediates)
        )
        units: list[tuple[str, tuple[str, ...]]] = []

        def printed() -> Any:
            # each unit compiles while the next one is printed; the text is
            # kept, what a worker receives
            for unit in backends.c_model_stream(spec):
                units.append(unit)
                yield unit

        try:
            path, _hit = backends.build_stream(printed())
            kernel = kernel_for("c", units, len(params), len(exprs))
            kernel.attach(_open_c(path, len(exprs)))
            kernel.library = path
            return kernel
        except backends.BackendError as exc:
            if backends.choose(backend) != "auto":
                raise
            backends.say_once(f"using the lambdify backend (slower): {exc}")
    func = backends.lambdify_job([time, *params], list(exprs), intermediates)
    try:
        source = inspect.getsource(func)
    except (OSError, TypeError):  # pragma: no cover - lambdify keeps its source
        source = None
    if source is None or func.__name__ != "_lambdifygenerated":
        # ``lambdify_job`` of no expressions: nothing to compile
        source = "def _lambdifygenerated(*args):\n    return []\n"
    kernel = kernel_for("lambdify", source, len(params), len(exprs))
    kernel.attach(func)
    return kernel


# --------------------------------------------------------------- quantities


@dataclass
class CompiledQuantity:
    """A named quantity compiled: its shape (``()`` for a scalar, ``(m, n)``
    for a matrix), the Autolev names of its parameters in argument order,
    what each is (``constant``, ``variable``, ``specified``, ``derivative``,
    ``other``) and its :class:`Kernel`."""

    name: str
    shape: tuple[int, ...]
    params: list[str]
    kinds: list[str]
    kernel: Kernel
    notes: list[str] = field(default_factory=list)
    #: how it was made: ``compiled`` here, loaded from ``disk``
    #: (:func:`load_plan`), or a ``numpy`` tape (:func:`tape_quantity`)
    origin: str = "compiled"


def split_given(job: Job, given: Mapping[str, Any]) -> tuple[dict, dict]:
    """``(settable, free)``: values of Inputs and integration settings (in
    the Input's units) and of any other name (in internal units, radians)."""
    settable, free = {}, {}
    for key, value in given.items():
        key = normalize_name(key)
        if key in job.inputs or key in INTEGRATION_DEFAULTS:
            settable[key] = value
        else:
            free[key] = value
    return settable, free


def _entries(
    job: Job, value: Any, free: frozenset[str]
) -> tuple[list, tuple[int, ...], list]:
    """``(drop, shape, entries)`` of a quantity: the objects of the names
    given directly (their right-hand sides are not substituted), its shape
    (``()`` for a scalar) and its entries in order."""
    drop = [obj for key, (_kind, obj) in job.entries.items() if key in free]
    if isinstance(value, sp.MatrixBase):
        return drop, tuple(value.shape), list(value)
    return drop, (), [value]


def _labelled(job: Job, params: Sequence[Any]) -> tuple[list, list]:
    """``(labels, kinds)`` of a quantity's parameters, in order."""
    from .run import label_of

    labels = [label_of(obj, job.names) for obj in params]
    kinds = [_kind(job, o, label) for o, label in zip(params, labels, strict=True)]
    return labels, kinds


def compile_quantity(
    job: Job,
    value: Any,
    name: str,
    free: frozenset[str],
    keep: frozenset[Any],
    backend: str | None = None,
) -> CompiledQuantity:
    """``value`` (a scalar or matrix of the script) as a compiled function
    of its parameters.  The right-hand sides in force are substituted but
    those of the names in ``free`` (given directly) and of the constants in
    ``keep`` (whose Input replaces the value the script gave)."""
    from .run import numeric_entries

    drop, shape, entries = _entries(job, value, free)
    made = numeric_entries(job, entries, [*drop, *keep], name)
    labels, kinds = _labelled(job, made.params)
    kernel = build_kernel(
        made.time, made.dummies, made.exprs, made.intermediates, backend
    )
    return CompiledQuantity(name, shape, labels, kinds, kernel)


#: a sweep of at most this many points of a large quantity runs its numpy
#: tape (:func:`takes_tape`): a few tenths of a second for the bicycle's
#: ``AMAT`` against seconds to print and compile it; beyond, the compiled
#: function's microseconds a point win
ONE_SHOT_POINTS = 20_000


def takes_tape(
    tape: CompiledQuantity | None, points: int | None, backend: str | None
) -> bool:
    """Whether a sweep of ``points`` points (None: ``evaluate()``) runs the
    quantity's numpy tape rather than a compiled function.  The rule looks
    at nothing that a cache holds, so that the same call gives the same
    numbers in any process, serially or on any executor:

    * ``backend="numpy"``: always;
    * the default backend (no ``backend=``, ``AL2PY_BACKEND`` unset or
      ``auto``): a sweep of at most :data:`ONE_SHOT_POINTS` points of a
      quantity of more than :data:`SMALL` intermediates (one that C would
      compile: seconds of printing and compiling, against tenths of a
      second for the tape);
    * else never."""
    if tape is None:
        return False
    if backend is not None:
        return backend.strip().lower() == "numpy"
    if os.environ.get("AL2PY_BACKEND", "auto").strip().lower() not in ("", "auto"):
        return False
    if points is None or points > ONE_SHOT_POINTS:
        return False
    return tape.kernel.tape.zs > SMALL  # type: ignore[attr-defined]


def plan_quantity(
    job: Job,
    value: Any,
    name: str,
    free: frozenset[str],
    keep: frozenset[Any],
    backend: str | None = None,
    *,
    tape: CompiledQuantity | None = None,
) -> CompiledQuantity:
    """``value`` compiled, the cheapest way at hand: the function compiled
    earlier for the same key (by any process, with this runtime) loaded
    from disk in milliseconds, else compiled (:func:`compile_quantity`) and
    kept on disk.  The key (:func:`disk_key`) is the digest of the
    quantity's numpy tape ``tape`` (:func:`tape_quantity`), found without
    printing anything; without a tape the quantity is compiled and not
    kept."""
    key = disk_key(tape, backend) if tape is not None else None
    plan = load_plan(key) if key is not None else None
    if plan is not None:
        return plan
    plan = compile_quantity(job, value, name, free, keep, backend)
    if key is not None and plan.kernel.backend == _resolved(tape, backend):
        store_plan(key, plan)
    return plan


def _resolved(tape: Any, backend: str | None) -> str:
    """The backend :func:`build_kernel` takes for ``tape``'s quantity: C
    for more than :data:`SMALL` intermediates when there is a compiler
    (``auto``), else ``lambdify`` (also for ``llvm``)."""
    name = backends.choose(backend)
    if name == "auto":
        big = tape.kernel.tape.zs > SMALL
        return "c" if big and backends.available("c") else "lambdify"
    return "c" if name == "c" else "lambdify"


def tape_quantity(
    job: Job, value: Any, name: str, free: frozenset[str], keep: frozenset[Any]
) -> CompiledQuantity | None:
    """``value`` as a numpy :class:`~.tape.Tape` (the expressions that
    :func:`~.run.numeric_entries` makes, not renamed); None if it holds a
    node the tape does not take."""
    from ..collector import paused
    from ..intermediates import autoz
    from .run import resolved_entries, t
    from .tape import TapeKernel, build_tape

    drop, shape, entries = _entries(job, value, free)
    exprs = []
    with paused():
        for e in resolved_entries(job, entries, [*drop, *keep]):
            book = autoz.book_of(e)
            exprs.append(book.rebase(e) if book is not None else e)
    made = build_tape(exprs, t)
    if made is None:
        return None
    tape, objs = made
    labels, kinds = _labelled(job, objs)
    kernel = TapeKernel(tape, len(objs), len(exprs))
    return CompiledQuantity(
        name, shape, labels, kinds, kernel, origin="numpy"  # type: ignore[arg-type]
    )


# ------------------------------------------------------------- on disk

#: a change of the sidecar's layout changes this
SIDECAR = 1


def disk_key(tape: CompiledQuantity, backend: str | None) -> str:
    """The key of the compiled quantity on disk (:mod:`.fingerprint`): its
    tape's digest, name, shape, parameters and their kinds, the runtime,
    the backend chosen, and the compiler and its flags."""
    from .fingerprint import quantity_key

    compiler = backends.find_compiler() if backends.available("c") else None
    extra = [
        f"backend={_resolved(tape, backend)}",  # the default and "c" share C
        f"small={SMALL}",
        f"cc={compiler}",
        f"flags={backends.C_FLAGS}",
        f"sidecar={SIDECAR}",
    ]
    return quantity_key(
        tape.kernel.tape,  # type: ignore[attr-defined]
        normalize_name(tape.name),
        tape.shape,
        tape.params,
        tape.kinds,
        extra,
    )


def _disk() -> Path:
    folder = backends.cache_folder() / "quantities"
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def store_plan(key: str, plan: CompiledQuantity) -> None:
    """Keep ``plan`` (compiled by C) on disk under ``key``: a JSON sidecar
    with what the compiled quantity needs besides the library (shape,
    parameter names in argument order, their kinds, the kernel's size and
    key, the library's name), and the C units (read only when the kernel
    is sent to an executor's workers).  Nothing is kept if the cache cannot
    be written (it is only a cache)."""
    kernel = plan.kernel
    if not isinstance(kernel, Kernel) or kernel.backend != "c":
        return  # lambdify builds in milliseconds, and writes nothing to disk
    meta: dict[str, Any] = {
        "sidecar": SIDECAR,
        "key": key,
        "name": plan.name,
        "shape": list(plan.shape),
        "params": list(plan.params),
        "kinds": list(plan.kinds),
        "backend": kernel.backend,
        "n_params": kernel.n_params,
        "n_out": kernel.n_out,
        "kernel": kernel.key,
    }
    try:
        if kernel.library is None:
            return
        folder = _disk()
        meta["library"] = kernel.library.name
        units = [[text, list(flags)] for text, flags in kernel.source]
        _write(folder / f"{key}.units.json", json.dumps(units))
        _write(folder / f"{key}.json", json.dumps(meta, indent=1))
    except OSError:
        return


def _write(path: Path, text: str) -> None:
    """``text`` into ``path`` atomically (a reader sees all or nothing)."""
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".tmp_", suffix=path.suffix)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def load_plan(key: str) -> CompiledQuantity | None:
    """The plan kept on disk under ``key`` (:func:`store_plan`), its
    library loaded; None if there is none, or it cannot be used (a
    library removed, a sidecar unreadable): then it is compiled again."""
    try:
        folder = backends.cache_folder() / "quantities"
        path = folder / f"{key}.json"
        if not path.exists():
            return None
        meta = json.loads(path.read_text(encoding="utf-8"))
        if meta.get("sidecar") != SIDECAR or meta.get("key") != key:
            return None
        n_params, n_out = int(meta["n_params"]), int(meta["n_out"])
        if meta["backend"] != "c":
            return None
        library = backends.cache_folder() / meta["library"]
        units = folder / f"{key}.units.json"
        if not (library.exists() and units.exists()):
            return None
        call = _open_c(library, n_out)
        with _KERNELS_LOCK:
            kernel = _KERNELS.get(meta["kernel"])
            if kernel is None:
                kernel = Kernel("c", None, n_params, n_out, meta["kernel"], units)
                _KERNELS[meta["kernel"]] = kernel
        kernel.attach(call)
        kernel.library = library
        return CompiledQuantity(
            meta["name"],
            tuple(meta["shape"]),
            list(meta["params"]),
            list(meta["kinds"]),
            kernel,
            origin="disk",
        )
    except (OSError, ValueError, KeyError, TypeError, backends.BackendError):
        return None


def _kind(job: Job, obj: Any, label: str) -> str:
    if isinstance(obj, sp.Derivative):
        return "derivative"
    entry = job.entries.get(normalize_name(label))
    return entry[0] if entry is not None else "other"


# ---------------------------------------------------------------- evaluating


@dataclass
class Points:
    """Parameter values at every point of a broadcast: ``times`` (N,),
    ``params`` (N, n) in internal units, the broadcast ``shape`` (N is its
    size) and the notes the values raised (a Specified quantity taken as 0)."""

    times: np.ndarray
    params: np.ndarray
    shape: tuple[int, ...]
    notes: list[str]


def gather(
    job: Job,
    plan: CompiledQuantity,
    settable: Mapping[str, Any],
    free: Mapping[str, Any],
    zero_missing: bool | None = None,
) -> Points:
    """The values of ``plan``'s parameters at each point: the Inputs (in
    internal units), ``settable`` (Input names, in the Input's units) and
    ``free`` (other names, internal units), each possibly an array;
    broadcast together.

    A value nobody gave follows the rule of a run,
    :func:`~.run.missing_value_rule`: a Specified quantity, a variable or
    a derivative with no equation is 0 (noted), a constant stops with its
    name and line unless ``zero_missing`` (then 0, noted)."""
    from .run import input_values, missing_value_rule

    arrays = {k: _as_array(k, v) for k, v in {**settable, **free}.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        raise NumericsError(
            f"{plan.name}: the values' shapes do not broadcast together ({shapes})"
        ) from None
    size = int(np.prod(shape)) if shape else 1
    first = {k: a.reshape(-1)[0] if a.size else 0.0 for k, a in arrays.items()}
    vals, _keep = input_values(
        job, {k: first[k] for k in settable}, zero_missing=zero_missing
    )
    columns: dict[str, Any] = dict(vals.values)
    computed = any(isinstance(v.value, sp.Basic) for v in job.inputs.values())
    varying = [k for k in settable if arrays[k].size > 1]
    if varying and computed:
        # Inputs computed from other Inputs (``Input E = COS(Q/2)``) follow
        # each point's values: the run's own conversion, point by point.
        flat = {k: np.broadcast_to(arrays[k], shape).reshape(-1) for k in settable}
        rows = [
            input_values(job, {k: flat[k][i] for k in settable}, zero_missing)[0]
            for i in range(size)
        ]
        for key in rows[0].values:
            columns[key] = np.array([r.values[key] for r in rows])
    else:
        for key in settable:
            unit = job.inputs[key].unit if key in job.inputs else None
            factor = job.unit_system.to_internal(unit) if unit else 1.0
            columns[key] = arrays[key] * factor
    for key in free:
        columns[key] = arrays[key]
    zeros: list[str] = []
    missing: list[str] = []
    params = np.empty((size, len(plan.params)))
    for j, label in enumerate(plan.params):
        key = normalize_name(label)
        if key in columns:
            params[:, j] = np.broadcast_to(columns[key], shape).reshape(-1)
            continue
        params[:, j] = 0.0
        zero, text = missing_value_rule(job, label, vals.zero_missing)
        if zero:
            zeros.append(text)
        else:
            missing.append(label)
    if missing:
        raise NumericsError(_missing_message(job, plan.name, missing))
    notes = list(dict.fromkeys(zeros))
    if "T" in columns:
        times = np.broadcast_to(columns["T"], shape).reshape(-1)
    else:
        times = np.full(size, float(vals.values.get("TINITIAL", 0.0)))
    return Points(times, params, tuple(shape), notes)


def _as_array(key: str, value: Any) -> np.ndarray:
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise NumericsError(f"{key} = {value!r} is not a number") from None


def _missing_message(job: Job, name: str, missing: list[str]) -> str:
    listed = []
    for label in dict.fromkeys(missing):
        line = job.declared.get(normalize_name(label))
        listed.append(f"{label} (declared on line {line})" if line else label)
    return (
        f"{name} needs a value for {', '.join(listed)}: give it as a keyword"
        " argument or with Input, or use 0 with zero_missing=True"
    )


def evaluate_compiled(
    job: Job,
    plan: CompiledQuantity,
    given: Mapping[str, Any],
    exact: Any,
    zero_missing: bool | None = None,
) -> Any:
    """``plan`` at the values ``given`` (see :func:`gather`): a float for a
    scalar at one point, else an array of shape (broadcast shape + the
    quantity's shape).  A point where the compiled value is not finite is
    evaluated by ``exact(point)`` (the substituting path, which says what
    went wrong or gives the complex value)."""
    settable, free = split_given(job, given)
    points = gather(job, plan, settable, free, zero_missing)
    from .run import warn_notes

    warn_notes(points.notes)  # MissingValueWarning, as run() warns
    out = plan.kernel.table(points.times, points.params)
    return finish(plan, points, out, given, exact)


def finish(
    plan: CompiledQuantity,
    points: Points,
    out: np.ndarray,
    given: Mapping[str, Any],
    exact: Any,
) -> Any:
    """The kernel's rows ``out`` shaped as the result; rows that are not
    finite are evaluated by ``exact``."""
    bad = ~np.all(np.isfinite(out), axis=1) if out.size else np.zeros(0, bool)
    if bad.any():
        arrays = {k: np.asarray(v) for k, v in given.items()}
        rows: list[Any] = list(out)
        for i in np.flatnonzero(bad).tolist():
            index = np.unravel_index(i, points.shape) if points.shape else ()
            point = {
                k: float(np.broadcast_to(a, points.shape)[index]) if a.ndim else v
                for (k, v), a in zip(given.items(), arrays.values(), strict=True)
            }
            rows[i] = np.asarray(exact(point)).reshape(-1)
        out = np.array(rows)
    result = out.reshape(points.shape + plan.shape)
    if not points.shape and not plan.shape:
        value = result.item()
        return value.real if isinstance(value, complex) and not value.imag else value
    return result


def quantity_key(
    name: str, free: Mapping[str, Any], keep: frozenset, backend: Any
) -> tuple:
    """What a compiled quantity depends on besides the job's values and the
    quantity's value itself (which the cache keeps and compares)."""
    return (normalize_name(name), frozenset(free), keep, backend)
