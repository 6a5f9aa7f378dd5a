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

The ``.al`` line of a failing Python line is the statement's ``line=`` argument
when it has one, else the line whose text the ``# al>`` comment above it echoes.
"""

from __future__ import annotations

import functools
import linecache
import os
import re
import sys
from pathlib import PurePath
from types import FrameType, TracebackType
from typing import Any

__all__ = ["AutolevRuntimeError", "excepthook", "guard_methods", "register"]


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
        self.line = line
        self.source = source
        super().__init__(self.format())

    def format(self) -> str:
        if self.filename is None:
            return self.message
        where = self.filename + (f":{self.line}" if self.line else "")
        out = f"{where}: error: {self.message}"
        if self.source.strip():
            out += "\n    " + self.source.strip()
        return out


#: generated module files (``co_filename``) -> the ``.al`` name they came from
_MODULES: dict[str, str] = {}
_installed = False
_previous_hook = sys.excepthook


def _is_generated(frame: FrameType) -> bool:
    doc = frame.f_globals.get("__doc__") or ""
    return doc.startswith("Autolev script ") and "by al2py" in doc


def register(filename: str, frame: FrameType | None) -> bool:
    """Called by ``Workspace.__init__``: remember the generated module that
    creates the workspace (``frame`` is its frame) and install the hook.
    True if ``frame`` is a generated module's."""
    global _installed
    if frame is None or not _is_generated(frame):
        return False
    _MODULES[frame.f_code.co_filename] = filename
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

_ECHO = "# al> "
_LINE_ARG = re.compile(r"\bline=(\d+)")


def _al_source(lines: list[str]) -> list[str] | None:
    import ast

    try:
        tree = ast.parse("".join(lines))
    except (SyntaxError, ValueError):
        return None
    for node in tree.body:
        if (
            isinstance(node, ast.Assign)
            and len(node.targets) == 1
            and isinstance(node.targets[0], ast.Name)
            and node.targets[0].id == "AL_SOURCE"
        ):
            try:
                return list(ast.literal_eval(node.value))
            except (ValueError, TypeError, SyntaxError):
                return None
    return None


def echo_above(lines: list[str], pyline: int) -> tuple[int | None, str]:
    """``(index, text)`` of the ``# al>`` echo at or above Python line
    ``pyline`` of a generated module's ``lines``: the Autolev statement that
    line belongs to (``(None, "")`` if there is none).

    >>> echo_above(["x = 1", "# al> Q' = U", "al.kd(...)"], 3)
    (1, "Q' = U")
    """
    start = min(pyline, len(lines)) - 1
    while start >= 0 and not lines[start].lstrip().startswith(_ECHO):
        start -= 1
    if start < 0:
        return None, ""
    return start, lines[start].lstrip()[len(_ECHO) :].rstrip()


def al_line(module_file: str, pyline: int, module_globals: Any = None) -> tuple:
    """``(line, source text)`` of the ``.al`` statement that Python line
    ``pyline`` of a generated module belongs to (``(None, "")`` if unknown)."""
    lines = linecache.getlines(module_file, module_globals)
    start, echoed = echo_above(lines, pyline)
    if start is None:
        return None, ""
    source = _al_source(lines) or []
    end = start + 1
    while end < len(lines) and not lines[end].lstrip().startswith(_ECHO):
        end += 1
    for text in lines[start:end]:
        m = _LINE_ARG.search(text)
        if m:
            n = int(m.group(1))
            return n, source[n - 1] if 0 < n <= len(source) else echoed
    # the k-th statement echoing this text is on the k-th source line with it
    k = sum(
        1
        for text in lines[: start + 1]
        if text.lstrip().startswith(_ECHO)
        and text.lstrip()[len(_ECHO) :].rstrip() == echoed
    )
    seen = 0
    for number, text in enumerate(source, start=1):
        if text.strip() and text.strip().startswith(echoed.strip()):
            seen += 1
            if seen == k:
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
    exc: BaseException, frame: FrameType, line: int | None = None
) -> AutolevRuntimeError:
    """``exc``, raised while ``frame`` (of a generated module) ran, as an
    :class:`AutolevRuntimeError` naming the ``.al`` line."""
    module_file = frame.f_code.co_filename
    found, source = al_line(module_file, frame.f_lineno, frame.f_globals)
    if line is None:
        line = found
    elif found != line:
        source = _source_line(module_file, line, frame.f_globals) or source
    name = _MODULES.get(module_file, PurePath(module_file).with_suffix(".al").name)
    return AutolevRuntimeError(describe(exc), name, line, source)


def _source_line(module_file: str, line: int, module_globals: Any) -> str:
    source = _al_source(linecache.getlines(module_file, module_globals)) or []
    return source[line - 1] if 0 < line <= len(source) else ""


# --------------------------------------------------------- the wrappers

#: methods with their own error reporting (jobs name their CODE statement),
#: and those a module's own functions call (their errors are not statements')
_UNGUARDED = frozenset({"run", "main", "names", "evaluate_name", "document_run"})


def guard_methods(cls: type) -> type:
    """Wrap the public methods of ``cls`` (a workspace class) so that an
    exception escaping into a generated module becomes located."""
    for name in dir(cls):
        if name.startswith("_") or name in _UNGUARDED:
            continue
        func = getattr(cls, name)
        if not callable(func) or isinstance(func, type):
            continue
        raw = cls.__dict__.get(name)
        if raw is None:  # inherited from a mixin: look it up along the MRO
            for base in cls.__mro__:
                if name in base.__dict__:
                    raw = base.__dict__[name]
                    break
        if isinstance(raw, staticmethod | classmethod | property):
            continue
        setattr(cls, name, _guarded(raw))
    return cls


def _guarded(func: Any) -> Any:
    @functools.wraps(func)
    def method(self: Any, *args: Any, **kw: Any) -> Any:
        try:
            return func(self, *args, **kw)
        except Exception as exc:
            frame = sys._getframe(1)
            if (
                frame.f_code.co_filename not in _MODULES
                or frame.f_code.co_name != "<module>"  # run(), kanes_method()...
                or (isinstance(exc, AutolevRuntimeError) and exc.filename is not None)
            ):
                raise
            line = kw.get("line")
            raise located(exc, frame, line if isinstance(line, int) else None) from exc

    return method


# ------------------------------------------------------------ the hook


def report(exc: BaseException) -> str | None:
    """The located message for ``exc`` if it came from a generated module."""
    if isinstance(exc, AutolevRuntimeError) and exc.filename is not None:
        return str(exc)
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
    if isinstance(exc, BrokenPipeError):
        return ""
    module_file = best.f_code.co_filename
    line, source = al_line(module_file, line_no, best.f_globals)
    name = _MODULES[module_file]
    return str(AutolevRuntimeError(describe(exc), name, line, source))


def excepthook(
    exc_type: type[BaseException],
    exc: BaseException,
    tb: TracebackType | None,
) -> None:
    """Print errors of generated modules as ``FILE.al:LINE: error: ...`` and
    exit with status 2; hand everything else to the previous hook."""
    if exc.__traceback__ is None:
        exc = exc.with_traceback(tb)
    try:
        message = report(exc) if issubclass(exc_type, Exception) else None
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
    os._exit(0 if isinstance(exc, BrokenPipeError) else 2)
