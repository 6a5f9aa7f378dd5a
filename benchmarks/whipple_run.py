"""Whipple bicycle: ``run()`` against Autolev's own compiled program (issue 21).

    python benchmarks/whipple_run.py                    # this checkout
    python benchmarks/whipple_run.py --before ../main   # and another, side by side

Moore's ``models/Whipple/Whipple.al`` and the ``WhippleDynamics.c`` Autolev
generated from it are extracted at run time from the fetched repository
(``$ALMIRROR``, default ``../.mirror``; nothing is kept).  Both get the same
``.in``: the script's Inputs, and a motion of our choosing (5 s from upright
at 4.6 m/s, a self-stable speed, with a lean rate of 0.5 rad/s; 501 printed
rows; ``abserr = relerr = 1e-8``).  Printed:

* Autolev's program (``cc -O2``, as our right-hand side), best of 3;
* the import (derivation) of the converted script;
* our script's first ``run()`` in a fresh process on a cold cache (code
  generation and compilation included; the import is not counted);
* ``run()`` again in the same process (warm), best of 3, and the ratio to
  Autolev's program;
* the first ``run()`` of a fresh process whose compiled library is cached;
* the largest difference between the two programs' tables (both print the
  same 16 columns; Autolev prints 7 digits).

Our own ``tests/models/whipple_benchmark.al`` (with the same motion and a
``Code Dynamics()`` line appended) is timed the same way; Autolev wrote no
program for it.  With ``--before DIR`` every al2py figure is also measured
with the runtime of the checkout ``DIR`` (its ``src`` and ``runtime``), in
the same run (the two take turns, A B B A, best of two each), and the
ratios before/after are printed.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
import autolev_programs as ap  # noqa: E402

SCRIPT = "models/Whipple/Whipple.al"
PROGRAM = "models/Whipple/WhippleDynamics.c"
OURS = ROOT / "tests" / "models" / "whipple_benchmark.al"
SPEED = 4.6  # m/s, inside the benchmark bicycle's self-stable range
MOTION = {
    "TINITIAL": 0.0,
    "TFINAL": 5.0,
    "INTEGSTP": 0.01,
    "_PRINTINT": 1.0,
    "ABSERR": 1e-8,
    "RELERR": 1e-8,
}
OUR_LINES = """
Input TFINAL=5, INTEGSTP=0.01, ABSERR=1e-8, RELERR=1e-8
Input Q1=0, Q2=0, Q3=0, Q4=0, Q5=0, Q6=0, Q7=0, Q8=0
Input U4=0.5, U6={u6!r}, U7=0
Output T, Q4, Q7, U4, U6, U7
Code Dynamics() whipple_ours.c
"""

# ------------------------------------------------------------ child process

CHILD = r"""
import importlib.util, json, sys, time, contextlib
from al2py_runtime.jobs.run import run_job
path, program, overrides = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
spec = importlib.util.spec_from_file_location("whipple_model", path)
module = importlib.util.module_from_spec(spec)
start = time.perf_counter()
spec.loader.exec_module(module)
t_import = time.perf_counter() - start
job = next(j for j in module.al.numerics.jobs
           if j.filename and j.filename.lower().endswith(program.lower()))
times = []
for _ in range(4):
    start = time.perf_counter()
    result = run_job(job, overrides)
    times.append(time.perf_counter() - start)
tables = [t.data.tolist() if hasattr(t.data, "tolist") else list(map(list, t.data))
          for t in result.tables if not getattr(t, "encoded", False)]
print(json.dumps({"import": t_import, "first": times[0], "warm": min(times[1:]),
                  "tables": tables}))
"""


def _python(checkout: Path, args: list[str], cwd: Path, cache: Path | None = None):
    """``python ARGS`` with ``checkout``'s al2py and runtime."""
    env = dict(os.environ)
    env["PYTHONPATH"] = f"{checkout / 'src'}{os.pathsep}{checkout / 'runtime'}"
    if cache is not None:
        env["AL2PY_CACHE_DIR"] = str(cache)
    proc = subprocess.run(
        [sys.executable, *args], cwd=cwd, env=env, capture_output=True, text=True
    )
    if proc.returncode:
        raise RuntimeError(
            f"failed with {checkout}:\n{proc.stdout}{proc.stderr[-3000:]}"
        )
    return proc.stdout


def _child(checkout: Path, module: Path, program: str, overrides: dict, cache: Path):
    args = ["-c", CHILD, str(module), program, json.dumps(overrides)]
    out = _python(checkout, args, module.parent, cache)
    return json.loads(out.strip().splitlines()[-1])


def _convert(checkout: Path, script: Path) -> Path:
    out = script.with_name(f"{script.stem}_{abs(hash(str(checkout))) % 10**6}.py")
    _python(checkout, ["-m", "al2py", script.name, "-o", out.name], script.parent)
    return out


