"""``python module.py``: the command line of a generated module.

``Workspace.main(AL_SOURCE)`` prints the transcript, writes the files named
by ``SAVE``, then performs the script's ``CODE`` job(s) with the ``Input``
values (changed by ``--set NAME=VALUE`` in the Input's units and ``--tfinal``),
writes the output files ``STEM.1``, ``STEM.2``, ... into ``--outdir``, prints
solved values of Nonlinear/Algebraic jobs and, with ``--plot``, writes one PNG
per output file.  Errors print one line and return 2.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path, PurePath
from typing import Any

from .jobs import check_overrides
from .records import INTEGRATION_DEFAULTS, NumericsError

__all__ = ["main", "build_parser"]


def build_parser(ws: Any) -> argparse.ArgumentParser:
    name = PurePath(ws.filename).stem or "autolev"
    inputs = ws.inputs
    lines = []
    if inputs:
        lines.append("Input values (change with --set NAME=VALUE, in these units):")
        for key, item in inputs.items():
            unit = f" {item.unit}" if item.unit else ""
            lines.append(f"  {key} = {item.value:g}{unit}")
    jobs = ws.jobs
    if jobs:
        kinds = ", ".join(f"CODE {j.kind.title()} -> {j.stem}.1, ..." for j in jobs)
        lines.append(f"Job: {kinds}")
    else:
        lines.append(
            "This script has no CODE statement: it only prints its transcript."
        )
    lines.append("Integration parameters: " + ", ".join(INTEGRATION_DEFAULTS) + ".")
    parser = argparse.ArgumentParser(
        prog=f"python {name}.py",
        description=(
            f"Print the Autolev transcript of {ws.filename} and perform its"
            " numerical CODE job."
        ),
        epilog="\n".join(lines),
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument(
        "--set",
        metavar="NAME=VALUE",
        action="append",
        default=[],
        help="change an Input value (repeatable); VALUE is in the Input's unit",
    )
    parser.add_argument("--tfinal", type=float, help="final time (sets TFINAL)")
    parser.add_argument(
        "--outdir", default=".", help="directory for output files (default: .)"
    )
    parser.add_argument(
        "--plot", action="store_true", help="also write STEM.n.png plots"
    )
    parser.add_argument(
        "--backend",
        choices=("auto", "c", "llvm", "lambdify"),
        help="how Dynamics/ODE equations are evaluated (default: $AL2PY_BACKEND"
        " or auto, the fastest available)",
    )
    parser.add_argument(
        "--emit-code",
        metavar="DIR",
        help="write the C program of each CODE Dynamics/ODE job into DIR"
        " (as 'al2py code' does) instead of running",
    )
    parser.add_argument(
        "--no-run",
        action="store_true",
        help="only print the transcript; do not perform the CODE job",
    )
    return parser


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
    parser = build_parser(ws)
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # --help (0) or a usage error (2)
        return exc.code if isinstance(exc.code, int) else 2
    jobs = ws.jobs
    try:
        overrides = _overrides(args.set, args.tfinal)
        if overrides and not jobs:
            raise NumericsError(
                f"{ws.filename} has no CODE statement; --set/--tfinal do nothing"
            )
        for job in jobs:
            check_overrides(job, overrides)
    except NumericsError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if args.emit_code is not None:
        from .cprogram import write_programs

        written, errors = write_programs(ws, args.emit_code)
        for path in written:
            print(f"Wrote {path}")
        for message in errors:
            print(f"error: {message}", file=sys.stderr)
        if not ws.jobs:
            print(f"error: {ws.filename} has no CODE statement", file=sys.stderr)
        return 2 if errors or not written else 0
    ws.print_transcript(source_lines)
    ws.write_saved_files(source_lines)
    if args.no_run:
        return 0
    outdir = Path(args.outdir)
    for job in jobs:
        try:
            result = ws.run_job(job, overrides, backend=args.backend)
            for note in result.notes:
                print(f"note: {note}", file=sys.stderr)
            written = result.write(outdir)
            for path, table in zip(written, result.tables, strict=True):
                cols = ", ".join(table.names)
                print(f"Wrote {path} ({len(table)} rows: {cols})")
            for line in result.solution_lines():
                print(line)
            if args.plot:
                for path in result.plot(outdir):
                    print(f"Wrote {path}")
        except NumericsError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
        except OSError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
    return 0
