"""Reading an expression as linear in given quantities, term by term.

The model (``Fr()``, ``FrStar()``, ``Constrain``) and the intermediates'
book (``ZEE_NOT``, :meth:`Intermediates.name_linear`) both split
expressions as ``sum(c_k * x_k) + rest``; this module sits below both.

>>> import sympy as sp
>>> x, y, a = sp.symbols("x y a")
>>> linear_terms(a * x + 2 * y + a, [x, y])
([a, 2], a)
>>> linear_terms(x * y, [x, y]) is None
True
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import sympy as sp

from .walks import appearing

__all__ = ["linear_terms"]


def linear_terms(expr: Any, xs: Sequence[Any]) -> tuple[list[Any], Any] | None:
    """``expr = sum(c_k * x_k) + rest`` read term by term (no differentiation,
    no expansion), or None if a term is not of that form."""
    position = {x: k for k, x in enumerate(xs)}
    wanted = frozenset(xs)
    coefs: list[Any] = [sp.Integer(0)] * len(xs)
    rest = []
    for term in sp.Add.make_args(expr):
        found = _one_factor(term, xs, wanted)
        if found is None:
            return None
        factor, var = found
        if var is None:
            rest.append(term)
            continue
        if var not in position:
            return None
        coefs[position[var]] += factor
    return coefs, sp.Add(*rest)


def _one_factor(
    term: Any, xs: Sequence[Any], wanted: frozenset
) -> tuple[Any, Any] | None:
    """``(term, None)`` for a term without ``xs``, else
    ``term.as_independent(*xs, as_Add=False)`` when only one factor holds
    them (None otherwise).  sympy's asks each factor for its free symbols and
    walks it again, without seeing that the factors of a large model share
    their parts (a tenth of a bicycle's import); here each factor is walked
    once, shared parts once."""
    if not term.is_Mul:
        return (sp.S.One, term) if _holds(term, wanted) else (term, None)
    args, nc = term.args_cnc()
    if nc:  # sympy's rule for noncommutative factors
        if not term.has(*xs):
            return term, None
        factor, var = term.as_independent(*xs, as_Add=False)
        return None if factor.has(*xs) else (factor, var)
    depend = [k for k, a in enumerate(args) if _holds(a, wanted)]
    if not depend:
        return term, None
    if len(depend) != 1:
        return None
    var = args[depend[0]]
    return sp.Mul(*(a for k, a in enumerate(args) if k != depend[0])), var


def _holds(e: Any, wanted: frozenset) -> bool:
    """Whether ``e`` has one of ``wanted`` (symbols, functions of time or
    derivatives): ``e.has(*wanted)``."""
    if e in wanted:
        return True
    return bool(e.args) and bool(appearing(e, wanted))
