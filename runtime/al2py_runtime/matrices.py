"""Pure functions behind Autolev's matrix commands (1-based indices).

>>> import sympy as sp
>>> A, B, C, D = sp.symbols("A B C D")
>>> M0 = sp.Matrix([[A, B], [C, D]])
>>> rows(M0, 2, (1, 2))
Matrix([
[C, D],
[A, B],
[C, D]])
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp
from sympy.matrices.utilities import dotprodsimp

from .model.kinematics import is_small

__all__ = [
    "block",
    "rows",
    "cols",
    "diagmat",
    "det",
    "inv",
    "transpose",
    "trace",
    "element",
]

Selector = int | tuple[int, int]


def as_matrix(a: Any, what: str) -> sp.Matrix:
    """``a`` as a mutable Matrix (lists accepted), or a TypeError naming ``what``."""
    if isinstance(a, sp.MatrixBase):
        return sp.Matrix(a)
    if isinstance(a, list | tuple):
        return sp.Matrix(a)
    raise TypeError(f"{what}: expected a matrix, not {type(a).__name__} {a!r}")


def _square(a: Any, what: str) -> sp.Matrix:
    m = as_matrix(a, what)
    if m.rows != m.cols or m.rows == 0:
        raise ValueError(
            f"{what}: expected a square matrix, not a {m.rows}x{m.cols} matrix"
        )
    return m


def _index(k: Any, what: str) -> int:
    try:
        value = sp.sympify(k)
    except sp.SympifyError:
        raise TypeError(f"{what}: index {k!r} is not an integer") from None
    if not value.is_Integer:
        raise TypeError(f"{what}: index {k} is not an integer")
    return int(value)


def block(entries: Sequence[Sequence[Any]]) -> sp.Matrix:
    """Build a matrix from rows whose entries are scalars or matrices.

    ``[M0, [1,2;3,4]]`` is ``block([[M0, Matrix([[1, 2], [3, 4]])]])``.

    >>> block([[sp.eye(2), sp.Matrix([5, 6])], [7, sp.Matrix([[8, 9]])]])
    Matrix([
    [1, 0, 5],
    [0, 1, 6],
    [7, 8, 9]])
    """
    if isinstance(entries, sp.MatrixBase):
        return sp.Matrix(entries)
    stripes = []
    for r, row in enumerate(entries, start=1):
        row = list(row) if isinstance(row, list | tuple) else [row]
        parts = [
            sp.Matrix(e) if isinstance(e, sp.MatrixBase) else sp.Matrix([[e]])
            for e in row
        ]
        parts = [p for p in parts if p.rows * p.cols]
        if not parts:
            continue
        heights = {p.rows for p in parts}
        if len(heights) > 1:
            raise ValueError(
                f"matrix row {r}: entries have different numbers of rows "
                f"({', '.join(str(p.rows) for p in parts)})"
            )
        stripes.append(sp.Matrix.hstack(*parts))
    if not stripes:
        return sp.zeros(0, 0)
    widths = {s.cols for s in stripes}
    if len(widths) > 1:
        raise ValueError(
            "matrix rows have different numbers of columns "
            f"({', '.join(str(s.cols) for s in stripes)})"
        )
    return sp.Matrix.vstack(*stripes)


def _selection(sel: Sequence[Selector], size: int, what: str, kind: str) -> list[int]:
    picked = []
    for s in sel:
        if isinstance(s, tuple | list):
            if len(s) != 2:
                raise ValueError(f"{what}: a range needs two ends, not {s!r}")
            lo, hi = (_index(k, what) for k in s)
            if lo > hi:
                raise ValueError(f"{what}: range {lo}:{hi} is empty")
            span = range(lo, hi + 1)
        elif isinstance(s, sp.MatrixBase):  # ``Rows(A, [1, 3])``: a list
            span = [_index(k, what) for k in s]
        else:
            span = range(_index(s, what), _index(s, what) + 1)
        for k in span:
            if not 1 <= k <= size:
                raise ValueError(f"{what}: {kind} {k} is out of range 1..{size}")
            picked.append(k - 1)
    return picked


def rows(a: Any, *sel: Selector) -> Any:
    """Autolev ``Rows(A)`` (number of rows) or ``Rows(A, 2, 1:2)``.

    >>> rows(sp.Matrix([[1, 2], [3, 4]]))
    2
    >>> rows(sp.Matrix([[1, 2], [3, 4]]), 2)
    Matrix([[3, 4]])
    """
    m = as_matrix(a, "Rows(A)")
    if not sel:
        return sp.Integer(m.rows)
    what = f"Rows(A, ...) with a {m.rows}x{m.cols} matrix"
    return m.extract(_selection(sel, m.rows, what, "row"), list(range(m.cols)))


def cols(a: Any, *sel: Selector) -> Any:
    """Autolev ``Cols(A)`` (number of columns) or ``Cols(A, 1, 3:4)``.

    >>> cols(sp.Matrix([[1, 2], [3, 4]]), 1)
    Matrix([
    [1],
    [3]])
    """
    m = as_matrix(a, "Cols(A)")
    if not sel:
        return sp.Integer(m.cols)
    what = f"Cols(A, ...) with a {m.rows}x{m.cols} matrix"
    return m.extract(list(range(m.rows)), _selection(sel, m.cols, what, "column"))


def diagmat(n: Any, m: Any, x: Any = None) -> sp.Matrix:
    """Autolev ``DiagMat(n, x)`` (n x n) or ``DiagMat(n, m, x)`` (n x m).

    >>> diagmat(2, 3, 7)
    Matrix([
    [7, 0, 0],
    [0, 7, 0]])
    """
    if x is None:
        n, m, x = n, n, m
    n, m = _index(n, "DiagMat"), _index(m, "DiagMat")
    if n < 1 or m < 1:
        raise ValueError(f"DiagMat: size {n}x{m} must be positive")
    out = sp.zeros(n, m)
    for k in range(min(n, m)):
        out[k, k] = x
    return out


def det(a: Any) -> sp.Expr:
    """Autolev ``Det(A)``.

    >>> A, B, C, D = sp.symbols("A B C D")
    >>> det(sp.Matrix([[A, B], [C, D]]))
    A*D - B*C
    """
    m = _square(a, "Det(A)")
    if m.rows > MAX_SYMBOLIC_DET and (m.is_upper or m.is_lower):
        return sp.Mul(*m.diagonal())
    if m.rows > MAX_SYMBOLIC_DET and m.free_symbols:
        raise ValueError(
            f"Det of a {m.rows}x{m.cols} matrix of symbolic expressions would "
            f"take minutes to hours (al2py expands symbolic determinants up to "
            f"{MAX_SYMBOLIC_DET}x{MAX_SYMBOLIC_DET}: about 10 s for a full one); "
            "give the quantities numbers first (Evaluate) or split the matrix"
        )
    with dotprodsimp(False if _large(m) else None):
        return m.det(method="berkowitz")


#: the largest matrix of symbolic expressions whose determinant ``Det``
#: expands (a full 16x16 one takes about 13 s, a 20x20 one 33 s and the
#: time grows as the fourth power of the size: a 40x40 one would take
#: minutes to hours, silently)
MAX_SYMBOLIC_DET = 16


def _large(m: sp.MatrixBase) -> bool:
    """An entry of more than 300 tree nodes: sympy's simplification of
    products as it goes (``dotprodsimp``, an expansion) is turned off for
    such a matrix, as it can take hours."""
    return not all(is_small(e, 300) for e in m if isinstance(e, sp.Basic))


def _vanishes(m: sp.Matrix, d: Any) -> bool:
    """Whether the determinant ``d`` of ``m`` vanishes at two random points
    (relative to Hadamard's bound there: the product of the rows' norms);
    each distinct part of the entries is evaluated once."""
    from .intermediates.autoz import Intermediates, book_of

    if d == 0:
        return True
    book = book_of(m) or Intermediates()
    for point in (1, 2):
        try:
            values = book.values_at([*m, d], point)
        except (ValueError, ZeroDivisionError, OverflowError):
            return False
        n = m.cols
        bound = 1.0
        for i in range(m.rows):
            bound *= sum(abs(v) ** 2 for v in values[i * n : (i + 1) * n]) ** 0.5
        if abs(values[-1]) > 1e-9 * max(bound, 1e-300):
            return False
    return True


def inv(a: Any) -> sp.Matrix:
    """Autolev ``Inv(A)``; raises ValueError for a singular matrix.

    >>> inv(sp.Matrix([[2, 0], [0, 4]]))
    Matrix([
    [1/2,   0],
    [  0, 1/4]])
    """
    m = _square(a, "Inv(A)")
    singular = "Inv(A): the matrix is singular (determinant is zero)"
    if m.rows <= 3:  # adjugate/determinant keeps small inverses readable
        large = _large(m)
        with dotprodsimp(False if large else None):
            d = m.det(method="berkowitz")
            # large entries: a vanishing determinant is found at random
            # points rather than by expanding it
            if _vanishes(m, d) if large else sp.expand(d) == 0:
                raise ValueError(singular)
            return m.adjugate().applyfunc(lambda e: e / d)
    try:
        return m.inv()
    except ValueError:
        raise ValueError(singular) from None


def transpose(a: Any) -> sp.Matrix:
    """Autolev ``Transpose(A)``.

    >>> transpose(sp.Matrix([1, 2]))
    Matrix([[1, 2]])
    """
    return as_matrix(a, "Transpose(A)").T


def trace(a: Any) -> sp.Expr:
    """Autolev ``Trace(A)`` for a square matrix.

    >>> trace(sp.Matrix([[1, 2], [3, 4]]))
    5
    """
    return _square(a, "Trace(A)").trace()


def element(a: Any, i: Any, j: Any = None) -> sp.Expr:
    """Autolev ``Element(A, i, j)``; ``Element(A, i)`` for a row or column.

    >>> element(sp.Matrix([[1, 2], [3, 4]]), 2, 1)
    3
    """
    m = as_matrix(a, "Element(A)")
    i = _index(i, "Element(A, i)")
    if j is None:
        if m.cols != 1 and m.rows != 1:
            raise ValueError(
                f"Element(A, {i}): a {m.rows}x{m.cols} matrix needs two indices"
            )
        size = m.rows * m.cols
        if not 1 <= i <= size:
            raise ValueError(f"Element(A, {i}): index {i} is out of range 1..{size}")
        return m[i - 1]
    j = _index(j, "Element(A, i, j)")
    if not (1 <= i <= m.rows and 1 <= j <= m.cols):
        raise ValueError(
            f"Element(A, {i}, {j}): out of range for a {m.rows}x{m.cols} matrix"
        )
    return m[i - 1, j - 1]
