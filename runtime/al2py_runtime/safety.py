"""Errors of a generated module, reported against the ``.al`` script.

A statement can fail only when the module runs (a singular ``Solve``, a
position that was never defined).  The user then sees::

    model.al:12: error: P_O_Q> is not defined
        D = Mag(P_O_Q>)

never a Python traceback:

* Every workspace method that a generated module's statements call turns an
  exception into :class:`AutolevRuntimeError` (a ``ValueError``), whose
  message names the ``.al`` file and line (``import model`` raises it; catch
  it to handle any failure of a model).  The module's own functions
  (``run()``, ``kanes_method()``) raise their errors unchanged.
* ``python model.py`` (and an uncaught error of ``import model`` in a script)
  prints that message and exits with status 2 through :func:`excepthook`,
  which also locates exceptions raised by the module's own arithmetic
  (``M + V`` with mismatched shapes).  Exceptions that do not pass through a
  generated module go to the previous ``sys.excepthook`` untouched.
* An interrupt (Ctrl-C) that stops a generated module's derivation is
  printed as ``model.al:12: interrupted`` (the statement it stopped), and
  the process exits with status 130, as ``al2py`` itself does.

The ``.al`` line of a failing Python line is the statement's ``line=`` argument
when it has one, else the line whose text the ``# al>`` comment above it echoes.
"""

from __future__ import annotations

import functools
import linecache
import os
import re
import sys
from collections.abc import Callable, Sequence
from types import TracebackType
from typing import Any, TypeVar

from .collector import settled

__all__ = [
    "AutolevRuntimeError",
    "MissingValueWarning",
    "Statements",
    "echo_lines",
    "echoed_source",
    "excepthook",
    "module_source",
    "register",
    "statement",
]


class MissingValueWarning(UserWarning):
    """A value nobody gave was taken as 0, by al2py's one rule for missing
    values (``al2py_runtime.jobs.run.missing_value_rule``): a Specified
    quantity with no equation and no Input, a variable's initial value, or
    (with ``zero_missing``) a constant.  ``python module.py`` prints the same
    text as a ``note:`` line; ``result.notes`` keeps it."""


class AutolevRuntimeError(ValueError):
    """A statement of an Autolev script failed when its module ran (a
    ``ValueError``: the script's values cannot be computed).

    ``str(exc)`` is ``FILE.al:LINE: error: message`` followed by the
    statement's source line; ``filename``, ``line`` and ``message`` hold the
    parts (``line`` is None when it cannot be known).
    """

    def __init__(
        self,
        message: str,
        filename: str | None = None,
        line: int | None = None,
        source: str = "",
    ) -> None:
        self.message = message
        self.filename = filename
        self._line = line
        self._source = source
        super().__init__(message)

    @property
    def line(self) -> int | None:
        """The ``.al`` line: the one the module's call passed, else the
        statement whose Python line this error's own traceback passes in a
        generated module (known once the error has left the module)."""
        if self._line is None:
            self._line, self._source = _traceback_line(self)
        return self._line

    @property
    def source(self) -> str:
        self.line  # noqa: B018 - placed from the traceback if need be
        return self._source

    def format(self) -> str:
        if self.filename is None:
            return self.message
        where = self.filename + (f":{self.line}" if self.line else "")
        out = f"{where}: error: {self.message}"
        if self.source.strip():
            out += "\n    " + self.source.strip()
        return out

    def __str__(self) -> str:
        return self.format()


def _traceback_line(exc: BaseException) -> tuple[int | None, str]:
    """``(line, source)`` of the ``.al`` statement whose module-level Python
    line ``exc``'s traceback passes (``(None, "")`` if it passes none)."""
    tb = exc.__traceback__
    found: tuple[int | None, str] = (None, "")
    while tb is not None:
        code = tb.tb_frame.f_code
        if code.co_filename in _MODULES and code.co_name == "<module>":
            found = al_line(code.co_filename, tb.tb_lineno, tb.tb_frame.f_globals)
        tb = tb.tb_next
    return found


#: generated module files (``co_filename``) -> the ``.al`` name they came from
_MODULES: dict[str, str] = {}
_installed = False
_previous_hook = sys.excepthook


def register(filename: str, module_file: str | None) -> bool:
    """Called by ``Workspace.__init__``: remember the generated module that
    creates the workspace (``module_file`` is its ``__file__``, which the
    module passes) and install the hook.  True if there is such a module."""
    global _installed
    if module_file is None:
        return False
    _MODULES[module_file] = filename
    if not _installed:
        _installed = True
        sys.excepthook = excepthook
    return True


