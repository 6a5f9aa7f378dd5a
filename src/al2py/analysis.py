"""Semantic analysis: one symbol table, name checks, kinds, macro expansion.

Autolev scripts run top to bottom with no control flow, so analysis is a single
ordered walk.  :meth:`Analysis.enter` checks one statement against the symbol
table as it stands at that point, updates the table, and returns the facts the
generator needs.  Python identifiers are fixed before the walk by a pre-pass,
so a name keeps one identifier for the whole module.

Macro files (``.a``/``.r``) and ``RUN`` files are expanded by :func:`expand`
before the walk.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from al2py_runtime.jobs.records import INTEGRATION_DEFAULTS as _INTEGRATION_DEFAULTS
from al2py_runtime.jobs.records import KINDS as _CODE_KINDS
from al2py_runtime.vocabulary import (
    BUILTINS,
    FRAME_DECLS,
    MASSIVE_DECLS,
    OBJECT_DECLS,
    POINT_DECLS,
    QUANTITY_DECLS,
    TIME_DECLS,
    Builtin,
    Decl,
    Form,
    Kind,
    Match,
    Style,
    match,
)

from . import ir
from .errors import (
    AutolevError,
    ErrorList,
    InternalError,
    SemanticError,
    UnsupportedError,
)
from .ir import stmt_exprs, walk_expr
from .macros import expand, flatten
from .naming import Namer
from .static_checks import matrix_sum_error, unknown_call_message

__all__ = [
    "Symbol",
    "SymbolTable",
    "Analysis",
    "Facts",
    "StmtFacts",
    "UndeclaredError",
    "expand",
    "walk_expr",
]

#: Reserved names for the columns of generalized speeds (tutorial 2.4:
#: "U_INDEPENDENT, U_INDEPENDENT', ... are reserved"), kind "speeds".
SPEED_MATRICES = ("U_INDEPENDENT", "U_DEPENDENT", "U_AUXILIARY", "U_PARTIALS")

SOLVE_OPTIONS = frozenset({"GAUSS", "MINORS", "IMPLICIT"})
_MATRIX_FIRST = frozenset({"DET", "INV", "TRANSPOSE", "EIG", "ROWS", "COLS", "ELEMENT"})
_OBJECT_ARGS = frozenset({"MASS", "CM", "INERTIA", "KE"})
_NEEDS_NEWTONIAN = frozenset(
    {"FR", "FRSTAR", "KANE", "NICHECK", "GRAVITY", "KE", "MOMENTUM", "GYROSTAT"}
)
#: Integration parameters that ``Input`` sets without a declaration.
#: (Both tables are the runtime's, so the two sides never disagree.)
INTEGRATION_PARAMETERS = frozenset(_INTEGRATION_DEFAULTS)
CODE_OPTIONS = frozenset(_CODE_KINDS)
#: Words after a CODE statement's file name.  They shape the text of the
#: program Autolev wrote (NOSUBS: no substitution of intermediate values);
#: the numbers the job computes are the same.
CODE_FILE_OPTIONS = frozenset({"NOSUBS", "SUBS"})
#: Names that stop reading the script (Autolev ends the session).
STOP_WORDS = frozenset({"EXIT", "QUIT"})
#: Commands of an interactive session that a batch run has no use for.
INTERACTIVE_WORDS = {
    "PAUSE": "Autolev waits for a key press here; a batch run goes on.",
}


#: Python names every generated module uses; user names avoid them.
def _runtime_names() -> frozenset[str]:
    library = [b for b in BUILTINS.values() if b.style is Style.FUNC]
    return frozenset(b.python for b in library) | frozenset(
        b.degrees for b in library if b.degrees is not None
    )


RESERVED_IDENTIFIERS = (
    frozenset(
        {
            "al",
            "t",
            "pi",
            "I",
            "Matrix",
            "Eq",
            "Rational",
            "Integer",
            "Vector",
            "inertia",
            "outer",
            "Force",
            "Torque",
            "ReferenceFrame",
            "Point",
            "Particle",
            "symbols",
            "Workspace",
            "AUTOLEV",
            "AL_SOURCE",
            "main",
            "run",
            "evaluate",
            "kanes_method",
            "ode_function",
            "sys",
        }
    )
    | _runtime_names()
)


#: kinds whose values Units and computed Inputs may name: declared and
#: assigned quantities.
_VALUE_KINDS = QUANTITY_DECLS | {Decl.SCALAR, Decl.MATRIX}


@dataclass
class Symbol:
    """Everything the analysis knows about one Autolev name."""

    key: str  # canonical spelling
    kind: Decl
    ident: str
    span: ir.Span | None = None
    order: int = 0  # highest derivative order, for variables/specified
    sign: str | None = None
    has_rhs: bool = False
    seq: int = 0  # definition order: the latest definition of a name wins
    shape: tuple[int, int] | None = None  # matrices, when known statically
    of_vectors: bool = False  # a matrix whose entries are vectors (``[V1>, V2>]``)

    @property
    def value_kind(self) -> Kind:
        try:
            return Decl(self.kind).value_kind
        except ValueError:
            return Kind.UNKNOWN


class SymbolTable:
    """Canonical name -> :class:`Symbol`; physical objects live alongside."""

    def __init__(self, namer: Namer) -> None:
        self.namer = namer
        self._symbols: dict[str, Symbol] = {}
        self._physical: dict[str, Symbol] = {}
        self._seq = 0
        self.define("T", Decl.TIME, "t")
        self.define("PI", Decl.CONSTANT, "pi")
        for key in SPEED_MATRICES:
            self.define(key, Decl.SPEEDS, key)

    def define(self, key: str, kind: Decl, ident: str, **kw: object) -> Symbol:
        self._seq += 1
        sym = Symbol(key, kind, ident, seq=self._seq, **kw)  # type: ignore[arg-type]
        if kind in OBJECT_DECLS:
            self._physical[key] = sym
        else:
            self._symbols[key] = sym
        return sym

    def get(self, key: str) -> Symbol | None:
        """The latest definition of ``key``: a quantity or an object."""
        key = key.upper()
        found = [s for s in (self._symbols.get(key), self._physical.get(key)) if s]
        return max(found, key=lambda s: s.seq) if found else None

    def quantity(self, key: str) -> Symbol | None:
        return self._symbols.get(key.upper())

    def physical(self, key: str) -> Symbol | None:
        return self._physical.get(key.upper())

    def __iter__(self) -> Iterator[Symbol]:
        yield from self._symbols.values()
        yield from self._physical.values()


@dataclass(frozen=True)
class StmtFacts:
    """What the generator needs to know about one statement."""

    degrees: bool = False
    target: Symbol | None = None  # symbol assigned by an Assign
    stop: bool = False  # EXIT/QUIT: nothing after this runs
    form: Match | None = None  # syntactical form assigned (``P_O_P> = ...``)
    new_constants: tuple[Symbol, ...] = ()  # declared by Mass/Inertia items
    #: An interactive command with nothing to do in a batch run (``Pause``),
    #: and why.
    noop: str = ""


class UndeclaredError(SemanticError):
    """A name used before it is declared or assigned."""

    def __init__(self, message: str, span: ir.Span, *, name: str) -> None:
        super().__init__(message, span)
        self.name = name


class Facts:
    """What the analysis of a whole file found: everything the generator reads.

    Per statement (:meth:`of`), per name node (:meth:`resolution`: the symbol
    or syntactical form it stands for there), per expression (:meth:`kind`),
    and the final symbol table (identifiers are fixed for the whole file).
    """

    def __init__(self, analysis: Analysis) -> None:
        self.table = analysis.table
        self.mentioned = frozenset(analysis.mentioned)
        self._stmt = analysis.stmt_facts
        self._resolved = analysis.resolved
        self._kinds = analysis.kinds
        self._vector_matrices = frozenset(analysis.vector_matrices)
        self._namer = analysis.namer

    def helper_ident(self, key: str, spelling: str) -> str:
        """The identifier of a name the generator adds (a body's sympy
        ``RigidBody``, the list ``kd_eqs``).  Chosen after every Autolev name
        has its identifier, so the script's names keep theirs."""
        return self._namer.assign("#" + key, spelling, "body")

    def of(self, stmt: ir.Stmt) -> StmtFacts:
        return self._stmt.get(stmt.nid, StmtFacts())

    def resolution(self, node: ir.Name) -> Symbol | Match:
        found = self._resolved.get(node.nid)
        if found is None:  # never a guess: a miss is a bug, not a name to look up
            raise InternalError(f"{node.name} at {node.span} was not analysed")
        return found

    def kind(self, expr: ir.Expr) -> Kind:
        return self._kinds.get(expr.nid, Kind.UNKNOWN)

    def is_vector_matrix(self, expr: ir.MatrixLit) -> bool:
        return expr.nid in self._vector_matrices

    def quantity(self, spelling: str) -> Symbol:
        sym = self.table.quantity(spelling) or self.table.get(spelling)
        if sym is None:
            raise InternalError(f"{spelling} missing from the symbol table")
        return sym

    def object(self, spelling: str) -> Symbol:
        sym = self.table.physical(spelling)
        if sym is None:
            raise InternalError(f"object {spelling} missing from the symbol table")
        return sym

    def is_point(self, spelling: str) -> bool:
        sym = self.table.physical(spelling)
        return sym is not None and sym.kind in POINT_DECLS


