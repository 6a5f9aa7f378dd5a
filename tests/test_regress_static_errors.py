"""Regression tests: statically visible input errors that al2py accepts.

The conversion succeeds (exit 0) and the generated module then raises a Python
traceback on import.  Expected: exit 2 with ``file:line:col: error:``.
"""

from __future__ import annotations

import pytest

from al2py import convert
from al2py.errors import AutolevError

CASES = {
    "ragged_matrix": ("M = [1,2;3]\n", 1),
    "index_zero": ("X = [1, 2]\nX[0] = 2\n", 2),
    "det_of_constant": ("Constants A\nZ = Det(A)\n", 2),
    "rows_of_constant": ("Constants A\nZ = Rows(A, 1, 2)\n", 2),
    "literal_index_out_of_range": ("M = [1, 2]\nE = M[5]\n", 2),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_statically_visible_error_is_reported(name):
    src, line = CASES[name]
    with pytest.raises(AutolevError) as info:
        convert(src, "s.al")
    assert info.value.span.line == line


def test_mass_of_a_constant():
    with pytest.raises(AutolevError):
        convert("Constants A\nE = A + Mass(A)\n", "s.al")


def test_nicheck_without_newtonian():
    with pytest.raises(AutolevError):
        convert("NiCheck()\n", "s.al")
