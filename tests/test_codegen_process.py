"""``al2py code`` as its own process ends itself once its output is
flushed (:func:`al2py.codegen_c.end_process`): the same files, lines and
status as ``main`` called in-process, which returns."""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT

from al2py.cli import main as al2py_main

TUTOR6 = ROOT / "examples" / "tutor6.al"


def _process(*args: str, cwd) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        capture_output=True,  # pipes: the output is buffered until flushed
        text=True,
        cwd=cwd,
        timeout=600,
    )


def test_the_process_writes_what_main_writes(tmp_path, capsys):
    assert gc.isenabled()
    assert al2py_main(["code", str(TUTOR6), "-o", str(tmp_path / "a")]) == 0
    assert gc.isenabled()  # in-process: the collector as it was
    inprocess = capsys.readouterr().out
    done = _process("code", str(TUTOR6), "-o", "b", cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout == inprocess.replace(str(tmp_path / "a"), "b")
    assert done.stdout.count("Wrote ") == 2
    written = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert written == ["tutor6.c", "tutor6.in"]
    for name in written:
        assert (tmp_path / "b" / name).read_bytes() == (
            tmp_path / "a" / name
        ).read_bytes()


def test_run_alone_ends_the_process_without_the_collector(tmp_path):
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            "import gc\n"
            "from al2py.codegen_c import run_alone\n"
            "run_alone(lambda: print('collector', gc.isenabled()) or 3)\n"
            "print('not reached')\n",
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert (done.returncode, done.stdout) == (3, "collector False\n")


def test_the_process_ends_with_main_s_status(tmp_path, capsys):
    (tmp_path / "none.al").write_text("constants a\nb = a + 1\n")
    assert al2py_main(["code", str(tmp_path / "none.al")]) == 2
    said = capsys.readouterr().err
    done = _process("code", "none.al", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr == said.replace(str(tmp_path / "none.al"), "none.al")
    assert "has no CODE statement" in done.stderr


# ------------------------------------------- programs formed in processes

# Five jobs: one with nothing to integrate yet (an error line), two naming
# one file (the second is named apart), one with another Output, and an
# Algebraic job.
MANY_JOBS = """\
Variables X'
Constants A, B
Input A=2, B=0.5, X=1, TFINAL=1
Output T, X
CODE ODE() early.c
X' = -A*X + B
CODE ODE() decay.c
CODE ODE() decay.c
Output T, X, A*X
CODE ODE() decay.m
Y = 2*X
CODE Algebraic() decayalg.m
"""


def _written(folder, printed: str) -> dict:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())} | {
        "printed": printed.replace(str(folder), "OUT")
    }


#: the files MANY_JOBS's programs make (one job named apart as decay_2)
MANY_JOBS_FILES = [
    "decay.c",
    "decay.in",
    "decay.m",
    "decay_2.c",
    "decay_2.in",
    "decayalg.in",
    "decayalg.m",
]


def test_processes_write_what_one_process_writes(tmp_path, capsys):
    """``-j 3`` (jobs formed by forked copies, one of them named apart and
    formed again here) and ``-j 1`` write the same bytes, lines, notes and
    errors."""
    script = tmp_path / "many.al"
    script.write_text(MANY_JOBS)
    seen = []
    for workers in ("1", "3", "2"):
        out = tmp_path / f"j{workers}"
        status = al2py_main(["code", "-j", workers, str(script), "-o", str(out)])
        captured = capsys.readouterr()
        seen.append((status, _written(out, captured.out), captured.err))
    assert seen[0][0] == 2  # early.c
    assert "early.c (line 5): nothing to integrate" in seen[0][2]
    assert "is written as decay_2.c" in seen[0][2]
    assert sorted(seen[0][1]) == sorted([*MANY_JOBS_FILES, "printed"])
    assert seen[1] == seen[0]
    assert seen[2] == seen[0]


