"""Units for ``UnitSystem``, ``Input X=2 deg``, ``Output X m`` and ``Units(a, b)``.

A unit text is a product/quotient of unit names with integer or decimal
powers: ``"m/sec^2"``, ``"n*sec/m"``, ``"kg*m^2"``, ``"rad/sec"``, ``"1/sec"``.
Names are case-insensitive.  Each unit is a factor to SI (kg, m, sec, rad) and
exponents of mass, length, time and angle.

Values inside a run are in the *internal* units: the ``UnitSystem`` units for
mass, length and time (SI when there is no ``UnitSystem``) and radians for
angles.

>>> round(units_factor("n*m", "lbf*ft"), 7)
0.7375621
>>> UnitSystem().to_internal("deg") == math.pi / 180
True
>>> round(UnitSystem("slug", "ft", "sec").to_internal("n"), 7)
0.2248089
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

__all__ = [
    "Unit",
    "UnitError",
    "UnitSystem",
    "parse_unit",
    "units_factor",
    "UNIT_NAMES",
]


class UnitError(ValueError):
    """An unknown unit name, a malformed unit text or a dimension mismatch."""


# Dimension exponents: (mass, length, time, angle)
_M = (1, 0, 0, 0)
_L = (0, 1, 0, 0)
_T = (0, 0, 1, 0)
_A = (0, 0, 0, 1)
_ONE = (0, 0, 0, 0)


def _dim(m: float = 0, length: float = 0, t: float = 0, a: float = 0) -> tuple:
    return (m, length, t, a)


_LBF = 4.4482216152605
_FORCE = _dim(1, 1, -2)
_ENERGY = _dim(1, 2, -2)
_POWER = _dim(1, 2, -3)
_PRESSURE = _dim(1, -1, -2)

_TABLE: dict[tuple[str, ...], tuple[float, tuple]] = {
    # length
    ("m", "meter", "meters", "metre", "metres"): (1.0, _L),
    ("cm", "centimeter", "centimeters"): (0.01, _L),
    ("mm", "millimeter", "millimeters"): (0.001, _L),
    ("km", "kilometer", "kilometers"): (1000.0, _L),
    ("ft", "foot", "feet"): (0.3048, _L),
    ("in", "inch", "inches"): (0.0254, _L),
    ("yd", "yard", "yards"): (0.9144, _L),
    ("mi", "mile", "miles"): (1609.344, _L),
    # mass
    ("kg", "kilogram", "kilograms"): (1.0, _M),
    ("g", "gram", "grams"): (0.001, _M),
    ("slug", "slugs"): (_LBF / 0.3048, _M),
    ("lbm",): (0.45359237, _M),
    # time
    ("s", "sec", "secs", "second", "seconds"): (1.0, _T),
    ("ms", "msec"): (0.001, _T),
    ("min", "mins", "minute", "minutes"): (60.0, _T),
    ("hr", "hrs", "hour", "hours"): (3600.0, _T),
    ("day", "days"): (86400.0, _T),
    # angle
    ("rad", "rads", "radian", "radians"): (1.0, _A),
    ("deg", "degs", "degree", "degrees"): (math.pi / 180, _A),
    ("rev", "revs", "revolution", "revolutions", "cycle", "cycles"): (
        2 * math.pi,
        _A,
    ),
    # derived
    ("n", "newton", "newtons"): (1.0, _FORCE),
    ("kn", "kilonewton", "kilonewtons"): (1000.0, _FORCE),
    ("lbf",): (_LBF, _FORCE),
    ("dyne", "dynes"): (1e-5, _FORCE),
    ("j", "joule", "joules"): (1.0, _ENERGY),
    ("kj",): (1000.0, _ENERGY),
    ("cal", "calorie", "calories"): (4.184, _ENERGY),
    ("erg", "ergs"): (1e-7, _ENERGY),
    ("w", "watt", "watts"): (1.0, _POWER),
    ("kw", "kilowatt", "kilowatts"): (1000.0, _POWER),
    ("hp", "horsepower"): (745.69987158227022, _POWER),
    ("pa", "pascal", "pascals"): (1.0, _PRESSURE),
    ("kpa",): (1000.0, _PRESSURE),
    ("psi",): (_LBF / 0.0254**2, _PRESSURE),
    ("hz", "hertz"): (1.0, _dim(t=-1)),
    ("rpm",): (2 * math.pi / 60, _dim(t=-1, a=1)),
    ("mph",): (1609.344 / 3600, _dim(length=1, t=-1)),
    ("g0", "gee", "gees"): (9.80665, _dim(length=1, t=-2)),
    ("unitless", "none", "ud"): (1.0, _ONE),
}

#: Every recognised unit name -> (factor to SI, (mass, length, time, angle)).
UNIT_NAMES: dict[str, tuple[float, tuple]] = {
    name: value for names, value in _TABLE.items() for name in names
}


@dataclass(frozen=True)
class Unit:
    """A parsed unit: ``factor`` to SI and dimension exponents ``dims``."""

    factor: float
    dims: tuple = _ONE

    def __mul__(self, other: Unit) -> Unit:
        return Unit(
            self.factor * other.factor,
            tuple(a + b for a, b in zip(self.dims, other.dims, strict=True)),
        )

    def __truediv__(self, other: Unit) -> Unit:
        return self * other ** (-1)

    def __pow__(self, p: float) -> Unit:
        return Unit(self.factor**p, tuple(a * p for a in self.dims))


_TOKEN = re.compile(
    r"\s*(?:(?P<num>\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|\.\d+)"
    r"|(?P<name>[A-Za-z_][A-Za-z0-9_]*)|(?P<op>\*\*|[*/^()+-])"
    r"|(?P<dot>\.(?=[A-Za-z_])))"
)


def _tokens(text: str) -> list[str]:
    out = []
    pos = 0
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:
            raise UnitError(f"cannot read unit {text!r} at {text[pos:]!r}")
        # ``kg.m^2``: a dot between unit words multiplies
        out.append("*" if m.lastgroup == "dot" else m.group(m.lastgroup).lower())
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.toks = _tokens(text)
        self.i = 0

    def peek(self) -> str | None:
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self) -> str:
        tok = self.peek()
        if tok is None:
            raise UnitError(f"unit {self.text!r} ends too early")
        self.i += 1
        return tok

    def parse(self) -> Unit:
        if not self.toks:
            return Unit(1.0)
        unit = self.product()
        if self.peek() is not None:
            raise UnitError(f"cannot read unit {self.text!r} at {self.peek()!r}")
        return unit

    def product(self) -> Unit:
        unit = self.power()
        while self.peek() in ("*", "/"):
            op = self.take()
            rhs = self.power()
            unit = unit * rhs if op == "*" else unit / rhs
        return unit

    def power(self) -> Unit:
        base = self.atom()
        if self.peek() in ("^", "**"):
            self.take()
            sign = 1.0
            while self.peek() in ("-", "+"):
                sign *= -1.0 if self.take() == "-" else 1.0
            if self.peek() == "(":
                self.take()
                while self.peek() in ("-", "+"):
                    sign *= -1.0 if self.take() == "-" else 1.0
                exponent = self.number()
                if self.take() != ")":
                    raise UnitError(f"missing ')' in unit {self.text!r}")
            else:
                exponent = self.number()
            base = base ** (sign * exponent)
        return base

    def number(self) -> float:
        tok = self.take()
        try:
            return float(tok)
        except ValueError:
            raise UnitError(
                f"expected a number after '^' in unit {self.text!r}"
            ) from None

    def atom(self) -> Unit:
        tok = self.take()
        if tok == "(":
            unit = self.product()
            if self.take() != ")":
                raise UnitError(f"missing ')' in unit {self.text!r}")
            return unit
        if tok[0].isdigit() or tok[0] == ".":
            return Unit(float(tok))
        if tok in UNIT_NAMES:
            factor, dims = UNIT_NAMES[tok]
            return Unit(factor, dims)
        raise UnitError(f"unknown unit {tok!r} in {self.text!r}")


@lru_cache(maxsize=512)
def parse_unit(text: str | None) -> Unit:
    """Parse a unit text (``None`` or ``""`` is dimensionless 1)."""
    if text is None:
        return Unit(1.0)
    return _Parser(str(text)).parse()


def _same_dims(a: tuple, b: tuple) -> bool:
    """Mass, length and time must match; angles are dimensionless (rad = 1)."""
    return all(abs(x - y) < 1e-12 for x, y in zip(a[:3], b[:3], strict=True))


def units_factor(a: str, b: str) -> float:
    """Autolev ``Units(a, b)``: the number a quantity in ``a`` is multiplied by
    to express it in ``b``."""
    ua, ub = parse_unit(a), parse_unit(b)
    if not _same_dims(ua.dims, ub.dims):
        raise UnitError(f"cannot convert {a!r} to {b!r}: dimensions differ")
    return ua.factor / ub.factor


class UnitSystem:
    """The ``UnitSystem mass, length, time`` declaration (default kg, m, sec)."""

    def __init__(self, mass: str = "kg", length: str = "m", time: str = "sec"):
        self.names = (mass, length, time)
        units = [parse_unit(n) for n in self.names]
        for unit, want, label in zip(
            units, (_M, _L, _T), ("mass", "length", "time"), strict=True
        ):
            if unit.dims != want:
                raise UnitError(f"UnitSystem: {label} unit expected, not {unit!r}")
        self._base = tuple(u.factor for u in units)

    def __repr__(self) -> str:
        return "UnitSystem({}, {}, {})".format(*map(repr, self.names))

    @property
    def time_unit(self) -> str:
        return self.names[2]

    def to_internal(self, text: str | None) -> float:
        """Factor converting a value in unit ``text`` to internal units."""
        unit = parse_unit(text)
        m, length, t, _a = unit.dims
        base = self._base[0] ** m * self._base[1] ** length * self._base[2] ** t
        return unit.factor / base
