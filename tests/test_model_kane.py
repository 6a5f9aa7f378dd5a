"""The module is a sympy.physics.mechanics model (issue 9, acceptance).

For tutor6 and tutor8: the sympy points know Autolev's velocities,
``kanes_method()`` is sympy's ``KanesMethod`` whose ``mass_matrix_full`` and
``forcing_full`` give the same state derivatives as ``ode_function()`` (two
independent derivations: sympy's Kane and the runtime's ZERO), and
``solve_ivp`` on ``ode_function()`` reproduces ``run()``'s table.
"""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import t
from sympy.physics.mechanics import (
    KanesMethod,
    Particle,
    RigidBody,
    find_dynamicsymbols,
)

# tutor8 evaluates ZERO with these numbers before CODE (they are not Inputs).
FIXED = {"tutor6": {}, "tutor8": {"L": 1, "MA": 10, "MB": 1, "G": 9.81}}
POINTS = {"tutor6": ("P", "Q"), "tutor8": ("AO", "BO")}


def _same_vector(a, b, frame, subs) -> bool:
    for e in (frame.x, frame.y, frame.z):
        x = complex(sp.sympify(a.dot(e)).subs(subs).evalf())
        y = complex(sp.sympify(b.dot(e)).subs(subs).evalf())
        if abs(x - y) > 1e-9 * max(1.0, abs(y)):
            return False
    return True


def _random_subs(mod, rng):
    """Random values for every symbol and function of time in the model."""
    subs = {}
    for name in mod.AUTOLEV:
        kind = mod.al.kind(name)
        if kind in ("constant", "variable", "specified") and "'" not in name:
            obj = mod.al.symbol(name)
            if obj is not t:
                subs[obj] = rng.uniform(0.2, 1.5)
                if kind != "constant":
                    subs[sp.Derivative(obj, t)] = rng.uniform(0.2, 1.5)
    return subs


@pytest.mark.parametrize("name", ["tutor6", "tutor8"])
def test_points_know_autolev_velocities(tutorial, name):
    mod = tutorial(name)
    rng = random.Random(6)
    subs = _random_subs(mod, rng)
    for point in POINTS[name]:
        p = mod.al.model.point(point)
        given = mod.al.resolve(mod.AUTOLEV[f"V_{point}_N>"])
        assert _same_vector(mod.al.resolve(p.vel(mod.N)), given, mod.N, subs)
    # ... and still after kanes_method() (actual values, speeds kept)
    mod.al.model.kanes_method()
    for point in POINTS[name]:
        p = mod.al.model.point(point)
        given = mod.al.resolve(mod.AUTOLEV[f"V_{point}_N>"])
        assert _same_vector(p.vel(mod.N), given, mod.N, subs)


@pytest.mark.parametrize(
    "name", ["tutor6", "tutor6f", "tutor7", "tutor7a", "tutor7c", "tutor8"]
)
def test_kanes_method_matches_ode_function(tutorial, name):
    mod = tutorial(name)
    km = mod.kanes_method()
    assert isinstance(km, KanesMethod)
    inputs = mod.al.model.kane_inputs()
    kinds = {type(b) for b in inputs.bodies}
    assert kinds <= {RigidBody, Particle} and inputs.bodies
    assert all(isinstance(load, tuple) and len(load) == 2 for load in inputs.loads)
    assert len(inputs.kd_eqs) == len(inputs.q_ind) >= 2
    assert mod.al.model.kd_eqs == inputs.kd_eqs
    f, y0, names = mod.ode_function()
    assert len(y0) == len(names)
    params = {}
    for key in mod.al.numerics.inputs:
        if mod.al.kind(key) == "constant":
            params[mod.al.symbol(key)] = float(mod.al.numerics.input_value(key, True))
    for key, value in FIXED.get(name, {}).items():
        params[mod.al.symbol(key)] = value
    states = [*km.q, *km.u]
    # the dependent speeds are computed from the constraints, not integrated
    dependent = list(inputs.u_dependent)
    known = [s for s in states if s not in dependent]
    index = [names.index(mod.al.name_of(s)) for s in known]
    mm, ff = km.mass_matrix_full, km.forcing_full
    free = (mm.free_symbols | ff.free_symbols) - {t} - set(params)
    assert not free, free
    # Constraint forces (tutor7c's FC1, FC2 at R) may remain with coefficients
    # that vanish on the constraint: they get random values.
    forces = find_dynamicsymbols(mm.row_join(ff)) - set(states)
    assert forces <= set(mod.al.model.registry.kane["forces"]), forces
    rng = np.random.default_rng(8)
    for _ in range(5):
        y = rng.uniform(-1.0, 1.0, len(names))
        at = dict(params)
        at.update({f: rng.uniform(-5.0, 5.0) for f in forces})
        at.update({s: y[i] for s, i in zip(known, index, strict=True)})
        for u, c in zip(dependent, inputs.velocity_constraints, strict=True):
            at[u] = float((u - c).subs(at).evalf())
        m_num = np.array(mm.subs(at).evalf(), dtype=float)
        f_num = np.array(ff.subs(at).evalf(), dtype=float).ravel()
        kane = np.linalg.solve(m_num, f_num)
        kane = kane[[states.index(s) for s in known]]
        ours = np.asarray(f(0.0, y))[index]
        assert np.allclose(kane, ours, rtol=1e-8, atol=1e-8), (kane, ours)


