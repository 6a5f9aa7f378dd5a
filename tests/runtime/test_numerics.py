"""Tests for the numerical CODE jobs (al2py_runtime.jobs.numerics, .jobs, .cli).

Workspaces are built by hand, as a generated module would build them, from
the tutorial's scripts and printed equations.
"""

from __future__ import annotations

import math
import re
import sys

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import Workspace, t
from al2py_runtime.jobs.run import NumericsError, output_times
from scipy.integrate import solve_ivp

# ------------------------------------------------------------------ scripts


def odexy(columns=None) -> Workspace:
    """tutor's odexy; ``columns(x, y)`` gives other Output columns."""
    ws = Workspace("odexy.al")
    a, b = ws.constants("a", "b")
    x, y = ws.variables("x'", "y'")
    ws.assign("x'", -a * x - b * y, line=7)
    ws.assign("y'", -y - t * x**2, line=8)
    ws.numerics.input({"A": 1, "B": 2, "X": 2, "Y": 3}, line=9)
    ws.numerics.input({"TINITIAL": 0, "TFINAL": 5, "INTEGSTP": 0.1}, line=10)
    ws.numerics.output(
        (
            columns(x, y)
            if columns
            else [
                ("T", t, None),
                ("X", x, None),
                ("Y", y, None),
                ("X'", ws.value("X'"), None),
                ("Y'", ws.value("Y'"), None),
            ]
        ),
        line=11,
    )
    ws.numerics.code("ODE", file="odexy.c", line=12)
    return ws


def katy() -> Workspace:
    ws = Workspace("katy.al")
    x, y = ws.variables("x", "y")
    a, r = ws.constants("a", "r")
    ws.assign("eqn[1]", x**2 + y**2 - r)
    eqn = ws.assign("eqn[2]", y - a * sp.sin(x))
    ws.numerics.input({"A": 1.0, "R": 1.0})
    ws.numerics.input({"X": 0.5, "Y": 0.5})
    ws.numerics.code("NONLINEAR", eqs=eqn, unknowns=[x, y], file="katy.m")
    return ws


def becky() -> Workspace:
    ws = Workspace("becky.al")
    x, y = ws.variables("x", "y")
    a11, a12, a21, a22, b1, b2 = ws.constants("a11", "a12", "a21", "a22", "b1", "b2")
    ws.assign("eqn[1]", a11 * x + a12 * y - b1)
    eqn = ws.assign("eqn[2]", a21 * x + a22 * y - b2)
    ws.numerics.input({"A11": 1, "A12": 2, "A21": 3, "A22": 4, "B1": 5, "B2": 6})
    ws.numerics.code("ALGEBRAIC", eqs=eqn, unknowns=[x, y], file="becky.for")
    return ws


def tutor3() -> Workspace:
    ws = Workspace("tutor3.al")
    qa, qb, qc = ws.variables("QA", "QB", "QC")
    la, lb, lc, ln = ws.constants("LA", "LB", "LC", "LN")
    ws.assign("CONFIG[1]", la * sp.cos(qa) + lb * sp.cos(qb) - lc * sp.cos(qc))
    config = ws.assign(
        "CONFIG[2]", la * sp.sin(qa) + lb * sp.sin(qb) - lc * sp.sin(qc) - ln
    )
    ws.numerics.unit_system("kg", "meter", "sec")
    ws.numerics.input(
        {"LA": (1, "m"), "LB": (2, "m"), "LC": (2, "m"), "LN": (1, "m")}, line=31
    )
    ws.numerics.input(
        {"QA": (30, "deg"), "QB": (60, "deg"), "QC": (20, "deg")}, line=32
    )
    ws.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=33)
    ws.numerics.code(
        "NONLINEAR", eqs=config, unknowns=[qb, qc], file="tutor3.for", line=36
    )
    return ws


