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
exists, a forked copy of this process converts the script while this one
imports the runtime (a third of a second or more each), and gives back the
module's text (:func:`converted`).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import linecache
import sys
import types
from collections.abc import Callable, Sequence
from concurrent.futures import Future
from functools import partial
from pathlib import Path

from al2py_runtime import collector, copies

from .cli import end_process

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
#: (numpy among them, and the three languages' printers, which the copies
#: that form the programs would otherwise wait for after the derivation),
#: which a script with errors never needs.
RUNTIME_MODULES = (
    ("al2py_runtime.workspace", "al2py_runtime.functions"),
    (
        "al2py_runtime.codegen",
        "al2py_runtime.codegen.c",
        "al2py_runtime.codegen.fortran",
        "al2py_runtime.codegen.octave",
    ),
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

    A copy of this process converts the script: a standard-library process
    pool of one (:class:`~concurrent.futures.ProcessPoolExecutor` over
    ``fork``, made before anything heavy is imported), whose result is the
    module's text.  Meanwhile this process runs the steps (imports the
    runtime and sympy).  A step after the first runs only while the copy
    has not failed.  When the copy gives no text (an error in the script,
    no ``fork``, a copy that broke), the script is converted here and its
    errors are raised and reported as always: every message and status is
    the one a conversion in this process gives.

    The copy leaves an interrupt to this process, which ends the copy
    whenever it leaves before the text has come
    (:mod:`al2py_runtime.copies`).
    The derivation gets the room for deep recursion the conversion made
    when both ran here."""
    pool = copies.fork_pool(1)
    future = None
    code = None
    try:
        if pool is not None:
            # (an interrupt held back while the copy is forked is raised
            # as the signals come through, leaving with the copy made)
            with contextlib.suppress(OSError), copies.forking():  # else: here
                future = pool.submit(_convert_in_copy, text, filename)
        for i, step in enumerate(prepare):
            if i and future is not None and _failed(future):
                break
            step()
        if future is not None and not _failed(future):
            with contextlib.suppress(Exception):  # the pool broke: here
                code = future.result()
    finally:
        if pool is not None:  # leaving early: the copy ended at once
            copies.end_pool(pool, work_left=future is None or not future.done())
    if code is None:
        return _convert(text, filename)
    from al2py_runtime.walks import allow_deep_recursion

    allow_deep_recursion()  # as the conversion does
    return code


def _failed(future: Future) -> bool:
    """Whether the copy has ended without the text (not waiting for it)."""
    return future.done() and (future.exception() is not None or future.result() is None)


def _convert_in_copy(text: str, filename: str) -> str | None:
    """In the copy: the module's text, or None where the script has errors
    (they are found and reported again by the process, as always)."""
    from .errors import AutolevError

    try:
        return _convert(text, filename)
    except AutolevError:
        return None


def run_alone(command: Callable[[], int]) -> int:
    """Run ``command`` (``al2py code``'s :func:`main`) as the whole work of
    this process and end it with its status (:func:`.cli.end_process`:
    freeing the derived model object by object and the collections at exit
    take a tenth of the command, and nothing is left to do).

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
