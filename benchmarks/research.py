"""Research at interactive speed (issue 36): evaluate, sweep, linearize.

    python benchmarks/research.py               # everything
    python benchmarks/research.py --no-dask     # without the Dask cluster

On our bicycle script written as research scripts are
(tests/models/whipple_linear.al: ``AMAT = D(XDOT, X)`` in the script), in
one run, each figure against its baseline measured in turns with it:

* ``evaluate("AMAT", U6=...)``: the first call (it compiles the quantity)
  and later calls, against the substituting path that every call took
  before issue 36 (``jobs.run.evaluate_with_inputs``), medians of turns;
* a 101-speed ``sweep`` per point (its numpy tape made, against the
  compiled function), its eigenvalues against Meijaard et al. (2007)
  Table 2 at 4, 5 and 10 m/s, and the same sweep on a local Dask cluster
  of 2 worker processes (identical arrays?);
* the 101-speed sweep and the first ``evaluate()`` in a fresh process (as a
  user meets them: ``import whipple_linear; whipple_linear.sweep(...)``),
  with an empty cache folder and with a warm one, each against the path
  before the tape and the disk cache (the quantity compiled from its
  printed C: ``quantities.compile_quantity``), in alternating turns;
* ``linearize()`` of the Dynamics job against the script's import time
  (``python -c "import whipple_linear"``, turns alternated), also for the
  script without its ``D()`` lines (linearize then derives every partial
  derivative itself);
* a 200-run sweep of tutor6's job over two Inputs on a process pool against
  200 single ``run()`` calls (the same tables?).

The machine may be shared: figures are ratios within one run.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from al2py import convert

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
BICYCLE = ROOT / "tests" / "models" / "whipple_linear.al"
TUTOR6 = ROOT / "examples" / "tutor6.al"
RR = 0.3
sys.path.insert(0, str(ROOT / "tests"))
from test_whipple import TABLE2  # noqa: E402


def write(path: Path, folder: Path, text: str | None = None, stem: str = "") -> Path:
    result = convert(text if text is not None else path.read_text(), str(path))
    out = folder / f"{stem or result.module}.py"
    out.write_text(result.code)
    return out


def _last_number(folder: Path, code: str, cache: Path | None = None) -> float:
    """The last number ``code`` prints, run by a new Python in ``folder``
    (``cache``: its AL2PY_CACHE_DIR, else this process's)."""
    env = dict(os.environ)
    if cache is not None:
        env["AL2PY_CACHE_DIR"] = str(cache)
    out = subprocess.run(
        [sys.executable, "-W", "ignore", "-c", code],
        cwd=folder,
        capture_output=True,
        text=True,
        check=True,
        env=env,
    )
    return float(out.stdout.split()[-1])


def import_seconds(folder: Path, module: str) -> float:
    code = f"import time; t = time.perf_counter(); import {module}; print(time.perf_counter() - t)"
    return _last_number(folder, code)


def in_fresh_process(
    folder: Path, module: str, body: str, cache: Path | None = None
) -> float:
    """Seconds of ``body`` (which sets ``seconds``) after importing ``module``
    in a new process (``cache``: its AL2PY_CACHE_DIR)."""
    return _last_number(
        folder,
        f"import {module} as m, numpy as np, time\n{body}\nprint(seconds)",
        cache,
    )


#: a 101-speed sweep of AMAT as a user meets it: ``sweep()`` in a new process
NEW_SWEEP = """
t = time.perf_counter()
m.sweep("AMAT", U6=-np.linspace(0, 10, 101) / 0.3)
seconds = time.perf_counter() - t
"""

#: the first ``evaluate()`` of AMAT in a new process
NEW_EVALUATE = """
t = time.perf_counter()
m.evaluate("AMAT", U6=-5 / 0.3)
seconds = time.perf_counter() - t
"""

#: the path before the tape and the disk cache (in the same run): the
#: quantity compiled from its printed C (numeric form, printing, the
#: compiler unless the printed text's library is cached), then evaluated
OLD = """
from al2py_runtime.jobs.quantities import compile_quantity, evaluate_compiled
from al2py_runtime.jobs.quantities import split_given
from al2py_runtime.jobs.run import evaluate_with_inputs, input_values
from al2py_runtime.jobs.sweep import sweep_quantity
given = {given}
t = time.perf_counter()
job = m.al.numerics._make_job("ALGEBRAIC", line=None)
value = m.al.value("AMAT")
settable, free = split_given(job, given)
keep = input_values(job, dict.fromkeys(settable, 0.0), False)[1]
plan = compile_quantity(job, value, "AMAT", frozenset(free), frozenset(keep))
exact = lambda p: evaluate_with_inputs(job, value, "AMAT", p)
{what}(job, plan, given, exact)
seconds = time.perf_counter() - t
"""
OLD_SWEEP = OLD.format(
    given='{"U6": -np.linspace(0, 10, 101) / 0.3}', what="sweep_quantity"
)
OLD_EVALUATE = OLD.format(given='{"U6": -5 / 0.3}', what="evaluate_compiled")


def fresh_turns(
    folder: Path, turns: int, bodies: dict[str, str], warm: Path | None
) -> dict[str, float]:
    """Median seconds of each body in new processes, in alternating turns:
    each with an empty cache folder of its own (``warm`` None), else all
    with the folder ``warm``."""
    times: dict[str, list[float]] = {k: [] for k in bodies}
    for _ in range(turns):
        for key, body in bodies.items():
            cache = warm or Path(tempfile.mkdtemp(prefix="cache_", dir=folder))
            times[key].append(in_fresh_process(folder, "whipple_linear", body, cache))
    return {k: statistics.median(v) for k, v in times.items()}


def worst_table2(ev_by_speed: dict[float, np.ndarray]) -> float:
    worst = 0.0
    for v, ev in ev_by_speed.items():
        for w in TABLE2[v]:
            worst = max(worst, float(np.min(np.abs(np.asarray(ev) - w))))
    return worst


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--no-dask", action="store_true")
    parser.add_argument("--turns", type=int, default=3)
    args = parser.parse_args()
    # every file of the run (modules, caches) lives in one folder, removed
    # at the end
    with tempfile.TemporaryDirectory(prefix="al2py_research_") as tmp:
        measure(args, Path(tmp))


def measure(args: argparse.Namespace, folder: Path) -> None:
    """Every figure of the benchmark, with its files in ``folder``."""
    # this process starts from an empty cache of its own (the figures
    # below do not depend on what an earlier run left)
    os.environ["AL2PY_CACHE_DIR"] = str(folder / "cache")
    sys.path.insert(0, str(folder))
    write(BICYCLE, folder)
    plain = "\n".join(
        ln
        for ln in BICYCLE.read_text().splitlines()
        if not ln.startswith(("AMAT", "BMAT"))
    )
    write(BICYCLE, folder, plain, stem="whipple_plain")
    write(TUTOR6, folder)
    rows: list[tuple[str, str, str]] = []

    # ---------------------------------------------------- import and linearize
    imports, lins, plain_imports, plain_lins = [], [], [], []
    body = "t = time.perf_counter(); m.linearize(); seconds = time.perf_counter() - t"
    for _ in range(args.turns):
        imports.append(import_seconds(folder, "whipple_linear"))
        lins.append(in_fresh_process(folder, "whipple_linear", body))
        plain_imports.append(import_seconds(folder, "whipple_plain"))
        plain_lins.append(in_fresh_process(folder, "whipple_plain", body))
    imp, lin = statistics.median(imports), statistics.median(lins)
    pimp, plin = statistics.median(plain_imports), statistics.median(plain_lins)
    rows.append(("import whipple_linear (s)", f"{imp:.2f}", f"turns {imports}"))
    rows.append(("linearize() (s), ratio to import", f"{lin:.2f}", f"{lin / imp:.2f}x"))
    rows.append(("import, script without D() (s)", f"{pimp:.2f}", ""))
    rows.append(("its linearize() (s), ratio", f"{plin:.2f}", f"{plin / pimp:.2f}x"))

    import whipple_linear as bike
    from al2py_runtime.jobs.run import evaluate_with_inputs

    lin5 = bike.linearize(U6=-5 / RR)
    rows.append(
        (
            "linearize() eigenvalues vs Table 2 at 5 m/s",
            f"{worst_table2({5.0: lin5.eigenvalues()}):.1e}",
            "",
        )
    )

    # ------------------------------------------------------------- evaluate
    t = time.perf_counter()
    bike.evaluate("AMAT", U6=-5 / RR)
    first = time.perf_counter() - t
    job = bike.al.numerics._make_job("ALGEBRAIC")  # noqa: SLF001 - the old path
    value = bike.al.value("AMAT")
    zeros = {"TPHI": 0, "TDELTA": 0, "TTHETAR": 0}  # the old path needed them
    new, old = [], []
    for k in range(args.turns * 3):
        u6 = -(4 + k * 0.1) / RR
        t = time.perf_counter()
        for _ in range(20):
            a = bike.evaluate("AMAT", U6=u6)
        new.append((time.perf_counter() - t) / 20)
        t = time.perf_counter()
        b = evaluate_with_inputs(job, value, "AMAT", {"U6": u6, **zeros})
        old.append(time.perf_counter() - t)
        assert np.allclose(a, b, rtol=1e-9, atol=1e-12)
    n, o = statistics.median(new), statistics.median(old)
    rows.append(("evaluate AMAT: first call (compiles) (s)", f"{first:.2f}", ""))
    rows.append(
        (
            "evaluate AMAT: a later call (ms)",
            f"{n * 1e3:.3f}",
            f"before: {o * 1e3:.0f} ms a call ({o / n:.0f}x)",
        )
    )

    # ---------------------------------------------------------------- sweep
    speeds = np.linspace(0, 10, 101)
    t = time.perf_counter()
    s = bike.sweep("AMAT", U6=-speeds / RR)  # makes the numpy tape
    tape_first = time.perf_counter() - t
    bike.sweep("AMAT", U6=-speeds / RR, backend="c")  # its plan made once
    again, compiled = [], []
    for _ in range(args.turns):
        t = time.perf_counter()
        s = bike.sweep("AMAT", U6=-speeds / RR)
        again.append(time.perf_counter() - t)
        t = time.perf_counter()
        c = bike.sweep("AMAT", U6=-speeds / RR, backend="c")
        compiled.append(time.perf_counter() - t)
    sweep, csweep = statistics.median(again), statistics.median(compiled)
    ev = s.eigenvalues()
    worst = worst_table2({v: ev[int(round(v * 10))] for v in (4.0, 5.0, 10.0)})
    scale = np.maximum(np.abs(s.values), np.abs(c.values))
    gap = np.abs(s.values - c.values) / np.where(scale > 0, scale, 1)
    rows.append(
        (
            "sweep of 101 speeds, per point (ms)",
            f"{sweep / 101 * 1e3:.3f}",
            f"its numpy tape; backend='c': {csweep / 101 * 1e3:.3f} ms;"
            f" before: {o * 1e3:.0f} ms a point (a loop of evaluate)",
        )
    )
    rows.append(
        (
            "  first sweep in this process (makes the tape) (ms/pt)",
            f"{tape_first / 101 * 1e3:.2f}",
            f"tape vs compiled: largest relative difference {gap.max():.1e}",
        )
    )
    rows.append(("sweep eigenvalues vs Table 2 at 4, 5, 10 m/s", f"{worst:.1e}", ""))

    # ------------------------------------------- fresh processes (a user's)
    timed = {
        "new": NEW_SWEEP,
        "old": OLD_SWEEP,
        "new_e": NEW_EVALUATE,
        "old_e": OLD_EVALUATE,
    }
    empty = fresh_turns(folder, args.turns, timed, None)
    warm_dir = Path(tempfile.mkdtemp(prefix="cache_", dir=folder))
    in_fresh_process(folder, "whipple_linear", NEW_EVALUATE, warm_dir)  # warms
    warm = fresh_turns(folder, args.turns, timed, warm_dir)
    for label, got in (("empty cache", empty), ("warm disk cache", warm)):
        rows.append(
            (
                f"fresh process, {label}: 101-speed sweep (ms/pt)",
                f"{got['new'] / 101 * 1e3:.1f}",
                f"{got['new']:.2f} s in all; before: {got['old'] / 101 * 1e3:.1f}"
                f" ms/pt ({got['old']:.2f} s, {got['old'] / got['new']:.1f}x)",
            )
        )
    for label, got in (("empty cache", empty), ("warm disk cache", warm)):
        rows.append(
            (
                f"fresh process, {label}: first evaluate() (s)",
                f"{got['new_e']:.2f}",
                f"before: {got['old_e']:.2f} s ({got['old_e'] / got['new_e']:.1f}x)",
            )
        )
    if not args.no_dask:
        try:
            import distributed
        except ImportError:
            rows.append(("Dask cluster", "skipped", "pip install 'al2py[dask]'"))
        else:
            with (
                distributed.LocalCluster(
                    n_workers=2, threads_per_worker=1, dashboard_address=None
                ) as cluster,
                distributed.Client(cluster) as client,
            ):
                t = time.perf_counter()
                d = bike.sweep("AMAT", U6=-speeds / RR, executor=client.get_executor())
                dt = time.perf_counter() - t
            same = np.array_equal(d.values, s.values)
            rows.append(
                (
                    "the sweep on LocalCluster(2 workers) (s)",
                    f"{dt:.2f}",
                    f"identical arrays: {same}",
                )
            )

    # ---------------------------------------------------------- job sweeps
    import tutor6

    qa, k = np.linspace(10, 40, 10), np.linspace(100, 300, 20)
    t = time.perf_counter()
    singles = [tutor6.run(QA=float(a), K=float(b)) for a in qa for b in k]
    single = time.perf_counter() - t
    with ProcessPoolExecutor(2) as pool:
        t = time.perf_counter()
        swept = tutor6.sweep(job="tutor6", QA=qa, K=k, executor=pool)
        pooled = time.perf_counter() - t
    same = all(
        np.array_equal(x.tables[0].data, y.tables[0].data)
        for x, y in zip(swept.results.reshape(-1), singles, strict=True)
    )
    rows.append(
        (
            "tutor6: 200 runs on a pool of 2 (s)",
            f"{pooled:.2f}",
            f"200 run() calls: {single:.2f} s; same tables: {same}",
        )
    )

    width = max(len(r[0]) for r in rows)
    for name, value, note in rows:
        print(f"{name:<{width}}  {value:>9}  {note}")


if __name__ == "__main__":
    main()