def output_path(outdir: str | os.PathLike, name: str) -> Any:
    """Where a module writes its output file ``name`` (``Save``, CODE tables,
    plots): ``outdir`` joined with the base name only, so ``../x.all`` and
    ``/abs/x.py`` stay inside ``outdir``.  None if no base name is left."""
    from pathlib import Path

    seps = "".join(re.escape(c) for c in {"/", os.sep, os.altsep or "/"})
    base = re.split(f"[{seps}]", str(name).strip())[-1]
    if base in ("", ".", "..") or (os.name == "nt" and ":" in base):
        return None
    return Path(outdir) / base


# ----------------------------------------------------------- line mapping

#: how a generated module holds each line of its ``.al`` file, once, as a
#: comment at column 0: ``# al> TEXT`` (the line, stripped), ``# al+ ...``
#: (the rest of a line too long for one comment), ``# al! 'TEXT'`` (a line
#: with a character a comment cannot hold, as a Python string), and ``#``
#: (a blank line).  The transcript reads its source from these comments.
ECHO, MORE, QUOTED, BLANK = "# al> ", "# al+", "# al! ", "#"
_WIDTH = 88


def echo_lines(line: str) -> list[str]:
    """The comment lines that hold one ``.al`` line in a module.

    >>> echo_lines("Simprot(N, A, 3, QA)   ")
    ['# al> Simprot(N, A, 3, QA)']
    >>> echo_lines("")
    ['#']
    """
    text = line.strip()
    if not text:
        return [BLANK]
    if all(c.isprintable() or c == "\t" for c in text):
        out = _pieces(ECHO, text)
        if out is not None:
            return out
    # a character a comment cannot hold, or a run of blanks too long to cut
    # after a word: the line as a string, with no blank left to lose
    quoted = repr(text).replace(" ", "\\x20").replace("\t", "\\t")
    return _pieces(QUOTED, quoted) or [QUOTED + quoted]


def _pieces(lead: str, text: str) -> list[str] | None:
    """``text`` in comment lines of at most 88 columns (a tab as 8), cut
    before a space after a word (never on a blank, which black would strip);
    None if that cannot be done."""
    out: list[str] = []
    while text:
        piece = _piece(text, _WIDTH - len(lead))
        if piece is None:
            return None
        out.append(lead + piece)
        text = text[len(piece) :]
        lead = MORE
    return out


def _piece(text: str, room: int) -> str | None:
    """The longest start of ``text`` that fits ``room`` columns, ending before
    a space where it can, and never on whitespace (None if every start
    that fits does)."""
    width = 0
    end = 0
    while end < len(text):
        width += 8 if text[end] == "\t" else 1
        if width > room:
            break
        end += 1
    if end == len(text):
        return text
    for cut in range(end, 0, -1):  # before a space, after a word
        if text[cut].isspace() and not text[cut - 1].isspace():
            return text[:cut]
    cut = end
    while cut > 0 and text[cut - 1].isspace():
        cut -= 1
    return text[:cut] if cut > 0 else None


def echoed_source(module_lines: Sequence[str]) -> list[str]:
    """The ``.al`` lines (stripped) that a generated module echoes, in order:
    what :func:`transcript_lines` numbers.

    >>> echoed_source(["x = 1", "# al> Q' = U", "f(x)", "#", "# al> %  a", "# al+ b"])
    ["Q' = U", '', '%  a b']
    """
    return [text for _, text in echo_records(module_lines)]


def echo_records(module_lines: Sequence[str]) -> list[tuple[int, str]]:
    """``(index in module_lines, .al line)`` of each line a module echoes:
    the ``k``-th record is line ``k`` of the ``.al`` file.

    >>> echo_records(["# al> Constants G", "A.orient_axis(N, N.z, Q)  # al> Simprot(N, A, 3, Q)"])
    [(0, 'Constants G'), (1, 'Simprot(N, A, 3, Q)')]
    """
    import ast

    out: list[tuple[int, str]] = []
    quoted: list[bool] = []
    for index, _col, comment in _echo_comments(module_lines):
        if comment == BLANK:
            out.append((index, ""))
            quoted.append(False)
        elif comment.startswith((ECHO, QUOTED)):
            out.append((index, comment[len(ECHO) :]))
            quoted.append(comment.startswith(QUOTED))
        elif comment.startswith(MORE) and out:
            out[-1] = (out[-1][0], out[-1][1] + comment[len(MORE) :])
    for k, is_quoted in enumerate(quoted):
        if is_quoted:
            try:
                out[k] = (out[k][0], str(ast.literal_eval(out[k][1])))
            except (ValueError, SyntaxError):
                pass
    return out


