"""The right-hand side of a model with many intermediates is compiled in
parts (issue 35, the Whipple bicycle's first run()): the same numbers, to
the bit, as the right-hand side compiled whole; a small model's C is as it
was."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.jobs import backends

pytestmark = pytest.mark.skipif(not backends.available("c"), reason="no C compiler")


def _spec(n: int) -> backends.DynamicsSpec:
    """Two accelerations from a mass matrix, state derivatives with and
    without them, and outputs, over a chain of ``n`` intermediates (powers,
    roots, functions of the states alone and of intermediates)."""
    t = sp.Symbol("t")
    q1, q2, u1, u2, a1, a2, c, k = sp.symbols("q1 q2 u1 u2 a1 a2 c k")
    zs = sp.symbols(f"z0:{n}")
    inter = [(zs[0], sp.sin(q1) * c + u1)]
    for j in range(1, n):
        z = zs[j - 1]
        inter.append(
            (
                zs[j],
                sp.cos(z) * q2
                - sp.sin(z) / (2 + u2**2)
                + c * (1 + z**2) ** sp.Rational(-3, 2)
                + sp.sqrt(1 + zs[j // 2] ** 2) * sp.tan(q2) * k / (j + 3)
                + sp.cos(q1) * zs[j // 3] / 7,
            )
        )
    mass = [
        4 + sp.cos(q1),
        sp.sin(zs[n // 2]) / 10,
        sp.cos(zs[n // 3]) / 10,
        4 + sp.sin(zs[-1]) ** 2,
    ]
    forcing = [-c * zs[-1] + t, k * zs[-2] * sp.sin(q2)]
    derivs = [u1 + zs[-3], u2, a1, a2 * zs[5] + zs[-4]]
    outputs = [[q1, a1 * zs[-1]], [zs[j] + t for j in range(0, n, 7)]]
    return backends.DynamicsSpec(
        t, [q1, q2, u1, u2], [a1, a2], [c, k], mass, forcing, derivs, outputs, inter
    )


def _bound(spec, p, **split):
    path, _hit = backends.build_stream(backends.c_model_stream(spec, **split))
    lib = backends.load_library(path)
    nout = sum(map(len, spec.outputs))
    return backends._CBound(
        lib, len(spec.states), nout, [len(r) for r in spec.outputs], p
    )


def _same(a, b) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


@pytest.mark.parametrize("outputs_split", [None, 10])
def test_split_rhs_gives_the_same_bits(monkeypatch, tmp_path, outputs_split):
    """al_rhs, al_out and al_advance of the split right-hand side (with the
    outputs whole or in parts too) give exactly the unsplit numbers."""
    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path))
    spec = _spec(60)
    p = [0.7, 0.3]
    whole = _bound(spec, p, split=outputs_split, rhs_split=1000)
    parts = _bound(spec, p, split=outputs_split, rhs_split=10)
    rng = random.Random(35)
    for _ in range(200):
        y = np.array([rng.uniform(-2, 2) for _ in range(4)])
        tt = rng.uniform(0, 3)
        assert _same(whole.rhs(tt, y), parts.rhs(tt, y))
        for a, b in zip(whole.outputs(tt, y), parts.outputs(tt, y), strict=True):
            assert _same(a, b)
    y0 = [0.1, -0.2, 0.3, 0.05]
    steppers = [b.stepper(0.0, y0, 0.01, 1e-8, 1e-8) for b in (whole, parts)]
    for target in (0.5, 1.0, 2.0):
        for s in steppers:
            s.advance(target)
        assert _same(steppers[0].y, steppers[1].y)
        assert steppers[0].evals == steppers[1].evals > 0


def test_split_rhs_compiles_in_several_units(monkeypatch, tmp_path):
    """Above rhs_split intermediates, they are computed by functions al_rK
    in two units or more (-O2), before the unit of al_mf, which computes the
    functions of the states alone once and keeps everything in z."""
    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path))
    spec = _spec(60)
    units = backends.c_model_units(spec, rhs_split=10)
    assert len(units) >= 3
    assert all(flags == ("-O2",) for _text, flags in units)
    *parts, main = units
    assert all("void al_r" in text and "al_mf" not in text for text, _f in parts)
    assert "double z[" in main[0] and "al_r0(t, y, p, z);" in main[0]
    # a function of the states alone: once, in al_mf, before the parts
    mf = main[0][main[0].index("void al_mf") : main[0].index("int al_rhs")]
    assert mf.count("sin(y[0])") == 1
    assert mf.index("sin(y[0])") < mf.index("al_r0(t, y, p, z);")
    assert not any("sin(y[" in text or "cos(y[" in text for text, _f in parts)
    path, hit = backends.build_stream(iter(units))
    assert not hit and path.exists()
    assert len(list(tmp_path.glob("*.o"))) == len(units)
    # with the outputs in parts too: the parts, the right-hand side, then
    # the outputs' parts and al_out
    both = backends.c_model_units(spec, split=10, rhs_split=10)
    assert [f for _t, f in both[: len(units)]] == [("-O2",)] * len(units)
    assert both[len(units)][1] == backends.OUT_FLAGS
    assert backends.build_stream(iter(both))[0].exists()


def test_small_models_keep_their_c():
    """At or below the thresholds the C is one unit, c_model_source's."""
    spec = _spec(30)
    assert backends.c_model_units(spec) == [(backends.c_model_source(spec), ("-O2",))]
    exprs, _targets = backends._mf_exprs(spec)
    count = len(backends.needed(spec.intermediates, exprs, spec.free))
    units = backends.c_model_units(spec, rhs_split=count)
    assert units == [(backends.c_model_source(spec), ("-O2",))]
    assert len(backends.c_model_units(spec, rhs_split=count - 1)) > 1
