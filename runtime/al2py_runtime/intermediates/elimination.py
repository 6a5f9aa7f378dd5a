"""Symbolic Gauss-Jordan elimination with named entries and numeric pivots.

The AutoZ book (:class:`al2py_runtime.intermediates.autoz.Intermediates`)
solves with it (``Intermediates.solve``: a script's ``Solve``, ``Constrain``
and ``Kane()``, and :class:`~al2py_runtime.model.fastkane.FastKane`'s
kinematical equations and constraints); the names and the probe values are
the caller's.

>>> import sympy as sp
>>> x, one, two = sp.Symbol("x"), sp.S.One, sp.S(2)
>>> eliminate([[0, one], [x, two]], [[one], [3 * one]], lambda e: e, lambda e, p: 1j)
[[1/x], [1]]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

__all__ = ["SMALL", "eliminate", "pivot_row"]

#: with ``AutoZ OFF``, linear systems up to this many unknowns are solved in
#: closed form (Cramer's rule: short, readable results, as Autolev prints
#: them); larger ones always by :func:`eliminate` with named entries.
SMALL = 3

Probe = Callable[[Any, int], complex]


def pivot_row(column: list[Any], probe: Probe) -> int | None:
    """The row to pivot on: non-zero at probe point 0 (the coordinates at 0,
    the usual reference configuration, e.g. an upright bicycle) if possible,
    else the largest at the random probe point 1; None if every entry is 0."""
    best, best_key = None, None
    for r, e in enumerate(column):
        if e == 0:
            continue
        at_zero, at_random = abs(probe(e, 0)), abs(probe(e, 1))
        if at_random < 1e-12 and at_zero < 1e-12:
            continue
        key = (at_zero > 1e-9 * max(1.0, at_random), at_zero, at_random)
        if best_key is None or key > best_key:
            best, best_key = r, key
    if best is None:  # zero at both probes: take any structural non-zero
        best = next((r for r, e in enumerate(column) if e != 0), None)
    return best


def eliminate(
    a: list[list[Any]], b: list[list[Any]], name: Callable[[Any], Any], probe: Probe
) -> list[list[Any]]:
    """Solve ``a x = b`` (lists of rows), giving every new entry to ``name``;
    pivots by :func:`pivot_row` with ``probe(expr, point)``."""
    n = len(a)
    a = [row[:] for row in a]
    b = [row[:] for row in b]
    for col in range(n):
        pivot = pivot_row([a[r][col] for r in range(col, n)], probe)
        if pivot is None:
            raise ValueError("the linear system is singular")
        pivot += col
        a[col], a[pivot] = a[pivot], a[col]
        b[col], b[pivot] = b[pivot], b[col]
        p = a[col][col]
        for r in range(n):
            if r == col or a[r][col] == 0:
                continue
            f = name(a[r][col] / p)
            a[r] = [
                name(x - f * y) if y != 0 else x
                for x, y in zip(a[r], a[col], strict=True)
            ]
            b[r] = [
                name(x - f * y) if y != 0 else x
                for x, y in zip(b[r], b[col], strict=True)
            ]
    return [[name(x / a[i][i]) for x in b[i]] for i in range(n)]
