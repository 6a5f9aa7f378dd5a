"""Functions of time for a script's ``Variables`` and ``Specified``: what
sympy's ``dynamicsymbols`` makes, with the function's hash kept.

sympy's cache keys every cached call by its arguments and their classes,
and the class of a function of time (``Q1`` in ``Q1(t)``) computes its hash
from its class key on every call.  A large model makes tens of thousands of
such calls while it derives, so the class here keeps its hash.  It is equal
to, and hashes as, the function ``dynamicsymbols`` makes with the same name
and assumptions, either way round:

>>> from sympy.physics.mechanics import dynamicsymbols
>>> q = time_function("Q1", real=True)
>>> q == dynamicsymbols("Q1", real=True), hash(q) == hash(dynamicsymbols("Q1", real=True))
(True, True)
>>> dynamicsymbols("Q1", real=True) == q, q.diff(dynamicsymbols._t)
(True, Derivative(Q1(t), t))
>>> q == dynamicsymbols("Q1")  # other assumptions: another function
False
"""

from __future__ import annotations

import copyreg
from functools import reduce
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef, UndefinedFunction
from sympy.core.parameters import global_parameters
from sympy.physics.vector import dynamicsymbols as _sympy_dynamicsymbols

__all__ = ["TimeFunction", "TimeValue", "dynamicsymbols", "time_function"]

#: time, as sympy's ``dynamicsymbols`` names it
_T = _sympy_dynamicsymbols._t


class TimeValue(AppliedUndef):
    """A function of time's value (``Q1(t)``): sympy's ``AppliedUndef``,
    whose rate ``diff(t)`` is formed once.

    sympy forms ``Derivative(Q1(t), t)`` anew on every ``diff(t)`` (a
    script's ``q1'`` and the chain rule of every time derivative of a sine
    of it), a third of a millisecond each: the first one's answer is kept
    and given again (it is the same object), while sympy evaluates
    (``evaluate(False)`` forms it as sympy does).

    >>> q = time_function("Q1", real=True)
    >>> t = _sympy_dynamicsymbols._t
    >>> q.diff(t) is q.diff(t), sp.diff(q, t) == sp.Derivative(q, t)
    (True, True)
    """

    def diff(self, *symbols: Any, **assumptions: Any) -> Any:
        if (
            len(symbols) == 1
            and symbols[0] is _T
            and not assumptions
            and global_parameters.evaluate
        ):
            found = self.__dict__.get("_rate")
            if found is None:
                found = self.__dict__["_rate"] = super().diff(_T)
            return found
        return super().diff(*symbols, **assumptions)


class TimeFunction(UndefinedFunction):
    """sympy's ``UndefinedFunction`` whose hash is found once, at creation
    (it depends only on the name, the number of arguments and the
    assumptions, which do not change); its values are :class:`TimeValue`."""

    def __new__(mcl, name: str, **assumptions: Any) -> Any:
        cls = super().__new__(mcl, name, bases=(TimeValue,), **assumptions)
        cls._al2py_hash = UndefinedFunction.__hash__(cls)
        return cls

    def __hash__(cls) -> int:
        return cls._al2py_hash

    def __eq__(cls, other: object) -> bool:
        # sympy's test, accepting any undefined function (sympy's own asks
        # for an instance of the other's metaclass, which would make a
        # function made by dynamicsymbols unequal to this one)
        return cls is other or (
            isinstance(other, UndefinedFunction)
            and cls.class_key() == other.class_key()
            and cls._kwargs == other._kwargs
        )

    def __ne__(cls, other: object) -> bool:
        return not cls == other


def _rebuild(name: str, assumptions: dict) -> TimeFunction:
    return TimeFunction(name, **assumptions)


# A class made at run time pickles by value through copyreg, as sympy's
# undefined functions do (its table is looked up by the exact metaclass).
copyreg.pickle(TimeFunction, lambda f: (_rebuild, (f.name, f._kwargs)))


def time_function(name: str, **assumptions: Any) -> Any:
    """``dynamicsymbols(name, **assumptions)``: ``name(t)``."""
    return TimeFunction(name, **assumptions)(_sympy_dynamicsymbols._t)


def dynamicsymbols(names: str, level: int = 0, **assumptions: Any) -> Any:
    """sympy's ``dynamicsymbols``: the functions of time ``t`` that
    ``names`` lists (``level`` times differentiated), equal to sympy's and
    hashing as they do, each keeping its hash (:class:`TimeFunction`), as
    the runtime's own variables do.  A module declares its variables with it
    (``U1, U2 = dynamicsymbols("U1 U2", real=True)``).

    >>> u1, u2 = dynamicsymbols("U1 U2", real=True)
    >>> (u1, u2) == tuple(_sympy_dynamicsymbols("U1 U2", real=True))
    True
    >>> dynamicsymbols("Q", 1)
    Derivative(Q(t), t)
    """
    t = _sympy_dynamicsymbols._t
    funcs = sp.symbols(names, cls=TimeFunction, **assumptions)

    def applied(f: Any) -> Any:
        return reduce(sp.diff, [t] * level, f(t))

    if isinstance(funcs, list | tuple):
        return [applied(f) for f in funcs]
    return applied(funcs)
