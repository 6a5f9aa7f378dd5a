"""Research at interactive speed (issue 36): evaluate, sweep, linearize.

    python benchmarks/research.py               # everything
    python benchmarks/research.py --no-dask     # without the Dask cluster

On our bicycle script written as research scripts are
(tests/models/whipple_linear.al: ``AMAT = D(XDOT, X)`` in the script), in
one run, each figure against its baseline measured in turns with it:

* ``evaluate("AMAT", U6=...)``: the first call (it compiles the quantity)
  and later calls, against the substituting path that every call took
  before issue 36 (``jobs.run.evaluate_with_inputs``), medians of turns;
* a 101-speed ``sweep`` per point (after the first call, and in a fresh
  process including the compile), its eigenvalues against Meijaard et al.
  (2007) Table 2 at 4, 5 and 10 m/s, and the same sweep on a local Dask
  cluster of 2 worker processes (identical arrays?);
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


def _last_number(folder: Path, code: str) -> float:
    """The last number ``code`` prints, run by a new Python in ``folder``."""
    out = subprocess.run(
        [sys.executable, "-c", code],
        cwd=folder,
        capture_output=True,
        text=True,
        check=True,
    )
    return float(out.stdout.split()[-1])


def import_seconds(folder: Path, module: str) -> float:
    code = f"import time; t = time.perf_counter(); import {module}; print(time.perf_counter() - t)"
    return _last_number(folder, code)


def in_fresh_process(folder: Path, module: str, body: str) -> float:
    """Seconds of ``body`` (which sets ``seconds``) after importing ``module``
    in a new process."""
    return _last_number(
        folder, f"import {module} as m, numpy as np, time\n{body}\nprint(seconds)"
    )


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
    folder = Path(tempfile.mkdtemp(prefix="al2py_research_"))
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
    s = bike.sweep("AMAT", U6=-speeds / RR)
    sweep = time.perf_counter() - t
    ev = s.eigenvalues()
    worst = worst_table2({v: ev[int(round(v * 10))] for v in (4.0, 5.0, 10.0)})
    fresh = in_fresh_process(
        folder,
        "whipple_linear",
        "t = time.perf_counter(); m.sweep('AMAT', U6=-np.linspace(0, 10, 101) / 0.3)"
        "; seconds = time.perf_counter() - t",
    )
    rows.append(
        (
            "sweep of 101 speeds, per point (ms)",
            f"{sweep / 101 * 1e3:.3f}",
            f"before: {o * 1e3:.0f} ms a point (a loop of evaluate)",
        )
    )
    rows.append(
        (
            "  the same in a fresh process, compile included (ms/pt)",
            f"{fresh / 101 * 1e3:.1f}",
            f"{fresh:.2f} s in all",
        )
    )
    rows.append(("sweep eigenvalues vs Table 2 at 4, 5, 10 m/s", f"{worst:.1e}", ""))
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
