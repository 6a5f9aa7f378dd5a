"""Regression tests: Summary-of-Commands entries that do not convert."""

from __future__ import annotations

import sympy as sp
from conftest import load_module

from al2py import convert


def _run(src, tmp_path):
    return load_module(convert(src, str(tmp_path / "g.al")).code, tmp_path, "g")


def test_solve_with_option(tmp_path):
    # Summary: Solve(option,A,X), option is Gauss, Minors or Implicit
    m = _run("Variables X, Y\nE = [X+Y-3; X-Y-1]\nSolve(Gauss, E, [X; Y])\n", tmp_path)
    assert m.AUTOLEV["X"] == 2 and m.AUTOLEV["Y"] == 1


def test_polynomial1(tmp_path):
    # Summary (Matrix commands): Polynomial1(A,x)
    m = _run("Variables X\nP = Polynomial1([1, 2, 3], X)\n", tmp_path)
    x = m.AUTOLEV["X"]
    assert sp.expand(m.AUTOLEV["P"] - (x**2 + 2 * x + 3)) == 0


def test_units(tmp_path):
    # Summary (Mathematical commands): Units(n*m, lbf*ft)
    m = _run("E = Units(n*m, lbf*ft)\n", tmp_path)
    assert abs(float(m.AUTOLEV["E"]) - 0.7375621) < 1e-6


def test_autotaylor(tmp_path):
    # Summary (Mathematical commands): AutoTaylor(0:2, w=a, x=0)
    m = _run("Variables X\nAutoTaylor(0:1, X=0)\nE = Sin(X)\n", tmp_path)
    assert m.AUTOLEV["E"] == m.AUTOLEV["X"]


def test_units_summary_example(tmp_path):
    # Summary: Units(n*m, lbf*ft) -> "undeclared name 'n'"
    m = _run("E = Units(n*m, lbf*ft)\n", tmp_path)
    assert abs(float(m.AUTOLEV["E"]) - 0.7375621) < 1e-6
