"""Regression tests for numerical jobs found on SymPy's examples."""

from __future__ import annotations

import pytest
from conftest import load_module

from al2py import convert

ALIAS = """\
MotionVariables' THETA'', OMEGA'
Constants G, L
Newtonian N
Bodies A
Simprot(N, A, 2, THETA)
OMEGA = THETA'
W_A_N> = OMEGA*N2>
Points O
P_O_AO> = L*A3>
V_O_N> = 0>
V2pts(N, A, O, AO)
Mass A=M
Inertia A, 0, 0, 0
Gravity(G*N3>)
Zero = Fr() + FrStar()
Kane()
Input G=9.81, L=1, M=1, THETA=1 rad, OMEGA=0.5
Input tFinal=1, integStp=0.1
CODE Dynamics() alias.c
"""


def test_input_of_an_alias_sets_the_state_it_names(tmp_path):
    """``OMEGA = THETA'`` and ``Input OMEGA=0.5``: THETA' starts at 0.5."""
    code = convert(ALIAS, str(tmp_path / "alias.al")).code
    result = load_module(code, tmp_path, "alias").run()
    assert float(result.states["THETA'"][0]) == pytest.approx(0.5)
    assert not any("THETA'" in note for note in result.notes)
