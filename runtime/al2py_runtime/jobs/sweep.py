"""Sweeps: a quantity or a ``CODE`` job over a grid of values, on one
machine or many.

``model.sweep("AMAT", U6=-speeds/0.3)`` evaluates the compiled quantity
(:mod:`.quantities`) at every point of the grid that its 1-D arrays span
(several arrays: their product, in the order given); a scalar is fixed.
``model.sweep(job="tutor6", QA=[10, 20], K=[100, 200])`` performs the job
at every point, one :class:`~.tables.Result` each.  Either way the answer
is a :class:`Sweep`.

``executor=`` takes any :class:`concurrent.futures.Executor` (a
``ProcessPoolExecutor``, or Dask's ``Client.get_executor()`` for a
cluster); ``executor="dask"`` uses the Dask client already made in this
process.  Work goes out in chunks (``chunksize`` points each; by default
about four chunks per worker), and each worker builds the model once:

* a quantity's chunk carries its :class:`~.quantities.Kernel` (the C or
  Python source, built once per worker process) or its numpy
  :class:`~.tape.Tape` (:func:`~.quantities.takes_tape`), and the
  parameter rows;
* a job's chunk carries the generated module's name and file, imported
  once per worker process, and the points' values.

The results are the serial ones, bit for bit: the same compiled code (or
tape) runs on the same values.  A sweep of more than 2 s shows its progress on
standard error when that is a terminal (:class:`~..progress.Steps`).

>>> import numpy as np
>>> import sympy as sp
>>> from al2py_runtime import Workspace
>>> al = Workspace("k.al")
>>> k, c = al.constants("K", "C")
>>> _ = al.assign("M", sp.Matrix([[0, 1], [-k, -c]]))
>>> al.numerics.input({"K": 4, "C": 0})
>>> s = al.numerics.sweep("M", C=[0.0, 1.0, 5.0])
>>> s.values.shape
(3, 2, 2)
>>> np.round(s.eigenvalues()[0], 6)
array([0.-2.j, 0.+2.j])
>>> s
<Sweep of M over C (3 points): values (3, 2, 2)>
"""

from __future__ import annotations

import html
import importlib.util
import math
import sys
import threading
from collections.abc import Callable, Mapping, Sequence
from concurrent.futures import Executor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from ..names.printing import element_labels
from ..progress import Steps
from .quantities import CompiledQuantity, Kernel, Points, finish, gather, split_given
from .records import Job, NumericsError, normalize_name

__all__ = ["Sweep", "grid", "resolve_executor", "sweep_job", "sweep_quantity"]


# --------------------------------------------------------------------- grid


def grid(
    given: Mapping[str, Any],
) -> tuple[dict[str, np.ndarray], dict[str, Any], dict[str, np.ndarray]]:
    """``(axes, fixed, at)``: the 1-D values among ``given`` (the grid's
    axes, in the order given), the scalars, and every value on the grid
    (arrays of the grid's shape; ``numpy.meshgrid`` with ``ij`` indexing).

    >>> axes, fixed, at = grid({"A": [1, 2, 3], "B": 0.5, "C": [10, 20]})
    >>> list(axes), fixed, at["C"].shape
    (['A', 'C'], {'B': 0.5}, (3, 2))
    """
    axes: dict[str, np.ndarray] = {}
    fixed: dict[str, Any] = {}
    for name, value in given.items():
        if isinstance(value, str):
            raise NumericsError(f"{name} = {value!r} is not a number")
        array = np.asarray(value)
        if array.ndim == 0:
            fixed[name] = value
        elif array.ndim == 1:
            try:
                axes[name] = array.astype(float)
            except (TypeError, ValueError):
                raise NumericsError(f"{name}: the values are not numbers") from None
        else:
            raise NumericsError(
                f"{name}: a sweep takes 1-D arrays (each spans an axis of the"
                f" grid), not an array of shape {array.shape}; evaluate()"
                " broadcasts arrays of any shape"
            )
    mesh = np.meshgrid(*axes.values(), indexing="ij") if axes else []
    at = dict(zip(axes, mesh, strict=True))
    return axes, fixed, at


# ---------------------------------------------------------------- executors


