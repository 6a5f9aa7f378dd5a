"""Tests for al2py_runtime.jobs.units (UnitSystem, Input/Output units, Units(a, b))."""

from __future__ import annotations

import math

import pytest
from al2py_runtime import Workspace
from al2py_runtime.jobs.units import UnitError, UnitSystem, parse_unit, units_factor

SI = UnitSystem("kg", "meter", "sec")


@pytest.mark.parametrize(
    ("text", "factor"),
    [
        ("m", 1.0),
        ("meters", 1.0),
        ("cm", 0.01),
        ("mm", 0.001),
        ("km", 1000.0),
        ("ft", 0.3048),
        ("in", 0.0254),
        ("kg", 1.0),
        ("g", 0.001),
        ("slug", 14.593902937206364),
        ("lbm", 0.45359237),
        ("sec", 1.0),
        ("s", 1.0),
        ("min", 60.0),
        ("hr", 3600.0),
        ("rad", 1.0),
        ("deg", math.pi / 180),
        ("degrees", math.pi / 180),
        ("degs", math.pi / 180),
        ("rev", 2 * math.pi),
        ("n", 1.0),
        ("Newtons", 1.0),
        ("lbf", 4.4482216152605),
        ("joules", 1.0),
        ("j", 1.0),
        ("w", 1.0),
        ("watts", 1.0),
        ("rpm", 2 * math.pi / 60),
        ("m/sec^2", 1.0),
        ("n/m", 1.0),
        ("n*sec/m", 1.0),
        ("rad/sec", 1.0),
        ("deg/sec", math.pi / 180),
        ("ft/sec^2", 0.3048),
        ("kg*m^2", 1.0),
        ("lbf*ft", 4.4482216152605 * 0.3048),
        ("1/sec", 1.0),
        ("cm^2", 1e-4),
        ("(ft/min)^2", (0.3048 / 60) ** 2),
        ("sec^-1", 1.0),
        ("min^(-1)", 1 / 60),
        ("", 1.0),
        (None, 1.0),
    ],
)
def test_si_factors(text, factor):
    assert SI.to_internal(text) == pytest.approx(factor, rel=1e-12)


def test_dimensions_of_products():
    assert parse_unit("n*sec/m").dims == (1, 0, -1, 0)
    assert parse_unit("m/sec^2").dims == (0, 1, -2, 0)
    assert parse_unit("joules").dims == parse_unit("n*m").dims
    assert parse_unit("rad/sec").dims == (0, 0, -1, 1)


def test_english_unit_system():
    us = UnitSystem("slug", "ft", "sec")
    assert us.to_internal("ft") == pytest.approx(1.0)
    assert us.to_internal("m") == pytest.approx(1 / 0.3048)
    assert us.to_internal("lbf") == pytest.approx(1.0)
    assert us.to_internal("n") == pytest.approx(0.224808943, rel=1e-8)
    assert us.to_internal("deg") == pytest.approx(math.pi / 180)
    assert us.time_unit == "sec"


@pytest.mark.parametrize(
    ("a", "b", "factor"),
    [
        ("n*m", "lbf*ft", 0.7375621492772654),
        ("m", "ft", 1 / 0.3048),
        ("deg", "rad", math.pi / 180),
        ("rpm", "rad/sec", 2 * math.pi / 60),
        ("km/hr", "m/sec", 1 / 3.6),
        ("joules", "n*m", 1.0),
    ],
)
def test_units_factor(a, b, factor):
    assert units_factor(a, b) == pytest.approx(factor, rel=1e-12)


@pytest.mark.parametrize("text", ["furlong", "m/", "m^", "m**x", "(m", "m)", "m $"])
def test_bad_unit_text(text):
    with pytest.raises(UnitError):
        parse_unit(text)


def test_dimension_mismatch():
    with pytest.raises(UnitError, match="dimensions differ"):
        units_factor("m", "sec")
    with pytest.raises(UnitError, match="length unit expected"):
        UnitSystem("kg", "sec", "sec")


def test_workspace_units_and_input_value():
    ws = Workspace("u.al")
    assert float(ws.numerics.units("n*m", "lbf*ft")) == pytest.approx(
        0.7375621, rel=1e-7
    )
    ws.numerics.unit_system("slug", "ft", "sec")
    ws.numerics.input({"LA": (1, "m"), "QA": (30, "deg"), "N": 3})
    assert ws.numerics.input_value("la") == 1
    assert float(ws.numerics.input_value("LA", unit_system=True)) == pytest.approx(
        1 / 0.3048
    )
    assert float(ws.numerics.input_value("QA", unit_system=True)) == pytest.approx(
        math.pi / 6
    )
    assert ws.numerics.input_value("N") == 3
    with pytest.raises(KeyError):
        ws.numerics.input_value("MISSING")
