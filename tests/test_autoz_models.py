"""AutoZ ON derives with intermediates; the results are AutoZ OFF's.

tests/models/rolling_disc.al (our own: a disc rolling without slip, two
dependent speeds) is converted as written and with ``AutoZ ON`` in front;
the generalized forces, ZERO, the constraint solutions and the integrated
motion must agree, and the transcript shows the intermediates by name."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.intermediates.autoz import has_intermediates
from conftest import SHARED, load_module
from sympy.core.function import AppliedUndef

from al2py import convert

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "models" / "rolling_disc.al"

STATE = {
    "Q1": 0.1,
    "Q2": -0.2,
    "Q3": 0.3,
    "Q4": 0.25,
    "Q5": 0.7,
    "U3": 0.4,
    "U4": -0.3,
    "U5": 5.0,
    "U3'": 0.1,
    "U4'": 0.2,
    "U5'": -0.3,
}


def _module(tmp_path: Path, autoz: bool, name: str):
    source = SCRIPT.read_text()
    if autoz:
        source = "AutoZ ON\n" + source
    path = tmp_path / f"{name}.al"
    path.write_text(source)
    result = convert(source, str(path))
    (tmp_path / f"{name}.py").write_text(result.code)
    return load_module(result.code, tmp_path, name)


@pytest.fixture(scope="module")
def disc(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("disc")
    return _module(tmp, False, "disc_off"), _module(tmp, True, "disc_on"), tmp


def _transcript(folder: Path, name: str, outdir: Path) -> Any:
    """``python NAME.py --outdir OUTDIR`` in ``folder``: it must succeed."""
    done = subprocess.run(
        [sys.executable, f"{name}.py", "--outdir", str(outdir)],
        cwd=folder,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    return done


def test_both_settings_derive_with_intermediates(disc, tmp_path):
    """Issue 21: ``AutoZ`` changes what is shown, not how equations are
    formed.  Both derive over intermediates; with it OFF, ``AUTOLEV[...]``
    and the transcript write them out (no ``Z`` name is ever printed)."""
    off, on, tmp = disc
    assert has_intermediates(on.al.value("ZERO"))
    assert has_intermediates(off.al.value("ZERO"))
    assert not has_intermediates(off.AUTOLEV["ZERO"])
    done = _transcript(tmp, "disc_off", tmp_path)
    shown = [line for line in done.stdout.splitlines() if line.startswith("->")]
    assert shown and not any(re.search(r"\bZ\d+\b", line) for line in shown)


@pytest.mark.parametrize("name", ["U1", "U2", "U1'", "U2'", "ZERO"])
def test_same_values_with_and_without_autoz(disc, name):
    off, on, _tmp = disc
    for scale in (1.0, -0.7):
        state = {k: v * scale for k, v in STATE.items()}
        a = np.asarray(off.evaluate(name, **state), dtype=float)
        b = np.asarray(on.evaluate(name, **state), dtype=float)
        assert np.allclose(a, b, rtol=1e-10, atol=1e-12), (name, a, b)


def test_same_motion_with_and_without_autoz(disc):
    off, on, _tmp = disc
    a, b = off.run(), on.run()
    for column in ("Q3", "Q4", "U3", "U4", "U5"):
        assert np.allclose(a[column], b[column], rtol=1e-9, atol=1e-12), column
    assert abs(a["Q4"][-1] - 0.2) > 1e-3  # the disc really moved


def test_transcript_names_intermediates(disc, tmp_path):
    """AutoZ ON: each Z is defined (``-> (n) Z1 = ...``) before the first
    response that uses it; the program runs end to end from the command
    line."""
    _off, _on, tmp = disc
    done = _transcript(tmp, "disc_on", tmp_path)
    lines = done.stdout.splitlines()
    z1 = re.compile(r"\bZ1\b")
    defined = [i for i, line in enumerate(lines) if re.search(r"\) Z1 = ", line)]
    used = [
        i
        for i, line in enumerate(lines)
        if line.startswith("->") and z1.search(line.split("=", 1)[-1])
    ]
    assert defined and used and defined[0] < min(used)
    assert (tmp_path / "rolling_disc.1").exists()


def test_autolev_names_are_written_out(disc):
    """``AUTOLEV[name]`` gives the full expression; ``al.value`` keeps Z's."""
    off, on, _tmp = disc
    full = on.AUTOLEV["ZERO"]
    assert not has_intermediates(full) and has_intermediates(on.al.value("ZERO"))
    subs = {
        on.al.table.entries[k].obj: v for k, v in STATE.items() if not k.endswith("'")
    }
    subs.update(
        {
            on.al.table.entries[k].obj: v
            for k, v in {"R": 0.3, "G": 9.81, "M": 2}.items()
        }
    )
    t = on.al.table.entries["T"].obj
    accel = {
        on.al.table.entries[k[:-1]].obj.diff(t): v
        for k, v in STATE.items()
        if k.endswith("'")
    }
    got = np.array([float(e.xreplace(accel).xreplace(subs)) for e in full])
    want = np.asarray(off.evaluate("ZERO", **STATE), dtype=float).ravel()
    assert np.allclose(got, want, rtol=1e-10)