def resolve_executor(executor: Any) -> Executor | None:
    """``None`` (serial), an :class:`~concurrent.futures.Executor`, or
    ``"dask"``: the executor of the Dask client made in this process."""
    if executor is None or isinstance(executor, Executor):
        return executor
    if executor == "dask":
        try:
            from distributed import get_client
        except ImportError:
            raise NumericsError(
                "executor='dask' needs Dask: pip install 'al2py[dask]'"
                " (or 'al2py-runtime[dask]' for the runtime alone)"
            ) from None
        try:
            client = get_client()
        except ValueError:
            raise NumericsError(
                "executor='dask' uses the Dask client of this process, and"
                " there is none: make one first, e.g. `from dask.distributed"
                " import Client; client = Client()` (a cluster on this"
                " machine) or Client('scheduler-address')"
            ) from None
        return client.get_executor()
    if hasattr(executor, "submit"):  # an executor-like object
        return executor
    raise NumericsError(
        f"executor must be None, 'dask' or a concurrent.futures.Executor,"
        f" not {executor!r}"
    )


def _workers(executor: Any) -> int:
    found = getattr(executor, "_max_workers", None)
    if isinstance(found, int) and found > 0:
        return found
    client = getattr(executor, "_client", None)
    if client is not None:
        try:
            return max(1, len(client.scheduler_info().get("workers", {})))
        except Exception:  # noqa: BLE001 - any client: fall back to a guess
            return 4
    return 4


def _chunks(size: int, executor: Any, chunksize: int | None) -> list[range]:
    """Consecutive ranges of the ``size`` points: ``chunksize`` each, else
    about four per worker (serially: pieces of about a second's work)."""
    if chunksize is None:
        parts = 4 * _workers(executor) if executor is not None else 100
        chunksize = max(1, math.ceil(size / parts))
    if chunksize < 1:
        raise NumericsError(f"chunksize must be at least 1, not {chunksize}")
    return [range(a, min(a + chunksize, size)) for a in range(0, size, chunksize)]


def _run_chunks(
    work: Callable[..., Any],
    chunks: Sequence[tuple[range, tuple]],
    executor: Executor | None,
    steps: Steps,
) -> list[Any]:
    """``work(*args)`` for each chunk, in order; serially or on ``executor``."""
    if executor is None:
        out = []
        for span, args in chunks:
            out.append(work(*args))
            steps.advance(len(span))
        return out
    futures = [executor.submit(work, *args) for _span, args in chunks]
    out = []
    for (span, _args), future in zip(chunks, futures, strict=True):
        out.append(future.result())
        steps.advance(len(span))
    return out


def kernel_rows(kernel: Kernel, times: np.ndarray, params: np.ndarray) -> np.ndarray:
    """A chunk of a quantity sweep (run by a worker): the kernel's values
    at each row; the kernel is built once per process."""
    from .backends import BackendError

    try:
        return kernel.table(times, params)
    except BackendError as exc:  # a worker without a C compiler, ...
        raise NumericsError(f"a worker cannot build the model: {exc}") from None


# ------------------------------------------------------------------ sweeps


def sweep_quantity(
    job: Job,
    plan: CompiledQuantity,
    given: Mapping[str, Any],
    exact: Callable[[Mapping[str, Any]], Any],
    *,
    executor: Any = None,
    zero_missing: bool | None = None,
    chunksize: int | None = None,
) -> Sweep:
    """``plan`` at every point of the grid of ``given`` (see :func:`grid`)."""
    axes, fixed, at = grid(given)
    values = {**fixed, **at}
    settable, free = split_given(job, values)
    points = gather(job, plan, settable, free, zero_missing)
    notes = list(points.notes)
    unused = [n for n in axes if normalize_name(n) not in _used(job, plan)]
    if unused:
        notes.append(f"{', '.join(unused)} does not appear in {plan.name}")
    pool = resolve_executor(executor)
    size = len(points.times)
    if getattr(plan.kernel, "vectorized", False) and pool is None:
        # a numpy tape takes many points at once
        from .tape import CHUNK

        chunksize = chunksize or CHUNK
    ranges = _chunks(size, pool, chunksize)
    chunks = [
        (
            r,
            (
                plan.kernel,
                points.times[r.start : r.stop],
                points.params[r.start : r.stop],
            ),
        )
        for r in ranges
    ]
    with Steps(f"sweeping {plan.name}", size) as steps:
        rows = _run_chunks(kernel_rows, chunks, pool, steps)
    out = np.concatenate(rows) if rows else np.empty((0, plan.kernel.n_out))
    shaped = Points(points.times, points.params, points.shape, points.notes)
    result = finish(plan, shaped, out, values, exact)
    labels = element_labels(plan.name, *plan.shape) if plan.shape else [plan.name]
    return Sweep(
        plan.name,
        axes,
        fixed,
        values=np.asarray(result),
        labels=list(labels),
        notes=notes,
    )