def tutor4() -> Workspace:
    ws = Workspace("tutor4.al")
    ws.variables("U1", "U2")
    qa, qb = ws.variables("QA'", "QB'")
    g, la, lb, k, lo, mp, mq = ws.constants("G", "LA", "LB", "K", "LO", "MP", "MQ")
    loq = ws.assign("LOQ", sp.sqrt(la**2 + lb**2 + 2 * la * lb * sp.cos(qa - qb)))
    stretch = ws.assign("STRETCH", loq - lo)
    zero = ws.assign(
        "ZERO",
        sp.Matrix(
            [
                k * lb * sp.sin(qa - qb) * stretch / loq - g * (mp + mq) * sp.sin(qa),
                -g * mq * sp.sin(qb) - k * la * sp.sin(qa - qb) * stretch / loq,
            ]
        ),
    )
    ws.numerics.unit_system("kg", "meter", "sec")
    ws.numerics.input(
        {
            "G": (9.81, "m/sec^2"),
            "LA": (1, "m"),
            "LB": (2, "m"),
            "LO": (1, "m"),
            "K": (200, "n/m"),
            "MP": (10, "kg"),
            "MQ": (20, "kg"),
        }
    )
    ws.numerics.input({"QA": (-30, "deg"), "QB": (30, "deg")})
    ws.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07})
    ws.numerics.code("NONLINEAR", eqs=zero, unknowns=[qa, qb], file="tutor4.c", line=52)
    return ws


def tutor6(*, digits: int | None = None) -> Workspace:
    """tutor6 from the equations printed in tutorial §5.6, plus an energy
    check ECHECK = KE + PE - WORK whose WORK' (power of the damper and of FP)
    is integrated alongside, as NiCheck does."""
    ws = Workspace("tutor6.al")
    u1, u2 = ws.variables("U1'", "U2'")
    qa, qb = ws.variables("QA'", "QB'")
    ws.variables("F1", "F2")
    g, la, lb = ws.constants("G", "LA", "LB")
    k, lo = ws.constants("K", "LO")
    c, d = ws.constants("C", "D")
    stretch = ws.specified("STRETCH'")
    fp = ws.specified("FP")
    ws.assign("FP", -d * qa.diff(t))
    mp, mq = ws.constants("MP", "MQ")
    ws.assign("QA'", u1 / la)
    ws.assign("QB'", u2 / lb)
    loq = ws.assign("LOQ", sp.sqrt(la**2 + lb**2 + 2 * la * lb * sp.cos(qa - qb)))
    ws.assign("STRETCH", loq - lo)
    ws.assign("STRETCH'", sp.sin(qa - qb) * (la * u2 - lb * u1) / loq)
    sdot = stretch.diff(t)
    s = sp.sin(qa - qb)
    zero1 = (
        fp
        + s * (lb**2 * (k * stretch + c * sdot) / loq - mq * u2**2) / lb
        - g * (mp + mq) * sp.sin(qa)
        - (mp + mq) * u1.diff(t)
        - mq * sp.cos(qa - qb) * u2.diff(t)
    )
    zero2 = (
        mq * s * u1**2 / la
        - g * mq * sp.sin(qb)
        - mq * u2.diff(t)
        - mq * sp.cos(qa - qb) * u1.diff(t)
        - la * (k * stretch + c * sdot) * s / loq
    )
    ws.assign("ZERO", sp.Matrix([zero1, zero2]))
    work = ws.variables("NICHECK_WORK'")  # as NiCheck() declares it
    ws.assign("NICHECK_WORK'", fp * u1 - c * sdot**2)
    ke = (mp * u1**2 + mq * (u1**2 + u2**2 + 2 * u1 * u2 * sp.cos(qa - qb))) / 2
    pe = -g * (mp * la * sp.cos(qa) + mq * (la * sp.cos(qa) + lb * sp.cos(qb)))
    echeck = ws.assign("ECHECK", ke + pe + k * stretch**2 / 2 - work)
    ws.numerics.unit_system("kg", "meter", "sec")
    ws.numerics.input({"G": (9.81, "m/sec^2"), "LA": (1, "m"), "LB": (2, "m")}, line=70)
    ws.numerics.input({"LO": (1, "m"), "K": (200, "n/m")}, line=71)
    ws.numerics.input({"C": (300, "n*sec/m"), "D": (300, "n*sec/m")}, line=72)
    ws.numerics.input({"MP": (10, "kg"), "MQ": (20, "kg")}, line=73)
    ws.numerics.input({"QA": (20, "deg"), "QB": (60, "deg")}, line=74)
    ws.numerics.input({"U1": (0, "rad/sec"), "U2": (0, "rad/sec")}, line=75)
    ws.numerics.input({"TINITIAL": 0, "TFINAL": 20}, line=76)
    ws.numerics.input({"INTEGSTP": 0.2, "PRINTINT": 1}, line=77)
    ws.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=78)
    ws.numerics.output(
        [
            ("T", t, None),
            ("STRETCH", stretch, "m"),
            ("QA", qa, "deg"),
            ("QB", qb, "deg"),
            ("ECHECK", echeck, "joules"),
        ],
        line=80,
    )
    if digits is not None:
        ws.settings.set("Digits", digits)
    ws.numerics.code("DYNAMICS", file="tutor6.c", line=87)
    return ws


