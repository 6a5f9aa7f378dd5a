"""The Whipple bicycle benchmark, built directly in sympy mechanics.

Written from the description in Meijaard, Papadopoulos, Ruina and Schwab,
"Linearized dynamics equations for the balance and steer of a bicycle: a
benchmark and review", Proc. R. Soc. A 463 (2007): four rigid bodies (rear
wheel R, rear frame with rider B, front frame H, front wheel F), knife-edge
wheels rolling without slip on flat ground, the parameter values of Table 1.

Axes as in the paper: x forward, y to the right, z down; the origin is the
rear contact point; gravity acts along +z.

Coordinates (u_i = q_i'):
    q1, q2  rear contact point in the ground plane
    q3      yaw, q4 roll (lean), q5 rear-frame pitch (dependent)
    q6      rear wheel angle relative to the rear frame
    q7      steer angle, q8 front wheel angle relative to the front frame

The rear wheel's no-slip condition gives two velocity constraints, the front
wheel's three (its third, vertical one is the time derivative of the
holonomic constraint that the front wheel touches the ground).  The
independent speeds are roll rate u4, rear wheel rate u6 and steer rate u7.

The linearized equations are checked against Table 2's eigenvalues and against
the closed-form matrices M, C1, K0, K2 of the paper's Appendix A, both in
``tests/test_whipple.py``.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp
from sympy.physics import mechanics as me

#: Table 1 of Meijaard et al. (2007).
BENCHMARK = {
    "w": 1.02,
    "c": 0.08,
    "lam": math.pi / 10,
    "g": 9.81,
    "rR": 0.3,
    "mR": 2.0,
    "IRxx": 0.0603,
    "IRyy": 0.12,
    "xB": 0.3,
    "zB": -0.9,
    "mB": 85.0,
    "IBxx": 9.2,
    "IByy": 11.0,
    "IBzz": 2.8,
    "IBxz": 2.4,
    "xH": 0.9,
    "zH": -0.7,
    "mH": 4.0,
    "IHxx": 0.05892,
    "IHyy": 0.06,
    "IHzz": 0.00708,
    "IHxz": -0.00756,
    "rF": 0.35,
    "mF": 3.0,
    "IFxx": 0.1405,
    "IFyy": 0.28,
}


def build():
    """The model as KanesMethod-style inputs (a dict)."""
    q = me.dynamicsymbols("q1:9")
    u = me.dynamicsymbols("u1:9")
    p = {name: sp.Symbol(name) for name in BENCHMARK}
    w, c, lam, g = p["w"], p["c"], p["lam"], p["g"]
    rr, rf = p["rR"], p["rF"]

    n = me.ReferenceFrame("N")
    yaw = n.orientnew("Y", "Axis", [q[2], n.z])
    roll = yaw.orientnew("L", "Axis", [q[3], yaw.x])
    rear = roll.orientnew("B", "Axis", [q[4], roll.y])
    rear_wheel = rear.orientnew("WR", "Axis", [q[5], rear.y])
    steer_axis = rear.orientnew("E", "Axis", [lam, rear.y])  # z: down the head tube
    fork = steer_axis.orientnew("H", "Axis", [q[6], steer_axis.z])
    fork_g = fork.orientnew("HG", "Axis", [-lam, fork.y])  # = B when steer is 0
    front_wheel = fork.orientnew("WF", "Axis", [q[7], fork.y])

    # Angular velocities in terms of the speeds.
    yaw.set_ang_vel(n, u[2] * n.z)
    roll.set_ang_vel(yaw, u[3] * yaw.x)
    rear.set_ang_vel(roll, u[4] * roll.y)
    rear_wheel.set_ang_vel(rear, u[5] * rear.y)
    fork.set_ang_vel(steer_axis, u[6] * steer_axis.z)
    front_wheel.set_ang_vel(fork, u[7] * fork.y)

    # Points.
    contact_r = me.Point("P")
    contact_r.set_vel(n, u[0] * n.x + u[1] * n.y)
    center_r = contact_r.locatenew("RC", -rr * roll.z)
    center_r.v2pt_theory(contact_r, n, roll)
    mass_b = center_r.locatenew("BO", p["xB"] * rear.x + (p["zB"] + rr) * rear.z)
    mass_b.v2pt_theory(center_r, n, rear)
    # The steer axis meets the ground at (w + c, 0) in the reference
    # configuration; that point is fixed in both frames.
    axis_point = center_r.locatenew("S", (w + c) * rear.x + rr * rear.z)
    axis_point.v2pt_theory(center_r, n, rear)
    mass_h = axis_point.locatenew(
        "HO", (p["xH"] - w - c) * fork_g.x + p["zH"] * fork_g.z
    )
    mass_h.v2pt_theory(axis_point, n, fork)
    center_f = axis_point.locatenew("FC", -c * fork_g.x - rf * fork_g.z)
    center_f.v2pt_theory(axis_point, n, fork)
    # The front wheel's lowest point: down in the wheel plane.
    down = me.cross(fork.y, me.cross(n.z, fork.y))
    down_unit = down / sp.sqrt(1 - me.dot(n.z, fork.y) ** 2)
    contact_f = center_f.locatenew("Q", rf * down_unit)

    # Constraints.
    holonomic = me.dot(contact_f.pos_from(contact_r), n.z)
    slip_r = center_r.vel(n) + me.cross(rear_wheel.ang_vel_in(n), rr * roll.z)
    slip_f = center_f.vel(n) + me.cross(front_wheel.ang_vel_in(n), rf * down_unit)
    velocity_constraints = [
        me.dot(slip_r, n.x),
        me.dot(slip_r, n.y),
        me.dot(slip_f, n.x),
        me.dot(slip_f, n.y),
        me.dot(slip_f, n.z),
    ]

    bodies = [
        me.RigidBody(
            "rear_wheel",
            center_r,
            rear_wheel,
            p["mR"],
            (me.inertia(rear_wheel, p["IRxx"], p["IRyy"], p["IRxx"]), center_r),
        ),
        me.RigidBody(
            "rear_frame",
            mass_b,
            rear,
            p["mB"],
            (
                me.inertia(rear, p["IBxx"], p["IByy"], p["IBzz"], 0, 0, p["IBxz"]),
                mass_b,
            ),
        ),
        me.RigidBody(
            "front_frame",
            mass_h,
            fork_g,
            p["mH"],
            (
                me.inertia(fork_g, p["IHxx"], p["IHyy"], p["IHzz"], 0, 0, p["IHxz"]),
                mass_h,
            ),
        ),
        me.RigidBody(
            "front_wheel",
            center_f,
            front_wheel,
            p["mF"],
            (me.inertia(front_wheel, p["IFxx"], p["IFyy"], p["IFxx"]), center_f),
        ),
    ]
    loads = [(b.masscenter, b.mass * g * n.z) for b in bodies]
    kane = dict(
        frame=n,
        q_ind=[q[0], q[1], q[2], q[3], q[5], q[6], q[7]],
        u_ind=[u[3], u[5], u[6]],
        kd_eqs=[qi.diff() - ui for qi, ui in zip(q, u, strict=True)],
        q_dependent=[q[4]],
        configuration_constraints=[holonomic],
        u_dependent=[u[0], u[1], u[2], u[4], u[7]],
        velocity_constraints=velocity_constraints,
    )
    return dict(
        kane=kane,
        bodies=bodies,
        loads=loads,
        q=list(q),
        u=list(u),
        params=[p[name] for name in BENCHMARK],
        holonomic=holonomic,
    )


def eigenvalues(model, kane, speeds, values=None, step=1e-30):
    """Eigenvalues of the linearized lean/steer equations at forward speeds.

    ``kane`` is a formulation after ``kanes_equations`` with ``mass_matrix``,
    ``forcing``, ``u`` and either ``numeric`` (FastKane) or plain sympy
    expressions.  The state matrix is the exact Jacobian (complex-step
    derivative) of (roll, steer, roll rate, steer rate)' at the upright
    configuration; pitch and the dependent speeds are solved numerically."""
    values = dict(BENCHMARK, **(values or {}))
    q, u, params = model["q"], model["u"], model["params"]
    pvals = [values[s.name] for s in params]
    rear_radius = values.get("RR", values["rR"])
    args = q + u + params
    exprs = [kane.mass_matrix, kane.forcing]
    if hasattr(kane, "numeric"):  # FastKane: intermediates evaluated in order
        both = kane.numeric(args, exprs)
    else:
        both = sp.lambdify(args, exprs, cse=True)
    holonomic = model.get("holonomic")
    if holonomic is not None:
        constraint = sp.lambdify(q + params, holonomic)
        d_constraint = sp.lambdify(q + params, holonomic.diff(q[4]))
    kd = model["kane"]
    vel = sp.Matrix(kd["velocity_constraints"]).xreplace(
        {qi.diff(): ui for qi, ui in zip(q, u, strict=True)}
    )
    u_dep = kd["u_dependent"]
    a_dep, b_dep = vel.jacobian(u_dep), vel.xreplace(dict.fromkeys(u_dep, 0))
    f_a = sp.lambdify(args, a_dep)
    f_b = sp.lambdify(args, b_dep)
    order = [u.index(s) for s in kd["u_ind"] + u_dep]

    def rhs(x, v):
        roll, steer, roll_rate, steer_rate = x
        qs = [0, 0, 0, roll, 0.0 * roll, 0, steer, 0]
        pitch = 0.0 * roll
        # Newton on the holonomic constraint.  (Without it, pitch stays at
        # its reference value 0: by symmetry it changes only to second order
        # in roll and steer, which the linearization does not see.)
        for _ in range(30 if holonomic is not None else 0):
            qs[4] = pitch
            pitch = pitch - constraint(*qs, *pvals) / d_constraint(*qs, *pvals)
        qs[4] = pitch
        us = [0] * 8
        us[3], us[5], us[6] = roll_rate, -v / rear_radius, steer_rate
        a = np.array(f_a(*qs, *us, *pvals), dtype=complex)
        b = np.array(f_b(*qs, *us, *pvals), dtype=complex).ravel()
        for s, val in zip(u_dep, np.linalg.solve(a, -b), strict=True):
            us[u.index(s)] = val
        mm, f = both(*qs, *us, *pvals)
        mm = np.array(mm, dtype=complex)
        f = np.array(f, dtype=complex).ravel()
        acc = np.linalg.solve(mm, f)  # in the order u_ind + u_dep
        acc_by_speed = dict(zip(order, acc, strict=True))
        return np.array([roll_rate, steer_rate, acc_by_speed[3], acc_by_speed[6]])

    out = []
    for v in speeds:
        jac = np.zeros((4, 4))
        for j in range(4):
            x = np.zeros(4, dtype=complex)
            x[j] = 1j * step
            jac[:, j] = rhs(x, v).imag / step
        out.append(np.linalg.eigvals(jac))
    return out


def benchmark_matrices(values=None):
    """M, C1, K0, K2 of the paper's Appendix A (closed form), lean/steer."""
    v = dict(BENCHMARK, **(values or {}))
    w, c, lam, rr, rf = v["w"], v["c"], v["lam"], v["rR"], v["rF"]
    mr, mb, mh, mf = v["mR"], v["mB"], v["mH"], v["mF"]
    xb, zb, xh, zh = v["xB"], v["zB"], v["xH"], v["zH"]
    mt = mr + mb + mh + mf
    xt = (xb * mb + xh * mh + w * mf) / mt
    zt = (-rr * mr + zb * mb + zh * mh - rf * mf) / mt
    itxx = v["IRxx"] + v["IBxx"] + v["IHxx"] + v["IFxx"]
    itxx += mr * rr**2 + mb * zb**2 + mh * zh**2 + mf * rf**2
    itxz = v["IBxz"] + v["IHxz"] - mb * xb * zb - mh * xh * zh + mf * w * rf
    itzz = v["IRxx"] + v["IBzz"] + v["IHzz"] + v["IFxx"]
    itzz += mb * xb**2 + mh * xh**2 + mf * w**2
    ma = mh + mf
    xa = (xh * mh + w * mf) / ma
    za = (zh * mh - rf * mf) / ma
    iaxx = v["IHxx"] + v["IFxx"] + mh * (zh - za) ** 2 + mf * (rf + za) ** 2
    iaxz = v["IHxz"] - mh * (xh - xa) * (zh - za) + mf * (w - xa) * (rf + za)
    iazz = v["IHzz"] + v["IFxx"] + mh * (xh - xa) ** 2 + mf * (w - xa) ** 2
    ua = (xa - w - c) * math.cos(lam) - za * math.sin(lam)
    s, co = math.sin(lam), math.cos(lam)
    iall = ma * ua**2 + iaxx * s**2 + 2 * iaxz * s * co + iazz * co**2
    ialx = -ma * ua * za + iaxx * s + iaxz * co
    ialz = ma * ua * xa + iaxz * s + iazz * co
    mu = c / w * co
    sr, sf = v["IRyy"] / rr, v["IFyy"] / rf
    st = sr + sf
    sa = ma * ua + mu * mt * xt
    m = np.array(
        [
            [itxx, ialx + mu * itxz],
            [ialx + mu * itxz, iall + 2 * mu * ialz + mu**2 * itzz],
        ]
    )
    k0 = np.array([[mt * zt, -sa], [-sa, -sa * s]])
    k2 = np.array([[0, (st - mt * zt) / w * co], [0, (sa + sf * s) / w * co]])
    c1 = np.array(
        [
            [0, mu * st + sf * co + itxz / w * co - mu * mt * zt],
            [-(mu * st + sf * co), ialz / w * co + mu * (sa + itzz / w * co)],
        ]
    )
    return m, c1, k0, k2


def reference_eigenvalues(speed, values=None):
    """Eigenvalues of M q'' + v C1 q' + (g K0 + v^2 K2) q = 0."""
    m, c1, k0, k2 = benchmark_matrices(values)
    g = dict(BENCHMARK, **(values or {}))["g"]
    minv = np.linalg.inv(m)
    a = np.zeros((4, 4))
    a[:2, 2:] = np.eye(2)
    a[2:, :2] = -minv @ (g * k0 + speed**2 * k2)
    a[2:, 2:] = -minv @ (speed * c1)
    return np.linalg.eigvals(a)


__all__ = [
    "BENCHMARK",
    "build",
    "eigenvalues",
    "benchmark_matrices",
    "reference_eigenvalues",
]
