"""The exported model equals sympy's own ``KanesMethod`` (issue 22).

``kanes_method()`` is a ``KanesMethod`` whose equations the runtime's engine,
FastKane, derives and writes out.  On every tutorial script with ``Kane()``
and the models of ``tests/models``, its mass matrix, forcing (full forms),
Fr, Fr* and auxiliary equations equal those of sympy's ``KanesMethod``
derivation on the same ``KaneInputs``, at random points, as plain
expressions; and the runtime never calls sympy's derivation."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import model as model_api
from conftest import ROOT, SHARED
from kane_reference import assert_same_kane, sympy_kanes_method
from sympy.physics import mechanics as me

KANE_SCRIPTS = [
    p.stem
    for p in sorted(SHARED.glob("*.al"))
    if "KANE(" in p.read_text(errors="replace").upper()
    and "GYROSTAT" not in p.read_text(errors="replace").upper()
]
MODELS = ROOT / "tests" / "models"
MODEL_SCRIPTS = [
    "aux_planar_pendulum",  # auxiliary and dependent speeds
    "aux_spherical_pendulum",
    "rolling_disc",
    "twin_disc",
]


def test_there_are_tutorial_models():
    assert len(KANE_SCRIPTS) >= 6


@pytest.mark.parametrize("name", KANE_SCRIPTS)
def test_tutorial_export_equals_kanesmethod(name, tutorial):
    module = tutorial(name)
    inputs = model_api.kane_inputs(module.al.model)
    assert_same_kane(model_api.kanes_method(inputs), sympy_kanes_method(inputs), name)


@pytest.mark.parametrize("name", MODEL_SCRIPTS)
def test_model_export_equals_kanesmethod(name, convert_and_import):
    module, _ = convert_and_import(MODELS / f"{name}.al")
    inputs = model_api.kane_inputs(module.al.model)
    assert_same_kane(model_api.kanes_method(inputs), sympy_kanes_method(inputs), name)


@pytest.fixture
def no_sympy_derivation(monkeypatch):
    """sympy's Kane derivation (``kanes_equations`` and the Fr, Fr* and
    acceleration-constraint steps under it) raises."""
    calls = []

    def refuse(name):
        def method(self, *args, **kw):
            calls.append(name)
            raise AssertionError(f"sympy's KanesMethod.{name} was called")

        return method

    for name in ("kanes_equations", "_form_fr", "_form_frstar"):
        monkeypatch.setattr(me.KanesMethod, name, refuse(name))
    return calls


@pytest.mark.parametrize("name", ["tutor6", "tutor7c"])
def test_runtime_never_calls_sympys_derivation(name, tutorial, no_sympy_derivation):
    with pytest.raises(AssertionError, match="kanes_equations"):
        me.KanesMethod.kanes_equations(None)  # the guard is in place
    no_sympy_derivation.clear()
    km = tutorial(name).kanes_method()
    assert isinstance(km, me.KanesMethod) and km.mass_matrix_full.shape[0] > 2
    assert no_sympy_derivation == []


@pytest.mark.parametrize("name", ["tutor6", "tutor7c"])
def test_linearize_equals_kanesmethods(name, tutorial):
    """``linearize()`` (sympy's, reading the stored equations) gives
    ``KanesMethod``'s M, A, B; tutor7c has dependent speeds and the
    constraint forces FC1, FC2 as inputs ``r``."""
    inputs = model_api.kane_inputs(tutorial(name).al.model)
    ours = model_api.kanes_method(inputs).linearize()
    ref = sympy_kanes_method(inputs).linearize()
    assert ours[3] == ref[3]
    args = sorted(set().union(*(m.free_symbols for m in ref[:3])), key=str)
    dyn = sorted(set().union(*(me.find_dynamicsymbols(m) for m in ref[:3])), key=str)
    assert all(set(m.free_symbols) <= set(args) for m in ours[:3])
    f_ours = sp.lambdify(dyn + args, ours[:3])
    f_ref = sp.lambdify(dyn + args, ref[:3])
    rng = np.random.default_rng(5)
    for _ in range(2):
        x = rng.uniform(0.3, 1.2, len(dyn) + len(args))
        for a, b in zip(f_ours(*x), f_ref(*x), strict=True):
            assert np.allclose(a, b, rtol=1e-9, atol=1e-9)