def _used(job: Job, plan: CompiledQuantity) -> set[str]:
    """Names whose values reach the quantity: its parameters, the time, and
    every Input and integration setting (an Input may be computed from
    another one)."""
    from .records import INTEGRATION_DEFAULTS

    return (
        {normalize_name(p) for p in plan.params}
        | {"T"}
        | set(INTEGRATION_DEFAULTS)
        | (set(job.inputs) if _computed(job) else set())
    )


def _computed(job: Job) -> bool:
    import sympy as sp

    return any(isinstance(v.value, sp.Basic) for v in job.inputs.values())


#: generated modules imported by this (worker) process, by file
_MODULES: dict[str, Any] = {}
_MODULES_LOCK = threading.Lock()


def module_at(origin: tuple[str, str | None]) -> Any:
    """The generated module ``origin = (name, file)`` in this process: the
    one already imported from that file, else imported once from the file
    (a worker of a sweep)."""
    name, file = origin
    if file is None:
        raise NumericsError(f"the model {name} has no file to import")
    path = str(Path(file).resolve())
    with _MODULES_LOCK:
        found = _MODULES.get(path)
        if found is not None:
            return found
        for module in list(sys.modules.values()):
            mfile = getattr(module, "__file__", None)
            if mfile and hasattr(module, "al") and str(Path(mfile).resolve()) == path:
                _MODULES[path] = module
                return module
        spec = importlib.util.spec_from_file_location(f"_al2py_sweep_{name}", path)
        if spec is None or spec.loader is None:
            raise NumericsError(f"cannot import the model {path}")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        _MODULES[path] = module
        return module


def job_points(
    origin: tuple[str, str | None],
    index: int,
    points: list[dict[str, Any]],
    backend: str | None,
    zero_missing: bool | None,
) -> list[Any]:
    """A chunk of a job sweep (run by a worker): the job ``index`` of the
    module ``origin`` performed at each point."""
    from .run import run_job

    module = module_at(origin)
    job = module.al.numerics.jobs[index]
    out = []
    for p in points:
        result = run_job(job, p, backend=backend, zero_missing=zero_missing)
        # The motion holds the worker's sympy model: only its numbers
        # travel, and the parent joins them to its own model (_rejoin).
        motion, result.motion = result.motion, None
        out.append((result, None if motion is None else (motion.times, motion.ys)))
    return out


def _rejoin(
    job: Job,
    point: Mapping[str, Any],
    result: Any,
    numbers: tuple[np.ndarray, np.ndarray] | None,
    zero_missing: bool | None,
    layouts: dict,
) -> Any:
    """A worker's result with the motion its numbers make in this
    process's model (for ``result.animate()``)."""
    from .run import Motion, dynamics_layout, input_values

    if numbers is None:
        return result
    vals, keep = input_values(job, point, zero_missing)
    keep = frozenset(keep)
    if keep not in layouts:
        layouts[keep] = dynamics_layout(job, keep).state_objs
    result.motion = Motion(job, vals, keep, list(layouts[keep]), *numbers)
    return result


