"""The programs ``CODE`` statements name: C, MATLAB/Octave and Fortran.

:func:`write_programs` writes, for each ``CODE`` job, what Autolev's
``CODE Dynamics() model.c`` (or ``.m``, ``.f``, ``.for``) wrote: a program
with the equations, the outputs and a driver that reads ``model.in`` (see
:mod:`.infile`), integrates with Kutta-Merson (Dynamics, ODE), solves the
linear equations (Algebraic, :mod:`.static`) or solves by Newton's method
(Nonlinear) and writes the output tables ``model.1``, ``model.2``, ... --
and ``model.in`` itself,
with the script's Input values.  ``CODE ... model.c, NOSUBS`` writes the
equations only (no driver).  One description of the program
(:mod:`.program`) is spelled by three printers (:mod:`.c`, :mod:`.fortran`,
:mod:`.octave`).

    cc -O2 -std=c99 -Wall -o tutor6 tutor6.c -lm && ./tutor6 TFINAL=5
"""

from __future__ import annotations

import dataclasses
from pathlib import Path, PurePath
from typing import Any

from .. import progress
from ..jobs import backends
from ..jobs.run import Job, NumericsError
from .infile import in_text
from .program import Program, describe
from .static import describe_static

__all__ = ["LANGUAGES", "in_text", "program_source", "target_file", "write_programs"]

#: File extensions of ``CODE`` and their language.
LANGUAGES = {".c": "C", ".m": "MATLAB", ".f": "Fortran", ".for": "Fortran"}
#: ``--lang`` values and the extension each writes.
LANG_SUFFIX = {"c": ".c", "m": ".m", "matlab": ".m", "f": ".f", "fortran": ".f"}


def target_file(job: Job, lang: str | None = None) -> str:
    """The file a job's ``CODE`` statement names (``STEM.c`` if none); with
    ``lang`` (``c``, ``m``, ``f``) the same stem in that language."""
    # a Windows path names its file after the last backslash, as RUN's does
    name = (job.filename or f"{job.stem}.c").replace("\\", "/")
    suffix = PurePath(name).suffix.lower()
    if lang is not None:
        want = LANG_SUFFIX[lang.lower()]
        if suffix != want and not (want == ".f" and suffix == ".for"):
            name, suffix = f"{PurePath(name).stem}{want}", want
    if suffix == "":
        name, suffix = f"{name}.c", ".c"
    if suffix not in LANGUAGES:
        raise NumericsError(f"{job.where}: unknown code language '{suffix}'")
    return name


def program_source(program: Program, target: str) -> str:
    """The text of ``target`` (its extension chooses the language)."""
    suffix = PurePath(target).suffix.lower()
    if suffix == ".c":
        from .c import c_source

        return c_source(program, target)
    if suffix == ".m":
        from .octave import octave_source

        return octave_source(program, target)
    from .fortran import fortran_source

    return fortran_source(program, target)


def write_programs(
    ws: Any,
    directory: str | Path = ".",
    lang: str | None = None,
    jobs: list[Job] | None = None,
    source: str | None = None,
) -> tuple[list[Path], list[str]]:
    """Write each ``CODE`` job's program (``lang``: all in one language) and
    its ``STEM.in`` into ``directory``.  Returns (files written, error
    messages of the jobs that cannot be written)."""
    directory = Path(directory)
    written: list[Path] = []
    errors: list[str] = []
    jobs = ws.numerics.jobs if jobs is None else jobs
    described: list[Program] = []
    with progress.task("writing programs", len(jobs)) as task:
        for job in jobs:
            _write_one(job, lang, source, directory, written, errors, task, described)
            task.advance()
    return written, errors


#: what a job's program is made of: two jobs alike in all these (a script's
#: ``CODE Dynamics() x.m`` and ``CODE Dynamics() x.c``) describe one program
_DESCRIBED_BY = (
    "kind",
    "stem",
    "source",
    "eqs_name",
    "sweep",
    "digits",
    "options",
    "unit_system",
    "variables",
    "unknowns",
    "names",
    "entries",
    "initials",
    "encoded",
    "declared",
    "outputs",
    "inputs",
    "rhs",
    "zero",
    "eqs",
)


def _twin(job: Job, described: list[Program]) -> Program | None:
    """The program already described for a job alike (see
    :data:`_DESCRIBED_BY`), made this job's; None if there is none."""
    for program in described:
        other = program.job
        try:
            alike = all(
                _same(getattr(job, f), getattr(other, f)) for f in _DESCRIBED_BY
            )
        except Exception:  # noqa: BLE001 - values that do not compare: not alike
            alike = False
        if alike:
            return dataclasses.replace(program, job=job)
    return None


def _same(a: Any, b: Any) -> bool:
    if a is b:
        return True
    if type(a) is not type(b):
        return False
    return bool(a == b)


def _write_one(
    job: Job,
    lang: str | None,
    source: str | None,
    directory: Path,
    written: list[Path],
    errors: list[str],
    task: progress.Task,
    described: list[Program],
) -> None:
    """Write one job's program and ``.in`` (see :func:`write_programs`);
    ``described`` keeps the programs described so far."""
    try:
        name = PurePath(target_file(job, lang)).name
        static = job.kind in ("ALGEBRAIC", "NONLINEAR")
        task.doing(f"{name} (forming the equations)")
        program = _twin(job, described)
        if program is None:
            program = (describe_static if static else describe)(job, source)
            described.append(program)
        task.doing(f"{name} (printing)")
        text = program_source(program, name)
    except (NumericsError, backends.BackendError) as exc:
        message = str(exc)
        if not message.startswith(job.where):
            message = f"{job.where}: {message}"
        errors.append(message)
        return
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / name
    path.write_text(text, encoding="utf-8")
    written.append(path)
    if not program.nosubs:
        infile = directory / f"{program.stem}.in"
        infile.write_text(in_text(program), encoding="utf-8")
        written.append(infile)
