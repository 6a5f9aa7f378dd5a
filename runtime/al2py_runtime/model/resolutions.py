"""The model's substitutions of right-hand sides, each made once.

A derivation resolves the same quantities many times: ``Fr()`` resolves the
velocity of each loaded point, ``FrStar()`` the same velocities again for
their linear forms, and its check of a given acceleration the acceleration
it then uses; each velocity formed from a position resolves the velocities
it is built on.  :meth:`Resolutions.resolver` keeps, for each set of kept
quantities, one resolver (the script's, whose walks share their parts) and
the answer for each expression it was given, as long as the script's
right-hand sides stay the same (a new or changed right-hand side starts
afresh).  The answers are the script's own: a resolution depends only on
the expression, the right-hand sides and what is kept -- and of what is
kept, only the quantities that have a right-hand side.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

import sympy as sp

if TYPE_CHECKING:
    from ..names.table import NameTable
    from .script import ScriptNames

__all__ = ["Resolutions"]


class Resolutions:
    """The script's resolvers (:meth:`ScriptNames.resolver`), remembered
    while its right-hand sides do not change."""

    def __init__(self, script: ScriptNames, table: NameTable) -> None:
        self._script = script
        self._table = table
        #: the table's count of changes the remembered answers were made at
        #: (None: nothing remembered yet)
        self._changes: int | None = None
        #: whether every right-hand side is a sympy object (a value that may
        #: change in place, such as a mutable matrix, is never remembered)
        self._immutable = True
        self._resolvers: dict[frozenset, Callable[[Any], Any]] = {}

    def resolver(self, keep: Iterable[Any] = ()) -> Callable[[Any], Any]:
        """``script.resolver(keep)``, answering an expression it has
        resolved before from memory."""
        rhs = self._table.rhs
        if self._changes != self._table.rhs_changes:
            self._resolvers.clear()
            self._changes = self._table.rhs_changes
            self._immutable = all(isinstance(v, sp.Basic) for v in rhs.values())
        # a kept quantity without a right-hand side changes nothing
        kept = frozenset(k for k in (sp.sympify(x) for x in keep) if k in rhs)
        found = self._resolvers.get(kept)
        if found is None:
            found = self._remembering(self._script.resolver(kept))
            if self._immutable:
                self._resolvers[kept] = found
        return found

    @staticmethod
    def _remembering(resolve: Callable[[Any], Any]) -> Callable[[Any], Any]:
        memo: dict = {}

        def apply(expr: Any) -> Any:
            if not isinstance(expr, sp.Basic):
                return resolve(expr)
            found = memo.get(expr)
            if found is None:
                found = memo[expr] = resolve(expr)
            return found

        return apply
