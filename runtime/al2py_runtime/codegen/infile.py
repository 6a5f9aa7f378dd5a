"""The ``STEM.in`` file Autolev wrote beside a program and its programs read.

Six header lines, then one group of lines per kind of value (constants,
initial values, integration parameters), a blank line after each group.
Each line describes one value (description, name, unit) and holds the value
from column 60 on; the programs read only that column, so a line may be
edited in place as long as the value stays right of column 59.
"""

from __future__ import annotations

import textwrap

from .program import Entry, Program

__all__ = ["VALUE_COLUMN", "in_text"]

#: The value of each line starts at this (1-based) column or later.
VALUE_COLUMN = 60


def _value(e: Entry) -> str:
    if e.name == "PRINTINT" and float(e.value).is_integer():
        return str(int(e.value))
    return repr(float(e.value))


def _unit(e: Entry) -> str:
    if e.name == "PRINTINT":
        return "Positive Integer"
    if e.name in ("ABSERR", "RELERR"):
        return ""
    return e.unit or "UNITS"


def in_text(program: Program) -> str:
    rule = "-" * 58
    lines = [
        f"File: {program.stem}.in   (al2py {program.version}, from {program.source})",
        "-" * 77,
        "Values are read from column 60 on; edit them with spaces, not tabs.",
        rule + "+" + "-" * 18,
        f"{'Description':<21}{'Quantity':<21}{'Units':<16}| Value",
        rule + "|" + "-" * 18,
    ]
    for group in program.groups:
        for e in group:
            left = f"{e.group:<21}{e.name:<20} {_unit(e):<16}"
            if len(left) > VALUE_COLUMN - 2:  # a long name: keep the column
                left = left[: VALUE_COLUMN - 3] + "~"
            lines.append(f"{left:<{VALUE_COLUMN - 2}}| {_value(e)}")
        lines.append("")
    lines += [
        rule + "+" + "-" * 18,
        "",
    ]
    if program.kind in ("ALGEBRAIC", "NONLINEAR"):
        lines += textwrap.wrap(program.task, 72)
    else:
        lines += [
            "INTEGSTP*PRINTINT is the time between rows of the output files.",
            "ABSERR and RELERR bound each integration step's absolute and relative",
            "error estimate (Kutta-Merson).",
        ]
    return "\n".join(lines) + "\n"
