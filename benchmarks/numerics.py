"""Benchmark: the right-hand side of converted models, backend by backend.

    python benchmarks/numerics.py               # pendulum n = 4, 8, 16; chain 2, 3
    python benchmarks/numerics.py --pendulum 8 --chain 2

For each model it prints, measured side by side in one process:

* microseconds per right-hand-side call ``f(t, y)`` (mass matrix, forcing,
  linear solve, the state derivatives), best of 60 rounds of 250 calls at the initial
  state;
* seconds for ``solve_ivp`` (DOP853, rtol = atol = 1e-7, max_step = 0.1)
  over 10 s of simulation, best of 3;
* for the pendulum, the same per-call cost measured inside C (a loop of
  calls, no Python in between) for al2py's ``c`` backend and the reference;
* for al2py's backends, the first-call overhead (code generation and
  compilation into an empty cache) and the same with the cache warm.

Rows: al2py's ``c``, ``llvm`` and ``lambdify`` backends (and which one
``auto``, the default, picks); ``lambdify(math, cse)`` + ``numpy.linalg.solve``
by hand on ``KanesMethod``'s equations; PyDy's Cython generator if PyDy and
Cython are installed; and, for the pendulum, a hand-written C right-hand
side with the linear solve in C, called through ctypes exactly like al2py's
``c`` backend: the limit.  ``x C ref`` is the ratio to that limit.
"""

from __future__ import annotations

import argparse
import ctypes
import importlib.util
import math
import os
import sys
import tempfile
import time
import timeit
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402
from al2py_runtime.jobs import backends  # noqa: E402
from al2py_runtime.jobs import run as jobs  # noqa: E402
from large import chain_inputs, chain_source  # noqa: E402
from pendulum import LENGTH, MASS, G, autolev_source, hand_derive  # noqa: E402
from scipy.integrate import solve_ivp  # noqa: E402

from al2py import convert  # noqa: E402

T_FINAL, TOL, MAX_STEP = 10.0, 1e-7, 0.1
CALLS, REPEATS = 250, 60

# The n-link pendulum by hand: M_ij = m l^2 c_ij cos(q_i - q_j),
# f_i = -m l^2 sum_j c_ij sin(q_i - q_j) u_j^2 - m g l c_i sin(q_i), with
# c_ij = n - max(i, j) (0-based) the number of particles beyond the joint.
REFERENCE_C = r"""
#include <math.h>
#define N %(n)d
int ref_rhs(double t, const double *y, const double *p, double *dy)
{
    const double l = p[0], m = p[1], g = p[2];
    double s[N], c[N], a[N * N], b[N];
    (void)t;
    for (int i = 0; i < N; i++) {
        s[i] = sin(y[i]);
        c[i] = cos(y[i]);
        dy[i] = y[N + i];
    }
    for (int i = 0; i < N; i++) {
        double fi = -m * g * l * (N - i) * s[i];
        for (int j = 0; j < N; j++) {
            int w = N - (i > j ? i : j);
            double cij = c[i] * c[j] + s[i] * s[j];
            double sij = s[i] * c[j] - c[i] * s[j];
            a[i * N + j] = m * l * l * w * cij;
            fi -= m * l * l * w * sij * y[N + j] * y[N + j];
        }
        b[i] = fi;
    }
    for (int k = 0; k < N; k++) {
        int piv = k;
        double big = fabs(a[k * N + k]);
        for (int i = k + 1; i < N; i++)
            if (fabs(a[i * N + k]) > big) {
                big = fabs(a[i * N + k]);
                piv = i;
            }
        if (big == 0.0) return 1;
        if (piv != k) {
            for (int j = k; j < N; j++) {
                double tmp = a[k * N + j];
                a[k * N + j] = a[piv * N + j];
                a[piv * N + j] = tmp;
            }
            double tmp = b[k];
            b[k] = b[piv];
            b[piv] = tmp;
        }
        for (int i = k + 1; i < N; i++) {
            double f = a[i * N + k] / a[k * N + k];
            for (int j = k + 1; j < N; j++) a[i * N + j] -= f * a[k * N + j];
            b[i] -= f * b[k];
        }
    }
    for (int i = N - 1; i >= 0; i--) {
        double v = b[i];
        for (int j = i + 1; j < N; j++) v -= a[i * N + j] * b[j];
        b[i] = v / a[i * N + i];
        dy[N + i] = b[i];
    }
    return 0;
}
"""


