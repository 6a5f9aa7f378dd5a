"""Whole libraries of ``.al`` scripts: ``al2py check`` and ``al2py convert``.

``check`` converts each script, imports the generated module in a fresh
Python process (so one bad file can neither hang nor crash the run) and, where
Autolev's transcript ``NAME.all`` sits beside ``NAME.al``, compares every
response mathematically with :func:`al2py.checking.check_responses`.

``convert`` writes one module per script into an output folder, keeping the
folder layout.  Both go on after a bad file and report it as
``file:line:col: error: ...``.

This module stays light at import time (no sympy): the pytest plugin imports
it in every test session.
"""

from __future__ import annotations

import errno
import fnmatch
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
import time
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import asdict, dataclass, field
from pathlib import Path

from .lines import split_lines

__all__ = [
    "Script",
    "ResponseFailure",
    "FileResult",
    "find_scripts",
    "orphan_transcripts",
    "check_file",
    "check_files",
    "format_table",
    "format_report",
    "format_file_report",
    "junit_xml",
    "ConvertResult",
    "convert_file",
    "convert_files",
    "write_atomically",
]

DEFAULT_TIMEOUT = 300.0
PASSED, FAILED, ERRORED = "passed", "failed", "errored"
NO_TRANSCRIPT = "none"  # responses column of a file without a transcript


# ------------------------------------------------------------- discovery


@dataclass(frozen=True)
class Script:
    """One ``.al`` file found under a path given by the user."""

    path: Path  # as found (absolute or relative to the current directory)
    relative: Path  # below the folder it was found in (its name, for a file)

    @property
    def display(self) -> str:
        return display_path(self.path)

    @property
    def transcript(self) -> Path | None:
        """``NAME.all`` beside ``NAME.al`` (any case of the suffix), if any."""
        return _sibling(self.path, ".all")


def display_path(path: Path) -> str:
    """``path`` relative to the current directory when below it."""
    try:
        rel = os.path.relpath(path)
    except ValueError:  # another drive on Windows
        return str(path)
    return str(path) if rel.startswith("..") else rel


def _sibling(path: Path, suffix: str) -> Path | None:
    exact = path.with_suffix(suffix)
    if exact.is_file():
        return exact
    try:
        for other in path.parent.iterdir():
            if (
                other.stem == path.stem
                and other.suffix.lower() == suffix
                and other.is_file()
            ):
                return other
    except OSError:
        pass
    return None


def _excluded(script: Script, patterns: Sequence[str]) -> bool:
    candidates = {script.display, script.relative.as_posix(), script.path.name}
    return any(fnmatch.fnmatch(c, p) for p in patterns for c in candidates)


def _walk(root: Path, suffix: str) -> list[Path]:
    found = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(
            d for d in dirnames if not d.startswith(".") and d != "__pycache__"
        )
        for name in sorted(filenames):
            if Path(name).suffix.lower() == suffix:
                found.append(Path(dirpath) / name)
    return found


def find_scripts(
    paths: Iterable[str | Path], exclude: Sequence[str] = ()
) -> list[Script]:
    """The ``.al`` files named by ``paths`` (folders searched recursively).

    A path that does not exist raises ``FileNotFoundError``."""
    out: list[Script] = []
    seen: set[Path] = set()
    for given in paths:
        root = Path(given)
        if root.is_dir():
            found = [Script(p, p.relative_to(root)) for p in _walk(root, ".al")]
        elif root.is_file():
            found = [Script(root, Path(root.name))]
        else:
            raise FileNotFoundError(str(given))
        for script in found:
            key = script.path.resolve()
            if key in seen or _excluded(script, exclude):
                continue
            seen.add(key)
            out.append(script)
    return out


def orphan_transcripts(paths: Iterable[str | Path]) -> list[Path]:
    """``.all`` files under the given folders with no ``.al`` beside them."""
    out = []
    for given in paths:
        root = Path(given)
        if root.is_dir():
            out += [p for p in _walk(root, ".all") if _sibling(p, ".al") is None]
    return out


