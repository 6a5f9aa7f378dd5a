"""Benchmark: al2py on an n-link pendulum against the same model written by hand.

    python benchmarks/run.py            # n = 4, 8, 16
    python benchmarks/run.py 4 8        # chosen sizes

For each n it prints conversion time, import (derivation) time next to
``KanesMethod`` by hand, ``run()`` time for 10 s of simulation (rtol = atol =
1e-7) next to hand-written ``lambdify(cse, math)`` + ``numpy.linalg.solve`` +
``solve_ivp``, and microseconds per right-hand-side call.  Targets: import
within 1.2x of KanesMethod; ``run()`` no slower than the hand-written code.
"""

from __future__ import annotations

import importlib.util
import math
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import al2py_runtime  # noqa: E402,F401  (library import is not model derivation)
from pendulum import autolev_source, hand_derive, hand_simulate  # noqa: E402

from al2py import convert  # noqa: E402


def _timed(fn, *args):
    start = time.perf_counter()
    out = fn(*args)
    return out, time.perf_counter() - start


def _import(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def measure(n: int, workdir: Path) -> dict[str, float]:
    source = autolev_source(n)
    (workdir / f"pendulum{n}.al").write_text(source)
    result, t_convert = _timed(convert, source, str(workdir / f"pendulum{n}.al"))
    path = workdir / f"pendulum{n}.py"
    path.write_text(result.code)
    # Best of three for every timing: the machine may be busy with other work.
    module, t_import = min(
        (_timed(_import, path, f"pendulum{n}_{k}") for k in range(3)),
        key=lambda r: r[1],
    )
    (kane, q, u, consts), t_kane = min(
        (_timed(hand_derive, n) for _ in range(3)), key=lambda r: r[1]
    )

    def fresh_run():
        for job in module.al.numerics.jobs:  # each run() regenerates its functions
            job.cache.clear()
        return module.run()

    run, t_run = min((_timed(fresh_run) for _ in range(3)), key=lambda r: r[1])
    (states, calls), t_hand = min(
        (_timed(hand_simulate, kane, q, u, consts) for _ in range(3)),
        key=lambda r: r[1],
    )
    ours_final = [float(run[f"Q{k}"][-1]) for k in range(1, n + 1)]
    hand_final = [math.degrees(x) for x in states[:n, -1]]
    drift = max(abs(a - b) for a, b in zip(ours_final, hand_final, strict=True))
    nfev = run.nfev
    return {
        "n": n,
        "convert_s": t_convert,
        "import_s": t_import,
        "kanesmethod_s": t_kane,
        "run_s": t_run,
        "hand_run_s": t_hand,
        "us_per_call": 1e6 * t_run / max(nfev, 1),
        "hand_us_per_call": 1e6 * t_hand / max(calls, 1),
        "max_angle_difference_deg": drift,
    }


def main(argv: list[str]) -> int:
    sizes = [int(a) for a in argv] or [4, 8, 16]
    header = (
        f"{'n':>3} {'convert s':>10} {'import s':>9} {'Kanes s':>8} {'ratio':>6} "
        f"{'run s':>7} {'hand s':>7} {'ratio':>6} {'us/call':>8} {'hand us':>8} {'dQ deg':>8}"
    )
    print(header)
    print("-" * len(header))
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            r = measure(n, Path(tmp))
            print(
                f"{r['n']:>3} {r['convert_s']:>10.2f} {r['import_s']:>9.2f} "
                f"{r['kanesmethod_s']:>8.2f} {r['import_s'] / r['kanesmethod_s']:>6.2f} "
                f"{r['run_s']:>7.2f} {r['hand_run_s']:>7.2f} "
                f"{r['run_s'] / r['hand_run_s']:>6.2f} {r['us_per_call']:>8.1f} "
                f"{r['hand_us_per_call']:>8.1f} {r['max_angle_difference_deg']:>8.1e}",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
