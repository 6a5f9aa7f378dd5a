"""Run a benchmark step in a child process with a time budget."""

from __future__ import annotations

import multiprocessing as mp
import time
from collections.abc import Callable
from typing import Any


def _child(queue: Any, fn: Callable[..., Any], args: tuple) -> None:
    start = time.perf_counter()
    try:
        out = fn(*args)
    except Exception as exc:  # reported by the parent, never raised there
        queue.put(
            ("error", f"{type(exc).__name__}: {exc}", time.perf_counter() - start)
        )
        return
    queue.put(("ok", out, time.perf_counter() - start))


def within(budget: float, fn: Callable[..., Any], *args: Any) -> tuple[str, Any, float]:
    """``(status, result, seconds)``: status ``ok``, ``error`` or ``budget``.

    ``fn`` runs in a forked child (so a model that never finishes deriving is
    stopped after ``budget`` seconds); its result must pickle."""
    ctx = mp.get_context("fork")
    queue = ctx.Queue()
    proc = ctx.Process(target=_child, args=(queue, fn, args))
    proc.start()
    try:
        status, out, seconds = queue.get(timeout=budget)
    except Exception:  # queue.Empty: over budget
        status, out, seconds = "budget", None, budget
    proc.join(timeout=1)
    if proc.is_alive():
        proc.kill()
        proc.join()
    return status, out, seconds


def show(status: str, seconds: float, budget: float) -> str:
    if status == "ok":
        return f"{seconds:.2f}"
    if status == "budget":
        return f">{budget:.0f}"
    return "error"


def exponent(sizes: list[int], seconds: list[float | None]) -> str:
    """Least-squares slope of log(time) against log(size)."""
    import math

    pts = [(math.log(n), math.log(t)) for n, t in zip(sizes, seconds, strict=True) if t]
    if len(pts) < 2:
        return "-"
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    sxy = sum((x - mx) * (y - my) for x, y in pts)
    return f"{sxy / sxx:.1f}" if sxx else "-"
