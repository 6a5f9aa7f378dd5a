"""Random expressions for the printers' property tests: sums, products,
powers, sines and cosines (and, if asked, intermediates' shape) over given
leaves, so that an ordering or a memo is checked against sympy's on many
trees rather than a few written by hand."""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp


@dataclass(frozen=True)
class ExpressionMaker:
    """Makes random expressions of a given depth.

    ``leaves``: what a leaf is chosen from; ``coefficients``: the numbers
    that multiply a product or each term of a weighted sum; ``exponents``:
    a power's; ``leaf_chance``: the chance that a node above depth 0 is a
    leaf; ``intermediate(rng, parts)``: a node of an intermediate's shape
    (None: no such nodes)."""

    leaves: Sequence[Any]
    coefficients: Sequence[Any]
    exponents: Sequence[Any]
    leaf_chance: float
    intermediate: Callable[[random.Random, list], sp.Expr] | None = None

    def make(self, rng: random.Random, depth: int) -> sp.Expr:
        if depth == 0 or rng.random() < self.leaf_chance:
            return rng.choice(self.leaves)
        kind = rng.randrange(6 if self.intermediate is None else 7)
        parts = [self.make(rng, depth - 1) for _ in range(rng.randint(2, 4))]
        if kind == 0:
            return sp.Add(*parts)
        if kind == 1:
            return rng.choice(self.coefficients) * sp.Mul(*parts)
        if kind == 2:
            return sp.Mul(*parts)
        if kind == 3:
            return parts[0] ** rng.choice(self.exponents)
        if kind == 4:
            return rng.choice([sp.sin, sp.cos])(parts[0])
        if kind == 5 and self.intermediate is not None:
            return self.intermediate(rng, parts)
        return sp.Add(*[rng.choice(self.coefficients) * p for p in parts])


def written_tree(e: Any) -> str:
    """``e`` written with every argument in its stored order, for comparing
    two ways of forming an expression node for node (sympy's printers,
    ``srepr`` too, sort a sum's terms and a product's factors; two books'
    intermediates are of different classes, so they are compared by text).
    A tuple is written as its items.

    >>> x, y = sp.symbols("x y")
    >>> written_tree(sp.Add(x, y, evaluate=False))
    "Add(Symbol('x'),Symbol('y'))"
    >>> written_tree(sp.Add(y, x, evaluate=False))
    "Add(Symbol('y'),Symbol('x'))"
    """
    if isinstance(e, tuple):
        return "(" + ",".join(written_tree(a) for a in e) + ")"
    if isinstance(e, sp.Basic) and e.args and not e.is_Atom:
        return type(e).__name__ + "(" + ",".join(written_tree(a) for a in e.args) + ")"
    return sp.srepr(e)


def plain_factor(
    rng: random.Random,
    pools: tuple[Sequence, Sequence, Sequence, Sequence, Any],
    odd: Sequence | None = None,
) -> sp.Expr:
    """A factor that sympy's light simplifications (``factor_terms``,
    ``TR10i``) leave alone, from ``pools = (rates, angles, constants,
    intermediates, t)``: a rate, its derivative, a constant, an
    intermediate, an angle, or the sine or cosine of an angle or of the
    first constant.  With ``odd``, one more kind: half the time one of
    ``odd`` (factors whose arguments hold a sum those simplifications
    would change), else a rate.

    >>> t = sp.Symbol("t")
    >>> f = plain_factor(random.Random(1), ([t], [t], [t], [t], t))
    >>> f.has(t)
    True
    """
    rates, angles, constants, intermediates, t = pools
    kind = rng.randrange(6 if odd is None else 7)
    if kind == 6:
        return rng.choice(odd if rng.random() < 0.5 else rates)
    if kind == 0:
        return rng.choice(rates)
    if kind == 1:
        return sp.Derivative(rng.choice(rates), t)
    if kind == 2:
        return rng.choice(constants)
    if kind == 3:
        return rng.choice(intermediates)
    if kind == 4:
        return rng.choice(angles)
    return rng.choice([sp.sin, sp.cos])(rng.choice(list(angles) + list(constants[:1])))
