"""Progress while a generated module derives: never a silent wait.

Importing a large model can take seconds.  While a generated module is being
imported for more than :data:`AFTER` seconds and standard error is a terminal,
one line on standard error names the Autolev statement being derived (the
``# al>`` echo above the Python line running now) and the time so far; the
line is cleared when the module is done.  Anywhere else (a pipe, a file, CI)
nothing is written.  :class:`Steps` does the same for other long waits
counted in steps (a sweep's points, a linearization's columns).

>>> watch = ImportWatch("m.al", None)  # no module: nothing to watch
>>> watch.start(); watch.stop()
"""

from __future__ import annotations

import linecache
import sys
import threading
import time
from typing import Any, TextIO

from .safety import echo_above

__all__ = ["AFTER", "ImportWatch", "Steps", "is_terminal"]

#: seconds of deriving before the progress line appears
AFTER = 2.0
#: seconds between updates of the line
EVERY = 0.5


def is_terminal(stream: Any) -> bool:
    """True if ``stream`` is a terminal (progress lines go only there)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


class ImportWatch:
    """Shows which statement the module ``module_file`` is deriving (see the
    module docstring); :meth:`stop` when the module is done."""

    def __init__(
        self, filename: str, module_file: str | None, stream: TextIO | None = None
    ) -> None:
        self.filename = filename
        self.stream = stream if stream is not None else sys.stderr
        self._file = module_file  # the generated module's __file__
        self._thread_id = threading.get_ident()
        self._done = threading.Event()
        self._shown = 0  # width of the line on screen
        self._thread: threading.Thread | None = None

    def start(self) -> None:
        if self._file is None or not is_terminal(self.stream):
            return
        self._thread = threading.Thread(target=self._watch, daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._done.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join()

    # ----------------------------------------------------------- the watch

    def _watch(self) -> None:
        t0 = time.perf_counter()
        if self._done.wait(AFTER):
            return
        while not self._done.is_set():
            statement = self._statement()
            if statement is None:  # the module stopped (an error): be quiet
                break
            self._show(f"{self.filename}: deriving {statement}", t0)
            if self._done.wait(EVERY):
                break
        self._clear()

    def _statement(self) -> str | None:
        """The echoed source of the statement running now, '' if not known;
        None once the module's frame is gone."""
        frame = sys._current_frames().get(self._thread_id)
        while frame is not None and frame.f_code.co_filename != self._file:
            frame = frame.f_back
        if frame is None:
            return None
        lines = linecache.getlines(self._file, frame.f_globals)
        return echo_above(lines, frame.f_lineno)[1]

    def _show(self, text: str, t0: float) -> None:
        text = f"{text[:60]} ({time.perf_counter() - t0:.0f} s)"
        pad = " " * max(0, self._shown - len(text))
        self._write("\r" + text + pad)
        self._shown = len(text)

    def _clear(self) -> None:
        if self._shown:
            self._write("\r" + " " * self._shown + "\r")
            self._shown = 0

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):  # a closed terminal: nothing to show
            self._done.set()


class Steps:
    """A progress line for work counted in steps (a sweep's points, a
    linearization's columns): after :data:`AFTER` seconds, and only when
    the stream is a terminal, one line ``WHAT: done/total (s)`` on standard
    error, updated every :data:`EVERY` seconds and cleared at the end.

    >>> import io
    >>> with Steps("sweeping AMAT", 3, stream=io.StringIO()) as steps:
    ...     steps.advance(3)
    >>> steps.done
    3
    """

    def __init__(self, what: str, total: int, stream: TextIO | None = None) -> None:
        self.what = what
        self.total = total
        self.done = 0
        self.stream = stream if stream is not None else sys.stderr
        self._stop = threading.Event()
        self._shown = 0
        self._thread: threading.Thread | None = None

    def __enter__(self) -> Steps:
        if is_terminal(self.stream):
            self._thread = threading.Thread(target=self._watch, daemon=True)
            self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()

    def advance(self, steps: int = 1) -> None:
        """``steps`` more are done."""
        self.done += steps

    def _watch(self) -> None:
        t0 = time.perf_counter()
        if self._stop.wait(AFTER):
            return
        while not self._stop.is_set():
            text = (
                f"{self.what[:50]}: {self.done}/{self.total}"
                f" ({time.perf_counter() - t0:.0f} s)"
            )
            pad = " " * max(0, self._shown - len(text))
            self._write("\r" + text + pad)
            self._shown = len(text)
            if self._stop.wait(EVERY):
                break
        if self._shown:
            self._write("\r" + " " * self._shown + "\r")

    def _write(self, text: str) -> None:
        try:
            self.stream.write(text)
            self.stream.flush()
        except (OSError, ValueError):  # a closed terminal: nothing to show
            self._stop.set()
