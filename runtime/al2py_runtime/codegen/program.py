"""One description of the program a ``CODE`` job writes (Dynamics and ODE
here, Algebraic and Nonlinear in :mod:`.static`).

:func:`describe` turns a job into a :class:`Program`: the ``.in`` entries
(constants, initial values, integration parameters, in the Input's units
with their factors to internal units), the equations as assignments to
named targets (the script's names; AutoZ intermediates ``z1, z2, ...`` and
common subexpressions ``x1, x2, ...`` named) and the output tables.  The C,
Fortran and MATLAB printers (:mod:`.c`, :mod:`.fortran`, :mod:`.octave`)
only spell it in their language.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import sympy as sp
from sympy.core import basic as _sympy_basic
from sympy.core.basic import _args_sortkey
from sympy.functions.elementary.exponential import ExpBase

from ..jobs import backends
from ..jobs.run import (
    Column,
    Deferred,
    Job,
    dynamics_equations,
    initial_state,
    input_values,
    integration_parameters,
    label_of,
    missing_value_rule,
    normalize_name,
    output_factors,
)
from ..jobs.tables import table_heading
from ..version import __version__
from ..walks import allow_deep_recursion

__all__ = ["Assign", "Entry", "OutputTable", "Program", "describe", "one_based_target"]

#: ``.in`` descriptions of the integration parameters, in file order.
INTEGRATION_LINES = (
    ("Initial Time", "TINITIAL"),
    ("Final Time", "TFINAL"),
    ("Integration Step", "INTEGSTP"),
    ("Print-Integer", "PRINTINT"),
    ("Absolute Error", "ABSERR"),
    ("Relative Error", "RELERR"),
)

#: Names the printers use for their own variables (never a script name).
_INTERNAL = {
    # the printers' own variables and routines
    "t",
    "y",
    "p",
    "dy",
    "ud",
    "mm",
    "out",
    "ierr",
    "code",
    "eqns",
    "outputs",
    "kutta",
    "main",
    "al_solve",
    "al_f",
    # functions the printed equations call
    "abs",
    "max",
    "min",
    "sqrt",
    "exp",
    "log",
    "sin",
    "cos",
    "tan",
    "asin",
    "acos",
    "atan",
    "atan2",
    "sinh",
    "cosh",
    "tanh",
    "pi",
    "floor",
    "ceil",
    "pow",
    "fabs",
    "sign",
    "dsign",
    "copysign",
    "mod",
    "rem",
    "fix",
    "round",
    "trunc",
    "nint",
    "aint",
    "anint",
    "dble",
    "real",
    "isfinite",
    "isnan",
    "log10",
    "erf",
    "gamma",
    "heaviside",
    "merge",
    # C, Fortran and MATLAB words
    "double",
    "int",
    "char",
    "float",
    "long",
    "short",
    "void",
    "const",
    "static",
    "return",
    "if",
    "else",
    "for",
    "while",
    "do",
    "end",
    "function",
    "global",
    "switch",
    "case",
    "break",
    "continue",
    "default",
    "goto",
    "sizeof",
    "struct",
    "union",
    "enum",
    "register",
    "auto",
    "extern",
    "signed",
    "unsigned",
    "volatile",
    "inline",
    "restrict",
    "typedef",
    "program",
    "subroutine",
    "module",
    "use",
    "implicit",
    "none",
    "intent",
    "in",
    "inout",
    "call",
    "dimension",
    "parameter",
    "stop",
    "format",
    "open",
    "close",
    "read",
    "write",
    "print",
    "data",
    "common",
    "entry",
    "result",
    "contains",
    "logical",
    "integer",
    "precision",
    "complex",
    "then",
    "endif",
    "enddo",
    "true",
    "false",
    "ans",
    "disp",
    "error",
    "zeros",
    "ones",
    "size",
    "numel",
    "nargin",
    "nargout",
    "varargin",
    "varargout",
    "try",
    "catch",
    "otherwise",
    "endfunction",
    "unwind_protect",
    "printf",
    "fprintf",
}


@dataclass
class Entry:
    """One line of the ``.in`` file and one Input of the program."""

    group: str  # "Constant", "Initial Value", "Initial Time", ...
    name: str  # the script's name (``Q1'``)
    ident: str  # its identifier in the program (``Q1p``)
    unit: str | None
    value: float  # in ``unit``
    factor: float  # ``unit`` -> internal units
    key: str = ""  # its NAME=VALUE name when not ``name`` (a range's PHI_STEP)

    @property
    def setting(self) -> str:
        return (self.key or self.name).upper()


@dataclass
class Assign:
    """``target = expr``: ``target`` is ``("tmp", name)``, ``("m", i, j)``,
    ``("f", i)``, ``("dy", i)``, ``("ud", i, name)`` (unpack the solved
    acceleration ``i`` as ``name``) or ``("out", k)``."""

    target: tuple
    expr: Any
    #: a ``("tmp", name)`` target's symbol, when the program has it (the
    #: printers assign to it rather than form it again)
    symbol: Any = field(default=None, compare=False, repr=False)


@dataclass
class OutputTable:
    number: int
    header: str  # the file's first lines, as Result.write writes them
    columns: int
    width: int
    factors: list[float]
    written: bool  # False for Encode's quantities (no file)


@dataclass
class Program:
    job: Job
    stem: str
    source: str
    version: str
    nosubs: bool
    constants: list[Entry]
    initials: list[Entry]
    integration: list[Entry]
    nu: int  # accelerations solved from M ud = f
    eqns: list[Assign]  # M, f and dy (with the solve between, see solve_at)
    solve_at: int  # eqns[:solve_at] give M, f; the solve; then eqns[solve_at:]
    outputs: list[Assign]  # needs the solved ud (unpacked by ("ud", ...))
    tables: list[OutputTable]
    digits: int
    time: sp.Symbol = field(default_factory=lambda: sp.Symbol("T", real=True))
    #: DYNAMICS, ODE, ALGEBRAIC (solve M ud = f for the unknowns ud) or
    #: NONLINEAR (Newton's method on the unknowns y: dy = F(y), M = dF/dy,
    #: ud = -F, so the solve leaves the Newton step in ud)
    #: what the program says on standard error before it runs: the values
    #: nobody gave that it takes as 0 (``jobs.run.missing_value_rule``)
    notes: list[str] = field(default_factory=list)
    kind: str = "DYNAMICS"
    #: Algebraic ``[PHI deg=0,360,1]``: start, final value, step of the
    #: last constant (which the .in file then leaves out of the constants)
    ranges: list[Entry] = field(default_factory=list)
    t0: float = 0.0  # the time of a Nonlinear/Algebraic job (TINITIAL)
    labels: list[str] = field(default_factory=list)  # the equations' names
    unknowns: list[str] = field(default_factory=list)  # the script's names
    #: the free symbols of this program's expressions, remembered
    #: (:func:`..jobs.backends.free_symbols_of`'s memo): the program's own
    free: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def task(self) -> str:
        """What the driver does, in one sentence (headers and .in files)."""
        stem = self.stem
        if self.kind == "ALGEBRAIC":
            what = "Evaluates the outputs"
            if self.unknowns:
                what = "Solves the linear equations for " + ", ".join(self.unknowns)
            rows = (
                f"a row for each {self.ranges[0].name} from Range Start to"
                " Range Final in steps of Range Step"
                if self.ranges
                else "one row"
            )
            return f"{what} and writes {stem}.1, ...: {rows}."
        if self.kind == "NONLINEAR":
            return (
                "Solves the equations for "
                + ", ".join(e.name for e in self.initials)
                + " by Newton's method from the guesses (until each |residual| <="
                " ABSERR, times the largest at the guesses when that is over 1,"
                " and each step <= ABSERR + RELERR*|value|; at most 100"
                f" iterations) and writes {stem}.1, ...: one row."
            )
        return (
            "Integrates with Kutta-Merson (ABSERR, RELERR, steps of INTEGSTP)"
            f" and writes {stem}.1, ... every PRINTINT steps."
        )

    @property
    def eqns_doc(self) -> list[str]:
        """What ``eqns`` computes (comment lines, any language)."""
        if self.kind == "NONLINEAR":
            return [
                "The residuals dy = F(y) of the equations at the unknowns y with",
                "the constants p, and Newton's step ud solved from J ud = -F",
                "(J = dF/dy).  Code 0, 1 when J is singular, 2 when not finite.",
            ]
        if self.kind == "ALGEBRAIC":
            return [
                "The unknowns ud solved from the linear equations M ud = f with",
                "the constants p.  Code 0, 1 when M is singular, 2 when not finite.",
            ]
        return [
            "The derivatives dy of the states y at time T with the constants p,",
            "and the accelerations ud solved from M ud = f.  Code 0, 1 when M",
            "is singular, 2 when a derivative is not finite.",
        ]

    @property
    def inputs(self) -> list[Entry]:
        """The constants the ``.in`` file lists (all but a range's)."""
        return self.constants[:-1] if self.ranges else self.constants

    @property
    def groups(self) -> list[list[Entry]]:
        """The ``.in`` file's groups (empty ones left out)."""
        every = (self.inputs, self.initials, self.ranges, self.integration)
        return [g for g in every if g]

    @property
    def entries(self) -> list[Entry]:
        return [e for g in self.groups for e in g]

    @property
    def ny(self) -> int:
        return len(self.initials)

    @property
    def np(self) -> int:
        return len(self.constants)

    @property
    def nout(self) -> int:
        return sum(t.columns for t in self.tables)

    def params_used(self, block: Iterable[Assign]) -> list[tuple[int, Entry]]:
        return _used(self.constants, block, self.free)

    def states_used(self, block: Iterable[Assign]) -> list[tuple[int, Entry]]:
        return _used(self.initials, block, self.free)

    def entries_used(
        self, block: Iterable[Assign]
    ) -> tuple[list[tuple[int, Entry]], list[tuple[int, Entry]]]:
        """(:meth:`params_used`, :meth:`states_used`) of ``block``, its
        statements' names gathered once for both."""
        names = _names_used(block, self.free)
        return _entries_named(self.constants, names), _entries_named(
            self.initials, names
        )

    def free_symbols(self, expr: Any) -> frozenset:
        """``expr.free_symbols`` of one of this program's expressions,
        remembered (:attr:`free`)."""
        return backends.free_symbols_of(expr, self.free)


def one_based_target(a: Assign) -> str:
    """The Fortran/MATLAB spelling of ``a``'s target (``mm(1, 2)``, ``x3``)."""
    kind = a.target[0]
    if kind == "tmp":
        return a.target[1]
    if kind == "m":
        return f"mm({a.target[1] + 1}, {a.target[2] + 1})"
    if kind == "f":
        return f"ud({a.target[1] + 1})"
    return f"{kind}({a.target[1] + 1})"


def _used(
    entries: list[Entry], block: Iterable[Assign], free: dict
) -> list[tuple[int, Entry]]:
    return _entries_named(entries, _names_used(block, free))


def _names_used(block: Iterable[Assign], free: dict) -> set[str]:
    """The names of the free symbols of ``block``'s statements."""
    symbols: set[Any] = set()
    for a in block:
        symbols |= backends.free_symbols_of(a.expr, free)
    return {s.name for s in symbols}


def _entries_named(entries: list[Entry], names: set[str]) -> list[tuple[int, Entry]]:
    return [(i, e) for i, e in enumerate(entries) if e.ident in names]


def identifier(name: str, taken: set[str]) -> str:
    """A C/Fortran/MATLAB identifier for an Autolev name, unique among
    ``taken`` (compared without case, as Fortran does): ``Q1'`` -> ``Q1p``."""
    base = name.replace("'", "p")
    base = re.sub(r"[^A-Za-z0-9_]", "_", base)
    if not base or not base[0].isalpha():
        base = "v" + base
    base = base.rstrip("_") or "v"
    out = base
    k = 1
    while out.lower() in taken or out.lower() in _INTERNAL:
        out = f"{base}_{k}"
        k += 1
    taken.add(out.lower())
    return out


class Entries:
    """Makes :class:`Entry` lines in the Inputs' units, with unique names."""

    def __init__(self, job: Job, vals: Any) -> None:
        self.job, self.vals, self.us = job, vals, job.unit_system
        self.taken: set[str] = {"t"}

    def unit_of(self, name: str) -> str | None:
        return self.vals.units.get(normalize_name(name))

    def entry(self, group: str, name: str, internal: float) -> Entry:
        unit = self.unit_of(name)
        f = self.us.to_internal(unit)
        value = internal / f
        given = self.job.inputs.get(normalize_name(name))
        if given is not None and isinstance(given.value, int | float):
            if math.isclose(float(given.value) * f, internal, rel_tol=1e-12):
                value = float(given.value)  # 60 deg, not 59.99999999999999
        return Entry(group, name, identifier(name, self.taken), unit, value, f)

    def integration(self, keys: Iterable[str]) -> list[Entry]:
        """The integration parameters ``keys`` (run()'s defaults if absent)."""
        vals, us = self.vals, self.us
        ip = integration_parameters(vals)
        out = []
        for group, key in INTEGRATION_LINES:
            if key not in keys:
                continue
            unit = self.unit_of(key) if key in vals.values else None
            if key in ("TINITIAL", "TFINAL", "INTEGSTP") and unit is None:
                unit = us.time_unit
            f = us.to_internal(self.unit_of(key)) if key in vals.values else 1.0
            out.append(Entry(group, key, key, unit, ip[key] / f, f))
        return out


def describe(
    job: Job, source: str | None = None, nosubs: bool | None = None
) -> Program:
    """The program of a Dynamics/ODE ``job`` with its Input values
    (:func:`.static.describe_static` describes Algebraic/Nonlinear ones)."""
    free_memo: dict = {}  # the program's free symbols (Program.free)
    vals, keep = input_values(job, {})
    c = dynamics_equations(job, frozenset(keep), deferred=True)
    y0 = initial_state(job, c, vals)
    spec = c.spec
    made = Entries(job, vals)
    taken = made.taken
    rename: dict[Any, Any] = {spec.time: sp.Symbol("T", real=True)}
    # The .in order of Autolev's programs: names sorted without case, within
    # each group (docs/semantics.md); a Specified quantity with neither an
    # equation nor an Input is 0 in the program, not read.
    constants = []
    unspecified: list[sp.Symbol] = []
    notes: list[str] = []  # one for each
    for obj, d in sorted(
        zip(c.params, spec.params, strict=True),
        key=lambda od: in_order(label_of(od[0], job.names)),
    ):
        name = label_of(obj, job.names)
        if job.entries.get(name, ("", None))[0] == "specified" and (
            job.inputs.get(normalize_name(name)) is None
        ):
            s = sp.Symbol(identifier(name, taken), real=True)
            unspecified.append(s)
            notes.append(missing_value_rule(job, name)[1])
            rename[d] = s
            continue
        e = made.entry("Constant", name, vals.param(obj))
        constants.append(e)
        rename[d] = sp.Symbol(e.ident, real=True)
    initials = []
    states = sorted(range(len(spec.states)), key=lambda i: in_order(c.state_names[i]))
    for i in states:
        e = made.entry("Initial Value", c.state_names[i], y0[i])
        initials.append(e)
        rename[spec.states[i]] = sp.Symbol(e.ident, real=True)
    integration = made.integration([key for _group, key in INTEGRATION_LINES])
    accel_names = [identifier(label_of(o, job.names), taken) for o in c.ud_objs]
    for d, name in zip(spec.accels, accel_names, strict=True):
        rename[d] = sp.Symbol(name, real=True)
    memo: dict = {}  # renamed parts, shared: ``rename`` only grows (see below)
    inter = named_intermediates(spec.intermediates, rename, taken, memo)

    def sub(e: Any) -> Any:
        return renamed_evaluated(sp.sympify(e), rename, memo)

    n = len(spec.accels)
    accel_syms = {rename[d] for d in spec.accels}
    derivs = [sub(spec.derivs[i]) for i in states]
    # a derivative that reads an acceleration, itself or through the
    # intermediates it needs, is computed after the accelerations are solved
    # (only those intermediates asked: the outputs' may be most of them)
    late_ids = set(
        backends.reading(
            backends.needed(inter, derivs, free_memo), derivs, accel_syms, free_memo
        )
    )
    x_names = iter_names("x", taken)
    first = [sub(e) for e in [*spec.mass, *spec.forcing]]
    first_targets = [("m", i // n, i % n) for i in range(n * n)]
    first_targets += [("f", i) for i in range(n)]
    free = [i for i in range(len(derivs)) if i not in late_ids]
    first += [derivs[i] for i in free]
    first_targets += [("dy", i) for i in free]
    eqns, defined = assignments(first, first_targets, inter, x_names, set(), free_memo)
    eqns = _zeros(unspecified, eqns, free_memo) + eqns
    solve_at = len(eqns)
    unpack = [Assign(("ud", k, name), 0) for k, name in enumerate(accel_names)]
    late = [derivs[i] for i in sorted(late_ids)]
    if late:
        eqns += unpacked(unpack, late, inter, free_memo)
        more, _ = assignments(
            late,
            [("dy", i) for i in sorted(late_ids)],
            inter,
            x_names,
            defined,
            free_memo,
        )
        eqns += more
    flat = [sub(e) for row in spec.outputs for e in row]
    outputs = output_block(flat, unpack, inter, x_names, free_memo)
    outputs = _zeros(unspecified, outputs, free_memo) + outputs
    return new_program(
        job,
        source,
        nosubs,
        (constants, initials, integration),
        (n, eqns, solve_at, outputs),
        output_tables(job, vals),
        notes=notes,
        free=free_memo,
    )


def new_program(
    job: Job,
    source: str | None,
    nosubs: bool | None,
    entries: tuple[list[Entry], list[Entry], list[Entry]],
    equations: tuple[int, list[Assign], int, list[Assign]],
    tables: list[OutputTable],
    **more: Any,
) -> Program:
    """A :class:`Program` of ``job`` (NOSUBS as its CODE statement says
    unless ``nosubs`` is given): ``entries`` are (constants, initials,
    integration), ``equations`` (nu, eqns, solve_at, outputs)."""
    if nosubs is None:
        nosubs = "NOSUBS" in getattr(job, "options", ())
    source = source or job.source
    head = (job, job.stem, source, __version__, nosubs)
    return Program(*head, *entries, *equations, tables, job.digits, **more)


def named_intermediates(
    intermediates: Iterable[tuple[Any, Any]],
    rename: dict[Any, Any],
    taken: set[str],
    memo: dict | None = None,
) -> list[tuple[Any, Any]]:
    """The AutoZ intermediates as ``z1, z2, ...`` (``rename`` learns them).

    One ``memo`` of renamed parts serves every definition (and, given, the
    caller's later renaming with the same ``rename``): a part's answer
    depends on the part and the objects it holds, and each definition holds
    only intermediates defined before it, so the ones ``rename`` learns
    later are in no part already answered."""
    z_names = iter_names("z", taken)
    memo = {} if memo is None else memo
    inter = []
    #: a Deferred definition's objects -> their names, and the objects the
    #: intermediates' dummies stand for, per table of names (keyed by the
    #: table's time dummy: each job's table has its own)
    straight: dict[Any, tuple[dict, dict]] = {}
    for d, body in intermediates:
        s = sp.Symbol(next(z_names), real=True)
        rename[d] = s
        if isinstance(body, Deferred):
            # straight from the book's definition to the program's names:
            # its objects -> their dummies -> rename, in one walk (its parts
            # keyed apart from the dummies' in ``memo``: other objects)
            rule, objects = straight.get(body.time, (None, None))
            if rule is None:
                rule = body.renaming(rename)
                objects = {v: k for k, v in body.names.items()}
                straight[body.time] = (rule, objects)
            assert objects is not None
            inter.append((s, renamed_evaluated(body.body, rule, memo)))
            if d in objects:
                rule[objects[d]] = s
            continue
        for rule, objects in straight.values():
            if d in objects:
                rule[objects[d]] = s
        inter.append((s, renamed_evaluated(sp.sympify(body), rename, memo)))
    return inter


def renamed_evaluated(expr: Any, rule: dict[Any, Any], memo: dict | None = None) -> Any:
    """``expr.xreplace(rule)`` (the same expression, node for node) for a
    ``rule`` that renames objects to distinct symbols.

    ``xreplace`` rebuilds every sum and product that holds a renamed object
    with sympy's evaluation (``Mul.flatten``, ``Add.flatten``), which is
    most of the cost of writing a program's intermediates.  For a sum or
    product whose terms or factors evaluation keeps as they are (distinct
    bases or terms, at most one number, no nested sum or product, numeric
    powers that evaluate to themselves: :func:`_kept_args`) evaluation only
    sorts them, so they are sorted here with sympy's key; anything else
    is rebuilt by sympy as ``xreplace`` does.  ``memo``: as
    :func:`..walks.xreplace`'s (calls whose rules agree on the objects of
    every part it holds); it also keeps one object for each part formed
    (equal parts formed from different ones, say a definition's as the book
    gives it and an output's made numeric, are one object: printing and
    ``cse`` compare them at once).

    The walk is :func:`..walks.xreplace`'s (a part in ``rule`` replaced,
    an intermediate none of whose parts is in ``rule`` kept whole, any
    other part rebuilt from its arguments when one of them changed), with
    the rebuilding written into it: a program's intermediates are
    thousands of short definitions, each walked once."""
    if not isinstance(expr, sp.Basic) or not rule:
        return expr
    allow_deep_recursion()
    memo = {} if memo is None else memo
    same = memo.get(_SAME)
    if same is None:
        same = memo[_SAME] = {}
        memo[_KEYS] = CompareKeys()
    return _renamed(expr, rule, memo, same)[0]


def _renamed(e: Any, rule: dict, memo: dict, same: dict) -> tuple[Any, bool]:
    """``e`` renamed by ``rule`` and whether it changed
    (:func:`renamed_evaluated`)."""
    found = rule.get(e, _ABSENT)
    if found is not _ABSENT:
        return found, True
    if e.is_Atom:
        return e, False
    return _renamed_part(e, rule, memo, same)


def _renamed_part(e: Any, rule: dict, memo: dict, same: dict) -> tuple[Any, bool]:
    """:func:`_renamed` of ``e``, a part not in ``rule`` and not an atom
    (its arguments are asked here, once each)."""
    known = memo.get(e)
    if known is not None:
        return known
    if e.is_Function and hasattr(e, "walk_parts"):
        # an intermediate: none of its parts is replaced
        if rule.keys().isdisjoint(e.walk_parts()):
            memo[e] = out = (e, False)
            return out
    args = e.args
    paired = True  # (whether _sorted_only may find two names)
    if type(e) is _MUL and len(args) < 4:
        # (most products: of two renamed objects, after -1 or not; as
        # below, without the general walk of the arguments)
        x, y = rule.get(args[-2]), rule.get(args[-1])
        if type(x) is _NAME and type(y) is _NAME:
            keys = memo[_KEYS]
            named = _two_names_keyed(
                [x, y] if len(args) == 2 else [args[0], x, y], keys
            )
            if named is not None:
                kept, content = named
                part = _MUL._from_args(kept, True)
                keys.learn(part, content)
                memo[e] = out = (same.setdefault(part, part), True)
                return out
            # (the arguments below are these, the first when it is kept)
            paired = False
    new = None
    for i, a in enumerate(args):
        if not isinstance(a, sp.Basic):  # pragma: no cover - sympy's are Basic
            continue
        # a renamed object or an atom (most arguments) here, as the call
        # below would answer
        b = rule.get(a, _ABSENT)
        if b is _ABSENT:
            if a.is_Atom:
                continue
            b, changed = _renamed_part(a, rule, memo, same)
            if not changed:
                continue
        if new is None:
            new = list(args)
        new[i] = b
    if new is None:
        out = (e, False)
    else:
        if not paired and len(args) == 3 and new[0] is not args[0]:
            paired = True  # (a first factor renamed: asked again)
        part = _sorted_only(e, new, memo[_KEYS], paired)
        out = (same.setdefault(part, part), True)
    memo[e] = out
    return out


#: the key in :func:`renamed_evaluated`'s memo of the parts formed
_SAME = ("renamed_evaluated", "formed parts")
#: the key in :func:`renamed_evaluated`'s memo of its :class:`CompareKeys`
_KEYS = ("renamed_evaluated", "compare keys")
#: what ``rule.get`` gives for a part not in the rule
_ABSENT = object()


def _sorted_only(
    expr: Any, args: list[Any], keys: CompareKeys, paired: bool = True
) -> Any:
    """``expr.func(*args)``, a sum or product that evaluation would only
    sort formed from ``args`` sorted (:func:`renamed_evaluated`; ``keys``:
    the program's; ``paired`` False: the caller found :func:`_two_names`
    gives None for ``args``)."""
    cls = type(expr)
    if cls is sp.Mul and paired:
        # (most products: of two names; their key learned for the sums
        # that hold them)
        named = _two_names_keyed(args, keys)
        if named is not None:
            kept, content = named
            part = cls._from_args(kept, True)
            keys.learn(part, content)
            return part
    if cls is sp.Mul or cls is sp.Add:
        kept = _kept_args(cls is sp.Mul, args, keys, paired=False)
        if kept is not None:
            return cls._from_args(kept, True)
    return expr.func(*args)


def _kept_args(
    mul: bool, args: list[Any], order: CompareKeys | None = None, paired: bool = True
) -> list[Any] | None:
    """The arguments of ``Mul(*args)`` (``mul``) or ``Add(*args)`` when
    sympy's evaluation only sorts ``args``, else None (``order``: sympy's
    order of the arguments, :class:`CompareKeys`).

    The conditions follow ``Mul.flatten`` and ``Add.flatten``: numbers
    combine (and 1 or 0 goes), a product's equal bases and a sum's equal
    terms (the same part beside the number) combine, nested products and
    sums are flattened, a number times a sum is distributed, powers of
    numbers combine, ``exp`` factors combine (their base is ``E``), a
    product's powers (and a sum's term ``c*s`` of one factor) are
    evaluated again.  With none of these, the result is ``args`` sorted by
    sympy's key, the number first.

    A name (most factors) and a sum's product (most terms) are asked only
    what these conditions ask of them, first; a product of two names (or
    of -1 and two names: most of a program's products) at once (``paired``
    False: the caller found :func:`_two_names` gives None)."""
    order = CompareKeys() if order is None else order
    if mul and paired:
        pair = _two_names(args, order)
        if pair is not None:
            return pair
    number = None
    rest = []
    keys: list[Any] = []
    for a in args:
        kind = type(a)
        if kind is _NAME:
            if not a.is_commutative:
                return None
            key: Any = a if mul else (a,)
        elif kind is _MUL and not mul:
            if not a.is_commutative:
                return None
            key = a.args
            if key[0].is_Number:
                key = key[1:]
                if len(key) == 1 and not _plain_factor(key[0], True):
                    return None  # c*s: Mul(c, s) is evaluated again
        elif a.is_Number:
            if number is not None:
                return None
            if a is not _MINUS_ONE and (not a.is_finite or a == 0 or (mul and a == 1)):
                return None
            number = a
            continue
        else:
            if not a.is_commutative or not _plain_factor(a, mul):
                return None
            if mul:
                key = a.args[0] if a.is_Pow else a
            elif a.is_Add:
                return None
            else:
                key = (a,)
        keys.append(key)
        rest.append(a)
    if len(keys) > 1 and len(set(keys)) != len(keys):
        return None  # equal bases or terms combine
    if mul and number is not None and len(rest) == 1 and rest[0].is_Add:
        return None  # 2*(x + y) is distributed
    if len(rest) > 1:
        _sort_canonically(rest, order)
    if number is not None:
        rest.insert(0, number)
    return rest


def _two_names(args: list[Any], keys: CompareKeys) -> list[Any] | None:
    """:func:`_kept_args` of a product's arguments that are two names of
    different spellings (so not equal) that commute, after -1 or not;
    else None (:func:`_kept_args` decides); ``keys``: the program's
    :class:`CompareKeys`."""
    named = _two_names_keyed(args, keys)
    return None if named is None else named[0]


def _two_names_keyed(
    args: list[Any], keys: CompareKeys
) -> tuple[list[Any], tuple | None] | None:
    """:func:`_two_names` and the keys of its answer's arguments, in order
    (the product's content, :meth:`CompareKeys.learn`; None when -1 has no
    key)."""
    if len(args) == 2:
        first, a, b = None, args[0], args[1]
    elif len(args) == 3 and args[0] is _MINUS_ONE:
        first, a, b = args
    else:
        return None
    if type(a) is not _NAME or type(b) is not _NAME or a.name == b.name:
        return None
    if not (a.is_commutative and b.is_commutative):
        return None
    # ``Basic.compare`` of two names of one class: the lengths of their
    # ``_hashable_content()`` (the name, then the assumptions), then the
    # names, which differ; their keys (each name's formed once) say it
    known = keys.parts
    key_a = known.get(a) or keys.key(a)
    key_b = known.get(b) or keys.key(b)
    if key_a > key_b:  # type: ignore[operator]
        a, b = b, a
        key_a, key_b = key_b, key_a
    if first is None:
        return [a, b], (key_a, key_b)
    sign = keys.sign
    if sign is None:
        sign = keys.sign = keys.key(first)
    return [first, a, b], None if sign is None else (sign, key_a, key_b)


_NAME = sp.Symbol
_MUL = sp.Mul
_MINUS_ONE = sp.S.NegativeOne


def _first(pair: tuple) -> Any:
    return pair[0]


def _sort_canonically(parts: list[Any], keys: CompareKeys) -> None:
    """Sort ``parts`` (two or more) in place by sympy's ``Basic.compare``
    (``_args_sortkey``, the order ``Mul.flatten`` and ``Add.flatten`` give)
    with their :class:`CompareKeys`; by ``compare`` itself when a part has
    no such key."""
    found = []
    known = keys.parts  # (most parts: keyed before; no number is here)
    for a in parts:
        key = known.get(a)
        if key is None:
            key = keys.key(a)
        if key is None:
            parts.sort(key=_args_sortkey)
            return
        found.append(key)
    if len(parts) == 2:
        if found[0] > found[1]:
            parts.reverse()
        return
    # (by the keys alone, stably: as sorting the positions by them)
    parts[:] = [a for _key, a in sorted(zip(found, parts, strict=True), key=_first)]


#: ``_hashable_content`` methods that return the object's arguments (all
#: sympy objects)
_ARGS_CONTENT = (sp.Basic._hashable_content, sp.Expr._hashable_content)
#: ``_hashable_content`` methods that return plain values (strings, numbers
#: and tuples of them), compared as Python compares them
_PLAIN_CONTENT = (
    sp.Symbol._hashable_content,
    sp.Dummy._hashable_content,
    sp.Rational._hashable_content,
    sp.Float._hashable_content,
)


class CompareKeys:
    """Keys whose order is sympy's ``Basic.compare`` (the order of a
    canonical sum's or product's arguments), each part's formed once.

    ``compare`` orders two objects by class (:func:`_class_key`), then by
    the length of their ``_hashable_content()``, then by its items in turn
    (sympy objects by ``compare``, other values as Python orders them).  An
    object's key is ``(class key, length, items)`` with each sympy item's
    own key, which Python's tuples order the same way: ``a``'s key is below
    ``b``'s exactly when ``a.compare(b) < 0``, and equal when it is 0.  One
    instance serves one program (its names and products are keyed again
    and again); a number is remembered with its class (sympy's ``==``
    may hold between numbers of different classes)."""

    __slots__ = ("classes", "numbers", "parts", "sign")

    def __init__(self) -> None:
        self.parts: dict = {}
        self.numbers: dict = {}  # (class, number) -> its key
        self.classes: dict = {}
        #: -1's key (the first argument of most products that have a
        #: number), read without hashing -1 again and again
        self.sign: tuple | None = None

    def learn(self, part: Any, content: tuple | None) -> None:
        """Remember the key of ``part``, a sum or product whose arguments'
        keys are ``content`` (in order; None: not known), as :meth:`key`
        would find it."""
        if content is None:
            return
        cls = type(part)
        head = self.classes.get(cls, _ABSENT)
        if head is _ABSENT:
            self.key(part)  # (the class's first: as key does)
            return
        if head is not None and cls._hashable_content in _ARGS_CONTENT:
            self.parts[part] = (head, len(content), content)

    def key(self, e: Any) -> tuple | None:
        """``e``'s key, or None when ``e`` (or a part of it) is of a class
        whose content this does not know, or that compares in its own way
        (then use ``compare``)."""
        if e.is_Number:
            part: Any = (type(e), e)
            known = self.numbers
        else:
            part = e
            known = self.parts
        found = known.get(part)
        if found is not None:
            return found
        cls = type(e)
        head = self.classes.get(cls, _ABSENT)
        if head is _ABSENT:
            # (a class with a compare of its own, an intermediate's: None)
            own = cls.compare is not sp.Basic.compare
            head = self.classes[cls] = None if own else _class_key(cls)
        if head is None:
            return None
        content_of = cls._hashable_content
        if content_of in _ARGS_CONTENT:
            items = []
            parts = self.parts
            for a in e.args:
                if a is _MINUS_ONE:  # a product's sign: its key kept apart
                    key = self.sign
                    if key is None:
                        key = self.sign = self.key(a)
                        if key is None:
                            return None
                    items.append(key)
                    continue
                key = parts.get(a)  # (most arguments: names keyed before)
                if key is None:
                    if not isinstance(a, sp.Basic):
                        return None
                    key = self.key(a)
                    if key is None:
                        return None
                items.append(key)
            content: tuple = tuple(items)
        elif content_of in _PLAIN_CONTENT:
            content = e._hashable_content()
        else:
            return None
        found = known[part] = (head, len(content), content)
        return found


def _class_key(cls: type) -> tuple[int, str]:
    """The order of ``cls`` in ``Basic.compare`` (sympy's ``_cmp_name``):
    the classes named in ``ordering_of_classes`` in its order, then the
    others by name."""
    order = _sympy_basic.ordering_of_classes
    name = cls.__name__
    if name in order:
        return order.index(name), ""
    return len(order) + 1, name


def _plain_factor(a: Any, mul: bool) -> bool:
    """Whether ``a`` (not a number) is kept as it is by ``Mul.flatten``
    (``mul``) or ``Add.flatten`` among other arguments."""
    if a.is_Symbol or a.is_Add:
        return mul or not a.is_Add
    if a.is_Pow:
        base, e = a.args
        if base.is_Atom and not base.is_Symbol:
            return False  # a power of a number, of E or of I
        if not mul:
            return True
        return (e.is_Number or e.is_Symbol) and sp.Pow(base, e) == a
    if a.is_Mul:
        return not mul
    return isinstance(a, sp.Function) and not isinstance(a, ExpBase)


def unpacked(
    unpack: list[Assign],
    exprs: list[Any],
    inter: list[tuple[Any, Any]],
    memo: dict | None = None,
) -> list[Assign]:
    """The ``("ud", k, name)`` unpackings ``exprs`` use (``memo``: the
    program's free symbols, :attr:`Program.free`)."""
    if not unpack:  # (an Algebraic job without unknowns)
        return []
    free = _free(exprs, inter, memo)
    return [a for a in unpack if sp.Symbol(a.target[2], real=True) in free]


def output_block(
    flat: list[Any],
    unpack: list[Assign],
    inter: list[tuple[Any, Any]],
    names: Any,
    memo: dict | None = None,
) -> list[Assign]:
    """The outputs routine's body: unpackings, intermediates, ``out[k]``
    (``memo``: the program's free symbols, :attr:`Program.free`)."""
    more, _ = assignments(
        flat, [("out", k) for k in range(len(flat))], inter, names, set(), memo
    )
    return unpacked(unpack, flat, inter, memo) + more


def output_tables(
    job: Job, vals: Any, columns: list[list[Column]] | None = None
) -> list[OutputTable]:
    """The tables of the job's Outputs (or ``columns``: one written table
    of those columns, each converted by its unit)."""
    us = job.unit_system
    if columns is None:
        columns = [[Column(i.label, i.unit) for i in o.items] for o in job.outputs]
        factors = output_factors(job, vals)
        written = [not o.encoded for o in job.outputs]
    else:
        factors = [[1.0 / us.to_internal(c.unit) for c in cols] for cols in columns]
        written = [True] * len(columns)
    tables = []
    for number, (cols, fac, w) in enumerate(
        zip(columns, factors, written, strict=True), start=1
    ):
        name = f"{job.stem}.{number}"
        header, width = table_heading(cols, job.digits, name, us.time_unit)
        tables.append(OutputTable(number, header, len(cols), width, fac, w))
    return tables


def in_order(name: str) -> tuple[int, str]:
    """Autolev's order of a ``.in`` group: without case (``c, g, IBxx, lam``;
    ``G1, G10, G2``), derivatives after the names (``q1 .. q9, q1' .. q9'``)."""
    return name.count("'"), name.lower()


def _zeros(names: list[sp.Symbol], block: list[Assign], memo: dict) -> list[Assign]:
    """``NAME = 0`` for the Specified quantities without a value that
    ``block`` uses (Autolev's "Quantities to be specified")."""
    if not names:
        return []
    wanted = set(names)
    used: set[Any] = set()
    for a in block:  # (each statement's names meet the few wanted)
        used |= wanted.intersection(backends.free_symbols_of(a.expr, memo))
    return [Assign(("tmp", s.name), sp.Integer(0), s) for s in names if s in used]


def iter_names(prefix: str, taken: set[str]) -> Any:
    k = 0
    while True:
        k += 1
        name = f"{prefix}{k}"
        low = name.lower()
        if low not in taken and low not in _INTERNAL:
            taken.add(low)
            yield name


def _free(
    exprs: list[Any], inter: list[tuple[Any, Any]], memo: dict | None
) -> set[Any]:
    out: set[Any] = set()
    for e in exprs:
        out |= backends.free_symbols_of(e, memo)
    for _s, body in backends.needed(inter, exprs, memo):
        out |= backends.free_symbols_of(body, memo)
    return out


def assignments(
    exprs: list[Any],
    targets: list[tuple],
    inter: list[tuple[Any, Any]],
    names: Any,
    defined: set[Any],
    memo: dict | None = None,
) -> tuple[list[Assign], set[Any]]:
    """The intermediates ``exprs`` need (those not ``defined`` yet), then
    common subexpressions, then the targets (``memo``: the program's free
    symbols, :attr:`Program.free`)."""
    out = []
    defined = set(defined)
    for s, body in backends.needed(inter, exprs, memo):
        if s not in defined:
            out.append(Assign(("tmp", s.name), body, s))
            defined.add(s)
    if exprs:
        temps, reduced = sp.cse(
            exprs, symbols=(sp.Symbol(x, real=True) for x in names), order="none"
        )
        for s, e in temps:
            out.append(Assign(("tmp", s.name), e, s))
            defined.add(s)
        for target, e in zip(targets, reduced, strict=True):
            out.append(Assign(target, e))
    return out, defined


def finite(x: float) -> float:
    return x if math.isfinite(x) else 0.0
