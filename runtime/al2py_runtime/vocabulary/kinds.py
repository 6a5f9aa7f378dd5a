"""What an Autolev expression is, and what a declaration makes a name.

:class:`Kind` is the kind of value an expression has (the transpiler's
analysis checks operators and arguments with it); :class:`Decl` is the kind
of name a declaration or an assignment makes.  ``Decl`` members are strings,
so a name table may store them and compare them with plain text.

>>> Decl.of_keyword("Bodies")
<Decl.BODY: 'body'>
>>> Decl.BODY in FRAME_DECLS, Decl.BODY == "body", Decl.BODY.value_kind
(True, True, <Kind.FRAME: 'frame'>)
>>> sorted(str(d) for d in OBJECT_DECLS)
['body', 'frame', 'newtonian', 'particle', 'point']
"""

from __future__ import annotations

from enum import Enum, StrEnum

__all__ = [
    "Kind",
    "Decl",
    "SCALAR_DECLS",
    "QUANTITY_DECLS",
    "TIME_DECLS",
    "FRAME_DECLS",
    "POINT_DECLS",
    "MASSIVE_DECLS",
    "OBJECT_DECLS",
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


class Decl(StrEnum):
    """What kind of name a declaration (``Constants``, ``Bodies``...) or an
    assignment makes."""

    CONSTANT = "constant"
    VARIABLE = "variable"
    SPECIFIED = "specified"
    IMAGINARY = "imaginary"
    NEWTONIAN = "newtonian"
    FRAME = "frame"
    BODY = "body"
    PARTICLE = "particle"
    POINT = "point"
    #: made by assignment, or reserved
    SCALAR = "scalar"
    TIME = "time"
    MATRIX = "matrix"
    VECTOR = "vector"
    DYADIC = "dyadic"
    POLYADIC = "polyadic"
    SPEEDS = "speeds"  # U_INDEPENDENT, U_DEPENDENT... (tutorial 2.4)

    @classmethod
    def of_keyword(cls, keyword: str) -> Decl | None:
        """The kind a declaration keyword (any case) makes, or None."""
        return _KEYWORDS.get(keyword.upper())

    @property
    def value_kind(self) -> Kind:
        """The kind of value a name of this kind has."""
        if self in SCALAR_DECLS:
            return Kind.SCALAR
        if self in FRAME_DECLS:
            return Kind.FRAME
        if self in POINT_DECLS:
            return Kind.POINT
        if self is Decl.SPEEDS:
            return Kind.MATRIX
        return Kind(self.value)


#: Declaration keyword -> the kind of the names it declares.
_KEYWORDS = {
    "CONSTANTS": Decl.CONSTANT,
    "VARIABLES": Decl.VARIABLE,
    "SPECIFIED": Decl.SPECIFIED,
    "IMAGINARY": Decl.IMAGINARY,
    "NEWTONIAN": Decl.NEWTONIAN,
    "FRAMES": Decl.FRAME,
    "BODIES": Decl.BODY,
    "PARTICLES": Decl.PARTICLE,
    "POINTS": Decl.POINT,
}

#: Names whose values are scalars.
SCALAR_DECLS = frozenset(
    {
        Decl.CONSTANT,
        Decl.VARIABLE,
        Decl.SPECIFIED,
        Decl.IMAGINARY,
        Decl.SCALAR,
        Decl.TIME,
    }
)
#: Declared quantities: their values are given, integrated or specified.
QUANTITY_DECLS = frozenset({Decl.CONSTANT, Decl.VARIABLE, Decl.SPECIFIED})
#: Declared functions of time (they have derivatives ``Q'``).
TIME_DECLS = frozenset({Decl.VARIABLE, Decl.SPECIFIED})
#: Names of reference frames.
FRAME_DECLS = frozenset({Decl.NEWTONIAN, Decl.FRAME, Decl.BODY})
#: Names of points.
POINT_DECLS = frozenset({Decl.POINT, Decl.PARTICLE})
#: Objects with mass.
MASSIVE_DECLS = frozenset({Decl.BODY, Decl.PARTICLE})
#: The physical objects: frames, bodies, particles and points.
OBJECT_DECLS = FRAME_DECLS | POINT_DECLS
