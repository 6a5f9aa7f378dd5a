"""One Kane formulation (issue 22): a script's ``FrStar()`` and ``FastKane``
form the generalized inertia forces with the same function
(``fastkane.inertia_rows``), and ``FrStar()`` takes accelerations from the
velocities' linear forms only where they equal the script's own."""

from __future__ import annotations

import random
import sys
from pathlib import Path

import sympy as sp
from al2py_runtime.model import equations, fastkane
from sympy.physics.mechanics import find_dynamicsymbols

from al2py import convert

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))
from conftest import load_module  # noqa: E402
from large import chain_inputs, chain_source  # noqa: E402


def _module(source: str, tmp_path: Path, name: str):
    return load_module(convert(source, f"{name}.al").code, tmp_path, name)


def _at_random_point(exprs, seed: int = 1) -> list[complex]:
    """The values of ``exprs`` with every symbol, function of time and
    derivative given a random value (the same for the same name)."""
    out = []
    for e in exprs:
        e = sp.sympify(e)
        atoms = sorted(
            e.atoms(sp.Derivative) | find_dynamicsymbols(e) | e.free_symbols,
            key=lambda x: (-sp.count_ops(x), str(x)),
        )
        values = {}
        for x in atoms:
            if x == sp.Symbol("t"):
                continue
            rng = random.Random(f"{seed}:{x}")
            values[x] = rng.uniform(0.5, 1.5)
        # derivatives first, so that U1' is not U1's value differentiated
        for x in [a for a in atoms if isinstance(a, sp.Derivative)]:
            e = e.xreplace({x: values[x]})
        out.append(complex(e.xreplace(values).evalf()))
    return out


def test_frstar_keeps_an_acceleration_that_is_not_the_velocitys_derivative(
    tmp_path,
):
    mod = _module(
        (ROOT / "tests/models/odd_acceleration.al").read_text(), tmp_path, "odd"
    )
    zero = mod.AUTOLEV["ZERO"][0]
    m, k, q, u = mod.M, mod.K, mod.Q, mod.U1
    expected = -k * q - 2 * m * sp.Derivative(u, sp.Symbol("t"))
    assert _at_random_point([zero - expected]) == [0j]


def test_fast_accelerations_equal_the_scripts(tmp_path, monkeypatch):
    """The 2-body spatial chain (A2pts accelerations, rigid bodies): ZERO from
    the velocities' linear forms equals ZERO from the script's
    accelerations at random points."""
    source = chain_source(2, autoz="OFF")
    fast = _module(source, tmp_path, "fast")
    calls = []
    original = equations.KaneEquations._same_vector

    def never(self, *args):
        calls.append(original(self, *args))
        return False

    monkeypatch.setattr(equations.KaneEquations, "_same_vector", never)
    script = _module(source, tmp_path, "script")
    assert calls and all(calls)  # the check ran and found them equal
    a = _at_random_point(list(fast.AUTOLEV["ZERO"]))
    b = _at_random_point(list(script.AUTOLEV["ZERO"]))
    assert len(a) == 6
    for x, y in zip(a, b, strict=True):
        assert abs(x - y) <= 1e-9 * max(1.0, abs(y))


def test_frstar_and_fastkane_form_inertia_forces_in_one_place(tmp_path, monkeypatch):
    used = []
    rows = fastkane.inertia_rows

    def counted(*args, **kw):
        used.append(True)
        return rows(*args, **kw)

    monkeypatch.setattr(equations, "inertia_rows", counted)
    monkeypatch.setattr(fastkane, "inertia_rows", counted, raising=True)
    _module(chain_source(2), tmp_path, "chain2")
    assert len(used) == 1  # the script's FrStar()
    fastkane.FastKane(**chain_inputs(2))
    assert len(used) == 2  # FastKane


def test_frstar_and_fastkane_share_the_kinematics(tmp_path, monkeypatch):
    """Partial velocities (linear forms) and accelerations (their rates) are
    formed by the same functions for a script and for FastKane."""
    used: dict[str, int] = {}
    for name in ("linear_form", "form_rate"):
        original = getattr(fastkane, name)

        def counted(*args, _name=name, _f=original, **kw):
            used[_name] = used.get(_name, 0) + 1
            return _f(*args, **kw)

        monkeypatch.setattr(equations, name, counted)
        monkeypatch.setattr(fastkane, name, counted)
    _module(chain_source(2), tmp_path, "chain2k")
    script = dict(used)
    assert script.get("linear_form", 0) >= 4 and script.get("form_rate", 0) >= 4
    fastkane.FastKane(**chain_inputs(2))
    assert used["linear_form"] >= script["linear_form"] + 4
    assert used["form_rate"] >= script["form_rate"] + 4