def measure(checkouts: list[Path], modules: dict, program: str, overrides: dict):
    """Per checkout: cold (fresh cache), warm (same process) and cached (new
    process, library cached).  The checkouts take turns (A B B A), and each
    figure is the better of its two turns, so a change of the machine's load
    during the run does not favour one of them."""
    out: dict[Path, dict] = {}
    order = checkouts + checkouts[::-1]
    for checkout in order:
        m = modules[checkout]
        with tempfile.TemporaryDirectory(prefix="al2py-cache-") as cache:
            cold = _child(checkout, m, program, overrides, Path(cache))
            cached = _child(checkout, m, program, overrides, Path(cache))
        new = {
            "import": min(cold["import"], cached["import"]),
            "cold": cold["first"],
            "warm": min(cold["warm"], cached["warm"]),
            "cached": cached["first"],
            "tables": cold["tables"],
        }
        old = out.get(checkout)
        if old is not None:
            new = {k: v if k == "tables" else min(v, old[k]) for k, v in new.items()}
        out[checkout] = new
    return out


# ------------------------------------------------------------------ Autolev


def autolev_seconds(program: Path, repeat: int = 3) -> tuple[float, list[np.ndarray]]:
    exe = program.with_suffix(".exe")
    subprocess.run(
        ["cc", "-O2", "-w", "-o", str(exe), str(program), "-lm"],
        check=True,
        capture_output=True,
    )
    best = float("inf")
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([str(exe)], cwd=program.parent, check=True, capture_output=True)
        best = min(best, time.perf_counter() - start)
    prog = ap.CProgram.parse(program.read_text(encoding="latin-1"))
    tables = []
    k = 1
    while prog.outfiles and (program.parent / (prog.outfiles % k)).exists():
        tables.append(ap.read_table(program.parent / (prog.outfiles % k)))
        k += 1
    return best, tables


def _moore_overrides(module: Path, prog: ap.CProgram) -> tuple[dict, dict]:
    """The ``.in`` values (Autolev's names) and the same as run() overrides."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("whipple_probe", module)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    job = ap.job_for(mod, PROGRAM)
    values = ap._values(prog, job, MOTION)
    values["U6"] = -SPEED / values["RR"]
    values["U4"] = 0.5
    return values, ap._overrides(prog, job, values)


def _row(label: str, after: dict, before: dict | None, autolev: float | None) -> None:
    def cell(key: str) -> str:
        text = f"{after[key]:7.3f}"
        if before is not None:
            text += f" (before {before[key]:7.3f}, {before[key] / after[key]:4.1f}x)"
        return text

    ratio = f"   warm / Autolev {after['warm'] / autolev:4.2f}" if autolev else ""
    print(f"  {label}")
    print(f"    import         {cell('import')} s")
    print(f"    first run()    {cell('cold')} s  (cold cache: generate + compile)")
    print(f"    cached run()   {cell('cached')} s  (new process, library cached)")
    print(f"    warm run()     {cell('warm')} s{ratio}")


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", type=Path, help="a checkout to compare with")
    args = parser.parse_args(argv)
    if shutil.which("cc") is None:
        print("skipped: no C compiler (cc)")
        return 0
    pair = ap.Pair("moorepants+AutolevToolKit", SCRIPT, PROGRAM, "dynamics", True)
    if not pair.git_dir().is_dir():
        print(f"skipped: {pair.git_dir()} not fetched")
        return 0
    checkouts = [ROOT] + ([args.before.resolve()] if args.before else [])
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"load average at start: {load:.1f} ({os.cpu_count()} cores)")
    with tempfile.TemporaryDirectory(prefix="al2py-whipple-") as tmp:
        work = Path(tmp)
        script, program = ap.extract(pair, work)
        prog = ap.CProgram.parse(program.read_text(encoding="latin-1"))
        modules = {c: _convert(c, script) for c in checkouts}
        values, overrides = _moore_overrides(modules[ROOT], prog)
        ap.write_in(prog, values, program.parent / prog.infile)
        t_autolev, theirs = autolev_seconds(program)
        print(
            f"Moore's Whipple.al, 5 s at {SPEED} m/s, 501 rows:"
            f" Autolev's WhippleDynamics.c {t_autolev:.4f} s (best of 3)"
        )
        results = measure(checkouts, modules, Path(PROGRAM).name, overrides)
        after = results[ROOT]
        before = results.get(checkouts[-1]) if args.before else None
        _row("al2py", after, before, t_autolev)
        worst = 0.0
        for ours, their in zip(after["tables"], theirs, strict=False):
            ours = np.asarray(ours, float)
            scale = np.maximum(np.max(np.abs(their), axis=0), 1.0)
            worst = max(worst, float(np.max(np.abs(ours - their) / scale)))
        print(f"    tables vs Autolev's: largest difference {worst:.1e} (relative)")

        ours_dir = work / "ours"
        ours_dir.mkdir()
        text = OURS.read_text() + OUR_LINES.format(u6=-SPEED / 0.3)
        (ours_dir / OURS.name).write_text(text)
        own = {c: _convert(c, ours_dir / OURS.name) for c in checkouts}
        res = measure(checkouts, own, "whipple_ours.c", {})
        print("Our whipple_benchmark.al, the same motion (no Autolev program):")
        _row(
            "al2py",
            res[ROOT],
            res.get(checkouts[-1]) if args.before else None,
            None,
        )
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"load average at end: {load:.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
