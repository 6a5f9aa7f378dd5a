"""``python module.py``: the command line of a generated module.

``Workspace.main(AL_SOURCE)`` prints the transcript, writes the files named
by ``SAVE``, then performs the script's ``CODE`` job(s) with the ``Input``
values (changed by ``--set NAME=VALUE`` in the Input's units and ``--tfinal``),
writes the output files ``STEM.1``, ``STEM.2``, ... into ``--outdir``, prints
solved values of Nonlinear/Algebraic jobs and, with ``--plot``, writes one PNG
per output file; ``--animate`` writes ``STEM.html``, the model in motion.  Errors print one line and return 2.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path, PurePath
from typing import Any

from .jobs import budget
from .jobs.records import (
    INTEGRATION_DEFAULTS,
    NumericsError,
    job_stem,
    job_where,
    output_stems,
)
from .progress import is_terminal
from .safety import AutolevRuntimeError, describe

__all__ = ["main", "build_parser", "help_text"]


def help_text(
    filename: str,
    inputs: Sequence[tuple[str, str, str | None]],
    jobs: Sequence[tuple[str, str | None, int | None]],
) -> str:
    """What ``python module.py --help`` prints, from what the script states:
    its Input values as written and ``(kind, file, line)`` of each CODE job.
    The converter writes it into the module, which prints it before
    importing anything, so a bicycle's ``--help`` answers at once.

    >>> print(help_text("m.al", [("X", "2", "m")], [("ODE", "m.c", 3)]))
    ... # doctest: +ELLIPSIS
    usage: python m.py [-h] ...
    Input values (change with --set NAME=VALUE, in these units):
      X = 2 m
    Jobs (--job STEM runs one; default: all, in script order):
      m: CODE Ode m.c (line 3) -> m.1, ...
    ...
    """
    stems = output_stems([job_stem(file, filename) for _kind, file, _line in jobs])
    described = [
        (stem, job_where(kind, file, line))
        for stem, (kind, file, line) in zip(stems, jobs, strict=True)
    ]
    return build_parser(filename, inputs, described).format_help()


def _described(ws: Any) -> tuple[list, list]:
    """Inputs and jobs of a derived workspace, as :func:`build_parser` takes."""
    inputs = []
    for key, item in ws.numerics.inputs.items():
        try:
            shown = format(float(item.value), "g")
        except (TypeError, ValueError):  # an Input given as an expression
            shown = str(item.value)
        inputs.append((key, shown, item.unit))
    return inputs, [(j.stem, j.where) for j in ws.numerics.jobs]


#: columns of the help text (one width everywhere: the converter writes it
#: into modules)
_WIDTH = 79


def build_parser(
    filename: str,
    inputs: Sequence[tuple[str, str, str | None]],
    jobs: Sequence[tuple[str, str]],
) -> argparse.ArgumentParser:
    """The command line of ``python module.py``: ``inputs`` are ``(name,
    value as shown, unit)``, ``jobs`` are ``(stem, description)``."""
    name = PurePath(filename).stem or "autolev"
    lines = []
    if inputs:
        lines.append("Input values (change with --set NAME=VALUE, in these units):")
        lines += _columns(
            [
                f"{key} = {shown}" + (f" {unit}" if unit else "")
                for key, shown, unit in inputs
            ]
        )
    if jobs:
        lines.append("Jobs (--job STEM runs one; default: all, in script order):")
        for stem, where in jobs:
            lines += _wrapped(f"  {stem}: {where} -> {stem}.1, ...", "    ")
    else:
        lines.append(
            "This script has no CODE statement: it only prints its transcript."
        )
    lines.append("Integration parameters: " + ", ".join(INTEGRATION_DEFAULTS) + ".")
    parser = argparse.ArgumentParser(
        prog=f"python {name}.py",
        usage="%(prog)s [-h] [options]",  # each option is listed below
        description="\n".join(
            _wrapped(
                f"Print the Autolev transcript of {filename} and perform its"
                " numerical CODE job."
            )
        ),
        epilog="\n".join(lines),
        # one width everywhere: the converter writes this help into modules
        formatter_class=lambda prog: argparse.RawDescriptionHelpFormatter(
            prog, width=_WIDTH
        ),
    )
    parser.add_argument(
        "--set",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="change an Input value (repeatable); VALUE is in the Input's unit",
    )
    parser.add_argument(
        "--job",
        metavar="STEM",
        help="perform (or with --emit-code, write) only the CODE job whose file"
        " is STEM (see the list below)",
    )
    parser.add_argument(
        "--tfinal", type=float, help="final time (sets TFINAL; Dynamics/ODE jobs)"
    )
    parser.add_argument(
        "--outdir",
        default=".",
        help="directory for every file the script writes: Save files, output "
        "tables and plots, under their base names (default: .)",
    )
    parser.add_argument(
        "--plot", action="store_true", help="also write STEM.n.png plots"
    )
    parser.add_argument(
        "--animate",
        action="store_true",
        help="also write STEM.html, an animation of the model that plays in a"
        " browser (Dynamics/ODE jobs; what the script's Animate names, else"
        " every body)",
    )
    parser.add_argument(
        "--backend",
        choices=("auto", "c", "llvm", "lambdify"),
        help="how Dynamics/ODE equations are evaluated (default: $AL2PY_BACKEND"
        " or auto, the fastest available)",
    )
    parser.add_argument(
        "--zero-missing",
        action="store_true",
        help="use 0 for constants that no Input gives (by default the job stops"
        " and names them; or AL2PY_ZERO_MISSING=1)",
    )
    parser.add_argument(
        "--emit-code",
        metavar="DIR",
        help="write the program (C, MATLAB or Fortran, as CODE names it) and"
        " STEM.in of each CODE job into DIR (as 'al2py code'"
        " does) instead of running",
    )
    parser.add_argument(
        "--no-run",
        action="store_true",
        help="only print the transcript; perform no CODE job and write no file",
    )
    parser.add_argument(
        "--max-seconds",
        type=_positive,
        metavar="S",
        help=f"time budget of one integration (default {budget.LIMITS['seconds']:g};"
        " or AL2PY_MAX_SECONDS)",
    )
    parser.add_argument(
        "--max-evals",
        type=_positive,
        metavar="N",
        help="right-hand-side evaluations allowed in one integration (default "
        f"{budget.LIMITS['evaluations']:g}; or AL2PY_MAX_EVALS)",
    )
    return parser


def _wrapped(text: str, indent: str = "") -> list[str]:
    """``text`` in lines of the help's width, cut between words (later lines
    indented by ``indent`` more).

    >>> _wrapped("  job: CODE Ode x.m (line 3) -> x.1, ...", "  ")
    ['  job: CODE Ode x.m (line 3) -> x.1, ...']
    """
    import textwrap

    lead = text[: len(text) - len(text.lstrip())]
    return textwrap.wrap(
        text.lstrip(),
        _WIDTH,
        initial_indent=lead,
        subsequent_indent=lead + indent,
        break_long_words=False,
        break_on_hyphens=False,
    )


def _columns(items: Sequence[str], width: int = _WIDTH) -> list[str]:
    """``items`` in columns, in order along each line, in ``width`` columns.

    >>> _columns(["A = 1", "BB = 2 m", "C = 3"], 30)
    ['  A = 1     BB = 2 m  C = 3']
    """
    if not items:
        return []
    column = max(len(item) for item in items) + 2
    per_line = max(1, (width - 2 + 2) // column)
    return [
        (
            "  " + "".join(item.ljust(column) for item in items[k : k + per_line])
        ).rstrip()
        for k in range(0, len(items), per_line)
    ]


def _positive(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not x > 0:
        raise argparse.ArgumentTypeError("must be positive")
    return x


def _overrides(items: Sequence[str], tfinal: float | None) -> dict[str, float]:
    out: dict[str, float] = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip():
            raise NumericsError(f"--set {item!r}: expected NAME=VALUE")
        try:
            out[name.strip()] = float(value)
        except ValueError:
            raise NumericsError(f"--set {item!r}: {value!r} is not a number") from None
    if tfinal is not None:
        out["TFINAL"] = tfinal
    return out


def main(
    ws: Any, source_lines: Sequence[str], argv: Sequence[str] | None = None
) -> int:
    """Print the transcript, write Save files, run the CODE jobs; 0, or 2 on
    an error (printed as ``FILE.al:LINE: error: ...``, never a traceback)."""
    try:
        return _main(ws, source_lines, argv)
    except BrokenPipeError:  # python model.py | head
        _quiet_stdout()
        return 0


def _quiet_stdout() -> None:
    import os

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _error(ws: Any, message: str, line: int | None = None) -> int:
    where = f"{ws.filename}:{line}" if line else ws.filename
    print(f"{where}: error: {message}", file=sys.stderr)
    return 2


def _main(ws: Any, source_lines: Sequence[str], argv: Sequence[str] | None) -> int:
    parser = build_parser(ws.filename, *_described(ws))
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2)
        return exc.code if isinstance(exc.code, int) else 2
    jobs = ws.numerics.jobs
    try:
        if args.job is not None:
            jobs = [ws.numerics.job(args.job)]
        overrides = _overrides(args.set, args.tfinal)
        if overrides and not jobs:
            raise NumericsError(
                f"{ws.filename} has no CODE statement; --set/--tfinal do nothing"
            )
        if args.tfinal is not None:
            for job in jobs:
                if job.kind not in ("DYNAMICS", "ODE"):
                    raise NumericsError(
                        f"--tfinal: {job.where} has no time (only Dynamics and "
                        "ODE jobs integrate)"
                    )
        if overrides:  # (the jobs' module, numpy and all, only when used)
            from .jobs.run import check_overrides

            for job in jobs:
                check_overrides(job, overrides)
    except NumericsError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.emit_code is not None:
        from .codegen import write_programs

        notes: list[str] = []
        written, errors = write_programs(ws, args.emit_code, jobs=jobs, notes=notes)
        for path in written:
            print(f"Wrote {path}")
        for note in notes:
            print(f"note: {note}", file=sys.stderr)
        for message in errors:
            print(f"error: {message}", file=sys.stderr)
        if not ws.numerics.jobs:
            print(f"error: {ws.filename} has no CODE statement", file=sys.stderr)
        return 2 if errors or not written else 0
    # the process's own command: a long transcript printed on two
    # processors where it may (none of the caller's threads to fork with)
    from .names.responses import side_by_side

    ws.print_transcript(source_lines, side_by_side())
    if args.no_run:
        return 0  # --no-run writes nothing
    outdir = Path(args.outdir)
    try:
        ws.write_saved_files(source_lines, outdir)
    except AutolevRuntimeError as exc:  # names the Save statement's line
        print(exc, file=sys.stderr)
        return 2
    if args.max_seconds is not None:
        budget.LIMITS["seconds"] = args.max_seconds
    if args.max_evals is not None:
        budget.LIMITS["evaluations"] = args.max_evals
    budget.PROGRESS = is_terminal(sys.stdout)
    if jobs:
        from .jobs.run import run_job
    for job in jobs:
        try:
            result = run_job(
                job,
                overrides,
                backend=args.backend,
                zero_missing=True if args.zero_missing else None,
            )
            budget.clear_progress()
            for note in result.notes:
                print(f"note: {note}", file=sys.stderr)
            own = job_stem(job.filename, ws.filename)
            if own != job.stem:  # named apart: no job writes another's files
                print(
                    f"note: {job.where} writes {job.stem}.1, ...: an earlier"
                    f" CODE statement's file has the stem {own}",
                    file=sys.stderr,
                )
            written = result.write(outdir)
            for path, table in zip(written, result.written, strict=True):
                cols = ", ".join(table.names)
                print(f"Wrote {path} ({len(table)} rows: {cols})")
            for line in result.solution_lines():
                print(line)
            if args.plot:
                if job.kind not in ("DYNAMICS", "ODE") and all(
                    len(table) <= 1 for table in result.tables
                ):
                    print(
                        f"note: no plot: {job.where} solves for one point "
                        "(plots need a time history or a sweep)",
                        file=sys.stderr,
                    )
                    continue
                for path in result.save_plots(outdir):
                    print(f"Wrote {path}")
            if args.animate:
                if result.motion is None:
                    print(
                        f"note: no animation: {job.where} has no time history"
                        " (animations need CODE Dynamics or ODE)",
                        file=sys.stderr,
                    )
                    continue
                try:
                    path = result.animate(outdir / f"{result.stem}.html").path
                except NumericsError as exc:  # nothing to place: say so
                    print(f"note: no animation: {exc}", file=sys.stderr)
                    continue
                print(f"Wrote {path}")
        except BrokenPipeError:
            raise
        except (AutolevRuntimeError, NumericsError) as exc:
            budget.clear_progress()
            text = str(exc)
            if text.startswith(job.where + ": "):
                text = text[len(job.where) + 2 :]
            return _error(ws, f"{job.where}: {text}", job.line)
        except OSError as exc:
            budget.clear_progress()
            name = f" {exc.filename}" if exc.filename else ""
            return _error(ws, f"cannot write{name}: {exc.strerror}", job.line)
        except Exception as exc:  # noqa: BLE001 - no traceback reaches the user
            budget.clear_progress()
            return _error(ws, f"{job.where} failed: {describe(exc)}", job.line)
    return 0
