"""``al2py code FILE.al``: write the program of every ``CODE`` statement.

    al2py code tutor6.al              writes tutor6.c and tutor6.in
    al2py code tutor6.al -o build/    into another folder
    al2py code tutor7.al --lang c     C although CODE names tutor7.for

Converts the script, derives the model once as the generated module would on
import, and writes each ``CODE Dynamics/ODE/Algebraic/Nonlinear`` job's
program in the language its file extension names (C ``.c``, MATLAB/Octave
``.m``, Fortran ``.f``/``.for``; see :mod:`al2py_runtime.codegen`) with the
``.in`` file it reads.  A job that cannot be written gets one clear error
line and the exit status is 2 (the other files are written).

The conversion imports no sympy, the derivation does: where ``fork``
exists, a copy of this process converts the script while this one imports
the runtime (a third of a second or more each), and sends the module's
text back through a pipe (:func:`converted`).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import linecache
import os
import signal
import sys
import types
from collections.abc import Callable, Iterable, Sequence
from functools import partial
from pathlib import Path

from al2py_runtime import collector

__all__ = ["converted", "end_process", "main", "parser", "run_alone"]

#: The runtime's tables that the conversion reads and the derivation uses
#: too (no sympy): imported before the copy is made, once for both.
SHARED_MODULES = (
    "al2py_runtime.vocabulary",
    "al2py_runtime.safety",
    "al2py_runtime.progress",
    "al2py_runtime.jobs.records",
)

#: What this process imports while its copy converts the script
#: (:func:`main`): what the derivation imports (sympy among them), then,
#: unless the copy has failed already, what writing the programs imports
#: (numpy among them), which a script with errors never needs.
RUNTIME_MODULES = (
    ("al2py_runtime.workspace", "al2py_runtime.functions"),
    ("al2py_runtime.codegen",),
)


def _positive(text: str) -> int:
    """``-j``'s value: a whole number of processes, at least 1."""
    try:
        n = int(text)
    except ValueError:
        n = 0
    if n < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number >= 1, not {text!r}")
    return n


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py code",
        description="Write the program of every CODE statement of an Autolev "
        "script in the language its file names (C .c, MATLAB/Octave .m, "
        "Fortran .f or .for), and the NAME.in file of Input values it reads: "
        "the equations, the outputs and a driver (Kutta-Merson for Dynamics "
        "and ODE, a linear solve for Algebraic, Newton's method for "
        "Nonlinear) that writes the tables NAME.1, ... as run() does.  "
        "'CODE Dynamics() NAME.c, NOSUBS' writes the equations only.",
        epilog="C: 'cc -O2 -std=c99 -o NAME NAME.c -lm && ./NAME [X=VALUE ...]'; "
        "Fortran: 'gfortran -O2 -o NAME NAME.f && ./NAME [X=VALUE ...]'; MATLAB"
        " or Octave: 'octave --eval \"NAME X=VALUE ...\"' in the folder of "
        "NAME.m.  Each reads NAME.in (values from column 60) from the current "
        "folder, then the X=VALUE arguments.  No file is written twice: a "
        "job whose files another job already wrote is named apart, NAME_2 "
        "(docs/jobs.md).",
    )
    p.add_argument("input", help="the .al script")
    p.add_argument(
        "-o",
        "--outdir",
        default=".",
        metavar="DIR",
        help="folder for the programs (default: the current folder)",
    )
    p.add_argument(
        "--lang",
        choices=("c", "m", "f"),
        help="write every program in this language (c, m for MATLAB/Octave,"
        " f for Fortran) whatever the CODE statement's file extension says"
        " (tutor7's CODE names tutor7.for; --lang c writes tutor7.c)",
    )
    p.add_argument(
        "-j",
        "--jobs",
        type=_positive,
        default=None,
        metavar="N",
        help="form the programs in N processes at once (default: one per"
        " processor, at most 4; 1: in this process alone, the script converted"
        " here too); the files are the same",
    )
    return p