def test_tutor8_kanes_method_is_the_model_before_evaluate(tutorial):
    """What ``kanes_method()`` represents (README): the script's bodies, loads
    and kinematical equations with its constants as symbols, not ZERO as the
    script changed it after Kane().  tutor8's ``Zero := Evaluate(Zero, L=1,
    MA=10, MB=1, G=9.81)`` puts numbers in ZERO only; given the same numbers,
    KanesMethod's matrices give ode_function()'s state derivatives, matched
    by name: ode_function() lists the states in Autolev's order (U1, U2, X,
    THETA, ...), KanesMethod in ``[q; u]`` order (X, THETA, U1, U2)."""
    mod = tutorial("tutor8")
    km = mod.kanes_method()
    fixed = {mod.al.symbol(k): v for k, v in FIXED["tutor8"].items()}
    free = km.mass_matrix_full.free_symbols | km.forcing_full.free_symbols
    assert set(fixed) <= free  # symbols in the exported model ...
    assert not set(fixed) & sp.Matrix(mod.AUTOLEV["ZERO"]).free_symbols  # not in ZERO
    f, y0, names = mod.ode_function()
    states = [*km.q, *km.u]
    index = [names.index(mod.al.name_of(s)) for s in states]
    assert index != list(range(len(states)))  # the orders differ
    gains = {
        mod.al.symbol(k): float(mod.al.numerics.input_value(k, True))
        for k in ("K1", "K2", "K3", "K4")
    }
    rng = np.random.default_rng(22)
    for _ in range(4):
        y = rng.uniform(-2.0, 2.0, len(names))
        at = fixed | gains | {s: y[i] for s, i in zip(states, index, strict=True)}
        m_num = np.array(km.mass_matrix_full.subs(at).evalf(), dtype=float)
        f_num = np.array(km.forcing_full.subs(at).evalf(), dtype=float).ravel()
        kane = np.linalg.solve(m_num, f_num)
        ours = np.asarray(f(0.0, y))[index]
        assert np.allclose(kane, ours, rtol=1e-9, atol=1e-9), (kane, ours)
        # without the script's numbers the model is another system
        loose = {k: v for k, v in at.items() if k not in fixed}
        loose |= {k: 2 * v for k, v in fixed.items()}
        m2 = np.array(km.mass_matrix_full.subs(loose).evalf(), dtype=float)
        f2 = np.array(km.forcing_full.subs(loose).evalf(), dtype=float).ravel()
        assert not np.allclose(np.linalg.solve(m2, f2), ours, rtol=1e-3)


def test_solve_ivp_on_ode_function_reproduces_run(tutorial):
    from scipy.integrate import solve_ivp

    mod = tutorial("tutor6")
    result = mod.run()
    f, y0, names = mod.ode_function()
    times = np.asarray(result["T"], dtype=float)
    sol = solve_ivp(
        f,
        (times[0], times[-1]),
        y0,
        method="DOP853",
        t_eval=times,
        rtol=1e-9,
        atol=1e-9,
    )
    assert sol.status == 0
    for state in ("QA", "QB"):
        ours = np.degrees(sol.y[names.index(state)])
        assert np.allclose(ours, result[state], rtol=1e-5, atol=1e-4), state
    # the initial state is the Inputs', in radians
    assert y0[names.index("QA")] == pytest.approx(np.radians(20))


def test_ode_function_overrides(tutorial):
    mod = tutorial("tutor6")
    f, y0, names = mod.ode_function(QA=30)
    assert y0[names.index("QA")] == pytest.approx(np.radians(30))
    # at rest, QA' = U1/LA = 0 and the pendulum starts to fall
    dy = f(0.0, np.array(y0))
    assert dy[names.index("QA")] == pytest.approx(0.0)
    assert dy[names.index("U1")] != 0


def test_gyrostat_is_not_silently_left_out(tutorial):
    """tutor9's rotor enters FrStar through Gyrostat, which has no sympy
    body: kanes_method() says so instead of returning a model without it."""
    mod = tutorial("tutor9")
    with pytest.raises(ValueError, match="Gyrostat"):
        mod.kanes_method()


