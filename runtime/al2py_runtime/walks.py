"""sympy's tree walks, each distinct subexpression visited once.

sympy's ``xreplace`` and ``replace`` walk an expression as a tree: a part
that occurs many times (an intermediate ``Z12(q1, q4, ...)`` used by many
products, its arguments, a shared product) is walked each time it occurs.
Expressions over named intermediates share most of their parts, so these
walks keep one answer per distinct part, and an object with a
``walk_parts()`` method (an intermediate: the set of all parts of its
arguments, kept) is answered from that set rather than walked.  Each gives sympy's result: the
answer for a part depends only on the part (sympy's ``==``, which the
memo's lookup uses, is structural), and parts are rebuilt exactly when
sympy rebuilds them.

:func:`vmap` maps a function over the scalars of a vector, dyadic or matrix.
"""

from __future__ import annotations

import sys
from collections.abc import Callable
from typing import Any

import sympy as sp
from sympy.physics.vector import Dyadic, Vector

__all__ = ["appearing", "atoms", "replace", "vmap", "xreplace"]


def allow_deep_recursion() -> None:
    """Room for walks over deep expressions (a long chain of intermediates
    nests as deep as it is long)."""
    if sys.getrecursionlimit() < 20000:
        sys.setrecursionlimit(20000)


def xreplace(
    expr: Any,
    rule: dict,
    memo: dict | None = None,
    rebuild: Callable[[Any, list, list[int]], Any] | None = None,
) -> Any:
    """``expr.xreplace(rule)`` for a sympy object (anything else is
    returned as it is).  ``memo`` may be shared by calls with the same
    ``rule`` (a part's answer depends on the part and the rule only).
    ``rebuild(e, args, changed)`` forms a part from its new arguments (the
    positions of those that changed given), where sympy's ``e.func(*args)``
    would give the same object another way."""
    if not isinstance(expr, sp.Basic):
        return expr
    if not rule:
        return expr
    allow_deep_recursion()
    if memo is None:
        memo = {}

    def walk(e: Any) -> tuple[Any, bool]:
        # Basic._xreplace: a part in the rule is replaced; otherwise it is
        # rebuilt from its arguments when a replacement happened below.
        if e in rule:
            return rule[e], True
        if e.is_Atom:
            return e, False
        found = memo.get(e)
        if found is not None:
            return found
        if e.is_Function and hasattr(e, "walk_parts"):
            # an intermediate: none of its parts is replaced
            if rule.keys().isdisjoint(e.walk_parts()):
                memo[e] = out = (e, False)
                return out
        args = []
        changed = []
        for i, a in enumerate(e.args):
            if isinstance(a, sp.Basic):
                b, c = walk(a)  # noqa: F821 - deleted after the walk
                args.append(b)
                if c:
                    changed.append(i)
            else:  # pragma: no cover - sympy's arguments are Basic
                args.append(a)
        if not changed:
            out = (e, False)
        elif rebuild is None:
            out = (e.func(*args), True)
        else:
            out = (rebuild(e, args, changed), True)
        memo[e] = out
        return out

    try:
        return walk(expr)[0]
    finally:
        del walk  # it refers to itself: freed now with its memo, not by a collection


def replace(expr: Any, query: Callable[[Any], Any], value: Callable[[Any], Any]) -> Any:
    """``expr.replace(query, value)`` with callables (``simultaneous``, no
    map), as sympy's ``Basic.replace`` does it: bottom-up, a part rebuilt
    from its replaced arguments, then replaced itself."""
    if not isinstance(expr, sp.Basic):
        return expr
    allow_deep_recursion()
    memo: dict[Any, Any] = {}

    def walk(rv: Any) -> Any:
        found = memo.get(rv)
        if found is not None:
            return found
        key = rv
        args = getattr(rv, "args", None)
        if args is not None:
            done = False
            if args:
                newargs = tuple([walk(a) for a in args])  # noqa: F821 - as above
                if args != newargs:
                    rv = rv.func(*newargs)
                    # sympy: a part that became one of its (changed)
                    # arguments is not replaced again
                    for i, e in enumerate(args):
                        if rv == e and e != newargs[i]:
                            done = True
                            break
            if not done:
                result = query(rv)
                if result or result == {}:
                    v = value(rv)
                    if v is not None and v != rv:
                        rv = v
        memo[key] = rv
        return rv

    try:
        return walk(expr)
    finally:
        del walk  # as in xreplace


def appearing(expr: Any, targets: Any) -> set:
    """The ``targets`` that occur in ``expr`` (``{x for x in targets if
    expr.has(x)}``): one walk for all of them, rather than sympy's two per
    target that does not occur.  Targets are symbols, functions of time,
    derivatives (anything but a sum or product, whose ``has`` also finds
    parts of a sum or product)."""
    wanted = set(targets)
    if not wanted or not isinstance(expr, sp.Basic):
        return set()
    if any(isinstance(x, sp.Add | sp.Mul) for x in wanted):
        return {x for x in wanted if expr.has(x)}
    found: set = set()
    seen: set = set()
    stack = [expr]
    while stack:
        e = stack.pop()
        if e in wanted:
            found.add(e)
            if len(found) == len(wanted):
                break
        if e.is_Function and hasattr(e, "walk_parts"):
            found.update(wanted.intersection(e.walk_parts()))
            continue
        for a in e.args:
            if a not in seen:
                seen.add(a)
                stack.append(a)
    return found


def atoms(expr: Any, *types: type) -> set:
    """``expr.atoms(*types)`` for types given (the parts of ``expr`` of
    those types), each distinct part walked once."""
    if not isinstance(expr, sp.Basic):
        return set()
    found: set = set()
    seen: set = {expr}
    stack = [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, types):
            found.add(e)
        for a in e.args:
            if a not in seen:
                seen.add(a)
                stack.append(a)
    return found


#: the zero measure numbers a vector's components are compared with
ZERO_MEASURES = sp.ImmutableMatrix([0, 0, 0])


def vector(components: list) -> Vector:
    """``Vector(components)`` (pairs of measure numbers and frame): sympy's
    vector of the sums of each frame's measure numbers, in the order the
    frames come, but those that are zero.  sympy compares each sum with a
    zero matrix it makes anew (most of the cost of a vector of short
    components); here with one, :data:`ZERO_MEASURES`."""
    found: dict = {}
    for m, frame in components:
        found[frame] = found[frame] + m if frame in found else m
    out = Vector(0)
    out.args = [(m, frame) for frame, m in found.items() if m != ZERO_MEASURES]
    return out


def vmap(x: Any, f: Callable[[Any], Any]) -> Any:
    """Apply ``f`` to every scalar of a Vector, Dyadic, Matrix or scalar."""
    if isinstance(x, Vector):
        return vector([(m.applyfunc(f), frame) for m, frame in x.args])
    if isinstance(x, Dyadic):
        out = Dyadic(0)
        for c, a, b in x.args:
            out += f(c) * (a | b)
        return out
    if isinstance(x, sp.MatrixBase):
        return sp.Matrix(x).applyfunc(f)
    return f(x)