def test_copies_form_each_job_as_this_process_does(tmp_path):
    """Each job formed by a copy as here, named among the files written
    before it (those that meet an earlier job's wait until it is written)."""
    from al2py_runtime.codegen import Formers, form, write_one, written_files

    from al2py.transpile import convert

    code = convert(MANY_JOBS, "many.al", formatted=False).code
    namespace: dict = {"__name__": "many", "__file__": str(tmp_path / "many.py")}
    exec(compile(code, str(tmp_path / "many.py"), "exec"), namespace)  # noqa: S102
    jobs = namespace["al"].numerics.jobs
    pid = os.getpid()
    formers = Formers(jobs, None, None, 2)
    made: dict = {}
    try:
        for i, job in enumerate(jobs):
            got = formers.formed(i)
            here = form(job, None, None, None, written_files(made))
            assert got is not None  # formed by a copy
            assert got.program is None  # (a copy sends only the texts)
            fields = ("name", "text", "infile", "error", "apart")
            assert [getattr(got, f) for f in fields] == [
                getattr(here, f) for f in fields
            ]
            write_one(job, got, tmp_path / "out", [], [], [], made)
            formers.written(i, made)
    finally:
        formers.stop()
    assert sorted(made) == MANY_JOBS_FILES
    assert os.getpid() == pid
    assert Formers(jobs, None, None, 1).formed(0) is None  # one worker: no copies


def test_copies_stopped_midway_leave_no_process(tmp_path):
    """An error or an interrupt while copies still form: stop() ends them."""
    import multiprocessing

    from al2py_runtime.codegen import Formers

    from al2py.transpile import convert

    code = convert(MANY_JOBS, "many.al", formatted=False).code
    namespace: dict = {"__name__": "many", "__file__": str(tmp_path / "many.py")}
    exec(compile(code, str(tmp_path / "many.py"), "exec"), namespace)  # noqa: S102
    jobs = namespace["al"].numerics.jobs
    formers = Formers(jobs, None, None, 2)
    assert multiprocessing.active_children()
    formers.stop()
    assert not multiprocessing.active_children()


def _interrupted_forking(monkeypatch):
    """``copies.forking`` whose held-back signals bring an interrupt as
    they come through, once the copies are made (a Ctrl-C while forking)."""
    import contextlib

    from al2py_runtime import copies

    real = copies.forking

    @contextlib.contextmanager
    def forking():
        with real():
            yield
        raise KeyboardInterrupt

    monkeypatch.setattr(copies, "forking", forking)


def test_an_interrupt_as_the_copies_are_forked_leaves_no_process(tmp_path, monkeypatch):
    """A Ctrl-C held back while the copies are forked, which comes through
    once they are made: it leaves the command with no copy left behind
    (the copy of the conversion and the copies that form programs)."""
    import multiprocessing

    from al2py_runtime.codegen import Formers

    from al2py import codegen_c
    from al2py.transpile import convert

    code = convert(MANY_JOBS, "many.al", formatted=False).code
    namespace: dict = {"__name__": "many", "__file__": str(tmp_path / "many.py")}
    exec(compile(code, str(tmp_path / "many.py"), "exec"), namespace)  # noqa: S102
    jobs = namespace["al"].numerics.jobs
    _interrupted_forking(monkeypatch)
    with pytest.raises(KeyboardInterrupt):
        Formers(jobs, None, None, 2)
    assert not multiprocessing.active_children()
    with pytest.raises(KeyboardInterrupt):
        codegen_c.converted(TUTOR6.read_text(), "tutor6.al", prepare=[])
    assert not multiprocessing.active_children()


@pytest.mark.parametrize("value", ["0", "-2", "two", "1.5"])
def test_jobs_must_be_a_whole_number_of_processes(tmp_path, capsys, value):
    """``-j`` is never quietly taken as another number."""
    with pytest.raises(SystemExit) as exit_:
        al2py_main(["code", str(TUTOR6), "-o", str(tmp_path), "-j", value])
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert f"argument -j/--jobs: expected a whole number >= 1, not '{value}'" in err
    assert not any(tmp_path.iterdir())