TUTORIAL = SHARED
KANE_SCRIPTS = sorted(
    p.stem
    for p in TUTORIAL.glob("tutor*.al")
    if "KANE(" in p.read_text(errors="replace").upper()
    and "GYROSTAT" not in p.read_text(errors="replace").upper()
)


def _autoz_variant(name: str, tmp: Path, on: bool):
    source = (TUTORIAL / f"{name}.al").read_text(errors="replace")
    lines = source.splitlines()
    # AutoZ as the script's first statement, or removed (tutor7* say ON)
    lines = [ln for ln in lines if not ln.strip().upper().startswith("AUTOZ")]
    text = ("AutoZ ON\n" if on else "") + "\n".join(lines) + "\n"
    stem = f"{name}_{'on' if on else 'off'}"
    path = tmp / f"{stem}.al"
    path.write_text(text)
    result = convert(text, str(path))
    return load_module(result.code, tmp, stem)


@pytest.mark.parametrize("name", KANE_SCRIPTS)
def test_tutorial_zero_same_with_autoz(name, tmp_path):
    """Every tutorial model with Kane(): ZERO derived with intermediates
    equals ZERO derived with full expressions (which the tests compare with
    Autolev's transcripts and with KanesMethod) at random points."""
    off = _autoz_variant(name, tmp_path, False)
    on = _autoz_variant(name, tmp_path, True)
    # named quantities (tutor6's STRETCH, LOQ) written out in both
    a = off.al.resolve(off.AUTOLEV["ZERO"])
    b = on.al.resolve(on.AUTOLEV["ZERO"])
    assert a.shape == b.shape
    t = off.al.table.entries["T"].obj
    atoms = set()
    for m in (a, b):
        for e in m:
            atoms |= e.atoms(sp.Derivative)
    rng = np.random.default_rng(len(name))
    values = {d: sp.Float(rng.uniform(-1, 1)) for d in atoms}
    frozen = [m.xreplace(values) for m in (a, b)]
    others = set()
    for m in frozen:
        for e in m:
            others |= {x for x in e.atoms(sp.Symbol, AppliedUndef) if x != t}
    values = {x: sp.Float(rng.uniform(0.3, 1.2)) for x in others}
    values[t] = sp.Float(0.4)
    got = [complex(sp.N(e.xreplace(values))) for e in frozen[1]]
    want = [complex(sp.N(e.xreplace(values))) for e in frozen[0]]
    assert np.allclose(got, want, rtol=1e-9, atol=1e-9), (name, got, want)


# A double pendulum whose speeds are written Q' (no U's), differentiated by
# its coordinates and accelerations and encoded for CODE Algebraic: the
# shape of the DAS3 shoulder model.  Our own script.
RATES_SCRIPT = """\
Newtonian N
Bodies A, B
MotionVariables' Q{2}''
Constants L, M, G, IZ
Mass A = M, B = M
Inertia A, 0, 0, IZ
Inertia B, 0, 0, IZ
Simprot(N, A, 3, Q1)
Simprot(A, B, 3, Q2)
W_A_N> = Q1'*A3>
W_B_A> = Q2'*B3>
P_NO_AO> = L*A1>
P_AO_BO> = L*B1>
V_AO_N> = Dt(P_NO_AO>, N)
V_BO_N> = Dt(P_NO_BO>, N)
A_AO_N> = Dt(V_AO_N>, N)
A_BO_N> = Dt(V_BO_N>, N)
Gravity(-G*N2>)
Zero = Fr() + FrStar()
FB> = M*(-A_BO_N> - G*N2>)
F_B = [dot(FB>, B1>); dot(FB>, B2>)]
dz_dq = D(Zero, [Q1; Q2])
dz_dqdd = D(Zero, [Q1''; Q2''])
Encode Zero, dz_dq, dz_dqdd, F_B
Code Algebraic() rates_raw.c
"""

RATES_VALUES = {
    "L": 0.7,
    "M": 2.0,
    "G": 9.81,
    "IZ": 0.3,
    "Q1": 0.4,
    "Q2": -1.1,
    "Q1'": 0.9,
    "Q2'": -0.5,
    "Q1''": 0.2,
    "Q2''": 1.3,
}


