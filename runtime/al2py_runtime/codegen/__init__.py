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

import contextlib
import multiprocessing
import os
import signal
from concurrent.futures import Future, ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path, PurePath
from typing import Any

from .. import progress
from ..collector import paused
from ..jobs import backends
from ..jobs.run import Job, NumericsError
from .infile import in_text
from .program import Program, describe
from .static import describe_static

__all__ = [
    "DEFAULT_WORKERS",
    "LANGUAGES",
    "Formed",
    "Formers",
    "available_workers",
    "form",
    "in_text",
    "program_source",
    "target_file",
    "write_one",
    "write_programs",
]

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
    workers: int = 1,
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
    in ``notes`` (``note:`` lines).

    ``workers`` > 1: the jobs' programs are formed by that many forked
    copies of this process at once (:class:`Formers`), then named and
    written here in order: the same files, byte for byte.  Where ``fork``
    is not available, or a copy fails, this process forms them."""
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
    with paused():
        # the copies are forked here, before the progress line's thread
        # starts (a process forked while another thread runs may deadlock)
        formers = Formers(jobs, lang, source, workers)
        try:
            with progress.task("writing programs", len(jobs)) as task:
                for i, job in enumerate(jobs):
                    formed = formers.formed(i, task)
                    if formed is None:  # formed here, in order
                        formed = form(job, lang, source, task)
                    task.advance()
                    write_one(
                        job,
                        formed,
                        lang,
                        source,
                        directory,
                        written,
                        errors,
                        notes,
                        made,
                    )
        finally:
            formers.stop()
    return written, errors


@dataclass
class Formed:
    """One job's program formed under the name its ``CODE`` statement gives
    (:func:`form`): the file's name, its text and its ``.in`` file's (None
    with NOSUBS); or ``error``, the message of a job that cannot be
    written.  ``program`` is None when another process formed it."""

    name: str = ""
    text: str = ""
    infile: str | None = None
    error: str | None = None
    program: Program | None = None


def form(
    job: Job, lang: str | None, source: str | None, task: progress.Task | None = None
) -> Formed:
    """The program of ``job`` in ``lang`` (or its file's language), its
    text and its ``.in`` file's, under the name its ``CODE`` statement
    gives; ``task`` is told each step."""
    try:
        name = PurePath(target_file(job, lang)).name
        static = job.kind in ("ALGEBRAIC", "NONLINEAR")
        if task is not None:
            task.doing(f"{name} (forming the equations)")
        program = (describe_static if static else describe)(job, source)
        program.stem = PurePath(name).stem
        if task is not None:
            task.doing(f"{name} (printing)")
        text = program_source(program, name)
        infile = in_text(program) if not program.nosubs else None
    except (NumericsError, backends.BackendError) as exc:
        return Formed(error=_located(job, exc))
    return Formed(name, text, infile, None, program)


def _located(job: Job, exc: Exception) -> str:
    message = str(exc)
    return message if message.startswith(job.where) else f"{job.where}: {message}"


def write_one(
    job: Job,
    formed: Formed,
    lang: str | None,
    source: str | None,
    directory: Path,
    written: list[Path],
    errors: list[str],
    notes: list[str],
    made: dict[str, tuple[Job, str]],
) -> None:
    """Write one job's program and ``.in`` as ``formed`` (see
    :func:`write_programs`); ``made`` holds the files written so far, by
    lower-case name."""
    if formed.error is not None:
        errors.append(formed.error)
        return
    name, text, infile = formed.name, formed.text, formed.infile
    stem = PurePath(name).stem
    try:
        clash = name.lower() in made or (
            infile is not None
            and f"{stem}.in".lower() in made
            and made[f"{stem}.in".lower()][1] != infile
        )
        if clash:
            program = formed.program
            if program is None:  # formed in another process: again here
                again = form(job, lang, source)
                if again.error is not None:
                    errors.append(again.error)
                    return
                program = again.program
                assert program is not None
            own = name if name.lower() in made else f"{stem}.in"
            earlier = made[own.lower()][0]
            suffix = PurePath(name).suffix
            k = 2
            while any(f"{stem}_{k}{x}".lower() in made for x in (suffix, ".in")):
                k += 1
            program.stem = f"{stem}_{k}"
            for t in program.tables:  # "% FILE: STEM.1" in each header
                t.header = t.header.replace(
                    f"{stem}.{t.number}", f"{program.stem}.{t.number}", 1
                )
            name = f"{program.stem}{suffix}"
            stem = program.stem
            text = program_source(program, name)
            infile = in_text(program) if not program.nosubs else None
            notes.append(
                f"{job.where} is written as {name} (reading {stem}.in,"
                f" writing {stem}.1, ...): {own} is {earlier.where}'s"
            )
    except (NumericsError, backends.BackendError) as exc:
        errors.append(_located(job, exc))
        return
    files = [(name, text)]
    if infile is not None:
        shared = made.get(f"{stem}.in".lower())
        if shared is None:
            files.append((f"{stem}.in", infile))
        else:
            notes.append(
                f"{job.where} reads {stem}.in, written for"
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


#: the most copies ``al2py code`` makes unless asked (``-j``): each copy
#: of a large model's process soon holds much of its memory again
DEFAULT_WORKERS = 4


def available_workers() -> int:
    """``al2py code``'s default number of workers: the processors this
    process may run on, at most :data:`DEFAULT_WORKERS`."""
    affinity = getattr(os, "sched_getaffinity", None)
    count = None
    if affinity is not None:
        with contextlib.suppress(OSError):
            count = len(affinity(0))
    if count is None:
        count = os.cpu_count() or 1
    return max(1, min(count, DEFAULT_WORKERS))


class Formers:
    """The programs of ``jobs`` formed at once by ``workers`` forked copies
    of this process: a standard-library process pool
    (:class:`~concurrent.futures.ProcessPoolExecutor` over ``fork``), whose
    copies share the derived model with this process, so that only the
    programs' texts travel back.  A job's program depends on the job and
    the model alone, never on what was formed before or where, so a copy
    forms what this process would.  No copies are made with one worker or
    where ``fork`` is not available; a job whose copy failed (or whose pool
    broke) is formed here (:meth:`formed` gives None)."""

    def __init__(
        self, jobs: list[Job], lang: str | None, source: str | None, workers: int
    ) -> None:
        self._futures: dict[int, Future] = {}
        self._pool: ProcessPoolExecutor | None = None
        self._wheres = [job.where for job in jobs]
        n = self._workers = min(workers, len(jobs))
        if n < 2 or "fork" not in multiprocessing.get_all_start_methods():
            return
        # the printers' modules imported once, before the copies are made
        from . import c, fortran, octave  # noqa: F401

        try:
            self._pool = ProcessPoolExecutor(
                n,
                mp_context=multiprocessing.get_context("fork"),
                initializer=_copy_started,
                initargs=(jobs, lang, source),
            )
            # the later jobs first (a script's later jobs tend to be the
            # larger); the copies are forked at the first submit, before the
            # pool's own thread starts
            for i in reversed(range(len(jobs))):
                self._futures[i] = self._pool.submit(_form_in_copy, i)
        except OSError:
            self.stop()

    def formed(self, i: int, task: progress.Task | None = None) -> Formed | None:
        """Job ``i``'s program as a copy formed it (waiting for it, which
        ``task`` shows), or None: no copy formed it, form it here."""
        future = self._futures.pop(i, None)
        if future is None:
            return None
        if task is not None:
            task.doing(f"{self._wheres[i]} (in {self._workers} processes)")
        try:
            return Formed(*future.result())
        except Exception:  # noqa: BLE001 - the copy failed: formed here
            return None

    def stop(self) -> None:
        """The copies ended: at once when jobs are left (an error here, or
        an interrupt), the pool shut down."""
        pool, self._pool = self._pool, None
        if pool is None:
            return
        if any(not f.done() for f in self._futures.values()):
            for child in multiprocessing.active_children():
                child.terminate()
        self._futures.clear()
        pool.shutdown(wait=True, cancel_futures=True)


#: a copy's jobs, language and source (:func:`_copy_started`): the state of
#: a forked process of :class:`Formers`, never set in the process that forks
_COPY: dict[str, Any] = {}


def _copy_started(jobs: list[Job], lang: str | None, source: str | None) -> None:
    """A copy of :class:`Formers` starts: it keeps the jobs (given to it
    through ``fork``, not pickled) and leaves an interrupt to the process
    that forked it (which ends its copies), so that no copy prints one."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _COPY.update(jobs=jobs, lang=lang, source=source)


def _form_in_copy(i: int) -> tuple[str, str, str | None, str | None]:
    """In a copy: job ``i``'s program, as :class:`Formed`'s fields."""
    f = form(_COPY["jobs"][i], _COPY["lang"], _COPY["source"])
    return f.name, f.text, f.infile, f.error