@pytest.mark.parametrize("name", ["tutor6", "tutor8"])
def test_generated_source_speaks_sympy(name):
    """No string-keyed physics: forms are assigned through sympy's own
    setters (``P.set_pos(O_, ...)``), each followed by the runtime's record
    of it (issue 33)."""
    import re

    from conftest import SHARED

    from al2py import convert

    code = convert((SHARED / f"{name}.al").read_text(), f"{name}.al").code
    assert "# al> " in code
    code = re.sub(r"  # al> .*", "", code)  # without the echoes that end lines
    forms = re.compile(r'al\.assign\("(P|V|A|W|ALF|FORCE|TORQUE|I)_[A-Z0-9_]+>')
    assert not forms.search(code)
    assert "# al> " in code
    assert ".set_pos(" in code and "al.model.set_pos(" not in code
    if name == "tutor6":
        assert (
            'P_particle, Q_particle = Particle("P", P, 0), Particle("Q", Q, 0)\n'
            "al.model.declare_particles(P_particle, Q_particle)" in code
        )
        assert 'N = ReferenceFrame("N")\nal.model.declare_newtonian(N)' in code
        assert 'O_ = Point("O")\nal.model.declare_points(O_)' in code
        # loads: one list of sympy loads, which Fr() and kanes_method() read
        assert "loads = al.model.loads" in code
        assert (
            "loads.append(Force(P, FP * A.y))\nal.model.given_force(P, line=53)" in code
        )
        assert "set_force" not in code and "force_between" not in code
        assert "kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=33))" in code
        assert not re.search(r'al\.assign\("Q[AB]\'"', code)
        assert "P.set_pos(O_, LA * A.x)\nal.model.given_pos(P, O_, line=29)" in code
        assert "A.orient_axis(N, N.z, QA)\nal.model.given_orientation(A, N" in code
        assert "# sympy:" not in code  # no statement is only a comment


@pytest.mark.parametrize("name", ["tutor6", "tutor8"])
def test_module_holds_sympy_bodies_and_kd_eqs(tutorial, name):
    """The module's RigidBody/Particle objects carry the declared masses and
    are the bodies KanesMethod gets; its kd_eqs are sympy equations
    ``Eq(q', rhs)`` equal to the runtime's (issue 22, module shape)."""
    mod = tutorial(name)
    if name == "tutor6":
        bodies = {"P": (mod.P_particle, "MP"), "Q": (mod.Q_particle, "MQ")}
        assert all(isinstance(b, Particle) for b, _m in bodies.values())
    else:
        bodies = {"A": (mod.A_body, "MA"), "B": (mod.B_body, "MB")}
        assert all(isinstance(b, RigidBody) for b, _m in bodies.values())
        assert mod.B_body.frame is mod.B and mod.B_body.masscenter is mod.Bo
    for _name, (body, mass) in bodies.items():
        assert body.mass == mod.al.symbol(mass)
    eqs = mod.kd_eqs
    assert eqs and all(isinstance(e, sp.Eq) for e in eqs)
    coords = [e.lhs.expr for e in eqs]
    rhs = {
        sp.Derivative(q, t): mod.al.resolve(mod.AUTOLEV[mod.al.name_of(q) + "'"])
        for q in coords
    }
    assert all(sp.simplify(e.rhs - rhs[e.lhs]) == 0 for e in eqs)
    kd = {sp.Derivative(q, t) - r for q, r in ((e.lhs.expr, e.rhs) for e in eqs)}
    assert set(mod.al.model.kd_eqs) <= kd
    km = mod.kanes_method()
    assert {id(b) for b in km.bodies} == {id(b) for b, _m in bodies.values()}


VARYING = """\
Newtonian N
{declare}
Variables Q', U1'
Variables MV
Constants G
{mass}
Q' = U1
Simprot(N, B, 3, Q)
P_No_BO> = Q*N1>
V_BO_N> = U1*N1>
W_B_N> = U1*N3>
Force_BO> = -G*N1>
Zero = Fr() + FrStar()
Kane()
"""


@pytest.mark.parametrize(
    "declare, mass, kind",
    [
        ("Bodies B", "Mass B = MV\nInertia B, 1, 1, 1", "mass"),
        ("Bodies B", "Mass B = 2\nInertia B, MV, MV, MV", "inertia"),
    ],
)
def test_mass_that_varies_in_time_is_refused(
    tmp_path, convert_and_import, declare, mass, kind
):
    """The runtime's FrStar (Autolev's) is -m a; sympy's KanesMethod would
    add -m' v: kanes_method() names the body instead of exporting another
    model."""
    script = tmp_path / "varying.al"
    script.write_text(VARYING.format(declare=declare, mass=mass))
    mod, _ = convert_and_import(script)
    assert not sp.Matrix(mod.AUTOLEV["ZERO"]).has(sp.Derivative(mod.al.symbol("MV"), t))
    with pytest.raises(ValueError, match=f"the {kind} of B varies in time"):
        mod.kanes_method()