LOOP_C = r"""
int bench_loop(long reps, double *y, const double *p, double *dy)
{
    int code = 0;
    for (long k = 0; k < reps; k++) {
        y[0] += 1e-12;  /* a new state each call: nothing to hoist */
        code |= %(fn)s(0.0, y, p, dy);
    }
    return code;
}
"""


def c_only_us(sources: dict[str, tuple[str, list[float]]], y0: np.ndarray) -> dict:
    """Microseconds per call measured inside C (a loop of calls, no Python),
    for each {label: (C source with bench_loop, parameters)}; in turn, best
    of REPEATS rounds."""
    loops = {}
    for label, (source, p) in sources.items():
        path, _hit = backends.build_shared(source)
        fn = ctypes.CDLL(str(path)).bench_loop
        fn.argtypes = [ctypes.c_long] + [ctypes.c_void_p] * 3
        fn.restype = ctypes.c_int
        loops[label] = (fn, np.array(p, dtype=float))
    best = dict.fromkeys(loops, math.inf)
    reps = 500
    for _ in range(REPEATS):
        for label, (fn, p) in loops.items():
            y = np.array(y0, dtype=float)
            dy = np.empty_like(y)
            start = time.perf_counter()
            fn(reps, y.ctypes.data, p.ctypes.data, dy.ctypes.data)
            best[label] = min(best[label], 1e6 * (time.perf_counter() - start) / reps)
    return best


def reference_rhs(n: int):
    """The hand-written C pendulum, wrapped like al2py's ``c`` backend."""
    path, _hit = backends.build_shared(REFERENCE_C % {"n": n})
    lib = ctypes.CDLL(str(path))
    fn = lib.ref_rhs
    fn.argtypes = [ctypes.c_double, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p]
    fn.restype = ctypes.c_int
    p = np.array([LENGTH, MASS, G])
    pp = p.ctypes.data
    ny = 2 * n
    asarray, empty = np.ascontiguousarray, np.empty

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        y = asarray(y, dtype=float)
        dy = empty(ny)
        if fn(t, y.ctypes.data, pp, dy.ctypes.data):
            raise ArithmeticError("singular")
        return dy

    rhs._keep = (lib, p)  # type: ignore[attr-defined]
    return rhs


def hand_lambdify(kane, q, u, consts, values):
    """``lambdify(math, cse)`` + ``numpy.linalg.solve``, written by hand."""
    n = len(q)
    args = [*q, *u, *consts]
    mm = sp.lambdify(args, kane.mass_matrix.tolist(), modules="math", cse=True)
    ff = sp.lambdify(args, list(kane.forcing), modules="math", cse=True)
    qdot = sp.lambdify(args, [kane.kindiffdict()[x.diff()] for x in q], "math")

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        a = (*y.tolist(), *values)
        m = np.array(mm(*a), dtype=float).reshape(n, n)
        f = np.array(ff(*a), dtype=float).reshape(n)
        return np.concatenate([qdot(*a), np.linalg.solve(m, f)])

    return rhs


def pydy_rhs(kane, q, u, consts, values):
    """PyDy's Cython generator, or None when PyDy or Cython is missing."""
    try:
        import Cython  # noqa: F401
        from pydy.codegen.ode_function_generators import generate_ode_function
    except ImportError:
        return None
    kd = kane.kindiffdict()
    with tempfile.TemporaryDirectory() as tmp:
        cwd = os.getcwd()
        os.chdir(tmp)  # PyDy writes its build files into the working folder
        try:
            f = generate_ode_function(
                kane.forcing,
                q,
                u,
                list(consts),
                mass_matrix=kane.mass_matrix,
                coordinate_derivatives=sp.Matrix([kd[x.diff()] for x in q]),
                generator="cython",
                constants_arg_type="array",
            )
        finally:
            os.chdir(cwd)
    p = np.array(values, dtype=float)

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        return f(y, t, p)

    return rhs


