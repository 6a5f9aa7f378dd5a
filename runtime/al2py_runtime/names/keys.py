"""Parsing of Autolev spellings used as keys: ``"M0[2,2]"``, ``"STRETCH'"``, ``"H>"``.

>>> parse_key("m0[2, 2]")
Key(name='M0', primes=0, index=(2, 2))
>>> parse_key("stretch''")
Key(name='STRETCH', primes=2, index=())
"""

from __future__ import annotations

import re
from typing import NamedTuple

__all__ = ["Key", "parse_key"]

_KEY = re.compile(
    r"""^\s*(?P<name>[A-Za-z][A-Za-z0-9_]*>{0,3}|0>|1>>)\s*
        (?P<primes>'*)\s*
        (?:\[\s*(?P<index>\d+\s*(?:,\s*\d+\s*)?)\])?\s*$""",
    re.VERBOSE,
)


class Key(NamedTuple):
    """An Autolev name as a lookup key: canonical name, primes, 1-based index."""

    name: str
    primes: int
    index: tuple[int, ...]

    def __str__(self) -> str:
        text = self.name + "'" * self.primes
        if self.index:
            text += "[" + ",".join(map(str, self.index)) + "]"
        return text


def parse_key(text: str) -> Key:
    """Split an Autolev spelling into a :class:`Key` (case-insensitive)."""
    m = _KEY.match(text)
    if m is None:
        raise KeyError(f"{text!r} is not an Autolev name")
    index = m.group("index")
    idx = tuple(int(i) for i in index.split(",")) if index else ()
    return Key(m.group("name").upper(), len(m.group("primes")), idx)
