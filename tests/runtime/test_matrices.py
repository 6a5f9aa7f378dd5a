"""Tests for al2py_runtime.matrices (Autolev matrix commands)."""

from __future__ import annotations

import pytest
import sympy as sp
from al2py_runtime import matrices as mt

A, B, C, D = sp.symbols("A B C D", real=True)
M0 = sp.Matrix([[A, B], [C, D]])


def test_block_tutor1():
    m1 = mt.block([[M0, sp.Matrix([[1, 2], [3, 4]])]])
    assert m1 == sp.Matrix([[A, B, 1, 2], [C, D, 3, 4]])


def test_block_scalars_and_stacking():
    assert mt.block([[1, 2, 3, 4]]) == sp.Matrix([[1, 2, 3, 4]])
    assert mt.block([[1], [2]]) == sp.Matrix([1, 2])
    col = sp.Matrix([A, B])
    assert mt.block([[col], [C]]) == sp.Matrix([A, B, C])
    assert mt.block([[sp.eye(2), col], [sp.Matrix([[C, D]]), 5]]) == sp.Matrix(
        [[1, 0, A], [0, 1, B], [C, D, 5]]
    )


def test_block_errors():
    with pytest.raises(ValueError, match="row 1"):
        mt.block([[sp.eye(2), 1]])
    with pytest.raises(ValueError, match="columns"):
        mt.block([[1, 2], [3]])


def test_rows_cols_tutor1():
    assert mt.rows(M0) == 2 and isinstance(mt.rows(M0), sp.Integer)
    assert mt.cols(M0) == 2
    assert mt.rows(M0, 2, (1, 2)) == sp.Matrix([[C, D], [A, B], [C, D]])
    assert mt.cols(M0, 1) == sp.Matrix([A, C])
    wide = sp.Matrix([[1, 2, 3, 4, 5]])
    assert mt.cols(wide, 1, (3, 4)) == sp.Matrix([[1, 3, 4]])


def test_rows_cols_errors():
    with pytest.raises(ValueError, match="row 3 is out of range"):
        mt.rows(M0, 3)
    with pytest.raises(ValueError, match="column 0 is out of range"):
        mt.cols(M0, 0)
    with pytest.raises(ValueError, match="empty"):
        mt.rows(M0, (2, 1))
    with pytest.raises(TypeError):
        mt.rows(A)
    with pytest.raises(TypeError):
        mt.rows(M0, sp.Rational(1, 2))


def test_diagmat():
    assert mt.diagmat(3, 1) == sp.eye(3)
    assert mt.diagmat(2, 3, A) == sp.Matrix([[A, 0, 0], [0, A, 0]])
    with pytest.raises(ValueError):
        mt.diagmat(0, 1)


def test_det_inv_tutor1():
    assert sp.expand(mt.det(M0) - (A * D - B * C)) == 0
    m5 = mt.inv(M0)
    expected = sp.Matrix([[D, -B], [-C, A]]) / (A * D - B * C)
    assert (m5 - expected).applyfunc(sp.simplify) == sp.zeros(2, 2)
    assert m5[0, 0] == D / (A * D - B * C)
    big = sp.Matrix(4, 4, lambda i, j: (i + 1) ** j + (i == j))
    assert mt.inv(big) * big == sp.eye(4)


def test_det_inv_errors():
    with pytest.raises(ValueError, match="singular"):
        mt.inv(sp.Matrix([[1, 2], [2, 4]]))
    with pytest.raises(ValueError, match="square"):
        mt.det(sp.Matrix([[1, 2]]))
    with pytest.raises(TypeError):
        mt.inv(A)


def test_transpose_trace_element():
    assert mt.transpose(M0) == sp.Matrix([[A, C], [B, D]])
    assert mt.trace(M0) == A + D
    assert mt.element(M0, 2, 1) == C
    assert mt.element(sp.Matrix([[5, 6, 7]]), 3) == 7
    assert mt.element(sp.Matrix([5, 6, 7]), 1) == 5
    with pytest.raises(ValueError, match="out of range"):
        mt.element(M0, 3, 1)
    with pytest.raises(ValueError, match="two indices"):
        mt.element(M0, 1)
    with pytest.raises(ValueError, match="out of range"):
        mt.element(sp.Matrix([1, 2]), 3)


def test_inv_large_singular():
    m = sp.Matrix(4, 4, lambda i, j: i + j)
    with pytest.raises(ValueError, match="singular"):
        mt.inv(m)


def test_doctests():
    import doctest

    assert doctest.testmod(mt).failed == 0
