"""Autolev transcripts: numbered input lines interleaved with ``->`` responses.

Autolev numbers every input line and every response line in one sequence::

    (1) Constants A, B
    (2) X = 4*(A+B) - 3*(a-b)
    -> (3) X = A + 7*B

Blank lines are not numbered; a statement continued with ``&`` is one input
line.  Responses are attached to the physical line their statement starts on.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import TYPE_CHECKING, Any

from .settings import Response

if TYPE_CHECKING:
    from .responses import ResponseLines

__all__ = ["logical_lines", "printed_transcript", "transcript_lines"]


def logical_lines(source: Sequence[str]) -> Iterator[tuple[int, str]]:
    """``(first physical line, text)`` for each non-blank logical line."""
    pending: list[str] = []
    start = 0
    for number, line in enumerate(source, start=1):
        if not pending:
            start = number
            if not line.strip():
                continue
        code = line.split("%", 1)[0].rstrip()
        if code.endswith("&"):
            pending.append(line.rstrip())
            continue
        pending.append(line.rstrip())
        yield start, " ".join(
            p.strip() if i else p.rstrip() for i, p in enumerate(pending)
        )
        pending = []
    if pending:
        yield start, " ".join(p.strip() for p in pending)


def transcript_lines(
    source: Sequence[str],
    responses: Iterable[Response],
    form: Callable[[Any], Any] | None = None,
    tick: Callable[[int], None] | None = None,
) -> list[str]:
    """The full transcript as text lines.  ``form(value)`` forms each value
    that is not verbatim just before it is printed; ``tick(n)`` after each
    ``n`` responses are printed (progress)."""
    from .responses import ResponseLines

    return printed_transcript(source, ResponseLines(list(responses), form), tick)


def printed_transcript(
    source: Sequence[str],
    printed: ResponseLines,
    tick: Callable[[int], None] | None = None,
) -> list[str]:
    """:func:`transcript_lines` of the responses of ``printed``, their
    printer already made (:class:`.responses.ResponseLines`, with its own
    ``form``, which may share the printing with a forked copy)."""
    responses = printed.responses
    texts = printed.lines(tick)
    by_line: dict[int | None, list[int]] = defaultdict(list)
    for i, r in enumerate(responses):
        by_line[r.line].append(i)
    out: list[str] = []
    _interleave(source, by_line, texts.__getitem__, out)
    return out


def _interleave(
    source: Sequence[str],
    by_line: dict[int | None, list[int]],
    lines_of: Callable[[int], list[str]],
    out: list[str],
) -> None:
    """The numbered input lines, each followed by its responses' lines."""
    n = 0
    for start, text in logical_lines(source):
        n += 1
        out.append(f"({n}) {text.strip()}")
        for r in by_line.pop(start, []):
            for line in lines_of(r):
                n += 1
                out.append(f"-> ({n}) {line}")
    for key in sorted(by_line, key=lambda k: -1 if k is None else k):
        for r in by_line[key]:
            for line in lines_of(r):
                n += 1
                out.append(f"-> ({n}) {line}")