# ---------------------------------------------------------------- results


@dataclass(frozen=True)
class ResponseFailure:
    """One response of the transcript that our module does not reproduce."""

    line: int  # line in the .all file
    number: int  # Autolev's response number, ``-> (n)``
    label: str
    expected: str  # Autolev's text
    ours: str  # ours, printed the Autolev way
    reason: str


@dataclass
class FileResult:
    """The verdict for one script."""

    path: str  # as displayed
    status: str  # PASSED, FAILED or ERRORED
    matched: int = 0
    total: int = 0
    transcript: str | None = None  # displayed path of the .all file
    message: str = ""  # for ERRORED: what went wrong
    failures: list[ResponseFailure] = field(default_factory=list)
    seconds: float = 0.0
    jobs_run: int = 0  # CODE jobs performed (0 with --no-run or without CODE)
    #: responses of the transcript not compared: definitions of Autolev's
    #: AutoZ intermediates (``Z12 = ...``), expanded where they are used
    not_compared: int = 0
    #: what a check did not cover (a transcript that ends early or is cut
    #: off mid-line): shown below the file's row even when it passed
    notes: list[str] = field(default_factory=list)

    @property
    def responses(self) -> str:
        return f"{self.matched}/{self.total}" if self.transcript else NO_TRANSCRIPT

    @property
    def compared(self) -> bool:
        """Whether a transcript was compared (otherwise the file only had to
        convert, import and run its CODE jobs)."""
        return self.transcript is not None

    @classmethod
    def from_json(cls, data: dict) -> FileResult:
        data = dict(data)
        data["failures"] = [ResponseFailure(**f) for f in data.get("failures", [])]
        return cls(**data)


# ----------------------------------------------------- the worker process


def _check_in_this_process(
    source: Path,
    display: str,
    transcript: Path | None,
    workdir: Path,
    run_jobs: bool = True,
) -> FileResult:
    """Convert, import and check one script (runs inside the worker)."""
    import importlib.util

    from .errors import AutolevError, InternalError
    from .static_checks import too_deep, too_large, with_source_line
    from .transpile import convert

    shown_transcript = display_path(transcript) if transcript else None
    result = FileResult(display, ERRORED, transcript=shown_transcript)
    try:
        text = source.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        result.message = f"al2py: error: cannot read {display}: {exc.strerror}"
        return result
    try:
        conversion = convert(text, display, script_dir=source.parent)
    except AutolevError as exc:
        result.message = with_source_line(exc, display, split_lines(text)).format()
        return result
    except InternalError as exc:
        result.message = f"al2py: internal error: {exc} (please report this bug)"
        return result
    except RecursionError:
        result.message = too_deep(display, text).format()
        return result
    except MemoryError:
        result.message = too_large(display, text).format()
        return result
    except Exception as exc:  # noqa: BLE001 - a verdict, never a traceback
        result.message = f"al2py: internal error: {_unexpected(exc)}"
        return result

    module_path = workdir / f"{conversion.module}.py"
    module_path.write_text(conversion.code, encoding="utf-8")
    unique = f"_al2py_check_{conversion.module}"
    try:
        spec = importlib.util.spec_from_file_location(unique, module_path)
        assert spec is not None and spec.loader is not None
        module = importlib.util.module_from_spec(spec)
        sys.modules[unique] = module
        spec.loader.exec_module(module)
    except BaseException as exc:  # noqa: BLE001 - includes SystemExit
        result.message = _import_failure(exc, module_path, display)
        return result

    job_failure = ""
    if run_jobs:
        job_failure = _run_jobs(module, display, workdir / "outputs")
        result.jobs_run = len(module.al.numerics.jobs)
    if transcript is None:
        result.message = job_failure
        result.status = ERRORED if job_failure else PASSED
        return result
    # A failed CODE job does not stop the comparison: the symbolic responses
    # are compared and reported beside the job's failure.
    from .checking import check_responses, parse_transcript, transcript_verdict

    try:
        reference = transcript.read_text(encoding="utf-8", errors="replace")
        entries = parse_transcript(reference)
        from al2py_runtime.safety import module_source

        problem, result.notes = transcript_verdict(
            reference, entries, module.al, module_source(str(module_path))
        )
        if problem:  # never "passed 0/0": the reference cannot be used
            result.message = "\n".join(
                m for m in (job_failure, f"{shown_transcript}: error: {problem}") if m
            )
            return result
        every = check_responses(entries, module.al)
    except Exception as exc:  # noqa: BLE001
        result.message = "\n".join(
            m for m in (job_failure, f"checking failed: {_describe(exc)}") if m
        )
        return result
    checks = [c for c in every if c.compared]
    unread = [c for c in every if not c.compared and not c.ok]
    result.not_compared = len(every) - len(checks)
    result.total = len(checks) + len(unread)
    result.matched = sum(c.ok for c in checks)
    checks += unread
    result.failures = [
        ResponseFailure(
            c.entry.line,
            c.entry.number,
            c.entry.label,
            c.entry.value_text,
            c.ours,
            c.how,
        )
        for c in checks
        if not c.ok
    ]
    result.message = job_failure
    if job_failure:
        result.status = ERRORED
    else:
        result.status = FAILED if result.failures else PASSED
    return result


