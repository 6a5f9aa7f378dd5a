"""Large models: how long does importing (deriving) a converted module take?

A chain of n rigid bodies in 3-D, each joined to the previous one by a
spherical joint and oriented by body-fixed 1-2-3 angles, so the model has 3n
generalized speeds (n = 8 gives 24, the size of a detailed bicycle model).

    python benchmarks/large.py          # n = 2, 3, 4
    python benchmarks/large.py 6 10     # chosen sizes
"""

from __future__ import annotations

import importlib.util
import sys
import tempfile
import time
from pathlib import Path

import al2py_runtime  # noqa: F401  (library import is not model derivation)
import sympy as sp  # noqa: E402  (after al2py_runtime, as users would)
from sympy.physics import mechanics as me  # noqa: E402

from al2py import convert


def chain_source(n: int) -> str:
    """An Autolev script for a 3-D chain of n rigid bodies (3n speeds)."""
    lines = [
        f"% {n}-body spatial chain: body-123 angles, speeds = angular velocities",
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
    lines += [
        "Gravity(-G*N3>)",
        "Zero = Fr() + FrStar()",
        "Kane()",
    ]
    return "\n".join(lines) + "\n"


def kanesmethod_seconds(n: int) -> float:
    """The same chain written directly with ``KanesMethod`` (for comparison)."""
    start = time.perf_counter()
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
    kane = me.KanesMethod(frame_n, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(bodies, loads)
    return time.perf_counter() - start


def measure(n: int, workdir: Path) -> tuple[float, float, int]:
    source = chain_source(n)
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
    equations = len(module.AUTOLEV["ZERO"])
    return t_convert, t_import, equations


def main(argv: list[str]) -> int:
    sizes = [int(a) for a in argv] or [2, 3, 4]
    print(
        f"{'bodies':>6} {'speeds':>6} {'lines':>6} {'convert s':>10} "
        f"{'import s':>9} {'Kanes s':>8} {'ratio':>6}"
    )
    with tempfile.TemporaryDirectory() as tmp:
        for n in sizes:
            t_convert, t_import, equations = measure(n, Path(tmp))
            t_kane = kanesmethod_seconds(n)
            lines = len(chain_source(n).splitlines())
            print(
                f"{n:>6} {equations:>6} {lines:>6} {t_convert:>10.2f} "
                f"{t_import:>9.2f} {t_kane:>8.2f} {t_import / t_kane:>6.2f}",
                flush=True,
            )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
