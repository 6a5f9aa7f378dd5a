"""Fuzz the command line with mutated tutorial scripts.

Every run must end in one of two ways: exit 0 with Python source that
compiles, or exit 2 with ``file:line:col: error: ...`` as the first stderr
line.  Exit 3 (an internal error) or a traceback is a failure.

The mutations are deterministic (fixed seed), so a failure is reproducible:
the test id names the case, and the failure message shows the mutated text.
"""

from __future__ import annotations

import functools
import io
import os
import random
import re
import shutil
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from dataclasses import dataclass
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


# ------------------------------------------------ the public corpus (issue 32)

#: each fuzz child process may use this much address space: a mutant that
#: would exhaust memory must stop with a located message, not take the machine
MEMORY_CAP = 3 * 1024**3
N_CORPUS = 8  # corpus mutants converted by default (each in a capped process)
N_CORPUS_FULL = 200
CORPUS_SEED = 32


@dataclass(frozen=True)
class CorpusScript:
    """A public research script, read at run time (never committed)."""

    name: str  # repository and path, for messages
    text: str
    #: (file name, text) of the macro files (.a, .r) in its folder
    macros: tuple[tuple[str, str], ...] = ()

    def write(self, folder: Path, stem: str) -> Path:
        for name, text in self.macros:
            (folder / name).write_text(text, encoding="utf-8")
        path = folder / f"{stem}.al"
        path.write_text(self.text, encoding="utf-8")
        return path


def _git(git_dir: Path, *args: str) -> bytes:
    return subprocess.run(
        ["git", "--git-dir", str(git_dir), *args],
        capture_output=True,
        check=True,
        timeout=120,
    ).stdout


def _from_mirror(root: Path) -> list[CorpusScript]:
    """The ``.al`` scripts of every repository fetched under ``root``."""
    out = []
    for git_dir in sorted(root.glob("*/repo")):
        try:
            files = _git(git_dir, "ls-tree", "-r", "--name-only", "HEAD").decode()
        except (OSError, subprocess.SubprocessError):
            continue
        names = files.splitlines()
        for path in names:
            if not path.lower().endswith(".al"):
                continue
            folder = str(Path(path).parent)
            macros = tuple(
                (Path(m).name, _git(git_dir, "show", f"HEAD:{m}").decode("latin-1"))
                for m in names
                if str(Path(m).parent) == folder and m.lower().endswith((".a", ".r"))
            )
            text = _git(git_dir, "show", f"HEAD:{path}").decode("latin-1")
            out.append(CorpusScript(f"{git_dir.parent.name}/{path}", text, macros))
    return out


def _from_folder(root: Path) -> list[CorpusScript]:
    """The ``.al`` scripts of an extracted corpus folder."""
    out = []
    for path in sorted(p for p in root.rglob("*") if p.suffix.lower() == ".al"):
        macros = tuple(
            (m.name, m.read_text(encoding="latin-1"))
            for m in sorted(path.parent.iterdir())
            if m.suffix.lower() in (".a", ".r") and m.is_file()
        )
        text = path.read_text(encoding="latin-1")
        out.append(CorpusScript(str(path.relative_to(root)), text, macros))
    return out


@functools.cache
def corpus_scripts() -> tuple[CorpusScript, ...]:
    """The public corpus: the repositories fetched under ``$ALMIRROR`` (or
    ``../.mirror``), else the extracted ``../corpus``; empty when neither is
    here."""
    mirror = Path(os.environ.get("ALMIRROR") or ROOT.parent / ".mirror")
    found = _from_mirror(mirror) if mirror.is_dir() else []
    if not found and (ROOT.parent / "corpus").is_dir():
        found = _from_folder(ROOT.parent / "corpus")
    return tuple(found)


#: corpus scripts whose own, unmutated module runs past the fuzz's time
#: limit, so that every mutant would too: BICYCLE12.AL's ZERO=FR()+FRSTAR()
#: takes more than 5 minutes (a known performance gap, not a mutant's fault)
SLOW_SEEDS = ("MAE-223/BicycleDynamicsProject/AutolevSRC/BICYCLE12.AL",)


