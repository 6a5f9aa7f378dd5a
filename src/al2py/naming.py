"""The deterministic rule that turns Autolev names into Python identifiers.

The rule (also in the README):

1. Start from the name as first spelled in the script (Autolev is
   case-insensitive, so later spellings map to the same identifier).
2. Vectors drop their ``>`` and gain ``_vec``, dyadics ``_dyad``, higher
   polyadics ``_poly``: ``H>`` -> ``H_vec``, ``I_SYSTEM_CM>>`` ->
   ``I_SYSTEM_CM_dyad``.
3. Frames, bodies, particles and points keep their name.  A scalar or matrix
   that shares its name with one of them gains ``_val``: tutor8's body ``A``
   stays ``A`` and its matrix ``A`` is ``A_val``.
4. A Python keyword, builtin, a name the generated module itself uses
   (``al``, ``t``, ``run``, runtime functions such as ``cos``), or one of the
   ambiguous single letters ``l``, ``O``, ``I`` gains a trailing ``_``.
5. Any remaining clash (e.g. a scalar literally called ``H_vec`` next to
   ``H>``) is broken by appending ``_2``, ``_3``, ... in order of first
   appearance.

>>> n = Namer(reserved={"al", "t"})
>>> n.assign("H>", "H>", "vector"), n.assign("H", "H", "scalar")
('H_vec', 'H')
>>> n.assign("LAMBDA", "lambda", "scalar"), n.assign("T2", "t", "scalar")
('lambda_', 't_')
"""

from __future__ import annotations

import builtins
import keyword
import re

from al2py_runtime.vocabulary import OBJECT_DECLS, Decl

__all__ = ["Namer"]

_SUFFIX = {Decl.VECTOR: "_vec", Decl.DYADIC: "_dyad", Decl.POLYADIC: "_poly"}
_VALID = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
_PYTHON_NAMES = (
    frozenset(keyword.kwlist)
    | frozenset(keyword.softkwlist)
    | frozenset(dir(builtins))
    | {"l", "O", "I"}  # ambiguous letters (pycodestyle E741)
)


class Namer:
    """Hands out collision-free identifiers; remembers each canonical name's."""

    def __init__(self, reserved: set[str] | frozenset[str] = frozenset()) -> None:
        self._reserved = set(reserved)
        self._by_key: dict[str, str] = {}
        self._taken: set[str] = set()
        self._physical: set[str] = set()

    def note_physical(self, canonical: str) -> None:
        """Declare up front that ``canonical`` names a frame/body/point."""
        self._physical.add(canonical.upper())

    def reserve(self, ident: str) -> None:
        self._reserved.add(ident)

    def get(self, key: str) -> str | None:
        return self._by_key.get(key)

    def assign(self, key: str, spelling: str, kind: Decl) -> str:
        """The identifier for canonical ``key`` (first call decides)."""
        if key in self._by_key:
            return self._by_key[key]
        base = spelling.rstrip(">")
        if not _VALID.match(base):
            base = re.sub(r"\W", "_", base) or "name"
            if base[0].isdigit():
                base = "n_" + base
        base += _SUFFIX.get(kind, "")
        shared = key.rstrip(">") in self._physical and kind not in _SUFFIX
        if kind not in OBJECT_DECLS and shared:
            base += "_val"
        if base in _PYTHON_NAMES or base in self._reserved or base.startswith("__"):
            base += "_"
        ident, n = base, 1
        while ident in self._taken or ident in self._reserved:
            n += 1
            ident = f"{base}_{n}"
        self._taken.add(ident)
        self._by_key[key] = ident
        return ident
