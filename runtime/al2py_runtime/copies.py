"""Forked copies of this process, for work done side by side: a
standard-library process pool (:class:`~concurrent.futures.ProcessPoolExecutor`
over ``fork``), whose copies start with this process's state (a derived
model, the runtime's tables) so that only results travel back.

``al2py code`` forms its programs in such copies (``codegen.Formers``) and
converts its script in one while it imports the runtime
(``al2py.codegen_c.converted``); ``python model.py`` prints a long
transcript with one (``names.responses``).  All start and end their copies
here:

* :func:`fork_pool`: the pool, or None where ``fork`` is missing or no
  process can be made (the work is then done in this process);
* :func:`forking`: around the ``submit`` that forks the copies, the
  signals held back until each copy has its own actions for them;
* :func:`started`: what each copy does first about signals;
* :func:`submit_forking`: the first work given, which forks the copies
  (under :func:`forking`);
* :func:`end_pool` (and :func:`end`, which sees whether work is left): the
  copies ended, at once when work is left (an error, or an interrupt in
  this process).

Only the standard library is imported here (the converter uses it before
sympy is imported).
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import signal
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import Future, ProcessPoolExecutor
from contextlib import contextmanager
from typing import Any

__all__ = [
    "end",
    "end_pool",
    "fork_pool",
    "forking",
    "processors",
    "started",
    "submit_forking",
]

#: the signals a copy acts on as :func:`started` says, held back meanwhile
_HELD = tuple(
    getattr(signal, name)
    for name in ("SIGINT", "SIGTERM", "SIGHUP")
    if hasattr(signal, name)
)


def processors() -> int:
    """The processors this process may run on (at least 1)."""
    affinity = getattr(os, "sched_getaffinity", None)
    if affinity is not None:
        with contextlib.suppress(OSError):
            return max(1, len(affinity(0)))
    return os.cpu_count() or 1


def fork_pool(
    workers: int,
    initializer: Callable[..., None] | None = None,
    initargs: tuple[Any, ...] = (),
) -> ProcessPoolExecutor | None:
    """A pool of ``workers`` forked copies (made at its first ``submit``),
    each running ``initializer(*initargs)`` after :func:`started`; None
    where ``fork`` is not available or the pool cannot be made."""
    if "fork" not in multiprocessing.get_all_start_methods():
        return None
    try:
        return ProcessPoolExecutor(
            workers,
            mp_context=multiprocessing.get_context("fork"),
            initializer=_start,
            initargs=(initializer, initargs),
        )
    except OSError:
        return None


def _start(initializer: Callable[..., None] | None, initargs: tuple) -> None:
    started()
    if initializer is not None:
        initializer(*initargs)


@contextmanager
def forking() -> Iterator[None]:
    """Around the ``submit`` that forks a pool's copies (a ``fork`` pool
    makes all of them at its first ``submit``): SIGINT, SIGTERM and SIGHUP
    are held back, so that none reaches a copy before it has its own
    actions for them (:func:`started`; a copy interrupted sooner would
    print Python's traceback), and this process gets them after."""
    held = signal.pthread_sigmask(signal.SIG_BLOCK, _HELD)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, held)


def started() -> None:
    """A copy starts: an interrupt is left to the process that forked it,
    which ends its copies (:func:`end_pool`), so that no copy prints one;
    SIGTERM and SIGHUP take their default action (the handlers of the
    process, which unwind its own command, are not the copy's).  Then the
    signals held back while it was forked (:func:`forking`) come through."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    for signum in _HELD:
        if signum != signal.SIGINT:
            signal.signal(signum, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, _HELD)


def end_pool(pool: ProcessPoolExecutor, *, work_left: bool) -> None:
    """The copies of ``pool`` ended and the pool shut down: at once (each
    copy terminated) when ``work_left``."""
    if work_left:
        for child in multiprocessing.active_children():
            child.terminate()
    pool.shutdown(wait=True, cancel_futures=True)


def submit_forking(
    pool: ProcessPoolExecutor, calls: Iterable[tuple[Callable[..., Any], tuple]]
) -> list[Future] | None:
    """``pool.submit(fn, *args)`` for each ``(fn, args)`` of ``calls``, in
    order; the first forks the pool's copies, under :func:`forking` (before
    the pool's own thread starts).  The futures, or None when the copies
    cannot be made (``OSError``: the pool is ended, the work is then done
    in this process).  An interrupt held back while the copies were forked
    comes through once they are made: they are ended before it leaves."""
    futures: list[Future] = []
    try:
        with forking():
            for fn, args in calls:
                futures.append(pool.submit(fn, *args))
    except OSError:
        end(pool, futures)
        return None
    except BaseException:
        end(pool, futures)
        raise
    return futures


def end(pool: ProcessPoolExecutor, futures: Iterable[Future | None]) -> None:
    """:func:`end_pool`, at once when one of ``futures`` is not done."""
    left = any(f is not None and not f.done() for f in futures)
    end_pool(pool, work_left=left)
