"""The Whipple benchmark as an Autolev script (tests/models/whipple_benchmark.al).

The script is our own, written from the paper's description with tutorial
syntax.  With ``AutoZ ON`` it derives with intermediate variables, as
Autolev did (issue 10), and its own linearization gives Table 2."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.model.fastkane import FastKane
from test_whipple import TABLE2  # Meijaard et al. (2007), Table 2

from al2py import convert

HERE = Path(__file__).resolve().parent
SCRIPT = HERE / "models" / "whipple_benchmark.al"


def _whipple():
    spec = importlib.util.spec_from_file_location(
        "_whipple_sympy", HERE / "models" / "whipple_sympy.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_whipple_script_converts():
    result = convert(SCRIPT.read_text(), str(SCRIPT))
    code = result.code
    compile(code, "whipple_benchmark.py", "exec")
    # Every constraint and the steer-axis orientation reach the module.
    assert code.count("DEPENDENT") >= 5
    assert 'orient_body_fixed(E, (Q7, -LAM, 0), "321")' in code


def test_whipple_script_parameters_are_table1():
    """The script's Input values are Table 1's (the sympy fixture's)."""
    whipple = _whipple()
    values = {}
    for line in SCRIPT.read_text().splitlines():
        if line.startswith("Input "):
            for item in line[len("Input ") :].split(","):
                name, value = item.split("=")
                values[name.strip()] = float(value)
    spelled = {name.upper(): value for name, value in whipple.BENCHMARK.items()}
    assert values.keys() == spelled.keys()
    for name, value in spelled.items():
        assert np.isclose(values[name], value, rtol=0, atol=1e-14), name


@pytest.fixture(scope="module")
def whipple_module(tmp_path_factory):
    """The script converted and imported: it derives with AutoZ intermediates
    (about 20 s here; it did not finish in 25 minutes without them)."""
    result = convert(SCRIPT.read_text(), str(SCRIPT))
    path = tmp_path_factory.mktemp("whipple") / "whipple_benchmark.py"
    path.write_text(result.code)
    spec = importlib.util.spec_from_file_location("whipple_benchmark", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.mark.parametrize("speed", sorted(TABLE2))
def test_whipple_script_eigenvalues(whipple_module, speed):
    """The script's own linearization, AL = D([U4'; U7'], [Q4; Q7; U4; U7]),
    evaluated upright at forward speed v (U6 = -v/RR), gives Table 2."""
    upright = {f"Q{k}": 0.0 for k in range(1, 9)}
    al = whipple_module.evaluate("AL", U6=-speed / 0.3, U4=0.0, U7=0.0, **upright)
    a = np.zeros((4, 4))
    a[0, 2] = a[1, 3] = 1.0
    a[2:, :] = np.asarray(al, dtype=float)
    got = np.sort_complex(np.linalg.eigvals(a))
    wanted = np.sort_complex(np.asarray(TABLE2[speed], dtype=complex))
    assert np.max(np.abs(got - wanted)) < 1e-8, (got, wanted)


def test_whipple_script_uses_intermediates(whipple_module):
    """AutoZ ON: ZERO is written with Z intermediates, and sympy's model of
    the script (KanesMethod's inputs) has them written out."""
    from al2py_runtime.intermediates.autoz import has_intermediates
    from al2py_runtime.model import kane_inputs

    assert has_intermediates(whipple_module.al.value("ZERO"))
    inputs = kane_inputs(whipple_module.al.model)
    assert not has_intermediates(inputs.velocity_constraints)
    n = inputs.frame
    for body in inputs.bodies:
        assert not has_intermediates(body.masscenter.vel(n).to_matrix(n))
        assert not has_intermediates(body.masscenter.acc(n).to_matrix(n))


@pytest.mark.slow
def test_whipple_script_fastkane_eigenvalues(whipple_module):
    """sympy's model of the script (kane_inputs), derived by FastKane, gives
    Table 2 too."""
    from al2py_runtime.model import kane_inputs

    inputs = kane_inputs(whipple_module.al.model)
    kane = FastKane.from_inputs(inputs)
    whipple = _whipple()
    by_name = {
        str(s.func) if hasattr(s, "func") else str(s): s for s in kane.q[:] + kane.u[:]
    }
    model = {
        "q": [by_name[f"Q{k}"] for k in range(1, 9)],
        "u": [by_name[f"U{k}"] for k in range(1, 9)],
        "kane": {
            "u_ind": list(inputs.u_ind),
            "u_dependent": list(inputs.u_dependent),
            "velocity_constraints": list(inputs.velocity_constraints),
        },
    }
    constants = kane.mass_matrix.free_symbols | kane.forcing.free_symbols
    constants |= {s for _, e in kane.intermediates for s in e.free_symbols}
    names = {z for z, _ in kane.intermediates}
    model["params"] = sorted((constants - names) - {sp.Symbol("t")}, key=str)
    values = {name.upper(): value for name, value in whipple.BENCHMARK.items()}
    values.update(MR=2.0, MB=85.0, MH=4.0, MF=3.0)
    speeds = [0.0, 4.0, 5.0, 10.0]
    for speed, got in zip(
        speeds, whipple.eigenvalues(model, kane, speeds, values), strict=True
    ):
        wanted = whipple.reference_eigenvalues(speed)
        assert np.allclose(np.sort_complex(got), np.sort_complex(wanted), atol=1e-8)


@pytest.mark.slow
@pytest.mark.full  # sympy's own derivation of the converted Whipple takes 3-7 minutes
def test_whipple_kanes_method_equals_sympys_derivation(whipple_module):
    """The exported model (``kanes_method()``, derived by FastKane, written
    out) equals sympy's own ``KanesMethod`` derivation on the same inputs
    at a random point (about 3 minutes: sympy's derivation alone takes
    about 65 s here, the export about 8 s)."""
    from al2py_runtime.model import kane_inputs, kanes_method
    from kane_reference import assert_same_kane, sympy_kanes_method

    inputs = kane_inputs(whipple_module.al.model)
    ours = kanes_method(inputs)
    assert len(inputs.u_dependent) == 5 and ours.mass_matrix_full.shape == (16, 16)
    assert_same_kane(ours, sympy_kanes_method(inputs), "whipple", points=1)
