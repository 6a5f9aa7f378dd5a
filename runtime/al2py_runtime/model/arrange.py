"""Pure algebra behind ``Constrain`` and ``Kane`` (no workspace state).

``ZERO`` after ``Kane()`` (see :func:`arrange`): one row per independent
generalized speed ``Ui``, in declaration order,

    ZERO[i] = F[i] + M[i,1]*U1' + ... + M[i,n]*Un'

where ``F`` holds no speed derivatives.  ``ZERO[i] = 0`` is Kane's equation
``Fr + Fr* = 0`` for speed ``i`` (so ``-M`` is the mass matrix).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from typing import Any

import sympy as sp

from ..linear import linear_terms
from ..walks import appearing
from .kinematics import tidy

__all__ = ["solve_speeds", "arrange", "split_linear"]


def split_linear(
    exprs: Sequence[Any], unknowns: Sequence[Any]
) -> tuple[sp.Matrix, sp.Matrix]:
    """``exprs = A*x + b``: return ``(A, b)``; raise if not linear in ``x``."""
    a = sp.Matrix(len(exprs), len(unknowns), lambda i, j: 0)
    b = sp.zeros(len(exprs), 1)
    zero = {u: 0 for u in unknowns}
    for i, e in enumerate(exprs):
        e = sp.expand(sp.sympify(e))
        for j, u in enumerate(unknowns):
            c = sp.diff(e, u)
            if any(c.has(v) for v in unknowns):
                raise ValueError(f"equation {i + 1} is not linear in {u}")
            a[i, j] = c
        b[i, 0] = e.xreplace(zero)
    return a, b


def split_linear_named(
    exprs: Sequence[Any], unknowns: Sequence[Any], book: Any = None
) -> tuple[sp.Matrix, sp.Matrix]:
    """:func:`split_linear` without expanding (coefficients by derivatives),
    for expressions written with intermediates.  With their ``book``, the
    derivatives are its walk (:meth:`Intermediates.derivative`: each shared
    part once, no ``Derivative`` objects), which gives sympy's ``diff``."""
    a = sp.zeros(len(exprs), len(unknowns))
    b = sp.zeros(len(exprs), 1)
    plain = [sp.Dummy(f"x{k}") for k in range(len(unknowns))]
    swap = dict(zip(unknowns, plain, strict=True))
    zero = dict.fromkeys(plain, 0)
    for i, e in enumerate(exprs):
        e = sp.sympify(e).xreplace(swap)
        present = appearing(e, plain)
        for j, x in enumerate(plain):
            if x not in present:
                c = sp.S.Zero
            elif book is not None:
                c = book.derivative(e, x)
            else:
                c = e.diff(x)
            if appearing(c, plain):
                raise ValueError(f"equation {i + 1} is not linear in {unknowns[j]}")
            a[i, j] = c
        b[i, 0] = e.xreplace(zero)
    return a, b


def solve_speeds(
    eqs: Sequence[Any],
    unknowns: Sequence[Any],
    book: Any = None,
    zero: Sequence[Any] = (),
) -> list[Any]:
    """Solve linear equations ``eqs = 0`` for ``unknowns`` (tidied results).

    With a book of intermediates (``AutoZ ON``) every entry of the
    elimination is named; ``zero`` lists the variables that are 0 in the
    reference configuration, for the choice of pivots."""
    if len(eqs) != len(unknowns):
        raise ValueError(f"{len(eqs)} equations for {len(unknowns)} unknowns")
    if book is not None:
        a, b = split_linear_named(eqs, unknowns, book)
        return list(book.solve(a, -b, zero))
    a, b = split_linear(eqs, unknowns)
    a = a.applyfunc(tidy)
    det = tidy(a.det(method="berkowitz"))
    if det == 0:
        raise ValueError("the equations cannot be solved for " + str(list(unknowns)))
    adj = a.adjugate(method="berkowitz")
    sol = -(adj * b)
    return [tidy(sp.together(tidy(s) / det)) for s in sol]


def arrange(rows: Iterable[Any], accels: Sequence[Any], gens: Sequence[Any]) -> list:
    """Arrange each row as ``F + sum(M_k * accel_k)`` (see module doc).

    Rows are linear in the accelerations, so the coefficients are derivatives
    and the rest is the row with the accelerations set to zero: no expansion.
    The accelerations are swapped for plain symbols once, because sympy
    differentiates by a ``Derivative`` through a substitution on every call,
    which dominated the derivation of large models."""
    plain = [sp.Dummy(f"a{k}") for k in range(len(accels))]
    swap = dict(zip(accels, plain, strict=True))
    back = dict(zip(plain, accels, strict=True))
    zero = dict.fromkeys(plain, 0)
    # No tidying here: it is cosmetic and done when responses are printed.
    polish = _as_is
    out = []
    for row in rows:
        row = sp.sympify(row).xreplace(swap)
        split = linear_terms(row, plain)
        if split is not None:  # FrStar builds rows already arranged
            coefs, rest = split
        else:
            coefs = [row.diff(a) for a in plain]
            rest = row.xreplace(zero)
        coefs = [polish(c.xreplace(back)) for c in coefs]
        rest = polish(rest.xreplace(back), gens)
        out.append(rest + sum(c * a for c, a in zip(coefs, accels, strict=True)))
    return out


def _as_is(expr: Any, gens: Sequence[Any] = ()) -> Any:
    return expr
