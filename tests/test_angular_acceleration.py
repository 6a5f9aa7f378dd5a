"""``ALF_B_A> = ...`` given by the script is used as Autolev used it: B's
angular acceleration in N is ``ALF_A_N> + ALF_B_A> + W_A_N> x W_B_A>``.

Evidence: Autolev's bicycle14.m (MAE-223) builds every body's angular
acceleration this way from the script's ``ALF_B_A> = DT(W_B_A>, N)``; with
it al2py's equations match that program (docs/judge.md).  When the script
gives ``ALF_B_A>`` as the derivative in A, this is the derivative of
``W_B_N>`` in N, so consistent scripts are unchanged.
"""

from __future__ import annotations

import random

import sympy as sp
from conftest import load_module
from sympy.physics.vector import dynamicsymbols

from al2py import convert

SCRIPT = """\
Newtonian N
Frames A, B
Variables Q1', Q2'
Simprot(N, A, 3, Q1)
Simprot(A, B, 1, Q2)
W_A_N> = Q1'*A3>
W_B_A> = Q2'*B1>
ALF_A_N> = DT(W_A_N>, N)
ALF_B_A> = DT(W_B_A>, {frame})
W_B_N> = W_A_N> + W_B_A>
Alf_B_N>
"""


def _alf(tmp_path, frame):
    path = tmp_path / f"alf_{frame}.al"
    path.write_text(SCRIPT.format(frame=frame))
    module = load_module(convert(path.read_text(), str(path)).code, tmp_path, path.stem)
    return module, module.AUTOLEV["ALF_B_N>"]


def _at_random_point(module, vector, frame):
    rng = random.Random(7)
    values = {}
    for f in (module.Q1, module.Q2):
        for k in (2, 1, 0):
            values[f.diff(dynamicsymbols._t, k) if k else f] = rng.uniform(-2, 2)
    matrix = sp.Matrix(vector.to_matrix(frame)).xreplace(values).evalf()
    assert not matrix.free_symbols
    return matrix


def test_given_relative_angular_acceleration_is_composed_as_autolev_does(tmp_path):
    module, alf = _alf(tmp_path, "N")
    a, b = module.A, module.B
    w_an, w_ba = module.AUTOLEV["W_A_N>"], module.AUTOLEV["W_B_A>"]
    given = module.AUTOLEV["ALF_B_A>"]  # the script's: the derivative in N
    expected = module.AUTOLEV["ALF_A_N>"] + given + (w_an ^ w_ba)
    difference = _at_random_point(module, alf - expected, b)
    assert max(abs(x) for x in difference) < 1e-12
    # ... which is not the derivative of W_B_N> in N: the script's ALF_B_A>
    # already holds W_A_N> x W_B_A>, so Autolev counts it twice
    true = module.AUTOLEV["W_B_N>"].dt(module.N)
    assert max(abs(x) for x in _at_random_point(module, alf - true, a)) > 1e-3


def test_consistent_relative_angular_acceleration_changes_nothing(tmp_path):
    module, alf = _alf(tmp_path, "A")
    true = module.AUTOLEV["W_B_N>"].dt(module.N)
    assert max(abs(x) for x in _at_random_point(module, alf - true, module.B)) < 1e-12