def _echo_comments(module_lines: Sequence[str]) -> list[tuple[int, int, str]]:
    """``(index, column, comment)`` of each comment of ``module_lines`` that
    holds an echoed line: a comment at column 0 (``# al> ...``, ``# al+``,
    ``# al! ...``, ``#``), or a ``# al> ...`` comment that ends a top-level
    statement's line (``A.orient_axis(N, N.z, Q)  # al> Simprot(N, A, 3, Q)``).
    Comments are found by Python's tokenizer: a ``# al>`` inside a string
    is no echo."""
    import io
    import tokenize

    text = "".join(
        line if line.endswith("\n") else line + "\n" for line in module_lines
    )
    out: list[tuple[int, int, str]] = []
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type != tokenize.COMMENT:
                continue
            (row, col), comment = tok.start, tok.string.rstrip()
            if col == 0:
                out.append((row - 1, 0, comment))
            elif comment.startswith(ECHO) and not tok.line[:1].isspace():
                out.append((row - 1, col, comment))
    except (tokenize.TokenError, SyntaxError):
        return []
    return out


def module_source(module_file: str, module_globals: object = None) -> list[str]:
    """:func:`echoed_source` of the module in ``module_file``."""

    return echoed_source(linecache.getlines(module_file, module_globals))


_LINE_ARG = re.compile(r"\bline=(\d+)")


def echo_above(lines: list[str], pyline: int) -> tuple[int | None, str]:
    """``(index, text)`` of the ``# al>`` echo at or above Python line
    ``pyline`` of a generated module's ``lines`` (on the line itself, or
    ending a line above): the Autolev statement that line belongs to
    (``(None, "")`` if there is none).

    >>> echo_above(["x = 1", "# al> Q' = U", "al.kd(...)"], 3)
    (1, "Q' = U")
    >>> echo_above(["x = 1", "Y.orient_axis(N, N.z, Q)  # al> Simprot(N, Y, 3, Q)"], 2)
    (1, 'Simprot(N, Y, 3, Q)')
    """
    found: tuple[int | None, str] = (None, "")
    for index, _col, comment in _echo_comments(lines):
        if index >= pyline:
            break
        if comment.startswith(ECHO):
            found = (index, comment[len(ECHO) :])
    return found


def al_line(module_file: str, pyline: int, module_globals: Any = None) -> tuple:
    """``(line, source text)`` of the ``.al`` statement that Python line
    ``pyline`` of a generated module belongs to (``(None, "")`` if unknown):
    the ``line=`` its call passes, else the ``# al>`` echo at or above it
    (the ``k``-th line the module echoes is line ``k`` of the ``.al`` file)."""
    lines = linecache.getlines(module_file, module_globals)
    start, echoed = echo_above(lines, pyline)
    if start is None:
        return None, ""
    records = echo_records(lines)
    source = [text for _, text in records]
    comments = _echo_comments(lines)
    starts = [i for i, _c, text in comments if text.startswith(ECHO)]
    end = next((i for i in starts if i > start), len(lines))
    column = {i: c for i, c, text in comments if c > 0}  # trailing echoes
    for index in range(start, end):
        text = lines[index]
        m = _LINE_ARG.search(text[: column[index]] if index in column else text)
        if m:
            n = int(m.group(1))
            return n, source[n - 1] if 0 < n <= len(source) else echoed
    for number, (index, text) in enumerate(records, start=1):
        if index == start:
            return number, text
    return None, echoed


def describe(exc: BaseException) -> str:
    """The message of an exception, without Python's decoration.

    Only messages that al2py wrote reach the user: those of its own error
    classes, and those of a ``raise`` statement of its own code.  Anything
    else (a library's or Python's own text, from sympy, numpy or the
    interpreter) is a failure al2py did not foresee, and is worded as one
    (:func:`unexpected`).

    >>> describe(ValueError("the speeds are not independent"))
    'the speeds are not independent'
    """
    if not is_worded(exc):
        return unexpected(exc)
    if isinstance(exc, KeyError) and exc.args:
        text = str(exc.args[0])
    else:
        text = str(exc)
    return text or type(exc).__name__


#: packages whose ``raise`` statements word their messages for users
_OURS = ("al2py_runtime", "al2py")