def sweep_job(
    job: Job,
    index: int,
    given: Mapping[str, Any],
    *,
    origin: tuple[str, str | None] | None = None,
    executor: Any = None,
    backend: str | None = None,
    zero_missing: bool | None = None,
    chunksize: int | None = None,
) -> Sweep:
    """``job`` (the ``index``-th of its script) performed at every point of
    the grid of ``given``: one :class:`~.tables.Result` per point."""
    from .run import check_overrides, run_job

    axes, fixed, at = grid(given)
    check_overrides(job, given)
    shape = tuple(len(a) for a in axes.values())
    size = int(np.prod(shape)) if shape else 1
    flat = {k: a.reshape(-1) for k, a in at.items()}
    points = [
        {**fixed, **{k: float(a[i]) for k, a in flat.items()}} for i in range(size)
    ]
    pool = resolve_executor(executor)
    if origin is not None and origin[1] is None:
        origin = None  # a module made without a file (exec of its text)
    if pool is not None and origin is None:
        raise NumericsError(
            "a job sweep on an executor needs the model's module: call the"
            " module's sweep() (model.sweep(job=..., executor=...))"
        )
    ranges = _chunks(size, pool, chunksize)
    with Steps(f"sweeping {job.stem}", size) as steps:
        if pool is None:
            results = []
            for p in points:
                results.append(
                    run_job(job, p, backend=backend, zero_missing=zero_missing)
                )
                steps.advance()
        else:
            chunks = [
                (r, (origin, index, points[r.start : r.stop], backend, zero_missing))
                for r in ranges
            ]
            parts = _run_chunks(job_points, chunks, pool, steps)
            layouts: dict = {}
            results = [
                _rejoin(job, p, res, numbers, zero_missing, layouts)
                for p, (res, numbers) in zip(
                    points, (x for part in parts for x in part), strict=True
                )
            ]
    grid_results = np.empty(size, dtype=object)
    for i, res in enumerate(results):
        grid_results[i] = res
    notes = list(dict.fromkeys(n for res in results for n in res.notes))
    return Sweep(
        job.stem,
        axes,
        fixed,
        results=grid_results.reshape(shape),
        notes=notes,
        job=True,
    )


# ------------------------------------------------------------------ results