def corpus_mutant(index: int) -> tuple[CorpusScript, str]:
    """A corpus script mutated like the tutorial's (syntax, or for odd
    indexes numbers, names, operators and lines)."""
    scripts = [s for s in corpus_scripts() if not s.name.endswith(SLOW_SEEDS)]
    if not scripts:
        pytest.skip("needs the public corpus ($ALMIRROR or ../corpus)")
    rng = random.Random(CORPUS_SEED * 100_003 + index)
    script = scripts[rng.randrange(len(scripts))]
    text = script.text
    for _ in range(rng.choice([1, 1, 2, 3])):
        text = _mutate_once(text, rng) if index % 2 == 0 else _semantic(text, rng)
    return script, text


_NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d*)?(?:[eE][-+]?\d+)?(?![\w.])")
_NUMBERS = ["0", "-1", "1e300", "1e-300", "1e8", "-5", "0.0", "100000", "2.5"]
_OPERATORS = {"+": ["-", "*", "/"], "*": ["/", "^", "+"], "/": ["*", "^"], "-": ["+"]}


def _semantic(text: str, rng: random.Random) -> str:
    """One change that keeps the text parsing more often than not."""
    kind = rng.choice(["number", "number", "name", "operator", "lines"])
    if kind == "number" and (found := list(_NUMBER.finditer(text))):
        m = rng.choice(found)
        return text[: m.start()] + rng.choice(_NUMBERS) + text[m.end() :]
    if kind == "name" and (words := list(NAME.finditer(text))):
        m, other = rng.choice(words), rng.choice(words).group()
        return text[: m.start()] + other + text[m.end() :]
    if kind == "operator":
        spots = [i for i, c in enumerate(text) if c in _OPERATORS]
        if spots:
            i = rng.choice(spots)
            return text[:i] + rng.choice(_OPERATORS[text[i]]) + text[i + 1 :]
        return text
    return _mutate_once(text, random.Random(rng.random())) if text else text


def capped() -> None:
    """``preexec_fn`` of a fuzz child: at most :data:`MEMORY_CAP` bytes."""
    import resource

    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))


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


def _convert_corpus_mutant(index: int, tmp_path: Path) -> None:
    script, text = corpus_mutant(index)
    path = CorpusScript(script.name, text, script.macros).write(tmp_path, "fuzz")
    try:
        run = subprocess.run(
            [sys.executable, "-m", "al2py", path.name],
            capture_output=True,
            text=True,
            cwd=tmp_path,
            timeout=CORPUS_TIMEOUT,
            preexec_fn=capped,
        )
    except subprocess.TimeoutExpired:
        pytest.fail(f"mutant {index} of {script.name}: past {CORPUS_TIMEOUT} s")
    context = f"mutant {index} of {script.name}"
    assert "MemoryError" not in run.stderr, context
    _check(run.returncode, run.stdout, run.stderr, f"({context})")


CORPUS_TIMEOUT = 120  # seconds to convert one corpus mutant


@pytest.mark.parametrize("index", range(N_CORPUS))
def test_mutated_corpus_script_converts_or_stops_located(index, tmp_path):
    _convert_corpus_mutant(index, tmp_path)


@pytest.mark.slow
@pytest.mark.full  # 200 corpus conversions take many minutes
@pytest.mark.parametrize("index", range(N_CORPUS, N_CORPUS + N_CORPUS_FULL))
def test_mutated_corpus_script_full(index, tmp_path):
    _convert_corpus_mutant(index, tmp_path)


def test_mutations_are_deterministic_and_varied():
    first = [mutated_case(i)[1] for i in range(20)]
    again = [mutated_case(i)[1] for i in range(20)]
    assert first == again
    originals = {p.read_text(encoding="utf-8", errors="replace") for p in SEEDS}
    changed = [t for t in first if t not in originals]
    assert len(changed) >= 15
    assert len(set(first)) == len(first)
