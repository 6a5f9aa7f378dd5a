"""SymPy's own Autolev examples convert, import and agree with SymPy.

SymPy ships the Autolev scripts its parser was tested on, each beside the
Python code that parser generated (``sympy/parsing/autolev/test-examples``).
Every script must convert with al2py and its module must import.  For the
three pendulums we also run SymPy's expected code (repaired, see
:func:`repair`) and compare the equations of motion mathematically: every row
of our ``ZERO`` must equal the same row of SymPy's ``zero`` at random values of
the coordinates, speeds, accelerations and constants.

Both sides use Kane's equations ``Fr + Fr* = 0`` with the same sign and the
same row order (one row per independent speed, in declaration order), so the
rows are compared as they are: no sign or row scaling is allowed.

Repairs made to SymPy's expected files before they are run:

* ``q1_d, q2_d = dynamicsymbols('q1_ q2_', 1)``: SymPy's parser named each
  derivative after a *different* function ``q1_``; the kinematical equations
  ``q1_d - u1`` then do not involve ``q1'`` at all.  Rewritten to
  ``dynamicsymbols('q1 q2', 1)`` (likewise the second derivatives).
* The trailing ``from pydy.system import System ...`` simulation is dropped:
  pydy is not a SymPy dependency and the simulation is not part of the
  equations of motion.

Differences that are formulation, not error:

* ``chaos_pendulum``: ``OMEGA = THETA'`` and ``ALPHA = PHI'`` make OMEGA and
  ALPHA names for the rates, so al2py's generalized speeds are ``THETA'`` and
  ``PHI'``; SymPy's parser uses ``omega``/``alpha`` with the kinematical
  equations ``theta' = omega``.  The speeds are equal, so ``omega`` is
  evaluated at the value of ``THETA'`` and ``omega'`` at that of ``THETA''``.
  SymPy writes the inertia as ``1/12*ma...`` (a float); we compare to 1e-9.
* ``non_min_pendulum``: SymPy leaves the dependent speed ``u_q1_d`` and its
  derivative in ``zero``; al2py substitutes the constraint solution
  (``Q1' = -Q2*Q2'/Q1`` and its derivative).  We evaluate SymPy's row at the
  constraint-consistent values of ``u_q1_d`` and ``u_q1_d'``, derived here from
  SymPy's own velocity constraint ``f_v``.
* ``non_min_pendulum.al`` itself sets ``V_P_N> = DT(P_P_PN>, N)``, the
  *negative* of P's velocity (``P_P_PN>`` points from P to PN).  SymPy's code
  reproduces that faithfully (``point_pn.pos_from(particle_p.point)`` is
  ``P_P_PN>``), and so does al2py: both sides model the script as written.  No
  reversed ``pos_from`` was found in the expected files of the three
  pendulums.
"""

from __future__ import annotations

import random
import re
from pathlib import Path

import pytest
import sympy as sp
from conftest import load_module
from sympy.physics.vector import dynamicsymbols

from al2py import convert

EXAMPLES = Path(sp.__file__).parent / "parsing" / "autolev" / "test-examples"
PYDY = EXAMPLES / "pydy-example-repo"
t = dynamicsymbols._t

ALL_SCRIPTS = sorted(EXAMPLES.glob("ruletest*.al"), key=lambda p: int(p.stem[8:]))
ALL_SCRIPTS += sorted(PYDY.glob("*.al"))

pytestmark = pytest.mark.skipif(
    not EXAMPLES.is_dir(), reason="SymPy's Autolev test-examples are not installed"
)


def _id(path: Path) -> str:
    return path.stem if path.parent == EXAMPLES else f"pydy/{path.stem}"


def test_the_examples_are_all_there():
    names = {_id(p) for p in ALL_SCRIPTS}
    assert {f"ruletest{i}" for i in range(1, 13)} <= names
    assert {
        "pydy/double_pendulum",
        "pydy/chaos_pendulum",
        "pydy/mass_spring_damper",
        "pydy/non_min_pendulum",
    } <= names


