"""Errors that al2py reports to users, and the one it must never show them.

User-facing errors (:class:`AutolevError` and subclasses) know where in the
``.al`` source they happened and format as::

    tutor1.al:9:5: error: undeclared name 'Q'
        E = Q + 1
            ^

:class:`InternalError` marks a bug in al2py itself; the command line reports
it without a traceback and with a request to file an issue.
"""

from __future__ import annotations

from .ir import Span

__all__ = [
    "AutolevError",
    "ParseError",
    "SemanticError",
    "UnsupportedError",
    "MacroError",
    "ErrorList",
    "ParseErrorList",
    "InternalError",
]

#: At most this many errors are reported for one file (like a compiler's
#: ``-fmax-errors``); the rest are counted.
MAX_ERRORS = 50


#: the widest source line shown under a message; a longer one is shown
#: around the column, its cut ends marked ``...``
LINE_WIDTH = 120


def _window(text: str, col: int) -> tuple[str, int]:
    """``text`` cut to :data:`LINE_WIDTH` characters around column ``col``
    (0-based), and the column in the cut text."""
    col = max(col, 0)
    if len(text) <= LINE_WIDTH:
        return text, col
    start = max(0, min(col - LINE_WIDTH // 2, len(text) - LINE_WIDTH))
    end = start + LINE_WIDTH
    shown = text[start:end]
    if start > 0:
        shown, col = "..." + shown, col - start + 3
    if end < len(text):
        shown += "..."
    return shown, col


class AutolevError(Exception):
    """An error in the user's ``.al`` input, located by a :class:`Span`."""

    kind = "error"

    def __init__(self, message: str, span: Span | None = None, *, line_text: str = ""):
        super().__init__(message)
        self.message = message
        self.span = span
        self.line_text = line_text

    def format(self, lines: tuple[str, ...] | list[str] | None = None) -> str:
        """``file:line:col: error: message`` plus the source line and a caret."""
        if self.span is None:
            return f"error: {self.message}"
        text = self.line_text
        if not text and lines and 0 < self.span.line <= len(lines):
            text = lines[self.span.line - 1]
        out = f"{self.span}: error: {self.message}"
        if text:
            text, col = _window(text.rstrip("\n").expandtabs(1), self.span.col - 1)
            out += f"\n    {text}\n    {' ' * col}^"
        return out

    def __str__(self) -> str:
        return self.format()


class ParseError(AutolevError):
    """The text is not valid Autolev syntax."""


class SemanticError(AutolevError):
    """Valid syntax with a meaning error: undeclared name, wrong argument count."""


class UnsupportedError(AutolevError):
    """Valid Autolev that al2py does not translate (yet); never silently dropped."""


class MacroError(AutolevError):
    """A ``.a``/``.r`` macro or ``RUN`` file could not be found or expanded."""


class ErrorList(AutolevError):
    """Every error found in one file, sorted by position.

    It behaves as its first error (``span``, ``message``) for callers that
    report one, and :meth:`format` lists them all.
    """

    def __init__(self, errors: list[AutolevError]) -> None:
        if not errors:
            raise ValueError("ErrorList needs at least one error")
        flat: list[AutolevError] = []
        for e in errors:
            flat.extend(e.errors if isinstance(e, ErrorList) else [e])
        flat.sort(key=_position)
        self.errors = flat
        first = flat[0]
        super().__init__(first.message, first.span, line_text=first.line_text)

    def format(self, lines: tuple[str, ...] | list[str] | None = None) -> str:
        shown = self.errors[:MAX_ERRORS]
        out = [e.format(lines) for e in shown]
        hidden = len(self.errors) - len(shown)
        if hidden:
            out.append(f"... and {hidden} more error{'s' if hidden > 1 else ''}")
        if len(self.errors) > 1:
            out.append(f"{len(self.errors)} errors")
        return "\n".join(out)


class ParseErrorList(ErrorList, ParseError):
    """Several syntax errors."""


def errors_of(exc: AutolevError) -> list[AutolevError]:
    """The individual errors inside ``exc``."""
    return list(exc.errors) if isinstance(exc, ErrorList) else [exc]


def _position(e: AutolevError) -> tuple[int, int]:
    return (0, 0) if e.span is None else (e.span.line, e.span.col)


class InternalError(Exception):
    """A bug in al2py. Never raised for bad input."""
