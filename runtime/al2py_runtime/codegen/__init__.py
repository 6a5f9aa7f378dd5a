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

from collections.abc import Mapping
from concurrent.futures import Future, ProcessPoolExecutor
from dataclasses import dataclass
from pathlib import Path, PurePath
from typing import Any

from .. import copies, progress
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
    "estimated_work",
    "form",
    "in_text",
    "meeting",
    "placed",
    "program_source",
    "renamed_program",
    "target_file",
    "write_one",
    "write_programs",
    "written_files",
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
    copies of this process at once (:class:`Formers`), then written here
    in order: the same files, byte for byte.  Where ``fork`` is not
    available, or a copy fails, this process forms them."""
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
                    files = written_files(made)
                    formed = formers.formed(i, task)
                    if formed is not None and not _named_so(formed, files):
                        formed = None  # its .in file differs from an earlier one's
                    if formed is None:  # formed here, in order
                        formed = form(job, lang, source, task, files)
                    task.advance()
                    write_one(job, formed, directory, written, errors, notes, made)
                    formers.written(i, made)
        finally:
            formers.stop()
    return written, errors


@dataclass
class Formed:
    """One job's program formed (:func:`form`): the file's name, its text
    and its ``.in`` file's (None with NOSUBS); or ``error``, the message of
    a job that cannot be written.  ``apart``: the earlier file whose name
    the ``CODE`` statement's would take (:func:`placed`), None when the
    program has that name.  ``program`` is None when another process
    formed it."""

    name: str = ""
    text: str = ""
    infile: str | None = None
    error: str | None = None
    program: Program | None = None
    apart: str | None = None


def form(
    job: Job,
    lang: str | None,
    source: str | None,
    task: progress.Task | None = None,
    written: Mapping[str, str | None] | None = None,
) -> Formed:
    """The program of ``job`` in ``lang`` (or its file's language), its
    text and its ``.in`` file's, under the name its ``CODE`` statement
    gives, or, among the files ``written`` before it (:func:`written_files`),
    the name :func:`placed` gives it; ``task`` is told each step."""
    try:
        name = PurePath(target_file(job, lang)).name
        static = job.kind in ("ALGEBRAIC", "NONLINEAR")
        if task is not None:
            task.doing(f"{name} (forming the equations)")
        program = (describe_static if static else describe)(job, source)
        program.stem = PurePath(name).stem
        infile = in_text(program) if not program.nosubs else None
        apart = None
        if written is not None:
            name, apart = placed(name, infile, written)
            if apart is not None:
                renamed_program(program, PurePath(name).stem)
                infile = in_text(program) if infile is not None else None
        if task is not None:
            task.doing(f"{name} (printing)")
        text = program_source(program, name)
    except (NumericsError, backends.BackendError) as exc:
        return Formed(error=_located(job, exc))
    return Formed(name, text, infile, None, program, apart)


def _named_so(formed: Formed, written: Mapping[str, str | None]) -> bool:
    """Whether ``formed``, a copy's, has the name :func:`placed` gives it
    among the files ``written`` before it: a copy that formed it before
    they were written (:func:`meeting`) named it as its ``CODE`` statement
    does."""
    if formed.error is not None or formed.apart is not None:
        return True  # (named among those files)
    return placed(formed.name, formed.infile, written)[1] is None


def written_files(made: Mapping[str, tuple[Job, str]]) -> dict[str, str | None]:
    """The files written so far (:func:`write_programs`'s ``made``) as
    :func:`placed` reads them: by lower-case name, a ``.in`` file's text,
    None for a program's."""
    return {k: (v[1] if k.endswith(".in") else None) for k, v in made.items()}


def placed(
    name: str, infile: str | None, written: Mapping[str, str | None]
) -> tuple[str, str | None]:
    """The name of the program ``name`` (whose ``.in`` file's text under
    that name is ``infile``) among the files ``written`` before it
    (:func:`written_files`), and the earlier file it is named apart from
    (None: none): ``STEM_2`` (``_3``, ...) when ``name`` is taken, or when
    ``STEM.in`` is and holds other values (see :func:`write_programs`)."""
    stem = PurePath(name).stem
    own_in = f"{stem}.in"
    if name.lower() in written:
        own = name
    elif infile is not None and written.get(own_in.lower(), infile) != infile:
        own = own_in
    else:
        return name, None
    suffix = PurePath(name).suffix
    k = 2
    while any(f"{stem}_{k}{x}".lower() in written for x in (suffix, ".in")):
        k += 1
    return f"{stem}_{k}{suffix}", own


def renamed_program(program: Program, stem: str) -> None:
    """``program`` named ``stem``: its ``.in`` file and its tables' too."""
    for t in program.tables:  # "% FILE: STEM.1" in each header
        t.header = t.header.replace(
            f"{program.stem}.{t.number}", f"{stem}.{t.number}", 1
        )
    program.stem = stem


def _located(job: Job, exc: Exception) -> str:
    message = str(exc)
    return message if message.startswith(job.where) else f"{job.where}: {message}"


def write_one(
    job: Job,
    formed: Formed,
    directory: Path,
    written: list[Path],
    errors: list[str],
    notes: list[str],
    made: dict[str, tuple[Job, str]],
) -> None:
    """Write one job's program and ``.in`` as ``formed`` (see
    :func:`write_programs`), named among the files written before it
    (``made``: by lower-case name, the job that wrote each and its text)."""
    if formed.error is not None:
        errors.append(formed.error)
        return
    name, text, infile = formed.name, formed.text, formed.infile
    stem = PurePath(name).stem
    if formed.apart is not None:
        earlier = made[formed.apart.lower()][0]
        notes.append(
            f"{job.where} is written as {name} (reading {stem}.in,"
            f" writing {stem}.1, ...): {formed.apart} is {earlier.where}'s"
        )
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
    return max(1, min(copies.processors(), DEFAULT_WORKERS))


class Formers:
    """The programs of ``jobs`` formed at once by ``workers`` forked copies
    of this process: a standard-library process pool
    (:class:`~concurrent.futures.ProcessPoolExecutor` over ``fork``), whose
    copies share the derived model with this process, so that only the
    programs' texts travel back.  A job's program depends on the job, the
    model and the files written before it alone, never on where it was
    formed, so a copy forms what this process would.  No copies are made
    with one worker or where ``fork`` is not available; a job whose copy
    failed (or whose pool broke) is formed here (:meth:`formed` gives
    None).

    The largest jobs are formed first (:func:`estimated_work`), so that no
    copy is left with a large one when the others are done.  A job whose
    program's name an earlier job's may take (:func:`meeting`) waits until
    that one is written (:meth:`written`): the copy that forms it then
    names it among the files written before it, as this process would
    (:func:`placed`), and forms it once.  The others are named as their
    ``CODE`` statements do; :func:`write_programs` forms one again only
    when an earlier ``.in`` file of its stem holds other values."""

    def __init__(
        self, jobs: list[Job], lang: str | None, source: str | None, workers: int
    ) -> None:
        self._futures: dict[int, Future] = {}
        self._pool: ProcessPoolExecutor | None = None
        self._jobs = jobs
        #: the jobs waiting for each job to be written (see :meth:`written`)
        self._waiting: dict[int, list[int]] = {}
        n = self._workers = min(workers, len(jobs))
        if n < 2:
            return
        # the printers' modules imported once, before the copies are made
        from . import c, fortran, octave  # noqa: F401

        after = meeting(jobs, lang)
        first = [i for i in range(len(jobs)) if after[i] is None]
        for i, j in enumerate(after):
            if j is not None:
                self._waiting.setdefault(j, []).append(i)
        work = [estimated_work(job) for job in jobs]
        # the largest first (of equal ones, the later: a script's later
        # jobs tend to be the larger)
        first.sort(key=lambda i: (work[i], i), reverse=True)
        pool = copies.fork_pool(n, _copy_started, (jobs, lang, source))
        if pool is None:
            return
        futures = copies.submit_forking(
            pool, [(_form_in_copy, (i, None)) for i in first]
        )
        if futures is not None:
            self._pool = pool
            self._futures = dict(zip(first, futures, strict=True))

    def formed(self, i: int, task: progress.Task | None = None) -> Formed | None:
        """Job ``i``'s program as a copy formed it (waiting for it, which
        ``task`` shows), or None: no copy formed it, form it here."""
        future = self._futures.pop(i, None)
        if future is None:
            return None
        if task is not None:
            task.doing(f"{self._jobs[i].where} (in {self._workers} processes)")
        try:
            return Formed(*future.result())
        except Exception:  # noqa: BLE001 - the copy failed: formed here
            return None

    def written(self, i: int, made: dict[str, tuple[Job, str]]) -> None:
        """Job ``i``'s files are written (``made``: every file written so
        far, see :func:`write_programs`): the jobs waiting for it are
        formed now, named among those files."""
        waiting = self._waiting.pop(i, [])
        if self._pool is None or not waiting:
            return
        files = written_files(made)
        waiting.sort(key=lambda k: (estimated_work(self._jobs[k]), k), reverse=True)
        try:
            for k in waiting:
                self._futures[k] = self._pool.submit(_form_in_copy, k, files)
        except (OSError, RuntimeError):  # the pool broke: formed here
            pass

    def stop(self) -> None:
        """The copies ended: at once when jobs are left (an error here, or
        an interrupt), the pool shut down."""
        pool, self._pool = self._pool, None
        if pool is None:
            return
        futures = list(self._futures.values())
        self._futures.clear()
        copies.end(pool, futures)


def estimated_work(job: Job) -> int:
    """A cheap measure of the work of forming ``job``'s program, to form
    the largest first (:class:`Formers`): the scalar expressions it
    evaluates (each Output's and Encode's items, each state's derivative,
    the mass matrix and forcing of its implicit equations, the equations
    of an Algebraic or Nonlinear job and their Jacobian)."""
    count = sum(len(o.items) for o in job.outputs)
    count += sum(max(order, 1) for _name, _obj, order in job.variables)
    for eqs in (job.zero, job.eqs):
        if eqs is not None:
            count += len(eqs) * (len(eqs) + 1)
    return count


def meeting(jobs: list[Job], lang: str | None) -> list[int | None]:
    """For each job, the earlier job it waits for (None: none): when an
    earlier job's program may take its program's name (the same extension,
    and a stem its own, or its own with ``_2``, ``_3``, ... as it may be
    named apart, or the other way round), the last earlier job of such a
    stem, whatever its extension, so that the files written before that
    one are all those its own may meet (:func:`placed`).  Stems are
    compared without case, as :func:`placed` does.  A job of such a stem
    but another extension (``WhippleDynamics.c`` after
    ``WhippleDynamics.m``) does not wait: it is named apart only when its
    ``.in`` file's values differ, which :func:`write_programs` checks."""
    names: list[tuple[str, str] | None] = []
    for job in jobs:
        try:
            path = PurePath(target_file(job, lang))
        except NumericsError:
            names.append(None)  # no file: an error line
            continue
        names.append((path.stem.lower(), path.suffix.lower()))
    after: list[int | None] = []
    for i, this in enumerate(names):
        related = [
            j
            for j, other in enumerate(names[:i])
            if this is not None and other is not None and _related(this[0], other[0])
        ]
        same = this is not None and any(names[j][1] == this[1] for j in related)
        after.append(related[-1] if same else None)
    return after


def _related(a: str, b: str) -> bool:
    """Whether the stems ``a`` and ``b`` (lower case) may name one file:
    the same, or one the other with ``_2``, ``_3``, ..."""
    return a == b or a.startswith(b + "_") or b.startswith(a + "_")


#: a copy's jobs, language and source (:func:`_copy_started`): the state of
#: a forked process of :class:`Formers`, never set in the process that forks
_COPY: dict[str, Any] = {}


def _copy_started(jobs: list[Job], lang: str | None, source: str | None) -> None:
    """A copy of :class:`Formers` starts (after :func:`..copies.started`):
    it keeps the jobs (given to it through ``fork``, not pickled)."""
    _COPY.update(jobs=jobs, lang=lang, source=source)


def _form_in_copy(
    i: int, written: dict[str, str | None] | None
) -> tuple[str, str, str | None, str | None, None, str | None]:
    """In a copy: job ``i``'s program (named among the files ``written``
    before it, see :func:`form`), as :class:`Formed`'s fields."""
    f = form(_COPY["jobs"][i], _COPY["lang"], _COPY["source"], None, written)
    return f.name, f.text, f.infile, f.error, None, f.apart
