"""Auxiliary speeds bring constraint forces into evidence (issue 23, point 4).

Two models of our own (tests/models/aux_*.al): a spherical pendulum whose
base point P1 has the auxiliary speeds U1..U3, and a planar pendulum with two
auxiliary speeds and a dependent one in one ``Constrain``.  In both,
``Constrain`` comes before the velocities, which are formed by ``Dt`` from
positions whose coordinates have ``Q1' = U1``...: the auxiliary speeds must
stay in those velocities (they give the partial velocities) and be zero in
the equations.

Checked against derivations that share nothing with al2py's:
- the equations of motion against sympy's ``KanesMethod`` set up by hand here
  (spherical) or the closed form (planar);
- the reaction forces against Newton's second law for the mass center,
  ``R = M*a_cm - M*g``, with the accelerations from those equations;
- ``run()``'s table: finite, energy (computed here) conserved, the force
  columns equal to Newton's law at each row;
- the same script with ``Constrain`` after the velocities (Autolev's
  tutorial order) gives the same ZERO, forces and table.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import t
from conftest import load_module
from sympy.physics.mechanics import (
    KanesMethod,
    Point,
    ReferenceFrame,
    RigidBody,
    inertia,
)

from al2py import convert

HERE = Path(__file__).resolve().parent
MODELS = HERE / "models"
D = sp.Derivative

CONSTRAINT_LINE = re.compile(r"^(AUXILIARY|DEPENDENT|Constrain)\b")


def _constrain_last(text: str) -> str:
    """The same script with the motion constraints moved after the
    velocities and accelerations (just before ``Gravity``)."""
    lines = text.splitlines()
    moved = [x for x in lines if CONSTRAINT_LINE.match(x)]
    rest = [x for x in lines if not CONSTRAINT_LINE.match(x)]
    at = next(i for i, x in enumerate(rest) if x.startswith("Gravity"))
    assert moved and at > 0
    return "\n".join(rest[:at] + moved + rest[at:]) + "\n"


def _load(tmp: Path, name: str, text: str):
    path = tmp / f"{name}.al"
    path.write_text(text)
    result = convert(text, str(path))
    return load_module(result.code, tmp, name)


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("aux")
    out = {}
    for stem in ("aux_spherical_pendulum", "aux_planar_pendulum"):
        text = (MODELS / f"{stem}.al").read_text()
        first = _load(tmp, stem, text)
        last = _load(tmp, stem + "_last", _constrain_last(text))
        out[stem] = (first, last)
    return out


def _symbols(mod, names):
    return [mod.al.symbol(n) for n in names.split()]


# ------------------------------------------------------------ spherical


def _spherical_by_hand(mod):
    """sympy's KanesMethod for the spherical pendulum, set up here: base P1
    with auxiliary speeds u1..u3, rod A (two rotations), gravity -G*N3>, the
    force R on P1.  Returns its mass matrix, forcing and auxiliary
    equations, Newton's law for R and the energy (P1 at rest)."""
    q4, q5, u1, u2, u3, u4, u5 = _symbols(mod, "Q4 Q5 U1 U2 U3 U4 U5")
    G, L, M, IA, IC, RX, RY, RZ = _symbols(mod, "G L M IA IC RX RY RZ")
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Axis", (q4, N.x))
    A = B.orientnew("A", "Axis", (q5, B.y))
    B.set_ang_vel(N, u4 * B.x)
    A.set_ang_vel(B, u5 * A.y)
    NO = Point("NO")
    NO.set_vel(N, 0)
    P1 = NO.locatenew("P1", 0)
    P1.set_vel(N, u1 * N.x + u2 * N.y + u3 * N.z)
    AO = P1.locatenew("AO", -L * A.z)
    AO.v2pt_theory(P1, N, A)
    rod = RigidBody("rod", AO, A, M, (inertia(A, IA, IA, IC), AO))
    loads = [(AO, -M * G * N.z), (P1, RX * N.x + RY * N.y + RZ * N.z)]
    km = KanesMethod(
        N,
        q_ind=[q4, q5],
        u_ind=[u4, u5],
        kd_eqs=[D(q4, t) - u4, D(q5, t) - u5],
        u_auxiliary=[u1, u2, u3],
    )
    km.kanes_equations([rod], loads)
    qdots = km.kindiffdict()
    eqs = [
        _plain(e.subs(qdots), [u4, u5])
        for e in (km.mass_matrix, km.forcing, km.auxiliary_eqs)
    ]
    # the actual motion: P1 at rest
    a_cm = AO.acc(N).subs({D(u, t): 0 for u in (u1, u2, u3)})
    a_cm = a_cm.subs(dict.fromkeys((u1, u2, u3), 0))
    v_cm = AO.vel(N).subs(dict.fromkeys((u1, u2, u3), 0))
    w = A.ang_vel_in(N)
    energy = (
        M * v_cm.dot(v_cm) / 2
        + w.dot(inertia(A, IA, IA, IC).dot(w)) / 2
        + M * G * AO.pos_from(NO).dot(N.z)
    )
    newton = [M * a_cm.dot(e) + M * G * N.z.dot(e) for e in (N.x, N.y, N.z)]
    newton = [_plain(e.subs(qdots), [u4, u5]) for e in newton]
    return eqs, newton, energy