def main(argv: list[str], *, overlap: bool = False) -> int:
    """Returns the exit status; errors in the script raise ``AutolevError``
    (the caller prints them).  With ``overlap`` (the process's own command,
    see :func:`run_alone`) a copy of this process converts the script while
    this one imports the runtime (:func:`converted`), unless ``-j 1``."""
    args = parser().parse_args(argv)
    path = Path(args.input)
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        print(
            f"al2py: error: cannot read {args.input}: {exc.strerror}", file=sys.stderr
        )
        return 2
    if overlap and args.jobs != 1:
        _import(SHARED_MODULES)
        steps = [partial(_import, names) for names in RUNTIME_MODULES]
        code = converted(text, args.input, prepare=steps)
    else:
        code = _convert(text, args.input)
    module = types.ModuleType(path.stem)
    module.__file__ = str(path.with_suffix(".py"))
    # the module's text, for the progress line and errors naming .al lines
    linecache.cache[module.__file__] = (
        len(code),
        None,
        code.splitlines(keepends=True),
        module.__file__,
    )
    try:
        exec(compile(code, module.__file__, "exec"), module.__dict__)  # noqa: S102
    except Exception as exc:  # noqa: BLE001 - the model itself fails
        from al2py_runtime.safety import describe

        print(
            f"al2py: error: {args.input}: the model cannot be formed:"
            f" {describe(exc)}",
            file=sys.stderr,
        )
        return 2
    from al2py_runtime.codegen import available_workers, write_programs

    ws = module.al
    if not ws.numerics.jobs:
        print(f"al2py: error: {args.input} has no CODE statement", file=sys.stderr)
        return 2
    notes: list[str] = []
    workers = available_workers() if args.jobs is None else args.jobs
    written, errors = write_programs(
        ws, args.outdir, lang=args.lang, notes=notes, workers=workers
    )
    for item in written:
        print(f"Wrote {item}")
    for note in notes:
        print(f"al2py: note: {note}", file=sys.stderr)
    for message in errors:
        print(f"al2py: error: {message}", file=sys.stderr)
    return 2 if errors else 0


def _convert(text: str, filename: str) -> str:
    """The module of script ``text``, converted in this process (its errors
    raised).  The module is run, never shown: black's formatting (a third of
    the conversion) is left out, as for modules over
    ``transpile.BLACK_LIMIT``."""
    from .transpile import convert

    return convert(text, filename, formatted=False).code


def _import(names: Sequence[str]) -> None:
    for name in names:
        importlib.import_module(name)


def converted(text: str, filename: str, prepare: Sequence[Callable[[], object]]) -> str:
    """The module of script ``text`` (as :func:`_convert` gives it), while
    the steps of ``prepare`` run in this process.

    A copy of this process (``os.fork``, made before anything heavy is
    imported) converts the script and writes the module's text into a pipe;
    this process runs the steps (imports the runtime and sympy), then reads
    the text.  The copy sends the text or nothing: when it fails (an error
    in the script, or no ``fork``, no pipe, a copy killed), the script is
    converted here and its errors are raised and reported as always; so
    every message and status is the one a conversion in this process gives.
    A step after the first runs only while the copy has not failed: a
    script with errors is converted again once the first step is done (on
    an idle machine about as soon as when it was converted here alone: the
    runtime's import and the converter's follow each other either way).

    The copy takes the default action of SIGINT, SIGTERM and SIGHUP (it
    ends at once, silently); this process ends it whenever it leaves
    early (an interrupt while importing).  The copy never returns into
    its caller's code: it ends with ``os._exit``.  The derivation gets the
    room for deep recursion the conversion made when both ran here."""
    copy = _Copy.start(text, filename)
    code = None
    try:
        for i, step in enumerate(prepare):
            if i and copy is not None and copy.failed():
                break
            step()
        if copy is not None:
            code = copy.text()
    finally:
        if copy is not None:
            copy.end()
    if code is None:
        return _convert(text, filename)
    from al2py_runtime.walks import allow_deep_recursion

    allow_deep_recursion()  # as the conversion does
    return code


#: The signals that end the copy at once (:func:`converted`).
_ENDING = tuple(
    getattr(signal, name)
    for name in ("SIGINT", "SIGTERM", "SIGHUP")
    if hasattr(signal, name)
)


