"""Progress on every long wait: never a silent wait.

Importing a large model can take seconds.  While a generated module is being
imported for more than :data:`AFTER` seconds and standard error is a terminal,
one line on standard error names the Autolev statement being derived (the
``# al>`` echo above the Python line running now) and the time so far; the
line is cleared when the module is done.  Anywhere else (a pipe, a file, CI)
nothing is written.

>>> watch = ImportWatch("m.al", None)  # no module: nothing to watch
>>> watch.start(); watch.stop()

Any other wait (printing a transcript, writing programs, compiling,
linearizing, sweeping) is a :func:`task`: after :data:`AFTER` seconds, on a
terminal only, one line says what is being done and how far along it is,
``sweeping 12 of 40 points (30%), 3 s``, updated every :data:`EVERY`
seconds and cleared when the task ends::

    with progress.task("sweeping", total=len(points), unit="points") as p:
        for point in points:
            ...
            p.advance()

``p.doing("WhippleDynamics.c")`` names the step in progress.  Tasks nest:
the innermost one shows.  :func:`echo` prints a whole line on standard error
(clearing the progress line first), for commands that report as they go.

>>> with task("nothing to see", total=2) as p:  # not a terminal: no output
...     p.advance(); p.advance()
>>> p.done, p.total
(2, 2)
"""

from __future__ import annotations

import linecache
import os
import sys
import threading
import time
from typing import Any, TextIO

from .safety import echo_above

__all__ = ["AFTER", "ImportWatch", "Steps", "Task", "echo", "is_terminal", "task"]

#: seconds of waiting before the progress line appears
#: (``AL2PY_PROGRESS_AFTER=0`` shows it at once: tests, demonstrations)
AFTER = 2.0
try:
    AFTER = max(0.0, float(os.environ.get("AL2PY_PROGRESS_AFTER", AFTER)))
except ValueError:
    pass
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
            self._show(f"{self.filename}: deriving {statement}".rstrip(), t0)
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


# ------------------------------------------------------------------ tasks

#: the tasks running now, innermost last (only the innermost one shows)
_active: list[Task] = []
_lock = threading.RLock()
#: width of the progress line on screen, per stream
_widths: dict[Any, int] = {}
#: longest progress line (a terminal of 80 columns never wraps it)
WIDTH = 79


class Task:
    """A wait that shows its progress on a terminal (see :func:`task`)."""

    def __init__(
        self,
        what: str,
        total: int | None = None,
        *,
        unit: str = "",
        stream: TextIO | None = None,
    ) -> None:
        self.what = what
        self.total = total
        self.unit = unit
        self.done = 0
        self.step = ""
        self.stream = stream if stream is not None else sys.stderr
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._t0 = time.perf_counter()
        self._visible = False  # the line has been shown

    # ---------------------------------------------------- the caller's side

    def advance(self, n: int = 1) -> None:
        """``n`` more of :attr:`total` are done."""
        self.done += n

    def update(self, done: int | None = None, total: int | None = None) -> None:
        """Set how many are done (and the total, when it becomes known)."""
        if done is not None:
            self.done = done
        if total is not None:
            self.total = total

    def doing(self, step: str) -> None:
        """Name the step in progress (``"compiling WhippleDynamics.c"``);
        a line on the screen shows it at once."""
        self.step = step
        if self._visible:
            with _lock:
                if _active and _active[-1] is self:
                    _show(self.stream, self.line())

    def line(self) -> str:
        """The progress line as shown now."""
        text = self.what
        if self.total:
            unit = f" {self.unit}" if self.unit else ""
            pct = min(100, 100 * self.done // self.total)
            text += f" {self.done} of {self.total}{unit} ({pct}%)"
        if self.step:
            text += f": {self.step}"
        seconds = f", {time.perf_counter() - self._t0:.0f} s"
        room = WIDTH - len(seconds)
        if len(text) > room:
            text = text[: room - 3] + "..."
        return text + seconds

    # ---------------------------------------------------------- the context

    def __enter__(self) -> Task:
        self._t0 = time.perf_counter()
        with _lock:
            _active.append(self)
        if is_terminal(self.stream):
            if AFTER <= 0:  # at once, before the task can end
                self._visible = True
                with _lock:
                    _show(self.stream, self.line())
            self._thread = threading.Thread(target=self._watch, daemon=True)
            self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join()
        with _lock:
            if self in _active:
                _active.remove(self)
            if self._thread is not None:
                _clear(self.stream)

    def _watch(self) -> None:
        if self._stop.wait(AFTER):
            return
        self._visible = True
        while not self._stop.is_set():
            with _lock:
                if _active and _active[-1] is self:
                    _show(self.stream, self.line())
            if self._stop.wait(EVERY):
                break


def task(
    what: str,
    total: int | None = None,
    *,
    unit: str = "",
    stream: TextIO | None = None,
) -> Task:
    """A context manager showing ``what`` is being done and how far along
    (``total`` steps, counted by :meth:`Task.advance`) on standard error
    when it is a terminal, once the task has taken :data:`AFTER` seconds."""
    return Task(what, total, unit=unit, stream=stream)


class Steps(Task):
    """A :class:`Task` counted in steps (a sweep's points, a linearization's
    columns), shown as ``WHAT: done/total (pct%), seconds``.

    >>> import io
    >>> with Steps("sweeping AMAT", 3, stream=io.StringIO()) as steps:
    ...     steps.advance(3)
    >>> steps.done
    3
    """

    def __init__(self, what: str, total: int, stream: TextIO | None = None) -> None:
        super().__init__(what, total, stream=stream)

    def line(self) -> str:
        text = f"{self.what[:50]}: {self.done}/{self.total}"
        if self.total:
            text += f" ({min(100, 100 * self.done // self.total)}%)"
        if self.step:
            text += f": {self.step}"
        return f"{text[: WIDTH - 8]}, {time.perf_counter() - self._t0:.0f} s"


def echo(text: str, stream: TextIO | None = None) -> None:
    """Print ``text`` as a line on standard error, clearing any progress
    line first (the running task draws it again at its next update)."""
    stream = stream if stream is not None else sys.stderr
    with _lock:
        _clear(stream)
        _write(stream, text + "\n")


def _show(stream: TextIO, text: str) -> None:
    pad = " " * max(0, _widths.get(stream, 0) - len(text))
    if _write(stream, "\r" + text + pad):
        _widths[stream] = len(text)


def _clear(stream: TextIO) -> None:
    shown = _widths.pop(stream, 0)
    if shown:
        _write(stream, "\r" + " " * shown + "\r")


def _write(stream: TextIO, text: str) -> bool:
    try:
        stream.write(text)
        stream.flush()
    except (OSError, ValueError):  # a closed terminal: nothing to show
        return False
    return True
