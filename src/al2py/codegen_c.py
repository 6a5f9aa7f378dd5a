"""``al2py code FILE.al``: write the C program of each ``CODE`` statement.

    al2py code tutor6.al              writes tutor6.c (the name CODE gives)
    al2py code tutor6.al -o build/    into another folder
    al2py code tutor7.al --lang c     C although CODE names tutor7.for

Converts the script, derives the model as the generated module would on
import, and writes a self-contained C99 file per ``CODE Dynamics``/``ODE``
job (see :mod:`al2py_runtime.cprogram`).  MATLAB (``.m``) and Fortran
(``.f``, ``.for``) are not written yet; Nonlinear and Algebraic jobs
neither: each gets one clear error line and the exit status is 2.
"""

from __future__ import annotations

import argparse
import sys
import types
from pathlib import Path

from .transpile import convert

__all__ = ["main", "parser"]


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py code",
        description="Write the C program of each CODE Dynamics/ODE statement of "
        "an Autolev script: the equations of motion, the outputs and an "
        "integrator main program that writes the same tables as run().  "
        "Only C is written so far (not MATLAB or Fortran).",
        epilog="Build the result with 'cc -O2 -std=c99 -o NAME NAME.c -lm'; run "
        "'./NAME NAME=VALUE ...' to change Input values.",
    )
    p.add_argument("input", help="the .al script")
    p.add_argument(
        "-o",
        "--outdir",
        default=".",
        metavar="DIR",
        help="folder for the C files (default: the current folder)",
    )
    p.add_argument(
        "--lang",
        choices=("c",),
        help="write this language whatever the CODE statement's file"
        " extension says (tutor7's CODE names tutor7.for; --lang c writes"
        " tutor7.c)",
    )
    return p


def main(argv: list[str]) -> int:
    """Returns the exit status; errors in the script raise ``AutolevError``
    (the caller prints them)."""
    args = parser().parse_args(argv)
    path = Path(args.input)
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        print(
            f"al2py: error: cannot read {args.input}: {exc.strerror}", file=sys.stderr
        )
        return 2
    code = convert(text, args.input).code
    module = types.ModuleType(path.stem)
    module.__file__ = str(path.with_suffix(".py"))
    try:
        exec(compile(code, module.__file__, "exec"), module.__dict__)  # noqa: S102
    except Exception as exc:  # noqa: BLE001 - the model itself fails
        print(
            f"al2py: error: {args.input}: the model cannot be formed:"
            f" {type(exc).__name__}: {exc}",
            file=sys.stderr,
        )
        return 2
    from al2py_runtime.cprogram import write_programs

    ws = module.al
    if not ws.jobs:
        print(f"al2py: error: {args.input} has no CODE statement", file=sys.stderr)
        return 2
    written, errors = write_programs(ws, args.outdir, force_c=args.lang == "c")
    for item in written:
        print(f"Wrote {item}")
    for message in errors:
        print(f"al2py: error: {message}", file=sys.stderr)
    return 2 if errors else 0