def test_algebraic_job_with_rates_same_with_autoz(tmp_path):
    """CODE Algebraic of encoded Jacobians when the speeds are Q': AutoZ ON
    gives AutoZ OFF's numbers (a function of time replaced inside its own
    derivative used to stop this job), and D(ZERO, Q'') is minus the
    mass matrix: symmetric, negative definite."""
    results = []
    for on in (False, True):
        source = ("AutoZ ON\n" if on else "") + RATES_SCRIPT
        name = f"rates_{'on' if on else 'off'}"
        result = convert(source, str(tmp_path / f"{name}.al"))
        module = load_module(result.code, tmp_path, name)
        results.append(module.al.numerics.run(RATES_VALUES))
    off, on = results
    names = off.tables[0].names
    assert on.tables[0].names == names and len(names) == 12
    for name in names:
        assert on[name][0] == pytest.approx(off[name][0], rel=1e-10, abs=1e-12), name
    mass = -np.array([[on[f"DZ_DQDD[{i},{j}]"][0] for j in (1, 2)] for i in (1, 2)])
    assert mass[0, 1] == pytest.approx(mass[1, 0], rel=1e-12)
    assert np.all(np.linalg.eigvalsh(mass) > 0)


# The linearization thomasbike-style scripts do: solve ZERO, a first-order
# Taylor polynomial about upright rolling, its coefficients by COEF.
LINEARIZE = """
Solve(Zero, U3', U4', U5')
Constants V0
LIN = Taylor(Rhs(U4'), 0:1, Q3=0, Q4=0, Q5=0, U3=0, U4=0, U5=V0)
C4Q4 = Coef(LIN, Q4)
C4U3 = Coef(LIN, U3)
C4U5 = Coef(LIN, U5)
"""


def test_taylor_and_coef_same_with_autoz(tmp_path):
    """With AutoZ ON, Taylor takes values and derivatives at the point
    intermediate by intermediate; the polynomial and the coefficients COEF
    reads must be AutoZ OFF's."""
    modules = []
    for on in (False, True):
        source = ("AutoZ ON\n" if on else "") + SCRIPT.read_text() + LINEARIZE
        name = f"disc_lin_{'on' if on else 'off'}"
        result = convert(source, str(tmp_path / f"{name}.al"))
        modules.append(load_module(result.code, tmp_path, name))
    off, on = modules
    assert has_intermediates(on.al.value("LIN"))
    point = {**STATE, "V0": 4.0}
    seen = []
    for name in ("LIN", "C4Q4", "C4U3", "C4U5"):
        a = float(off.evaluate(name, **point))
        b = float(on.evaluate(name, **point))
        assert b == pytest.approx(a, rel=1e-10, abs=1e-12), name
        seen.append(a)
    assert seen[1] != 0  # lean really enters the lean acceleration


# Our own three-link loop: direction cosines that depend on the unknowns of
# a CODE Nonlinear job become intermediates.
LOOP_SCRIPT = """\
Newtonian N
Bodies A, B, C
Variables QA, QB, QC
Constants LA, LB, LC, LN
Simprot(N, A, 3, QA)
Simprot(A, B, 3, QB)
Simprot(B, C, 3, QC)
P> = LA*A1> + LB*B1> + LC*C1>
Loop = [Dot(P>, N1>) - LN; Dot(P>, N2>)]
Input QA = 30 deg, QB = 60 deg, QC = 200 deg
Input LA = 1, LB = 2, LC = 2, LN = 1
Code Nonlinear(Loop, QB, QC) loop.m
"""


def test_nonlinear_job_through_intermediates(tmp_path):
    """Newton's Jacobian sees through the intermediates that depend on the
    unknowns: AutoZ ON closes the loop where AutoZ OFF does."""
    results = []
    for on in (False, True):
        source = ("AutoZ ON\n" if on else "") + LOOP_SCRIPT
        name = f"loop_{'on' if on else 'off'}"
        result = convert(source, str(tmp_path / f"{name}.al"))
        module = load_module(result.code, tmp_path, name)
        if on:
            assert has_intermediates(module.al.value("LOOP"))
        results.append(module.al.numerics.run())
    off, on = results
    for name in ("QB", "QC"):
        assert on[name][0] == pytest.approx(off[name][0], abs=1e-9)
    qa, qb, qc = np.radians([30.0, off["QB"][0], off["QC"][0]])
    x = np.cos(qa) + 2 * np.cos(qa + qb) + 2 * np.cos(qa + qb + qc)
    y = np.sin(qa) + 2 * np.sin(qa + qb) + 2 * np.sin(qa + qb + qc)
    assert (x, y) == pytest.approx((1.0, 0.0), abs=1e-7)  # the loop closes