class _Copy:
    """A forked copy of this process converting a script
    (:func:`converted`): its process id and the reading end of its pipe."""

    def __init__(self, pid: int, reader: int) -> None:
        self.pid = pid
        self.reader = reader
        #: its exit status once it ended (and was reaped), else None
        self.status: int | None = None

    @classmethod
    def start(cls, text: str, filename: str) -> _Copy | None:
        """A copy converting ``text``; None where ``fork`` is not available
        or fails."""
        if not hasattr(os, "fork"):
            return None
        try:
            reader, writer = os.pipe()
        except OSError:
            return None
        sys.stdout.flush()
        sys.stderr.flush()
        # the signals wait until the copy has its own actions for them: an
        # interrupt now reaches this process (once forked) and, in the
        # copy, the default action, never Python's handler
        blocked = signal.pthread_sigmask(signal.SIG_BLOCK, _ENDING)
        try:
            pid = os.fork()
        except OSError:
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
            os.close(reader)
            os.close(writer)
            return None
        if pid == 0:  # the copy: converts, and ends there
            os.close(reader)
            _convert_in_copy(text, filename, writer, blocked)
        copy = cls(pid, reader)
        try:
            os.close(writer)
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        except BaseException:  # an interrupt that waited: end the copy too
            copy.end()
            raise
        return copy

    def _reaped(self, options: int) -> None:
        try:
            pid, status = os.waitpid(self.pid, options)
        except ChildProcessError:  # reaped by the system (SIGCHLD ignored)
            self.status = -1  # how it ended is not known: as a failure
            return
        if pid:
            self.status = os.waitstatus_to_exitcode(status)

    def failed(self) -> bool:
        """Whether the copy has ended without sending its text (not
        waiting for it)."""
        if self.status is None:
            self._reaped(os.WNOHANG)
        return self.status not in (None, 0)

    def text(self) -> str | None:
        """The text the copy sent, once it ended well; else None."""
        with open(self.reader, "rb", closefd=False) as pipe:
            data = pipe.read()
        if self.status is None:
            self._reaped(0)
        return data.decode("utf-8") if self.status == 0 else None

    def end(self) -> None:
        """The copy ended (killed if still running) and its pipe closed."""
        if self.status is None:
            with contextlib.suppress(ProcessLookupError):
                os.kill(self.pid, signal.SIGKILL)
            self._reaped(0)
        os.close(self.reader)


def _convert_in_copy(
    text: str, filename: str, writer: int, blocked: Iterable[int]
) -> None:
    """The copy's whole work: the module's text into the pipe ``writer``,
    then the end of the process (status 0 once all is sent, else 1; it
    never returns to the caller's code)."""
    status = 1
    try:
        for signum in _ENDING:
            signal.signal(signum, signal.SIG_DFL)
        signal.pthread_sigmask(signal.SIG_SETMASK, blocked)
        code = _convert(text, filename).encode("utf-8")
        with open(writer, "wb") as pipe:
            pipe.write(code)
        status = 0
    finally:
        os._exit(status)


def run_alone(command: Callable[[], int]) -> int:
    """Run ``command`` (``al2py code``'s :func:`main`) as the whole work of
    this process and end it with its status (:func:`end_process`).

    Without the cyclic garbage collector: the derivation and the programs
    make millions of objects that live until the end, which its passes
    walk again and again (a tenth of the command) to find the little
    cyclic garbage there is (Moore's Whipple: 9 MB beside 160 MB), freed
    when the process ends right after.  Only for the process's own command
    (``al2py``, ``python -m al2py``), never for a caller in the same
    process."""
    with collector.paused():
        status = command()
    return end_process(status)


def end_process(status: int) -> int:
    """End the ``al2py code`` process with ``status`` once its output is
    flushed, without the interpreter's teardown: freeing the derived model
    object by object and the collections at exit take a tenth of the
    command, and nothing is left to do (the programs are written and
    closed).  Only for the process's own command (``al2py``, ``python -m
    al2py``): a caller in the same process gets ``main``'s status."""
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):  # a closed or broken stream: exit as usual
        return status
    os._exit(status)