def _run_jobs(module, display: str, outdir: Path) -> str:
    """Perform every CODE job of an imported module ('' or what failed)."""
    from al2py_runtime.jobs.run import run_job

    jobs = list(module.al.numerics.jobs)
    for job in jobs:
        try:
            result = run_job(job)
            result.write(outdir)
        except BaseException as exc:  # noqa: BLE001 - a verdict, never a traceback
            where = getattr(job, "where", "CODE")
            line = getattr(job, "line", None)
            located = f"{display}:{line}" if line else display
            text = _describe(exc)  # al2py's own words, never a library's
            if text.startswith(where + ": "):
                text = text[len(where) + 2 :]
            return f"{located}: error: {where} failed: {text}"
    return ""


def _describe(exc: BaseException) -> str:
    """The runtime's wording of a failure (:func:`al2py_runtime.safety.describe`),
    imported when a failure happens: the runtime's package loads sympy."""
    from al2py_runtime.safety import describe

    return describe(exc)


def _unexpected(exc: BaseException) -> str:
    from al2py_runtime.safety import unexpected

    return unexpected(exc)


def _import_failure(exc: BaseException, module_path: Path, display: str) -> str:
    """``importing the module raised X: msg`` and where in the generated code
    (a located ``AutolevRuntimeError`` names the script's line instead)."""
    import traceback

    if type(exc).__name__ == "AutolevRuntimeError" and getattr(exc, "filename", None):
        line = getattr(exc, "line", None)
        where = f"{display}:{line}" if line else display
        text = f"{where}: error: {exc.message}"  # type: ignore[attr-defined]
        source = getattr(exc, "source", "")
        return text + (f"\n    {source.strip()}" if source.strip() else "")

    where = ""
    frames = traceback.extract_tb(exc.__traceback__)
    for frame in reversed(frames):
        if Path(frame.filename) == module_path:
            where = f"\n    generated line {frame.lineno}: {(frame.line or '').strip()}"
            break
    return f"{display}: error: importing the converted module failed: {_describe(exc)}{where}"


def _worker_main(argv: Sequence[str]) -> int:
    """``python -c ... SOURCE DISPLAY TRANSCRIPT RESULT.json WORKDIR RUN``."""
    source, display, transcript, out, workdir, *rest = argv
    run_jobs = not rest or rest[0] != "no-run"
    start = time.perf_counter()
    result = _check_in_this_process(
        Path(source),
        display,
        Path(transcript) if transcript else None,
        Path(workdir),
        run_jobs,
    )
    result.seconds = time.perf_counter() - start
    Path(out).write_text(json.dumps(asdict(result)), encoding="utf-8")
    return 0


