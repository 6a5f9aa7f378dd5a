"""The table of Autolev's built-in functions and commands.

Each entry says how many arguments a built-in takes, what kind of value it
returns, and how the generator spells it in Python:

* ``FUNC``: a library function imported from ``al2py_runtime.functions``
  (``SIN`` -> ``sin``).
* ``METHOD``: a workspace method (``EXPAND`` -> ``al.expand``); the runtime
  resolves the first argument's right-hand side, as Autolev does.
* ``SPECIAL``: emitted by a dedicated generator method (``Solve``, ``Eig`` with
  three arguments, ``Evaluate``...).
* ``PENDING``: valid Autolev that al2py does not translate yet; using it is a
  clear ``not supported yet`` error, never silently dropped.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum

__all__ = [
    "Style",
    "Kind",
    "Builtin",
    "BUILTINS",
    "DUAL_FUNCTIONS",
    "LIST_COMMANDS",
    "lookup",
    "by_spelling",
]


class Kind(Enum):
    """What an expression evaluates to."""

    SCALAR = "scalar"
    MATRIX = "matrix"
    VECTOR = "vector"
    DYADIC = "dyadic"
    POLYADIC = "polyadic"
    FRAME = "frame"
    POINT = "point"
    WORD = "word"
    UNKNOWN = "unknown"


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
    return Kind.UNKNOWN  # decided at run time (Partials: one vector or several)


def _momentum(kinds: list[Kind]) -> Kind:
    return Kind.UNKNOWN  # LINEAR/ANGULAR give vectors, GENERALIZED a matrix


def _gyrostat(kinds: list[Kind]) -> Kind:
    return Kind.UNKNOWN  # FRSTAR: matrix, ANGMOM: vector, KE: scalar


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
    name: str  # canonical Autolev spelling
    style: Style
    python: str  # function or method name in the runtime
    min_args: int
    max_args: int | None  # None: no limit
    result: KindRule = _scalar
    dual: bool = False  # ``Expand(E)`` alone means ``E := Expand(E)``
    issue: str = ""  # for PENDING: what brings it
    statement: bool = False  # a stand-alone command that responds (``V2pts``)
    words: tuple[int, ...] = ()  # argument positions holding option words
    #: Argument positions that name a frame, body, particle or point; from
    #: ``objects_from`` on, every argument does (``Gravity(v>, A, B)``).  A
    #: name that is both an object and a quantity (body ``C``, constant ``c``)
    #: means the object there and the quantity elsewhere.
    objects: tuple[int, ...] = ()
    objects_from: int | None = None

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


def _func(name: str, python: str, n: int = 1, hi: int | None = -1) -> Builtin:
    return Builtin(name, Style.FUNC, python, n, n if hi == -1 else hi, _first)


_NUMERICS = "numerical CODE jobs"


def _command(
    name: str,
    python: str,
    lo: int,
    hi: int | None,
    words: tuple[int, ...] = (),
    objects: tuple[int, ...] = (),
    objects_from: int | None = None,
) -> Builtin:
    return Builtin(
        name,
        Style.METHOD,
        python,
        lo,
        hi,
        statement=True,
        words=words,
        objects=objects,
        objects_from=objects_from,
    )


def _pending(name: str, issue: str, lo: int = 0, hi: int | None = None) -> Builtin:
    return Builtin(name, Style.PENDING, name.lower(), lo, hi, issue=issue)


_TABLE: list[Builtin] = [
    # -- library functions (tutorial Summary: operators and library functions)
    _func("ABS", "Abs"),
    _func("SIN", "sin"),
    _func("COS", "cos"),
    _func("TAN", "tan"),
    _func("SINH", "sinh"),
    _func("COSH", "cosh"),
    _func("TANH", "tanh"),
    _func("ASIN", "asin"),
    _func("ACOS", "acos"),
    _func("ATAN", "atan"),
    _func("ATAN2", "atan2", 2),
    _func("LOG", "log"),
    _func("LOG10", "log10"),
    _func("EXP", "exp"),
    _func("SQR", "sqr"),
    _func("SQRT", "sqrt"),
    _func("FACTORIAL", "factorial"),
    _func("CEIL", "ceil"),
    _func("FLOOR", "floor"),
    _func("INT", "trunc"),
    _func("ROUND", "nint"),
    _func("MAX", "maxof", 2, None),
    _func("MIN", "minof", 2, None),
    _func("SIGN", "sign"),
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
        _momentum,
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
        _gyrostat,
        words=(0, 1),
        objects=(2, 3),
    ),
    # -- stand-alone physics commands (statements; they respond)
    _command("SIMPROT", "simprot", 4, 4, objects=(0, 1)),
    _command("DIRCOS", "dircos", 4, None, words=(2,), objects=(0, 1)),
    _command("ANGVEL", "angvel", 2, None, words=(2,), objects=(0, 1)),
    _command("KINDIFFS", "kindiffs", 4, None, words=(2,), objects=(0, 1)),
    _command("V2PTS", "v2pts", 4, 4, objects=(0, 1, 2, 3)),
    _command("A2PTS", "a2pts", 4, 4, objects=(0, 1, 2, 3)),
    _command("V1PT", "v1pt", 4, 4, objects=(0, 1, 2, 3)),
    _command("A1PT", "a1pt", 4, 4, objects=(0, 1, 2, 3)),
    _command("GRAVITY", "gravity", 1, None, objects_from=1),
    _command("FORCE", "add_force", 2, 2, objects=(0,)),
    _command("TORQUE", "add_torque", 2, 2, objects=(0,)),
    _command("CONSTRAIN", "constrain", 1, None),
    _command("KANE", "kane", 0, None),
    Builtin("INPUT", Style.SPECIAL, "input_value", 1, 2),
    Builtin("UNITS", Style.SPECIAL, "units", 2, 2),
    Builtin("AUTOTAYLOR", Style.SPECIAL, "autotaylor", 2, None, statement=True),
    *(_pending(n, _NUMERICS) for n in ("SPLINE",)),
]

BUILTINS: dict[str, Builtin] = {b.name: b for b in _TABLE}

#: Built-ins that, used alone on a line with a name as first argument, assign
#: the result back to that name (tutorial §6.3).
DUAL_FUNCTIONS = frozenset(b.name for b in _TABLE if b.dual) | {"EXPRESS"}


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


#: Command words followed by a list (``Encode A, B'``, ``Units T=S``); any
#: other word followed by one word or number is a setting (``Digits 7``).
LIST_COMMANDS = frozenset({"ENCODE", "UNITS"})
