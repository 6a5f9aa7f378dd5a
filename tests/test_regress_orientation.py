"""A frame used before it is oriented is the script's error (issue 32).

It was reported as "an unexpected failure in sympy (an al2py bug ...)".
Where the unit vectors are written out, conversion stops at the call
(``file:line:col``); otherwise the module names the ``.al`` line and both
frames when it runs.
"""

from __future__ import annotations

import pytest
from al2py_runtime.safety import AutolevRuntimeError
from conftest import load_module

from al2py import convert
from al2py.errors import AutolevError

HEAD = "Newtonian N\nFrames A, B\nVariables Q\n"

STATIC = {
    "dot": ("V = Dot(A1>, N1>)\n", 5),
    "cross": ("V> = Cross(A1>, N1>)\n", 6),
    "express": ("V> = Express(A1>, N)\n", 6),
    "mag": ("V = Mag(A1> + N1>)\n", 5),
    "dt": ("V> = Dt(A1>, N)\n", 6),
    "oriented later": ("V = Dot(A1>, N1>)\nSimprot(N, A, 3, Q)\n", 5),
    "other pair oriented": ("Simprot(N, B, 3, Q)\nV = Dot(A1>, B1>)\n", 5),
}


@pytest.mark.parametrize("name", sorted(STATIC))
def test_a_frame_used_before_it_is_oriented_stops_conversion(name):
    body, col = STATIC[name]
    with pytest.raises(AutolevError) as info:
        convert(HEAD + body, "s.al")
    err = info.value
    line = 4 + body.split("\n").index(next(ln for ln in body.split("\n") if "1>" in ln))
    assert (err.span.line, err.span.col) == (line, col)
    assert "not oriented relative to frame" in err.message
    assert "sympy" not in err.message and "bug" not in err.message
    frames = {"A", "N"} if "B1>" not in body else {"A", "B"}
    assert all(f"frame {f}" in err.message for f in frames), err.message


OK = {
    "simprot": "Simprot(N, A, 3, Q)\nV = Dot(A1>, N1>)\n",
    "through another frame": (
        "Simprot(N, B, 3, Q)\nSimprot(B, A, 1, Q)\nV = Dot(A1>, N1>)\n"
    ),
    "direction cosines": "N_A = [1, 0, 0; 0, 1, 0; 0, 0, 1]\nV = Dot(A1>, N1>)\n",
    "dircos": "Dircos(N, A, Body123, Q, Q, Q)\nV> = Express(A1>, N)\n",
    "one frame": "V = Dot(A1>, A2>)\n",
}


@pytest.mark.parametrize("name", sorted(OK))
def test_oriented_frames_convert(name):
    convert(HEAD + OK[name], "s.al")


def test_an_unoriented_frame_in_a_named_vector_is_located_when_it_runs(tmp_path):
    text = HEAD + "V> = A1>\nX = Dot(V>, N1>)\n"
    result = convert(text, "s.al")
    with pytest.raises(AutolevRuntimeError) as info:
        load_module(result.code, tmp_path, result.module)
    err = info.value
    assert (err.filename, err.line) == ("s.al", 5)
    assert "frame A is not oriented relative to frame N" in err.message
    assert "sympy" not in err.message and "bug" not in err.message


def test_a_velocity_without_angular_velocity_is_located_when_it_runs(tmp_path):
    text = HEAD + "P_NO_AO> = A1>\nW> = V_AO_N>\n"
    result = convert(text, "s.al")
    with pytest.raises(AutolevRuntimeError) as info:
        load_module(result.code, tmp_path, result.module)
    err = info.value
    assert err.line == 5
    assert "frame A has no angular velocity relative to frame N" in err.message