_WORKER = (
    "import sys; from al2py.batch import _worker_main; "
    "sys.exit(_worker_main(sys.argv[1:]))"
)


# ---------------------------------------------------------------- checking


def check_file(
    script: Script | Path | str,
    timeout: float | None = DEFAULT_TIMEOUT,
    run_jobs: bool = True,
) -> FileResult:
    """Check one script in a fresh Python process, within ``timeout`` seconds:
    convert, import, perform its CODE jobs (unless ``run_jobs`` is false) and
    compare with its transcript."""
    if not isinstance(script, Script):
        path = Path(script)
        script = Script(path, Path(path.name))
    transcript = script.transcript
    start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="al2py-check-") as tmp:
        out = Path(tmp) / "result.json"
        cmd = [
            sys.executable,
            "-c",
            _WORKER,
            str(script.path.resolve()),
            script.display,
            str(transcript.resolve()) if transcript else "",
            str(out),
            tmp,
            "run" if run_jobs else "no-run",
        ]
        with _RUNNING_LOCK:
            if _STOPPING.is_set():
                raise KeyboardInterrupt
            proc = subprocess.Popen(
                cmd,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.PIPE,
                start_new_session=True,  # its own process group, killed on timeout
            )
            _RUNNING.add(proc)
        try:
            _, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            _kill_group(proc)
            _forget(proc)
            return FileResult(
                script.display,
                ERRORED,
                transcript=display_path(transcript) if transcript else None,
                message=f"{script.display}: error: timed out after {timeout:g} s",
                seconds=time.perf_counter() - start,
            )
        _forget(proc)
        if _STOPPING.is_set():
            raise KeyboardInterrupt
        try:
            result = FileResult.from_json(json.loads(out.read_text(encoding="utf-8")))
        except (OSError, ValueError, TypeError):
            tail = "\n".join(
                "    " + line
                for line in err.decode("utf-8", "replace").strip().splitlines()[-5:]
            )
            message = (
                f"{script.display}: error: the checking process died "
                f"({_exit_reason(proc.returncode)})"
            )
            result = FileResult(
                script.display,
                ERRORED,
                transcript=display_path(transcript) if transcript else None,
                message=message + ("\n" + tail if tail else ""),
            )
    result.seconds = time.perf_counter() - start
    return result


_RUNNING: set[subprocess.Popen] = set()
_RUNNING_LOCK = threading.Lock()
_STOPPING = threading.Event()


def _forget(proc: subprocess.Popen) -> None:
    with _RUNNING_LOCK:
        _RUNNING.discard(proc)


def _stop_all() -> None:
    """Kill every worker still running (on Ctrl-C: they have their own
    process groups, so the terminal's SIGINT does not reach them)."""
    with _RUNNING_LOCK:
        _STOPPING.set()
        running = list(_RUNNING)
    for proc in running:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        except AttributeError:  # no process groups (Windows)
            proc.kill()


def _kill_group(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError, AttributeError):
        proc.kill()
    proc.communicate()


def _exit_reason(code: int | None) -> str:
    if code is not None and code < 0:
        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit status {code}"