def is_worded(exc: BaseException) -> bool:
    """True if ``exc``'s message was written for users: its class is one of
    al2py's, or a ``raise`` statement of al2py's code made it (not an
    operation that failed inside it, nor a library).  An exception without
    a traceback (made, not raised) counts as worded."""
    if type(exc).__module__.split(".")[0] in _OURS:
        return True
    tb = _innermost(exc)
    if tb is None:
        return True
    frame = tb.tb_frame
    if _package(tb) not in _OURS:
        return False
    text = linecache.getline(frame.f_code.co_filename, tb.tb_lineno, frame.f_globals)
    return text.lstrip().startswith("raise ")


def _innermost(exc: BaseException) -> TracebackType | None:
    """The traceback entry of the frame that raised ``exc``."""
    tb = exc.__traceback__
    while tb is not None and tb.tb_next is not None:
        tb = tb.tb_next
    return tb


def _package(tb: TracebackType | None) -> str:
    """The top-level package of a traceback entry's code ("" if none)."""
    if tb is None:
        return ""
    return str(tb.tb_frame.f_globals.get("__name__", "")).split(".")[0]


#: what an unforeseen failure of each kind means, in the user's terms
_KINDS = (
    (RecursionError, "the expression is nested too deeply to evaluate"),
    (MemoryError, "out of memory"),
    (ZeroDivisionError, "division by zero"),
    (OverflowError, "a number is too large"),
)


#: sympy's matrix errors (by name: this module imports no library), which
#: a script's own arithmetic can cause
_SYMPY_KINDS = {
    "ShapeError": "the sizes of the matrices do not agree",
    "NonSquareMatrixError": "the matrix is not square",
    "NonInvertibleMatrixError": "the matrix is singular (not invertible)",
}


#: sympy.physics.vector's failures that are the script's own error (two
#: frames used together that nothing relates), reworded
_UNRELATED_FRAMES = re.compile(
    r"^No connecting (orientation|angular velocity) path found between "
    r"(\S+) and (\S+?)\.?$"
)


def _unrelated_frames(exc: BaseException) -> str:
    """``frame A is not oriented relative to frame N ...`` for sympy's
    ``No connecting orientation path found between N and A.`` (else '')."""
    if not isinstance(exc, ValueError) or _library(exc) != "sympy":
        return ""
    m = _UNRELATED_FRAMES.match(str(exc).strip())
    if m is None:
        return ""
    what, a, b = m.groups()
    if what == "orientation":
        return (
            f"frame {b} is not oriented relative to frame {a}: orient one in the "
            f"other first (for example Simprot({a}, {b}, 3, angle), Dircos(...) "
            f"or {a}_{b} = ...)"
        )
    return (
        f"frame {a} has no angular velocity relative to frame {b}: orient one "
        f"in the other first (Simprot, Dircos) or give W_{a}_{b}> = ..."
    )


def unexpected(exc: BaseException) -> str:
    """The user's message for an exception al2py did not word: what it
    means where that is known (division by zero, too deep, out of
    memory, two frames that nothing orients relative to each other), else
    which library failed; the library's own text only with
    ``AL2PY_DEBUG=1``."""
    for kind, meaning in _KINDS:
        if isinstance(exc, kind):
            out = meaning
            break
    else:
        out = _SYMPY_KINDS.get(type(exc).__name__, "") or _unrelated_frames(exc)
    if not out:
        out = (
            f"an unexpected failure in {_library(exc)} (an al2py bug: please"
            " report it with the script; AL2PY_DEBUG=1 shows the details)"
        )
    if os.environ.get("AL2PY_DEBUG"):
        out += f" [{type(exc).__module__}.{type(exc).__name__}: {exc}]"
    return out


def _library(exc: BaseException) -> str:
    """The package whose code raised ``exc`` (``Python`` for the
    interpreter's own operations and the standard library)."""
    root = _package(_innermost(exc))
    if root in ("sympy", "numpy", "scipy", "mpmath", "symengine", "matplotlib"):
        return root
    if root in _OURS:
        return "al2py"
    return "Python"


def located(
    exc: BaseException, filename: str, module_file: str, line: int
) -> AutolevRuntimeError:
    """``exc``, raised by the statement of ``.al`` line ``line`` of the
    generated module ``module_file``, as an :class:`AutolevRuntimeError`
    naming that line."""
    return AutolevRuntimeError(
        describe(exc), filename, line, _source_line(module_file, line, None)
    )


def _source_line(module_file: str, line: int, module_globals: Any) -> str:
    source = module_source(module_file, module_globals)
    return source[line - 1] if 0 < line <= len(source) else ""


# ----------------------------------------------------- statement methods

F = TypeVar("F", bound=Callable[..., Any])


