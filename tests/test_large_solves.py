"""Large linear solves do not swell, whatever AutoZ says (issue 21).

tests/models/twin_disc.al (our own: two rolling discs turning alike, nine
velocity constraints) has ``AutoZ OFF``.  Its ``Constrain`` of nine dependent
speeds, and the same nine-unknown system through ``Solve``, are solved by
elimination with named entries (Cramer's rule on it did not finish in 15
minutes).  The results must equal a written-out derivation at random points:
the constraint matrix of the explicit ``DEPENDENT`` solved by numpy, and the
time derivative of the constraints, written out by sympy, vanishing."""

from __future__ import annotations

import random
import time
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import walks
from al2py_runtime.intermediates.autoz import has_intermediates
from conftest import load_module

from al2py import convert

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "models" / "twin_disc.al"
DEPENDENT = ["U1", "U2", "U3", "U4", "U6", "U7", "U8", "U9", "U10"]


def _module(tmp_path: Path, source: str, name: str):
    path = tmp_path / f"{name}.al"
    path.write_text(source)
    result = convert(source, str(path))
    start = time.perf_counter()
    module = load_module(result.code, tmp_path, name)
    return module, time.perf_counter() - start


@pytest.fixture(scope="module")
def twin(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("twin")
    source = SCRIPT.read_text()
    solve = source.replace(
        "Constrain(DEPENDENT[" + ", ".join(DEPENDENT) + "])",
        "Solve(DEPENDENT, " + ", ".join(DEPENDENT) + ")",
    )
    solve = solve[: solve.index("Gravity")]
    assert "Solve(DEPENDENT" in solve
    return _module(tmp, source, "twin_constrain"), _module(tmp, solve, "twin_solve")


def _point(seed: int) -> dict:
    rng = random.Random(seed)
    point = {f"Q{k}": rng.uniform(-0.8, 0.8) for k in range(1, 11)}
    point.update(R=rng.uniform(0.2, 0.5), G=9.81, M=rng.uniform(1, 3))
    point["U5"] = rng.uniform(-3, 3)
    point["U5'"] = rng.uniform(-3, 3)
    return point


def _subs(module, point: dict) -> dict:
    """Symbols (module attributes: ``module.Q1``) -> the point's numbers."""
    return {
        getattr(module, key): value for key, value in point.items() if "'" not in key
    }


T = sp.Symbol("t")


def _constraints(module) -> sp.Matrix:
    """The explicit ``DEPENDENT`` with the kinematical equations Q' = U."""
    rates = {
        sp.Derivative(getattr(module, f"Q{k}"), T): getattr(module, f"U{k}")
        for k in range(1, 11)
    }
    return sp.Matrix(module.AUTOLEV["DEPENDENT"]).xreplace(rates)


def _written_out(module, point: dict) -> np.ndarray:
    """The dependent speeds from the explicit constraints, solved by numpy."""
    rows = _constraints(module)
    unknowns = [getattr(module, u) for u in DEPENDENT]
    numbers = _subs(module, point)
    a = rows.jacobian(unknowns).xreplace(numbers)
    b = rows.xreplace(dict.fromkeys(unknowns, 0)).xreplace(numbers)
    return np.linalg.solve(
        np.array(a.evalf(), dtype=float), -np.array(b.evalf(), dtype=float)
    ).ravel()


@pytest.mark.parametrize("which", [0, 1], ids=["constrain", "solve"])
def test_nine_unknowns_derive_in_seconds(twin, which):
    module, seconds = twin[which]
    assert seconds < 60, f"import took {seconds:.1f} s"  # was > 900 s
    # Named entries internally, AutoZ OFF notwithstanding ...
    assert has_intermediates(module.al.value("U1"))


@pytest.mark.parametrize("which", [0, 1], ids=["constrain", "solve"])
@pytest.mark.parametrize("seed", [1, 2, 3])
def test_solutions_equal_written_out_derivation(twin, which, seed):
    module, _ = twin[which]
    point = _point(seed)
    expected = _written_out(module, point)
    ours = np.array([float(module.evaluate(u, **point)) for u in DEPENDENT])
    assert np.allclose(ours, expected, rtol=1e-9, atol=1e-10), (ours, expected)


@pytest.mark.parametrize("seed", [4, 5])
def test_constrained_accelerations_keep_the_constraints(twin, seed):
    """``Constrain`` also gives U1' ... U10': the time derivative of the
    explicit constraints (written out by sympy, Q' = U) must vanish there."""
    module, _ = twin[0]
    point = _point(seed)
    qs = [getattr(module, f"Q{k}") for k in range(1, 11)]
    us = [getattr(module, f"U{k}") for k in range(1, 11)]
    rates = (
        _constraints(module)
        .diff(T)
        .xreplace({sp.Derivative(q, T): u for q, u in zip(qs, us, strict=True)})
    )
    speeds = {u: float(module.evaluate(u, **point)) for u in DEPENDENT + ["U5"]}
    accels = {f"{u}'": float(module.evaluate(f"{u}'", **point)) for u in DEPENDENT}
    accels["U5'"] = point["U5'"]
    numbers = _subs(module, {k: v for k, v in point.items() if "'" not in k})
    numbers.update({getattr(module, u): v for u, v in speeds.items()})
    numbers.update(
        {sp.Derivative(getattr(module, u[:-1]), T): v for u, v in accels.items()}
    )
    values = np.array(
        rates.xreplace({k: v for k, v in numbers.items() if k.is_Derivative})
        .xreplace({k: v for k, v in numbers.items() if not k.is_Derivative})
        .evalf(),
        dtype=float,
    )
    assert np.abs(values).max() < 1e-9, values


def test_autolev_of_a_large_value_comes_back_over_intermediates(twin, monkeypatch):
    """``AUTOLEV[name]`` writes out values up to ``WRITE_OUT`` nodes only;
    a larger one comes back at once over named intermediates, and
    ``AUTOLEV.written_out(name)`` writes it out: both equal at a point."""
    module, _ = twin[0]
    names = module.AUTOLEV
    name = next(u for u in DEPENDENT if has_intermediates(module.al.value(u)))
    assert not has_intermediates(names[name])  # small: written out
    monkeypatch.setattr(type(names), "WRITE_OUT", 1)
    start = time.perf_counter()
    short = names[name]
    assert time.perf_counter() - start < 5
    assert has_intermediates(short)
    full = names.written_out(name)
    assert not has_intermediates(full)
    numbers = _subs(module, _point(7))
    a = complex(short.xreplace(numbers).evalf())
    b = complex(full.xreplace(numbers).evalf())
    assert a == pytest.approx(b, rel=1e-10, abs=1e-12)
    assert abs(a) > 1e-6  # a real value, not a vanishing one


def _nested_script(depth: int) -> str:
    """``E_k = E_(k-1)^2 + B*E_(k-1)`` holding an acceleration: a few dozen
    distinct parts, a tree of about 2**depth times as many nodes."""
    lines = ["AutoZ ON", "Variables Q', U', X, Y", "Constants A, B"]
    lines.append("E1 = (Q + U')*(Q - A)")
    lines += [f"E{k} = E{k - 1}*E{k - 1} + B*E{k - 1}" for k in range(2, depth + 1)]
    lines += [f"Z2 = [E{depth}*X + Y - 1; X - A*Y]", "Solve(Z2, X, Y)"]
    return "\n".join(lines) + "\n"


def test_solve_and_transcript_walk_shared_parts_once(tmp_path):
    """A Solve of equations whose parts are shared (a tree of millions of
    nodes, a few hundred distinct parts) takes each part once (it did not
    finish in minutes), and the transcript prints it with names."""
    depth = 22
    mod, seconds = _module(tmp_path, _nested_script(depth), "nested")
    assert seconds < 30
    t = sp.Symbol("t")
    q, u, a, b = (mod.al.symbol(n) for n in ("Q", "U", "A", "B"))
    point = {sp.Derivative(u, t): 0.2, q: 0.3, a: 0.1, b: 0.5}
    e = (0.3 + 0.2) * (0.3 - 0.1)
    for _ in range(depth - 1):
        e = e * e + 0.5 * e
    y = float(mod.AUTOLEV["Y"].xreplace(point).evalf())
    x = float(mod.AUTOLEV["X"].xreplace(point).evalf())
    assert y == pytest.approx(1 / (1 + 0.1 * e))
    assert x == pytest.approx(0.1 * y)
    lines = mod.al.transcript(_nested_script(depth).splitlines())
    assert max(len(line) for line in lines) < 2000


def test_responses_too_large_to_print_as_trees_are_named():
    """A response of a few dozen distinct parts but millions of tree nodes
    is shown with its parts named (its acceleration kept visible), and the
    named form has the same value."""
    from al2py_runtime.intermediates.autoz import Intermediates
    from al2py_runtime.model.kinematics import is_small
    from al2py_runtime.workspace import _named_for_display
    from sympy.physics.mechanics import dynamicsymbols

    q, u = dynamicsymbols("q u")
    a, b = sp.symbols("a b")
    ud = sp.Derivative(u, sp.Symbol("t"))
    e = (q + 2) * (q - a)
    for _ in range(15):
        e = e * e + b * e
    value = e + q * ud
    book = Intermediates()
    shown = _named_for_display(book, sp.Matrix([value]))[0]
    assert is_small(shown, 50) and shown.has(ud)
    point = {q: 0.3, a: 2.1, b: 0.5, ud: 0.7}
    want = (0.3 + 2) * (0.3 - 2.1)
    for _ in range(15):
        want = want * want + 0.5 * want
    got = float(shown.xreplace(point).evalf())
    assert got == pytest.approx(want + 0.3 * 0.7)


def _shared(depth: int):
    """A polynomial in x with a few dozen distinct parts and a tree of about
    2**depth times as many nodes, and its value at x, a, b."""
    x, a, b = sp.symbols("x a b")
    e = a * x + b + 1
    for _ in range(depth):
        e = e * e + a * e
    return e, (x, a, b)


def _value(e0, depth: int, x: float, a: float, b: float) -> float:
    e = a * x + b + 1
    for _ in range(depth):
        e = e * e + a * e
    return e


def test_exclude_include_coef_of_large_shared_expressions():
    """Exclude, Include and Coef of an expression of millions of tree nodes
    (a polynomial in the name) take each distinct part once: Exclude is the
    expression at 0, Include the rest (they were an expansion that did not
    finish)."""
    from al2py_runtime import algebra

    depth = 18
    e, (x, a, b) = _shared(depth)
    point = {a: 0.1, b: -0.95}
    rest = algebra.exclude(e + 7 * x, x)
    assert float(walks.xreplace(rest, point)) == pytest.approx(
        _value(e, depth, 0, 0.1, -0.95)
    )
    full = algebra.include(e + 7 * x, x) + rest
    at = {**point, x: 0.3}
    assert float(walks.xreplace(full, at)) == pytest.approx(
        _value(e, depth, 0.3, 0.1, -0.95) + 2.1
    )
    # Coef of a large expression linear in y
    y = sp.Symbol("y")
    c = algebra.coef(e * y + e, y)
    assert float(walks.xreplace(c, at)) == pytest.approx(
        _value(e, depth, 0.3, 0.1, -0.95)
    )
    with pytest.raises(ValueError, match="not linear"):
        algebra.coef(e * y**2, y)


def test_det_and_inv_of_large_entries_do_not_expand():
    """Det and Inv of a 3x3 matrix of large shared entries: no expansion
    (sympy's simplification as it goes took hours), the same values."""
    from al2py_runtime import matrices

    depth = 18
    e, (x, a, b) = _shared(depth)
    m = sp.Matrix([[e, 1, 0], [x, e, 2], [0, a, 1]])
    at = {x: 0.3, a: 0.1, b: -0.95}
    v = _value(e, depth, 0.3, 0.1, -0.95)
    want = np.array([[v, 1, 0], [0.3, v, 2], [0, 0.1, 1]])
    d = matrices.det(m)
    assert float(walks.xreplace(d, at)) == pytest.approx(np.linalg.det(want))
    inverse = matrices.inv(m).applyfunc(lambda z: walks.xreplace(z, at))
    got = np.array(inverse.evalf(), dtype=float)
    assert np.allclose(got, np.linalg.inv(want))
    with pytest.raises(ValueError, match="singular"):
        matrices.inv(sp.Matrix([[e, e, 0], [x, x, 2], [0, 0, 1]]))