def check_files(
    scripts: Sequence[Script],
    *,
    jobs: int = 1,
    timeout: float | None = DEFAULT_TIMEOUT,
    progress: Callable[[int, int, FileResult], None] | None = None,
    run_jobs: bool = True,
    heartbeat: Callable[[list[tuple[str, float]]], None] | None = None,
    heartbeat_every: float = 15.0,
    started: Callable[[str], None] | None = None,
) -> list[FileResult]:
    """Check ``scripts`` with up to ``jobs`` worker processes at a time.

    Results come back in the order of ``scripts``; ``progress(k, n, result)``
    is called as each finishes, ``started(file)`` as each starts, and
    ``heartbeat([(file, seconds so far)])`` every ``heartbeat_every`` seconds
    while files are being checked."""
    results: list[FileResult | None] = [None] * len(scripts)
    _STOPPING.clear()
    running: dict[str, float] = {}
    running_lock = threading.Lock()
    stop_beat = threading.Event()

    def one(script: Script) -> FileResult:
        with running_lock:
            running[script.display] = time.perf_counter()
        if started is not None:
            started(script.display)
        try:
            return check_file(script, timeout, run_jobs)
        finally:
            with running_lock:
                running.pop(script.display, None)

    def beat() -> None:
        while not stop_beat.wait(heartbeat_every):
            now = time.perf_counter()
            with running_lock:
                current = [(name, now - t0) for name, t0 in running.items()]
            if current and heartbeat is not None:
                heartbeat(current)

    beater = None
    if heartbeat is not None:
        beater = threading.Thread(target=beat, daemon=True)
        beater.start()
    pool = ThreadPoolExecutor(max_workers=max(1, jobs))
    try:
        futures = {pool.submit(one, s): i for i, s in enumerate(scripts)}
        for done, future in enumerate(as_completed(futures), start=1):
            i = futures[future]
            results[i] = future.result()
            if progress is not None:
                progress(done, len(scripts), results[i])
    except BaseException:
        _stop_all()
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    finally:
        stop_beat.set()
    pool.shutdown(wait=True)
    return [r for r in results if r is not None]


# ---------------------------------------------------------------- reports


def _outcome(result: FileResult) -> str:
    if result.status == PASSED and not result.transcript:
        ran = " and ran its CODE job" if result.jobs_run else ""
        return f"passed (no transcript to compare: converted, imported{ran})"
    if result.transcript:
        notes = "".join(f"; note: {n}" for n in result.notes)
        return f"{result.status} ({result.responses} responses{_z_note(result)}{notes})"
    return result.status


def _z_note(result: FileResult) -> str:
    """``, 12 Z not compared`` when AutoZ intermediates were skipped."""
    if not result.not_compared:
        return ""
    return f", {result.not_compared} Z not compared"


def _duration(seconds: float) -> str:
    seconds = max(0, round(seconds))
    if seconds < 60:
        return f"{seconds}s"
    m, s = divmod(seconds, 60)
    if m < 60:
        return f"{m}m{s:02d}s"
    h, m = divmod(m, 60)
    return f"{h}h{m:02d}m"


def progress_line(k: int, n: int, result: FileResult, eta: float | None = None) -> str:
    """``[3/12] models/arm.al ... passed (18/18 responses) 2.1s, ETA 40s``"""
    line = f"[{k}/{n}] {result.path} ... {_outcome(result)} {result.seconds:.1f}s"
    if eta is not None and k < n:
        line += f", ETA {_duration(eta)}"
    return line


def eta_seconds(k: int, n: int, elapsed: float) -> float | None:
    """Time left after ``k`` of ``n`` files took ``elapsed`` seconds."""
    if k <= 0 or k >= n:
        return None
    return elapsed / k * (n - k)


def heartbeat_line(current: Sequence[tuple[str, float]]) -> str:
    """``still checking: models/arm.al (45s)``"""
    return "still checking: " + ", ".join(
        f"{name} ({_duration(seconds)})" for name, seconds in current
    )


def format_table(results: Sequence[FileResult]) -> str:
    """One row per file: result, responses matched/total, time, file; errors
    show their first line below the row."""
    header = ("RESULT", "RESPONSES", "TIME", "FILE")
    rows = [(r.status, r.responses, f"{r.seconds:.1f}s", r.path) for r in results]
    widths = [max(len(row[i]) for row in [header, *rows]) for i in range(3)]
    lines = []
    for row in [header, *rows]:
        cells = [row[i].ljust(widths[i]) for i in range(3)] + [row[3]]
        lines.append("  ".join(cells).rstrip())
    out = [lines[0]]
    for line, r in zip(lines[1:], results, strict=True):
        out.append(line)
        if r.status == ERRORED and r.message:
            out.append(" " * (sum(widths) + 6) + split_lines(r.message)[0])
        for note in r.notes:
            out.append(" " * (sum(widths) + 6) + f"note: {note}")
    return "\n".join(out)