@pytest.mark.parametrize("path", ALL_SCRIPTS, ids=_id)
def test_converts_and_imports(path, tmp_path):
    result = convert(path.read_text(encoding="utf-8"), str(path))
    module = load_module(result.code, tmp_path, result.module)
    assert len(module.AUTOLEV) > 0


# ------------------------------------------------------- SymPy's equations


def repair(source: str) -> str:
    """SymPy's expected code with the slips listed in the module doc fixed."""
    source = source.split("from pydy.system import System")[0]

    def fix(m: re.Match) -> str:
        names = " ".join(n.rstrip("_") for n in m.group(2).split())
        return f"dynamicsymbols({m.group(1)}{names}{m.group(1)}, {m.group(3)})"

    fixed = re.sub(_DERIVATIVES, fix, source)
    for m in re.finditer(_DERIVATIVES, fixed):
        assert not any(n.endswith("_") for n in m.group(2).split()), m.group(0)
    return fixed


#: ``dynamicsymbols('names', order)``: derivatives of the named functions.
_DERIVATIVES = r"dynamicsymbols\((['\"])([^'\"]*)\1, (\d)\)"


def sympy_model(name: str) -> dict:
    """Run SymPy's (repaired) expected code; return its namespace."""
    source = repair((PYDY / f"{name}.py").read_text(encoding="utf-8"))
    namespace: dict = {}
    exec(compile(source, f"{name}.py", "exec"), namespace)  # noqa: S102
    return namespace


def our_model(name: str, tmp_path: Path):
    path = PYDY / f"{name}.al"
    result = convert(path.read_text(encoding="utf-8"), str(path))
    return load_module(result.code, tmp_path, result.module)


def evaluate(expr, point: dict, constants: dict) -> complex:
    """``expr`` at ``point[(name, order)]`` for functions of time and their
    derivatives, and ``constants[name]`` for symbols (names lower-cased)."""
    expr = sp.sympify(expr)
    table = {}
    for d in expr.atoms(sp.Derivative):
        table[d] = point[(d.expr.func.__name__.lower(), d.derivative_count)]
    expr = expr.xreplace(table)
    table = {
        f: point[(f.func.__name__.lower(), 0)]
        for f in expr.atoms(sp.core.function.AppliedUndef)
    }
    expr = expr.xreplace(table)
    expr = expr.xreplace({s: constants[s.name.lower()] for s in expr.free_symbols})
    assert not expr.free_symbols, expr.free_symbols
    return complex(sp.N(expr, 30))


def random_values(names, seed, lo=0.3, hi=1.7) -> dict:
    r = random.Random(seed)
    return {n: r.uniform(lo, hi) * r.choice((1, -1)) for n in names}


def assert_rows_equal(ours, theirs, points) -> None:
    """Each row equal at every point (relative 1e-9), and not trivially 0."""
    assert len(ours) == len(theirs)
    for i, (a, b) in enumerate(zip(ours, theirs, strict=True)):
        nonzero = False
        for point, constants in points:
            x = evaluate(a, point, constants)
            y = evaluate(b, point, constants)
            assert abs(x - y) <= 1e-9 * max(1.0, abs(y)), (i + 1, point, x, y)
            nonzero = nonzero or abs(y) > 1e-6
        assert nonzero, f"row {i + 1} is zero at every point: nothing compared"


def our_zero(module) -> list:
    """Our ZERO with every named quantity (IAYY, LA, Q1'...) substituted."""
    return [module.al.resolve(e) for e in module.AUTOLEV["ZERO"]]


def test_double_pendulum_matches_sympy(tmp_path):
    theirs = sympy_model("double_pendulum")["zero"]
    ours = our_zero(our_model("double_pendulum", tmp_path))
    points = []
    for seed in range(4):
        v = random_values(["q1", "q2", "u1", "u2", "a1", "a2", "l", "m", "g"], seed)
        point = {
            ("q1", 0): v["q1"],
            ("q2", 0): v["q2"],
            ("u1", 0): v["u1"],
            ("u2", 0): v["u2"],
            ("q1", 1): v["u1"],  # Q1' = U1
            ("q2", 1): v["u2"],
            ("u1", 1): v["a1"],
            ("u2", 1): v["a2"],
        }
        points.append((point, {k: v[k] for k in ("l", "m", "g")}))
    assert_rows_equal(ours, theirs, points)


