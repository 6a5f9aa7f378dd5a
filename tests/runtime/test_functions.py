"""Tests for al2py_runtime.functions (Autolev library functions)."""

from __future__ import annotations

import math

import sympy as sp
from al2py_runtime import functions as fn
from al2py_runtime import vocabulary

x = sp.Symbol("x", real=True)


def test_table_names_exist():
    """Every library row's implementation is what generated modules import
    from ``al2py_runtime.functions`` under the row's Python name."""
    rows = [b for b in vocabulary.BUILTINS.values() if b.style is vocabulary.Style.FUNC]
    for row in rows:
        assert row.name == row.name.upper()
        assert getattr(fn, row.python) is row.implementation, row.name
        if row.degrees is not None:
            assert row.degrees_variant is getattr(fn, row.degrees)
            assert row.degrees_variant.__name__ == row.degrees
    expected = {
        "SIN",
        "COS",
        "SQR",
        "INT",
        "ROUND",
        "MAX",
        "MIN",
        "ABS",
        "LOG10",
        "CEIL",
    }
    assert expected <= {row.name for row in rows}
    degrees = {r.name for r in rows if r.degrees}
    assert degrees == set("SIN COS TAN ASIN ACOS ATAN ATAN2".split())


def test_reexports_are_sympy():
    assert fn.sin is sp.sin and fn.atan2 is sp.atan2 and fn.sqrt is sp.sqrt
    assert fn.absval(-3) == 3 and fn.Abs is sp.Abs


def test_simple_functions():
    assert fn.sqr(x + 1) == (x + 1) ** 2
    assert fn.sqr(3) == 9
    assert fn.log10(1000) == 3
    assert abs(float(fn.log10(2)) - math.log10(2)) < 1e-15
    assert fn.ceil(sp.Rational(3, 2)) == 2
    assert fn.floor(sp.Rational(-3, 2)) == -2
    assert fn.maxof(2, 3) == 3 and fn.minof(2, 3) == 2
    assert fn.maxof(x, 2) == sp.Max(x, 2)


def test_int_and_round():
    assert fn.trunc(sp.Rational(7, 2)) == 3
    assert fn.trunc(sp.Rational(-7, 2)) == -3
    assert fn.trunc(-2.9) == -2
    assert fn.nint(sp.Rational(5, 2)) == 3
    assert fn.nint(-2.5) == -3
    assert fn.nint(sp.Float("2.4")) == 2
    assert isinstance(fn.trunc(x), fn.trunc)
    assert fn.trunc(x).subs(x, sp.Rational(9, 4)) == 2
    f = sp.lambdify(x, fn.nint(x) + fn.trunc(x), "numpy")
    assert f(-2.5) == -5.0
    assert f(2.6) == 5.0


def test_degree_trig():
    assert fn.cos_deg(90) == 0
    assert fn.sin_deg(30) == sp.Rational(1, 2)
    assert fn.sin_deg(sp.Float(30)) == sp.Rational(1, 2)
    assert fn.tan_deg(45) == 1
    assert fn.cos_deg(x) == sp.cos(x)
    value = fn.sin_deg(45)
    assert isinstance(value, sp.Float)
    assert abs(float(value) - math.sqrt(2) / 2) < 1e-15
    # evaluated results are not converted a second time
    assert fn.sin_deg(1) == fn.sin_deg(1).evalf(20)


def test_degree_inverse_trig():
    assert fn.acos_deg(0.5) == 60
    assert fn.acos_deg(sp.Rational(1, 2)) == 60
    assert fn.asin_deg(1) == 90
    assert fn.atan_deg(1) == 45
    assert fn.atan2_deg(1, -1) == 135
    assert fn.acos_deg(x) == sp.acos(x)
    assert fn.atan2_deg(x, 1) == sp.atan2(x, 1)
    value = fn.asin_deg(sp.Rational(1, 3))
    assert abs(float(value) - math.degrees(math.asin(1 / 3))) < 1e-12


def test_doctests():
    import doctest

    assert doctest.testmod(fn).failed == 0


def test_max_min_more_arguments():
    assert fn.maxof(1, 5, 3) == 5
    assert fn.minof(x, 2, 1) == sp.Min(x, 1)