def format_file_report(result: FileResult) -> str:
    """The diff-like report for one failing or erroring file ('' if passed).

    A file whose CODE job failed still reports its compared responses."""
    lines = []
    if result.status == ERRORED:
        body = "\n".join("  " + line for line in split_lines(result.message))
        lines.append(f"{result.path}: errored\n{body}")
        if not (result.transcript and (result.total or result.not_compared)):
            return lines[0]
    elif result.status != FAILED:
        return ""
    n = len(result.failures)
    skipped = (
        f" ({result.not_compared} AutoZ intermediate definitions not compared)"
        if result.not_compared
        else ""
    )
    lines.append(
        f"{result.path}: {n} of {result.total} responses differ from "
        f"{result.transcript}{skipped}"
    )
    for f in result.failures:
        lines.append(
            f"  {result.transcript}:{f.line}: ({f.number}) {f.label}: {f.reason}"
        )
        lines.append(f"  - Autolev: {f.label} = {f.expected}")
        lines.append(f"  + al2py:   {f.label} = {f.ours}")
    return "\n".join(lines)


def summary_line(results: Sequence[FileResult], seconds: float | None = None) -> str:
    counts = {s: sum(r.status == s for r in results) for s in (PASSED, FAILED, ERRORED)}
    n = len(results)
    text = (
        f"{n} file{'s' if n != 1 else ''}: {counts[PASSED]} passed, "
        f"{counts[FAILED]} failed, {counts[ERRORED]} errored"
    )
    text += f" in {seconds:.1f}s" if seconds is not None else ""
    checked = [r for r in results if r.transcript]
    if checked:
        compared = sum(r.total for r in checked)
        matching = sum(r.matched for r in checked)
        skipped = sum(r.not_compared for r in checked)
        text += (
            f"\nresponses: {compared} compared, {matching} matching, "
            f"{skipped} not compared (AutoZ intermediate definitions)"
        )
    noted = [r.path for r in results if r.notes]
    if noted:
        shown = ", ".join(noted[:5]) + (
            f" and {len(noted) - 5} more" if len(noted) > 5 else ""
        )
        text += (
            f"\n{len(noted)} transcript{'s' if len(noted) != 1 else ''} not "
            f"compared in full (see the notes): {shown}"
        )
    bare = [r.path for r in results if r.status == PASSED and not r.transcript]
    if bare:
        shown = ", ".join(bare[:5]) + (
            f" and {len(bare) - 5} more" if len(bare) > 5 else ""
        )
        text += (
            f"\n{len(bare)} passed with no transcript, so nothing was compared: "
            f"{shown}"
        )
    return text


def format_report(results: Sequence[FileResult], seconds: float | None = None) -> str:
    """Table, then a report per failing file, then the summary line."""
    parts = [format_table(results)]
    bad = [format_file_report(r) for r in results if r.status != PASSED]
    if bad:
        parts.append("\n\n".join(bad))
    parts.append(summary_line(results, seconds))
    return "\n\n".join(parts) + "\n"


_XML_FORBIDDEN = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def xml_safe(text: str) -> str:
    """``text`` with the characters XML 1.0 forbids shown as ``\\xNN``."""
    return _XML_FORBIDDEN.sub(lambda m: f"\\x{ord(m.group()):02x}", text)


