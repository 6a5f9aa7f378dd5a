"""Keys that do not change between processes: what a compiled quantity is
kept under on disk (:mod:`.quantities`), found without printing it.

A fresh process that sweeps a quantity compiled by an earlier process
should load the library in milliseconds, not redo the numeric form and the
C printing to find the printed text's hash.  The key is computed from what
the compiled function computes, the same way in every process:

* the quantity's numpy tape (:meth:`.tape.Tape.digest`: every operation,
  constant and parameter slot, in the order of a walk that every process
  makes alike; never Python's ``hash()`` of a string, which varies between
  processes), the parameters' names and kinds and the quantity's shape;
* the runtime itself (:func:`runtime_digest`: its source files' bytes, and
  the versions of Python, sympy and numpy);
* what the caller adds (the quantity's name, the backend, the compiler and
  its flags).

Whatever changes the function (a line of the script, an Input that
replaces a value the script gave, another runtime) changes the key: a
stale library is never reused.  Two states that compute the same function
share it, which is right.
"""

from __future__ import annotations

import functools
import hashlib
import platform
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

__all__ = ["FORMAT", "quantity_key", "runtime_digest"]

#: a change of what a key holds changes this
FORMAT = "al2py-quantity-1"


@functools.lru_cache(maxsize=1)
def runtime_digest() -> str:
    """The runtime's source files (their bytes), Python's, sympy's and
    numpy's versions and the machine: a new runtime never reuses what an
    older one compiled."""
    import numpy as np
    import sympy as sp

    root = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for text in (sys.version, sp.__version__, np.__version__, platform.machine()):
        digest.update(text.encode() + b"\0")
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()


def quantity_key(
    tape: Any,
    name: str,
    shape: tuple[int, ...],
    params: list[str],
    kinds: list[str],
    extra: Iterable[Any] = (),
) -> str:
    """The key of the quantity ``name`` whose numpy tape is ``tape``, of
    shape ``shape``, with the parameters ``params`` (names, in the tape's
    order) of kinds ``kinds``; ``extra``: what else the compiled form
    depends on (texts: the backend, the compiler, its flags).  32 hex
    digits."""
    parts = [
        FORMAT,
        runtime_digest(),
        name,
        repr(tuple(shape)),
        repr(list(params)),
        repr(list(kinds)),
        tape.digest(),
        *map(str, extra),
    ]
    return hashlib.sha256("\0".join(parts).encode()).hexdigest()[:32]