FORMS = """\
% A double pendulum of two rigid rods (our own), AutoZ OFF (the default)
Newtonian N
Bodies A, B
Points O
Variables Q{2}', U{2}'
Constants L, M, G
Q1' = U1
Q2' = U2
Simprot(N, A, 3, Q1)
Simprot(A, B, 3, Q2)
W_A_N> = U1*A3>
W_B_A> = U2*B3>
Mass A=M, B=M
Inertia A, 0, 0, M*L^2/12
Inertia B, 0, 0, M*L^2/12
P_O_Ao> = L/2*A1>
P_O_Bo> = L*A1> + L/2*B1>
V_O_N> = 0>
V_Ao_N> = Dt(P_O_Ao>, N)
V_Bo_N> = Dt(P_O_Bo>, N)
A_Ao_N> = Dt(V_Ao_N>, N)
A_Bo_N> = Dt(V_Bo_N>, N)
Gravity(G*N1>)
Zero = Fr() + FrStar()
Kane()
GRAV = Coef(Zero, G)
INER = Coef(Zero, M)
REST = Exclude(Zero, G)
CHECK = Evaluate(Zero, Q1=0, Q2=0, U1=0, U2=0, U1'=0, U2'=0)
VB = Dot(V_Bo_N>, N1>)
WB = 2*VB
EXW = Explicit(WB)
EVW = Evaluate(WB, L=1)
"""


def test_form_reading_commands_see_written_out_values(tmp_path):
    """AutoZ OFF: the derivation's intermediates are internal, so ``Coef``,
    ``Exclude`` and ``Evaluate`` read the full expressions (a constant
    inside an intermediate would otherwise be missed: ``Coef(Zero, G)``
    would be 0)."""
    path = tmp_path / "forms.al"
    path.write_text(FORMS)
    mod = load_module(convert(FORMS, str(path)).code, tmp_path, "forms")
    zero = mod.AUTOLEV["ZERO"]
    assert has_intermediates(mod.al.value("ZERO"))
    g = next(s for s in zero.free_symbols if s.name == "G")
    m = next(s for s in zero.free_symbols if s.name == "M")
    grav, iner = mod.AUTOLEV["GRAV"], mod.AUTOLEV["INER"]
    rest = mod.AUTOLEV["REST"]
    # the commands' results themselves hold no intermediate
    # (EXW and EVW reach VB's intermediates through the name VB)
    assert has_intermediates(mod.al.value("VB"))
    for name in ("GRAV", "INER", "REST", "CHECK", "EXW", "EVW"):
        assert not has_intermediates(mod.al.value(name)), name
    assert grav != sp.zeros(2, 1)
    # ZERO is linear in G and in M: the coefficients rebuild it
    assert sp.expand(zero - grav * g - rest) == sp.zeros(2, 1)
    assert sp.expand(zero - iner * m) == sp.zeros(2, 1)
    # gravity along N1> is zero torque when hanging straight: exact zeros
    assert mod.al["CHECK"] == sp.zeros(2, 1)


def test_solve_for_some_accelerations_names_over_the_others(tmp_path):
    """``Solve(Zero[1], U3')`` with ``AutoZ ON`` while U4' and U5' stay:
    the intermediates are made over U4' and U5' themselves (each shown as
    ``Z12 = ...``, never taken at placeholders, ``Z12(Derivative(...))``),
    U4' and U5' stay visible in the solution, and its value is AutoZ
    OFF's."""
    values = []
    for on in (False, True):
        source = ("AutoZ ON\n" if on else "") + SCRIPT.read_text()
        source += "\nSolve(Zero[1], U3')\n"
        name = f"some_{'on' if on else 'off'}"
        result = convert(source, str(tmp_path / f"{name}.al"))
        (tmp_path / f"{name}.py").write_text(result.code)
        module = load_module(result.code, tmp_path, name)
        values.append(float(module.evaluate("U3'", **STATE)))
        if on:
            solution = module.al.value("U3'")
            shown = {str(d.expr.func) for d in solution.atoms(sp.Derivative)}
            assert shown == {"U4", "U5"}
            out = tmp_path / "out"
            out.mkdir()
            lines = _transcript(tmp_path, name, out).stdout.splitlines()
            solved = lines.index(next(x for x in lines if "Solve(Zero[1]" in x))
            shown = [x for x in lines[solved:] if x.startswith("->")]
            assert shown and not any(re.search(r"\bZ\d+\(", x) for x in shown)
            assert re.search(r"U3' = .*U4'", shown[-1]), shown[-1]
    assert values[1] == pytest.approx(values[0], rel=1e-10, abs=1e-12)


def test_intermediates_answer_every_assumption_from_their_own_class():
    """Each of sympy's assumption properties is written in the body of
    ``Intermediate`` (none attached at import, none left to sympy's)."""
    from al2py_runtime.intermediates.autoz import Intermediate
    from sympy.core.assumptions import _assume_defined

    for fact in _assume_defined:
        assert isinstance(Intermediate.__dict__.get("is_" + fact), property), fact