def _acc(u):
    """A plain symbol for the derivative of speed ``u`` (so values can be
    substituted for the speeds)."""
    return sp.Symbol(f"{u.func.__name__}_dot")


def _plain(expr, speeds):
    table = {D(u, t): _acc(u) for u in speeds}
    return sp.sympify(expr).xreplace(table)


def _value(mod, name, speeds, at) -> float:
    return float(_plain(mod.AUTOLEV[name], speeds).subs(at))


def _udot(mm, ff, at) -> np.ndarray:
    m = np.array(mm.subs(at), dtype=float)
    f = np.array(ff.subs(at), dtype=float)
    return np.linalg.solve(m, f).ravel()


def _zero_udot(mod, speeds, at) -> np.ndarray:
    """The accelerations that al2py's arranged ZERO gives at ``at``."""
    rows = [_plain(z, speeds).subs(at) for z in mod.AUTOLEV["ZERO"]]
    mm, rhs = sp.linear_eq_to_matrix(rows, [_acc(u) for u in speeds])
    return _udot(mm, rhs, {})


def test_formed_velocity_keeps_auxiliary_speeds(models):
    """V_AO_N> = Dt(P_NO_AO>, N) after Constrain still has U1..U3: its
    partial velocity for U1 is N1> (the response shows them too), while
    their values are those of the actual motion: zero."""
    first, _ = models["aux_spherical_pendulum"]
    N, AO = first.N, first.al.model.point("AO")
    u1, u2, u3 = _symbols(first, "U1 U2 U3")
    v = first.al.model.vel(AO, N)
    for u, e in ((u1, N.x), (u2, N.y), (u3, N.z)):
        part = first.al.model.partials(v, u)
        assert (part - e).express(N).simplify() == 0 * N.x
    shown = [r for r in first.al.responses if r.label == "V_AO_N>"]
    assert len(shown) == 1
    assert all(shown[0].value.to_matrix(N).has(u) for u in (u1, u2, u3))
    assert first.AUTOLEV["U1"] == 0 and first.AUTOLEV["U3'"] == 0


def test_spherical_reaction_forces_against_newton_and_kanes_method(models):
    first, last = models["aux_spherical_pendulum"]
    eqs, newton, _energy = _spherical_by_hand(first)
    q4, q5, u4, u5 = _symbols(first, "Q4 Q5 U4 U5")
    consts = _symbols(first, "G L M IA IC")
    forces = _symbols(first, "RX RY RZ")
    accels = [_acc(u4), _acc(u5)]
    rng = np.random.default_rng(23)
    for _ in range(6):
        at = dict(zip(consts, rng.uniform(0.3, 2.0, 5), strict=True))
        at.update(zip([q4, q5, u4, u5], rng.uniform(-1.2, 1.2, 4), strict=True))
        udot = _udot(*eqs[:2], at)
        at_acc = dict(at) | dict(zip(accels, udot, strict=True))
        expected = [float(e.subs(at_acc)) for e in newton]
        # sympy's auxiliary equations, set up by hand, agree with Newton
        by_kane = sp.solve(list(eqs[2].subs(at_acc)), forces)
        assert np.allclose([float(by_kane[f]) for f in forces], expected)
        for mod in (first, last):
            assert mod.AUTOLEV["ZERO"].shape == (2, 1)
            assert np.allclose(_zero_udot(mod, [u4, u5], at), udot, rtol=1e-10)
            ours = [_value(mod, f, [u4, u5], at_acc) for f in ("RX", "RY", "RZ")]
            assert np.allclose(ours, expected, rtol=1e-10, atol=1e-12), ours


