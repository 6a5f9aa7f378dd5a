"""The ``al2py`` command line.

    al2py tutor6.al -o tutor6.py     convert one script
    al2py - < tutor6.al              read standard input, write standard output
    al2py check models/ -j 4         convert, import and compare with .all files
    al2py convert models/ -o py/     convert a library, keeping its layout

The first argument ``check`` or ``convert`` selects a subcommand; a script
literally named ``check`` is given as ``./check``.

Exit status: 0 on success, 2 for errors in the input (``file:line:col:
error: ...``) or files that fail their check, 3 for a bug in al2py itself,
130 when interrupted.  No traceback reaches the user.
"""

from __future__ import annotations

import argparse
import contextlib
import os  # part of the module interface (tests patch cli.os)
import sys
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .lines import split_lines

if TYPE_CHECKING:
    from collections.abc import Callable

    from . import batch

__all__ = ["main"]

EXIT_OK, EXIT_INPUT, EXIT_BUG, EXIT_INTERRUPTED = 0, 2, 3, 130
SUBCOMMANDS = ("check", "convert", "code")


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py",
        description="Convert an Autolev (.al) script into a readable Python module "
        "built on sympy.physics.mechanics.",
        epilog="Run the result with 'python OUT.py' to print Autolev's transcript, "
        "or 'import' it to use the model.  For whole libraries: "
        "'al2py check PATH...' converts, imports and compares each script with "
        "its .all transcript; 'al2py convert DIR -o OUTDIR' converts a folder "
        "tree (see 'al2py check --help', 'al2py convert --help').",
    )
    p.add_argument("input", help="the .al file to convert ('-' reads standard input)")
    p.add_argument(
        "-o",
        "--output",
        metavar="OUT.py",
        help="where to write the module ('-' or omitted: standard output)",
    )
    p.add_argument("--version", action=_Version)
    return p


class _Version(argparse.Action):
    """``--version``, whose number is looked up only when it is asked for:
    ``--help`` and every command start without reading the installed
    distributions' metadata (al2py, like its imports below, loads what a
    command needs when it needs it)."""

    def __init__(self, option_strings: list[str], dest: str, **kwargs) -> None:
        super().__init__(
            option_strings,
            dest,
            nargs=0,
            default=argparse.SUPPRESS,
            help="show program's version number and exit",
        )

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        from . import __version__

        print(f"al2py {__version__}")
        parser.exit()


def _jobs(text: str) -> int:
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if n < 1:
        raise argparse.ArgumentTypeError("must be at least 1")
    return n


def _seconds(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not x > 0:
        raise argparse.ArgumentTypeError("must be positive")
    return x


def _library_options(p: argparse.ArgumentParser) -> None:
    p.add_argument(
        "-j",
        "--jobs",
        type=_jobs,
        default=1,
        metavar="N",
        help="work on N files at a time, in separate processes (default 1)",
    )
    p.add_argument(
        "--exclude",
        action="append",
        default=[],
        metavar="GLOB",
        help="skip scripts whose path, path below the folder given, or name "
        "matches GLOB (repeatable), e.g. 'include/*' or 'slow_*.al'",
    )
    p.add_argument(
        "-q", "--quiet", action="store_true", help="no progress lines on stderr"
    )


def _default_timeout() -> float:
    from .batch import DEFAULT_TIMEOUT

    return DEFAULT_TIMEOUT


def _check_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py check",
        description="Check Autolev scripts: convert each .al file, import the "
        "generated module in a fresh process, perform its CODE jobs, and where "
        "a transcript NAME.all sits beside NAME.al, compare every response "
        "mathematically (numbers within Digits, expressions at random points).  "
        "A script without a transcript passes if it converts, imports and its "
        "jobs run; the report names these files, which had nothing to compare.",
        epilog="Prints a table (passed/failed/errored, responses matched/total) "
        "and a report for each failing response.  Exit status 0 if every file "
        "passed, 2 if any failed or errored.",
    )
    p.add_argument(
        "paths", nargs="+", metavar="PATH", help=".al files or folders (recursive)"
    )
    _library_options(p)
    p.add_argument(
        "--timeout",
        type=_seconds,
        default=_default_timeout(),
        metavar="SECONDS",
        help="give up on a file after SECONDS (default %(default)g)",
    )
    p.add_argument(
        "--junit", metavar="FILE", help="also write the results as JUnit XML"
    )
    p.add_argument(
        "--no-run",
        action="store_true",
        help="do not perform the scripts' CODE jobs (by default each job runs, "
        "within the --timeout of its file, and a failing job fails the file)",
    )
    return p