def test_chaos_pendulum_matches_sympy(tmp_path):
    theirs = sympy_model("chaos_pendulum")["zero"]
    module = our_model("chaos_pendulum", tmp_path)
    ours = our_zero(module)
    # al2py's speeds are THETA' and PHI' (OMEGA and ALPHA name them)
    assert all(e.has(sp.Derivative(module.THETA, (t, 2))) for e in ours[:1])
    points = []
    names = ["theta", "phi", "omega", "alpha", "domega", "dalpha"]
    names += ["g", "lb", "w", "h", "ma", "mb"]
    for seed in range(4):
        v = random_values(names, seed)
        point = {
            ("theta", 0): v["theta"],
            ("phi", 0): v["phi"],
            ("theta", 1): v["omega"],
            ("phi", 1): v["alpha"],
            ("theta", 2): v["domega"],
            ("phi", 2): v["dalpha"],
            ("omega", 0): v["omega"],
            ("alpha", 0): v["alpha"],
            ("omega", 1): v["domega"],
            ("alpha", 1): v["dalpha"],
        }
        constants = {k: abs(v[k]) for k in ("g", "lb", "w", "h", "ma", "mb")}
        points.append((point, constants))
    assert_rows_equal(ours, theirs, points)


def test_non_min_pendulum_matches_sympy(tmp_path):
    ns = sympy_model("non_min_pendulum")
    theirs = ns["zero"]
    ours = our_zero(our_model("non_min_pendulum", tmp_path))
    assert len(theirs) == 2  # Fr + Fr* for U_Q2_D, and the configuration row
    q1, q2 = ns["q1"], ns["q2"]
    # The dependent speed from SymPy's own constraint f_v = 0 (linear in q1').
    u1, u2 = sp.symbols("u1 u2")
    f_v = ns["f_v"].subs({q1.diff(t): u1, q2.diff(t): u2})
    dep = sp.solve(f_v, u1)
    assert len(dep) == 1
    dep_of_t = dep[0].subs(u2, q2.diff(t))
    ddep_of_t = sp.diff(dep_of_t, t)
    points = []
    for seed in range(4):
        v = random_values(["q1", "q2", "u2", "a2", "l", "m", "g"], seed)
        v["q1"] = abs(v["q1"])  # theta1 = atan(q2/q1) with q1 > 0
        base = {("q1", 0): v["q1"], ("q2", 0): v["q2"]}
        base.update({("q2", 1): v["u2"], ("q2", 2): v["a2"]})
        dep_value = float(evaluate(dep_of_t, base, {}).real)
        base[("q1", 1)] = dep_value  # the derivative of Q1' involves Q1'
        ddep_value = float(evaluate(ddep_of_t, base, {}).real)
        point = dict(base)
        point.update(
            {
                ("q1", 1): dep_value,
                ("q1", 2): ddep_value,
                ("u_q1_d", 0): dep_value,
                ("u_q1_d", 1): ddep_value,
                ("u_q2_d", 0): v["u2"],
                ("u_q2_d", 1): v["a2"],
            }
        )
        points.append((point, {k: abs(v[k]) for k in ("l", "m", "g")}))
    assert_rows_equal(ours, theirs, points)


def test_non_min_pendulum_speeds_are_derivatives(tmp_path):
    """MotionVariables' Q{2}'' without U variables: Q1', Q2' are the speeds;
    Constrain(DEPENDENT[Q1']) solves Q1' and leaves one row, in Q2''."""
    module = our_model("non_min_pendulum", tmp_path)
    q1, q2 = module.Q1, module.Q2
    assert module.al.model.generalized_speeds() == [q1.diff(t), q2.diff(t)]
    assert module.al.model.fr_speeds() == [q2.diff(t)]
    q1dot = module.AUTOLEV["Q1'"]
    assert sp.simplify(q1dot + q2 * q2.diff(t) / q1) == 0
    assert module.AUTOLEV["ZERO[1]"].has(sp.Derivative(q2, (t, 2)))
    assert not module.AUTOLEV["ZERO[1]"].has(sp.Derivative(q1, t))
