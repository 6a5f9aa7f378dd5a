"""Every wait against the floor: ``import sympy.physics.mechanics`` (issue 35).

    python benchmarks/waits.py                 # Moore's Whipple and the corpus
    python benchmarks/waits.py --repeats 5     # more turns (median of each)
    python benchmarks/waits.py --no-corpus     # the Whipple bicycle only

The cheapest thing any sympy model does is ``import sympy.physics.mechanics``;
every figure here is a ratio to that floor, measured in the same run, the
floor taking its turn before each measurement (the machine may be shared:
only ratios measured side by side mean anything).  Printed too, as
"paired": the median over turns of each turn's ratio to the floor's turn
just before it (and, for the transcript and ``al2py code``, of that ratio
over the import's of the same round), which a change of the machine's
speed between turns a minute apart does not sway.  Each measurement is a
fresh process; printed are the median wall time and the median CPU time
(user + system, less sensitive to other processes) and their ratios to the
floor's.  Measured:

* Moore's Whipple bicycle (``models/Whipple/Whipple.al`` of the corpus):
  its import; its transcript (``python whipple.py --no-run``, also as a ratio
  to its import); ``al2py code Whipple.al`` (also to its import); its first
  ``run()`` of the Dynamics job with an empty compile cache (in the process
  that imported it, the import not counted; as a ratio to the import);
* each public corpus script: the 33 that ``../shared/corpus/manifest.tsv``
  lists (``.al`` and ``.AL`` alike, where ``extract.py`` wrote them:
  ``CORPUS/OWNER__NAME/<path>``), or without the manifest every ``.al`` or
  ``.AL`` file under CORPUS; the default corpus is ``../corpus`` next to
  the checkout, or ``$AL2PY_CORPUS``: converted in a copy of its own
  folder and imported.  A script that does not convert (an error of its
  own) or does not import is named, with its first or last error line.

The targets of issue 35 are printed beside: the bicycle's import at most 3x
the floor, its transcript and ``al2py code`` at most 1.5x its import, its
first run at most 1x its import, each corpus script at most 12x the floor.
Each converted module is compiled to bytecode once before its turns, as
Python's first import of it does (``cache_bytecode``); a script run as
``python whipple.py`` is compiled each time, as Python always does.
Nothing is kept (the third-party scripts are copied to a temporary folder).
"""

from __future__ import annotations

import argparse
import json
import os
import py_compile
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WHIPPLE = "moorepants__AutolevToolKit/models/Whipple/Whipple.al"
MANIFEST = ROOT.parent / "shared" / "corpus" / "manifest.tsv"
FLOOR = "import sympy.physics.mechanics"

RUN_CHILD = r"""
import json, sys, time
start = time.perf_counter(); cpu = time.process_time()
import whipple
t_import, c_import = time.perf_counter() - start, time.process_time() - cpu
start = time.perf_counter(); cpu = time.process_time()
whipple.al.numerics.run(job="WhippleDynamics")
print(json.dumps({"import": [t_import, c_import],
                  "run": [time.perf_counter() - start, time.process_time() - cpu]}))
"""