def _convert_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py convert",
        description="Convert every .al script under the given folders into "
        "OUTDIR, keeping the folder layout (a/b/x.al -> OUTDIR/a/b/x.py).  "
        "Macros (.a, .r) and RUN files are found beside each script, then in "
        "AUTOLEVPATH.  A bad file is reported and the rest are still converted.",
        epilog="Exit status 0 if every file converted, 2 if any failed.",
    )
    p.add_argument(
        "paths", nargs="+", metavar="PATH", help=".al files or folders (recursive)"
    )
    p.add_argument(
        "-o",
        "--output",
        required=True,
        metavar="OUTDIR",
        help="folder for the modules (created if needed)",
    )
    _library_options(p)
    return p


def main(argv: list[str] | None = None) -> int:
    """The ``al2py`` command; without ``argv`` (the ``al2py`` script,
    ``python -m al2py``) the process's own command line, which ``al2py
    code`` runs alone (see :func:`.codegen_c.run_alone`).

    A Ctrl-C while the command's own modules are still being imported (or
    its arguments read) ends it as one during its work does."""
    try:
        status = _dispatch(argv)
    except KeyboardInterrupt:
        print("al2py: interrupted", file=sys.stderr)
        status = EXIT_INTERRUPTED
    if argv is None and status == EXIT_INTERRUPTED:
        # its work is unwound already (the ``finally`` blocks have run); a
        # process interrupted while Python imported modules was otherwise
        # sometimes ended by SIGINT during the interpreter's teardown,
        # whatever status it gave (Python 3.11, ``python -m al2py code``:
        # about a third of the interrupts in the tenth of a second after
        # the copy that converts is forked)
        return end_process(status)
    return status


def end_process(status: int) -> int:
    """End the process with ``status`` once its output is flushed, without
    the interpreter's teardown (``al2py code`` after its work, and any
    command interrupted).  Only for the process's own command (``al2py``,
    ``python -m al2py``): a caller in the same process gets ``main``'s
    status."""
    try:
        sys.stdout.flush()
        sys.stderr.flush()
    except (OSError, ValueError):  # a closed or broken stream: exit as usual
        return status
    os._exit(status)


def _dispatch(argv: list[str] | None) -> int:
    """:func:`main`, by subcommand."""
    console = argv is None
    if argv is None:
        argv = sys.argv[1:]
    argv = list(argv)
    if argv and argv[0] == "code":  # C programs of CODE statements
        from .codegen_c import main as code_main
        from .codegen_c import run_alone

        if console:
            return run_alone(
                lambda: _guarded(lambda: code_main(argv[1:], overlap=True))
            )
        return _guarded(lambda: code_main(argv[1:]))
    if argv and argv[0] in SUBCOMMANDS:
        command = argv[0]
        parser = _check_parser() if command == "check" else _convert_parser()
        args = parser.parse_args(argv[1:])
        run = _check if command == "check" else _convert_library
        return _guarded(lambda: run(args))
    args = _parser().parse_args(argv)
    return _guarded(lambda: _convert_file(args.input, args.output))


