"""Typed intermediate representation of an Autolev script.

Every node is a frozen, slotted dataclass that carries the :class:`Span` of the
source text it came from, so every later stage can report ``file:line:col``.
Nodes validate their own fields in ``__post_init__`` (LibCST style): a node that
exists is well formed.

Names are stored exactly as written (Autolev is case-insensitive; use
:func:`canon` to compare them).  The ``>`` suffix of vectors/dyadics is kept
in :attr:`Name.name`; primes are counted in :attr:`Name.primes`.

>>> n = Name(Span("f.al", 1, 1), "Qa", primes=1)
>>> n.key, n.autolev
('QA', "QA'")
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from fractions import Fraction

__all__ = [
    "autolev_text",
    "content",
    "walk_expr",
    "map_expr",
    "stmt_exprs",
    "Span",
    "canon",
    "Node",
    "Expr",
    "Number",
    "Name",
    "Element",
    "IndexedNames",
    "Call",
    "BinOp",
    "UnaryOp",
    "MatrixLit",
    "Range",
    "Equation",
    "String",
    "Stmt",
    "Comment",
    "Assign",
    "ExprStmt",
    "DeclItem",
    "Declaration",
    "Setting",
    "ListCommand",
    "UnitExpr",
    "InputItem",
    "InputStmt",
    "OutputItem",
    "OutputStmt",
    "UnitSystemStmt",
    "Sweep",
    "CodeStmt",
    "FileCommand",
    "MacroCall",
    "Script",
]


def canon(name: str) -> str:
    """Canonical (upper-case) spelling used to compare Autolev names."""
    return name.upper()


@dataclass(frozen=True, slots=True)
class Span:
    """Where a node came from: 1-based line and column of its first character."""

    file: str
    line: int
    col: int
    end_line: int = 0
    end_col: int = 0

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.col}"


#: Source of node identities: every node made in this process gets the next
#: number, so an identity is never reused (``id()`` of a freed node can be).
_identities = itertools.count(1)


@dataclass(frozen=True, slots=True)
class Node:
    """A piece of the tree: where it came from, and who it is.

    Nodes compare by value (two ``X`` at one span are equal), so neither value
    nor span identifies one.  ``nid`` does: a number fixed when the node is
    made and never given to another node in this process (also not by
    :func:`dataclasses.replace`, which makes a new node).  The analysis keeps
    its facts by ``nid``.

    >>> a, b = Name(Span("f.al", 1, 1), "X"), Name(Span("f.al", 1, 1), "X")
    >>> a == b, a.nid == b.nid
    (True, False)
    """

    span: Span
    nid: int = field(
        init=False, default_factory=_identities.__next__, compare=False, repr=False
    )


# ---------------------------------------------------------------- expressions


@dataclass(frozen=True, slots=True)
class Expr(Node):
    pass


@dataclass(frozen=True, slots=True)
class Number(Expr):
    """A numeric literal, kept as its source text (``"1.0E-07"``)."""

    text: str

    def __post_init__(self) -> None:
        if not self.text:
            raise ValueError("empty number literal")

    @property
    def is_integer(self) -> bool:
        return self.text.isdigit()

    @property
    def value(self) -> Fraction:
        """Exact value of the literal (decimals are exact rationals)."""
        return Fraction(self.text.lower())


@dataclass(frozen=True, slots=True)
class Name(Expr):
    """A name, possibly primed: ``X``, ``X''``, ``V_P_N>``, ``I_B_P>>``, ``0>``."""

    name: str
    primes: int = 0

    def __post_init__(self) -> None:
        if not self.name:
            raise ValueError("empty name")
        if self.primes < 0:
            raise ValueError("negative prime count")

    @property
    def key(self) -> str:
        """Canonical spelling without primes (``V_P_N>``)."""
        return canon(self.name)

    @property
    def rank(self) -> int:
        """0 scalar/matrix, 1 vector, 2 dyadic, 3 polyadic (number of ``>``)."""
        return len(self.name) - len(self.name.rstrip(">"))

    @property
    def autolev(self) -> str:
        return self.key + "'" * self.primes


@dataclass(frozen=True, slots=True)
class Element(Expr):
    """``X[7]``, ``M0[2,2]`` or ``DEPENDENT[U2,U3]``: a name with subscripts."""

    base: Name
    indices: tuple[Expr, ...]

    def __post_init__(self) -> None:
        if not self.indices:
            raise ValueError("element reference without an index")


@dataclass(frozen=True, slots=True)
class IndexedNames(Expr):
    """``U{1:3}'`` or ``a{1:2,1:2}``: a family of names, expanded by the analyzer.

    Each entry of ``ranges`` is ``(first, last)``; ``U{3}`` is ``((1, 3),)``.
    ``suffix`` follows the braces: ``RRF{2}O`` is ``RRF1O, RRF2O``.
    """

    stem: str
    ranges: tuple[tuple[int, int], ...]
    primes: int = 0
    suffix: str = ""
    _names: tuple[Name, ...] | None = field(
        init=False, default=None, compare=False, repr=False
    )

    def __post_init__(self) -> None:
        if not self.ranges:
            raise ValueError("index braces need at least one range")
        for lo, hi in self.ranges:
            if lo > hi:
                raise ValueError(f"empty index range {lo}:{hi}")

    def expand(self) -> tuple[str, ...]:
        """Names in Autolev order: ``a{1:2,1:2}`` -> ``a11, a12, a21, a22``."""
        names = [self.stem]
        for lo, hi in self.ranges:
            names = [f"{n}{i}" for n in names for i in range(lo, hi + 1)]
        return tuple(n + self.suffix for n in names)

    @property
    def names(self) -> tuple[Name, ...]:
        """The family as :class:`Name` nodes, made once and shared by every
        reader, so facts recorded on them are found again.

        >>> u = IndexedNames(Span("f.al", 1, 1), "U", ((1, 2),), primes=1)
        >>> [n.autolev for n in u.names], u.names[0] is u.names[0]
        (["U1'", "U2'"], True)
        """
        if self._names is None:  # made on first use, then kept
            names = tuple(Name(self.span, n, self.primes) for n in self.expand())
            object.__setattr__(self, "_names", names)
        return self._names  # type: ignore[return-value]


@dataclass(frozen=True, slots=True)
class Call(Expr):
    """``Func(arg, ...)``; keyword-style arguments are :class:`Equation`."""

    func: str
    args: tuple[Expr, ...] = ()

    @property
    def key(self) -> str:
        return canon(self.func)


@dataclass(frozen=True, slots=True)
class BinOp(Expr):
    op: str  # one of + - * / ^
    left: Expr
    right: Expr

    def __post_init__(self) -> None:
        if self.op not in ("+", "-", "*", "/", "^"):
            raise ValueError(f"unknown binary operator {self.op!r}")


@dataclass(frozen=True, slots=True)
class UnaryOp(Expr):
    op: str  # + or -
    operand: Expr

    def __post_init__(self) -> None:
        if self.op not in ("+", "-"):
            raise ValueError(f"unknown unary operator {self.op!r}")


@dataclass(frozen=True, slots=True)
class MatrixLit(Expr):
    """``[a, b; c, d]``: rows of entries; entries may themselves be matrices."""

    rows: tuple[tuple[Expr, ...], ...]

    def __post_init__(self) -> None:
        if not self.rows or not all(self.rows):
            raise ValueError("empty matrix row")


@dataclass(frozen=True, slots=True)
class Range(Expr):
    """``lo:hi`` as a function argument (``Expand(E, 1:2)``, ``X=0:dX``)."""

    lo: Expr
    hi: Expr


@dataclass(frozen=True, slots=True)
class Equation(Expr):
    """``lhs = rhs`` inside an argument list (``Evaluate(E, X=1)``)."""

    lhs: Expr
    rhs: Expr


@dataclass(frozen=True, slots=True)
class String(Expr):
    value: str


# ----------------------------------------------------------------- statements


@dataclass(frozen=True, slots=True)
class Stmt(Node):
    """A statement; ``comment`` is the trailing ``% ...`` text, if any."""

    comment: str | None = field(default=None, kw_only=True)


@dataclass(frozen=True, slots=True)
class Comment(Stmt):
    """A line that holds only a comment (``text`` excludes the ``%``).

    ``code_comment`` is True for ``%%`` comments, which Autolev copies into
    generated code.
    """

    text: str
    code_comment: bool = False


@dataclass(frozen=True, slots=True)
class Assign(Stmt):
    """``target op value``; ``op`` is one of ``= := += -= *= /= ^=``."""

    target: Expr  # Name | Element
    op: str
    value: Expr

    def __post_init__(self) -> None:
        if self.op not in ("=", ":=", "+=", "-=", "*=", "/=", "^="):
            raise ValueError(f"unknown assignment operator {self.op!r}")
        if not isinstance(self.target, Name | Element):
            raise ValueError("assignment target must be a name or an element")


@dataclass(frozen=True, slots=True)
class ExprStmt(Stmt):
    """A bare expression or a stand-alone command: ``Solve(Zero, X, Y)``."""

    expr: Expr


@dataclass(frozen=True, slots=True)
class DeclItem(Node):
    """One item of a declaration.

    ``Constants B=3``        -> target B, values (3,)
    ``Constants C+``          -> target C, sign "+"
    ``Mass A=M=12``           -> target A, values (M, 12)
    ``Variables Y{3}'``       -> target IndexedNames(Y, ((1,3),), primes=1)
    ``Inertia B, IB=..., 0``  -> every item after the first is a DeclItem too
    ``values`` may carry their own sign as ``signs`` (``Mass A=MA+``).
    """

    target: Expr
    values: tuple[Expr, ...] = ()
    sign: str | None = None
    value_signs: tuple[str | None, ...] = ()

    def __post_init__(self) -> None:
        if self.sign not in (None, "+", "-"):
            raise ValueError(f"bad sign suffix {self.sign!r}")


@dataclass(frozen=True, slots=True)
class Declaration(Stmt):
    """``Constants``, ``Variables``, ``Specified``, ``Imaginary``, ``Newtonian``,
    ``Frames``, ``Bodies``, ``Particles``, ``Points``, ``Mass``, ``Inertia``.

    ``keyword`` is the canonical declaration kind (``"CONSTANTS"``, ...), not
    the spelling (``Constant``/``CONSTANTS``/``MotionVariables``...);
    ``motion`` records the ``MotionVariables`` spelling of ``VARIABLES``.
    """

    keyword: str
    items: tuple[DeclItem, ...]
    #: ``MotionVariables`` (with or without a prime) rather than ``Variables``.
    motion: bool = False


@dataclass(frozen=True, slots=True)
class Setting(Stmt):
    """``Digits 7``, ``AutoRHS ALL``, ``Degrees ON``, ``Exit``...

    ``name`` is canonical upper case; ``value`` is the word/number text as
    written (or None for settings that take no value).
    """

    name: str
    value: str | None = None


@dataclass(frozen=True, slots=True)
class ListCommand(Stmt):
    """A command word followed by a list: ``Encode A, B'``, ``Units T=S``.

    ``items`` are names (possibly primed), elements, or ``name=word``
    :class:`Equation` s.
    """

    name: str  # canonical upper case
    items: tuple[Expr, ...]

    def __post_init__(self) -> None:
        if not self.items:
            raise ValueError(f"{self.name} needs at least one item")


@dataclass(frozen=True, slots=True)
class UnitExpr(Node):
    """A unit such as ``m``, ``deg``, ``n*sec/m``, ``m/sec^2``.

    ``factors`` is a tuple of (unit word, exponent); division gives negative
    exponents: ``m/sec^2`` -> (("m", 1), ("sec", -2)).
    """

    factors: tuple[tuple[str, int], ...]
    text: str = ""


@dataclass(frozen=True, slots=True)
class InputItem(Node):
    name: Expr  # Name | Element | IndexedNames
    value: Expr
    unit: UnitExpr | None = None


@dataclass(frozen=True, slots=True)
class InputStmt(Stmt):
    items: tuple[InputItem, ...]


@dataclass(frozen=True, slots=True)
class OutputItem(Node):
    expr: Expr
    unit: UnitExpr | None = None


@dataclass(frozen=True, slots=True)
class OutputStmt(Stmt):
    items: tuple[OutputItem, ...]


@dataclass(frozen=True, slots=True)
class UnitSystemStmt(Stmt):
    units: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Sweep(Node):
    """``[PHI deg=0,360,1]`` in a CODE statement."""

    name: Name
    unit: UnitExpr | None
    start: Expr
    stop: Expr
    step: Expr


@dataclass(frozen=True, slots=True)
class CodeStmt(Stmt):
    """``CODE Dynamics() tutor6.c`` / ``CODE Nonlinear(CONFIG, QB, QC) t.for``."""

    option: str  # canonical: DYNAMICS, ODE, NONLINEAR, ALGEBRAIC
    args: tuple[Expr, ...]
    sweep: Sweep | None
    filename: str | None
    #: Words after the file name (``CODE Dynamics() f.c, NOSUBS``), upper case.
    options: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class FileCommand(Stmt):
    """``Save tutor2.all``, ``Run other.al``: a command word and a file name."""

    command: str  # canonical: SAVE, RUN
    filename: str


@dataclass(frozen=True, slots=True)
class MacroCall(Stmt):
    """A statement produced by expanding a ``.a`` macro or ``RUN`` file.

    ``body`` holds the statements of the expansion; ``source`` is the macro
    file's path; ``span`` is the invoking statement's span.
    """

    name: str
    source: str
    body: tuple[Stmt, ...]


@dataclass(frozen=True, slots=True)
class Script(Node):
    """A whole file: ``statements`` in order; ``lines`` are the physical lines."""

    statements: tuple[Stmt, ...]
    lines: tuple[str, ...] = field(default=(), repr=False)


# ------------------------------------------------------------------ traversal


def content(node: Node) -> Iterator[tuple[str, object]]:
    """``(field, value)`` for the fields that hold a node's content, not its
    identity (``nid``) or what it keeps made (``IndexedNames.names``)."""
    for f in dataclasses.fields(node):
        if f.init:
            yield f.name, getattr(node, f.name)


def walk_expr(expr: Expr) -> Iterator[Expr]:
    """Every expression node below (and including) ``expr``, parents first.

    Iterative, so a deep tree costs linear time (nested generators would make
    it quadratic) and no recursion."""
    stack = [expr]
    while stack:
        node = stack.pop()
        yield node
        children: list[Expr] = []
        for _, value in content(node):
            if isinstance(value, Expr):
                children.append(value)
            elif isinstance(value, tuple):
                for item in value:
                    if isinstance(item, Expr):
                        children.append(item)
                    elif isinstance(item, tuple):
                        children.extend(s for s in item if isinstance(s, Expr))
        stack.extend(reversed(children))


def map_expr(expr: Expr, fn: Callable[[Expr], Expr | None]) -> Expr:
    """Rebuild ``expr`` bottom-up, replacing nodes for which ``fn`` returns a node."""
    changes = {}
    for name, value in content(expr):
        if isinstance(value, Expr):
            changes[name] = map_expr(value, fn)
        elif isinstance(value, tuple) and value and isinstance(value[0], Expr | tuple):
            changes[name] = tuple(
                (
                    map_expr(v, fn)
                    if isinstance(v, Expr)
                    else (
                        tuple(map_expr(s, fn) if isinstance(s, Expr) else s for s in v)
                        if isinstance(v, tuple)
                        else v
                    )
                )
                for v in value
            )
    if changes:
        expr = dataclasses.replace(expr, **changes)
    out = fn(expr)
    return expr if out is None else out


def stmt_exprs(stmt: Stmt) -> Iterator[Expr]:
    """The expressions directly held by a statement."""
    for _, value in content(stmt):
        if isinstance(value, Expr):
            yield value
        elif isinstance(value, tuple):
            for item in value:
                if isinstance(item, Expr):
                    yield item
                elif isinstance(item, Node):
                    for _, sub in content(item):
                        if isinstance(sub, Expr):
                            yield sub
                        elif isinstance(sub, tuple):
                            yield from (s for s in sub if isinstance(s, Expr))


_PRECEDENCE = {"+": 1, "-": 1, "*": 2, "/": 2, "^": 4}  # unary minus: 3


def autolev_text(expr: Expr, *, upper: bool = True) -> str:
    """``expr`` written back as compact Autolev text (upper case, no spaces,
    parentheses only where needed): the label of an Output column, whatever
    file or macro the expression came from.

    >>> s = Span("f.al", 1, 1)
    >>> x, y = Name(s, "x", primes=1), Name(s, "v_p_n>")
    >>> autolev_text(BinOp(s, "*", BinOp(s, "+", x, Number(s, "2")), x))
    "(X'+2)*X'"
    >>> autolev_text(Call(s, "Dot", (y, Name(s, "N1>"))))
    'DOT(V_P_N>,N1>)'
    >>> autolev_text(BinOp(s, "/", Name(s, "m"), Name(s, "sec")), upper=False)
    'm/sec'
    """
    text = _text(expr, upper)[0]
    return text.upper() if upper else text


def _text(e: Expr, upper: bool) -> tuple[str, int]:
    """(text, precedence): atoms 5, unary minus 3, then ``^ * / + -``."""
    if isinstance(e, Name) and not upper:
        return e.name + "'" * e.primes, 5
    if isinstance(e, UnaryOp):
        text, prec = _text(e.operand, upper)
        return e.op + (f"({text})" if prec < 3 else text), 3
    if isinstance(e, BinOp):
        prec = _PRECEDENCE[e.op]
        left, lp = _text(e.left, upper)
        right, rp = _text(e.right, upper)
        if lp < prec or (e.op == "^" and lp == prec):
            left = f"({left})"
        if rp < prec or (rp == prec and e.op in "-/^"):
            right = f"({right})"
        return f"{left}{e.op}{right}", prec
    return _atom_text(e), 0 if isinstance(e, Range | Equation) else 5


def _atom_text(e: Expr) -> str:
    if isinstance(e, Number):
        return e.text.upper()
    if isinstance(e, Name):
        return e.autolev
    if isinstance(e, Element):
        return f"{e.base.autolev}[{','.join(map(autolev_text, e.indices))}]"
    if isinstance(e, IndexedNames):
        braces = ",".join(f"{lo}:{hi}" for lo, hi in e.ranges)
        return canon(f"{e.stem}{{{braces}}}{e.suffix}") + "'" * e.primes
    if isinstance(e, Call):
        return f"{e.key}({','.join(map(autolev_text, e.args))})"
    if isinstance(e, MatrixLit):
        rows = ";".join(",".join(map(autolev_text, row)) for row in e.rows)
        return f"[{rows}]"
    if isinstance(e, Range):
        return f"{autolev_text(e.lo)}:{autolev_text(e.hi)}"
    if isinstance(e, Equation):
        return f"{autolev_text(e.lhs)}={autolev_text(e.rhs)}"
    if isinstance(e, String):
        return repr(e.value)
    raise TypeError(f"no Autolev text for {type(e).__name__}")
