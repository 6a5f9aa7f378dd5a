"""Large models: how long does importing (deriving) a converted module take?

A chain of n rigid bodies in 3-D, each joined to the previous one by a
spherical joint and oriented by body-fixed 1-2-3 angles, so the model has 3n
generalized speeds (n = 8 gives 24, the size of a detailed bicycle model).

For each size it prints the derivation time with intermediate variables
(``al2py_runtime.model.fastkane.FastKane``: the runtime's one Kane engine,
the one that derives a converted script, run on sympy's inputs), sympy's ``KanesMethod`` without intermediates on the same sympy model, their
ratio, and the conversion and import time of the converted Autolev script
through the runtime; then the growth exponent of each column.  ``FastKane``,
``KanesMethod`` and the import each run in a child process stopped after
``--budget`` seconds (shown as ``>budget``).

    python benchmarks/large.py                 # n = 2, 3, 4, 5, 6, 8
    python benchmarks/large.py 6 8 --budget 600
    python benchmarks/large.py 2 4 8 --autoz off --no-sympy   # only the import
    python benchmarks/large.py 2 3 4 --autoz off --closed     # Constrain too
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import tempfile
import time
from pathlib import Path

import al2py_runtime  # noqa: F401  (library import is not model derivation)
import sympy as sp  # noqa: E402  (after al2py_runtime, as users would)
from al2py_runtime.model.fastkane import FastKane  # noqa: E402
from sympy.physics import mechanics as me  # noqa: E402

from al2py import convert  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from budget import exponent, show, within  # noqa: E402


def chain_source(n: int, autoz: str = "ON", closed: bool = False) -> str:
    """An Autolev script for a 3-D chain of n rigid bodies (3n speeds), with
    ``AutoZ ON`` or ``OFF`` (Autolev's default); ``closed``: the last body's
    mass center moves only along ``N3>`` (two velocity constraints, ``U1``
    and ``U2`` dependent)."""
    lines = [
        f"% {n}-body spatial chain: body-123 angles, speeds = angular velocities",
        f"AutoZ {autoz}",
        "Newtonian N",
        f"Bodies B{{{n}}}",
        "Points O",
        f"Variables Q{{{3 * n}}}', U{{{3 * n}}}'",
        "Constants L, M, IA, IT, G",
    ]
    for k in range(1, n + 1):
        q = [3 * k - 2, 3 * k - 1, 3 * k]
        parent = "N" if k == 1 else f"B{k - 1}"
        lines.append(f"Mass B{k}=M")
        lines.append(f"Inertia B{k}, IT, IT, IA")
        lines.append(f"Dircos({parent}, B{k}, BODY123, Q{q[0]}, Q{q[1]}, Q{q[2]})")
        lines.append(
            f"W_B{k}_{parent}> = U{q[0]}*B{k}1> + U{q[1]}*B{k}2> + U{q[2]}*B{k}3>"
        )
        lines.append(f"Kindiffs({parent}, B{k}, BODY123, Q{q[0]}, Q{q[1]}, Q{q[2]})")
    lines.append("V_O_N> = 0>")
    previous = "O"
    for k in range(1, n + 1):
        lines.append(f"P_{previous}_B{k}O> = L*B{k}3>")
        lines.append(f"V2pts(N, B{k}, {previous}, B{k}O)")
        lines.append(f"A2pts(N, B{k}, {previous}, B{k}O)")
        previous = f"B{k}O"
    if closed:
        lines += [
            f"Dependent[1] = Dot(V_B{n}O_N>, N1>)",
            f"Dependent[2] = Dot(V_B{n}O_N>, N2>)",
            "Constrain(Dependent[U1, U2])",
        ]
    lines += [
        "Gravity(-G*N3>)",
        "Zero = Fr() + FrStar()",
        "Kane()",
    ]
    return "\n".join(lines) + "\n"


def chain_inputs(n: int, closed: bool = False) -> dict:
    """The same chain written directly in sympy mechanics (KanesMethod's
    inputs; ``closed``: with the two velocity constraints)."""
    q = me.dynamicsymbols(f"q1:{3 * n + 1}")
    u = me.dynamicsymbols(f"u1:{3 * n + 1}")
    length, mass, ia, it, g = sp.symbols("L M IA IT G")
    frame_n = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(frame_n, 0)
    parent, previous = frame_n, origin
    bodies, loads, kd = [], [], []
    for k in range(n):
        qs, us = q[3 * k : 3 * k + 3], u[3 * k : 3 * k + 3]
        frame = me.ReferenceFrame(f"B{k + 1}")
        frame.orient_body_fixed(parent, qs, "123")
        w = us[0] * frame.x + us[1] * frame.y + us[2] * frame.z
        kd += list((frame.ang_vel_in(parent) - w).to_matrix(frame))
        frame.set_ang_vel(parent, w)
        center = previous.locatenew(f"P{k + 1}", length * frame.z)
        center.v2pt_theory(previous, frame_n, frame)
        inertia = me.inertia(frame, it, it, ia)
        bodies.append(me.RigidBody(f"R{k + 1}", center, frame, mass, (inertia, center)))
        loads.append((center, -mass * g * frame_n.z))
        parent, previous = frame, center
    out = dict(frame=frame_n, q_ind=q, u_ind=u, kd_eqs=kd, bodies=bodies, loads=loads)
    if closed:
        v = previous.vel(frame_n)
        out.update(
            u_ind=u[2:],
            u_dependent=u[:2],
            velocity_constraints=[v.dot(frame_n.x), v.dot(frame_n.y)],
        )
    return out


def kanesmethod_seconds(n: int, closed: bool = False) -> float:
    """Build the chain and derive it with ``KanesMethod`` (no intermediates)."""
    start = time.perf_counter()
    inputs = chain_inputs(n, closed)
    bodies, loads = inputs.pop("bodies"), inputs.pop("loads")
    kane = me.KanesMethod(**inputs)
    kane.kanes_equations(bodies, loads)
    return time.perf_counter() - start


def fastkane_seconds(n: int, closed: bool = False) -> float:
    """Build the chain and derive it with intermediates (FastKane)."""
    start = time.perf_counter()
    inputs = chain_inputs(n, closed)
    bodies, loads = inputs.pop("bodies"), inputs.pop("loads")
    kane = FastKane(**inputs)
    kane.kanes_equations(bodies, loads)
    return time.perf_counter() - start


def al2py_seconds(
    n: int, autoz: str = "ON", closed: bool = False
) -> tuple[float, float, int]:
    """Convert the Autolev chain and import (derive) the module."""
    with tempfile.TemporaryDirectory() as tmp:
        workdir = Path(tmp)
        source = chain_source(n, autoz, closed)
        path = workdir / f"chain{n}.al"
        path.write_text(source)
        start = time.perf_counter()
        result = convert(source, str(path))
        t_convert = time.perf_counter() - start
        module_path = workdir / f"chain{n}.py"
        module_path.write_text(result.code)
        spec = importlib.util.spec_from_file_location(f"chain{n}", module_path)
        module = importlib.util.module_from_spec(spec)
        start = time.perf_counter()
        spec.loader.exec_module(module)
        t_import = time.perf_counter() - start
        return t_convert, t_import, len(module.al.value("ZERO"))


def best(fn, n: int, repeats: int, closed: bool = False) -> float:
    return min(fn(n, closed) for _ in range(repeats))


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sizes", nargs="*", type=int, default=[2, 3, 4, 5, 6, 8])
    parser.add_argument(
        "--budget", type=float, default=120.0, help="seconds per KanesMethod or import"
    )
    parser.add_argument(
        "--no-import", action="store_true", help="skip converting and importing the .al"
    )
    parser.add_argument(
        "--autoz",
        choices=["on", "off"],
        default="on",
        help="the chain script's AutoZ setting (default on)",
    )
    parser.add_argument(
        "--closed",
        action="store_true",
        help="the last body's mass center moves only vertically: two velocity"
        " constraints (Constrain in the script, u_dependent in sympy)",
    )
    parser.add_argument(
        "--no-sympy",
        action="store_true",
        help="skip the FastKane and KanesMethod columns",
    )
    args = parser.parse_args(argv)
    closed = ", closed by two velocity constraints" if args.closed else ""
    print(f"chain scripts with AutoZ {args.autoz.upper()}{closed}", flush=True)
    print(
        f"{'bodies':>6} {'speeds':>6} {'FastKane s':>10} {'Kanes s':>8} {'ratio':>6} "
        f"{'convert s':>9} {'import s':>8}",
        flush=True,
    )
    fast_times, kane_times, import_times = [], [], []
    for n in args.sizes:
        # In a child too: building the sympy chain (v2pt_theory through n
        # frames) grows steeply by itself.
        if args.no_sympy:
            status_f = status = "skipped"
            t_fast = t_kane = None
            fast_col = kane_col = "-"
        else:
            status_f, t_fast, _ = within(
                args.budget, best, fastkane_seconds, n, 3 if n <= 4 else 1, args.closed
            )
            fast_col = show(status_f, t_fast if status_f == "ok" else 0, args.budget)
            t_fast = t_fast if status_f == "ok" else None
            status, t_kane, _ = within(args.budget, kanesmethod_seconds, n, args.closed)
            kane_col = show(status, t_kane if status == "ok" else 0, args.budget)
        if t_fast is None or args.no_sympy:
            ratio = "-"
        elif status == "ok":
            ratio = f"{t_kane / t_fast:.1f}"
        else:
            ratio = f">{args.budget / t_fast:.0f}"
        if args.no_import:
            conv_col = imp_col = "-"
            t_imp = None
        else:
            status_i, out, _ = within(
                args.budget, al2py_seconds, n, args.autoz.upper(), args.closed
            )
            conv_col = f"{out[0]:.2f}" if status_i == "ok" else "-"
            imp_col = show(status_i, out[1] if status_i == "ok" else 0, args.budget)
            t_imp = out[1] if status_i == "ok" else None
        fast_times.append(t_fast)
        kane_times.append(t_kane if status == "ok" else None)
        import_times.append(t_imp)
        print(
            f"{n:>6} {3 * n:>6} {fast_col:>10} {kane_col:>8} {ratio:>6} "
            f"{conv_col:>9} {imp_col:>8}",
            flush=True,
        )
    print(
        "growth exponent (time ~ bodies^k, sizes that finished): FastKane "
        f"{exponent(args.sizes, fast_times)}, KanesMethod "
        f"{exponent(args.sizes, kane_times)}, al2py import "
        f"{exponent(args.sizes, import_times)}"
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