class Terminated(BaseException):
    """SIGTERM or SIGHUP arrived: unwind (removing temporary files) and exit."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


def _raise_terminated(signum: int, frame: object) -> None:
    raise Terminated(signum)


def _terminating_signals() -> dict[int, object]:
    """Make SIGTERM/SIGHUP raise :class:`Terminated`; returns the old handlers."""
    import signal

    old: dict[int, object] = {}
    for name in ("SIGTERM", "SIGHUP"):
        signum = getattr(signal, name, None)
        if signum is None:
            continue
        try:
            old[signum] = signal.signal(signum, _raise_terminated)
        except (ValueError, OSError):  # not the main thread
            pass
    return old


def _guarded(run) -> int:
    """Run a command; map every exception to a message and an exit status."""
    import signal

    old = _terminating_signals()
    try:
        return _guarded_inner(run)
    finally:
        for signum, handler in old.items():
            signal.signal(signum, handler)  # type: ignore[arg-type]


def _guarded_inner(run) -> int:
    from .errors import AutolevError, InternalError

    try:
        return run()
    except KeyboardInterrupt:
        print("al2py: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Terminated as exc:
        print("al2py: terminated", file=sys.stderr)
        return 128 + exc.signum
    except BrokenPipeError:
        _quiet_broken_pipe()
        return EXIT_OK
    except AutolevError as exc:
        print(exc.format(), file=sys.stderr)
        return EXIT_INPUT
    except InternalError as exc:
        print(f"al2py: internal error: {exc} (please report this bug)", file=sys.stderr)
        return EXIT_BUG
    except RecursionError:
        print("al2py: error: the input is nested too deeply", file=sys.stderr)
        return EXIT_INPUT
    except Exception as exc:  # noqa: BLE001 - last line of defence: no traceback
        if isinstance(exc, ModuleNotFoundError) and (exc.name or "").startswith(
            "al2py_runtime"
        ):
            print(f"al2py: error: {_runtime_missing(exc.name or '')}", file=sys.stderr)
            return EXIT_BUG
        from al2py_runtime.safety import unexpected

        print(f"al2py: internal error: {unexpected(exc)}", file=sys.stderr)
        return EXIT_BUG


def _runtime_missing(name: str) -> str:
    """What is wrong when the runtime cannot be imported: not installed at
    all, or installed without one of its modules (a broken install)."""
    import importlib.util

    try:
        found = importlib.util.find_spec("al2py_runtime") is not None
    except (ImportError, ValueError):
        found = False
    if name == "al2py_runtime" or not found:
        return (
            "the al2py-runtime distribution is not installed (al2py depends "
            "on it): pip install al2py-runtime (from a checkout: pip install ./runtime)"
        )
    return (
        f"the installed al2py-runtime is incomplete: its module {name} is "
        "missing; reinstall it (pip install --force-reinstall al2py-runtime, "
        "from a checkout: pip install --force-reinstall ./runtime)"
    )


def _quiet_broken_pipe() -> None:
    """The reader of standard output went away (``al2py x.al | head``): stop
    quietly; point stdout at /dev/null so the interpreter's final flush
    does not complain either."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _progress(quiet: bool):
    if quiet:
        return None

    def show(line: str) -> None:
        print(line, file=sys.stderr, flush=True)

    return show


def _live(what: str, total: int, unit: str):
    """A live progress line on standard error when it is a terminal (the
    runtime's :func:`al2py_runtime.progress.task`); else no task (``None``),
    and the runtime (sympy) is not imported for it."""
    if not sys.stderr.isatty():
        return contextlib.nullcontext()
    from al2py_runtime import progress

    return progress.task(what, total, unit=unit)


def _stepper(task: Any) -> Callable[[str], None] | None:
    """The ``step`` of a conversion shown by ``task`` (:func:`_live`'s,
    None when not shown): the step named, those before it counted done."""
    if task is None:
        return None
    count = 0

    def step(what: str) -> None:
        nonlocal count
        task.update(count)
        count += 1
        task.doing(what)

    return step


def _echo(line: str) -> None:
    """A line on standard error that does not mix with the live line."""
    from al2py_runtime import progress

    progress.echo(line)


def _find(paths: list[str], exclude: list[str]) -> list[batch.Script] | None:
    from . import batch

    try:
        scripts = batch.find_scripts(paths, exclude)
    except FileNotFoundError as exc:
        print(f"al2py: error: no such file or folder: {exc}", file=sys.stderr)
        return None
    if not scripts:
        print(
            f"al2py: error: no .al scripts found in {' '.join(paths)}",
            file=sys.stderr,
        )
        return None
    return scripts


def _check(args: argparse.Namespace) -> int:
    from . import batch

    scripts = _find(args.paths, args.exclude)
    if scripts is None:
        return EXIT_INPUT
    show = _progress(args.quiet)
    orphans = batch.orphan_transcripts(args.paths)
    if orphans and show:
        names = ", ".join(batch.display_path(p) for p in orphans[:5])
        more = f" and {len(orphans) - 5} more" if len(orphans) > 5 else ""
        show(f"note: transcripts without a script are not checked: {names}{more}")
    start = time.perf_counter()
    with _live("checking", len(scripts), "scripts") as task:
        if show and task is not None:
            show = _echo

        def progress(k: int, n: int, r: batch.FileResult) -> None:
            if task is not None:
                task.update(k)
            if show:
                eta = batch.eta_seconds(k, n, time.perf_counter() - start)
                show(batch.progress_line(k, n, r, eta))

        results = batch.check_files(
            scripts,
            jobs=args.jobs,
            timeout=args.timeout,
            progress=progress,
            run_jobs=not args.no_run,
            heartbeat=(lambda cur: show(batch.heartbeat_line(cur))) if show else None,
            started=task.doing if task is not None else None,
        )
    elapsed = time.perf_counter() - start
    sys.stdout.write(batch.format_report(results, elapsed))
    sys.stdout.flush()
    if args.junit:
        try:
            batch.write_atomically(Path(args.junit), batch.junit_xml(results, elapsed))
        except OSError as exc:
            print(
                f"al2py: error: cannot write {args.junit}: {exc.strerror}",
                file=sys.stderr,
            )
            return EXIT_INPUT
    ok = all(r.status == batch.PASSED for r in results)
    return EXIT_OK if ok else EXIT_INPUT