# ------------------------------------------------------------------ helpers


# ------------------------------------------------------------------ analysis


class Analysis:
    """Checks statements in order against one :class:`SymbolTable`."""

    def __init__(
        self, stmts: tuple[ir.Stmt, ...], reserved: frozenset[str] = frozenset()
    ) -> None:
        self.namer = Namer(reserved=set(RESERVED_IDENTIFIERS) | set(reserved))
        self.table = SymbolTable(self.namer)
        self.degrees = False
        #: Object names appearing anywhere, also inside forms (``P_O_Ao>``).
        self.mentioned: set[str] = set()
        #: Name nodes used as operands of arithmetic: there a name that is both
        #: a quantity and a (later declared) object means the quantity, since
        #: frames and points are never values (``Constants L`` ...
        #: ``Particles L`` ... ``L*N1>``).
        self._as_value: set[int] = set()  # nids of Name nodes
        #: Name nodes where the context takes a frame or point (``Simprot``).
        self._as_object: set[int] = set()
        #: What each Name node means (a :class:`Symbol` or a :class:`~al2py_runtime.vocabulary.Match`),
        #: and the kind of each expression, by node identity (``nid``).
        self.resolved: dict[int, Symbol | Match] = {}
        self.kinds: dict[int, Kind] = {}
        #: Facts of each statement, by ``nid``, filled by :meth:`run`.
        self.stmt_facts: dict[int, StmtFacts] = {}
        self.errors: list[AutolevError] = []
        self._poisoned: set[str] = set()
        #: The statements of :meth:`run`, to explain undeclared names.
        self._stmts: tuple[ir.Stmt, ...] = ()
        self._fragment_told = False
        #: Matrix literals of vectors, allowed as arguments of Dot
        #: (``Dot(V1>, [V2>; 2*V2>])`` is the column of the dot products).
        self.vector_matrices: set[int] = set()  # nids of MatrixLit nodes
        self._plan_identifiers(stmts)

    # ---------------------------------------------------------- identifiers

    def _plan_identifiers(self, stmts: tuple[ir.Stmt, ...]) -> None:
        """Fix every Python identifier up front (see :mod:`al2py.naming`)."""
        flat = list(flatten(stmts))
        for s in flat:
            if isinstance(s, ir.Declaration) and Decl.of_keyword(s.keyword):
                kind = Decl.of_keyword(s.keyword)
                if kind in OBJECT_DECLS:
                    for name in self._decl_names(s):
                        self.namer.note_physical(name)
                        if kind in FRAME_DECLS:
                            self.namer.note_physical(name + "O")
        for s in flat:
            if isinstance(s, ir.Declaration) and Decl.of_keyword(s.keyword):
                kind = Decl.of_keyword(s.keyword)
                for name in self._decl_names(s):
                    self._ident(name, kind)
            for e in stmt_exprs(s):
                for node in walk_expr(e):
                    if isinstance(node, ir.Name):
                        self._ident(node.name, _kind_from_spelling(node.name))
                        self.mentioned.update(_parts(node.name))
                    elif isinstance(node, ir.IndexedNames):
                        for n in node.expand():
                            self._ident(n, Decl.SCALAR)

    def _decl_names(self, s: ir.Declaration) -> Iterator[str]:
        for item in s.items:
            if isinstance(item.target, ir.Name):
                yield item.target.name
            elif isinstance(item.target, ir.IndexedNames):
                yield from item.target.expand()

    def _ident(self, spelling: str, kind: Decl) -> str:
        key = spelling.upper()
        if key in ("T", "PI", "0>", "1>>") or (key == "I" and kind == Decl.IMAGINARY):
            return {"T": "t", "PI": "pi", "I": "I"}.get(key, key)
        ns = ("phys:" if kind in OBJECT_DECLS else "") + key
        return self.namer.assign(ns, spelling, kind)

    def ident(self, spelling: str, kind: Decl = Decl.SCALAR) -> str:
        """The Python identifier for an Autolev name."""
        return self._ident(spelling, kind)

    # -------------------------------------------------------------- lookup

    def is_frame(self, name: str) -> bool:
        sym = self.table.physical(name)
        return sym is not None and sym.kind in FRAME_DECLS

    def is_point(self, name: str) -> bool:
        sym = self.table.physical(name)
        return sym is not None and sym.kind in POINT_DECLS

    def is_body(self, name: str) -> bool:
        sym = self.table.physical(name)
        return sym is not None and sym.kind in MASSIVE_DECLS

    def form(self, node: ir.Name) -> Match | None:
        """The syntactical form ``node`` spells (``V_P_N>``, ``A1>``), if any."""
        if node.key in ("0>", "1>>") or "_" not in node.name and not node.rank:
            return None
        return match(node.name, self.is_frame, self.is_point, self.is_body)

    def lookup(self, node: ir.Name, want: Kind | None = None) -> Symbol:
        """The symbol a (non-form) name refers to; errors for undeclared names.

        A name may stand for both a quantity and an object (constant ``c`` and
        body ``C``): ``want`` (FRAME or POINT where the context takes an
        object, SCALAR where it takes a value) picks one; otherwise the
        latest definition wins.
        """
        sym = self.table.get(node.name)
        if want in (Kind.FRAME, Kind.POINT) or node.nid in self._as_object:
            obj = self.table.physical(node.name)
            sym = obj if obj is not None and not node.primes else sym
        elif want is not None or node.nid in self._as_value or node.primes:
            sym = self.table.quantity(node.name) or sym
        if sym is None:
            if node.rank:
                raise UndeclaredError(
                    f"'{node.name}' is not defined (assign it before using it)",
                    node.span,
                    name=node.key,
                )
            hint = ""
            if re.fullmatch(r"Z\d+", node.key):
                hint = (
                    " (it looks like one of Autolev's AutoZ intermediates, whose "
                    "numbering al2py cannot reproduce: use the expression it "
                    "stands for)"
                )
            raise UndeclaredError(
                f"undeclared name '{node.name}'{hint}", node.span, name=node.key
            )
        self.resolved[node.nid] = sym
        if node.primes and sym.kind not in TIME_DECLS | {Decl.SCALAR, Decl.SPEEDS}:
            raise SemanticError(
                f"'{node.name}' is a {sym.kind} and has no time derivative", node.span
            )
        return sym

    # --------------------------------------------------------------- kinds

    def kind_of(self, expr: ir.Expr) -> Kind:
        """The kind of value ``expr`` produces, checking names on the way."""
        method = getattr(self, "_kind_" + type(expr).__name__, None)
        if method is None:
            raise SemanticError(
                f"{type(expr).__name__.lower()} is not allowed here", expr.span
            )
        kind = method(expr)
        self.kinds[expr.nid] = kind
        return kind

    def _kind_Number(self, expr: ir.Number) -> Kind:
        return Kind.SCALAR

    def _kind_String(self, expr: ir.String) -> Kind:
        raise SemanticError("a string is not a value here", expr.span)

    def _kind_Name(self, expr: ir.Name) -> Kind:
        if expr.key == "0>":
            return Kind.VECTOR
        if expr.key == "1>>":
            return Kind.DYADIC
        form = self.form(expr)
        if form is not None:
            if expr.primes:
                raise SemanticError(f"'{expr.name}' has no time derivative", expr.span)
            self.resolved[expr.nid] = form
            return form.row.value_kind
        return self.lookup(expr).value_kind

    def _check_indices(self, indices: tuple[ir.Expr, ...]) -> None:
        for i in indices:
            self._expect_scalar(i)
            value = int_literal(i)
            if value is not None and value < 1:
                raise SemanticError("matrix indices start at 1", i.span)

    def _kind_Element(self, expr: ir.Element) -> Kind:
        self._check_indices(expr.indices)
        if len(expr.indices) > 2:
            raise SemanticError("a matrix element takes one or two indices", expr.span)
        form = self.form(expr.base)
        if (
            form is not None
            and form.kind is Form.DCM
            and self.table.get(expr.base.name) is None
        ):
            # ``N_A[1,1]``: an element of the direction-cosine matrix.
            self.resolved[expr.base.nid] = form
            return Kind.SCALAR
        sym = self.lookup(expr.base)
        self._check_bounds(sym, expr)
        if sym.kind not in (Decl.MATRIX, Decl.SPEEDS):
            raise SemanticError(f"'{expr.base.name}' is not a matrix", expr.base.span)
        if len(expr.indices) > 2:
            raise SemanticError("a matrix element takes one or two indices", expr.span)
        for i in expr.indices:
            self._expect_scalar(i)
        return Kind.VECTOR if sym.of_vectors else Kind.SCALAR

    @staticmethod
    def _grow_shape(sym: Symbol, idx: list[int | None]) -> None:
        """Track a known shape through ``M[i] = ...`` / ``M[i,j] = ...``."""
        if sym.shape is None or None in idx:
            sym.shape = None
        elif len(idx) == 1:
            rows, cols = sym.shape
            sym.shape = (max(rows, idx[0]), cols) if cols == 1 else None
        else:
            sym.shape = (max(sym.shape[0], idx[0]), max(sym.shape[1], idx[1]))

    def _check_bounds(self, sym: Symbol, expr: ir.Element) -> None:
        idx = [int_literal(i) for i in expr.indices]
        if sym.shape is None or None in idx:
            return
        rows, cols = sym.shape
        if len(idx) == 1:
            size = rows * cols if 1 in (rows, cols) else None
            if size is not None and idx[0] > size:
                raise SemanticError(
                    f"{expr.base.name} has {size} elements; there is no element {idx[0]}",
                    expr.span,
                )
        elif idx[0] > rows or idx[1] > cols:
            raise SemanticError(
                f"{expr.base.name} is {rows}x{cols}; there is no element "
                f"[{idx[0]},{idx[1]}]",
                expr.span,
            )

    def _operand(self, expr: ir.Expr) -> Kind:
        """The kind of an operand of arithmetic (see ``_as_value``)."""
        if (
            isinstance(expr, ir.Name)
            and self.form(expr) is None
            and self.table.quantity(expr.name) is not None
            and self.table.physical(expr.name) is not None
        ):
            self._as_value.add(expr.nid)
        return self.kind_of(expr)

    def _kind_UnaryOp(self, expr: ir.UnaryOp) -> Kind:
        return self._operand(expr.operand)

    def _check_matrix_sum(self, expr: ir.BinOp) -> None:
        """Matrices of statically known, different sizes (issue 12)."""
        message = matrix_sum_error(
            expr,
            lambda n: getattr(self.table.get(n.name), "shape", None),
            lambda e: self._operand(e) is Kind.SCALAR,
        )
        if message:
            raise SemanticError(message, expr.span)

    def _kind_BinOp(self, expr: ir.BinOp) -> Kind:
        left, right = self._operand(expr.left), self._operand(expr.right)
        if expr.op in "+-":
            if (
                Kind.SCALAR in (left, right)
                and left != right
                and Kind.UNKNOWN not in (left, right)
            ):
                raise SemanticError(
                    f"cannot {'add' if expr.op == '+' else 'subtract'} a {right.value} "
                    f"and a {left.value}",
                    expr.span,
                )
            if left is Kind.MATRIX and right is Kind.MATRIX:
                self._check_matrix_sum(expr)
            return left if left is not Kind.UNKNOWN else right
        if expr.op == "^":
            if right is not Kind.SCALAR:
                raise SemanticError("an exponent must be a scalar", expr.right.span)
            return left
        if expr.op == "/":
            if right not in (Kind.SCALAR, Kind.UNKNOWN):
                raise SemanticError(
                    f"cannot divide by a {right.value}", expr.right.span
                )
            return left
        if left is Kind.MATRIX or right is Kind.MATRIX:
            if Kind.VECTOR in (left, right) or Kind.DYADIC in (left, right):
                raise SemanticError("cannot multiply a matrix and a vector", expr.span)
            return Kind.MATRIX
        if left is Kind.VECTOR and right is Kind.VECTOR:
            return Kind.DYADIC
        if {left, right} & {Kind.FRAME, Kind.POINT, Kind.WORD}:
            raise SemanticError("frames and points are not values", expr.span)
        if left is Kind.SCALAR:
            return right
        if right is Kind.SCALAR or right is Kind.UNKNOWN:
            return left
        raise SemanticError(
            f"cannot multiply a {left.value} by a {right.value} (use Dot or Cross)",
            expr.span,
        )

    def _kind_MatrixLit(self, expr: ir.MatrixLit) -> Kind:
        kinds = [[self.kind_of(e) for e in row] for row in expr.rows]
        if any(k is Kind.VECTOR for row in kinds for k in row):
            # ``VCA = [COEF(V_CA_N>, U2), COEF(V_CA_N>, U3)]``: a matrix of
            # vectors, whose elements are vectors (``DOT(VCA[1], N1>)``).
            return self._vector_matrix(expr)
        if all(k is Kind.SCALAR for row in kinds for k in row):
            widths = {len(row) for row in expr.rows}
            if len(widths) > 1:
                raise SemanticError(
                    "the rows of this matrix have different lengths "
                    f"({', '.join(str(len(r)) for r in expr.rows)})",
                    expr.span,
                )
        for row, row_kinds in zip(expr.rows, kinds, strict=True):
            for entry, k in zip(row, row_kinds, strict=True):
                if k not in (Kind.SCALAR, Kind.MATRIX, Kind.UNKNOWN):
                    raise SemanticError(
                        f"a matrix entry cannot be a {k.value}", entry.span
                    )
        return Kind.MATRIX

    def _kind_Call(self, expr: ir.Call) -> Kind:
        b = BUILTINS.get(expr.key)
        if b is None:
            raise SemanticError(unknown_call_message(expr.func), expr.span)
        if b.style is Style.PENDING:
            raise UnsupportedError(
                f"'{expr.func}' ({b.issue}) is not supported yet", expr.span
            )
        message = b.arity_error(len(expr.args))
        if message:
            raise SemanticError(message, expr.span)
        if b.statement:
            raise SemanticError(
                f"{expr.func} is a stand-alone command; use it alone on a line",
                expr.span,
            )
        return b.result(self.arg_kinds(expr))

    def arg_kinds(self, call: ir.Call) -> list[Kind]:
        """Check a call's arguments; option words (``ANGULAR``) are WORD."""
        b = BUILTINS[call.key]
        if b.name in _NEEDS_NEWTONIAN and not self._has_newtonian():
            raise SemanticError(
                f"{call.func} needs a Newtonian frame: declare one first", call.span
            )
        kinds = []
        for i, a in enumerate(call.args):
            if b.name == "UNITS":
                kinds.append(Kind.WORD)  # unit expressions, read as text
                continue
            if (
                b.name == "SOLVE"
                and i == 0
                and isinstance(a, ir.Name)
                and a.key in SOLVE_OPTIONS
                and self.table.get(a.key) is None
            ):
                kinds.append(Kind.WORD)
                continue
            if i in b.words:
                if not isinstance(a, ir.Name) or a.primes or a.rank:
                    raise SemanticError(f"{b.name} expects an option word here", a.span)
                kinds.append(Kind.WORD)
            elif b.name in ("FORCE", "TORQUE") and i == 0:
                self._mark_objects(a)
                kinds.append(self._load_target(a, b.name))
            elif b.name == "CONSTRAIN":
                kinds.append(self._constraint(a))
            elif b.name == "DOT" and isinstance(a, ir.MatrixLit):
                kinds.append(self._vector_matrix(a))
            else:
                if b.takes_object(i):
                    self._mark_objects(a)
                kinds.append(self._arg_kind(a))
        self._check_arg_kinds(call, b, kinds)
        return kinds

    def _mark_objects(self, arg: ir.Expr) -> None:
        """Names here mean objects (``Simprot(B, C, 2, q)`` with constant ``c``)."""
        names = [arg.left, arg.right] if isinstance(arg, ir.BinOp) else [arg]
        for n in names:
            if isinstance(n, ir.Name) and not n.primes and not n.rank:
                if self.table.physical(n.name) is not None:
                    self._as_object.add(n.nid)

    def _vector_matrix(self, expr: ir.MatrixLit) -> Kind:
        """A matrix literal as an argument of Dot: all scalars, or all vectors."""
        kinds = [self.kind_of(e) for row in expr.rows for e in row]
        if any(k is Kind.VECTOR for k in kinds):
            widths = {len(row) for row in expr.rows}
            for row in expr.rows:
                for e in row:
                    if self.kind_of(e) not in (Kind.VECTOR, Kind.UNKNOWN):
                        raise SemanticError(
                            "a matrix of vectors holds only vectors", e.span
                        )
            if len(widths) > 1:
                raise SemanticError(
                    "the rows of this matrix have different lengths", expr.span
                )
            self.vector_matrices.add(expr.nid)
            return Kind.MATRIX
        return self.kind_of(expr)

    def _check_arg_kinds(self, call: ir.Call, b: Builtin, kinds: list[Kind]) -> None:
        ok = (Kind.UNKNOWN,)
        if b.name in _MATRIX_FIRST and kinds and kinds[0] not in (Kind.MATRIX, *ok):
            raise SemanticError(
                f"{call.func} needs a matrix, not a {kinds[0].value}", call.args[0].span
            )
        if b.name in _OBJECT_ARGS:
            for a, k in zip(call.args, kinds, strict=True):
                if k not in (Kind.FRAME, Kind.POINT, *ok):
                    raise SemanticError(
                        f"{call.func} takes bodies, particles or points, not a {k.value}",
                        a.span,
                    )

    def _has_newtonian(self) -> bool:
        return any(s.kind == Decl.NEWTONIAN for s in self.table)

    def _load_target(self, arg: ir.Expr, command: str) -> Kind:
        want = Kind.POINT if command == "FORCE" else Kind.FRAME
        names = (
            [arg.left, arg.right]
            if isinstance(arg, ir.BinOp) and arg.op == "/"
            else [arg]
        )
        for n in names:
            if not isinstance(n, ir.Name) or self.kind_of(n) is not want:
                noun = "point or particle" if want is Kind.POINT else "frame or body"
                raise SemanticError(f"{command.title()} needs a {noun} here", n.span)
        return want

    def _constraint(self, arg: ir.Expr) -> Kind:
        if not (
            isinstance(arg, ir.Element)
            and arg.base.key in ("DEPENDENT", "AUXILIARY")
            and all(isinstance(i, ir.Name) for i in arg.indices)
        ):
            raise SemanticError(
                "Constrain takes DEPENDENT[speeds] or AUXILIARY[speeds]", arg.span
            )
        sym = self.table.quantity(arg.base.key)
        if sym is None or sym.kind != Decl.MATRIX:
            raise SemanticError(f"{arg.base.name} has not been assigned", arg.span)
        for i in arg.indices:
            assert isinstance(i, ir.Name)
            if self.lookup(i).kind != "variable":
                raise SemanticError(f"'{i.name}' is not a generalized speed", i.span)
        return Kind.MATRIX

    def _arg_kind(self, arg: ir.Expr) -> Kind:
        if isinstance(arg, ir.Range):
            self._expect_scalar(arg.lo)
            self._expect_scalar(arg.hi)
            return Kind.SCALAR
        if isinstance(arg, ir.Equation):
            self.kind_of(arg.lhs)
            rhs = arg.rhs
            if isinstance(rhs, ir.Range):
                self._expect_scalar(rhs.lo)
                self._expect_scalar(rhs.hi)
            else:
                self.kind_of(rhs)
            return Kind.SCALAR
        if isinstance(arg, ir.IndexedNames):
            for n in arg.names:
                self.lookup(n)
            return Kind.MATRIX
        return self.kind_of(arg)

    def _expect_scalar(self, expr: ir.Expr) -> None:
        k = self.kind_of(expr)
        if k not in (Kind.SCALAR, Kind.UNKNOWN):
            raise SemanticError(f"expected a scalar here, not a {k.value}", expr.span)

    def _kind_Range(self, expr: ir.Range) -> Kind:
        raise SemanticError(
            "a range 'a:b' is only allowed as a function argument", expr.span
        )

    def _kind_Equation(self, expr: ir.Equation) -> Kind:
        raise SemanticError(
            "'name=value' is only allowed as a function argument", expr.span
        )

    def _kind_IndexedNames(self, expr: ir.IndexedNames) -> Kind:
        raise SemanticError(
            "'name{...}' is only allowed in declarations and arguments", expr.span
        )

    # ---------------------------------------------------------- the walk

    def run(
        self,
        stmts: tuple[ir.Stmt, ...],
        poisoned: set[str] | frozenset[str] = frozenset(),
    ) -> Facts:
        """Analyse every statement in order; raise all errors at once.

        A statement with an error is skipped and the walk goes on, so one run
        reports every problem of a file.  Names a failed statement (or a line
        with a syntax error: ``poisoned``) would have defined are not reported
        again as undeclared.
        """
        self._poisoned = {n.upper() for n in poisoned}
        self._stmts = stmts
        self._fragment_told = False
        for stmt in stmts:
            if not self._run_one(stmt):
                break
        if self.errors:
            raise ErrorList(self.errors)
        return Facts(self)

    def _run_one(self, stmt: ir.Stmt) -> bool:
        """Analyse one statement (and a macro's body); False after Exit."""
        try:
            facts = self.enter(stmt)
        except UndeclaredError as exc:
            if exc.name not in self._poisoned:
                self.errors.append(self._explain_undeclared(exc))
            self._poison(stmt)
            return True
        except AutolevError as exc:
            self.errors.append(exc)
            self._poison(stmt)
            return True
        except RecursionError:
            self.errors.append(
                SemanticError(
                    "this statement is too deeply nested to convert", stmt.span
                )
            )
            return True
        self.stmt_facts[stmt.nid] = facts
        if isinstance(stmt, ir.MacroCall):
            for inner in stmt.body:
                if not self._run_one(inner):
                    return False
        return not facts.stop

    def _explain_undeclared(self, exc: UndeclaredError) -> UndeclaredError:
        """Add what the file itself says about an undeclared name, if anything.

        Real scripts that stop here are mostly work in progress: the line that
        defined the name was commented out (``%U5P=TAYLOR(...)``), or the file
        is the tail of a longer script and declares nothing itself.
        """
        if exc.span is None or not re.fullmatch(
            r"undeclared name '[^']*'", exc.message
        ):
            return exc
        stmts = list(flatten(self._stmts))
        hint = ""
        line = _commented_definition(stmts, exc.name, exc.span)
        if line is not None:
            hint = f" (line {line} assigns it, but that line is a comment)"
        elif not self._fragment_told and not any(
            isinstance(s, ir.Declaration) for s in stmts
        ):
            self._fragment_told = True  # once per file, at the first name
            hint = (
                " (this file declares nothing: it looks like a fragment to run "
                "after the script that declares its names)"
            )
        if not hint:
            return exc
        return UndeclaredError(exc.message + hint, exc.span, name=exc.name)

    def _poison(self, stmt: ir.Stmt) -> None:
        for e in stmt_exprs(stmt):
            for node in walk_expr(e):
                if isinstance(node, ir.Name):
                    self._poisoned.add(node.key)
                elif isinstance(node, ir.IndexedNames):
                    self._poisoned.update(n.upper() for n in node.expand())

    # ---------------------------------------------------------- statements

    def enter(self, stmt: ir.Stmt) -> StmtFacts:
        """Check ``stmt``, update the symbol table, return generator facts."""
        method = getattr(self, "_enter_" + type(stmt).__name__)
        return method(stmt)

    def _facts(self, **kw: object) -> StmtFacts:
        return StmtFacts(degrees=self.degrees, **kw)  # type: ignore[arg-type]

    def _enter_Comment(self, stmt: ir.Comment) -> StmtFacts:
        return self._facts()

    def _enter_MacroCall(self, stmt: ir.MacroCall) -> StmtFacts:
        return self._facts()

    def _enter_Setting(self, stmt: ir.Setting) -> StmtFacts:
        from al2py_runtime.names.settings import SETTINGS, check_setting

        message = check_setting(stmt.name, stmt.value)
        if message is not None:
            error = SemanticError if stmt.name in SETTINGS else UnsupportedError
            raise error(message, stmt.span)
        value = (stmt.value or "").upper()
        if stmt.name == "DEGREES":
            self.degrees = value == "ON"
        return self._facts()

    def _enter_Declaration(self, stmt: ir.Declaration) -> StmtFacts:
        if stmt.keyword == "MASS":
            return self._enter_mass(stmt)
        if stmt.keyword == "INERTIA":
            return self._enter_inertia(stmt)
        kind = Decl.of_keyword(stmt.keyword)
        if kind is None:
            raise UnsupportedError(
                f"declaration {stmt.keyword} is not supported", stmt.span
            )
        for item in stmt.items:
            names, primes = self._decl_target(item, kind)
            if item.values and kind not in (Decl.CONSTANT, Decl.SPECIFIED):
                raise SemanticError(
                    f"{stmt.keyword.title()} cannot assign values", item.values[0].span
                )
            if len(item.values) > 1:
                raise SemanticError("one value per declared name", item.values[1].span)
            if kind in OBJECT_DECLS and primes:
                raise SemanticError("objects have no derivatives", item.target.span)
            for name in names:
                self._declare(name, kind, item, primes)
            if item.values:
                self.kind_of(item.values[0])
        return self._facts()

    def _declare(
        self, name: str, kind: Decl, item: ir.DeclItem, primes: int = 0
    ) -> Symbol:
        key = name.upper()
        old = self.table.quantity(key)
        if old is not None and old.kind == Decl.TIME:
            raise SemanticError(f"'{name}' is reserved (time)", item.target.span)
        if kind in OBJECT_DECLS and "_" in name:
            raise SemanticError(
                f"object names cannot contain underscores ('{name}')", item.target.span
            )
        order = primes if kind in TIME_DECLS else 0
        sym = self.table.define(
            key,
            kind,
            self._ident(name, kind),
            span=item.target.span,
            order=order,
            sign=item.sign,
            has_rhs=bool(item.values),
        )
        if kind in FRAME_DECLS:
            point = Decl.PARTICLE if kind is Decl.BODY else Decl.POINT
            self.table.define(
                key + "O", point, self._ident(name + "o", point), span=item.target.span
            )
        return sym

    def _new_constant(self, node: ir.Expr, sign: str | None) -> Symbol | None:
        """Declare ``node`` as a constant if it is a fresh bare name."""
        if not isinstance(node, ir.Name) or node.primes or node.rank:
            return None
        if self.table.get(node.name) is not None:
            return None
        item = ir.DeclItem(node.span, node, sign=sign)
        sym = self._declare(node.name, "constant", item)
        self.resolved[node.nid] = sym
        return sym

    def _enter_mass(self, stmt: ir.Declaration) -> StmtFacts:
        new: list[Symbol] = []
        for item in stmt.items:
            target = item.target
            if not isinstance(target, ir.Name) or not self.is_body(target.name):
                raise SemanticError("Mass takes body or particle names", target.span)
            if not item.values or len(item.values) > 2:
                raise SemanticError(
                    "write Mass A=mA or Mass A=mA=value", item.target.span
                )
            first = item.values[0]
            sym = self._new_constant(first, "+")
            if sym is not None:
                new.append(sym)
            elif len(item.values) == 2:
                raise SemanticError(
                    "in Mass A=m=value, m must be a new name", first.span
                )
            else:
                self._expect_scalar(first)
            if len(item.values) == 2:
                self._expect_scalar(item.values[1])
                new[-1].has_rhs = True
        return self._facts(new_constants=tuple(new))

    def _enter_inertia(self, stmt: ir.Declaration) -> StmtFacts:
        body, *rest = stmt.items
        target = body.target
        if isinstance(target, ir.Call):  # Inertia C(B), ...: in B's basis
            basis = target.args[0]
            if not isinstance(basis, ir.Name) or not self.is_frame(basis.name):
                raise SemanticError(
                    f"Inertia {target.func}(...) names the frame whose basis the "
                    "inertia scalars are given in",
                    basis.span,
                )
            self._as_object.add(basis.nid)
            target = ir.Name(target.span, target.func)
        if not isinstance(target, ir.Name) or not self.is_body(target.name):
            raise SemanticError("Inertia starts with a body name", body.target.span)
        if (
            rest
            and isinstance(rest[0].target, ir.Name)
            and self.is_point(rest[0].target.name)
        ):
            rest = rest[1:]
        if not 1 <= len(rest) <= 6:
            raise SemanticError("Inertia takes 1 to 6 inertia scalars", stmt.span)
        new: list[Symbol] = []
        for k, item in enumerate(rest):
            sym = self._new_constant(item.target, "+" if k < 3 else None)
            if sym is not None:
                new.append(sym)
            else:
                self._expect_scalar(item.target)
            if item.values:
                if sym is None:
                    raise SemanticError(
                        "only a new name can be given a value here", item.target.span
                    )
                self._expect_scalar(item.values[0])
                sym.has_rhs = True
        return self._facts(new_constants=tuple(new))

    def _decl_target(
        self, item: ir.DeclItem, kind: Decl
    ) -> tuple[tuple[str, ...], int]:
        target = item.target
        if isinstance(target, ir.Name):
            if target.rank:
                raise SemanticError(
                    f"cannot declare '{target.name}' this way", target.span
                )
            if target.primes and kind not in TIME_DECLS:
                raise SemanticError(
                    f"only variables and specified quantities take primes ('{target.autolev}')",
                    target.span,
                )
            return (target.name,), target.primes
        if isinstance(target, ir.IndexedNames):
            return target.expand(), target.primes
        raise SemanticError("expected a name to declare", target.span)

    def _enter_Assign(self, stmt: ir.Assign) -> StmtFacts:
        value_kind = self.kind_of(stmt.value)
        target = stmt.target
        if stmt.op not in ("=", ":="):
            self.kind_of(target)
            if stmt.op in ("*=", "/=", "^=") and value_kind is not Kind.SCALAR:
                raise SemanticError(f"{stmt.op} needs a scalar", stmt.value.span)
        if isinstance(target, ir.Element):
            self._check_indices(target.indices)
            if len(target.indices) > 2:
                raise SemanticError(
                    "a matrix element takes one or two indices", target.span
                )
            if value_kind not in (Kind.SCALAR, Kind.UNKNOWN):
                raise SemanticError(
                    f"a matrix element must be a scalar, not a {value_kind.value}",
                    stmt.value.span,
                )
            sym = self._assign_name(target.base, Decl.MATRIX)
            self._grow_shape(sym, [int_literal(i) for i in target.indices])
            return self._facts(target=sym)
        form = self.form(target)
        if form is not None:
            want = form.row.value_kind
            if form.kind is Form.UNIT or target.primes:
                raise SemanticError(f"'{target.name}' cannot be assigned", target.span)
            if value_kind not in (want, Kind.UNKNOWN) and not (
                want is Kind.VECTOR
                and value_kind is Kind.SCALAR
                and _is_zero(stmt.value)
            ):
                raise SemanticError(
                    f"{target.name} must be a {want.value}, not a {value_kind.value}",
                    stmt.value.span,
                )
            return self._facts(form=form)
        if target.rank:
            if target.key in ("0>", "1>>"):
                raise SemanticError(f"'{target.name}' is reserved", target.span)
            want = {1: Kind.VECTOR, 2: Kind.DYADIC}.get(target.rank, Kind.POLYADIC)
            if value_kind not in (want, Kind.UNKNOWN):
                raise SemanticError(
                    f"{target.name} must be a {want.value}, not a {value_kind.value}",
                    stmt.value.span,
                )
            sym = self._assign_name(target, want.value)
            return self._facts(target=sym)
        if value_kind in (Kind.VECTOR, Kind.DYADIC, Kind.FRAME, Kind.POINT, Kind.WORD):
            raise SemanticError(
                f"{target.name} names a scalar or matrix; a {value_kind.value} "
                f"needs a name ending in '>'",
                stmt.value.span,
            )
        if target.primes:
            sym = self.table.quantity(target.name)
            if sym is None:
                raise SemanticError(f"undeclared name '{target.name}'", target.span)
            if sym.kind not in TIME_DECLS:
                raise SemanticError(
                    f"'{target.name}' is a {sym.kind}; only variables have derivatives",
                    target.span,
                )
            if value_kind not in (Kind.SCALAR, Kind.UNKNOWN):
                raise SemanticError(
                    f"{target.autolev} must be a scalar", stmt.value.span
                )
            sym.order = max(sym.order, target.primes)
            sym.has_rhs = True
            return self._facts(target=sym)
        kind = Decl.MATRIX if value_kind is Kind.MATRIX else Decl.SCALAR
        sym = self._assign_name(target, kind)
        sym.shape = _literal_shape(stmt.value) if stmt.op in ("=", ":=") else None
        sym.of_vectors = (
            isinstance(stmt.value, ir.MatrixLit)
            and stmt.value.nid in self.vector_matrices
        )
        return self._facts(target=sym)

    def _assign_name(self, target: ir.Name, kind: Decl) -> Symbol:
        sym = self.table.quantity(target.name)
        if (
            sym is not None
            and sym.kind in (Decl.TIME, Decl.IMAGINARY, Decl.SPEEDS)
            or target.key == "PI"
        ):
            raise SemanticError(
                f"'{target.name}' is reserved and cannot be assigned", target.span
            )
        if sym is not None and sym.kind in QUANTITY_DECLS:
            if kind == Decl.MATRIX:
                raise SemanticError(
                    f"'{target.name}' is a declared {sym.kind}, not a matrix",
                    target.span,
                )
            sym.has_rhs = True
            return sym
        if sym is None or sym.kind != kind:
            sym = self.table.define(
                target.key,
                kind,
                self._ident(target.name, kind),
                span=target.span,
                has_rhs=True,
            )
        return sym

    def _enter_ExprStmt(self, stmt: ir.ExprStmt) -> StmtFacts:
        expr = stmt.expr
        if isinstance(expr, ir.Name) and not expr.primes and expr.key in STOP_WORDS:
            return self._facts(stop=True)
        if (
            isinstance(expr, ir.Name)
            and expr.key in INTERACTIVE_WORDS
            and self.table.get(expr.key) is None
        ):
            return self._facts(noop=INTERACTIVE_WORDS[expr.key])
        if isinstance(expr, ir.Call):
            b = BUILTINS.get(expr.key)
            if b is not None and b.statement:
                return self._enter_command(expr, b)
            if b is not None and b.dual and expr.args:
                first = expr.args[0]
                self.kind_of(expr)
                if (
                    isinstance(first, ir.Name)
                    and not first.primes
                    and not self.form(first)
                ):
                    sym = self.lookup(first)
                    if sym.kind not in (Decl.TIME, Decl.IMAGINARY) and sym.key != "PI":
                        return self._facts(target=sym)
                return self._facts()
            if b is not None and b.name == "EIG" and len(expr.args) >= 2:
                self.kind_of(expr.args[0])
                for out in expr.args[1:]:
                    if not isinstance(out, ir.Name) or out.primes or out.rank:
                        raise SemanticError(
                            "Eig(A, values, vectors) needs names", out.span
                        )
                    self._assign_name(out, Decl.MATRIX)
                return self._facts()
            if b is not None and b.name == "SOLVE":
                self.kind_of(expr)
                return self._facts()
        self.kind_of(expr)
        return self._facts()

    #: Argument kinds of stand-alone kinematics commands.
    _COMMAND_ARGS = {
        "SIMPROT": (Kind.FRAME, Kind.FRAME, Kind.UNKNOWN, Kind.SCALAR),
        "V2PTS": (Kind.FRAME, Kind.FRAME, Kind.POINT, Kind.POINT),
        "A2PTS": (Kind.FRAME, Kind.FRAME, Kind.POINT, Kind.POINT),
        "V1PT": (Kind.FRAME, Kind.FRAME, Kind.POINT, Kind.POINT),
        "A1PT": (Kind.FRAME, Kind.FRAME, Kind.POINT, Kind.POINT),
        "GRAVITY": (Kind.VECTOR,),
    }

    def _enter_command(self, call: ir.Call, b: Builtin) -> StmtFacts:
        message = b.arity_error(len(call.args))
        if b.name == "ANGVEL" and len(call.args) == 3:
            message = (
                "Angvel takes 2 arguments (Angvel(A, B) shows W_B_A>) or at least 4"
            )
        if message:
            raise SemanticError(message, call.span)
        kinds = self.arg_kinds(call)
        want = self._COMMAND_ARGS.get(b.name)
        if b.name == "AUTOTAYLOR":
            want = None
            if any(not isinstance(a, ir.Equation | ir.Name) for a in call.args[1:]):
                raise SemanticError(
                    "AutoTaylor(0:2, X=0, ...) expands about name=value", call.span
                )
        if b.name in ("DIRCOS", "ANGVEL", "KINDIFFS"):
            want = (Kind.FRAME, Kind.FRAME, Kind.WORD) + (Kind.SCALAR,) * (
                len(kinds) - 3
            )
        if b.name in ("FORCE", "TORQUE"):
            want = (kinds[0], Kind.VECTOR)
        if b.name == "KANE":
            want = (Kind.SCALAR,) * len(kinds)
            for a in call.args:
                if not isinstance(a, ir.Name) or a.primes:
                    raise SemanticError(
                        "Kane takes names of force measure numbers", a.span
                    )
        if want is not None:
            for a, got, need in zip(call.args, kinds, want, strict=False):
                if got is not need and Kind.UNKNOWN not in (got, need):
                    raise SemanticError(
                        f"{call.func} expects a {need.value} here, not a {got.value}",
                        a.span,
                    )
        if b.name == "GRAVITY":
            for a in call.args[1:]:
                if not isinstance(a, ir.Name) or not self.is_body(a.name):
                    raise SemanticError(
                        "Gravity(v>, A, B, ...) names bodies or particles after the vector",
                        a.span,
                    )
        if b.name == "ANIMATE":
            self._check_animate(call)
        if b.name == "SIMPROT":
            axis = call.args[2]
            value = int_literal(axis)
            bad = value is None or abs(value) not in (1, 2, 3)
            if kinds[2] is not Kind.VECTOR and bad:
                raise SemanticError(
                    "Simprot's axis is 1, 2, 3, -1, -2, -3 or a vector", axis.span
                )
        return self._facts()

    def _check_animate(self, call: ir.Call) -> None:
        """``Animate(N, O, A, B, ...)``: the Newtonian frame, a point, then
        the frames and bodies to animate (names)."""
        first, point, *shown = call.args
        checks = [
            (first, self._is_newtonian, "a Newtonian frame"),
            (point, self.is_point, "a point"),
        ] + [(a, self.is_frame, "a frame or body") for a in shown]
        for arg, test, what in checks:
            plain = isinstance(arg, ir.Name) and not arg.primes and not arg.rank
            if not plain or not test(arg.name):
                raise SemanticError(
                    f"Animate(N, O, A, ...) expects {what} here", arg.span
                )

    def _is_newtonian(self, name: str) -> bool:
        sym = self.table.physical(name)
        return sym is not None and sym.kind == Decl.NEWTONIAN

    def _enter_FileCommand(self, stmt: ir.FileCommand) -> StmtFacts:
        if stmt.command != "SAVE":
            raise UnsupportedError(f"{stmt.command} is not supported", stmt.span)
        return self._facts()

    def _enter_UnitSystemStmt(self, stmt: ir.UnitSystemStmt) -> StmtFacts:
        return self._facts()

    def _enter_ListCommand(self, stmt: ir.ListCommand) -> StmtFacts:
        if stmt.name == "ENCODE":
            for item in stmt.items:
                if not isinstance(item, ir.Name) or item.rank:
                    raise SemanticError(
                        "Encode lists scalars and matrices by name", item.span
                    )
                kind = self.kind_of(item)
                if kind not in (Kind.SCALAR, Kind.MATRIX, Kind.UNKNOWN):
                    raise SemanticError(
                        f"Encode computes scalars and matrices, not a {kind.value}",
                        item.span,
                    )
            return self._facts()
        if stmt.name == "UNITS":
            from al2py_runtime.jobs.units import UnitError, parse_unit

            for item in stmt.items:
                if not isinstance(item, ir.Equation) or not isinstance(
                    item.lhs, ir.Name
                ):
                    raise SemanticError("Units takes name=unit pairs", item.span)
                name = item.lhs
                if name.key not in INTEGRATION_PARAMETERS | {"T"}:
                    sym = self.lookup(name)
                    # ``Units POP1X=M``: also the assigned scalars (and
                    # matrices) a script outputs.
                    if sym.kind not in _VALUE_KINDS:
                        raise SemanticError(
                            "Units gives units of constants, variables and"
                            f" assigned quantities, not a {sym.kind}",
                            name.span,
                        )
                try:
                    parse_unit(_unit_word(item.rhs))
                except UnitError as exc:
                    raise SemanticError(str(exc), item.rhs.span) from None
            return self._facts()
        raise UnsupportedError(f"'{stmt.name}' is not a supported command", stmt.span)

    def _enter_InputStmt(self, stmt: ir.InputStmt) -> StmtFacts:
        for item in stmt.items:
            names = self._input_names(item.name)
            for n in names:
                if n.key in INTEGRATION_PARAMETERS and not n.primes:
                    continue
                sym = self.lookup(n)
                if sym.kind not in QUANTITY_DECLS:
                    raise SemanticError(
                        f"Input takes constants and variables, not a {sym.kind}", n.span
                    )
            for n in _free_names(item.value):
                # ``Input E4 = COS(QQ1/2)``: a value computed from other Inputs.
                if n.key in INTEGRATION_PARAMETERS or n.primes:
                    raise SemanticError(
                        "an Input value is a number or an expression of constants",
                        n.span,
                    )
                sym = self.lookup(n, Kind.SCALAR)
                # ``QQ1 = PI/4`` then ``Input E4 = COS(QQ1/2)``, ``Input P =
                # V[1]``: the script's own values, evaluated when the CODE job
                # runs, with the Input values known then.
                if sym.kind not in _VALUE_KINDS:
                    raise SemanticError(
                        f"an Input value may use other Inputs and assigned "
                        f"values, not the {sym.kind} '{n.name}'",
                        n.span,
                    )
            self._expect_scalar(item.value)
        return self._facts()

    def _input_names(self, node: ir.Expr) -> list[ir.Name]:
        return input_names(node)

    def _enter_OutputStmt(self, stmt: ir.OutputStmt) -> StmtFacts:
        for item in stmt.items:
            # ``Output A, G>``: a matrix gives one column per element, a
            # vector its measure numbers in the Newtonian frame.
            kind = self.kind_of(item.expr)
            if kind is Kind.VECTOR and not self._has_newtonian():
                raise SemanticError(
                    "an Output vector gives its measure numbers in the Newtonian "
                    "frame: declare one, or output DOT(V>, A1>), ...",
                    item.expr.span,
                )
            if kind not in (Kind.MATRIX, Kind.VECTOR):
                self._expect_scalar(item.expr)
        return self._facts()

    def _enter_CodeStmt(self, stmt: ir.CodeStmt) -> StmtFacts:
        if stmt.option not in CODE_OPTIONS:
            raise SemanticError(
                f"CODE option must be one of {', '.join(sorted(CODE_OPTIONS))}",
                stmt.span,
            )
        if stmt.args:
            if stmt.option not in ("NONLINEAR", "ALGEBRAIC"):
                raise SemanticError(
                    f"CODE {stmt.option.title()}() takes no arguments", stmt.span
                )
            eqs, *unknowns = stmt.args
            if self.kind_of(eqs) is not Kind.MATRIX:
                raise SemanticError(
                    "the first CODE argument is a matrix of equations", eqs.span
                )
            if not unknowns:
                raise SemanticError("name the unknowns after the equations", eqs.span)
            for u in unknowns:
                for n in self._input_names(u):
                    if self.lookup(n).kind not in QUANTITY_DECLS:
                        raise SemanticError(f"'{n.name}' cannot be an unknown", n.span)
        elif stmt.option in ("NONLINEAR",):
            raise SemanticError(
                "CODE Nonlinear(equations, unknowns...) needs arguments", stmt.span
            )
        if stmt.sweep is not None:
            self.lookup(stmt.sweep.name)
            for e in (stmt.sweep.start, stmt.sweep.stop, stmt.sweep.step):
                self._expect_scalar(e)
        for word in stmt.options:
            if word not in CODE_FILE_OPTIONS:
                raise UnsupportedError(
                    f"CODE option {word} is not supported (known: "
                    f"{', '.join(sorted(CODE_FILE_OPTIONS))})",
                    stmt.span,
                )
        if stmt.filename is not None:
            ext = (
                stmt.filename.rsplit(".", 1)[-1].lower() if "." in stmt.filename else ""
            )
            if ext not in ("c", "m", "for", "f"):
                raise SemanticError(
                    "the CODE file name ends in .c, .m, .for or .f", stmt.span
                )
        return self._facts()


