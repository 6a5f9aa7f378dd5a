"""The results of numerical jobs: output tables, their files and plots."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..names.printing import element_labels
from .records import NumericsError, normalize_name
from .results import ResultViews, TableViews

if TYPE_CHECKING:  # numpy is imported where it is used (issue 35)
    import numpy as np

__all__ = ["Column", "Table", "Result", "fmt_number", "format_table", "table_heading"]


# ------------------------------------------------------------------ results


@dataclass(frozen=True)
class Column:
    label: str
    unit: str | None = None


@dataclass(repr=False)
class Table(TableViews):
    """One output table: one ``Output`` statement evaluated at every row."""

    number: int
    columns: list[Column]
    data: np.ndarray
    line: int | None = None
    encoded: bool = False  # Encode's quantities (not written to a file)

    @property
    def names(self) -> list[str]:
        return [c.label for c in self.columns]

    def __len__(self) -> int:
        return self.data.shape[0]

    def __getitem__(self, label: str) -> np.ndarray:
        key = normalize_name(label)
        for j, col in enumerate(self.columns):
            if normalize_name(col.label) == key:
                return self.data[:, j]
        raise KeyError(f"{label!r} is not a column of table {self.number}")

    def __contains__(self, label: object) -> bool:
        if not isinstance(label, str):
            return False
        key = normalize_name(label)
        return any(normalize_name(c.label) == key for c in self.columns)


@dataclass(repr=False)
class Result(ResultViews):
    """The outcome of :meth:`Numerics.run <al2py_runtime.jobs.numerics.Numerics.run>`.

    ``result["QA"]`` is a numpy array in the Output (or Input) unit of ``QA``;
    ``result.tables`` holds one :class:`Table` per ``Output`` statement.
    """

    kind: str
    stem: str
    tables: list[Table]
    digits: int
    solution: dict[str, np.ndarray] = field(default_factory=dict)
    solution_units: dict[str, str | None] = field(default_factory=dict)
    states: dict[str, np.ndarray] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    #: the notes of values nobody gave, taken as 0 (a subset of ``notes``;
    #: ``al2py_runtime.jobs.run.missing_value_rule``)
    missing: list[str] = field(default_factory=list)
    time_unit: str | None = None
    nfev: int = 0  # right-hand-side evaluations of a Dynamics/ODE integration
    #: ``Encode``d and ``Output`` matrices: name -> shape; ``result["AMAT"]``
    #: is an array of shape (rows, m, n), one matrix per output row.
    encoded: dict[str, tuple[int, int]] = field(default_factory=dict)
    #: a Dynamics/ODE run's job, values and states at every row
    #: (:class:`~al2py_runtime.jobs.run.Motion`), what :meth:`animate` needs;
    #: None for other jobs and for tables read from files
    motion: Any = field(default=None, repr=False)
    #: the file a table was read from (:func:`~.reading.read_table`), else None
    source: str | None = None

    def _encoded(self, key: str) -> np.ndarray:
        import numpy as np

        m, n = self.encoded[key]
        cols = [self[label] for label in element_labels(key, m, n)]
        return np.stack(cols, axis=-1).reshape(len(cols[0]), m, n)

    @property
    def written(self) -> list[Table]:
        """The tables written to files (one per ``Output`` statement)."""
        return [t for t in self.tables if not t.encoded]

    def __getitem__(self, name: str) -> np.ndarray:
        for table in self.tables:
            if name in table:
                return table[name]
        key = normalize_name(name)
        if key in self.encoded:
            return self._encoded(key)
        for source in (self.solution, self.states):
            if key in source:
                return source[key]
        raise KeyError(f"{name!r} is neither an output nor a solved quantity")

    def __contains__(self, name: object) -> bool:
        try:
            self[name]  # type: ignore[index]
        except (KeyError, TypeError):
            return False
        return True

    def files(self) -> list[str]:
        """The names :meth:`write` uses: ``STEM.1``, ``STEM.2``, ..."""
        return [f"{self.stem}.{table.number}" for table in self.written]

    def write(self, directory: str | Path = ".") -> list[Path]:
        """Write each table as ``STEM.n``: a ``%`` header naming columns and
        units, then one row per line with ``Digits`` significant digits
        (``numpy.loadtxt(path, comments="%")`` reads them back)."""
        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        written = []
        for table, name in zip(self.written, self.files(), strict=True):
            path = directory / name
            path.write_text(
                format_table(table, self.digits, name, self.time_unit),
                encoding="utf-8",
            )
            written.append(path)
        return written

    def plot(
        self,
        x: str | None = "T",
        y: str | Sequence[str] | None = None,
        *,
        table: int | None = None,
        overlay: bool = False,
        title: str | None = None,
        **style: Any,
    ) -> Any:
        """A ``matplotlib.figure.Figure`` of ``y`` against ``x``, units in the
        labels: by default each column of the first table against time (or
        the row number where the job has no time), one panel each;
        ``plot(x="QA", y="U1")`` is a phase plane.  See
        :func:`~al2py_runtime.jobs.viewing.figure`."""
        from .viewing import figure

        return figure(self, x, y, table=table, overlay=overlay, title=title, **style)

    def save_plots(self, directory: str | Path = ".") -> list[Path]:
        """Write ``STEM.n.png`` per table (``--plot``): :meth:`plot` of each
        column against time (the table's ``T`` column, else the job's time
        at each row), or against the row number where the job has no time
        (a solve or a sweep)."""
        directory = Path(directory)
        directory.mkdir(parents=True, exist_ok=True)
        written = []
        for table, name in zip(self.written, self.files(), strict=True):
            x, _label, ys = self.abscissa(table)
            if not ys or len(table) == 0:
                continue
            xname = None
            if len(ys) < len(table.columns):
                xname = next(
                    c.label for j, c in enumerate(table.columns) if j not in ys
                )
            elif "T" in self.states and len(self.states["T"]) == len(table):
                xname = "T"
            fig = self.plot(
                xname,
                [table.columns[j].label for j in ys],
                table=table.number,
                title=name,
            )
            path = directory / f"{name}.png"
            fig.savefig(path, dpi=100)
            written.append(path)
        return written

    def animate(
        self,
        path: str | Path | None = None,
        *,
        frames: Sequence[Any] | None = None,
        points: Sequence[Any] = (),
        origin: Any = None,
        newtonian: Any = None,
        **options: Any,
    ) -> Any:
        """An :class:`~al2py_runtime.jobs.animation.Animation` of the run:
        the points locating the animated bodies, each animated frame's triad
        and the lines joining points fixed together, at every output row.

        What is shown is the script's ``Animate(N, O, A, B)`` before the
        CODE statement; ``frames``, ``points``, ``origin`` and ``newtonian``
        (names or objects) change it, and without ``Animate`` choose it
        (default: every body, else every frame; a point at rest in N).  In
        a notebook the animation shows itself; with ``path`` it is also
        written (``.html`` self-contained, ``.gif``, ``.mp4``).  ``options``:
        ``speed`` (simulated seconds per second), ``width``, ``height``,
        ``follow``, ``title`` (see docs/animation.md)."""
        motion = self.motion
        if motion is None:
            raise NumericsError(
                f"{self.title()} has no motion to animate: animations need a"
                " CODE Dynamics or ODE job run by run()"
            )
        options.setdefault("title", self.stem)
        animation = motion.animation(
            frames=frames,
            points=points,
            origin=origin,
            newtonian=newtonian,
            time_unit=self.time_unit,
            **options,
        )
        if path is not None:
            animation.save(path)
        return animation

    def _repr_html_(self) -> str:
        from .viewing import result_html

        return result_html(self)

    def abscissa(self, table: Table) -> tuple[np.ndarray, str, list[int]]:
        """``(x, x label, columns to plot)`` for a plot of ``table``: time
        where there is one, else the row number."""
        import numpy as np

        for j, col in enumerate(table.columns):
            if normalize_name(col.label) == "T":
                others = [k for k in range(len(table.columns)) if k != j]
                return table.data[:, j], _heading(col, self.time_unit), others
        every = list(range(len(table.columns)))
        time = self.states.get("T")
        if time is not None and len(time) == len(table):
            return time, _heading(Column("T"), self.time_unit), every
        return np.arange(1, len(table) + 1), "row (output step)", every

    def solution_lines(self) -> list[str]:
        """``QB = 74.47751 deg`` for each solved quantity (Nonlinear/Algebraic)."""
        out = []
        for name, values in self.solution.items():
            unit = self.solution_units.get(name)
            suffix = f" {unit}" if unit else ""
            if len(values) == 1:
                out.append(f"{name} = {fmt_number(values[0], self.digits)}{suffix}")
        return out


def _heading(col: Column, time_unit: str | None) -> str:
    unit = col.unit
    if unit is None and normalize_name(col.label) == "T" and time_unit:
        unit = time_unit
    return f"{col.label} ({unit})" if unit else col.label


def fmt_number(x: float, digits: int) -> str:
    return f"{x:.{digits}g}"


def table_heading(
    columns: Sequence[Column], digits: int, name: str, time_unit: str | None = None
) -> tuple[str, int]:
    """The heading of an output file (its text before the first row) and
    the width of each of its columns."""
    width = max(digits + 8, 12)
    labels, units = [], []
    for col in columns:
        unit = col.unit
        if unit is None and normalize_name(col.label) == "T" and time_unit:
            unit = time_unit
        labels.append(col.label)
        units.append(f"({unit})" if unit else "(UNITS)")
    width = max([width] + [len(s) + 2 for s in labels + units])
    lines = [
        f"% FILE: {name}",
        "%",
        "%" + "".join(s.center(width) for s in labels).rstrip(),
        "%" + "".join(s.center(width) for s in units).rstrip(),
        "",
    ]
    return "\n".join(lines) + "\n", width


def format_table(
    table: Table, digits: int, name: str, time_unit: str | None = None
) -> str:
    """The text of one output file."""
    heading, width = table_heading(table.columns, digits, name, time_unit)
    rows = [
        " " + "".join(f"{v:.{digits - 1}E}".rjust(width) for v in row).rstrip() + "\n"
        for row in table.data
    ]
    return heading + "".join(rows)
