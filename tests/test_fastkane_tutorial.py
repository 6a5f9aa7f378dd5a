"""FastKane equals KanesMethod on every tutorial model with Kane().

Both derive the same inputs, the runtime's ``KaneInputs`` of the converted
script (``al2py_runtime.model``, which arrives with the sympy-model rewrite;
until then these tests skip)."""

from __future__ import annotations

import random

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.model.fastkane import FastKane
from conftest import SHARED
from sympy.physics import mechanics as me

model_api = pytest.importorskip(
    "al2py_runtime.model", reason="the runtime's KaneInputs are not on this branch yet"
)

KANE_SCRIPTS = [
    p.stem
    for p in sorted(SHARED.glob("*.al"))
    if "KANE(" in p.read_text(errors="replace").upper()
    and "GYROSTAT" not in p.read_text(errors="replace").upper()
]


def test_there_are_tutorial_models():
    assert len(KANE_SCRIPTS) >= 6


@pytest.mark.parametrize("name", KANE_SCRIPTS)
def test_tutorial_fastkane_equals_kanesmethod(name, tutorial):
    module = tutorial(name)
    inputs = model_api.kane_inputs(module.al.model)
    km = model_api.kanes_method(inputs)
    fk = FastKane.from_inputs(inputs)
    wanted = [km.mass_matrix_full, km.forcing_full]
    got = [fk.mass_matrix_full, fk.forcing_full]
    t = me.dynamicsymbols._t
    dyn = set(km.q) | set(km.u)
    constants = set()
    for m in wanted:
        dyn |= me.find_dynamicsymbols(m)
        constants |= m.free_symbols - {t}
    args = sorted(dyn, key=str) + sorted(constants, key=str)
    f_km = sp.lambdify(args, wanted, cse=True)
    f_fk = fk.numeric(args, got)
    rng = random.Random(name)
    for _ in range(2):
        x = [rng.uniform(0.3, 1.2) for _ in args]
        for a, b in zip(f_fk(*x), f_km(*x), strict=True):
            a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
            assert a.shape == b.shape
            assert np.allclose(a, b, rtol=1e-9, atol=1e-9), (name, a, b)
