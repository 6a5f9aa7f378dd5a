"""Fuzz the generated modules, not just the converter (issue 12 acceptance).

Each mutant of a tutorial, golden or library script (the mutations of
``test_fuzz.py``, from a different range of seeds) is converted in-process;
when it converts, the module is imported and run in a fresh process
(``import mod; mod.main([...])``: transcript, Save files, CODE jobs) with a
time budget.  At every stage the only acceptable outcomes are success or exit
status 2 with a message naming the ``.al`` file (and, after conversion, the
line): never a Python traceback.

Mutants of the public corpus scripts (Moore's bicycles, DAS3, the BioMAC
gait models: read at run time from ``$ALMIRROR`` or ``../corpus``, skipped
when absent) are converted and run the same way, each in its own process.
Every child process runs under a memory cap (``resource.setrlimit``) and a
time limit: running out of either is a failure too, as is a ``MemoryError``
traceback.

By default a representative subset of :data:`N_DEFAULT` tutorial and
:data:`N_CORPUS_DEFAULT` corpus mutants runs (a minute or two on two cores).
The full acceptance runs are in the full tier::

    make test-full        # or: .venv/bin/python -m pytest --full tests/test_reliability_fuzz.py
"""

from __future__ import annotations

import io
import os
import random
import re
import subprocess
import sys
import threading
from concurrent.futures import ThreadPoolExecutor
from contextlib import redirect_stderr, redirect_stdout
from dataclasses import dataclass
from pathlib import Path

import pytest
from test_fuzz import SEEDS, CorpusScript, _workdir, capped, corpus_mutant
from test_fuzz import mutated_case as syntax_mutant

from al2py import cli

FIRST = 5000  # mutant numbers not used by test_fuzz.py
N_DEFAULT = 24
N_FULL = 500
N_CORPUS_DEFAULT = 8
N_CORPUS_FULL = 150
CORPUS_FIRST = 9000  # corpus mutant numbers not used by test_fuzz.py
CONVERT_TIMEOUT = 120.0  # seconds to convert one corpus mutant
WORKERS = max(1, min(4, os.cpu_count() or 1))
RUN_TIMEOUT = 120.0  # seconds per module process (symbolic work included)
BUDGET = {"AL2PY_MAX_SECONDS": "10", "AL2PY_MAX_EVALS": "300000"}

CONVERT_ERROR = re.compile(r"^fuzz_\w+\.al:\d+:\d+: error: \S")
RUN_ERROR = re.compile(r"^fuzz_\w+\.al:\d+: error: \S")
DRIVER = (
    "import sys, importlib\n"
    "mod = importlib.import_module(sys.argv[1])\n"
    "sys.exit(mod.main(['--outdir', 'out']))\n"
)


NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d*)?(?:[eE][-+]?\d+)?(?![\w.])")
WORD = re.compile(r"[A-Za-z_]\w*")
NUMBERS = ["0", "-1", "1e300", "1e-300", "1e8", "-5", "0.0", "100000", "2.5"]
OPERATORS = {"+": ["-", "*", "/"], "*": ["/", "^", "+"], "/": ["*", "^"], "-": ["+"]}


def semantic_mutant(index: int) -> tuple[Path, str]:
    """A mutant that still parses more often than not: numbers, names,
    operators and whole lines change, so the generated module has to cope."""
    rng = random.Random(7919 * index)
    seed = SEEDS[index % len(SEEDS)]
    text = seed.read_text(encoding="utf-8", errors="replace")
    for _ in range(rng.choice([1, 1, 2])):
        kind = rng.choice(["number", "number", "name", "operator", "lines"])
        if kind == "number" and (found := list(NUMBER.finditer(text))):
            m = rng.choice(found)
            text = text[: m.start()] + rng.choice(NUMBERS) + text[m.end() :]
        elif kind == "name" and (words := list(WORD.finditer(text))):
            m, other = rng.choice(words), rng.choice(words).group()
            text = text[: m.start()] + other + text[m.end() :]
        elif kind == "operator":
            spots = [i for i, c in enumerate(text) if c in OPERATORS]
            if spots:
                i = rng.choice(spots)
                text = text[:i] + rng.choice(OPERATORS[text[i]]) + text[i + 1 :]
        else:
            lines = text.split("\n")
            i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
            op = rng.choice(["dup", "drop", "exchange"])
            if op == "dup":
                lines.insert(j, lines[i])
            elif op == "drop":
                del lines[i]
            else:
                lines[i], lines[j] = lines[j], lines[i]
            text = "\n".join(lines)
    return seed, text


def mutated_case(index: int) -> tuple[Path, str]:
    """Three semantic mutants for every syntactic one of ``test_fuzz.py``."""
    return syntax_mutant(index) if index % 4 == 0 else semantic_mutant(index)


@dataclass
class Outcome:
    index: int
    stage: str  # "convert", "run", "timeout", "ok"
    problem: str = ""


def _fuzz(n: int, root: Path) -> list[Outcome]:
    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        # conversions run in-process one at a time; module processes in parallel
        return list(pool.map(lambda i: _case(i, root), range(FIRST, FIRST + n)))


def _verdict(outcomes: list[Outcome]) -> None:
    problems = [o.problem for o in outcomes if o.problem]
    assert not problems, "\n\n".join(problems[:5])
    ran = [o for o in outcomes if o.stage in ("run", "ok")]
    # the mutants exercise the generated modules, not only the parser
    assert len(ran) >= len(outcomes) // 4, [o.stage for o in outcomes]


_CHDIR_LOCK = threading.Lock()


def _case(index: int, root: Path) -> Outcome:
    with _CHDIR_LOCK:  # conversion changes directory: one at a time
        converted = _convert_only(index, root)
    if converted is not None:
        return converted
    return _run_only(index, root)