def test_default_copies_are_the_processors_at_most_four(monkeypatch):
    from al2py_runtime import codegen, copies

    monkeypatch.setattr(copies.os, "sched_getaffinity", lambda pid: set(range(64)))
    assert copies.processors() == 64
    assert codegen.available_workers() == codegen.DEFAULT_WORKERS == 4
    monkeypatch.setattr(copies.os, "sched_getaffinity", lambda pid: {0, 1})
    assert codegen.available_workers() == 2


# ------------------------- the script converted by a copy (issue 35)

#: three errors of a script: all reported, in order, whoever converts
BAD = """\
Variables X'
Constants A
X' = -A*X + Q
Y = 3 +* 2
Z = foo(X
CODE ODE() bad.c
"""

#: a script that converts but whose model cannot be formed
SINGULAR = """\
Variables X'
Constants A
X' = -A*X
M = [1, 2; 2, 4]
N = Inv(M)
Input A=1, X=1
Output X
CODE ODE() x.c
"""


@pytest.mark.parametrize(
    ("script", "said"),
    [
        (BAD, "3 errors"),
        (SINGULAR, "the model cannot be formed"),
    ],
)
def test_the_process_reports_what_main_reports(tmp_path, capsys, script, said):
    """The process (its script converted by a copy) and ``main`` in-process
    (converted here) print the same messages, with status 2, no file."""
    (tmp_path / "s.al").write_text(script)
    assert al2py_main(["code", str(tmp_path / "s.al"), "-o", str(tmp_path / "a")]) == 2
    inprocess = capsys.readouterr()
    done = _process("code", "s.al", "-o", "b", cwd=tmp_path)
    assert done.returncode == 2
    assert said in done.stderr
    assert done.stderr == inprocess.err.replace(str(tmp_path / "s.al"), "s.al")
    assert done.stdout == inprocess.out == ""
    assert not (tmp_path / "b").exists() and not (tmp_path / "a").exists()


_COPY_PROBE = """\
import sys
from al2py.codegen_c import _convert, converted
text = open(sys.argv[1]).read()
seen = []
def step():
    seen.append([m for m in ("al2py.transpile", "sympy") if m in sys.modules])
    import sympy
code = converted(text, "tutor6.al", prepare=[step, step])
print(seen, "al2py.transpile" in sys.modules)
assert code == _convert(text, "tutor6.al")
"""