def test_spherical_run_integrates(models):
    """run() is finite, conserves energy, and its RX, RY, RZ columns are
    Newton's law at every row; Constrain after the velocities gives the
    same table."""
    first, last = models["aux_spherical_pendulum"]
    eqs, newton, energy = _spherical_by_hand(first)
    q4, q5, u4, u5 = _symbols(first, "Q4 Q5 U4 U5")
    consts = _symbols(first, "G L M IA IC")
    params = {c: float(first.al.numerics.input_value(c.name, True)) for c in consts}
    accels = [_acc(u4), _acc(u5)]
    state = [q4, q5, u4, u5]
    mm = sp.lambdify(state, eqs[0].subs(params))
    ff = sp.lambdify(state, eqs[1].subs(params))
    law = sp.lambdify(state + accels, [e.subs(params) for e in newton])
    total = sp.lambdify(state, energy.subs(params))
    result = first.run()
    table = np.column_stack([result[k] for k in ("Q4", "Q5", "U4", "U5")])
    assert len(table) == 101 and np.all(np.isfinite(table))
    assert np.ptp(table[:, 0]) > 0.1  # it swings
    e = np.array([total(*row) for row in table])
    assert np.ptp(e) < 1e-7 * np.max(np.abs(e))
    for k, row in enumerate(table):
        ud = np.linalg.solve(mm(*row), ff(*row)).ravel()
        expected = law(*row, *ud)
        got = [result[f][k] for f in ("RX", "RY", "RZ")]
        assert np.allclose(got, expected, rtol=1e-9, atol=1e-9), (k, got, expected)
    again = last.run()
    for key in ("Q4", "Q5", "U4", "U5", "RX", "RY", "RZ"):
        assert np.allclose(again[key], result[key], rtol=1e-12, atol=1e-12)


# ------------------------------------------------------------- planar


def _planar_by_hand(mod):
    """Closed forms: (IZ + M*L^2)*U3' = -M*G*L*COS(Q3); the mass center
    accelerates by L*U3'*A2> - L*U3^2*A1>; R = M*a_cm + M*G*N2>."""
    q3, u3 = _symbols(mod, "Q3 U3")
    G, L, M, IZ = _symbols(mod, "G L M IZ")
    s, c = sp.sin(q3), sp.cos(q3)
    u3d = -M * G * L * c / (IZ + M * L**2)
    ax = -L * u3d * s - L * u3**2 * c
    ay = L * u3d * c - L * u3**2 * s
    energy = (IZ + M * L**2) * u3**2 / 2 + M * G * L * s
    return u3d, [M * ax, M * ay + M * G], energy


