"""How generalized coordinates and speeds are identified (issue 9, "never a
silent zero").

Each case is one declaration style found in real Autolev scripts, applied to
the same physical pendulum: a uniform rod A (mass M, central moment of inertia
I about A3>) hinged at NO, mass center AO at L/2 along A2>, gravity G*N2>.
Its angle THETA is the coordinate.  When the generalized speed is
``u = THETA'/c`` (c = 1 unless stated), Kane's equation for ``u`` is

    ZERO = -c^2*(I + M*L^2/4)*u' - c*M*G*L/2*SIN(THETA)

and every case is compared with it at random points.  Rules: docs/semantics.md
("Generalized speeds").
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime import t
from conftest import load_module

from al2py import convert

# The body of every script: {kde} is the kinematical differential equation,
# {w} the angular velocity's source.
COMMON = """
Newtonian N
Bodies A
Constants G, L, M, I
{decl}
Mass A=M
Inertia A, 0, 0, I
Simprot(N, A, 3, THETA)
{kde}
P_NO_AO> = L/2*A2>
{w}
V_AO_N> = Dt(P_NO_AO>, N)
Gravity(G*N2>)
Zero = Fr() + FrStar()
"""

# name: (declarations, kinematical equation, angular velocity, speed, c)
STYLES = {
    # moorepants' Pendulum.al: the coordinate is a plain variable
    "variables_and_motionvariables": (
        "Variables THETA'\nMotionVariables' OMEGA'",
        "THETA' = OMEGA",
        "Angvel(N, A)",
        "OMEGA",
        1,
    ),
    # both in MotionVariables
    "motionvariables_both": (
        "MotionVariables' THETA', OMEGA'",
        "THETA' = OMEGA",
        "Angvel(N, A)",
        "OMEGA",
        1,
    ),
    # the tutorial's style: U{n}' speeds and a scaled kinematical equation
    "tutorial_u_speeds": (
        "Variables U{1}'\nVariables THETA'",
        "THETA' = U1/L",
        "W_A_N> = THETA'*A3>",
        "U1",
        sp.Symbol("L", real=True) ** -1,
    ),
    # MOTIONVARIABLES without the prime, U names (bicycle scripts)
    "motionvariables_u": (
        "MotionVariables U{1}'\nVariables THETA'",
        "THETA' = U1",
        "Angvel(N, A)",
        "U1",
        1,
    ),
    # the kinematical equation solved for (RollingDiscKane.al)
    "solved_kinematical_equation": (
        "Variables THETA'\nMotionVariables' OMEGA'",
        "KD = THETA' - 2*OMEGA\nSolve(KD, THETA')",
        "Angvel(N, A)",
        "OMEGA",
        2,
    ),
    # arrays of names (DoublePendulum.al): THETA1, OMEGA1
    "indexed_names": (
        "Variables THETA{1}'\nMotionVariables' OMEGA{1}'",
        "THETA1' = OMEGA1",
        "Angvel(N, A)",
        "OMEGA1",
        1,
    ),
    # second order: the coordinate's derivative is the speed
    "second_order_motion_variable": (
        "MotionVariables' THETA''",
        "",
        "Angvel(N, A)",
        "THETA'",
        1,
    ),
}


def _script(style: str) -> str:
    decl, kde, w, _speed, _c = STYLES[style]
    text = COMMON.format(decl=decl, kde=kde, w=w)
    if style == "indexed_names":
        text = text.replace("THETA)", "THETA1)")
    return text


def _load(text: str, tmp_path, name: str):
    result = convert(text, f"{name}.al")
    return load_module(result.code, tmp_path, name)


def _points(mod, names, n=5):
    rng = random.Random(9)
    out = []
    for _ in range(n):
        out.append({mod.al.symbol(k): rng.uniform(0.3, 2.0) for k in names})
    return out


@pytest.mark.parametrize("style", sorted(STYLES))
def test_each_declaration_style_gives_the_pendulum(style, tmp_path):
    mod = _load(_script(style), tmp_path, f"pend_{style}")
    _decl, _kde, _w, speed, c = STYLES[style]
    theta_name = "THETA1" if style == "indexed_names" else "THETA"
    theta = mod.al.symbol(theta_name)
    u = mod.al.symbol(speed)
    G, L, M, I = (mod.al.symbol(k) for k in ("G", "L", "M", "I"))  # noqa: E741
    assert mod.al.model.generalized_speeds() == [u]
    zero = mod.AUTOLEV["ZERO"]
    assert zero.shape == (1, 1)
    a = sp.Symbol("a")  # u'
    got = mod.al.resolve(zero[0]).subs(sp.Derivative(u, t), a)
    expected = -(c**2) * (I + M * L**2 / 4) * a - c * M * G * L / 2 * sp.sin(theta)
    assert got != 0
    for point in _points(mod, ["G", "L", "M", "I", theta_name]):
        point[a] = 0.7
        point[u] = 1.3
        x = complex(got.subs(point).evalf())
        y = complex(expected.subs(point).evalf())
        assert abs(x - y) <= 1e-9 * max(1.0, abs(y)), (style, x, y)


def test_issue_script_prints_the_speed_and_solves(tmp_path):
    """Why 2 of issue 9: W_A_N> in terms of OMEGA; Solve(Zero, OMEGA')."""
    text = _script("variables_and_motionvariables") + "Solve(Zero, OMEGA')\n"
    mod = _load(text, tmp_path, "pend_issue")
    A, N = mod.A, mod.N
    omega, theta = mod.al.symbol("OMEGA"), mod.al.symbol("THETA")
    G, L, M, I = (mod.al.symbol(k) for k in ("G", "L", "M", "I"))  # noqa: E741
    shown = [r for r in mod.al.responses if r.label == "W_A_N>"]
    assert len(shown) == 1
    assert (shown[0].value - omega * A.z).express(N).simplify() == 0 * N.x
    solved = mod.AUTOLEV["OMEGA'"]
    expected = -M * G * L / 2 * sp.sin(theta) / (I + M * L**2 / 4)
    assert sp.simplify(solved - expected) == 0


def test_no_speeds_is_an_error_not_a_zero(tmp_path):
    """Variables THETA'' alone names no generalized speed: Fr() refuses."""
    text = COMMON.format(decl="Variables THETA''", kde="", w="Angvel(N, A)")
    with pytest.raises(ValueError, match="generalized speeds"):
        _load(text, tmp_path, "pend_nospeeds")


def test_speed_nothing_depends_on_is_an_error(tmp_path):
    """OMEGA declared as a speed but the kinematical equation forgotten."""
    text = COMMON.format(
        decl="Variables THETA'\nMotionVariables' OMEGA'", kde="", w="Angvel(N, A)"
    )
    with pytest.raises(ValueError, match="OMEGA"):
        _load(text, tmp_path, "pend_forgotten")


DOUBLE = """
Newtonian N
Bodies A, B
Constants G, L{2}, M{2}, I{2}
Variables THETA{2}'
MotionVariables' OMEGA{2}'
Mass A=M1, B=M2
Inertia A, 0, 0, I1
Inertia B, 0, 0, I2
Simprot(N, A, 3, THETA1)
Simprot(A, B, 3, THETA2)
THETA1' = OMEGA1
THETA2' = OMEGA2
P_NO_AO> = L1/2*A2>
P_NO_BO> = L1*A2> + L2/2*B2>
Angvel(N, A)
Angvel(N, B)
V_AO_N> = Dt(P_NO_AO>, N)
V_BO_N> = Dt(P_NO_BO>, N)
Gravity(G*N2>)
Zero = Fr() + FrStar()
Solve(Zero, OMEGA1', OMEGA2')
"""


def test_double_pendulum_matches_sympy_kanes_method(tmp_path):
    """Two motion-variable speeds (DoublePendulum.al's style): the solved
    OMEGA1', OMEGA2' equal sympy's KanesMethod at random states."""
    mod = _load(DOUBLE, tmp_path, "double_pendulum")
    km = mod.al.model.kanes_method()
    w1, w2 = mod.al.symbol("OMEGA1"), mod.al.symbol("OMEGA2")
    assert list(km.u) == [w1, w2]
    assert list(km.q) == [mod.al.symbol("THETA1"), mod.al.symbol("THETA2")]
    names = ["G", "L1", "L2", "M1", "M2", "I1", "I2", "THETA1", "THETA2"]
    names += ["OMEGA1", "OMEGA2"]
    for point in _points(mod, names, n=3):
        mm = km.mass_matrix_full.subs(point).evalf()
        ff = km.forcing_full.subs(point).evalf()
        xdot = mm.LUsolve(ff)
        for k, name in ((2, "OMEGA1'"), (3, "OMEGA2'")):
            ours = complex(mod.al.resolve(mod.AUTOLEV[name]).subs(point).evalf())
            assert abs(ours - complex(xdot[k])) <= 1e-9 * max(1, abs(ours)), name


DISC = """
Newtonian N
Frames A, B
Bodies C
Points CN
Constants M, G, R, I, J
Variables X', Y', PSI', PHI', TH'
MotionVariables' W{3}'
Mass C=M
Inertia C, I, J, I
Simprot(N, A, 3, PSI)
Simprot(A, B, 1, PHI)
Simprot(B, C, 2, TH)
W_C_N> = W1*B1> + W2*B2> + W3*B3>
WQ> = PSI'*A3> + PHI'*B1> + TH'*B2>
KD = [Dot(WQ> - W_C_N>, B1>); Dot(WQ> - W_C_N>, B2>); Dot(WQ> - W_C_N>, B3>)]
Solve(KD, PSI', PHI', TH')
P_CN_CO> = -R*B3>
V_CO_N> = Cross(W_C_N>, P_CN_CO>)
VQ> = X'*N1> + Y'*N2> + Cross(PSI'*A3> + PHI'*B1>, -R*B3>)
E1 = Dot(VQ> - V_CO_N>, N1>)
E2 = Dot(VQ> - V_CO_N>, N2>)
Solve([E1; E2], X', Y')
Gravity(G*A3>)
Zero = Fr() + FrStar()
"""


def test_rolling_disc_matches_sympy_kanes_method(tmp_path):
    """A rolling disc (RollingDiscKane.al's style): speeds W1..W3 declared as
    motion variables, coordinates from solved kinematical equations."""
    mod = _load(DISC, tmp_path, "rolling_disc")
    ws = [mod.al.symbol(f"W{k}") for k in (1, 2, 3)]
    assert mod.al.model.generalized_speeds() == ws
    km = mod.al.model.kanes_method()
    names = ["X", "Y", "PSI", "PHI", "TH"]
    assert list(km.q) == [mod.al.symbol(n) for n in names]
    assert list(km.u) == ws
    accels = [sp.Derivative(w, t) for w in ws]
    zero = sp.Matrix([mod.al.resolve(e) for e in mod.AUTOLEV["ZERO"]])
    coef = zero.jacobian(accels)
    rest = zero.subs(dict.fromkeys(accels, 0))
    for point in _points(mod, ["M", "G", "R", "I", "J", *names, "W1", "W2", "W3"]):
        mm = km.mass_matrix_full.subs(point).evalf()
        ff = km.forcing_full.subs(point).evalf()
        xdot = mm.LUsolve(ff)
        ours = coef.subs(point).evalf().LUsolve(-rest.subs(point).evalf())
        for k in range(3):
            a, b = complex(ours[k]), complex(xdot[5 + k])
            assert abs(a - b) <= 1e-9 * max(1, abs(b)), (k, a, b)