def measure(candidates: list[dict], y0: np.ndarray) -> None:
    """Fill ``us`` and ``ivp`` of each candidate ({"rhs": f, ...}).

    Candidates are timed in turn, round after round, and each keeps its best
    round: load from other processes then hits all of them alike."""
    for c in candidates:
        c["rhs"](0.0, y0)
        c["us"], c["ivp"] = math.inf, math.inf
    for _ in range(REPEATS):
        for c in candidates:
            rhs = c["rhs"]
            secs = timeit.timeit(lambda rhs=rhs: rhs(0.0, y0), number=CALLS)
            c["us"] = min(c["us"], 1e6 * secs / CALLS)
    for _ in range(3):
        for c in candidates:
            start = time.perf_counter()
            solve_ivp(
                c["rhs"],
                (0.0, T_FINAL),
                y0,
                method="DOP853",
                rtol=TOL,
                atol=TOL,
                max_step=MAX_STEP,
            )
            c["ivp"] = min(c["ivp"], time.perf_counter() - start)


def _import(source: str, name: str, workdir: Path):
    path = workdir / f"{name}.al"
    path.write_text(source)
    module_path = workdir / f"{name}.py"
    module_path.write_text(convert(source, str(path)).code)
    spec = importlib.util.spec_from_file_location(name, module_path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def al2py_model(module):
    """(spec, parameter values, initial state) of the module's CODE job."""
    job = module.al.numerics.jobs[-1]
    vals, keep = jobs.input_values(job, {})
    c = jobs.dynamics_equations(job, frozenset(keep))
    p = [vals.param(obj) for obj in c.params]
    y0 = np.array([vals.get(name, 0.0, note=False) for name in c.state_names])
    return c.spec, p, y0


def al2py_candidates(spec, p) -> list[dict]:
    """One candidate per available backend, with its first-call overhead
    (into an empty cache) and its cost with the cache warm."""
    default = backends.compile_dynamics(spec, "auto").backend
    out = []
    for name in backends.BACKENDS:
        if not backends.available(name):
            continue
        with tempfile.TemporaryDirectory() as cache:
            old = os.environ.get("AL2PY_CACHE_DIR")
            os.environ["AL2PY_CACHE_DIR"] = cache
            try:
                start = time.perf_counter()
                try:
                    backends.compile_dynamics(spec, name)
                except backends.BackendError as exc:
                    print(f"  ({name}: {exc})")
                    continue
                first = time.perf_counter() - start
                start = time.perf_counter()
                compiled = backends.compile_dynamics(spec, name)
                again = time.perf_counter() - start
            finally:
                if old is None:
                    del os.environ["AL2PY_CACHE_DIR"]
                else:
                    os.environ["AL2PY_CACHE_DIR"] = old
        label = f"al2py {name}" + (" (default)" if name == default else "")
        out.append(
            {
                "label": label,
                "rhs": compiled.bind(p).rhs,
                "first": first,
                "cached": again,
            }
        )
    return out


def by_hand(kane, q, u, consts, values) -> list[dict]:
    """Hand-written lambdify, and PyDy's Cython generator if installed."""
    out = [
        {
            "label": "lambdify+numpy by hand",
            "rhs": hand_lambdify(kane, q, u, consts, values),
        }
    ]
    start = time.perf_counter()
    pydy = pydy_rhs(kane, q, u, consts, values)
    if pydy is not None:
        out.append(
            {"label": "PyDy Cython", "rhs": pydy, "first": time.perf_counter() - start}
        )
    return out


def report(title: str, candidates: list[dict], reference: dict | None) -> None:
    print(f"\n{title}")
    head = (
        f"  {'right-hand side':<28} {'us/call':>8} {'x C ref':>8} "
        f"{'ivp 10 s':>9} {'first call s':>13} {'cached s':>9}"
    )
    print(head)
    print("  " + "-" * (len(head) - 2))
    for c in candidates:
        ratio = f"{c['us'] / reference['us']:8.2f}" if reference else f"{'-':>8}"
        first, cached = c.get("first"), c.get("cached")
        f1 = f"{first:13.2f}" if first is not None else f"{'-':>13}"
        f2 = f"{cached:9.2f}" if cached is not None else f"{'-':>9}"
        print(
            f"  {c['label']:<28} {c['us']:8.1f} {ratio} {c['ivp']:9.3f} {f1} {f2}",
            flush=True,
        )


def pendulum(n: int, workdir: Path) -> None:
    module = _import(autolev_source(n), f"pendulum{n}", workdir)
    spec, p, y0 = al2py_model(module)
    kane, q, u, consts = hand_derive(n)
    reference = {"label": "hand-written C (limit)", "rhs": reference_rhs(n)}
    candidates = al2py_candidates(spec, p)
    # The same equations: al2py's default against the hand-written C.
    ours = candidates[0]["rhs"](0.0, y0)
    assert np.allclose(ours, reference["rhs"](0.0, y0), rtol=1e-9, atol=1e-9)
    candidates += by_hand(kane, q, u, consts, (LENGTH, MASS, G))
    candidates.append(reference)
    measure(candidates, y0)
    report(f"{n}-link pendulum ({2 * n} states)", candidates, reference)
    inside = c_only_us(
        {
            "al2py c": (
                backends.c_model_source(spec) + LOOP_C % {"fn": "al_rhs"},
                p,
            ),
            "reference": (
                REFERENCE_C % {"n": n} + LOOP_C % {"fn": "ref_rhs"},
                [LENGTH, MASS, G],
            ),
        },
        y0,
    )
    print(
        f"  inside C (no Python call): al2py c {inside['al2py c']:.2f} us,"
        f" hand-written {inside['reference']:.2f} us,"
        f" ratio {inside['al2py c'] / inside['reference']:.2f}"
    )


CHAIN_VALUES = {"L": 0.5, "M": 1.0, "IA": 0.01, "IT": 0.1, "G": 9.81}


def hand_chain(n: int):
    """The spatial chain with ``KanesMethod`` directly (large.py's model)."""
    from sympy.physics import mechanics as me

    inputs = chain_inputs(n)
    q, u = inputs["q_ind"], inputs["u_ind"]
    kane = me.KanesMethod(inputs["frame"], q_ind=q, u_ind=u, kd_eqs=inputs["kd_eqs"])
    kane.kanes_equations(inputs["bodies"], inputs["loads"])
    return kane, q, u, sp.symbols("L M IA IT G")


def chain(n: int, workdir: Path) -> None:
    source = chain_source(n) + "\n".join(
        [
            "Input L=0.5 m, M=1 kg, IA=0.01 kg*m^2, IT=0.1 kg*m^2, G=9.81 m/sec^2",
            "Input " + ", ".join(f"Q{k}={10 + 5 * k} deg" for k in range(1, 3 * n + 1)),
            f"Input tFinal={T_FINAL:g}, integStp={MAX_STEP:g}, absErr={TOL:g}, relErr={TOL:g}",
            "Output T, Q1 deg",
            f"CODE Dynamics() chain{n}.c",
            "",
        ]
    )
    module = _import(source, f"chain{n}", workdir)
    spec, p, y0 = al2py_model(module)
    kane, q, u, consts = hand_chain(n)
    values = tuple(CHAIN_VALUES[str(c)] for c in consts)
    candidates = al2py_candidates(spec, p)
    hand = by_hand(kane, q, u, consts, values)
    ours = candidates[0]["rhs"](0.0, y0)
    assert np.allclose(ours, hand[0]["rhs"](0.0, y0), rtol=1e-8, atol=1e-8)
    measure(candidates + hand, y0)
    title = f"{n}-body spatial chain ({6 * n} states; no hand-written C)"
    report(title, candidates + hand, None)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--pendulum", type=int, nargs="*", default=[4, 8, 16])
    parser.add_argument("--chain", type=int, nargs="*", default=[2, 3])
    args = parser.parse_args(argv)
    print(
        "backends available: "
        + ", ".join(b for b in backends.BACKENDS if backends.available(b))
    )
    with tempfile.TemporaryDirectory() as tmp:
        for n in args.pendulum:
            pendulum(n, Path(tmp))
        for n in args.chain:
            chain(n, Path(tmp))
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