def timed(cmd: list[str], cwd: Path, env: dict | None = None) -> tuple[float, float]:
    """(wall, CPU) seconds of ``cmd`` as a fresh process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode:
        raise RuntimeError(proc.stderr.decode(errors="replace")[-2000:])
    cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    return wall, cpu


class Series:
    """Turns of one measurement, each after a turn of the floor.

    Besides each measurement's median, a turn is kept with the floor's turn
    just before it (:meth:`paired`): this machine's speed changes by up to
    twice for tens of seconds at a time, which two turns seconds apart
    share, and turns a minute apart often do not."""

    def __init__(self) -> None:
        self.rows: dict[str, list[tuple[float, float]]] = {}
        #: each measurement's turns as (its wall time, the floor's just before)
        self.pairs: dict[str, list[tuple[float, float]]] = {}

    def add(self, name: str, wall: float, cpu: float) -> None:
        self.rows.setdefault(name, []).append((wall, cpu))
        floor = self.rows.get("floor")
        if name != "floor" and floor:
            self.pairs.setdefault(name, []).append((wall, floor[-1][0]))

    def median(self, name: str) -> tuple[float, float]:
        turns = self.rows[name]
        return (
            statistics.median(w for w, _ in turns),
            statistics.median(c for _, c in turns),
        )

    def paired(self, name: str, to: str | None = None) -> float | None:
        """The median over turns of ``name``'s wall time over the floor's
        just before it; with ``to``, of that over the same for ``to``'s
        turn of the same round (None: no such turns)."""
        ours = self.pairs.get(name, [])
        if to is None:
            ratios = [w / f for w, f in ours]
        else:
            theirs = self.pairs.get(to, [])
            ratios = [
                (w / f) / (tw / tf)
                for (w, f), (tw, tf) in zip(ours, theirs, strict=False)
            ]
        return statistics.median(ratios) if ratios else None


def cache_bytecode(module: Path) -> None:
    """Compile a converted module into ``__pycache__`` once, as Python's
    first import of it does: every later import (a user's, and each turn
    here) reads the bytecode, as the floor reads sympy's.  Without this, an
    environment with ``PYTHONDONTWRITEBYTECODE`` set would compile the
    module on every turn (about 10 ms for the bicycle)."""
    py_compile.compile(str(module), doraise=True)


def floor_turn(series: Series, work: Path) -> None:
    series.add("floor", *timed([sys.executable, "-c", FLOOR], work))


def whipple(series: Series, corpus: Path, work: Path, repeats: int) -> None:
    folder = work / "whipple"
    folder.mkdir()
    shutil.copy(corpus / WHIPPLE, folder / "Whipple.al")
    al2py = [sys.executable, "-m", "al2py"]
    subprocess.run([*al2py, "Whipple.al", "-o", "whipple.py"], cwd=folder, check=True)
    cache_bytecode(folder / "whipple.py")
    for k in range(repeats):
        floor_turn(series, work)
        series.add(
            "Whipple import", *timed([sys.executable, "-c", "import whipple"], folder)
        )
        floor_turn(series, work)
        series.add(
            "Whipple transcript",
            *timed([sys.executable, "whipple.py", "--no-run"], folder),
        )
        floor_turn(series, work)
        series.add(
            "al2py code Whipple.al",
            *timed([*al2py, "code", "Whipple.al", "-o", f"code{k}"], folder),
        )
        floor_turn(series, work)
        with tempfile.TemporaryDirectory(dir=work) as cache:
            env = {**os.environ, "AL2PY_CACHE_DIR": cache}
            proc = subprocess.run(
                [sys.executable, "-c", RUN_CHILD],
                cwd=folder,
                env=env,
                capture_output=True,
                text=True,
                check=True,
            )
        times = json.loads(proc.stdout.strip().splitlines()[-1])
        series.add("first run() (import not counted)", *times["run"])
        series.add("  its import, same process", *times["import"])


def listed_scripts(corpus: Path) -> list[Path]:
    """The corpus scripts to measure: the manifest's (each where
    ``extract.py`` writes it), else every ``.al``/``.AL`` file of
    ``corpus``."""
    if MANIFEST.exists():
        rows = MANIFEST.read_text(encoding="utf-8").splitlines()[1:]
        found = []
        for row in rows:
            cols = row.split("\t")
            if len(cols) < 3:
                continue
            script = corpus / cols[1].replace("/", "__") / cols[2]
            if script.exists():
                found.append(script)
            else:
                print(f"  {cols[1]}/{cols[2]}: not extracted (skipped)")
        return sorted(found)
    return sorted(p for p in corpus.rglob("*") if p.suffix.lower() == ".al")


def corpus_scripts(series: Series, corpus: Path, work: Path) -> list[str]:
    names = []
    for k, script in enumerate(listed_scripts(corpus)):
        folder = work / f"corpus{k}"
        folder.mkdir()
        for f in script.parent.iterdir():  # the script's own folder
            if f.is_file() and f.stat().st_size < 5_000_000:
                shutil.copy(f, folder / f.name)
        module = f"m{k}"
        name = str(script.relative_to(corpus))
        convert = subprocess.run(
            [sys.executable, "-m", "al2py", script.name, "-o", f"{module}.py"],
            cwd=folder,
            capture_output=True,
        )
        if convert.returncode:
            first = convert.stderr.decode(errors="replace").strip().splitlines()
            print(
                f"  {name}: does not convert (exit {convert.returncode}):"
                f" {(first or ['?'])[0][:100]}"
            )
            continue
        cache_bytecode(folder / f"{module}.py")
        floor_turn(series, work)
        try:
            series.add(name, *timed([sys.executable, "-c", f"import {module}"], folder))
        except RuntimeError as exc:
            last = str(exc).strip().splitlines()[-1:] or ["?"]
            print(f"  {name}: does not import: {last[0][:100]}")
            continue
        names.append(name)
    return names


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument(
        "--corpus",
        type=Path,
        default=Path(os.environ.get("AL2PY_CORPUS", ROOT.parent / "corpus")),
    )
    parser.add_argument("--no-corpus", action="store_true")
    args = parser.parse_args(argv)
    if not (args.corpus / WHIPPLE).exists():
        print(f"needs the corpus ({args.corpus / WHIPPLE} not found)")
        return 1
    series = Series()
    with tempfile.TemporaryDirectory(prefix="al2py-waits-") as tmp:
        work = Path(tmp)
        whipple(series, args.corpus, work, args.repeats)
        scripts = [] if args.no_corpus else corpus_scripts(series, args.corpus, work)
    fw, fc = series.median("floor")
    iw, ic = series.median("Whipple import")
    print(f"\nfloor: {FLOOR}: {fw:.2f} s wall, {fc:.2f} s CPU (median)\n")
    print(f"{'':44} {'wall':>7} {'x floor':>8} {'CPU':>7} {'x floor':>8}  target")
    targets = {
        "Whipple import": "<= 3x floor",
        "Whipple transcript": "<= 1.5x import",
        "al2py code Whipple.al": "<= 1.5x import",
        "first run() (import not counted)": "<= 1x import",
    }
    for name in [*targets, "  its import, same process"]:
        w, c = series.median(name)
        line = f"{name:44} {w:7.2f} {w / fw:8.2f} {c:7.2f} {c / fc:8.2f}"
        if name in targets and name != "Whipple import":
            line += f"  {w / iw:.2f}x import wall, {c / ic:.2f}x CPU"
            line += f" ({targets[name]})"
        elif name in targets:
            line += f"  ({targets[name]})"
        print(line)
    print(
        "\npaired (wall): the median over turns of each turn's ratio to the"
        " floor's turn just before it,\nand to the import, of the two such"
        " ratios in one round:"
    )
    first_run = "first run() (import not counted)"
    for name in targets:
        if name == first_run:
            # measured in the process that imported: its own import's turn
            runs = series.rows[name]
            imports = series.rows["  its import, same process"]
            ratio = statistics.median(
                r / i for (r, _), (i, _) in zip(runs, imports, strict=True)
            )
            print(f"  {name:42} {ratio:.2f}x its import ({targets[name]})")
            continue
        to_floor = series.paired(name)
        line = f"  {name:42} {to_floor:.2f}x floor"
        if name != "Whipple import":
            line += f", {series.paired(name, 'Whipple import'):.2f}x import"
        print(f"{line} ({targets[name]})")
    if scripts:
        print(f"\ncorpus scripts' imports ({len(scripts)}; target <= 12x floor):")
        for name in sorted(scripts, key=lambda n: -series.median(n)[1]):
            w, c = series.median(name)
            paired = series.paired(name)
            print(
                f"  {name[:60]:60} {w:7.2f} {w / fw:6.1f}x {c:7.2f} {c / fc:6.1f}x"
                f"  paired {paired:5.1f}x"
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
