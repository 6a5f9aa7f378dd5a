"""A long transcript printed side by side by this process and a forked copy
(``names.responses``): the same lines as this process alone prints, the
copy's parts really printed there, and a copy that fails replaced here."""

from __future__ import annotations

import multiprocessing
import os
import random

import pytest
import sympy as sp
from al2py_runtime.names import responses as R
from al2py_runtime.names.settings import Response
from al2py_runtime.names.transcript import printed_transcript, transcript_lines

pytestmark = pytest.mark.skipif(
    "fork" not in multiprocessing.get_all_start_methods(),
    reason="no fork here: a transcript is printed by one process",
)

NAMES = sp.symbols("A B C Q1 Q2 U1 U2")


def _value(rng: random.Random) -> sp.Expr:
    """A random sum of products of the names and small powers."""
    terms = []
    for _ in range(rng.randint(1, 5)):
        factors = [sp.Integer(rng.randint(-9, 9) or 1)]
        for _ in range(rng.randint(1, 3)):
            x = rng.choice(NAMES)
            factors.append(rng.choice([x, x**2, sp.sin(x), sp.cos(x)]))
        terms.append(sp.Mul(*factors))
    return sp.Add(*terms)


def _responses(n: int, seed: int = 7) -> list[Response]:
    rng = random.Random(seed)
    return [Response(i // 3 + 1, f"Z{i + 1}", _value(rng), 7) for i in range(n)]


def test_shared_lines_are_this_process_lines() -> None:
    responses = _responses(R.MIN_SHARED + 150)
    alone = R.response_lines(responses, _doubled, copies=1)
    shared = R.response_lines(responses, _doubled, copies=2)
    assert shared == alone
    assert len(alone) == len(responses)
    assert alone[0] == [f"Z1 = {_text(2 * responses[0].value)}"]
    assert alone[-1] == [f"Z{len(responses)} = {_text(2 * responses[-1].value)}"]


def _doubled(value: sp.Expr) -> sp.Expr:
    return 2 * value


def _text(value: sp.Expr) -> str:
    from al2py_runtime.names.printing import Printing

    return Printing().autolev_str(value)


def _marked(value: sp.Expr) -> sp.Expr:
    """The value with the printing process's id: who printed what."""
    return value + sp.Symbol(f"PID{os.getpid()}")


def test_the_copy_prints_the_last_parts() -> None:
    responses = _responses(R.MIN_SHARED + 50)
    lines = R.response_lines(responses, _marked, copies=2)
    mine = f"PID{os.getpid()}"
    by_us = [mine in text[0] for text in lines]
    assert by_us[0]  # this process starts at the first part
    assert not by_us[-1]  # the copy at the last one
    # each prints whole consecutive parts: ours first, then the copy's
    first_copy = by_us.index(False)
    assert not any(by_us[first_copy:])


def test_few_responses_are_printed_here() -> None:
    responses = _responses(R.MIN_SHARED - 1)
    lines = R.response_lines(responses, _marked, copies=2)
    assert all(f"PID{os.getpid()}" in text[0] for text in lines)


def test_a_failing_copy_is_replaced_here() -> None:
    parent = os.getpid()

    def form(value: sp.Expr) -> sp.Expr:
        if os.getpid() != parent:
            raise RuntimeError("the copy fails")
        return value

    responses = _responses(R.MIN_SHARED + 10, seed=3)
    assert R.response_lines(responses, form, copies=2) == R.response_lines(
        responses, form
    )


def test_an_error_here_is_raised_as_alone() -> None:
    parent = os.getpid()

    def form(value: sp.Expr) -> sp.Expr:
        if os.getpid() == parent:
            raise ValueError("cannot form")
        return value

    with pytest.raises(ValueError, match="cannot form"):
        R.response_lines(_responses(R.MIN_SHARED), form, copies=2)


def test_transcript_numbers_lines_after_shared_printing() -> None:
    responses = _responses(R.MIN_SHARED + 3)
    source = [f"Z{i} = something" for i in range(1, responses[-1].line + 1)]
    alone = transcript_lines(source, responses)
    shared = printed_transcript(source, R.ResponseLines(responses, copies=2))
    assert shared == alone
    assert alone[0] == "(1) Z1 = something"
    assert alone[1].startswith("-> (2) Z1 = ")
    assert alone[-1].startswith(f"-> ({len(alone)}) Z{len(responses)} = ")


def test_no_copy_while_another_thread_runs() -> None:
    import threading

    stop = threading.Event()
    other = threading.Thread(target=stop.wait)
    other.start()
    try:
        assert R.side_by_side() == 1
    finally:
        stop.set()
        other.join()
    if threading.active_count() == 1:  # this process alone again
        from al2py_runtime.copies import processors

        assert R.side_by_side() == min(2, processors())