def input_names(node: ir.Expr) -> list[ir.Name]:
    """The names an Input item (or a CODE unknown) stands for: ``X``, ``U{3}``."""
    if isinstance(node, ir.Name):
        return [node]
    if isinstance(node, ir.IndexedNames):
        return list(node.names)
    raise SemanticError("Input assigns names: Input X=1, Y=2 deg", node.span)


def _free_names(expr: ir.Expr) -> list[ir.Name]:
    return [
        n for n in walk_expr(expr) if isinstance(n, ir.Name) and n.key not in ("PI",)
    ]


def _unit_word(expr: ir.Expr) -> str:
    return expr.name if isinstance(expr, ir.Name) else getattr(expr, "text", "")


def _literal_shape(expr: ir.Expr) -> tuple[int, int] | None:
    """The shape of a matrix literal of scalars, else None (unknown)."""
    if not isinstance(expr, ir.MatrixLit):
        return None
    if any(isinstance(e, ir.MatrixLit) for row in expr.rows for e in row):
        return None
    return len(expr.rows), len(expr.rows[0])


def int_literal(expr: ir.Expr) -> int | None:
    if isinstance(expr, ir.UnaryOp):
        inner = int_literal(expr.operand)
        return None if inner is None else (-inner if expr.op == "-" else inner)
    if isinstance(expr, ir.Number) and expr.is_integer:
        return int(expr.text)
    return None


def _is_zero(expr: ir.Expr) -> bool:
    return isinstance(expr, ir.Number) and expr.value == 0


def _parts(name: str) -> set[str]:
    return {p for p in name.upper().rstrip(">").split("_") if p}


def _kind_from_spelling(name: str) -> Decl:
    rank = len(name) - len(name.rstrip(">"))
    return {0: Decl.SCALAR, 1: Decl.VECTOR, 2: Decl.DYADIC}.get(rank, Decl.POLYADIC)


_COMMENTED_ASSIGNMENT = re.compile(r"\s*%*\s*([A-Za-z]\w*)'*\s*(?::=|[-+*/^]?=)")


def _commented_definition(stmts: list[ir.Stmt], key: str, use: ir.Span) -> int | None:
    """Line of the last comment before ``use`` that reads like ``KEY = ...``."""
    found = None
    for s in stmts:
        if not isinstance(s, ir.Comment) or s.span.file != use.file:
            continue
        if s.span.line >= use.line:
            break
        m = _COMMENTED_ASSIGNMENT.match(s.text)
        if m and m.group(1).upper() == key:
            found = s.span.line
    return found