def test_planar_reaction_forces_with_a_dependent_speed(models):
    """Constrain(AUXILIARY[U1, U2], DEPENDENT[U4]) before the velocities."""
    first, last = models["aux_planar_pendulum"]
    u3d, newton, _energy = _planar_by_hand(first)
    q3, u3 = _symbols(first, "Q3 U3")
    consts = _symbols(first, "G L M IZ")
    accel = _acc(u3)
    rng = np.random.default_rng(4)
    for _ in range(6):
        at = dict(zip(consts, rng.uniform(0.3, 2.0, 4), strict=True))
        at.update(zip([q3, u3], rng.uniform(-1.5, 1.5, 2), strict=True))
        ud = float(u3d.subs(at))
        at_acc = dict(at) | {accel: ud}
        expected = [float(e.subs(at)) for e in newton]
        for mod in (first, last):
            assert mod.AUTOLEV["ZERO"].shape == (1, 1)
            assert np.allclose(_zero_udot(mod, [u3], at), [ud], rtol=1e-10)
            ours = [_value(mod, f, [u3], at_acc) for f in ("RX", "RY")]
            assert np.allclose(ours, expected, rtol=1e-10, atol=1e-12), ours
    # al2py's KanesMethod inputs: U1, U2 auxiliary, U4 dependent; its
    # auxiliary equations give the same forces
    inputs = first.al.model.kane_inputs()
    u1, u2, u4 = _symbols(first, "U1 U2 U4")
    assert inputs.u_auxiliary == [u1, u2] and inputs.u_dependent == [u4]
    km = first.kanes_method()
    forces = _symbols(first, "RX RY")
    at = dict(zip(consts, [9.81, 0.8, 1.5, 0.1], strict=True)) | {q3: 0.4, u3: -0.7}
    ud = float(u3d.subs(at))
    at |= {accel: ud, u4: 0.8 * at[u3], _acc(u4): 0.8 * ud}
    aux_eqs = _plain(km.auxiliary_eqs.subs(km.kindiffdict()), [u3, u4])
    by_kane = sp.solve(list(aux_eqs.subs(at)), forces)
    expected = [float(e.subs(at)) for e in newton]
    assert np.allclose([float(by_kane[f]) for f in forces], expected)


def test_planar_run_integrates(models):
    first, last = models["aux_planar_pendulum"]
    u3d, newton, energy = _planar_by_hand(first)
    q3, u3 = _symbols(first, "Q3 U3")
    consts = _symbols(first, "G L M IZ")
    params = {c: float(first.al.numerics.input_value(c.name, True)) for c in consts}
    total = sp.lambdify([q3, u3], energy.subs(params))
    law = sp.lambdify([q3, u3], [e.subs(params) for e in newton])
    result = first.run()
    q, u = np.asarray(result["Q3"]), np.asarray(result["U3"])
    assert len(q) == 151 and np.all(np.isfinite(q)) and np.ptp(q) > 0.5
    e = total(q, u)
    assert np.ptp(e) < 1e-7 * np.max(np.abs(e))
    rx, ry = law(q, u)
    assert np.allclose(result["RX"], rx, rtol=1e-9, atol=1e-9)
    assert np.allclose(result["RY"], ry, rtol=1e-9, atol=1e-9)
    again = last.run()
    for key in ("Q3", "U3", "RX", "RY"):
        assert np.allclose(again[key], result[key], rtol=1e-12, atol=1e-12)


# ------------------------------------------------------------ the hint

MISSING = """Newtonian N
Bodies A
Points P1
Variables Q3', U{3}'
Variables RX, RY
Constants G, L, M, IZ
Mass A = M
Inertia A, 0, 0, IZ
Simprot(N, A, 3, Q3)
Q3' = U3
W_A_N> = U3*A3>
AUXILIARY[1] = U1
AUXILIARY[2] = U2
Constrain(AUXILIARY[U1, U2])
V_P1_N> = U1*N1> + U2*N2>
V_AO_N> = L*U3*A2>
Force_P1> = RX*N1> + RY*N2>
Zero = Fr() + FrStar()
"""


def test_auxiliary_speed_missing_from_velocities_names_the_cause(tmp_path):
    """The mass center's velocity was given without P1's auxiliary speeds:
    the error says so, and does not suggest a kinematical equation."""
    with pytest.raises(ValueError) as err:
        _load(tmp_path, "aux_missing", MISSING)
    text = str(err.value)
    assert "auxiliary speeds U1, U2" in text
    assert "V_P_N> = ... + U1*N1>" in text
    assert "kinematical" not in text
    # an independent speed with no kinematical equation keeps that hint
    forgot = MISSING.replace("Q3' = U3\n", "").replace("W_A_N> = U3*A3>", "")
    forgot = forgot.replace("L*U3*A2>", "L*U1*A2>")
    with pytest.raises(ValueError) as err:
        _load(tmp_path, "aux_missing2", forgot)
    assert "U3; is a kinematical differential equation" in str(err.value)
