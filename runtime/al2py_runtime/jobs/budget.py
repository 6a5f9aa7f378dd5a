"""Limits that keep a numerical job from running forever.

A stiff system (``x' = -1e8*(x - cos(T))``) makes an explicit integrator take
billions of tiny steps; integrating backwards through damping blows up.  Every
``CODE Dynamics``/``ODE`` integration therefore has a budget:

* ``seconds``: wall-clock time of one integration (default 120 s);
* ``evaluations``: right-hand-side evaluations (default 5,000,000).

Change them for one process with the environment variables
``AL2PY_MAX_SECONDS`` and ``AL2PY_MAX_EVALS``, from Python by assigning
``al2py_runtime.jobs.budget.LIMITS["seconds"] = 600``, or for ``python model.py``
with ``--max-seconds`` and ``--max-evals``.  When a budget is exhausted the job
stops with an error naming the time reached.  ``TFINAL`` before ``TINITIAL``
is an error too.

While an integration runs longer than two seconds and :data:`PROGRESS` is true
(``python model.py`` sets it when standard output is a terminal), a progress
line ``integrating: t = 3.2 of 10 (32%)`` is updated on standard error.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from typing import Any

__all__ = [
    "LIMITS",
    "PROGRESS",
    "Meter",
    "limits",
    "check_span",
    "exhausted",
    "guard",
    "clear_progress",
]

#: defaults; the environment variables below override them
LIMITS: dict[str, float] = {"seconds": 120.0, "evaluations": 5_000_000}
_ENV = {"seconds": "AL2PY_MAX_SECONDS", "evaluations": "AL2PY_MAX_EVALS"}

#: show a progress line on standard error during long integrations
PROGRESS = False


def _error(message: str) -> Exception:
    from .records import NumericsError

    return NumericsError(message)


def limits() -> dict[str, float]:
    """The budget in force: :data:`LIMITS`, overridden by the environment."""
    out = dict(LIMITS)
    for key, var in _ENV.items():
        text = os.environ.get(var)
        if text:
            try:
                value = float(text)
            except ValueError:
                raise _error(f"{var}={text!r} is not a number") from None
            if not value > 0:
                raise _error(f"{var} must be positive, not {text}")
            out[key] = value
    return out


def check_span(t0: float, t1: float) -> None:
    """``TFINAL`` must not come before ``TINITIAL``."""
    if t1 < t0:
        raise _error(
            f"TFINAL = {t1:g} is before TINITIAL = {t0:g}; "
            "Autolev integrates forward in time"
        )


def guard(
    fun: Callable[[float, Any], Any], where: str, t0: float, t1: float
) -> Callable[[float, Any], Any]:
    """``fun`` (an ODE right-hand side) counting its evaluations and the time
    spent; raises an error naming ``where`` when the budget is exhausted."""
    budget = limits()
    max_evals = int(budget["evaluations"])
    max_seconds = budget["seconds"]
    start = time.monotonic()
    state = {"n": 0, "shown": start + 2.0}

    def guarded(tt: float, y: Any) -> Any:
        state["n"] += 1
        n = state["n"]
        if n > max_evals:
            raise exhausted(where, tt, t1, evaluations=max_evals)
        if n % 256 == 0:
            now = time.monotonic()
            if now - start > max_seconds:
                raise exhausted(where, tt, t1, seconds=max_seconds)
            if PROGRESS and now >= state["shown"]:
                state["shown"] = now + 0.5
                _show(tt, t0, t1)
        return fun(tt, y)

    return guarded


def exhausted(
    where: str,
    tt: float,
    t1: float,
    evaluations: int | None = None,
    seconds: float | None = None,
) -> Exception:
    """The error for an integration stopped at ``tt`` by its budget."""
    if evaluations is not None:
        spent = (
            f"after {evaluations} right-hand-side evaluations (the budget; raise"
            " it with --max-evals or AL2PY_MAX_EVALS)"
        )
    else:
        spent = (
            f"after {seconds:g} s (the time budget; raise it with --max-seconds"
            " or AL2PY_MAX_SECONDS)"
        )
    return _error(
        f"{where}: stopped at t = {tt:.6g} of {t1:g} {spent}.  The equations may"
        " be stiff, or integStp/absErr/relErr too small"
    )


class Meter:
    """The budget of an integration that counts its own evaluations (the
    compiled integrator): what is left, and the progress line."""

    def __init__(self, where: str, t0: float, t1: float) -> None:
        budget = limits()
        self.where, self.t0, self.t1 = where, t0, t1
        self.max_evals = int(budget["evaluations"])
        self.max_seconds = budget["seconds"]
        self.start = time.monotonic()
        self.shown = self.start + 2.0

    def seconds_left(self) -> float:
        """Seconds of the time budget left (at least a millisecond)."""
        return max(self.max_seconds - (time.monotonic() - self.start), 1e-3)

    def tick(self, tt: float) -> None:
        """After an integration reached ``tt``: the progress line."""
        now = time.monotonic()
        if now - self.start > self.max_seconds:
            raise exhausted(self.where, tt, self.t1, seconds=self.max_seconds)
        if PROGRESS and now >= self.shown:
            self.shown = now + 0.5
            _show(tt, self.t0, self.t1)


_shown = [False]


def _show(tt: float, t0: float, t1: float) -> None:
    _shown[0] = True
    span = t1 - t0
    pct = f" ({100 * (tt - t0) / span:.0f}%)" if span else ""
    try:
        sys.stderr.write(f"\rintegrating: t = {tt:.4g} of {t1:g}{pct}   ")
        sys.stderr.flush()
    except (OSError, ValueError):
        pass


def clear_progress() -> None:
    """Erase the progress line, if one was shown."""
    if not _shown[0]:
        return
    _shown[0] = False
    try:
        sys.stderr.write("\r" + " " * 60 + "\r")
        sys.stderr.flush()
    except (OSError, ValueError):
        pass