# ------------------------------------------------------------------- tests


def test_recording_does_no_work(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    import scipy.integrate

    def boom(*args, **kwargs):  # pragma: no cover - must not be called
        raise AssertionError("integration at record time")

    monkeypatch.setattr(scipy.integrate, "solve_ivp", boom)
    ws = tutor6()
    assert capsys.readouterr() == ("", "")
    assert list(tmp_path.iterdir()) == []
    assert [j.kind for j in ws.numerics.jobs] == ["DYNAMICS"]
    assert ws.numerics.jobs[0].stem == "tutor6"


def test_odexy():
    result = odexy().numerics.run()
    table = result.tables[0]
    assert table.names == ["T", "X", "Y", "X'", "Y'"]
    assert len(table) == 51  # every INTEGSTP when PRINTINT is not given
    assert result["T"][-1] == 5
    assert result["X"][-1] == pytest.approx(0.497489, abs=5e-7)
    assert result["Y"][-1] == pytest.approx(-0.491040, abs=5e-7)

    # independent check: the same equations, integrated far more tightly
    ref = solve_ivp(
        lambda tt, v: [-v[0] - 2 * v[1], -v[1] - tt * v[0] ** 2],
        (0, 5),
        [2, 3],
        method="Radau",
        rtol=1e-12,
        atol=1e-12,
        t_eval=table["T"],
    )
    assert np.allclose(result["X"], ref.y[0], atol=1e-6)
    assert np.allclose(result["Y"], ref.y[1], atol=1e-6)
    # output derivatives come from the right-hand sides
    x, y, tt = result["X"], result["Y"], result["T"]
    assert np.allclose(result["X'"], -x - 2 * y)
    assert np.allclose(result["y'"], -y - tt * x**2)


def test_katy_nonlinear():
    result = katy().numerics.run()
    assert result["X"][0] == pytest.approx(0.739085, abs=1e-6)
    assert result["Y"][0] == pytest.approx(0.673612, abs=1e-6)
    assert result.solution_lines() == ["X = 0.7390851", "Y = 0.673612"]


def test_becky_algebraic():
    result = becky().numerics.run()
    assert result["x"][0] == pytest.approx(-4)
    assert result["y"][0] == pytest.approx(4.5)
    assert result.tables[0].names == ["X", "Y"]


def test_algebraic_must_be_linear():
    ws = Workspace("bad.al")
    x, y = ws.variables("x", "y")
    eqs = ws.assign("E", sp.Matrix([x * y - 1, x + y]))
    ws.numerics.code("ALGEBRAIC", eqs=eqs, unknowns=[x, y], file="bad.m")
    with pytest.raises(NumericsError, match="not linear in X, Y; use CODE Nonlinear"):
        ws.numerics.run()


def test_tutor3_nonlinear_in_degrees():
    ws = tutor3()
    result = ws.numerics.run()
    assert result["QB"][0] == pytest.approx(74.4775, abs=1e-4)
    assert result["QC"][0] == pytest.approx(45.5225, abs=1e-4)
    assert result.solution_units == {"QB": "deg", "QC": "deg"}
    assert result.solution_lines() == ["QB = 74.47751 deg", "QC = 45.52249 deg"]
    assert ws.numerics.jobs[0].eqs_name == "CONFIG"


@pytest.mark.parametrize(
    ("guess", "solution"),
    [
        ((-30, 30), (-50.1492, 35.1548)),
        ((30, -30), (50.1492, -35.1548)),
        ((20, 60), (0.0, 0.0)),
    ],
)
def test_tutor4_guesses(guess, solution):
    result = tutor4().numerics.run(qa=guess[0], QB=guess[1])  # overrides in Input units
    assert result["QA"][0] == pytest.approx(solution[0], abs=1e-4)
    assert result["QB"][0] == pytest.approx(solution[1], abs=1e-4)


def test_nonconvergence_names_the_residual():
    ws = Workspace("nope.al")
    x = ws.variables("x")
    eqs = ws.assign("EQ", sp.Matrix([x**2 + 1]))
    ws.numerics.input({"X": 0.5})
    ws.numerics.code("NONLINEAR", eqs=eqs, unknowns=[x], file="nope.m", line=4)
    with pytest.raises(NumericsError) as info:
        ws.numerics.run()
    message = str(info.value)
    assert "CODE Nonlinear nope.m (line 4)" in message
    assert "no solution found" in message
    assert "residual |EQ[1]| = 1" in message
    assert "\n" not in message


def test_tutor6_dynamics():
    ws = tutor6()
    result = ws.numerics.run()
    (table,) = result.tables
    assert table.names == ["T", "STRETCH", "QA", "QB", "ECHECK"]
    assert [c.unit for c in table.columns] == [None, "m", "deg", "deg", "joules"]
    # printInt = 1 integration step of 0.2 s (Autolev's Print-Integer)
    assert len(table) == 101
    assert np.allclose(result["T"], np.linspace(0, 20, 101))
    assert result["QA"][0] == pytest.approx(20)
    assert result["QB"][0] == pytest.approx(60)
    # the tutorial's own printed equations come to rest here (its text swaps
    # both signs)
    assert result["QA"][-1] == pytest.approx(50.123, abs=1e-3)
    assert result["QB"][-1] == pytest.approx(-35.150, abs=1e-3)
    # the energy check stays constant while WORK is integrated alongside
    assert np.ptp(result["ECHECK"]) < 1e-5
    assert "NICHECK_WORK" in result.states
    assert result.notes == []  # NiCheck's work variable starts at 0 silently
    # stretch is the RHS of STRETCH in metres
    qa, qb = np.radians(result["QA"]), np.radians(result["QB"])
    loq = np.sqrt(1 + 4 + 4 * np.cos(qa - qb))
    assert np.allclose(result["STRETCH"], loq - 1)


def test_tutor6_overrides_in_input_units():
    ws = tutor6()
    result = ws.numerics.run(QA=30, tfinal=2, printint=5)  # every 5 steps of 0.2 s
    assert np.allclose(result["T"], [0, 1, 2])
    with pytest.raises(NumericsError, match="whole number of integration steps"):
        ws.numerics.run(printint=0.5)
    assert result["QA"][0] == pytest.approx(30)
    with pytest.raises(NumericsError, match="not an Input or a declared name"):
        ws.numerics.run(NOPE=1)
    with pytest.raises(NumericsError, match="defined by an equation"):
        ws.numerics.run(ECHECK=1)


def _spring_with_dependent_speed() -> Workspace:
    """Two carts moving together (U2 = U1 is a dependent speed), a spring on
    the first; F = the force the second cart needs (auxiliary, uses U1')."""
    ws = Workspace("carts.al")
    u1, u2 = ws.variables("U1'", "U2'")
    x1, x2 = ws.variables("X1'", "X2'")
    m1, m2, k = ws.constants("M1", "M2", "K")
    ws.assign("U2", u1)
    ws.assign("U2'", u1.diff(t))
    ws.assign("X1'", u1)
    ws.assign("X2'", u2)
    ws.assign("ZERO", sp.Matrix([-k * x1 - m1 * u1.diff(t) - m2 * u2.diff(t)]))
    f = ws.variables("F")
    ws.assign("F", m2 * u1.diff(t))
    ws.numerics.input({"M1": 1, "M2": 3, "K": 4, "X1": 0.5, "X2": 0.5, "TFINAL": 3})
    ws.numerics.input(
        {"INTEGSTP": 0.05, "PRINTINT": 10, "ABSERR": 1e-9, "RELERR": 1e-9}
    )
    ws.numerics.output(
        [("T", t, None), ("X1", x1, None), ("X2", x2, None), ("U2", u2, None)]
    )
    ws.numerics.output([("T", t, None), ("F", f, "n")])
    ws.numerics.code("DYNAMICS", file="carts.for")
    return ws


def test_dependent_speed_and_auxiliary_force():
    result = _spring_with_dependent_speed().numerics.run()
    tt = result["T"]
    omega = math.sqrt(4 / 4)
    assert set(result.states) == {"T", "U1", "X1", "X2"}  # U2 is not integrated
    assert np.allclose(result["X1"], 0.5 * np.cos(omega * tt), atol=1e-7)
    assert np.allclose(result["X2"], result["X1"], atol=1e-7)
    assert np.allclose(result["U2"], -0.5 * omega * np.sin(omega * tt), atol=1e-7)
    # F = M2*U1' = -M2*K*X1/(M1+M2)
    assert np.allclose(result.tables[1]["F"], -3 * result["X1"], atol=1e-6)


def test_second_order_variable_and_initial_derivative():
    ws = Workspace("osc.al")
    x = ws.variables("X''")
    w = ws.constants("W")
    ws.assign("X''", -(w**2) * x)
    ws.numerics.input({"W": 2, "X": 1, "X'": (1, "m/sec"), "TFINAL": (1, "sec")})
    ws.numerics.output([("T", t, None), ("X", x, "cm"), ("XD", x.diff(t), None)])
    ws.numerics.code("ODE", file="osc.c")
    result = ws.numerics.run()
    tt = result["T"]
    exact = np.cos(2 * tt) + np.sin(2 * tt) / 2
    assert len(tt) == 101
    assert np.allclose(result["X"], 100 * exact, atol=1e-4)
    assert np.allclose(result["XD"], -2 * np.sin(2 * tt) + np.cos(2 * tt), atol=1e-6)
    changed = ws.numerics.run({"X'": 0})
    assert np.allclose(changed["X"], 100 * np.cos(2 * tt), atol=1e-4)


def test_zero_not_linear_in_accelerations():
    ws = Workspace("bad.al")
    u = ws.variables("U'")
    ws.assign("ZERO", sp.Matrix([u.diff(t) ** 2 - 1]))
    ws.numerics.code("DYNAMICS", file="bad.c")
    with pytest.raises(NumericsError, match="not linear in U'"):
        ws.numerics.run()


def test_code_takes_a_snapshot():
    ws = Workspace("snap.al")
    x = ws.variables("X'")
    a = ws.constants("A")
    ws.assign("X'", -a * x)
    e = ws.assign("E", 2 * x)
    ws.numerics.input({"A": 1, "X": 1, "TFINAL": 1, "INTEGSTP": 0.1, "PRINTINT": 5})
    ws.numerics.output([("T", t, None), ("E", e, None)])
    ws.numerics.code("ODE", file="snap.m")
    ws.assign("E", 100 * x)  # after CODE: does not change the job
    ws.assign("X'", 0)
    ws.numerics.input({"A": 5})
    result = ws.numerics.run()
    assert np.allclose(result["E"], 2 * np.exp(-np.array([0, 0.5, 1])), atol=1e-7)


def _defaults() -> Workspace:
    ws = Workspace("defaults.al")
    x = ws.variables("X'", line=1)
    g = ws.constants("G", line=2)
    ws.assign("G", sp.Rational(981, 100))  # Constants G = 9.81
    h, _k, j = ws.constants("H", "K", "J", line=3)
    ws.settings.set("AutoRHS", "OFF")  # keep G in X' (AutoRHS ON substitutes 9.81)
    ws.assign("X'", g + h + j)
    ws.numerics.output([("T", t, None), ("X", x, None)])
    ws.numerics.code("ODE", file="defaults.m", line=9)
    return ws


def test_missing_constants_are_named_before_code_is_generated(monkeypatch):
    """Every constant the job needs without a value, with its line, at once;
    and no code generated (the backend is never reached)."""
    ws = _defaults()
    calls = []
    monkeypatch.setattr(
        "al2py_runtime.jobs.backends.compile_dynamics", lambda *a: calls.append(a)
    )
    message = (
        "CODE Ode defaults.m (line 9): no value for H (declared on line 3), "
        "J (declared on line 3). Give them with Input"
    )
    with pytest.raises(NumericsError, match=re.escape(message)):
        ws.numerics.run()
    with pytest.raises(NumericsError, match=re.escape(message)):
        ws.numerics.ode_function()
    assert calls == []  # K is not needed; X starts at 0 as in Autolev
    monkeypatch.undo()
    assert ws.numerics.run(H=1, J=2)["X"][-1] == pytest.approx(128.1)
    monkeypatch.setenv("AL2PY_ZERO_MISSING", "1")
    assert ws.numerics.run()["X"][-1] == pytest.approx(98.1)


def test_constants_with_values_and_missing_inputs_default_to_zero():
    ws = _defaults()
    result = ws.numerics.run(zero_missing=True)
    assert result["X"][-1] == pytest.approx(98.1)  # TFINAL defaults to 10
    assert len(result["T"]) == 101
    assert "H has no Input value; using 0" in result.notes
    assert "X has no Input value; using 0" in result.notes
    # a constant's value can still be changed from the command line
    assert ws.numerics.run(G=1, H=1, J=0)["X"][-1] == pytest.approx(20)


def test_override_of_a_substituted_constant_is_noted():
    ws = Workspace("autorhs.al")
    ws.variables("X'")
    g = ws.constants("G")
    ws.assign("G", 2)
    ws.assign("X'", g)  # AutoRHS ON: X' = 2
    ws.numerics.input({"X": 0, "TFINAL": 1})
    ws.numerics.code("ODE", file="autorhs.m")
    result = ws.numerics.run(G=5)
    assert result.states["X"][-1] == pytest.approx(2)
    assert any(n.startswith("G does not appear") for n in result.notes)


def test_algebraic_sweep_like_tutor2():
    ws = Workspace("tutor2.al")
    ws.settings.set("Degrees", "ON")
    phi = ws.variables("PHI")
    distance = ws.assign(
        "DISTANCE",
        sp.sqrt(
            sp.Rational(17, 18)
            - sp.Rational(2, 9) * sp.cos(phi)
            - sp.Rational(1, 18) * sp.sin(phi)
        ),
    )
    ws.numerics.unit_system("kg", "meter", "sec")
    ws.numerics.output(
        [("PHI", phi, "degrees"), ("DISTANCE", distance, "meters")], line=52
    )
    ws.numerics.code(
        "ALGEBRAIC", sweep=(phi, "deg", 0, 360, 1), file="tutor2.c", line=55
    )
    result = ws.numerics.run()
    (table,) = result.tables
    assert len(table) == 361
    assert np.allclose(table["PHI"], np.arange(361))
    i = int(np.argmin(table["DISTANCE"]))
    assert table["PHI"][i] == 14
    assert table["DISTANCE"][i] == pytest.approx(0.8458, abs=1e-4)
    assert result.notes == []


def test_output_times():
    assert np.allclose(output_times(0, 20, 1), np.arange(21))
    assert np.allclose(output_times(0, 1, 0.3), [0, 0.3, 0.6, 0.9, 1.0])
    assert np.allclose(output_times(0, 5, 0.1), np.linspace(0, 5, 51))
    assert np.allclose(output_times(2, 0, 1), [2, 1, 0])


def test_write_files_with_digits_of_code_statement(tmp_path):
    ws = tutor6(digits=5)
    ws.settings.set("Digits", 2)  # after CODE: the job keeps 5
    result = ws.numerics.run(tfinal=3, printint=5)  # a row every 5*0.2 s
    (path,) = result.write(tmp_path)
    assert path.name == "tutor6.1"
    lines = path.read_text().splitlines()
    assert lines[0] == "% FILE: tutor6.1"
    assert lines[2].split() == ["%", "T", "STRETCH", "QA", "QB", "ECHECK"]
    assert lines[3].split() == ["%", "(sec)", "(m)", "(deg)", "(deg)", "(joules)"]
    rows = [line for line in lines if line.strip() and not line.startswith("%")]
    assert len(rows) == 4
    assert rows[0].split()[2] == "2.0000E+01"  # QA = 20 deg, 5 digits
    data = np.loadtxt(path, comments="%")
    assert np.allclose(data, result.tables[0].data, rtol=1e-4)


def test_plot(tmp_path):
    pytest.importorskip("matplotlib")
    result = odexy().numerics.run()
    (path,) = result.save_plots(tmp_path)
    assert path.name == "odexy.1.png"
    assert path.read_bytes()[:4] == b"\x89PNG"


def test_plot_axes_are_time_else_the_row():
    """Plots read against time: the table's T column wherever it stands, else
    the job's time at each row; a job without time plots against the row."""
    result = odexy().numerics.run()
    x, label, ys = result.abscissa(result.tables[0])
    assert label == "T (sec)" and ys == [1, 2, 3, 4]
    assert np.allclose(x, np.arange(0, 5.0001, 0.1))
    time = x
    result = odexy(lambda x, y: [("X", x, None), ("T", t, "s")]).numerics.run()
    x, label, ys = result.abscissa(result.tables[0])
    assert label == "T (s)" and ys == [0]  # T is the second column here
    assert np.allclose(x, time)
    result = odexy(lambda x, y: [("Y", y, None)]).numerics.run()
    x, label, ys = result.abscissa(result.tables[0])  # no T column: the job's
    assert label == "T (sec)" and ys == [0] and np.allclose(x, time)  # time
    solved = katy().numerics.run()
    x, label, ys = solved.abscissa(solved.tables[0])
    assert label == "row (output step)" and list(x) == [1]
    assert ys == list(range(len(solved.tables[0].columns)))


def test_plot_without_matplotlib(tmp_path, monkeypatch):
    result = odexy().numerics.run()
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    monkeypatch.setitem(sys.modules, "matplotlib.figure", None)
    monkeypatch.setitem(sys.modules, "matplotlib.backends.backend_agg", None)
    with pytest.raises(NumericsError, match="pip install"):
        result.save_plots(tmp_path)
    with pytest.raises(NumericsError, match="pip install"):
        result.plot()


# --------------------------------------------------------------------- main

SOURCE = ["% File: tutor3.al", "Variables QA, QB, QC"]


def test_main_help(capsys):
    ws = tutor3()
    assert ws.main(SOURCE, ["--help"]) == 0
    out = capsys.readouterr().out
    assert "--set NAME=VALUE" in out
    assert "QA = 30 deg" in out


def test_main_runs_and_writes(tmp_path, capsys):
    ws = tutor3()
    code = ws.main(SOURCE, ["--outdir", str(tmp_path), "--set", "QB=50"])
    assert code == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0] == "(1) % File: tutor3.al"
    assert "QB = 74.47751 deg" in out
    assert "QC = 45.52249 deg" in out
    assert (tmp_path / "tutor3.1").exists()