def test_a_copy_converts_while_this_process_prepares(tmp_path):
    """:func:`converted` gives the conversion's text, made by a copy: this
    process had not imported the converter when its steps ran, nor
    afterwards (until the check converts here)."""
    done = subprocess.run(
        [sys.executable, "-c", _COPY_PROBE, str(TUTOR6)],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout == "[[], ['sympy']] False\n"


def test_a_failed_copy_skips_the_later_steps(monkeypatch):
    """A copy that has failed (a script with errors): the steps after the
    first are left out, and the errors are those of a conversion here."""
    from concurrent.futures import Future

    from al2py import codegen_c
    from al2py.errors import AutolevError

    class FailedCopy:
        """A pool whose copy has failed by the time the first step ends."""

        def __init__(self, *args: object, **kwargs: object) -> None:
            self.future: Future = Future()

        def submit(self, *args: object) -> Future:
            return self.future

        def fail(self) -> None:
            self.future.set_exception(RuntimeError("the copy failed"))

        def shutdown(self, **kwargs: object) -> None:
            pass

    pools: list[FailedCopy] = []
    monkeypatch.setattr(
        codegen_c.copies,
        "fork_pool",
        lambda *a, **k: pools.append(FailedCopy()) or pools[-1],
    )
    steps = []
    with pytest.raises(AutolevError) as here:
        codegen_c._convert(BAD, "bad.al")
    with pytest.raises(AutolevError) as copied:
        codegen_c.converted(
            BAD,
            "bad.al",
            prepare=[
                lambda: steps.append(1) or pools[0].fail(),
                lambda: steps.append(2),
            ],
        )
    assert steps == [1]
    assert copied.value.format() == here.value.format()
    assert "3 errors" in copied.value.format()


def test_without_fork_the_script_is_converted_here(tmp_path, monkeypatch):
    from al2py import codegen_c

    monkeypatch.setattr(
        codegen_c.copies.multiprocessing, "get_all_start_methods", lambda: ["spawn"]
    )
    text = TUTOR6.read_text()
    calls = []
    code = codegen_c.converted(text, "tutor6.al", prepare=[lambda: calls.append(1)])
    assert calls == [1]
    assert code == codegen_c._convert(text, "tutor6.al")


def _stat(entry: Path) -> list[str]:
    """The fields of ``/proc/PID/stat`` after the command's name (the
    state first, the process group third); [] when the process is gone."""
    try:
        return (entry / "stat").read_text().rsplit(")", 1)[1].split()
    except (OSError, IndexError):
        return []


def _group(pgid: int) -> list[int]:
    """The processes of process group ``pgid`` (Linux's /proc)."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        fields = _stat(entry)
        if fields and int(fields[2]) == pgid:
            found.append(int(entry.name))
    return found


def _state(pid: int) -> str:
    """The state letter of process ``pid`` ('Z' for one that has ended and
    is not yet reaped; '' when it is gone)."""
    return (_stat(Path("/proc") / str(pid)) or [""])[0]


def _interrupted_at(tmp_path: Path, when: str) -> tuple[int, int, str, str] | None:
    """Run ``al2py code`` on the bicycle and send SIGINT to its process group
    ``when`` the copy converts, or later while the model is derived.  The
    group is stopped (SIGSTOP) first and the moment checked while nothing in
    it runs, so that a test process kept off the processors cannot send the
    interrupt late: None when the moment had passed (the run says nothing),
    else the process group, the status, standard error and output."""
    import signal
    import time

    script = ROOT / "tests" / "models" / "whipple_benchmark.al"
    proc = subprocess.Popen(
        [sys.executable, "-m", "al2py", "code", str(script), "-o", "out"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        deadline = time.monotonic() + 120
        while len(_group(proc.pid)) < 2:  # the copy is converting
            assert proc.poll() is None and time.monotonic() < deadline
            time.sleep(0.01)
        if when == "deriving":
            while len(_group(proc.pid)) > 1:  # the copy has sent its text
                assert proc.poll() is None and time.monotonic() < deadline
                time.sleep(0.01)
        os.killpg(proc.pid, signal.SIGSTOP)
        copies = len(_group(proc.pid)) - 1
        in_time = _state(proc.pid) not in ("Z", "") and (
            copies >= 1 if when == "converting" else copies == 0
        )
        os.killpg(proc.pid, signal.SIGINT)  # delivered as the group goes on
        os.killpg(proc.pid, signal.SIGCONT)
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    if not in_time:
        return None
    return proc.pid, proc.returncode, err, out


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc")
@pytest.mark.parametrize("when", ["converting", "deriving"])
def test_an_interrupt_ends_every_process_at_once(tmp_path, when):
    """Ctrl-C (SIGINT to the process group) while the copy converts, or
    later while the model is derived: ``al2py: interrupted``, status 130,
    no file written, no process left."""
    import time

    for attempt in range(5):  # a busy machine may pass the moment by
        folder = tmp_path / str(attempt)
        folder.mkdir()
        result = _interrupted_at(folder, when)
        if result is not None:
            break
    else:
        pytest.fail(f"the command was never caught {when} in 5 runs")
    pgid, *ended = result
    assert ended == [130, "al2py: interrupted\n", ""]
    assert not (folder / "out").exists()
    time.sleep(0.1)
    assert _group(pgid) == []
