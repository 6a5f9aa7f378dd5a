"""Fuzz the command line with mutated tutorial scripts.

Every run must end in one of two ways: exit 0 with Python source that
compiles, or exit 2 with ``file:line:col: error: ...`` as the first stderr
line.  Exit 3 (an internal error) or a traceback is a failure.

The mutations are deterministic (fixed seed), so a failure is reproducible:
the test id names the case, and the failure message shows the mutated text.
"""

from __future__ import annotations

import io
import random
import re
import shutil
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest
import sympy
from conftest import GOLDEN, ROOT, SHARED

from al2py import cli

SEED = 20240611
N_CASES = 300
N_SUBPROCESS = 6

PY_NAMES = [
    "lambda",
    "class",
    "print",
    "import",
    "None",
    "__import__",
    "exec",
    "def",
    "return",
    "True",
    "eval",
    "open",
    "al",
    "t",
    "AUTOLEV",
    "AL_SOURCE",
    "main",
    "Matrix",
    "Workspace",
    "sympy",
    "__name__",
    "self",
]
INSERTS = list("+-*/^=:;,.()[]{}<>'\"%&#!$@~`\\ \t\n0123456789eEXxT_") + [
    "'",
    "''",
    ">",
    ">>",
    ":=",
    "+=",
    "^=",
    "1e400",
    "0.000000000000000001",
    "[1,2;3]",
    "&\n",
    '% """',
    "\u00e9",
    "\x00",
    "\r",
]
NAME = re.compile(r"[A-Za-z_]\w*")
ERROR_HEAD = re.compile(r"^.+:\d+:\d+: error: \S")


LIBRARY = ROOT / "tests" / "library"
SYMPY_EXAMPLES = Path(sympy.__file__).parent / "parsing" / "autolev" / "test-examples"


def _seed_files() -> list[Path]:
    """The tutorial, the golden cases, the multi-file library and SymPy's own
    Autolev examples: every command al2py supports appears in some seed."""
    files = sorted(SHARED.glob("*.al")) + sorted(GOLDEN.glob("*.al"))
    assert len(files) >= 10, "tutorial scripts not found"
    files += sorted(LIBRARY.rglob("*.al")) + sorted(SYMPY_EXAMPLES.rglob("*.al"))
    return files


SEEDS = _seed_files()


def _mutate_once(text: str, rng: random.Random) -> str:
    kind = rng.choice(
        ["delete", "insert", "swap", "truncate", "name", "names", "lines", "delete"]
    )
    n = len(text)
    if n == 0:
        return rng.choice(INSERTS)
    pos = rng.randrange(n)
    if kind == "delete":
        length = rng.choice([1, 1, 1, 2, 5, 20])
        return text[:pos] + text[pos + length :]
    if kind == "insert":
        return text[:pos] + rng.choice(INSERTS) + text[pos:]
    if kind == "swap" and n > 1:
        pos = min(pos, n - 2)
        return text[:pos] + text[pos + 1] + text[pos] + text[pos + 2 :]
    if kind == "truncate":
        return text[:pos]
    if kind in ("name", "names"):
        names = list(NAME.finditer(text))
        if not names:
            return text
        match = rng.choice(names)
        new = rng.choice(PY_NAMES)
        if kind == "name":  # one occurrence
            return text[: match.start()] + new + text[match.end() :]
        # every occurrence of that name, so declarations stay consistent
        pattern = re.compile(rf"\b{re.escape(match.group())}\b", re.IGNORECASE)
        return pattern.sub(lambda _: new, text)
    # "lines": duplicate, drop or exchange whole lines
    lines = text.split("\n")
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    op = rng.choice(["dup", "drop", "exchange"])
    if op == "dup":
        lines.insert(j, lines[i])
    elif op == "drop":
        del lines[i]
    else:
        lines[i], lines[j] = lines[j], lines[i]
    return "\n".join(lines)


def mutated_case(index: int) -> tuple[Path, str]:
    rng = random.Random(SEED * 1000 + index)
    seed = SEEDS[index % len(SEEDS)]
    text = seed.read_text(encoding="utf-8", errors="replace")
    for _ in range(rng.choice([1, 1, 2, 3, 5])):
        text = _mutate_once(text, rng)
    return seed, text


def _workdir(tmp_path: Path, seed: Path) -> Path:
    """A directory holding the seed's macro files, so ``POWER(...)`` still works."""
    for macro in list(seed.parent.glob("*.a")) + list(seed.parent.glob("*.r")):
        shutil.copy(macro, tmp_path / macro.name)
    return tmp_path


def _check(status, out: str, err: str, text: str) -> None:
    context = f"\n--- exit {status}; stderr:\n{err}\n--- input:\n{text}"
    assert "Traceback" not in out + err, context
    if status == 0:
        assert err == "", context
        compile(out, "<generated>", "exec")
    else:
        assert status == 2, context
        assert out == "", context
        first = err.splitlines()[0] if err else ""
        assert ERROR_HEAD.match(first), context


@pytest.mark.parametrize("index", range(N_CASES))
def test_mutated_script_in_process(index, tmp_path, monkeypatch):
    seed, text = mutated_case(index)
    work = _workdir(tmp_path, seed)
    path = work / f"fuzz_{seed.stem}.al"
    path.write_text(text, encoding="utf-8")
    monkeypatch.chdir(work)
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = cli.main([path.name])
    _check(status, out.getvalue(), err.getvalue(), text)


@pytest.mark.parametrize("index", range(0, N_CASES, N_CASES // N_SUBPROCESS))
def test_mutated_script_as_a_process(index, tmp_path):
    seed, text = mutated_case(index)
    work = _workdir(tmp_path, seed)
    path = work / f"fuzz_{seed.stem}.al"
    path.write_text(text, encoding="utf-8")
    run = subprocess.run(
        [sys.executable, "-m", "al2py", path.name],
        capture_output=True,
        text=True,
        cwd=work,
        timeout=300,
    )
    _check(run.returncode, run.stdout, run.stderr, text)


def test_mutations_are_deterministic_and_varied():
    first = [mutated_case(i)[1] for i in range(20)]
    again = [mutated_case(i)[1] for i in range(20)]
    assert first == again
    originals = {p.read_text(encoding="utf-8", errors="replace") for p in SEEDS}
    changed = [t for t in first if t not in originals]
    assert len(changed) >= 15
    assert len(set(first)) == len(first)
