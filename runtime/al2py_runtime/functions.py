"""Autolev's library functions under Python-safe names for generated code.

Where Autolev's function is sympy's, sympy's is re-exported unchanged
(``sin``, ``atan2``, ``sqrt``, ...).  Which Autolev name each stands for,
and the variants used while ``Degrees ON`` is in force, are the built-in
rows of :mod:`al2py_runtime.vocabulary`.

>>> cos_deg(90), asin_deg(sp.Rational(1, 2))
(0, 30)
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy import (
    Abs,
    Max,
    Min,
    acos,
    asin,
    atan,
    atan2,
    cos,
    cosh,
    exp,
    factorial,
    floor,
    log,
    sign,
    sin,
    sinh,
    sqrt,
    tan,
    tanh,
)

__all__ = [
    "Abs",
    "absval",
    "acos",
    "acos_deg",
    "asin",
    "asin_deg",
    "atan",
    "atan2",
    "atan2_deg",
    "atan_deg",
    "ceil",
    "cos",
    "cos_deg",
    "cosh",
    "exp",
    "factorial",
    "floor",
    "log",
    "log10",
    "maxof",
    "minof",
    "nint",
    "sign",
    "sin",
    "sin_deg",
    "sinh",
    "sqr",
    "sqrt",
    "tan",
    "tan_deg",
    "tanh",
    "trunc",
]

#: Autolev ``ABS``.
absval = Abs
#: Autolev ``CEIL``.
ceil = sp.ceiling


def sqr(x: Any) -> sp.Expr:
    """Autolev ``SQR(x)``: the square of ``x``.

    >>> sqr(sp.Symbol("x") + 1)
    (x + 1)**2
    """
    return sp.sympify(x) ** 2


def log10(x: Any) -> sp.Expr:
    """Autolev ``LOG10(x)``: base-10 logarithm.

    >>> log10(1000)
    3
    """
    return sp.log(sp.sympify(x), 10)


def maxof(x: Any, y: Any, *more: Any) -> sp.Expr:
    """Autolev ``MAX(x, y)`` (more arguments are accepted too).

    >>> maxof(2, 3)
    3
    """
    return Max(x, y, *more)


def minof(x: Any, y: Any, *more: Any) -> sp.Expr:
    """Autolev ``MIN(x, y)`` (more arguments are accepted too).

    >>> minof(2, 3)
    2
    """
    return Min(x, y, *more)


class trunc(sp.Function):  # noqa: N801 - named like the function it stands for
    """Autolev ``INT(x)``: truncate toward zero (printed ``INT``).

    >>> trunc(sp.Rational(-7, 2)), trunc(2.9)
    (-3, 2)
    """

    nargs = 1

    @classmethod
    def eval(cls, x: sp.Expr) -> sp.Expr | None:
        if x.is_Integer:
            return x
        if x.is_number and x.is_extended_real:
            return sp.Integer(int(sp.floor(abs(x))) * (-1 if x.is_negative else 1))
        return None

    def _numpycode(self, printer: Any) -> str:
        return (
            f"{printer._module_format('numpy.trunc')}({printer._print(self.args[0])})"
        )


class nint(sp.Function):  # noqa: N801
    """Autolev ``ROUND(x)``: nearest integer, halves away from zero.

    >>> nint(sp.Rational(5, 2)), nint(-2.5), nint(2.4)
    (3, -3, 2)
    """

    nargs = 1

    @classmethod
    def eval(cls, x: sp.Expr) -> sp.Expr | None:
        if x.is_Integer:
            return x
        if x.is_number and x.is_extended_real:
            magnitude = sp.floor(abs(x) + sp.Rational(1, 2))
            return sp.Integer(int(magnitude) * (-1 if x.is_negative else 1))
        return None

    def _numpycode(self, printer: Any) -> str:
        arg = printer._print(self.args[0])
        np_sign = printer._module_format("numpy.sign")
        np_floor = printer._module_format("numpy.floor")
        np_abs = printer._module_format("numpy.abs")
        return f"{np_sign}({arg})*{np_floor}({np_abs}({arg}) + 0.5)"


# ------------------------------------------------------------- degrees


def _exact(x: Any) -> sp.Expr:
    """A float argument as the exact decimal it spells (0.5 -> 1/2)."""
    x = sp.sympify(x)
    if x.has(sp.Float):
        x = sp.nsimplify(x, rational=True)
    return x


def _result(value: sp.Expr) -> sp.Expr:
    """Exact rationals stay exact; anything else is evaluated once."""
    return value if value.is_Rational else value.evalf(20)


def _trig_deg(func: Any, x: Any) -> sp.Expr:
    x = sp.sympify(x)
    if not x.is_number:
        return func(x)
    return _result(func(_exact(x) * sp.pi / 180))


def _atrig_deg(func: Any, *args: Any) -> sp.Expr:
    args = tuple(sp.sympify(a) for a in args)
    if not all(a.is_number for a in args):
        return func(*args)
    return _result(func(*(_exact(a) for a in args)) * 180 / sp.pi)


def sin_deg(x: Any) -> sp.Expr:
    """``SIN(x)`` with ``Degrees ON``: a numeric ``x`` is in degrees.

    >>> sin_deg(30), sin_deg(sp.Symbol("x"))
    (1/2, sin(x))
    """
    return _trig_deg(sin, x)


def cos_deg(x: Any) -> sp.Expr:
    """``COS(x)`` with ``Degrees ON``.

    >>> cos_deg(90), cos_deg(45)
    (0, 0.70710678118654752440)
    """
    return _trig_deg(cos, x)


def tan_deg(x: Any) -> sp.Expr:
    """``TAN(x)`` with ``Degrees ON``.

    >>> tan_deg(45)
    1
    """
    return _trig_deg(tan, x)


def asin_deg(x: Any) -> sp.Expr:
    """``ASIN(x)`` with ``Degrees ON``: a numeric result is in degrees.

    >>> asin_deg(1)
    90
    """
    return _atrig_deg(asin, x)


def acos_deg(x: Any) -> sp.Expr:
    """``ACOS(x)`` with ``Degrees ON``.

    >>> acos_deg(0.5)
    60
    """
    return _atrig_deg(acos, x)


def atan_deg(x: Any) -> sp.Expr:
    """``ATAN(x)`` with ``Degrees ON``.

    >>> atan_deg(1)
    45
    """
    return _atrig_deg(atan, x)


def atan2_deg(y: Any, x: Any) -> sp.Expr:
    """``ATAN2(y, x)`` with ``Degrees ON``.

    >>> atan2_deg(1, -1)
    135
    """
    return _atrig_deg(atan2, y, x)
