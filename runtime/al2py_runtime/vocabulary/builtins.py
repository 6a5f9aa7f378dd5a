"""Autolev's built-in functions and commands: one row each.

A row (:class:`Builtin`) says how many arguments a built-in takes, what kind
of value it returns (a rule on the argument kinds), how the runtime spells
it, and, for a library function, its implementation, its ``Degrees ON``
variant, the sympy function its values print with, and the plain-number
function the numeric backends use.  The styles:

* ``FUNC``: a library function that generated modules import from
  :mod:`al2py_runtime.functions` (``SIN`` -> ``sin``);
* ``METHOD``: a workspace method (``EXPAND`` -> ``al.expand``);
* ``SPECIAL``: the transpiler emits it with a dedicated method (``Solve``,
  ``Evaluate``...);
* ``PENDING``: valid Autolev that al2py does not translate yet.

>>> row = lookup("cos")
>>> row.style, row.python, row.arity_error(2), row.degrees
(<Style.FUNC: 'func'>, 'cos', 'Cos takes exactly 1 argument, not 2', 'cos_deg')
>>> import sympy
>>> printed_name(sympy.ceiling(sympy.Symbol("x"))), by_spelling("inverse").name
('CEIL', 'INV')

The table names a library function's implementation (``python``, in
:mod:`al2py_runtime.functions`) and looks it up there when first asked for
(:attr:`Builtin.implementation`), so that reading the table -- as the
transpiler does -- imports no sympy.  A made-up function is one more row,
given its implementation (:func:`registered` adds it for a while):

>>> class hav(sympy.Function):
...     '''A haversine that stays unevaluated.'''
>>> with registered(library("HAVERSINE", "hav", hav)) as row:
...     import al2py_runtime.functions as fn
...     fn.hav is hav, printed_name(hav(sympy.Symbol("x")))
(True, 'HAVERSINE')
>>> lookup("haversine") is None
True
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from enum import Enum
from functools import cache
from typing import TYPE_CHECKING, Any

from .kinds import Kind

if TYPE_CHECKING:
    import sympy

__all__ = [
    "Style",
    "Builtin",
    "BUILTINS",
    "LIST_COMMANDS",
    "library",
    "lookup",
    "by_spelling",
    "register",
    "unregister",
    "registered",
    "printed_name",
    "numeric_namespace",
    "complex_functions",
]


class Style(Enum):
    FUNC = "func"
    METHOD = "method"
    SPECIAL = "special"
    PENDING = "pending"


#: A rule giving the result kind from the argument kinds.
KindRule = Callable[[list[Kind]], Kind]


def _scalar(_: list[Kind]) -> Kind:
    return Kind.SCALAR


def _matrix(_: list[Kind]) -> Kind:
    return Kind.MATRIX


def _vector(_: list[Kind]) -> Kind:
    return Kind.VECTOR


def _dyadic(_: list[Kind]) -> Kind:
    return Kind.DYADIC


def _dot(kinds: list[Kind]) -> Kind:
    if Kind.MATRIX in kinds:
        return Kind.MATRIX  # Dot(v>, [v1>; v2>]): a matrix of vectors
    if Kind.DYADIC in kinds:
        return Kind.DYADIC if kinds.count(Kind.DYADIC) == 2 else Kind.VECTOR
    return Kind.SCALAR


def _represent(kinds: list[Kind]) -> Kind:
    # A vector or dyadic gives its matrix; a matrix gives a vector or dyadic.
    return Kind.UNKNOWN if kinds and kinds[0] is Kind.MATRIX else Kind.MATRIX


def _unknown(_: list[Kind]) -> Kind:
    # Decided at run time: Partials gives one vector or several; Momentum's
    # LINEAR/ANGULAR give vectors, GENERALIZED a matrix; Gyrostat's FRSTAR a
    # matrix, ANGMOM a vector, KE a scalar.
    return Kind.UNKNOWN


def _first(kinds: list[Kind]) -> Kind:
    return kinds[0] if kinds else Kind.UNKNOWN


def _matrix_if_many(kinds: list[Kind]) -> Kind:
    return Kind.SCALAR if len(kinds) == 1 else Kind.MATRIX


def _d(kinds: list[Kind]) -> Kind:
    if len(kinds) >= 2 and kinds[1] is Kind.MATRIX:
        return Kind.MATRIX
    return _first(kinds)


def _polynomial(kinds: list[Kind]) -> Kind:
    return Kind.SCALAR if kinds and kinds[0] is Kind.MATRIX else Kind.MATRIX


def _coef(kinds: list[Kind]) -> Kind:
    if any(k is Kind.MATRIX for k in kinds[:2]):
        return Kind.MATRIX
    return _first(kinds)


@dataclass(frozen=True, slots=True)
class Builtin:
    """One Autolev built-in (see the module's docstring)."""

    name: str  # canonical Autolev spelling, also the printed name
    style: Style
    python: str  # function or method name in the runtime
    min_args: int
    max_args: int | None  # None: no limit
    result: KindRule = _scalar
    dual: bool = False  # ``Expand(E)`` alone means ``E := Expand(E)``
    issue: str = ""  # for PENDING: what brings it
    statement: bool = False  # a stand-alone command (``V2pts``, ``Gravity``)
    responds: bool = False  # it prints a response (generated calls pass line=)
    words: tuple[int, ...] = ()  # argument positions holding option words
    #: Argument positions that name a frame, body, particle or point; from
    #: ``objects_from`` on, every argument does (``Gravity(v>, A, B)``).  A
    #: name that is both an object and a quantity (body ``C``, constant ``c``)
    #: means the object there and the quantity elsewhere.
    objects: tuple[int, ...] = ()
    objects_from: int | None = None
    #: FUNC: the name in :mod:`al2py_runtime.functions` of the variant used
    #: while ``Degrees ON`` is in force (``"sin_deg"``).
    degrees: str | None = None
    #: FUNC: the name of the sympy function class its unevaluated values have
    #: (``MAX`` gives ``Max(...)``); by default the implementation, when a
    #: class.
    head: str | None = None
    #: FUNC: the function on plain numbers (float or complex) the numeric
    #: backends call for ``head``; None when Python's ``math``/``cmath``
    #: spell it as sympy does.
    numeric: Callable[..., Any] | None = None
    #: FUNC, a row made outside the table: its implementation and degree
    #: variant, which :func:`register` adds to :mod:`al2py_runtime.functions`
    #: as ``python`` and ``degrees``.
    given: tuple[Callable[..., Any] | None, ...] = ()

    @property
    def implementation(self) -> Callable[..., Any] | None:
        """FUNC: the function generated code calls, exported by
        :mod:`al2py_runtime.functions` as ``python`` (imported, and sympy
        with it, now)."""
        return self._function(self.python) if self.style is Style.FUNC else None

    @property
    def degrees_variant(self) -> Callable[..., Any] | None:
        """FUNC: the function ``degrees`` names, or None."""
        return None if self.degrees is None else self._function(self.degrees)

    @property
    def sympy_head(self) -> type | None:
        if self.head is not None:
            import sympy

            return getattr(sympy, self.head)
        impl = self.implementation
        return impl if isinstance(impl, type) else None

    @staticmethod
    def _function(name: str) -> Callable[..., Any]:
        from .. import functions

        return getattr(functions, name)

    def takes_object(self, i: int) -> bool:
        return i in self.objects or (
            self.objects_from is not None and i >= self.objects_from
        )

    def arity_error(self, n: int) -> str | None:
        """A plain-English message if ``n`` arguments are wrong, else None."""
        lo, hi = self.min_args, self.max_args
        if lo <= n and (hi is None or n <= hi):
            return None
        if hi is None:
            want, top = f"at least {lo}", lo
        elif lo == hi:
            want, top = f"exactly {lo}", lo
        else:
            want, top = f"{lo} to {hi}", hi
        plural = "" if top == 1 else "s"
        return f"{self.name.title()} takes {want} argument{plural}, not {n}"


def library(
    name: str,
    python: str,
    implementation: Callable[..., Any] | None = None,
    n: int = 1,
    hi: int | None = -1,
    degrees: Callable[..., Any] | str | None = None,
    **more: Any,
) -> Builtin:
    """The row of a library function: ``n`` arguments (up to ``hi``; None
    for no limit), the kind of its first argument.  The table's own rows
    name their functions (``python``, ``degrees``) in
    :mod:`al2py_runtime.functions`; a row made outside gives them
    (``implementation`` and the ``degrees`` function), and :func:`register`
    adds them there."""
    top = n if hi == -1 else hi
    given: tuple[Callable[..., Any] | None, ...] = ()
    if implementation is not None or callable(degrees):
        given = (implementation, degrees if callable(degrees) else None)
        degrees = getattr(degrees, "__name__", degrees)
    return Builtin(
        name, Style.FUNC, python, n, top, _first, degrees=degrees, given=given, **more
    )


def _trunc(x: Any) -> float:
    """``INT`` on a plain number: toward zero."""
    return float(math.trunc(_real(x)))


def _nint(x: Any) -> float:
    """``ROUND`` on a plain number: halves away from zero."""
    x = _real(x)
    return math.copysign(math.floor(abs(x) + 0.5), x)


def _real(x: Any) -> float:
    if isinstance(x, complex):
        if x.imag:
            raise ValueError(f"{x} is not real")
        return x.real
    return x


_NUMERICS = "numerical CODE jobs"


def _command(
    name: str,
    python: str,
    lo: int,
    hi: int | None,
    words: tuple[int, ...] = (),
    objects: tuple[int, ...] = (),
    objects_from: int | None = None,
    responds: bool = True,
) -> Builtin:
    return Builtin(
        name,
        Style.METHOD,
        python,
        lo,
        hi,
        statement=True,
        responds=responds,
        words=words,
        objects=objects,
        objects_from=objects_from,
    )


def _pending(name: str, issue: str, lo: int = 0, hi: int | None = None) -> Builtin:
    return Builtin(name, Style.PENDING, name.lower(), lo, hi, issue=issue)


_TABLE: list[Builtin] = [
    # -- library functions (tutorial Summary: operators and library functions)
    library("ABS", "Abs", numeric=abs),
    library("SIN", "sin", degrees="sin_deg"),
    library("COS", "cos", degrees="cos_deg"),
    library("TAN", "tan", degrees="tan_deg"),
    library("SINH", "sinh"),
    library("COSH", "cosh"),
    library("TANH", "tanh"),
    library("ASIN", "asin", degrees="asin_deg"),
    library("ACOS", "acos", degrees="acos_deg"),
    library("ATAN", "atan", degrees="atan_deg"),
    library("ATAN2", "atan2", n=2, degrees="atan2_deg"),
    library("LOG", "log"),
    library("LOG10", "log10"),
    library("EXP", "exp"),
    library("SQR", "sqr"),
    library("SQRT", "sqrt"),
    library("FACTORIAL", "factorial"),
    library("CEIL", "ceil"),
    library("FLOOR", "floor"),
    library("INT", "trunc", numeric=_trunc),
    library("ROUND", "nint", numeric=_nint),
    library("MAX", "maxof", n=2, hi=None, head="Max"),
    library("MIN", "minof", n=2, hi=None, head="Min"),
    library("SIGN", "sign"),
    # -- mathematical commands
    Builtin("D", Style.METHOD, "d", 2, 3, _d, objects=(2,)),
    Builtin("DT", Style.METHOD, "dt", 1, 2, _first, objects=(1,)),
    Builtin("EVALUATE", Style.SPECIAL, "evaluate", 1, None, _first),
    Builtin("TAYLOR", Style.SPECIAL, "taylor", 3, None, _first),
    Builtin("POLYNOMIAL", Style.METHOD, "polynomial", 2, 3, _polynomial),
    # The Summary lists Polynomial1(A, x), most likely a footnote marker.
    Builtin("POLYNOMIAL1", Style.METHOD, "polynomial", 2, 2, _polynomial),
    Builtin("ROOTS", Style.METHOD, "roots", 1, 3, _matrix),
    Builtin("SOLVE", Style.SPECIAL, "solve", 2, None),
    Builtin("REPLACE", Style.SPECIAL, "replace", 2, None, _first),
    Builtin("RHS", Style.METHOD, "rhs", 1, 1, _first),
    Builtin("EXPLICIT", Style.METHOD, "explicit", 1, 2, _first, dual=True),
    # -- matrix commands
    Builtin("COLS", Style.METHOD, "cols", 1, None, _matrix_if_many),
    Builtin("ROWS", Style.METHOD, "rows", 1, None, _matrix_if_many),
    Builtin("DET", Style.METHOD, "det", 1, 1),
    Builtin("DIAGMAT", Style.METHOD, "diagmat", 2, 3, _matrix),
    Builtin("EIG", Style.SPECIAL, "eig", 1, 3, _matrix),
    Builtin("ELEMENT", Style.METHOD, "element", 2, 3),
    Builtin("INV", Style.METHOD, "inv", 1, 1, _matrix),
    Builtin("TRACE", Style.METHOD, "trace", 1, 1),
    Builtin("TRANSPOSE", Style.METHOD, "transpose", 1, 1, _matrix),
    # -- simplification commands (dual functions marked)
    Builtin("ARRANGE", Style.METHOD, "arrange", 3, 3, _first, dual=True),
    Builtin("COEF", Style.METHOD, "coef", 2, 2, _coef),
    Builtin("EPSILON", Style.METHOD, "epsilon", 1, 2, _first),
    Builtin("EXCLUDE", Style.METHOD, "exclude", 2, 2, _first),
    Builtin("EXPAND", Style.METHOD, "expand", 1, 2, _first, dual=True),
    Builtin("FACTOR", Style.METHOD, "factor", 1, None, _first, dual=True),
    Builtin("INCLUDE", Style.METHOD, "include", 2, 2, _first),
    Builtin("ZEE", Style.METHOD, "zee", 1, 2, _first, dual=True),
    Builtin("AUTOZ", Style.METHOD, "autoz", 1, 2, _first),
    # -- vectors and dyadics
    Builtin("DOT", Style.METHOD, "dot", 2, 2, _dot),
    Builtin("CROSS", Style.METHOD, "cross", 2, 2, _vector),
    Builtin("MAG", Style.METHOD, "mag", 1, 1),
    Builtin("MAGSQ", Style.METHOD, "magsq", 1, 1),
    Builtin("UNITVEC", Style.METHOD, "unitvec", 1, 1, _vector),
    Builtin("EXPRESS", Style.METHOD, "express", 2, 2, _first, dual=True, objects=(1,)),
    Builtin("REPRESENT", Style.METHOD, "represent", 2, 2, _represent, objects=(1,)),
    Builtin("VECTOR", Style.METHOD, "vector", 2, 4, _vector, objects=(0,)),
    Builtin("DYADIC", Style.METHOD, "dyadic", 2, None, _dyadic),
    Builtin("MATRIX", Style.METHOD, "matrix", 2, 2, _matrix, objects=(0,)),
    Builtin("PARTIALS", Style.METHOD, "partials", 1, None, _unknown),
    Builtin("REMAINDER", Style.METHOD, "remainder", 1, 1, _vector),
    # -- mass distribution, loads, dynamics (values)
    Builtin("MASS", Style.METHOD, "mass_of", 0, None, objects_from=0),
    Builtin("CM", Style.METHOD, "cm", 1, None, _vector, objects_from=0),
    Builtin("INERTIA", Style.METHOD, "inertia", 1, None, _dyadic, objects_from=0),
    Builtin("KE", Style.METHOD, "ke", 0, None, objects_from=0),
    Builtin(
        "MOMENTUM",
        Style.METHOD,
        "momentum",
        1,
        None,
        _unknown,
        words=(0,),
        objects_from=1,
    ),
    Builtin("TSTAR", Style.METHOD, "tstar", 1, 2, _vector),
    Builtin("FR", Style.METHOD, "fr", 0, 0, _matrix),
    Builtin("FRSTAR", Style.METHOD, "frstar", 0, 0, _matrix),
    Builtin("NICHECK", Style.METHOD, "nicheck", 0, 0),
    Builtin(
        "GYROSTAT",
        Style.METHOD,
        "gyrostat",
        5,
        5,
        _unknown,
        words=(0, 1),
        objects=(2, 3),
    ),
    # -- stand-alone physics commands (statements; most respond)
    _command("SIMPROT", "simprot", 4, 4, objects=(0, 1)),
    _command("DIRCOS", "dircos", 4, None, words=(2,), objects=(0, 1)),
    _command("ANGVEL", "angvel", 2, None, words=(2,), objects=(0, 1)),
    _command("KINDIFFS", "kindiffs", 4, None, words=(2,), objects=(0, 1)),
    _command("V2PTS", "v2pts", 4, 4, objects=(0, 1, 2, 3)),
    _command("A2PTS", "a2pts", 4, 4, objects=(0, 1, 2, 3)),
    _command("V1PT", "v1pt", 4, 4, objects=(0, 1, 2, 3)),
    _command("A1PT", "a1pt", 4, 4, objects=(0, 1, 2, 3)),
    _command("GRAVITY", "gravity", 1, None, objects_from=1, responds=False),
    _command("FORCE", "add_force", 2, 2, objects=(0,), responds=False),
    _command("TORQUE", "add_torque", 2, 2, objects=(0,), responds=False),
    _command("CONSTRAIN", "constrain", 1, None),
    _command("KANE", "kane", 0, None),
    # -- code commands: Animate(N, O, A, B) records what a job's animation
    # shows (al.numerics.animate; see jobs/scene.py)
    _command("ANIMATE", "animate", 3, None, objects_from=0, responds=False),
    Builtin("INPUT", Style.SPECIAL, "input_value", 1, 2, words=(1,)),
    Builtin("UNITS", Style.SPECIAL, "units", 2, 2),
    Builtin("AUTOTAYLOR", Style.SPECIAL, "autotaylor", 2, None, statement=True),
    *(_pending(n, _NUMERICS) for n in ("SPLINE",)),
]

#: Every built-in by its canonical (upper-case) name.
BUILTINS: dict[str, Builtin] = {b.name: b for b in _TABLE}

#: Command words followed by a list (``Encode A, B'``, ``Units T=S``); any
#: other word followed by one word or number is a setting (``Digits 7``).
LIST_COMMANDS = frozenset({"ENCODE", "UNITS"})


def lookup(name: str) -> Builtin | None:
    """The built-in called ``name`` (any case), or None."""
    return BUILTINS.get(name.upper())


#: The shortest built-in name that a longer spelling may extend.
_SHORTEST_EXTENDED = 3


def by_spelling(name: str) -> Builtin | None:
    """The built-in that a call spelled ``name`` means in Autolev.

    The built-in of that name, else the built-in whose full name (three
    letters or more) ``name`` begins with and then goes on in letters only,
    the longest such: a published transcript answers ``inverse(GTran)`` as
    ``Inv(GTran)`` (docs/semantics.md, "Spellings").  Abbreviations shorter
    than a built-in's name are not accepted (no evidence that Autolev did).
    Callers look for a macro file of the spelled name first."""
    key = name.upper()
    found = BUILTINS.get(key)
    if found is not None or not key.isalpha():
        return found
    stems = [
        b
        for b in BUILTINS
        if len(b) >= _SHORTEST_EXTENDED and key.startswith(b) and b.isalpha()
    ]
    return BUILTINS[max(stems, key=len)] if stems else None


# ------------------------------------------------------------ registration


def register(row: Builtin) -> Builtin:
    """Add a built-in.  A library function's implementation (and degree
    variant) become names of :mod:`al2py_runtime.functions`, which generated
    modules import."""
    from .. import functions as fn

    if row.name in BUILTINS:
        raise ValueError(f"{row.name} is already a built-in")
    for name, impl in zip((row.python, row.degrees), row.given, strict=False):
        if impl is not None:
            if getattr(fn, name, impl) is not impl:
                raise ValueError(f"al2py_runtime.functions already has {name}")
            setattr(fn, name, impl)
    BUILTINS[row.name] = row
    _changed()
    return row


def unregister(name: str) -> None:
    """Remove the built-in ``name`` added by :func:`register`."""
    from .. import functions as fn

    row = BUILTINS.pop(name.upper())
    for attr, impl in zip((row.python, row.degrees), row.given, strict=False):
        if impl is not None and attr is not None and hasattr(fn, attr):
            delattr(fn, attr)
    _changed()


@contextmanager
def registered(row: Builtin) -> Iterator[Builtin]:
    """:func:`register` ``row`` for the ``with`` block."""
    register(row)
    try:
        yield row
    finally:
        unregister(row.name)


def _changed() -> None:
    _printed_names.cache_clear()
    numeric_namespace.cache_clear()
    complex_functions.cache_clear()


def _library() -> list[Builtin]:
    return [b for b in BUILTINS.values() if b.style is Style.FUNC]


# ------------------------------------------------------------ readers


@cache
def _printed_names() -> dict[str, str]:
    return {b.sympy_head.__name__: b.name for b in _library() if b.sympy_head}


def printed_name(expr: sympy.Basic) -> str:
    """The Autolev name a sympy function application prints with: its
    built-in's name, else the sympy name in capitals."""
    name = type(expr).__name__
    return _printed_names().get(name, name.upper())


@cache
def numeric_namespace() -> dict[str, Callable[..., Any]]:
    """``lambdify``'s namespace for the built-ins whose number functions
    Python's ``math`` does not spell as sympy does (``trunc``, ``nint``)."""
    return {
        b.sympy_head.__name__: b.numeric
        for b in _library()
        if b.numeric is not None and b.sympy_head is not None
    }


@cache
def complex_functions() -> dict[type, Callable[[complex], Any]]:
    """Sympy function class -> its one-argument function on complex numbers
    (``cmath``'s, or the built-in's own ``numeric``)."""
    out: dict[type, Callable[[complex], Any]] = {}
    for b in _library():
        head = b.sympy_head
        if head is None or b.min_args != 1 or b.max_args != 1:
            continue
        f = b.numeric or getattr(cmath, head.__name__, None)
        if f is not None:
            out[head] = f
    return out