def test_main_dynamics_with_tfinal(tmp_path, capsys):
    ws = tutor6()
    assert ws.main([], ["--outdir", str(tmp_path), "--tfinal", "4"]) == 0
    out = capsys.readouterr().out
    assert "tutor6.1 (21 rows: T, STRETCH, QA, QB, ECHECK)" in out
    data = np.loadtxt(tmp_path / "tutor6.1", comments="%")
    assert data.shape == (21, 5)


def test_main_no_run(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert tutor3().main(SOURCE, ["--no-run"]) == 0
    assert list(tmp_path.iterdir()) == []


def test_main_errors_exit_2(capsys):
    assert tutor3().main(SOURCE, ["--set", "NOPE=1"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("error: NOPE is not an Input")
    assert len(err.strip().splitlines()) == 1
    assert tutor3().main(SOURCE, ["--set", "QB"]) == 2
    assert "expected NAME=VALUE" in capsys.readouterr().err
    assert tutor3().main(SOURCE, ["--set", "QB=abc"]) == 2
    assert "not a number" in capsys.readouterr().err
    assert tutor3().main(SOURCE, ["--bogus"]) == 2


def test_main_nonconvergence_exit_2(tmp_path, capsys):
    ws = Workspace("nope.al")
    x = ws.variables("x")
    eqs = ws.assign("EQ", sp.Matrix([x**2 + 1]))
    ws.numerics.code("NONLINEAR", eqs=eqs, unknowns=[x], file="nope.m")
    assert ws.main([], ["--outdir", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "no solution found" in err
    assert "Traceback" not in err


def test_main_without_code_statement(capsys):
    ws = Workspace("plain.al")
    ws.constants("A")
    assert ws.main(["Constants A"], []) == 0
    assert capsys.readouterr().out == "(1) Constants A\n"
    assert ws.main(["Constants A"], ["--set", "A=1"]) == 2


def test_english_unit_system_converts_inputs_and_outputs(tmp_path):
    ws = Workspace("feet.al")
    x = ws.variables("X'")
    v = ws.constants("V")
    ws.assign("X'", v)
    ws.numerics.unit_system("slug", "ft", "sec")
    ws.numerics.input({"V": (1, "m/sec"), "X": (0, "m"), "TFINAL": (2, "sec")})
    ws.numerics.input({"INTEGSTP": 1, "PRINTINT": 1})
    ws.numerics.output(
        [("T", t, None), ("X", x, "m"), ("XFT", x, None), ("XIN", x, "in")]
    )
    ws.numerics.code("ODE", file="feet.m")
    result = ws.numerics.run(V=2)  # m/sec, the Input's unit
    assert np.allclose(result["X"], [0, 2, 4])
    assert np.allclose(result["XFT"], np.array([0, 2, 4]) / 0.3048)
    assert np.allclose(result["XIN"], np.array([0, 2, 4]) / 0.0254)
    assert np.allclose(result.states["X"], [0, 2, 4])  # in the Input's unit
    (path,) = result.write(tmp_path)
    assert "(sec)" in path.read_text()


def test_nonlinear_outputs_are_evaluated_at_the_solution():
    ws = katy()
    x, y = ws.symbol("X"), ws.symbol("Y")
    ws.numerics.output([("X", x, None), ("R2", x**2 + y**2, None), ("XD", x, "deg")])
    ws.numerics.code("NONLINEAR", eqs=ws["EQN"], unknowns=[x, y], file="katy2.m")
    result = ws.numerics.run(job="katy2")  # two jobs: run() names, not guesses
    (table,) = result.tables
    assert table.names == ["X", "R2", "XD"]
    assert table["R2"][0] == pytest.approx(1.0)
    assert table["XD"][0] == pytest.approx(math.degrees(0.739085), abs=1e-4)
    assert ws.numerics.jobs[-1].eqs_name == "EQN"


def test_algebraic_sweep_with_unknowns():
    ws = Workspace("sweep.al")
    x = ws.variables("X")
    s, a = ws.constants("S", "A")
    eqs = ws.assign("E", sp.Matrix([a * x - s]))
    ws.numerics.input({"A": 4})
    ws.numerics.code("ALGEBRAIC", eqs=eqs, unknowns=[x], sweep=(s, None, 0, 2, 0.5))
    result = ws.numerics.run()
    assert result.tables[0].names == ["S", "X"]
    assert np.allclose(result["X"], [0, 0.125, 0.25, 0.375, 0.5])
    assert np.allclose(result["S"], [0, 0.5, 1, 1.5, 2])
    assert result.notes == []


def test_division_by_a_defaulted_input_is_reported():
    ws = Workspace("div.al")
    ws.variables("X'")
    la = ws.constants("LA")
    ws.assign("X'", 1 / la)
    ws.numerics.code("ODE", file="div.m")
    with pytest.raises(
        NumericsError, match="at t = 0; LA has no value .* and was taken as 0"
    ):
        ws.numerics.run(zero_missing=True)


def test_singular_mass_matrix():
    ws = Workspace("sing.al")
    u = ws.variables("U'")
    m = ws.constants("M")
    ws.assign("ZERO", sp.Matrix([-m * u.diff(t) + 1]))
    ws.numerics.code("DYNAMICS", file="sing.c")
    with pytest.raises(NumericsError, match="matrix of U' in ZERO is singular"):
        ws.numerics.run(zero_missing=True)
    assert ws.numerics.run(M=2).states["U"][-1] == pytest.approx(5)


def test_expressions_reading_an_acceleration_through_intermediates():
    """A derivative that reads an acceleration only through an intermediate
    of an intermediate is computed after the solve, as one that reads it
    itself (``backends.reading``; run()'s split and the programs' both)."""
    import sympy as sp
    from al2py_runtime.jobs import backends

    ud, q, z1, z2, z3 = sp.symbols("ud q z1 z2 z3")
    inter = [(z1, 2 * ud), (z2, z1 + q), (z3, sp.sin(q))]
    exprs = [q + 1, z2 * q, z3, ud, z1]
    assert backends.reading(inter, exprs, {ud}) == [1, 3, 4]
    assert backends.reading(inter, exprs, set()) == []
    assert backends.reading(inter[1:], exprs, {ud}) == [3]  # z1 unknown
