"""The n-link planar pendulum, written twice: as an Autolev script and by hand.

``autolev_source(n)`` is the model a user would have in Autolev; the
``hand_*`` functions are what a careful SymPy user would write directly with
``KanesMethod`` and ``lambdify(cse=True, modules="math")``.  The benchmark
compares the two (see ``run.py``).
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics import mechanics as me

G, LENGTH, MASS = 9.81, 1.0, 1.0
T_FINAL, TOL = 10.0, 1e-7
STEP = 0.1  # integStp: the largest step and (printInt = 1) the output interval


def initial_angles(n: int) -> list[float]:
    """Initial link angles in degrees (a fixed, non-trivial configuration)."""
    return [30.0 + 10.0 * k for k in range(n)]


def autolev_source(n: int) -> str:
    """An Autolev script for an n-link pendulum of point masses on light rods."""
    lines = [
        f"% {n}-link planar pendulum: particles P1..P{n} on rods of length L",
        "Newtonian N",
        f"Frames A{{{n}}}",
        f"Particles P{{{n}}}",
        "Points O",
        f"Variables Q{{{n}}}', U{{{n}}}'",
        "Constants L, M, G",
        "Mass " + ", ".join(f"P{k}=M" for k in range(1, n + 1)),
    ]
    for k in range(1, n + 1):
        lines.append(f"Simprot(N, A{k}, 3, Q{k})")
    for k in range(1, n + 1):
        lines.append(f"Q{k}' = U{k}")
        lines.append(f"W_A{k}_N> = U{k}*N3>")
    lines.append("V_O_N> = 0>")
    lines.append("P_O_P1> = L*A11>")
    lines.append("V2pts(N, A1, O, P1)")
    for k in range(2, n + 1):
        lines.append(f"P_P{k - 1}_P{k}> = L*A{k}1>")
        lines.append(f"V2pts(N, A{k}, P{k - 1}, P{k})")
    lines += [
        "Gravity(G*N1>)",
        "Zero = Fr() + FrStar()",
        "Kane()",
        "Input L=1 m, M=1 kg, G=9.81 m/sec^2",
        "Input "
        + ", ".join(f"Q{k}={a:g} deg" for k, a in enumerate(initial_angles(n), 1)),
        f"Input tInitial=0, tFinal={T_FINAL:g}, integStp={STEP:g}, printInt=1",
        f"Input absErr={TOL:g}, relErr={TOL:g}",
        "Output T, " + ", ".join(f"Q{k} deg" for k in range(1, n + 1)),
        f"CODE Dynamics() pendulum{n}.c",
    ]
    return "\n".join(lines) + "\n"


def hand_derive(n: int):
    """The same model with KanesMethod directly: returns (kane, q, u, consts)."""
    q = me.dynamicsymbols(f"q1:{n + 1}")
    u = me.dynamicsymbols(f"u1:{n + 1}")
    length, mass, g = sp.symbols("l m g")
    frame_n = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(frame_n, 0)
    particles, loads = [], []
    previous = origin
    for k in range(n):
        frame = frame_n.orientnew(f"A{k + 1}", "Axis", (q[k], frame_n.z))
        frame.set_ang_vel(frame_n, u[k] * frame_n.z)
        point = previous.locatenew(f"P{k + 1}", length * frame.x)
        point.v2pt_theory(previous, frame_n, frame)
        particles.append(me.Particle(f"Pa{k + 1}", point, mass))
        loads.append((point, mass * g * frame_n.x))
        previous = point
    kd = [q[k].diff() - u[k] for k in range(n)]
    kane = me.KanesMethod(frame_n, q_ind=q, u_ind=u, kd_eqs=kd)
    kane.kanes_equations(particles, loads)
    return kane, q, u, (length, mass, g)


def hand_simulate(kane, q, u, consts) -> tuple[np.ndarray, int]:
    """lambdify(cse, math) + numpy.linalg.solve + solve_ivp, the fast way by hand.

    Returns the states at 101 output times and the number of RHS calls."""
    n = len(q)
    args = [*q, *u, *consts]
    # The kinematical equations are q' = u, so only the dynamics need solving.
    mm = sp.lambdify(args, kane.mass_matrix.tolist(), modules="math", cse=True)
    ff = sp.lambdify(args, list(kane.forcing), modules="math", cse=True)
    values = (LENGTH, MASS, G)
    calls = 0

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        nonlocal calls
        calls += 1
        a = (*y, *values)
        m = np.array(mm(*a), dtype=float).reshape(n, n)
        f = np.array(ff(*a), dtype=float).reshape(n)
        return np.concatenate([y[n:], np.linalg.solve(m, f)])

    y0 = [math.radians(a) for a in initial_angles(n)] + [0.0] * n
    times = np.linspace(0, T_FINAL, 101)
    sol = solve_ivp(
        rhs, (0, T_FINAL), y0, t_eval=times, rtol=TOL, atol=TOL, max_step=STEP
    )
    return sol.y, calls