def _convert_library(args: argparse.Namespace) -> int:
    from . import batch

    scripts = _find(args.paths, args.exclude)
    if scripts is None:
        return EXIT_INPUT
    outdir = Path(args.output)
    if outdir.exists() and not outdir.is_dir():
        print(f"al2py: error: {args.output} is not a folder", file=sys.stderr)
        return EXIT_INPUT
    show = _progress(args.quiet)

    def progress(k: int, n: int, r: batch.ConvertResult) -> None:
        if show is not None:
            show(f"[{k}/{n}] {r.path} -> {r.output} ... {'ok' if r.ok else 'error'}")
        if not r.ok:  # errors are shown even with --quiet
            print(r.message, file=sys.stderr, flush=True)

    results = batch.convert_files(scripts, outdir, jobs=args.jobs, progress=progress)
    failed = [r for r in results if not r.ok]
    print(
        f"al2py: converted {len(results) - len(failed)} of {len(results)} "
        f"scripts into {args.output}"
        + (
            f"; {len(failed)} failed: {', '.join(r.path for r in failed)}"
            if failed
            else ""
        ),
        file=sys.stderr,
    )
    return EXIT_INPUT if failed else EXIT_OK


def _convert_file(source: str, output: str | None) -> int:
    if source == "-":
        raw = getattr(sys.stdin, "buffer", None)  # bytes, so bad UTF-8 is replaced
        text = raw.read().decode("utf-8", "replace") if raw else sys.stdin.read()
        filename = "<stdin>"
    else:
        path = Path(source)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError as exc:
            print(
                f"al2py: error: cannot read {source}: {exc.strerror}", file=sys.stderr
            )
            return EXIT_INPUT
        filename = source
    from .errors import AutolevError
    from .static_checks import too_deep, too_large, with_source_line
    from .transpile import STEPS, convert  # sympy: only when a command needs it

    try:
        # a large script takes seconds: its step on a terminal (not for "-")
        with _live(f"converting {Path(filename).name}", len(STEPS), "steps") as task:
            result = convert(text, filename, step=_stepper(task))
    except AutolevError as exc:
        raise with_source_line(exc, filename, split_lines(text)) from None
    except RecursionError:
        raise too_deep(filename, text) from None
    except MemoryError:
        raise too_large(filename, text) from None
    if output is None or output == "-":
        sys.stdout.write(result.code)
        return EXIT_OK
    out = Path(output)
    if source != "-" and out.exists() and out.resolve() == Path(source).resolve():
        print(
            f"al2py: error: refusing to overwrite the input file {source}",
            file=sys.stderr,
        )
        return EXIT_INPUT
    problem = _output_problem(out)
    if problem:
        print(f"al2py: error: cannot write {output}: {problem}", file=sys.stderr)
        return EXIT_INPUT
    try:
        _write_atomically(out, result.code)
    except OSError as exc:
        print(f"al2py: error: cannot write {output}: {exc.strerror}", file=sys.stderr)
        return EXIT_INPUT
    return EXIT_OK


def _output_problem(out: Path) -> str:
    """Why ``out`` must not be the target of ``-o`` ('' if it may)."""
    if out.is_dir():
        return "it is a directory"
    if out.exists() and not out.is_file():
        # /dev/full, a named pipe, a socket: an atomic rename would replace it
        return "it exists and is not a regular file (use '-o -' for standard output)"
    if out.suffix == ".py" and not out.stem.isidentifier():
        from .transpile import module_name

        better = module_name(out.stem + ".al")
        return (
            f"'{out.stem}' is not a Python identifier, so 'import {out.stem}' "
            f"cannot load it; name the output {better}.py"
        )
    return ""


def _write_atomically(path: Path, text: str) -> None:
    from .batch import write_atomically

    write_atomically(path, text)