@dataclass
class Sweep:
    """A quantity or a job over a grid of values (see the module docstring).

    ``axes``: the swept names and their values, in grid order; ``fixed``:
    the values given as scalars.  A quantity's sweep has ``values``, an
    array of shape (grid + the quantity's shape); a job's has ``results``,
    an array of :class:`~.tables.Result` of the grid's shape."""

    name: str
    axes: dict[str, np.ndarray]
    fixed: dict[str, Any] = field(default_factory=dict)
    values: np.ndarray | None = None
    results: np.ndarray | None = None
    labels: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    job: bool = False
    _eigen: np.ndarray | None = field(default=None, repr=False)

    @property
    def shape(self) -> tuple[int, ...]:
        """The grid's shape: one length per swept name."""
        return tuple(len(a) for a in self.axes.values())

    def __len__(self) -> int:
        return int(np.prod(self.shape)) if self.shape else 1

    def __repr__(self) -> str:
        over = ", ".join(self.axes) or "no name"
        what = "job" if self.job else ""
        tail = (
            f"{len(self)} results"
            if self.job
            else f"values {tuple(np.shape(self.values))}"
        )
        return (
            f"<Sweep of {what + ' ' if what else ''}{self.name} over {over}"
            f" ({len(self)} points): {tail}>"
        )

    # ----------------------------------------------------------- eigenvalues

    def eigenvalues(self) -> np.ndarray:
        """The eigenvalues of a square matrix at every point: an array of
        shape (grid + (n,)), complex.  Along the grid each column follows
        one branch: the eigenvalues at a point are matched to those of the
        point before it (along the last axis that moved) as extrapolated
        from the two before, by the assignment of least total distance, so
        that ``ev[:, k]`` is one mode (weave, capsize, castor) across a
        speed sweep.  The first point's are sorted by real part."""
        if self._eigen is not None:
            return self._eigen
        values = self._quantity_values()
        if values.ndim < 2 or values.shape[-1] != values.shape[-2]:
            raise NumericsError(
                f"eigenvalues() needs a square matrix; {self.name} is"
                f" {'x'.join(map(str, values.shape[len(self.shape):])) or 'a scalar'}"
            )
        raw = np.linalg.eigvals(values.astype(complex))
        self._eigen = follow_branches(raw, self.shape)
        return self._eigen

    def _quantity_values(self) -> np.ndarray:
        if self.values is None:
            raise NumericsError(
                f"the sweep of job {self.name} has results (one per point), not"
                " values"
            )
        return self.values

    # -------------------------------------------------------------- tables

    def to_pandas(self, eigenvalues: bool = False, table: int = 0) -> Any:
        """A tidy ``pandas.DataFrame``: one row per grid point and element
        (columns: the swept names, ``name``, ``value``); with
        ``eigenvalues=True`` one row per point and branch (the swept names,
        ``branch``, ``real``, ``imag``); for a job, the rows of each point's
        written table ``table`` (0: the first) after the swept names (a
        swept name the table also outputs is ``NAME (swept)``)."""
        try:
            import pandas as pd
        except ImportError:
            raise NumericsError(
                "to_pandas() needs pandas, which al2py does not install:"
                " pip install pandas"
            ) from None
        coords = self._coordinates()
        if self.job:
            frames = []
            for i, res in enumerate(np.asarray(self.results).reshape(-1)):
                written = res.written or res.tables
                frame = written[table].to_pandas()
                for j, name in enumerate(self.axes):
                    # an output of the swept name too: ``QA (swept)``
                    label = f"{name} (swept)" if name in frame.columns else name
                    frame.insert(j, label, coords[i][j])
                frames.append(frame)
            return pd.concat(frames, ignore_index=True)
        if eigenvalues:
            ev = self.eigenvalues().reshape(len(self), -1)
            rows = [
                (*coords[i], k + 1, float(ev[i, k].real), float(ev[i, k].imag))
                for i in range(len(self))
                for k in range(ev.shape[1])
            ]
            return pd.DataFrame(rows, columns=[*self.axes, "branch", "real", "imag"])
        flat = self._quantity_values().reshape(len(self), -1)
        rows = [
            (*coords[i], label, flat[i, k])
            for i in range(len(self))
            for k, label in enumerate(self.labels)
        ]
        return pd.DataFrame(rows, columns=[*self.axes, "name", "value"])

    def _coordinates(self) -> list[tuple[float, ...]]:
        if not self.axes:
            return [()]
        mesh = np.meshgrid(*self.axes.values(), indexing="ij")
        return list(zip(*(m.reshape(-1).tolist() for m in mesh), strict=True))

    # ---------------------------------------------------------------- plots

    def plot(
        self,
        eigenvalues: bool | None = None,
        *,
        x: Any = None,
        xlabel: str | None = None,
        column: str | None = None,
    ) -> Any:
        """A matplotlib ``Figure`` of a sweep over one name.

        For a square matrix (or ``eigenvalues=True``) the classic stability
        plot: each branch's real part (solid) and imaginary part (dashed)
        against the swept value; branches that are zero everywhere are left
        out (and counted in the title).  Otherwise each element that varies
        against the swept value.  For a job, ``column`` (default: the
        first written column after time) against time, one line per point.
        ``x`` replaces the abscissa (``x=speeds`` for a sweep of
        ``U6=-speeds/RR``), ``xlabel`` its label."""
        try:
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure
        except ImportError:
            raise NumericsError(
                "plotting needs matplotlib: pip install 'al2py-runtime[plot]'"
            ) from None
        fig = Figure(figsize=(7, 4.5))
        FigureCanvasAgg(fig)
        ax = fig.subplots()
        if self.job:
            self._plot_job(ax, column)
            fig.tight_layout()
            return fig
        axis = self._one_axis()
        xs = np.asarray(x, dtype=float) if x is not None else self.axes[axis]
        if len(xs) != len(self.axes[axis]):
            raise NumericsError(
                f"x has {len(xs)} values; the sweep has {len(self.axes[axis])}"
            )
        values = self._quantity_values().reshape((len(xs), *self._element_shape()))
        square = values.ndim == 3 and values.shape[1] == values.shape[2] > 1
        if eigenvalues is None:
            eigenvalues = square
        if eigenvalues:
            ev = self.eigenvalues().reshape(len(xs), -1)
            zero = np.all(np.abs(ev) < 1e-9, axis=0)
            for k in np.flatnonzero(~zero).tolist():
                (line,) = ax.plot(xs, ev[:, k].real, "-")
                ax.plot(xs, ev[:, k].imag, "--", color=line.get_color())
            ax.axhline(0.0, color="0.6", linewidth=0.8)
            title = f"eigenvalues of {self.name}: real (solid), imaginary (dashed)"
            if zero.any():
                title += f"; {int(zero.sum())} zero everywhere, not shown"
            ax.set_title(title, fontsize=9)
            ax.set_ylabel("eigenvalue (1/s)")
        else:
            flat = values.reshape(len(xs), -1)
            shown = 0
            for k, label in enumerate(self.labels):
                column_k = flat[:, k]
                if np.ptp(column_k.real) == 0 and len(self.labels) > 1:
                    continue
                ax.plot(xs, column_k.real, label=label)
                shown += 1
                if shown == 12:
                    break
            if shown and len(self.labels) > 1:
                ax.legend(fontsize=8)
            ax.set_ylabel(self.name)
        ax.set_xlabel(xlabel or axis)
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        return fig

    def _element_shape(self) -> tuple[int, ...]:
        return tuple(np.shape(self.values)[len(self.shape) :])

    def _one_axis(self) -> str:
        moving = [n for n, a in self.axes.items() if len(a) > 1]
        if len(moving) != 1:
            raise NumericsError(
                "plot() draws a sweep over one name; this one is over "
                + (", ".join(moving) or "none")
                + " (plot a slice of .values, or sweep one name)"
            )
        return moving[0]

    def _plot_job(self, ax: Any, column: str | None) -> None:
        coords = self._coordinates()
        results = np.asarray(self.results).reshape(-1)
        first = results[0]
        table = (first.written or first.tables)[0]
        if column is None:
            names = [n for n in table.names if normalize_name(n) != "T"]
            column = names[0] if names else table.names[0]
        for i, res in enumerate(results):
            t = res["T"] if "T" in res else np.arange(len(res[column]))
            label = ", ".join(
                f"{n}={v:g}" for n, v in zip(self.axes, coords[i], strict=True)
            )
            ax.plot(t, res[column], label=label if len(results) <= 10 else None)
        if len(results) <= 10:
            ax.legend(fontsize=8)
        ax.set_xlabel("T")
        ax.set_ylabel(column)
        ax.set_title(f"{self.name}: {column} at each of {len(results)} points")
        ax.grid(True, alpha=0.3)

    # ------------------------------------------------------------ notebooks

    def _repr_html_(self) -> str:
        rows = [
            f"<tr><th style='text-align:left'>{html.escape(n)}</th><td>{len(a)}"
            f" values, {a.min():g} to {a.max():g}</td></tr>"
            for n, a in self.axes.items()
            if len(a)
        ]
        rows += [
            f"<tr><th style='text-align:left'>{html.escape(str(n))}</th>"
            f"<td>{html.escape(repr(v))} (fixed)</td></tr>"
            for n, v in self.fixed.items()
        ]
        if self.job:
            what = f"{len(self)} results of CODE job {html.escape(self.name)}"
        else:
            what = (
                f"{html.escape(self.name)}: values of shape "
                f"{tuple(np.shape(self.values))}"
            )
        notes = "".join(f"<li>{html.escape(n)}</li>" for n in self.notes)
        return (
            f"<div><b>Sweep</b> of {what}<table>{''.join(rows)}</table>"
            + (f"<ul>{notes}</ul>" if notes else "")
            + "</div>"
        )


