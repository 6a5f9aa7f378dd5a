"""Dictionary views, a short ``repr`` and pandas export for job results.

``run()`` returns a :class:`~al2py_runtime.jobs.run.Result`; these mixins give it
(and each of its tables) the habits of a mapping from column names to numpy
arrays::

    r = model.run()
    list(r.keys())          # ['T', 'STRETCH', 'QA', 'QB', 'ECHECK']
    dict(r.items())         # name -> numpy array
    r                       # <Result of CODE Dynamics tutor6: 21 rows of T, ...>
    r.to_pandas()           # a pandas.DataFrame (pandas is optional)
    r.tables[0].to_pandas()

pandas is imported only by ``to_pandas``; it is never a dependency.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

__all__ = ["ResultViews", "TableViews", "document_run"]


def _pandas() -> Any:
    try:
        import pandas
    except ImportError:
        raise ImportError(
            "to_pandas() needs pandas, which al2py does not install: "
            "pip install pandas"
        ) from None
    return pandas


def _names(names: list[str], limit: int = 6) -> str:
    shown = ", ".join(names[:limit])
    return shown + (f", ... ({len(names)} columns)" if len(names) > limit else "")


class _Views:
    """``values``/``items``/iteration from ``keys`` and ``[key]``."""

    def keys(self) -> list[str]:  # pragma: no cover - defined by subclasses
        raise NotImplementedError

    def values(self) -> list[Any]:
        return [self[k] for k in self.keys()]  # type: ignore[index]

    def items(self) -> list[tuple[str, Any]]:
        return [(k, self[k]) for k in self.keys()]  # type: ignore[index]

    def __iter__(self) -> Iterator[str]:
        return iter(self.keys())


class TableViews(_Views):
    """Mapping habits of a :class:`~al2py_runtime.jobs.run.Table`."""

    def keys(self) -> list[str]:
        return list(self.names)  # type: ignore[attr-defined]

    def to_dict(self) -> dict[str, Any]:
        """``{column name: numpy array}``: ``pandas.DataFrame(t.to_dict())``."""
        return dict(self.items())

    def to_pandas(self) -> Any:
        """The table as a ``pandas.DataFrame`` (one column per output)."""
        return _pandas().DataFrame(self.to_dict())

    def __repr__(self) -> str:
        return (
            f"<Table {self.number}: {len(self)} rows of "  # type: ignore[attr-defined]
            f"{_names(self.keys())}>"
        )


class ResultViews(_Views):
    """Mapping habits of a :class:`~al2py_runtime.jobs.run.Result`: keys are every
    output column (in table order), then solved and state quantities."""

    def keys(self) -> list[str]:
        out: list[str] = []
        seen: set[str] = set()
        groups = [t.names for t in self.tables]  # type: ignore[attr-defined]
        groups.append(list(self.solution))  # type: ignore[attr-defined]
        groups.append(list(self.states))  # type: ignore[attr-defined]
        for names in groups:
            for name in names:
                key = name.upper()
                if key not in seen:
                    seen.add(key)
                    out.append(name)
        return out

    def __len__(self) -> int:
        return len(self.keys())

    def to_pandas(self) -> Any:
        """All outputs as one ``pandas.DataFrame`` (columns of equal length:
        every output table; a Nonlinear/Algebraic solution adds its values)."""
        pandas = _pandas()
        columns = {}
        rows = None
        for name, values in self.items():
            if rows is None:
                rows = len(values)
            if len(values) == rows:
                columns[name] = values
        return pandas.DataFrame(columns)

    def title(self) -> str:
        """What the result is of: ``CODE Dynamics tutor6``, or the file a
        table was read from."""
        source = self.source  # type: ignore[attr-defined]
        if source is not None:
            return f"table {source}"
        kind = self.kind.title()  # type: ignore[attr-defined]
        return f"CODE {kind} {self.stem}"  # type: ignore[attr-defined]

    def __repr__(self) -> str:
        tables = self.tables  # type: ignore[attr-defined]
        rows = len(tables[0]) if tables else len(next(iter(self.values()), []))
        return f"<Result of {self.title()}: {rows} rows of " f"{_names(self.keys())}>"


def _number(value: Any) -> float | None:
    """``value`` as a float, or None for an Input given as an expression."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return None


def document_run(numerics: Any, run: Any) -> Any:
    """Set ``run.__signature__`` to ``run(values=None, /, *, QA=20, ...)`` and
    list the Inputs with their units in ``run.__doc__``."""
    import inspect

    params = [
        inspect.Parameter("values", inspect.Parameter.POSITIONAL_ONLY, default=None)
    ]
    lines = []
    for name, item in numerics.inputs.items():
        unit = f" {item.unit}" if getattr(item, "unit", None) else ""
        value = _number(item.value)
        shown = format(value, "g") if value is not None else str(item.value)
        lines.append(f"    {name} = {shown}{unit}")
        if name.isidentifier():
            params.append(
                inspect.Parameter(
                    name,
                    inspect.Parameter.KEYWORD_ONLY,
                    default=value if value is not None else shown,
                )
            )
    jobs = [j.stem for j in numerics.jobs]
    if len(jobs) > 1 and not any(p.name.upper() == "JOB" for p in params):
        params.append(
            inspect.Parameter("job", inspect.Parameter.KEYWORD_ONLY, default=None)
        )
        lines.append(
            "    job = None (the only Dynamics/ODE job, else an error listing"
            f" the jobs; or one of {', '.join(jobs)})"
        )
    try:
        run.__signature__ = inspect.Signature(params)
        if lines:
            run.__doc__ = (run.__doc__ or "").rstrip() + (
                "\n\n    Inputs (keyword arguments, in these units):\n\n"
                + "\n".join(lines)
                + "\n"
            )
    except (AttributeError, TypeError, ValueError):
        pass
    return run