def junit_xml(
    results: Sequence[FileResult], seconds: float | None = None, name: str = "al2py"
) -> str:
    """JUnit XML: one ``testsuite``, one ``testcase`` per file."""
    import datetime
    import socket

    total = sum(r.seconds for r in results) if seconds is None else seconds
    suites = ET.Element("testsuites")
    suite = ET.SubElement(
        suites,
        "testsuite",
        {
            "name": name,
            "tests": str(len(results)),
            "failures": str(sum(r.status == FAILED for r in results)),
            "errors": str(sum(r.status == ERRORED for r in results)),
            "skipped": "0",
            "time": f"{total:.3f}",
            "timestamp": datetime.datetime.now().replace(microsecond=0).isoformat(),
            "hostname": socket.gethostname(),
        },
    )
    for attr in ("tests", "failures", "errors", "time"):
        suites.set(attr, suite.get(attr, ""))
    for r in results:
        parent = Path(r.path).parent.as_posix()
        classname = "al2py" if parent in ("", ".") else parent.replace("/", ".")
        case = ET.SubElement(
            suite,
            "testcase",
            {
                "classname": classname,
                "name": Path(r.path).name,
                "file": r.path,
                "time": f"{r.seconds:.3f}",
            },
        )
        if r.status == FAILED:
            el = ET.SubElement(
                case,
                "failure",
                {
                    "message": f"{len(r.failures)} of {r.total} responses differ",
                    "type": "ResponseMismatch",
                },
            )
            el.text = format_file_report(r)
        elif r.status == ERRORED:
            el = ET.SubElement(
                case,
                "error",
                {
                    "message": split_lines(r.message)[0] if r.message else "error",
                    "type": "ConversionError",
                },
            )
            el.text = format_file_report(r)
        elif r.transcript:
            out = ET.SubElement(case, "system-out")
            out.text = f"{r.responses} responses match {r.transcript}"
    for el in suites.iter():
        if el.text:
            el.text = xml_safe(el.text)
        for key, value in el.attrib.items():
            el.set(key, xml_safe(value))
    ET.indent(suites)
    return ET.tostring(suites, encoding="unicode", xml_declaration=True) + "\n"


# -------------------------------------------------------------- converting


@dataclass
class ConvertResult:
    """The outcome of converting one script of a library."""

    path: str  # the script, as displayed
    output: str  # the module written (or that would have been)
    ok: bool
    message: str = ""


def output_path(script: Script, outdir: Path, module: str | None = None) -> Path:
    """``OUTDIR/a/b/x.py`` for ``a/b/x.al`` (``module`` names the file when
    the script's name is not a Python identifier: ``2link.al`` -> ``m_2link.py``)."""
    from .transpile import module_name

    stem = module or module_name(script.path.name)
    return outdir / script.relative.parent / f"{stem}.py"


def convert_file(script: Script, outdir: Path) -> ConvertResult:
    """Convert one script into its place under ``outdir`` (never raises)."""
    from .errors import AutolevError, InternalError
    from .static_checks import too_deep, too_large, with_source_line
    from .transpile import convert

    target = output_path(script, outdir)
    shown = display_path(target)
    text = ""
    try:
        text = script.path.read_text(encoding="utf-8", errors="replace")
        conversion = convert(text, script.display, script_dir=script.path.parent)
        target.parent.mkdir(parents=True, exist_ok=True)
        write_atomically(target, conversion.code)
    except AutolevError as exc:
        exc = with_source_line(exc, script.display, split_lines(text))
        return ConvertResult(script.display, shown, False, exc.format())
    except InternalError as exc:
        message = f"al2py: internal error: {exc} (please report this bug)"
        return ConvertResult(script.display, shown, False, message)
    except RecursionError:
        message = too_deep(script.display, text).format()
        return ConvertResult(script.display, shown, False, message)
    except MemoryError:
        message = too_large(script.display, text).format()
        return ConvertResult(script.display, shown, False, message)
    except OSError as exc:
        message = f"al2py: error: {exc.filename or script.display}: {exc.strerror}"
        return ConvertResult(script.display, shown, False, message)
    except Exception as exc:  # noqa: BLE001 - a verdict, never a traceback
        message = f"al2py: internal error: {_unexpected(exc)}"
        return ConvertResult(script.display, shown, False, message)
    return ConvertResult(script.display, shown, True)


