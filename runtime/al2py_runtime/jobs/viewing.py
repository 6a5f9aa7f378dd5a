"""Looking at results: matplotlib figures of any columns, HTML for notebooks.

``result.plot()`` is :func:`figure`: each column of the first table against
time, one panel each; ``plot(x="QA", y="QB")`` a phase plane;
``plot(y=["QA", "QB"], overlay=True)`` one panel with a legend.  Labels carry
the Output (or Input) units.  It returns a ``matplotlib.figure.Figure`` made
without pyplot (no global state; a notebook shows it), which ``--plot``
saves as ``STEM.n.png`` (``result.save_plots(folder)``).

``Result._repr_html_`` is :func:`result_html`: the job's name and the head
of each table with its units.

>>> import numpy as np
>>> from al2py_runtime.jobs.tables import Column, Result, Table
>>> data = np.array([[0.0, 1.0], [0.5, 0.25], [1.0, 0.0]])
>>> r = Result("ODE", "drop", [Table(1, [Column("T"), Column("X", "m")], data)], 4,
...            time_unit="sec")
>>> fig = figure(r)
>>> [ax.get_xlabel() for ax in fig.axes], [ax.get_ylabel() for ax in fig.axes]
(['T (sec)'], ['X (m)'])
>>> "<th>X<br>(m)</th>" in result_html(r)
True
"""

from __future__ import annotations

import html
from collections.abc import Sequence
from typing import Any

import numpy as np

from .records import NumericsError, normalize_name

# (``Result`` and ``Table`` are :mod:`.tables`' classes, which import this
# module; annotations name them as text)
Result = Table = Any
__all__ = ["figure", "result_html", "series"]

#: rows a notebook shows of each table (its head)
HEAD_ROWS = 6


def _matplotlib() -> tuple[Any, Any]:
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        raise NumericsError(
            "plotting needs matplotlib: pip install 'al2py-runtime[plot]'"
        ) from None
    return Figure, FigureCanvasAgg


def _table(result: Result, table: int | None) -> Table | None:
    if table is None:
        tables = result.written or result.tables
        return tables[0] if tables else None
    for t in result.tables:
        if t.number == table:
            return t
    raise NumericsError(
        f"{result.stem} has no table {table}; tables: "
        + ", ".join(str(t.number) for t in result.tables)
    )


def series(
    result: Result, name: str | None, table: Table | None = None
) -> tuple[np.ndarray, str]:
    """``(values, label with unit)`` of a column (in ``table`` first), of
    a solved or state quantity, or of the row number for ``name=None``."""
    rows = len(table) if table is not None else len(next(iter(result.values()), []))
    if name is None:
        return np.arange(1, rows + 1), "row (output step)"
    key = normalize_name(name)
    tables = ([table] if table is not None else []) + list(result.tables)
    for t in tables:
        for j, col in enumerate(t.columns):
            if normalize_name(col.label) == key:
                unit = col.unit
                if unit is None and key == "T":
                    unit = result.time_unit
                return t.data[:, j], f"{col.label} ({unit})" if unit else col.label
    if key == "T" and "T" in result.states:
        unit = result.time_unit
        return result.states["T"], f"T ({unit})" if unit else "T"
    try:
        values = np.asarray(result[name], dtype=float)
    except KeyError:
        raise NumericsError(
            f"{name} is not a column of {result.stem}: " + ", ".join(result.keys())
        ) from None
    unit = result.solution_units.get(key)
    return values, f"{name} ({unit})" if unit else str(name)


def figure(
    result: Result,
    x: str | None = "T",
    y: str | Sequence[str] | None = None,
    *,
    table: int | None = None,
    overlay: bool = False,
    title: str | None = None,
    **style: Any,
) -> Any:
    """A ``matplotlib.figure.Figure`` of ``y`` against ``x``.

    ``x`` is any column name (``"T"`` by default; where a job has no time,
    the row number, as for ``x=None``); ``y`` a name or a list of names, by
    default every other column of ``table`` (the first table).  One panel
    per ``y`` sharing the x axis, or one panel for all with ``overlay``;
    ``style`` goes to ``Axes.plot`` (``marker="."``)."""
    Figure, FigureCanvasAgg = _matplotlib()
    chosen = _table(result, table)
    if x is not None and normalize_name(x) == "T":
        has_time = "T" in result.states or any(
            "T" in [normalize_name(c.label) for c in t.columns] for t in result.tables
        )
        if not has_time:
            x = None
    xs, xlabel = series(result, x, chosen)
    if y is None:
        if chosen is None:
            raise NumericsError(f"{result.stem} has no table to plot")
        skip = normalize_name(x) if x is not None else None
        names = [c.label for c in chosen.columns if normalize_name(c.label) != skip]
    elif isinstance(y, str):
        names = [y]
    else:
        names = list(y)
    if not names:
        raise NumericsError("nothing to plot: give y=")
    curves = []
    for name in names:
        values, label = series(result, name, chosen)
        if values.ndim != 1 or len(values) != len(xs):
            raise NumericsError(
                f"{name} has {len(values)} rows, {xlabel} has {len(xs)}: they"
                " cannot be plotted against each other"
            )
        curves.append((values, label))
    panels = 1 if overlay else len(curves)
    fig = Figure(figsize=(7, 1.0 + 2.0 * panels if panels > 1 else 4.0))
    FigureCanvasAgg(fig)
    axes = fig.subplots(panels, 1, sharex=True, squeeze=False)[:, 0]
    style.setdefault("marker", "." if len(xs) < 60 else None)
    for k, (values, label) in enumerate(curves):
        ax = axes[0 if overlay else k]
        ax.plot(xs, values, label=label, **style)
        if not overlay:
            ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    if overlay and len(curves) > 1:
        axes[0].legend()
    elif overlay:
        axes[0].set_ylabel(curves[0][1])
    axes[-1].set_xlabel(xlabel)
    fig.suptitle(title if title is not None else result.stem)
    fig.tight_layout()
    return fig


def _head(table: Table, digits: int, time_unit: str | None, rows: int) -> str:
    cells = []
    for col in table.columns:
        unit = col.unit or (time_unit if normalize_name(col.label) == "T" else None)
        unit_text = f"<br>({html.escape(unit)})" if unit else ""
        cells.append(f"<th>{html.escape(col.label)}{unit_text}</th>")
    lines = ["<table>", "<thead><tr>" + "".join(cells) + "</tr></thead>", "<tbody>"]
    for row in table.data[:rows]:
        lines.append(
            "<tr>" + "".join(f"<td>{float(v):.{digits}g}</td>" for v in row) + "</tr>"
        )
    lines.append("</tbody></table>")
    more = len(table) - rows
    if more > 0:
        lines.append(f"<div>... {more} more rows</div>")
    return "\n".join(lines)


def result_html(result: Result, rows: int = HEAD_ROWS) -> str:
    """The job's name, then the head of each table with units."""
    title = html.escape(result.title())
    parts = ['<div class="al2py-result">', f"<b>{title}</b>"]
    for table in result.tables:
        what = "Encode" if table.encoded else f"{result.stem}.{table.number}"
        parts.append(
            f"<div>{html.escape(what)}: {len(table)} rows</div>"
            + _head(table, result.digits, result.time_unit, rows)
        )
    lines = result.solution_lines()
    if lines:
        parts.append("<pre>" + html.escape("\n".join(lines)) + "</pre>")
    parts.append("</div>")
    return "\n".join(parts)