def _convert_only(index: int, root: Path) -> Outcome | None:
    seed, text = mutated_case(index)
    work = root / f"m{index}"
    work.mkdir()
    _workdir(work, seed)
    name = "fuzz_" + re.sub(r"\W", "_", seed.stem)
    path = work / f"{name}.al"
    path.write_text(text, encoding="utf-8")
    out, err = io.StringIO(), io.StringIO()
    cwd = os.getcwd()
    try:
        os.chdir(work)
        with redirect_stdout(out), redirect_stderr(err):
            status = cli.main([path.name, "-o", f"{name}.py"])
    finally:
        os.chdir(cwd)
    errors = err.getvalue()
    context = f"mutant {index} of {seed.name}"
    if "Traceback" in errors or status not in (0, 2):
        return Outcome(index, "convert", f"{context}: exit {status}\n{errors}\n{text}")
    if status == 2:
        if not CONVERT_ERROR.match(errors):
            return Outcome(index, "convert", f"{context}: unlocated\n{errors}")
        return Outcome(index, "convert")
    return None


def _run_only(index: int, root: Path) -> Outcome:
    seed, _ = mutated_case(index)
    name = "fuzz_" + re.sub(r"\W", "_", seed.stem)
    return _run_module(
        index, root / f"m{index}", name, f"mutant {index} of {seed.name}"
    )


def _run_module(index: int, work: Path, name: str, context: str) -> Outcome:
    """Import and run a converted mutant in a capped child process."""
    try:
        run = subprocess.run(
            [sys.executable, "-c", DRIVER, name],
            capture_output=True,
            text=True,
            cwd=work,
            timeout=RUN_TIMEOUT,
            env={**os.environ, **BUDGET},
            preexec_fn=capped,
        )
    except subprocess.TimeoutExpired:
        return Outcome(index, "timeout", f"{context}: ran past {RUN_TIMEOUT:g} s")
    stderr = run.stderr
    if "Traceback" in stderr or "MemoryError" in stderr or run.returncode not in (0, 2):
        return Outcome(
            index, "run", f"{context}: exit {run.returncode}\n{stderr[-3000:]}"
        )
    if run.returncode == 2:
        first = next((line for line in stderr.splitlines() if "error" in line), "")
        if not RUN_ERROR.match(first):
            return Outcome(index, "run", f"{context}: unlocated\n{stderr[-2000:]}")
        return Outcome(index, "run")
    return Outcome(index, "ok")


def _corpus_case(index: int, root: Path) -> Outcome:
    """Convert (in a capped child process) and run one corpus mutant."""
    script, text = corpus_mutant(index)
    work = root / f"c{index}"
    work.mkdir()
    name = "fuzz_" + re.sub(r"\W", "_", Path(script.name).stem)
    path = CorpusScript(script.name, text, script.macros).write(work, name)
    context = f"corpus mutant {index} of {script.name}"
    try:
        conv = subprocess.run(
            [sys.executable, "-m", "al2py", path.name, "-o", f"{name}.py"],
            capture_output=True,
            text=True,
            cwd=work,
            timeout=CONVERT_TIMEOUT,
            preexec_fn=capped,
        )
    except subprocess.TimeoutExpired:
        return Outcome(
            index, "timeout", f"{context}: converting took {CONVERT_TIMEOUT:g} s"
        )
    errors = conv.stderr
    if (
        "Traceback" in errors
        or "MemoryError" in errors
        or conv.returncode not in (0, 2)
    ):
        return Outcome(index, "convert", f"{context}: exit {conv.returncode}\n{errors}")
    if conv.returncode == 2:
        if not CONVERT_ERROR.match(errors):
            return Outcome(index, "convert", f"{context}: unlocated\n{errors}")
        return Outcome(index, "convert")
    return _run_module(index, work, name, context)


def _fuzz_corpus(n: int, root: Path) -> list[Outcome]:
    with ThreadPoolExecutor(max_workers=WORKERS) as pool:
        first = CORPUS_FIRST
        return list(pool.map(lambda i: _corpus_case(i, root), range(first, first + n)))


def test_generated_modules_survive_corpus_mutants(tmp_path, monkeypatch):
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    outcomes = _fuzz_corpus(N_CORPUS_DEFAULT, tmp_path)
    problems = [o.problem for o in outcomes if o.problem]
    assert not problems, "\n\n".join(problems[:5])


@pytest.mark.slow
@pytest.mark.full  # 150 corpus mutants take many minutes
def test_generated_modules_survive_many_corpus_mutants(tmp_path, monkeypatch):
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    outcomes = _fuzz_corpus(N_CORPUS_FULL, tmp_path)
    problems = [o.problem for o in outcomes if o.problem]
    stages = {
        s: sum(o.stage == s for o in outcomes)
        for s in ("convert", "run", "ok", "timeout")
    }
    print(f"\n{N_CORPUS_FULL} corpus mutants: {stages}")
    assert not problems, "\n\n".join(problems[:5])


def test_generated_modules_survive_mutants(tmp_path, monkeypatch):
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    _verdict(_fuzz(N_DEFAULT, tmp_path))


@pytest.mark.slow
@pytest.mark.full  # the 500-mutant run takes several minutes
def test_generated_modules_survive_500_mutants(tmp_path, monkeypatch):
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    outcomes = _fuzz(N_FULL, tmp_path)
    _verdict(outcomes)
    stages = {
        s: sum(o.stage == s for o in outcomes)
        for s in ("convert", "run", "ok", "timeout")
    }
    print(f"\n{N_FULL} mutants: {stages}")
    assert len(outcomes) == N_FULL
