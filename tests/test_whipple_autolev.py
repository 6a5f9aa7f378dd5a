"""The Whipple benchmark as an Autolev script (tests/models/whipple_benchmark.al).

The script is our own, written from the paper's description with tutorial
syntax.  It converts today; deriving it end to end needs the runtime's Kane
path to use intermediate variables (FastKane), see issue 10."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.fastkane import FastKane

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
    assert '"BODY321"' in code


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


@pytest.mark.slow
@pytest.mark.skip(
    reason="issue 10: importing the converted Whipple does not finish (>150 s) -- "
    "the runtime's own Constrain/Kane swell without intermediates; enable once "
    "the runtime derives its KaneInputs with FastKane"
)
def test_whipple_script_eigenvalues(tmp_path):  # pragma: no cover - see skip
    from al2py_runtime.model import kane_inputs

    result = convert(SCRIPT.read_text(), str(SCRIPT))
    path = tmp_path / "whipple_benchmark.py"
    path.write_text(result.code)
    spec = importlib.util.spec_from_file_location("whipple_benchmark", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    inputs = kane_inputs(module.al.model)
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