def follow_branches(raw: np.ndarray, shape: tuple[int, ...]) -> np.ndarray:
    """The eigenvalues ``raw`` (grid + (n,)) with each point's reordered to
    follow the branches of the point before (see :meth:`Sweep.eigenvalues`).

    >>> ev = np.array([[2.0, 1.0], [1.1, 2.1], [2.2, 1.2]])
    >>> follow_branches(ev, (3,)).real.tolist()
    [[1.0, 2.0], [1.1, 2.1], [1.2, 2.2]]
    """
    from scipy.optimize import linear_sum_assignment

    out = np.array(raw, dtype=complex)
    if out.size == 0:
        return out
    n = out.shape[-1]
    if not shape:
        return out[_sorted(out)]
    for index in np.ndindex(*shape):
        moved = [k for k, i in enumerate(index) if i > 0]
        if not moved:
            out[index] = out[index][_sorted(out[index])]
            continue
        k = moved[-1]
        prev = list(index)
        prev[k] -= 1
        target = out[tuple(prev)]
        if index[k] >= 2:
            before = list(index)
            before[k] -= 2
            target = 2 * target - out[tuple(before)]
        cost = np.abs(target[:, None] - out[index][None, :])
        rows, cols = linear_sum_assignment(cost)
        order = np.empty(n, dtype=int)
        order[rows] = cols
        out[index] = out[index][order]
    return out


def _sorted(ev: np.ndarray) -> np.ndarray:
    """The order of ``ev`` by real part, then imaginary part (real parts
    equal to 1e-9 of the largest are taken as equal)."""
    scale = max(1.0, float(np.max(np.abs(ev)))) if ev.size else 1.0
    return np.lexsort((ev.imag, np.round(ev.real / scale, 9)))
