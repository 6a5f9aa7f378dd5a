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

from pathlib import Path, PurePath
from typing import Any

from .. import progress
from ..collector import paused
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
    notes: list[str] | None = None,
) -> tuple[list[Path], list[str]]:
    """Write each ``CODE`` job's program (``lang``: all in one language) and
    its ``STEM.in`` into ``directory``.  Returns (files written, error
    messages of the jobs that cannot be written).

    No file is written twice.  A job whose program would have the name of
    an earlier job's (two CODE statements naming one file, or ``--lang f``
    on Whipple.al's ``WhippleDynamics.m`` and ``WhippleDynamics.c``), or
    whose ``STEM.in`` would differ from an earlier job's, is named apart:
    ``STEM_2`` (``_3``, ...) names its program, its ``.in`` file and the
    tables it writes.  Two programs of one stem that read the same values
    share one ``STEM.in`` (Autolev's programs did).  Each of these is said
    in ``notes`` (``note:`` lines)."""
    directory = Path(directory)
    written: list[Path] = []
    errors: list[str] = []
    notes = [] if notes is None else notes
    #: file name (lower case) -> (the job that wrote it, its text)
    made: dict[str, tuple[Job, str]] = {}
    jobs = ws.numerics.jobs if jobs is None else jobs
    # Each program forms, renames and prints tens of thousands of small
    # objects: the cyclic collector, run as they are made, would scan the
    # whole model again and again (a tenth to a fifth of the writing).
    with paused(), progress.task("writing programs", len(jobs)) as task:
        for job in jobs:
            _write_one(job, lang, source, directory, written, errors, notes, made, task)
            task.advance()
    return written, errors


def _write_one(
    job: Job,
    lang: str | None,
    source: str | None,
    directory: Path,
    written: list[Path],
    errors: list[str],
    notes: list[str],
    made: dict[str, tuple[Job, str]],
    task: progress.Task,
) -> None:
    """Write one job's program and ``.in`` (see :func:`write_programs`);
    ``made`` holds the files written so far, by lower-case name."""
    try:
        name = PurePath(target_file(job, lang)).name
        static = job.kind in ("ALGEBRAIC", "NONLINEAR")
        task.doing(f"{name} (forming the equations)")
        program = (describe_static if static else describe)(job, source)
        program.stem = PurePath(name).stem
        task.doing(f"{name} (printing)")
        text = program_source(program, name)
        infile = in_text(program) if not program.nosubs else None
        clash = name.lower() in made or (
            infile is not None
            and f"{program.stem}.in".lower() in made
            and made[f"{program.stem}.in".lower()][1] != infile
        )
        if clash:
            own = name if name.lower() in made else f"{program.stem}.in"
            earlier = made[own.lower()][0]
            stem, suffix = PurePath(name).stem, PurePath(name).suffix
            k = 2
            while any(f"{stem}_{k}{x}".lower() in made for x in (suffix, ".in")):
                k += 1
            program.stem = f"{stem}_{k}"
            for t in program.tables:  # "% FILE: STEM.1" in each header
                t.header = t.header.replace(
                    f"{stem}.{t.number}", f"{program.stem}.{t.number}", 1
                )
            name = f"{program.stem}{suffix}"
            text = program_source(program, name)
            infile = in_text(program) if not program.nosubs else None
            notes.append(
                f"{job.where} is written as {name} (reading {program.stem}.in,"
                f" writing {program.stem}.1, ...): {own} is {earlier.where}'s"
            )
    except (NumericsError, backends.BackendError) as exc:
        message = str(exc)
        if not message.startswith(job.where):
            message = f"{job.where}: {message}"
        errors.append(message)
        return
    files = [(name, text)]
    if infile is not None:
        shared = made.get(f"{program.stem}.in".lower())
        if shared is None:
            files.append((f"{program.stem}.in", infile))
        else:
            notes.append(
                f"{job.where} reads {program.stem}.in, written for"
                f" {shared[0].where} with the same values"
            )
    try:
        directory.mkdir(parents=True, exist_ok=True)
        for file, content in files:
            path = directory / file
            path.write_text(content, encoding="utf-8")
            made[file.lower()] = (job, content)
            written.append(path)
    except OSError as exc:
        errors.append(f"{job.where}: cannot write {file}: {exc.strerror or exc}")
