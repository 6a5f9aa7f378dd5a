"""Python's cyclic garbage collector kept quiet while sympy makes objects.

Deriving a model, printing its transcript, walking a quantity into a numpy
tape and writing its programs each make millions of small objects that all
live on (sympy's expressions are trees, the printers' memos keep them): the
collector, run at its default pace, walks them again and again and finds
nothing (a tenth to a fifth of the work).  :class:`Quiet` is the one way
the runtime quiets it, in either of two strengths:

* ``Quiet()``: the thresholds raised (``gc.set_threshold``), for work as
  long as a module's derivation, which may leave cyclic garbage;
* ``Quiet(paused=True)``: the collector paused (``gc.disable``), for a
  walk that makes no garbage of note (:func:`paused`);
* :func:`settled`: paused for one statement of a derivation, whose new
  objects then join the model out of the collector's sight (``gc.freeze``).

Each puts back what it changed with :meth:`Quiet.restore` (or on leaving
its ``with`` block, or when the object goes: an import that failed).
"""

from __future__ import annotations

import gc
import weakref
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

__all__ = ["THRESHOLDS", "Quiet", "paused", "settled"]

#: the raised thresholds: collect the youngest generation after this many
#: new objects (700 by default), the oldest hardly ever
THRESHOLDS = (100_000, 50, 1000)


class Quiet:
    """The collector quieted (see the module) until :meth:`restore`."""

    def __init__(self, paused: bool = False) -> None:
        if paused:
            enabled = gc.isenabled()
            gc.disable()
            self._finalizer = weakref.finalize(self, _enable_if, enabled)
            return
        saved = gc.get_threshold()
        gc.set_threshold(*(max(a, b) for a, b in zip(saved, THRESHOLDS, strict=True)))
        self._finalizer = weakref.finalize(self, gc.set_threshold, *saved)

    def restore(self) -> None:
        """Put back what was changed (once; again does nothing)."""
        self._finalizer()

    def __enter__(self) -> Quiet:
        return self

    def __exit__(self, *exc: Any) -> None:
        self.restore()


def _enable_if(enabled: bool) -> None:
    if enabled:
        gc.enable()


@contextmanager
def paused() -> Iterator[None]:
    """The collector paused for the ``with`` block (as it was after)."""
    with Quiet(paused=True):
        yield


@contextmanager
def settled() -> Iterator[None]:
    """The collector paused for the ``with`` block (as it was after), and,
    when the block ends without an error, every object it tracks moved out
    of its sight (``gc.freeze``), as at the end of a derivation.

    For one statement of a generated module's derivation: its new objects
    are the model's and live on, so a collection would walk each of them
    once and free next to nothing (a twentieth of DAS3's import; a few
    thousand small objects of cyclic garbage in all are kept).  A block
    that fails (an error, an interrupt: the import fails) gives back what
    was frozen (``gc.unfreeze``), so that a failed import's objects are
    collected as any others.

    >>> import gc
    >>> frozen = gc.get_freeze_count()
    >>> with settled():
    ...     gc.isenabled()
    False
    >>> gc.get_freeze_count() > frozen
    True
    >>> gc.unfreeze()
    """
    quiet = Quiet(paused=True)
    try:
        yield
    except BaseException:
        gc.unfreeze()
        raise
    else:
        gc.freeze()  # before the collector runs again: nothing new to walk
    finally:
        quiet.restore()
