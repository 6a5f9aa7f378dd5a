"""Whipple bicycle benchmark (Meijaard et al. 2007): derivation time.

    python benchmarks/whipple.py                # budget 300 s per slow step
    python benchmarks/whipple.py --budget 900

Prints, for the benchmark bicycle written directly in sympy mechanics
(tests/models/whipple_sympy.py):

* the derivation time with intermediate variables (``FastKane``, best of
  three), the time to build its numeric function, and the largest deviation
  of the linearized eigenvalues at v = 0, 4, 5, 10 m/s from Table 2;
* sympy's ``KanesMethod`` on the same inputs (stopped after ``--budget``);
* our Autolev script tests/models/whipple_benchmark.al through al2py
  (conversion, then import, i.e. derivation by the runtime);
* Moore's ``models/Whipple/Whipple.al`` (moorepants/AutolevToolKit) through
  al2py, when it has been fetched to /tmp/corpus.

Slow steps run in a child process stopped after ``--budget`` seconds and are
shown as ``>budget``.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import tempfile
import time
from pathlib import Path

import al2py_runtime  # noqa: F401  (library import is not model derivation)
import numpy as np
from al2py_runtime.model.fastkane import FastKane
from sympy.physics import mechanics as me

from al2py import convert

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))
from budget import show, within  # noqa: E402

MOORE = Path("/tmp/corpus/moorepants__AutolevToolKit/models/Whipple/Whipple.al")
OURS = ROOT / "tests" / "models" / "whipple_benchmark.al"


def _fixture():
    path = ROOT / "tests" / "models" / "whipple_sympy.py"
    spec = importlib.util.spec_from_file_location("whipple_sympy", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


whipple = _fixture()


def fastkane_seconds() -> tuple[float, FastKane, dict]:
    start = time.perf_counter()
    model = whipple.build()
    kane = FastKane(**model["kane"])
    kane.kanes_equations(model["bodies"], model["loads"])
    return time.perf_counter() - start, kane, model


SPEEDS = [0.0, 4.0, 5.0, 10.0]


def deviation(eigs) -> float:
    """Largest distance from Table 2 (the Appendix's closed form)."""
    return max(
        float(
            np.max(
                np.abs(
                    np.sort_complex(e)
                    - np.sort_complex(whipple.reference_eigenvalues(v))
                )
            )
        )
        for v, e in zip(SPEEDS, eigs, strict=True)
    )


def kanesmethod_seconds() -> tuple[float, float, str]:
    """KanesMethod's derivation, then the same linearization (lambdify with
    cse instead of evaluating intermediates): seconds, seconds, outcome."""
    start = time.perf_counter()
    model = whipple.build()
    kane = me.KanesMethod(**model["kane"])
    kane.kanes_equations(model["bodies"], model["loads"])
    t_derive = time.perf_counter() - start
    start = time.perf_counter()
    try:
        with np.errstate(all="ignore"):
            eigs = whipple.eigenvalues(model, kane, SPEEDS)
        outcome = f"eigenvalues vs Table 2 within {deviation(eigs):.0e}"
    except np.linalg.LinAlgError as exc:
        # KanesMethod solves the constraints by LU without pivoting: a pivot
        # that vanishes upright gives nan there.
        outcome = f"cannot linearize upright ({exc}: nan from a vanishing LU pivot)"
    return t_derive, time.perf_counter() - start, outcome


def script_eigenvalues(module) -> list:
    """The lean/steer eigenvalues from the script's own linearization:
    ``AL`` (ours: rows U4', U7' by Q4, Q7, U4, U7) or Moore's ``AMAT``
    (11 x 11, states Q1..Q8, U4, U6, U7), upright, U6 = -v/RR."""
    upright = {f"Q{k}": 0.0 for k in range(1, 9)}
    names = module.AUTOLEV
    out = []
    for v in SPEEDS:
        if "AL" in names:
            al = module.evaluate("AL", U6=-v / 0.3, U4=0.0, U7=0.0, **upright)
            a = np.zeros((4, 4))
            a[0, 2] = a[1, 3] = 1.0
            a[2:, :] = np.asarray(al, dtype=float)
        else:
            big = module.evaluate(
                "AMAT", U6=-v / 0.3, TPHI=0.0, TDELTA=0.0, TTHETAR=0.0
            )
            keep = [3, 6, 8, 10]
            a = np.asarray(big, dtype=float)[np.ix_(keep, keep)]
        out.append(np.linalg.eigvals(a))
    return out


def al2py_seconds(path: str) -> tuple[float, float, float]:
    """Convert, import (derive), and the eigenvalues' distance from Table 2."""
    source = Path(path).read_text(encoding="utf-8", errors="replace")
    start = time.perf_counter()
    result = convert(source, path)
    t_convert = time.perf_counter() - start
    with tempfile.TemporaryDirectory() as tmp:
        module_path = Path(tmp) / "whipple_module.py"
        module_path.write_text(result.code)
        spec = importlib.util.spec_from_file_location("whipple_module", module_path)
        module = importlib.util.module_from_spec(spec)
        start = time.perf_counter()
        spec.loader.exec_module(module)
        t_import = time.perf_counter() - start
        return t_convert, t_import, deviation(script_eigenvalues(module))


def convert_seconds(path: str) -> float:
    source = Path(path).read_text(encoding="utf-8", errors="replace")
    start = time.perf_counter()
    convert(source, path)
    return time.perf_counter() - start


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--budget", type=float, default=300.0)
    args = parser.parse_args(argv)

    runs = [fastkane_seconds() for _ in range(3)]
    t_fast, kane, model = min(runs, key=lambda r: r[0])
    start = time.perf_counter()
    worst = deviation(whipple.eigenvalues(model, kane, SPEEDS))
    t_eig = time.perf_counter() - start
    print(f"Whipple bicycle in sympy ({len(kane.intermediates)} intermediates)")
    print(
        f"  FastKane:    derive {t_fast:7.2f} s, linearize at 4 speeds {t_eig:7.2f} s, "
        f"eigenvalues vs Table 2 within {worst:.0e}"
    )
    status, out, _ = within(args.budget, kanesmethod_seconds)
    if status == "ok":
        t_kane, t_kane_eig, outcome = out
        print(
            f"  KanesMethod: derive {t_kane:7.2f} s, linearize at 4 speeds "
            f"{t_kane_eig:7.2f} s, {outcome}"
        )
        print(f"  ratio KanesMethod / FastKane derivation: {t_kane / t_fast:.1f}x")
    else:
        print(
            f"  KanesMethod: derive + linearize {show(status, 0, args.budget)} s ({out})"
        )
    scripts = [("our whipple_benchmark.al", OURS)]
    if MOORE.exists():
        scripts.append(("Moore's Whipple.al", MOORE))
    else:
        print(f"  (Moore's Whipple.al not fetched: {MOORE} missing)")
    for label, path in scripts:
        status, out, _ = within(args.budget, convert_seconds, str(path))
        if status != "ok":
            print(f"  {label}: conversion {show(status, 0, args.budget)} ({out})")
            continue
        status, out, _ = within(args.budget, al2py_seconds, str(path))
        t_imp = show(status, out[1] if status == "ok" else 0, args.budget)
        extra = f" ({out})" if status == "error" else ""
        if status == "ok":
            extra = f", its own linearization vs Table 2 within {out[2]:.0e}"
        print(
            f"  {label}: al2py convert {convert_seconds(str(path)):.2f} s,"
            f" import {t_imp} s{extra}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
