"""Reading output tables back: :func:`read_table`.

Autolev's programs (C, Fortran, MATLAB) and al2py's jobs write the same
format: ``% FILE: STEM.1``, a ``%`` line, a ``%`` line of column labels, a
``%`` line of units in parentheses (``(UNITS)`` for none), a blank line,
then one row of numbers per line (``1.839750E+00``; Fortran may write
``D`` exponents).  :func:`read_table` gives a
:class:`~al2py_runtime.jobs.tables.Result` with one table, so ``r["QA"]``,
``r.plot()`` and ``r.to_pandas()`` work on any of them.

>>> import tempfile, pathlib
>>> text = '''% FILE: drop.1
... %
... %       T              X
... %     (sec)           (m)
...
...  0.000000E+00   1.000000E+00
...  5.000000E-01   2.500000E-01
... '''
>>> path = pathlib.Path(tempfile.mkdtemp()) / "drop.1"
>>> _ = path.write_text(text)
>>> r = read_table(path)
>>> r
<Result of table drop.1: 2 rows of T, X>
>>> r["X"].tolist(), r.tables[0].columns[1].unit, r.digits, r.time_unit
([1.0, 0.25], 'm', 7, 'sec')
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .records import NumericsError, normalize_name
from .tables import Column, Result, Table

__all__ = ["read_table"]

_UNIT = re.compile(r"\([^()]*(?:\([^()]*\)[^()]*)*\)")


def _centers(line: str, pattern: re.Pattern) -> list[tuple[float, str]]:
    return [((m.start() + m.end()) / 2, m.group()) for m in pattern.finditer(line)]


def _digits(word: str) -> int | None:
    """Significant digits of a number as printed (``1.839750E+00``: 7)."""
    mantissa = re.split(r"[EeDd]", word.lstrip("+-"))[0]
    figures = mantissa.replace(".", "").lstrip("0")
    return len(figures) if figures else None


def read_table(path: str | Path) -> Result:
    """The table in ``path`` (Autolev's output format) as a ``Result``.

    Columns are named by the label line and get the units of the unit
    line (each in parentheses, spaces allowed); ``digits`` is
    the number of significant digits the numbers were printed with; the
    table's number is the file's suffix (``tutor6.1``: 1)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        raise NumericsError(f"cannot read {path}: {exc.strerror}") from None
    heads: list[str] = []
    rows: list[list[float]] = []
    digits = None
    for number, line in enumerate(text.splitlines(), start=1):
        if line.lstrip().startswith("%"):
            heads.append(line.lstrip()[1:])
            continue
        words = line.split()
        if not words:
            continue
        try:
            rows.append([float(w.replace("D", "E").replace("d", "e")) for w in words])
        except ValueError:
            raise NumericsError(
                f"{path}:{number}: not a row of numbers: {line.strip()[:60]}"
            ) from None
        if digits is None:
            digits = _digits(words[0])
    if not rows:
        raise NumericsError(f"{path}: no rows of numbers")
    width = len(rows[0])
    if any(len(r) != width for r in rows):
        raise NumericsError(f"{path}: rows have different numbers of values")
    labels, units = _header(heads, width)
    columns = [Column(lab, unit) for lab, unit in zip(labels, units, strict=True)]
    time_unit = next(
        (c.unit for c in columns if normalize_name(c.label) == "T" and c.unit), None
    )
    suffix = path.suffix[1:]
    table = Table(int(suffix) if suffix.isdigit() else 1, columns, np.array(rows))
    return Result(
        "TABLE",
        path.stem if suffix.isdigit() else path.name,
        [table],
        digits or 7,
        time_unit=time_unit,
        source=path.name,
    )


def _header(heads: list[str], width: int) -> tuple[list[str], list[str | None]]:
    """Labels and units from the ``%`` lines (``C1``, ``C2``... and no units
    where the file names none)."""
    lines = [
        h for h in heads if h.strip() and not h.strip().upper().startswith("FILE:")
    ]
    label_line = unit_line = None
    for i, h in enumerate(lines):
        if len(_centers(h, _UNIT)) == width and not _UNIT.sub("", h).strip():
            unit_line = h
            if i > 0:
                label_line = lines[i - 1]
            break
    if label_line is None and lines:
        label_line = lines[0]
    labels = [w for _c, w in _centers(label_line or "", re.compile(r"\S+"))]
    if len(labels) != width:
        labels = [f"C{j + 1}" for j in range(width)]
    units: list[str | None] = [None] * width
    if unit_line is not None:
        found = [w[1:-1].strip() for _c, w in _centers(unit_line, _UNIT)]
        units = [None if u.upper() in ("UNITS", "") else u for u in found]
    return labels, units
