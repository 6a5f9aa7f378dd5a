"""The printed lines of a transcript's responses, by this process alone or
side by side with a forked copy of it.

Each response's lines depend on the response and the finished model alone
(the printer's memos only spare work: :class:`.printing.Printing`), so they
may be printed in any order and by any copy of the process that holds the
model.  A large model's transcript (Moore's Whipple bicycle: 5,178
responses, most of them intermediates' definitions) takes about a third
as long to print as the model takes to derive; ``python model.py`` prints
it on two processors at once (:func:`response_lines` with ``copies``).

>>> import sympy as sp
>>> from al2py_runtime.names.settings import Response
>>> a, b = sp.symbols("A B")
>>> response_lines([Response(1, "X", a + b, 7), Response(2, "Y", 2 * a, 7)])
[['X = A + B'], ['Y = 2*A']]
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Sequence
from concurrent.futures import Future, ProcessPoolExecutor
from typing import Any

from .. import copies as forked
from .printing import Printing
from .settings import Response

__all__ = ["MIN_SHARED", "PARTS", "ResponseLines", "response_lines", "side_by_side"]

#: the fewest responses printed with a copy's help (fewer print in
#: milliseconds, less than making the copy takes)
MIN_SHARED = 400
#: the parts a shared transcript is cut into: each process prints whole
#: parts, the copy from the last one back and this process from the first
#: one on, until they meet (about one part apart: a part's lines come back
#: as one message)
PARTS = 64


def side_by_side() -> int:
    """How many processes may print a transcript at once here: two where
    this process runs no other thread (a process forked while another
    thread runs may deadlock) and may run on two processors or more, else
    one."""
    if threading.active_count() != 1:
        return 1
    return min(forked.processors(), 2)


def response_lines(
    responses: Sequence[Response],
    form: Callable[[Any], Any] | None = None,
    tick: Callable[[int], None] | None = None,
    copies: int = 1,
) -> list[list[str]]:
    """The lines of each of ``responses`` (``Printing.format_response``),
    each value that is not verbatim formed by ``form`` first; ``tick(n)``
    after each ``n`` printed; ``copies``: see :class:`ResponseLines`."""
    return ResponseLines(responses, form, copies).lines(tick)


class ResponseLines:
    """The lines of each of ``responses`` (:func:`response_lines`), printed
    when :meth:`lines` is called.  With ``copies`` 2 and at least
    :data:`MIN_SHARED` responses, a forked copy of this process is made
    here, to print part of them at the same time (:class:`_Sharing`): the
    same lines.  Make it before any other thread starts (a progress line's:
    see :func:`side_by_side`)."""

    def __init__(
        self,
        responses: Sequence[Response],
        form: Callable[[Any], Any] | None = None,
        copies: int = 1,
    ) -> None:
        self.printer = _Printer(responses, form)
        self.shared = None
        if copies > 1 and len(responses) >= MIN_SHARED:
            self.shared = _Sharing.start(self.printer)

    @property
    def responses(self) -> Sequence[Response]:
        """The responses printed, in order."""
        return self.printer.responses

    def lines(self, tick: Callable[[int], None] | None = None) -> list[list[str]]:
        """Every response's lines, in order (``tick(n)`` as they come)."""
        if self.shared is not None:
            shared, self.shared = self.shared, None
            return shared.lines(tick)
        out = []
        for i in range(len(self.printer.responses)):
            out.append(self.printer.lines(i))
            if tick is not None:
                tick(1)
        return out


class _Printer:
    """The lines of ``responses``, one :class:`.printing.Printing` (and its
    memos) for all that one process prints."""

    def __init__(
        self, responses: Sequence[Response], form: Callable[[Any], Any] | None
    ) -> None:
        self.responses = responses
        self.form = form
        self.printing = Printing()

    def lines(self, i: int) -> list[str]:
        r = self.responses[i]
        value = r.value if self.form is None or r.verbatim else self.form(r.value)
        return self.printing.format_response(r.label, value, r.digits)

    def part(self, span: tuple[int, int]) -> list[list[str]]:
        return [self.lines(i) for i in range(*span)]


#: the printer of a copy made by :class:`_Sharing`: the state of a forked
#: process, never set in the process that forks
_COPY: dict[str, _Printer] = {}


def _copy_started(printer: _Printer) -> None:
    """A copy starts: it keeps the responses and ``form`` (given to it
    through ``fork``, not pickled)."""
    _COPY["printer"] = printer


def _part_in_copy(span: tuple[int, int]) -> list[list[str]]:
    return _COPY["printer"].part(span)


class _Sharing:
    """The responses of ``printer`` printed by this process and one forked
    copy of it (a standard-library process pool of one over ``fork``,
    :mod:`..copies`), side by side.

    They are cut into :data:`PARTS` parts of consecutive responses, all
    given to the copy at once, last part first.  This process prints the
    parts from the first on, each only when it could take it back from
    the copy's queue (``Future.cancel``: the copy has not started it);
    the first it cannot take back, the copy is printing or has printed,
    and so every part after it: their lines are then read from the copy.
    A part whose copy failed (or whose pool broke) is printed here: every
    line and every error is the one this process alone would give."""

    def __init__(
        self, printer: _Printer, pool: ProcessPoolExecutor, spans: list
    ) -> None:
        self.printer = printer
        self.pool = pool
        self.spans = spans
        self.futures: list[Future | None] = [None] * len(spans)

    @classmethod
    def start(cls, printer: _Printer) -> _Sharing | None:
        """The copy made and given every part; None where no copy can be
        made (then this process prints them all)."""
        n = len(printer.responses)
        cuts = [n * k // PARTS for k in range(PARTS + 1)]
        spans = [(a, b) for a, b in zip(cuts, cuts[1:], strict=False) if b > a]
        pool = forked.fork_pool(1, _copy_started, (printer,))
        if pool is None:
            return None
        # the last part first: the copy takes them from the last one back
        order = list(reversed(range(len(spans))))
        futures = forked.submit_forking(
            pool, [(_part_in_copy, (spans[k],)) for k in order]
        )
        if futures is None:
            return None
        sharing = cls(printer, pool, spans)
        for k, future in zip(order, futures, strict=True):
            sharing.futures[k] = future
        return sharing

    def lines(self, tick: Callable[[int], None] | None) -> list[list[str]]:
        """Every response's lines, in order (``tick(n)`` as they come)."""
        try:
            out: list[list[str]] = []
            k = 0
            for k, span in enumerate(self.spans):
                future = self.futures[k]
                if future is not None and not future.cancel():
                    break  # the copy has this part and those after it
                out += self._here(span, tick)
            else:
                return out
            for span, future in zip(self.spans[k:], self.futures[k:], strict=True):
                out += self._read(span, future, tick)
            return out
        finally:
            self.stop()

    def _here(
        self, span: tuple[int, int], tick: Callable[[int], None] | None
    ) -> list[list[str]]:
        part = self.printer.part(span)
        if tick is not None:
            tick(len(part))
        return part

    def _read(
        self,
        span: tuple[int, int],
        future: Future | None,
        tick: Callable[[int], None] | None,
    ) -> list[list[str]]:
        part = None
        if future is not None:
            try:
                part = future.result()
            except Exception:  # noqa: BLE001 - the copy failed: printed here
                part = None
        if part is None or len(part) != span[1] - span[0]:
            return self._here(span, tick)
        if tick is not None:
            tick(len(part))
        return part

    def stop(self) -> None:
        """The copy ended: at once when parts are left (an error here, or
        an interrupt), the pool shut down."""
        pool, self.pool = self.pool, None
        if pool is None:
            return
        forked.end(pool, self.futures)
