"""The name table: what each Autolev name of a script is and holds.

One :class:`NameTable` per script (``Workspace.table``).  It answers what a
name was declared as (:attr:`NameTable.entries`), the right-hand side of a
scalar quantity or derivative (:attr:`NameTable.rhs`), the value of a
matrix, vector or dyadic (:attr:`NameTable.stored`) and the name of a sympy
object (:attr:`NameTable.by_obj`).  The workspace applies Autolev's rules on
top; the model and the numeric jobs read and extend the table here.

>>> import sympy as sp
>>> table = NameTable()
>>> a = table.declare("a", "constant", sp.Symbol("A"))
>>> table.entries["A"].kind, table.by_obj[a]
('constant', 'A')
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.physics.vector import dynamicsymbols

__all__ = ["Entry", "NameTable"]

#: Autolev's ``T`` (sympy.physics.mechanics' time symbol)
TIME = dynamicsymbols._t


@dataclass
class Entry:
    """What a name is: ``kind`` and the sympy/mechanics object standing for it."""

    kind: str
    obj: Any
    sign: str | None = None
    order: int = 0  # highest declared derivative for variables
    extra: dict = field(default_factory=dict)
    line: int | None = None  # the script line that declared it


class NameTable:
    """A script's names (keys are upper-case Autolev names)."""

    def __init__(self) -> None:
        #: declared and assigned scalar names -> :class:`Entry`
        self.entries: dict[str, Entry] = {}
        #: right-hand sides: a quantity's symbol or a variable's derivative
        #: (``Derivative(X, t)``) -> its value; read here, written only by
        #: :meth:`set_rhs`
        self.rhs: dict[sp.Basic, Any] = {}
        #: how many times :attr:`rhs` has been written (what remembers
        #: answers made with the right-hand sides compares this number)
        self.rhs_changes = 0
        #: matrices, vectors and dyadics: name -> value
        self.stored: dict[str, Any] = {}
        #: sympy object -> the name it stands for
        self.by_obj: dict[sp.Basic, str] = {}

    def declare(self, name: str, kind: str, obj: Any, **kw: Any) -> Any:
        """Enter ``name`` as a ``kind`` standing for ``obj``; returns ``obj``."""
        key = name.upper()
        self.entries[key] = Entry(kind, obj, **kw)
        if isinstance(obj, sp.Basic):
            self.by_obj[obj] = key
        return obj

    def set_rhs(self, key: Any, value: Any) -> None:
        """Give ``key`` (a quantity or a variable's derivative) the right-hand
        side ``value``."""
        self.rhs[key] = value
        self.rhs_changes += 1

    def rhs_key(self, name: str, primes: int = 0) -> Any:
        """The key of :attr:`rhs` for ``name`` or its ``primes``-th derivative."""
        obj = self.entries[name].obj
        return sp.Derivative(obj, TIME, primes) if primes else obj