class Statements:
    """Where a workspace's statement calls stand: the generated module it
    serves (``module_file``, None for a workspace made by hand), how deep
    the current statement's calls are (only the outermost call locates) and
    whether a derivation's statements run :func:`~.collector.settled`
    (``settle``: while a generated module derives)."""

    def __init__(self, filename: str, module_file: str | None) -> None:
        self.filename = filename
        self.module_file = module_file
        self.depth = 0
        self.settle = False


def statement(method: F) -> F:
    """Mark a method that a generated module calls: an exception escaping the
    module's own call (the outermost) becomes an :class:`AutolevRuntimeError`
    naming the ``.al`` line, the ``line=`` the module passes (a call without
    one, inside an expression, is placed from the error's traceback).  The object reaches its workspace's
    :class:`Statements` as ``self.statements``."""

    @functools.wraps(method)
    def call(self: Any, *args: Any, **kw: Any) -> Any:
        where: Statements | None = self.statements
        if where is None:  # not a workspace's (settings made by hand)
            return method(self, *args, **kw)
        if where.settle and where.depth == 0:
            with settled():
                return _located(where, method, self, args, kw)
        return _located(where, method, self, args, kw)

    return call  # type: ignore[return-value]


def _located(
    where: Statements, method: Callable[..., Any], obj: Any, args: tuple, kw: dict
) -> Any:
    """``method(obj, *args, **kw)``, an exception escaping the outermost
    statement call located (see :func:`statement`)."""
    where.depth += 1
    try:
        return method(obj, *args, **kw)
    except Exception as exc:
        if (
            where.depth > 1
            or where.module_file is None
            or (isinstance(exc, AutolevRuntimeError) and exc.filename is not None)
        ):
            raise
        line = kw.get("line")
        if isinstance(line, int):
            raise located(exc, where.filename, where.module_file, line) from exc
        # an expression's call (``al.d(...)`` inside a statement): its
        # line is placed from the traceback once it leaves the module
        raise AutolevRuntimeError(describe(exc), where.filename) from exc
    finally:
        where.depth -= 1


# ------------------------------------------------------------ the hook


def report(exc: BaseException) -> str | None:
    """The located message for ``exc`` if it came from a generated module."""
    if isinstance(exc, AutolevRuntimeError) and exc.filename is not None:
        return str(exc)
    found = _module_line(exc)
    if found is None:
        return None
    if isinstance(exc, BrokenPipeError):
        return ""
    name, line, source = found
    return str(AutolevRuntimeError(describe(exc), name, line, source))


def interrupted(exc: BaseException) -> str | None:
    """``FILE.al:LINE: interrupted`` for an interrupt (Ctrl-C) that stopped
    a generated module (the statement it was deriving), else None."""
    found = _module_line(exc)
    if found is None:
        return None
    name, line, _source = found
    return f"{name}:{line}: interrupted" if line else f"{name}: interrupted"


def _module_line(exc: BaseException) -> tuple[str, int | None, str] | None:
    """The ``.al`` file, line and source of the generated module's statement
    that ``exc`` left (its outermost frame of the module's body), or None
    when it did not pass through a generated module."""
    tb = exc.__traceback__
    best = None
    line_no = 0
    while tb is not None:
        code = tb.tb_frame.f_code
        if code.co_filename in _MODULES and code.co_name == "<module>":
            best, line_no = tb.tb_frame, tb.tb_lineno
        tb = tb.tb_next
    if best is None:
        return None
    module_file = best.f_code.co_filename
    line, source = al_line(module_file, line_no, best.f_globals)
    return _MODULES[module_file], line, source


def excepthook(
    exc_type: type[BaseException],
    exc: BaseException,
    tb: TracebackType | None,
) -> None:
    """Print errors of generated modules as ``FILE.al:LINE: error: ...`` and
    exit with status 2, and an interrupt (Ctrl-C) of one as ``FILE.al:LINE:
    interrupted`` with status 130, as ``al2py`` itself ends when
    interrupted; hand everything else to the previous hook."""
    if exc.__traceback__ is None:
        exc = exc.with_traceback(tb)
    status = 2
    try:
        if issubclass(exc_type, Exception):
            message = report(exc)
        elif issubclass(exc_type, KeyboardInterrupt):
            message, status = interrupted(exc), 130
        else:
            message = None
    except Exception:  # noqa: BLE001 - never fail while reporting
        message = None
    if message is None:
        _previous_hook(exc_type, exc, tb)
        return
    if message:
        try:
            sys.stderr.write(message + "\n")
        except (OSError, ValueError):
            pass
    if hasattr(sys, "ps1") or sys.flags.interactive:
        return  # an interactive session goes on
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    os._exit(0 if isinstance(exc, BrokenPipeError) else status)