def convert_files(
    scripts: Sequence[Script],
    outdir: Path,
    *,
    jobs: int = 1,
    progress: Callable[[int, int, ConvertResult], None] | None = None,
) -> list[ConvertResult]:
    """Convert every script; one failure does not stop the others.

    Two scripts that would write the same module are an error for the second.
    """
    results: list[ConvertResult | None] = [None] * len(scripts)
    todo: list[int] = []
    claimed: dict[Path, str] = {}
    for i, s in enumerate(scripts):
        target = output_path(s, outdir)
        key = Path(os.path.normcase(target.resolve()))
        if key in claimed:
            results[i] = ConvertResult(
                s.display,
                display_path(target),
                False,
                f"al2py: error: {s.display}: would overwrite "
                f"{display_path(target)}, converted from {claimed[key]}",
            )
        else:
            claimed[key] = s.display
            todo.append(i)
    done = 0
    n = len(scripts)
    for r in results:
        if r is not None and progress is not None:
            done += 1
            progress(done, n, r)

    def finish(i: int, r: ConvertResult) -> None:
        nonlocal done
        results[i] = r
        done += 1
        if progress is not None:
            progress(done, n, r)

    if jobs <= 1 or len(todo) <= 1:
        for i in todo:
            finish(i, convert_file(scripts[i], outdir))
    else:
        from concurrent.futures import ProcessPoolExecutor
        from concurrent.futures.process import BrokenProcessPool

        with ProcessPoolExecutor(max_workers=jobs) as pool:
            futures = {pool.submit(convert_file, scripts[i], outdir): i for i in todo}
            for future in as_completed(futures):
                i = futures[future]
                try:
                    r = future.result()
                except BrokenProcessPool:
                    r = ConvertResult(
                        scripts[i].display,
                        display_path(output_path(scripts[i], outdir)),
                        False,
                        f"al2py: internal error: {scripts[i].display}: the "
                        "converting process died (please report this bug)",
                    )
                finish(i, r)
    return [r for r in results if r is not None]


def write_atomically(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` via a temporary file and an atomic rename.

    The temporary file is ``.NAME.PID.XXXXXX.tmp`` beside ``path``; it is
    removed on any exception (including ``KeyboardInterrupt`` and the
    ``Terminated`` that the command line raises on SIGTERM/SIGHUP).  Temporary
    files of this naming left by a killed process (``kill -9``) are removed
    first.  A target that exists and is not a regular file (``/dev/full``, a
    named pipe) is refused: the rename would replace it.
    """
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if path.exists() and not path.is_file():
        raise OSError(errno.EEXIST, "it exists and is not a regular file", str(path))
    remove_stale_temp_files(path)
    fd, tmp = tempfile.mkstemp(
        prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=directory
    )
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


#: a temporary file without a live owner is stale after this many seconds
#: (older al2py versions did not put their process id in the name)
STALE_AFTER = 600.0


def remove_stale_temp_files(path: Path) -> list[Path]:
    """Remove ``.NAME.PID.*.tmp`` beside ``path`` whose process is gone
    (and ``.NAME.*.tmp`` without a process id, once older than
    :data:`STALE_AFTER`).  Returns the files removed."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    removed = []
    try:
        candidates = list(directory.glob(f".{glob_escape(path.name)}.*.tmp"))
    except OSError:
        return removed
    for tmp in candidates:
        middle = tmp.name[len(path.name) + 2 : -len(".tmp")]
        pid_text = middle.split(".", 1)[0]
        try:
            if pid_text.isdigit() and "." in middle:
                if _alive(int(pid_text)):
                    continue
            elif time.time() - tmp.stat().st_mtime < STALE_AFTER:
                continue
            tmp.unlink()
            removed.append(tmp)
        except OSError:
            pass
    return removed


def glob_escape(name: str) -> str:
    import glob

    return glob.escape(name)


def _alive(pid: int) -> bool:
    if pid == os.getpid() or os.name == "nt":
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OSError):
        return True
    return True
