"""Running the numerical jobs of ``CODE Dynamics/ODE/Nonlinear/Algebraic``.

The records live in :mod:`.records`, the result tables in :mod:`.tables`.

A :class:`Job` is a snapshot taken at the ``CODE`` statement: the equations,
the right-hand sides (RHS) in force, the ``Input`` values, ``Output``
statements, unit system and ``Digits``.  :func:`run_job` turns it into scalar
Python functions (``sympy.lambdify(..., cse=True, modules="math")``, built once
and cached per job) and integrates or solves with SciPy.  Values inside a run
are in internal units (see :mod:`al2py_runtime.jobs.units`); ``Input`` values are
converted in, ``Output`` values are converted out.
"""

from __future__ import annotations

import dataclasses
import math
import os
import re
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import sympy as sp
from sympy.core.function import AppliedUndef

from ..intermediates import autoz
from ..linear import linear_terms
from ..safety import MissingValueWarning
from ..walks import xreplace
from . import backends, budget
from .kutta import KuttaMerson, StepError
from .records import (
    INTEGRATION_DEFAULTS,
    InputValue,
    Job,
    NumericsError,
    OutputItem,
    OutputSpec,
    normalize_name,
)
from .tables import Column, Result, Table, fmt_number
from .units import UnitError

if TYPE_CHECKING:  # numpy is imported where it is used (issue 35)
    import numpy as np

__all__ = [
    "NumericsError",
    "InputValue",
    "OutputItem",
    "OutputSpec",
    "Job",
    "Column",
    "Table",
    "Result",
    "INTEGRATION_DEFAULTS",
    "run_job",
    "ode_function",
    "Motion",
    "evaluate_rows",
    "check_overrides",
    "normalize_name",
    "missing_value_rule",
    "warn_notes",
]

t = sp.Symbol("t")  # replaced below by the workspace's time symbol
try:  # the same object dynamicsymbols use
    from sympy.physics.mechanics import dynamicsymbols

    t = dynamicsymbols._t
except ImportError:  # pragma: no cover
    pass


# ---------------------------------------------------------------- resolving


def _resolve(expr: Any, table: Mapping) -> Any:
    """Substitute right-hand sides from ``table`` until none is left."""
    if not table:
        return expr
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: _resolve(e, table))
    if not isinstance(expr, sp.Basic):
        return sp.sympify(expr)
    for _ in range(200):
        new = expr.xreplace(table)
        if new == expr:
            break
        expr = new
    else:
        raise NumericsError("right-hand sides refer to each other in a cycle")
    if expr.has(sp.Derivative):
        expr = expr.replace(
            lambda e: isinstance(e, sp.Derivative)
            and not isinstance(e.expr, AppliedUndef),
            lambda e: e.doit(),
        )
        if expr.has(sp.Derivative):  # derivatives of names inside may have RHS
            again = expr.xreplace(table)
            if again != expr:
                return _resolve(again, table)
    return expr


def _deriv(obj: Any, k: int) -> Any:
    return sp.Derivative(obj, t, k) if k else obj


def _base(obj: Any) -> tuple[Any, int]:
    if isinstance(obj, sp.Derivative):
        return obj.expr, sum(c for _, c in obj.variable_count)
    return obj, 0


# ---------------------------------------------------------- numeric functions

lambdify_job = backends.lambdify_job  # one lambdify for CODE jobs and backends


@dataclass(frozen=True)
class Deferred:
    """An intermediate's definition ``body`` as the book gives it, not made
    numeric (``_Slots(deferred=True)``): its objects stand for the argument
    dummies ``names`` gives them (shared by every definition of one job,
    complete once the job's expressions are made numeric), the time
    symbol ``t`` for ``time``.  A caller that renames the dummies again
    (:func:`..codegen.program.named_intermediates`) renames ``body`` once,
    straight to its own names."""

    body: Any
    names: Mapping[Any, Any]
    time: Any

    def renaming(self, rename: Mapping[Any, Any]) -> dict[Any, Any]:
        """What ``body``'s objects become when each dummy ``d`` becomes
        ``rename[d]`` (those ``rename`` has)."""
        rule = {obj: rename[d] for obj, d in self.names.items() if d in rename}
        if self.time in rename:
            rule[t] = rename[self.time]
        return rule


class _Slots:
    """Sympy objects -> positional arguments of the numeric functions.

    ``deferred``: the intermediates' definitions that one walk makes
    numeric (:meth:`_definition`) are left :class:`Deferred`."""

    def __init__(self, job: Job, deferred: bool = False) -> None:
        self.job = job
        self.deferred = deferred
        self.time = sp.Dummy("T")
        self.known: dict[Any, sp.Dummy] = {}
        self.params: list[Any] = []  # objects, in argument order
        self.param_dummies: list[sp.Dummy] = []
        self._given: set[Any] = set()  # the objects in params
        self._dummies: set[sp.Dummy] = set()  # the values of known
        #: AutoZ intermediates, ``(dummy, numeric definition)`` in order
        self.intermediates: list[tuple[sp.Dummy, Any]] = []
        #: parts of definitions renamed by :meth:`_definition` (see there)
        self._renamed: dict[Any, Any] = {}
        #: what :meth:`_definition` does with a part of each class met
        self._kinds: dict[type, int] = {}
        #: the known variables of intermediates (:meth:`_variables_known`)
        self._variables: set[Any] = set()
        #: the sets of variables (the book's, :meth:`_variables_known`) all
        #: of whose variables are known
        self._variable_sets: set[frozenset] = set()

    def add(self, objs: Iterable[Any], prefix: str) -> list[sp.Dummy]:
        out = []
        for obj in objs:
            d = sp.Dummy(f"{prefix}{len(self.known)}")
            self.known[obj] = d
            self._dummies.add(d)
            out.append(d)
        return out

    def numeric(self, expr: Any, what: str) -> Any:
        """``expr`` with every object replaced by an argument dummy; new
        constants, specified quantities and unknown derivatives become
        parameters; intermediates become :attr:`intermediates`."""
        expr = sp.sympify(expr)
        zs = expr.atoms(autoz.Intermediate)
        if zs:
            book = next(iter(zs)).book
            expr = book.rebase(expr)
            for z in book.ordered([expr], self.known):
                definition = book.definition(z)
                if self.deferred and self._variables_known(z):
                    # its walk would find only known objects (see there)
                    body = Deferred(definition, self.known, self.time)
                else:
                    body = self._definition(definition, what)
                d = sp.Dummy(f"z{len(self.intermediates)}")
                self.known[z] = d
                self._dummies.add(d)
                self.intermediates.append((d, body))
            expr = expr.xreplace({z: self.known[z] for z in expr.atoms(book.Z)})
        # Derivatives before functions: a function replaced inside a
        # derivative would leave the derivative of an argument.
        for kind in (sp.Derivative, AppliedUndef):
            found = [a for a in expr.atoms(kind) if a not in self.known]
            for obj in sorted(found, key=sp.default_sort_key):
                if isinstance(obj, sp.Derivative):
                    self._derivative_param(obj, what)
                else:
                    self._param(obj)
            expr = expr.xreplace(self.known)
        for sym in sorted(expr.free_symbols, key=sp.default_sort_key):
            if sym in self._dummies or sym is self.time:
                continue
            if sym == t:
                continue
            self._param(sym)
        expr = expr.xreplace(self.known).xreplace({t: self.time})
        if expr.has(sp.Derivative):
            raise NumericsError(f"{self.job.where}: cannot evaluate {what}")
        return expr

    def _variables_known(self, z: Any) -> bool:
        """Whether every object in ``z``'s definition is known: then
        :meth:`_definition`'s walk of a deferred definition would make no
        parameter and take no other path (the intermediates it holds come
        before it, :meth:`~..intermediates.autoz.Intermediates.ordered`).

        An intermediate's arguments after its number are the variables its
        definition depends on (derivatives, functions of time and symbols,
        each outside the others, its intermediates' too: the book's
        ``_walk``), or, taken at other arguments, what stands for them: so
        when each is a known object, and a function of time among them is
        one of symbols (its arguments hold nothing the walk would note),
        the walk meets only known objects (and ``t``, which it leaves)."""
        # (an intermediate at its own variables: their set, one object the
        # book keeps for each, answered once, as most sets serve many)
        book = getattr(z, "book", None)
        varset = None if book is None else book.own_variables(z)
        sets = self._variable_sets
        if varset is not None and varset in sets:
            return True
        known, seen = self.known, self._variables
        for a in z.args[1:]:
            if a in seen:
                continue
            if a not in known:
                return False
            if isinstance(a, AppliedUndef) and not all(x.is_Symbol for x in a.args):
                return False
            seen.add(a)  # known for good (``known`` only grows)
        if varset is not None:
            sets.add(varset)
        return True

    def _definition(self, body: Any, what: str) -> Any:
        """:meth:`numeric` of an intermediate's definition, in one walk.

        Definitions are short, hold only intermediates at their own
        variables, and come in order (those they use are known already), so
        the general path's ten walks per definition (a large model has
        thousands) reduce to one; anything else takes the general path.
        Parameters are made in the general path's order."""
        zs, derivs, funcs, syms = [], [], [], []
        known = self.known
        kinds = self._kinds
        stack = [body]  # plain parts
        inner = []  # parts inside a function's arguments
        while stack:
            e = stack.pop()
            kind = kinds.get(type(e))
            if kind is None:
                kind = kinds[type(e)] = _part_kind(type(e))
            if kind == _WALKED:
                stack.extend(e.args)
            elif kind == _INTERMEDIATE:
                if e not in known:
                    return self.numeric(body, what)
                zs.append(e)
            elif kind == _DERIVATIVE:
                derivs.append(e)
            elif kind == _FUNCTION:
                funcs.append(e)
                inner.extend(e.args)
            elif kind == _SYMBOL:
                syms.append(e)
        while inner:  # a function's arguments: its symbols go with it
            e = inner.pop()
            kind = kinds.get(type(e))
            if kind is None:
                kind = kinds[type(e)] = _part_kind(type(e))
            if kind == _INTERMEDIATE:
                if e not in known:
                    return self.numeric(body, what)
                zs.append(e)
            elif kind == _DERIVATIVE:  # the general path
                return self.numeric(body, what)
            elif kind == _FUNCTION:
                funcs.append(e)
                inner.extend(e.args)
            elif kind == _WALKED:
                inner.extend(e.args)
        if derivs:
            for obj in sorted(
                {d for d in derivs if d not in known}, key=sp.default_sort_key
            ):
                self._derivative_param(obj, what)
        if funcs:
            for obj in sorted(
                {f for f in funcs if f not in known}, key=sp.default_sort_key
            ):
                self._param(obj)
        if syms:
            # the new parameters among the symbols (the known ones, the
            # dummies and T stay, t becomes T), in the general path's order
            fresh = {
                sym
                for sym in syms
                if sym not in known
                and sym not in self._dummies
                and sym is not self.time
            }
            for sym in sorted(fresh, key=sp.default_sort_key):
                if sym != t:
                    self._param(sym)
        # One memo for every definition: each rule maps an object as
        # ``known`` does (or leaves a dummy, T, as it is), and a part that
        # the renaming reaches holds its objects at the same level in any
        # definition (not inside a function or a derivative, which are
        # replaced whole), so its answer is the same under any rule.
        if self.deferred:  # ``known``'s (and T's) rule on its objects
            return Deferred(body, known, self.time)
        rule = {}
        for sym in set(syms):
            if sym in self._dummies or sym is self.time:
                continue
            rule[sym] = self.time if sym == t else known[sym]
        for obj in (*zs, *derivs, *funcs):
            rule[obj] = known[obj]
        return renamed(body, rule, self._renamed)

    def _derivative_param(self, obj: Any, what: str) -> None:
        """A derivative with no right-hand side: a parameter when it is the
        rate of a given function of time, else an error."""
        base, _k = _base(obj)
        state = base in self.known and base not in self._given
        if state or not isinstance(base, AppliedUndef):
            raise NumericsError(
                f"{self.job.where}: cannot evaluate {self.label(obj)}"
                f" in {what}: it has no right-hand side"
            )
        self._param(obj)

    def _param(self, obj: Any) -> None:
        d = sp.Dummy(f"p{len(self.params)}")
        self.known[obj] = d
        self._dummies.add(d)
        self.params.append(obj)
        self.param_dummies.append(d)
        self._given.add(obj)

    def label(self, obj: Any) -> str:
        return label_of(obj, self.job.names)


#: what :meth:`_Slots._definition` does with a part (:func:`_part_kind`)
_WALKED, _INTERMEDIATE, _DERIVATIVE, _FUNCTION, _SYMBOL, _ATOM = range(6)


def _part_kind(cls: type) -> int:
    """What :meth:`_Slots._definition` does with a part of class ``cls``:
    an intermediate, a derivative, a function of time and a symbol are
    noted, another atom left, anything else walked into (the tests
    :meth:`_Slots._definition` made of each part, in their order, asked
    once per class)."""
    if issubclass(cls, autoz.Intermediate):
        return _INTERMEDIATE
    if issubclass(cls, sp.Derivative):
        return _DERIVATIVE
    if issubclass(cls, AppliedUndef):
        return _FUNCTION
    if cls.is_Symbol:
        return _SYMBOL
    if cls.is_Atom:
        return _ATOM
    return _WALKED


def renamed(expr: Any, rule: Mapping[Any, Any], memo: dict | None = None) -> Any:
    """``expr.xreplace(rule)`` for a rule that only renames (objects to
    distinct symbols): sums, products and powers are rebuilt as they are,
    without sympy's evaluation, which is most of the cost of substituting
    into thousands of intermediates and cannot change anything here.
    ``memo`` keeps the answer of each part for calls whose rules agree on
    the objects of every part they reach."""
    return xreplace(expr, rule, memo, rebuild=_renamed_part)


def _renamed_part(expr: Any, args: list[Any], changed: list[int]) -> Any:
    """``expr`` formed from its renamed ``args`` (:func:`renamed`)."""
    cls = type(expr)
    if cls is sp.Add or cls is sp.Mul or cls is sp.Pow:
        return _unevaluated(cls, args)
    return expr.func(*args)


def _unevaluated(cls: type, args: list[Any]) -> Any:
    """``cls(*args, evaluate=False)`` of a sum, product or power: the same
    object, without sympify and sympy's cache (``args`` are sympy objects
    already); sympy's constructor postprocessors run only for arguments of
    a class that has them (matrix expressions, vectors, ...)."""
    if any(type(a) not in _PLAIN for a in args):
        if not all(_plain(type(a)) for a in args):
            return cls(*args, evaluate=False)
    if cls is sp.Pow:
        b, e = args
        obj = sp.Expr.__new__(cls, b, e)
        obj.is_commutative = b.is_commutative and e.is_commutative
        return obj
    return cls._from_args(args)


#: Classes without constructor postprocessors (:func:`_plain`).
_PLAIN: set[type] = set()


def _plain(kind: type) -> bool:
    """Whether sympy's constructor postprocessors leave a sum, product or
    power with an argument of class ``kind`` as it is (no class in its
    ``mro`` registered, as for every scalar expression)."""
    mapping = sp.Basic._constructor_postprocessor_mapping
    if any(c in mapping for c in kind.mro()):
        return False
    _PLAIN.add(kind)
    return True


@dataclass
class NumericEntries:
    """Expressions made numeric (:func:`numeric_entries`): of ``time`` and
    the ``dummies`` standing for ``params`` (the objects, in argument
    order), with ``intermediates`` (``(dummy, definition)``, in order)."""

    time: Any
    params: list[Any]
    dummies: list[Any]
    exprs: list[Any]
    intermediates: list[tuple[Any, Any]]


def numeric_entries(
    job: Job, entries: Iterable[Any], drop: Iterable[Any], what: str
) -> NumericEntries:
    """``entries`` with the job's right-hand sides substituted (but those of
    the objects in ``drop``) as expressions of argument dummies: every
    constant, variable, specified quantity and derivative left is a
    parameter (what ``evaluate()`` compiles; see :mod:`.quantities`)."""
    slots = _Slots(job)
    exprs = [slots.numeric(e, what) for e in resolved_entries(job, entries, drop)]
    return NumericEntries(
        slots.time,
        list(slots.params),
        list(slots.param_dummies),
        exprs,
        list(slots.intermediates),
    )


def resolved_entries(job: Job, entries: Iterable[Any], drop: Iterable[Any]) -> list:
    """``entries`` with the job's right-hand sides substituted until none is
    left (but those of the objects in ``drop``): what :func:`numeric_entries`
    makes numeric, and what a quantity's numpy tape walks
    (:func:`~.quantities.tape_quantity`)."""
    table = _without(job.rhs, drop)
    return [_resolve(sp.sympify(e), table) for e in entries]


def label_of(obj: Any, names: Mapping[Any, str]) -> str:
    base, k = _base(obj)
    name = names.get(base)
    if name is None:
        name = base.func.__name__ if isinstance(base, AppliedUndef) else str(base)
    return name + "'" * k


# -------------------------------------------------------------- input values


def missing_value_rule(
    job: Job, name: str, zero_missing: bool = False
) -> tuple[bool, str]:
    """al2py's one rule for a value that a job, ``ode_function()`` or
    ``evaluate()`` needs and nobody gave (no Input, no override, no
    equation), as Autolev's generated programs have it: ``(True, note)``
    when the value is 0 (the note says so: ``result.notes``, a ``note:``
    line of ``python module.py``, a :class:`MissingValueWarning` in Python),
    ``(False, what)`` when it stops (``what`` names it and its line).

    - a Specified quantity (or its derivative) is 0: an input of the job;
    - a variable is 0: its initial value (tutor7 inputs no U1), and a
      derivative with no equation is an input, as a Specified quantity is
      (the ``.in`` files of Autolev's Algebraic programs list them);
    - a constant stops, unless ``zero_missing`` (then 0, noted);
    - a name the job cannot know stops.

    >>> from al2py_runtime import Workspace
    >>> al = Workspace("m.al")
    >>> _ = al.constants("K", line=2), al.specified("TQ", line=3)
    >>> job = al.numerics._make_job("ALGEBRAIC")
    >>> missing_value_rule(job, "TQ")[0], missing_value_rule(job, "K")
    (True, (False, 'K (declared on line 2)'))
    """
    key = normalize_name(name)
    m = re.fullmatch(r"([A-Z][A-Z0-9_]*)('*)", key)
    base, primes = (m.group(1), m.group(2)) if m else (key, "")
    kind = job.entries.get(base, ("",))[0]
    line = job.declared.get(base)
    what = f"{name} (declared on line {line})" if line else name
    if kind == "specified":
        return True, (
            f"{name} is Specified with no equation and no Input; using 0"
            " (as Autolev's programs do)"
        )
    if kind == "variable":
        return True, f"{name} has no Input value; using 0"
    if kind == "constant" and zero_missing:
        return True, f"{name} has no Input value; using 0"
    return False, what


def warn_notes(notes: Iterable[str]) -> None:
    """Each note of a missing value as a :class:`MissingValueWarning` (for
    Python callers; ``python module.py`` prints ``note:`` lines instead)."""
    import warnings

    for note in notes:
        warnings.warn(note, MissingValueWarning, stacklevel=3)


@dataclass
class _Values:
    """Input values in internal units, plus what was defaulted."""

    job: Job
    values: dict[str, float]
    units: dict[str, str | None]
    notes: list[str]
    given: set[str] = field(default_factory=set)
    #: go on with 0 for values the script never gives (else stop and name them)
    zero_missing: bool = False
    #: the notes of values taken as 0 (:func:`missing_value_rule`)
    missing: list[str] = field(default_factory=list)
    #: the parameters (not initial values) taken as 0, by name
    zeroed: list[str] = field(default_factory=list)

    def require(self, params: Iterable[Any]) -> None:
        """Stop, naming every value among ``params`` that nobody gave and
        :func:`missing_value_rule` does not make 0 (a constant no Input
        gives, unless :attr:`zero_missing`), with the line declaring it."""
        job = self.job
        wanted = [label_of(obj, job.names) for obj in params]
        listed = []
        for n in _unique(wanted):
            if normalize_name(n) in self.values:
                continue
            zero, what = missing_value_rule(job, n, self.zero_missing)
            if not zero:
                listed.append(what)
        if not listed:
            return
        raise NumericsError(
            f"{job.where}: no value for {', '.join(listed)}. Give "
            f"{'them' if len(listed) > 1 else 'it'} with Input (or "
            "--set NAME=VALUE, run(NAME=value)), or use 0 with --zero-missing"
            " (run(zero_missing=True), AL2PY_ZERO_MISSING=1)"
        )

    def unused(self, used: Iterable[str]) -> None:
        """Note overrides that the job never reads."""
        used = {normalize_name(n) for n in used} | set(INTEGRATION_DEFAULTS)
        if self.job.sweep is not None:
            used.add(normalize_name(label_of(self.job.sweep[0], self.job.names)))
        for key in sorted(self.given - used):
            self.notes.append(
                f"{key} does not appear in the equations or outputs of this job"
                " (a value given in its declaration is substituted when"
                " equations are formed); setting it has no effect"
            )

    def get(self, name: str, default: float = 0.0, note: bool = True) -> float:
        """An initial value or guess: its Input, else ``default``, noted."""
        key = normalize_name(name)
        if key in self.values:
            return self.values[key]
        if note:  # noted, not warned: Autolev starts variables at 0
            self.notes.append(f"{name} has no Input value; using {default:g}")
        return default

    def param(self, obj: Any) -> float:
        """A parameter's value: its Input, else 0 by
        :func:`missing_value_rule`, noted and warned (a job has stopped on
        the others with :meth:`require`; ``al2py code`` writes them as 0
        into the ``.in`` file, where Autolev's programs read them)."""
        name = label_of(obj, self.job.names)
        key = normalize_name(name)
        if key in self.values:
            return self.values[key]
        zero, text = missing_value_rule(self.job, name, self.zero_missing)
        if not zero:  # not required (al2py code: the .in file holds it)
            self.notes.append(f"{name} has no Input value; using 0")
        else:
            self._note(text)
        self.zeroed.append(name)
        return 0.0

    def zero_hint(self) -> str:
        """For a division by zero or a singular matrix: the Variables and
        constants nobody gave that were taken as 0, with their lines (a
        mass or inertia declared with Variables and given no Input)."""
        named = []
        for name in _unique(self.zeroed):
            key = normalize_name(name)
            kind = self.job.entries.get(key, ("",))[0]
            if kind not in ("variable", "constant"):
                continue
            line = self.job.declared.get(key)
            word = "Variables" if kind == "variable" else "Constants"
            named.append(f"{name} ({word}, line {line})" if line else name)
        if not named:
            return ""
        many = len(named) > 1
        return (
            f"; {', '.join(named)} {'have' if many else 'has'} no value (no Input,"
            f" no equation) and {'were' if many else 'was'} taken as 0: a mass or"
            " inertia of 0 divides by zero; give "
            + ("them" if many else "it")
            + " with Input (or declare a parameter with Constants)"
        )

    def _note(self, text: str) -> None:
        self.notes.append(text)
        self.missing.append(text)


def input_values(
    job: Job, overrides: Mapping[str, Any], zero_missing: bool | None = None
) -> tuple[_Values, set]:
    """Convert Input values (with overrides) to internal units; return the
    constants whose numeric RHS the Input or an override replaces."""
    if zero_missing is None:
        zero_missing = os.environ.get("AL2PY_ZERO_MISSING", "") == "1"
    us = job.unit_system
    values: dict[str, float] = {}
    units: dict[str, str | None] = {}
    given: set[str] = set()
    raw = {k: (v.value, v.unit) for k, v in job.inputs.items()}
    for name, value in overrides.items():
        key = normalize_name(name)
        _check_override(job, key, name)
        unit = job.inputs[key].unit if key in job.inputs else None
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise NumericsError(f"{name} = {value!r} is not a number") from None
        raw[key] = (number, unit)
        given.add(key)
    computed = {}
    for key, (number, unit) in raw.items():
        try:
            factor = us.to_internal(unit)
        except UnitError as exc:
            raise NumericsError(f"Input {key}: {exc}") from None
        units[key] = unit
        if isinstance(number, sp.Basic):
            computed[key] = (number, factor)
        else:
            values[key] = number * factor
    values.update(_computed_inputs(job, computed, values))
    keep = set()
    for key in raw:
        entry = job.entries.get(key)
        if entry is None or "'" in key:
            continue
        kind, obj = entry
        value = job.rhs.get(obj)
        if value is not None and kind == "constant":
            if isinstance(value, sp.Basic) and value.is_number:
                keep.add(obj)
    return _Values(job, values, units, [], given, zero_missing), keep


def _computed_inputs(
    job: Job, computed: dict[str, tuple[Any, float]], values: dict[str, float]
) -> dict[str, float]:
    """Inputs given as expressions of other Inputs, in internal units."""
    out: dict[str, float] = {}
    pending = dict(computed)
    while pending:
        known = {**values, **out}
        subs = {}
        for name, (_kind, obj) in job.entries.items():
            if name in known:
                subs[obj] = known[name]
        progress = False
        for key, (expr, factor) in list(pending.items()):
            value = sp.sympify(sp.sympify(expr).xreplace(subs))
            if value.free_symbols or value.atoms(AppliedUndef):
                # ``QQ1 = PI/4`` then ``Input E4 = COS(QQ1/2)``: the script's
                # assigned values as they are when the job runs.
                value = sp.sympify(_resolve(value, job.rhs)).xreplace(subs)
            if value.free_symbols or value.atoms(AppliedUndef):
                continue
            try:
                out[key] = float(value) * factor
            except TypeError:
                raise NumericsError(
                    f"Input {key} = {expr} is not a real number"
                ) from None
            del pending[key]
            progress = True
        if not progress:
            key, (expr, _) = next(iter(pending.items()))
            value = _resolve(sp.sympify(expr), job.rhs)
            atoms = value.free_symbols | value.atoms(AppliedUndef)
            missing = sorted(
                {job.names.get(a, str(a)) for a in atoms} - set(computed), key=str
            ) or sorted(pending)
            raise NumericsError(
                f"Input {key} = {expr}: {', '.join(missing)} "
                f"{'has' if len(missing) == 1 else 'have'} no Input value"
            )
    return out


def evaluate_with_inputs(
    job: Job,
    value: Any,
    name: str,
    overrides: Mapping[str, Any],
    zero_missing: bool | None = None,
) -> Any:
    """``value`` with Inputs, ``overrides`` and right-hand sides substituted.

    A name still without a value follows :func:`missing_value_rule`, as in
    ``run()``: a Specified quantity, a variable and a derivative with no
    equation are 0, warned (:class:`MissingValueWarning`); a constant stops
    with its name and line (``zero_missing``: 0, warned)."""
    import numpy as np

    given = {normalize_name(k): v for k, v in overrides.items()}
    settable = {
        k: v for k, v in given.items() if k in job.inputs or k in INTEGRATION_DEFAULTS
    }
    free = {k: v for k, v in given.items() if k not in settable}
    vals, keep = input_values(job, settable, zero_missing)
    numbers = dict(vals.values)
    for key, v in free.items():
        try:
            numbers[key] = float(v)
        except (TypeError, ValueError):
            raise NumericsError(f"{key} = {v!r} is not a number") from None
    table = _without(
        job.rhs,
        [obj for key, (kind, obj) in job.entries.items() if key in free] + list(keep),
    )
    time = numbers.get("T", numbers.get("TINITIAL", 0.0))
    subs: dict[Any, Any] = {t: time}
    for key, number in numbers.items():
        m = re.fullmatch(r"([A-Z][A-Z0-9_]*)('*)", key)
        entry = job.entries.get(m.group(1)) if m else None
        if entry is not None:
            subs[_deriv(entry[1], len(m.group(2)))] = number

    cache: dict[Any, complex] = {}  # intermediates at this point
    notes: list[str] = []

    def missing(objs: set[Any]) -> None:
        """Give the names nobody gave their value by the rule, or stop."""
        stops = []
        for obj in sorted(objs, key=sp.default_sort_key):
            label = label_of(obj, job.names)
            zero, text = missing_value_rule(job, label, vals.zero_missing)
            if not zero:
                stops.append(text)
                continue
            notes.append(text)
            subs[obj] = 0.0
            if cache:
                cache[obj] = 0j
        if stops:
            raise NumericsError(
                f"{name} needs a value for {', '.join(stops)}"
                " (give it as a keyword argument"
                + (
                    "; constants may be 0 with zero_missing=True)"
                    if any("(declared on line" in x for x in stops)
                    else ")"
                )
            )

    def one(expr: Any) -> float:
        expr = _resolve(sp.sympify(expr), table)
        has_z = autoz.has_intermediates(expr)

        def derivatives() -> Any:
            # Derivatives first, so that QA' is not taken as d(value of QA)/dt.
            return sp.sympify(expr).xreplace(
                {k: v for k, v in subs.items() if isinstance(k, sp.Derivative)}
            )

        out = derivatives()
        # derivatives nobody gave, before their functions are substituted
        # (U(t) -> 0.5 would leave the derivative of a number)
        if out.has(sp.Derivative):
            missing(set(out.atoms(sp.Derivative)))
            out = derivatives()
        if has_z:
            # Intermediates are evaluated at the values, once each, in order
            # (substituting numbers into them would rebuild each one).
            left = {a for a in out.atoms(AppliedUndef) if a not in subs}
            left |= {s for s in out.free_symbols if s != t and s not in subs}
            if left:
                missing(left)
        else:
            plain = {k: v for k, v in subs.items() if k != t}
            out = sp.sympify(out.xreplace(plain))
            left = out.atoms(AppliedUndef) | {s for s in out.free_symbols if s != t}
            if left:
                missing(left)
                plain = {k: v for k, v in subs.items() if k != t}
                out = sp.sympify(derivatives().xreplace(plain))
        if has_z:
            if not cache:
                cache.update({k: complex(v) for k, v in subs.items()})
            number = autoz.number(expr, cache)  # values of Q' come from subs
        else:
            out = sp.sympify(out.xreplace({t: time}))
            number = complex(sp.N(out))
        return (
            number.real if abs(number.imag) < 1e-12 * max(1.0, abs(number)) else number
        )

    if isinstance(value, sp.MatrixBase):
        result: Any = np.array(
            [[one(value[i, j]) for j in range(value.cols)] for i in range(value.rows)]
        )
    elif not isinstance(value, sp.Basic | int | float):
        raise NumericsError(f"{name} is not a scalar or matrix; it cannot be evaluated")
    else:
        result = one(value)
    warn_notes(_unique(notes))
    return result


def check_overrides(job: Job, overrides: Mapping[str, Any]) -> None:
    """Raise :class:`NumericsError` for a name that cannot be set."""
    for name in overrides:
        _check_override(job, normalize_name(name), name)


def _check_override(job: Job, key: str, name: str) -> None:
    if key in INTEGRATION_DEFAULTS or key in job.inputs:
        return
    m = re.fullmatch(r"([A-Z][A-Z0-9_]*)('*)", key)
    entry = job.entries.get(m.group(1)) if m else None
    if entry is None:
        raise NumericsError(f"{name} is not an Input or a declared name of the script")
    kind, obj = entry
    if kind == "quantity":
        raise NumericsError(f"{name} is defined by an equation; it cannot be set")
    if kind not in ("constant", "variable", "specified"):
        raise NumericsError(f"{name} is a {kind}; it cannot be set")
    rhs = job.rhs.get(_deriv(obj, len(m.group(2))))
    if rhs is not None and not (isinstance(rhs, sp.Basic) and rhs.is_number):
        raise NumericsError(f"{name} is defined by an equation; it cannot be set")


def integration_parameters(vals: _Values) -> dict[str, float]:
    p = {}
    for key, default in INTEGRATION_DEFAULTS.items():
        if key in vals.values:
            p[key] = vals.values[key]
        else:
            p[key] = default  # type: ignore[assignment]
    if p["TFINAL"] is None:
        p["TFINAL"] = p["TINITIAL"] + 10.0
    budget.check_span(p["TINITIAL"], p["TFINAL"])
    span = p["TFINAL"] - p["TINITIAL"]
    if p["INTEGSTP"] is None or p["INTEGSTP"] == 0:
        p["INTEGSTP"] = abs(span) / 100 if span else 0.1
    if p["PRINTINT"] is None or p["PRINTINT"] == 0:
        p["PRINTINT"] = 1
    for key in ("INTEGSTP", "PRINTINT", "ABSERR", "RELERR"):
        if p[key] <= 0:
            raise NumericsError(f"{key} must be positive, not {p[key]}")
    # Autolev's programs read "Print-Integer PRINTINT Positive Integer":
    # a row is written every PRINTINT integration steps.
    if p["PRINTINT"] != round(p["PRINTINT"]):
        raise NumericsError(
            f"PRINTINT is a whole number of integration steps, not {p['PRINTINT']:g}"
        )
    return p


def output_times(t0: float, t1: float, step: float) -> np.ndarray:
    """``t0, t0+step, ...`` up to and including ``t1`` (``t1`` is always the
    last row)."""
    import numpy as np

    span = t1 - t0
    if span == 0:
        return np.array([t0])
    step = math.copysign(step, span)
    n = int(math.floor(span / step + 1e-9))
    times = t0 + step * np.arange(n + 1)
    if abs(times[-1] - t1) > 1e-9 * max(1.0, abs(t1)):
        times = np.append(times, t1)
    else:
        times[-1] = t1
    return times


# --------------------------------------------------------------------- runs


def run_job(
    job: Job,
    overrides: Mapping[str, Any] | None = None,
    *,
    backend: str | None = None,
    zero_missing: bool | None = None,
) -> Result:
    """Perform ``job`` with its Input values, changed by ``overrides``.

    ``backend`` chooses how Dynamics/ODE equations are evaluated (see
    :mod:`.backends`; default ``$AL2PY_BACKEND`` or ``auto``).  A value the
    job needs and nobody gave stops it, named, before any code is generated;
    ``zero_missing`` (default ``$AL2PY_ZERO_MISSING=1``) uses 0 instead."""
    vals, keep = input_values(job, overrides or {}, zero_missing)
    if job.kind in ("DYNAMICS", "ODE"):
        try:
            return _run_dynamics(job, vals, keep, backend)
        except backends.BackendError as exc:
            raise NumericsError(str(exc)) from None
    if job.kind == "NONLINEAR":
        return _run_nonlinear(job, vals, keep)
    if job.kind == "ALGEBRAIC":
        return _run_algebraic(job, vals, keep)
    raise NumericsError(f"unknown CODE option {job.kind}")  # pragma: no cover


def _without(table: dict, keep: Iterable[Any]) -> dict:
    keep = set(keep)
    return {k: v for k, v in table.items() if k not in keep}


def _output_exprs(job: Job, table: dict, slots: _Slots) -> list[list[Any]]:
    out = []
    for spec in job.outputs:
        row = []
        for item in spec.items:
            value = _resolve(item.expr, table)
            if isinstance(value, sp.MatrixBase):
                raise NumericsError(
                    f"Output {item.label} (line {spec.line}) is a matrix;"
                    " output its elements"
                )
            what = "Encode" if spec.encoded else "Output"
            row.append(slots.numeric(value, f"{what} {item.label}"))
        out.append(row)
    return out


def output_factors(job: Job, vals: _Values) -> list[list[float]]:
    us = job.unit_system
    factors = []
    for spec in job.outputs:
        row = []
        for item in spec.items:
            try:
                row.append(1.0 / us.to_internal(item.unit))
            except UnitError as exc:
                raise NumericsError(
                    f"Output {item.label} (line {spec.line}): {exc}"
                ) from None
        factors.append(row)
    return factors


def _columns(job: Job) -> list[list[Column]]:
    return [[Column(i.label, i.unit) for i in spec.items] for spec in job.outputs]


# ---------------------------------------------------------------- dynamics


@dataclass
class _Dynamics:
    state_objs: list[Any]
    state_names: list[str]
    ud_objs: list[Any]
    params: list[Any]
    spec: backends.DynamicsSpec  # the equations, for any backend
    compiled: backends.Compiled | None = None


def _compile_dynamics(job: Job, formed: _Dynamics, backend: str | None) -> _Dynamics:
    """``formed`` with its equations compiled by ``backend`` (a copy: each
    backend keeps its own)."""
    try:
        compiled = backends.compile_dynamics(formed.spec, backend)
    except backends.BackendError as exc:
        raise NumericsError(f"{job.where}: {exc}") from None
    return dataclasses.replace(formed, compiled=compiled)


@dataclass
class DynamicsLayout:
    """What a Dynamics/ODE job integrates, before any numbers: the
    right-hand sides in force (``table``), each integrated variable as
    ``(obj, order, implicit)`` in declaration order (``implicit``: its
    highest derivative is found from ``zero``), the states (the variables
    and their lower derivatives), the derivatives solved from ``zero``, and
    ``zero`` itself with the right-hand sides substituted (None without
    such derivatives)."""

    table: dict
    layout: list[tuple[Any, int, bool]]
    state_objs: list[Any]
    ud_objs: list[Any]
    zero: Any

    def rates(self) -> list[Any]:
        """The derivative of each state, in state order: a state itself
        (``Q'`` of a second-order ``Q``), an acceleration solved from
        ``zero`` (its object), or the expression of an explicit equation."""
        out: list[Any] = []
        for obj, k, imp in self.layout:
            out += [_deriv(obj, j + 1) for j in range(k - 1)]
            top = _deriv(obj, k)
            out.append(top if imp else _resolve(self.table[top], self.table))
        return out


def dynamics_layout(job: Job, keep: frozenset) -> DynamicsLayout:
    """The states and equations of a Dynamics/ODE job (see
    :class:`DynamicsLayout`)."""
    table = _without(job.rhs, keep)
    explicit: list[tuple[Any, int]] = []
    implicit: dict[Any, int] = {}
    candidates = []
    for name, obj, order in job.variables:
        if obj in table:
            continue  # computed from its own RHS (dependent speeds, specified)
        ks = [k for k in range(max(order, 1), 0, -1) if _deriv(obj, k) in table]
        if ks:
            explicit.append((obj, ks[0]))
        elif job.entries.get(name, ("", None))[0] != "specified":
            # A Specified quantity with no equation is an input of the job
            # (0 unless given, as in Autolev's programs), never an unknown.
            candidates.append(obj)
    zero = None
    if job.zero is not None:
        zero = _resolve(sp.Matrix(job.zero), table)
        cand = set(candidates)
        for d in zero.atoms(sp.Derivative):
            base, k = _base(d)
            if base in cand and d not in table:
                implicit[base] = max(implicit.get(base, 0), k)
        if not implicit:
            zero = None
    if zero is not None and len(zero) != len(implicit):
        names = ", ".join(
            label_of(_deriv(b, k), job.names) for b, k in implicit.items()
        )
        raise NumericsError(
            f"{job.where}: ZERO has {len(zero)} equations but {len(implicit)}"
            f" unknown derivatives ({names})"
        )
    # states in declaration order
    order_of = {obj: i for i, (_n, obj, _o) in enumerate(job.variables)}
    layout = sorted(
        [(obj, k, False) for obj, k in explicit]
        + [(obj, k, True) for obj, k in implicit.items()],
        key=lambda e: order_of[e[0]],
    )
    if not layout:
        raise NumericsError(
            f"{job.where}: nothing to integrate (no variable has an equation"
            " for its derivative)"
        )
    state_objs = [_deriv(obj, j) for obj, k, _i in layout for j in range(k)]
    ud_objs = [_deriv(obj, k) for obj, k, imp in layout if imp]
    return DynamicsLayout(table, layout, state_objs, ud_objs, zero)


def dynamics_equations(job: Job, keep: frozenset, deferred: bool = False) -> _Dynamics:
    """The job's states, parameters and equations as sympy expressions;
    ``deferred``: the intermediates' definitions may be :class:`Deferred`."""
    formed = dynamics_layout(job, keep)
    table, layout, zero = formed.table, formed.layout, formed.zero
    state_objs, ud_objs = formed.state_objs, formed.ud_objs
    slots = _Slots(job, deferred)
    ys = slots.add(state_objs, "y")
    uds = slots.add(ud_objs, "ud")
    derivs = []
    for obj, k, imp in layout:
        for j in range(k - 1):
            derivs.append(slots.known[_deriv(obj, j + 1)])
        if imp:
            derivs.append(slots.known[_deriv(obj, k)])
        else:
            label = label_of(_deriv(obj, k), job.names)
            derivs.append(slots.numeric(_resolve(table[_deriv(obj, k)], table), label))
    mf_exprs: list[Any] = []
    if zero is not None:
        numeric_zero = [slots.numeric(e, "ZERO") for e in zero]
        split = [linear_terms(e, uds) for e in numeric_zero]
        if all(part is not None for part in split):
            mass = sp.Matrix([coefs for coefs, _rest in split])
            zero_at_0 = [rest for _coefs, rest in split]
        else:
            mass = sp.Matrix(numeric_zero).jacobian(uds)
            zero_at_0 = [e.xreplace(dict.fromkeys(uds, 0)) for e in numeric_zero]
        if any(e.has(*uds) for e in mass):
            raise NumericsError(
                f"{job.where}: ZERO is not linear in "
                + ", ".join(label_of(d, job.names) for d in ud_objs)
            )
        mf_exprs = list(mass) + [-e for e in zero_at_0]
    outputs = _output_exprs(job, table, slots)
    n = len(uds)
    spec = backends.DynamicsSpec(
        slots.time,
        ys,
        uds,
        list(slots.param_dummies),
        mf_exprs[: n * n],
        mf_exprs[n * n :],
        derivs,
        outputs,
        slots.intermediates,
    )
    names = [label_of(o, job.names) for o in state_objs]
    return _Dynamics(state_objs, names, ud_objs, list(slots.params), spec)


def _state_aliases(job: Job, c: _Dynamics) -> dict[str, str]:
    """States that a declared name stands for: ``OMEGA = THETA'`` makes an
    Input of ``OMEGA`` the initial value of the state ``THETA'``."""
    states = dict(zip(c.state_objs, c.state_names, strict=True))
    aliases = {}
    for name, obj, _order in job.variables:
        rhs = job.rhs.get(obj)
        if rhs is not None and rhs in states:
            aliases[states[rhs]] = normalize_name(name)
    return aliases


def initial_state(job: Job, c: _Dynamics, vals: _Values) -> list[float]:
    """The states' values at TINITIAL, in internal units."""
    aliases = _state_aliases(job, c)
    y0 = []
    for name in c.state_names:
        alias = aliases.get(name)
        if normalize_name(name) not in vals.values and alias in vals.values:
            name = alias  # ``OMEGA = THETA'`` with ``Input OMEGA=0``
        y0.append(
            vals.get(name, job.initials.get(name, 0.0), note=name not in job.initials)
        )
    return y0


@dataclass
class OdeSystem:
    """The numeric equations of a dynamics job: ``fun(t, y)`` for
    ``scipy.integrate.solve_ivp``, the initial state ``y0`` and the state
    names, in internal units (the UnitSystem's, SI by default; radians).
    ``outputs(t, y)`` gives the Output rows (internal units), one list per
    Output statement."""

    fun: Any
    y0: list[float]
    names: list[str]
    outputs: Any
    compiled: _Dynamics
    params: list[float]
    clock: list[float]
    bound: backends.Bound
    #: :meth:`_Values.zero_hint`, for a singular matrix or a division by 0
    hint: str = ""


def _compiled(
    job: Job, keep: Iterable[Any], backend: str | None, vals: _Values | None = None
) -> _Dynamics:
    """The job's equations, built by ``backend`` once per job and backend;
    ``vals`` must hold every value they need (checked before any code is
    generated: see :meth:`_Values.require`)."""
    keep = frozenset(keep)
    formed = ("equations", keep)
    if formed not in job.cache:
        job.cache[formed] = dynamics_equations(job, keep)
    if vals is not None:
        vals.require(job.cache[formed].params)
    key = ("dyn", keep, backends.choose(backend))
    if key not in job.cache:
        job.cache[key] = _compile_dynamics(job, job.cache[formed], key[2])
    return job.cache[key]


def ode_system(
    job: Job,
    vals: _Values,
    keep: set,
    t0: float = 0.0,
    backend: str | None = None,
) -> OdeSystem:
    """The right-hand side ``y' = f(t, y)`` of a dynamics job (the one place
    where ``run()`` turns the equations into a numeric function, through the
    backend chosen: see :mod:`.backends`)."""
    try:
        c = _compiled(job, keep, backend, vals)
    except backends.BackendError as exc:
        raise NumericsError(str(exc)) from None
    vals.unused([label_of(o, job.names) for o in c.params] + c.state_names)
    p = [vals.param(obj) for obj in c.params]
    y0 = initial_state(job, c, vals)
    bound = c.compiled.bind(p)
    clock = [t0]  # time of the latest evaluation, for messages
    rhs = bound.rhs
    hint = vals.zero_hint()

    def fun(tt: float, y: np.ndarray) -> np.ndarray:
        clock[0] = tt
        try:
            return rhs(tt, y)
        except backends.SingularMatrixError as exc:
            raise _singular(job, c, exc.t, hint) from None

    def outputs(tt: float, y: Any) -> list[list[float]]:
        clock[0] = tt
        try:
            return bound.outputs(tt, y)
        except backends.SingularMatrixError as exc:
            raise _singular(job, c, exc.t, hint) from None

    return OdeSystem(fun, y0, list(c.state_names), outputs, c, p, clock, bound, hint)


def _singular(job: Job, c: _Dynamics, at: float, hint: str = "") -> NumericsError:
    return NumericsError(
        f"{job.where}: the coefficient matrix of "
        + ", ".join(label_of(d, job.names) for d in c.ud_objs)
        + f" in ZERO is singular at t = {at:g}"
        + hint
    )


def ode_function(
    job: Job,
    overrides: Mapping[str, Any] | None = None,
    *,
    backend: str | None = None,
    zero_missing: bool | None = None,
    notes: bool = False,
) -> tuple[Any, ...]:
    """``(f, y0, names)`` for ``solve_ivp(f, (t0, t1), y0)``: the job's
    equations of motion in internal units, with Inputs changed by
    ``overrides`` (as ``run()``), evaluated by ``backend``.  With ``notes``,
    ``(f, y0, names, notes)``: the notes of the values taken as 0
    (:func:`missing_value_rule`)."""
    if job.kind not in ("DYNAMICS", "ODE"):
        raise NumericsError(f"{job.where}: CODE {job.kind} has no equations of motion")
    vals, keep = input_values(job, overrides or {}, zero_missing)
    ip = integration_parameters(vals)
    system = ode_system(job, vals, keep, ip["TINITIAL"], backend)
    if notes:
        return system.fun, list(system.y0), list(system.names), _unique(vals.missing)
    return system.fun, list(system.y0), list(system.names)


def _run_dynamics(
    job: Job, vals: _Values, keep: set, backend: str | None = None
) -> Result:
    import numpy as np

    ip = integration_parameters(vals)
    system = ode_system(job, vals, keep, ip["TINITIAL"], backend)
    c, clock = system.compiled, system.clock
    times = output_times(ip["TINITIAL"], ip["TFINAL"], ip["INTEGSTP"] * ip["PRINTINT"])
    try:
        ys, nfev = _integrate(job, system, times, ip)
        factors = output_factors(job, vals)
        try:
            values = system.bound.table(times, ys, clock)
        except backends.SingularMatrixError as exc:
            raise _singular(job, c, exc.t, system.hint) from None
    except NumericsError:
        raise
    except (ValueError, ZeroDivisionError, OverflowError) as exc:
        hint = system.hint or ("; check the Input values" if vals.notes else "")
        raise NumericsError(f"{job.where}: {exc} at t = {clock[0]:g}{hint}") from None
    tables, k = [], 0
    for number, (cols, fac, spec) in enumerate(
        zip(_columns(job), factors, job.outputs, strict=True), start=1
    ):
        data = values[:, k : k + len(cols)] * fac
        k += len(cols)
        tables.append(Table(number, cols, data, spec.line, spec.encoded))
    states = {"T": np.asarray(times, dtype=float)}
    for j, name in enumerate(c.state_names):
        unit = vals.units.get(name)
        states[name] = ys[j] / job.unit_system.to_internal(unit)
    motion = Motion(job, vals, frozenset(keep), list(c.state_objs), times, ys)
    return _result(job, tables, vals, states=states, nfev=nfev, motion=motion)


@dataclass
class Motion:
    """What a Dynamics/ODE run keeps for computing other quantities at its
    output rows (:func:`evaluate_rows`; ``result.animate()``): the job, the
    values it ran with, and its states at every row, in internal units."""

    job: Job
    values: _Values
    keep: frozenset
    states: list[Any]  # the state objects, in the order of ``ys``' rows
    times: np.ndarray
    ys: np.ndarray  # (states, rows)

    @property
    def rows(self) -> int:
        return len(self.times)

    def evaluate(self, exprs: Sequence[Any], what: str = "Animate") -> np.ndarray:
        """:func:`evaluate_rows` of this run."""
        return evaluate_rows(self, exprs, what)

    def animation(
        self,
        *,
        frames: Sequence[Any] | None = None,
        points: Sequence[Any] = (),
        origin: Any = None,
        newtonian: Any = None,
        time_unit: str | None = None,
        **options: Any,
    ) -> Any:
        """An :class:`~al2py_runtime.jobs.animation.Animation` of this run:
        the job's ``Animate`` statement, changed by the arguments given
        (:func:`~al2py_runtime.jobs.scene.layout`)."""
        from .animation import Animation
        from .scene import layout, scene

        spec = self.job.animate
        if spec is not None:
            newtonian = spec.newtonian if newtonian is None else newtonian
            origin = spec.point if origin is None else origin
            frames = spec.frames if frames is None else frames
        shown = layout(self.job.geometry, newtonian, origin, frames, points)
        units = (time_unit, self.job.unit_system.names[1])
        options.setdefault("title", self.job.stem)
        return Animation(scene(self.evaluate, shown, self.times, units), **options)


def evaluate_rows(motion: Motion, exprs: Sequence[Any], what: str) -> np.ndarray:
    """``exprs`` (sympy expressions of the script's names) at every output
    row of a run: an array ``(rows, len(exprs))`` in internal units.

    The expressions are resolved and numbered as the job's own outputs are
    (:class:`_Slots`: the job's right-hand sides, its parameters and the
    named intermediates they need, each computed once), then one
    ``lambdify``'d numpy function (built once per job and expressions)
    computes all rows at once."""
    import numpy as np

    job = motion.job
    exprs = [sp.sympify(e) for e in exprs]
    key = ("rows", motion.keep, tuple(exprs))
    if key not in job.cache:
        table = _without(job.rhs, motion.keep)
        slots = _Slots(job)
        ys = slots.add(motion.states, "y")
        numeric = [slots.numeric(_resolve(e, table), what) for e in exprs]
        args = [slots.time, *ys, *slots.param_dummies]
        job.cache[key] = (
            list(slots.params),
            backends.lambdify_job(args, numeric, slots.intermediates, "numpy"),
            backends.lambdify_job(args, numeric, slots.intermediates),
        )
    params, vectorized, scalar = job.cache[key]
    motion.values.require(params)
    p = [motion.values.get(label_of(o, job.names), note=False) for o in params]
    rows = motion.rows
    if not exprs:
        return np.empty((rows, 0))
    try:
        with np.errstate(all="ignore"):
            out = vectorized(motion.times, *motion.ys, *p)
        columns = [np.broadcast_to(np.asarray(v, dtype=float), (rows,)) for v in out]
        return np.stack(columns, axis=1)
    except (TypeError, ValueError):
        # a function with no numpy form (Autolev's INT, ROUND): row by row
        values = [
            scalar(float(tt), *motion.ys[:, i].tolist(), *p)
            for i, tt in enumerate(motion.times)
        ]
        return np.array(values, dtype=float).reshape(rows, len(exprs))


def _result(job: Job, tables: list[Table], vals: _Values, **more: Any) -> Result:
    """The ``Result`` of ``job``: its tables, Encode values and the notes
    the Input values raised (each once), plus what the kind of job adds."""
    return Result(
        job.kind,
        job.stem,
        tables,
        job.digits,
        encoded=dict(job.encoded),
        notes=_unique(vals.notes),
        missing=_unique(vals.missing),
        time_unit=job.unit_system.time_unit,
        **more,
    )


def _integrate(
    job: Job, system: OdeSystem, times: np.ndarray, ip: dict[str, float]
) -> tuple[np.ndarray, int]:
    """The states at ``times`` (one column each) and the number of
    right-hand-side evaluations: Kutta-Merson with Autolev's step control
    (:mod:`.kutta`), compiled with the equations when the backend is ``c``."""
    import numpy as np

    t0, t1, clock = float(times[0]), float(times[-1]), system.clock
    args = (t0, system.y0, ip["INTEGSTP"], ip["ABSERR"], ip["RELERR"])
    ys = np.empty((len(system.y0), len(times)))
    ys[:, 0] = system.y0
    compiled = system.bound.stepper(*args)
    meter = budget.Meter(job.where, t0, t1)
    if compiled is not None:
        compiled.max_evals = meter.max_evals
        stepper: Any = compiled
    else:
        fun = budget.guard(system.fun, job.where, t0, t1)
        stepper = KuttaMerson(fun, *args)
        counted = [0]

        def counting(tt: float, y: np.ndarray) -> np.ndarray:
            counted[0] += 1
            return fun(tt, y)

        stepper.f = counting
    try:
        for i in range(1, len(times)):
            if compiled is not None:
                compiled.seconds = meter.seconds_left()
            stepper.advance(float(times[i]))
            ys[:, i] = stepper.y
            clock[0] = float(times[i])
            meter.tick(clock[0])
    except backends.SingularMatrixError as exc:
        raise _singular(job, system.compiled, exc.t, system.hint) from None
    except StepError as exc:
        clock[0] = exc.t
        if exc.code == 4:
            raise budget.exhausted(
                job.where, exc.t, t1, evaluations=meter.max_evals
            ) from None
        if exc.code == 5:
            raise budget.exhausted(
                job.where, exc.t, t1, seconds=meter.max_seconds
            ) from None
        if exc.code == 2:
            raise ValueError(backends.NOT_FINITE) from None
        raise NumericsError(
            f"{job.where}: integration failed at t = {exc.t:g}: the step was"
            " halved too often (ABSERR, RELERR)"
        ) from None
    return ys, compiled.evals if compiled is not None else counted[0]


def _unique(items: list[str]) -> list[str]:
    return list(dict.fromkeys(items))


# ------------------------------------------------------ nonlinear, algebraic


@dataclass
class _Static:
    unknown_names: list[str]
    residual: Any  # (T, *x, *p) -> F
    jacobian: Any  # (T, *x, *p) -> J row-major (Nonlinear), A (Algebraic)
    rhs: Any  # Algebraic: (T, *p) -> b
    outputs: list[Any]
    params: list[Any]


def eq_labels(job: Job) -> list[str]:
    n = len(job.eqs) if job.eqs is not None else 0
    if job.eqs_name:
        return [f"{job.eqs_name}[{i + 1}]" for i in range(n)]
    return [f"equation {i + 1}" for i in range(n)]


def _inline_dependent(
    intermediates: Sequence[tuple[Any, Any]], exprs: list[Any], xs: Sequence[Any]
) -> list[Any]:
    """``exprs`` with the intermediates that depend on ``xs`` substituted
    (each written out once, in order, then one substitution)."""
    if not xs:  # no unknowns: no intermediate depends on one
        return exprs
    full: dict[Any, Any] = {}
    for sym, expr in intermediates:
        if expr.has(*xs) or expr.free_symbols & full.keys():
            full[sym] = expr.xreplace(full)
    return [e.xreplace(full) for e in exprs] if full else exprs


@dataclass
class StaticSpec:
    """A Nonlinear/Algebraic job's equations as sympy expressions of dummies:
    ``eqs`` (residuals) and ``jac`` (their Jacobian in ``xs``, the unknowns)
    with the intermediates that depend on the unknowns written out."""

    unknowns: list[Any]  # objects, in the CODE statement's order
    time: Any
    xs: list[Any]
    params: list[Any]  # objects, in argument order
    param_dummies: list[Any]
    intermediates: list[tuple[Any, Any]]
    eqs: list[Any]
    jac: Any
    outputs: list[list[Any]]


def static_equations(job: Job, keep: frozenset, deferred: bool = False) -> StaticSpec:
    """The unknowns, parameters and equations of a Nonlinear/Algebraic job
    (for Algebraic, checked to be linear in the unknowns); ``deferred``:
    without unknowns, the intermediates' definitions may be
    :class:`Deferred` (with unknowns, some are written out here)."""
    unknowns = list(job.unknowns)
    table = _without(job.rhs, set(keep) | set(unknowns))
    slots = _Slots(job, deferred and not unknowns)
    xs = slots.add(unknowns, "x")
    eqs = []
    if job.eqs is not None:
        resolved = _resolve(sp.Matrix(job.eqs), table)
        eqs = [slots.numeric(e, "the equations") for e in resolved]
    if len(eqs) != len(unknowns):
        raise NumericsError(
            f"{job.where}: {len(eqs)} equations for {len(unknowns)} unknowns"
        )
    outputs = _output_exprs(job, table, slots)
    z = slots.intermediates
    eqs = _inline_dependent(z, eqs, xs)  # the Jacobian must see through them
    jac = sp.Matrix(eqs).jacobian(xs) if eqs else sp.Matrix()
    if job.kind == "ALGEBRAIC":
        bad = [u for u, x in zip(unknowns, xs, strict=True) if jac.has(x)]
        if bad:
            raise NumericsError(
                f"{job.where}: the equations are not linear in "
                + ", ".join(label_of(u, job.names) for u in bad)
                + "; use CODE Nonlinear"
            )
    return StaticSpec(
        unknowns,
        slots.time,
        xs,
        list(slots.params),
        list(slots.param_dummies),
        z,
        eqs,
        jac,
        outputs,
    )


def _compile_static(job: Job, keep: frozenset) -> _Static:
    s = static_equations(job, keep)
    args = [s.time, *s.xs]
    z = s.intermediates
    residual = lambdify_job([*args, *s.param_dummies], s.eqs, z)
    rhs = None
    if job.kind == "ALGEBRAIC":
        at0 = dict.fromkeys(s.xs, 0)
        rhs = lambdify_job(
            [s.time, *s.param_dummies], [-e.xreplace(at0) for e in s.eqs], z
        )
        jacobian = lambdify_job([s.time, *s.param_dummies], list(s.jac), z)
    else:
        jacobian = lambdify_job([*args, *s.param_dummies], list(s.jac), z)
    out_funcs = [lambdify_job([*args, *s.param_dummies], row, z) for row in s.outputs]
    return _Static(
        [label_of(u, job.names) for u in s.unknowns],
        residual,
        jacobian,
        rhs,
        out_funcs,
        s.params,
    )


def _static(job: Job, keep: set, vals: _Values) -> _Static:
    key = ("static", frozenset(keep))
    if key not in job.cache:
        job.cache[key] = _compile_static(job, frozenset(keep))
    c = job.cache[key]
    vals.unused([label_of(o, job.names) for o in c.params] + c.unknown_names)
    return c


def _static_result(
    job: Job,
    vals: _Values,
    c: _Static,
    t0: float,
    rows: list[tuple[list[float], list[float]]],
) -> Result:
    """Tables from ``rows`` of (unknown values, parameter values)."""
    import numpy as np

    us = job.unit_system
    solution = {}
    units = {}
    for j, name in enumerate(c.unknown_names):
        unit = vals.units.get(name)
        units[name] = unit
        solution[name] = np.array([x[j] for x, _p in rows]) / us.to_internal(unit)
    tables = []
    if job.outputs:
        factors = output_factors(job, vals)
        for number, (cols, func, fac, spec) in enumerate(
            zip(_columns(job), c.outputs, factors, job.outputs, strict=True), start=1
        ):
            try:
                data = [func(t0, *x, *p) for x, p in rows]
            except (ValueError, ZeroDivisionError, OverflowError) as exc:
                what = "Encode" if spec.encoded else "Output"
                at = f" (line {spec.line})" if spec.line else ""
                raise NumericsError(
                    f"{job.where}: {what} {', '.join(col.label for col in cols)}{at}:"
                    f" {exc}{vals.zero_hint()}"
                ) from None
            arr = np.array(data, dtype=float).reshape(len(rows), len(cols)) * fac
            tables.append(Table(number, cols, arr, spec.line, spec.encoded))
    if c.unknown_names and not any(not s.encoded for s in job.outputs):
        cols = [Column(n, units[n]) for n in c.unknown_names]
        data = np.column_stack([solution[n] for n in c.unknown_names])
        tables.append(Table(1, cols, data, job.line))
    return _result(job, tables, vals, solution=solution, solution_units=units)


def _run_nonlinear(job: Job, vals: _Values, keep: set) -> Result:
    import numpy as np
    from scipy.optimize import root

    c = _static(job, keep, vals)
    vals.require(c.params)
    ip = integration_parameters(vals)
    t0 = ip["TINITIAL"]
    p = [vals.param(obj) for obj in c.params]
    x0 = [vals.get(name) for name in c.unknown_names]
    n = len(x0)
    labels = eq_labels(job)

    def fun(x: np.ndarray) -> list[float]:
        return c.residual(t0, *x.tolist(), *p)

    def jac(x: np.ndarray) -> np.ndarray:
        return np.array(c.jacobian(t0, *x.tolist(), *p)).reshape(n, n)

    try:
        f0 = np.abs(fun(np.array(x0, dtype=float)))
        scale = max(1.0, float(f0.max()) if n else 1.0)
        tol = ip["ABSERR"] * scale
        best = None
        for method in ("hybr", "lm"):
            sol = root(fun, x0, jac=jac, method=method, tol=min(ip["RELERR"], 1e-10))
            res = np.abs(fun(sol.x))
            if best is None or res.max() < best[1].max():
                best = (sol.x, res)
            if res.max() <= tol:
                break
    except (ValueError, ZeroDivisionError, OverflowError) as exc:
        raise NumericsError(f"{job.where}: {exc}{vals.zero_hint()}") from None
    x, res = best
    if not np.all(np.isfinite(res)) or res.max() > tol:
        worst = int(np.nanargmax(res)) if np.any(np.isfinite(res)) else 0
        at = ", ".join(
            f"{name} = {fmt_number(v / job.unit_system.to_internal(vals.units.get(name)), 6)}"
            + (f" {vals.units[name]}" if vals.units.get(name) else "")
            for name, v in zip(c.unknown_names, x, strict=True)
        )
        raise NumericsError(
            f"{job.where}: no solution found from the Input guesses;"
            f" residual |{labels[worst]}| = {res[worst]:.3g} at {at}."
            " Try other guesses."
        )
    return _static_result(job, vals, c, t0, [(x.tolist(), p)])


def _run_algebraic(job: Job, vals: _Values, keep: set) -> Result:
    import numpy as np

    c = _static(job, keep, vals)
    sweep_obj = job.sweep[0] if job.sweep is not None else None
    vals.require([obj for obj in c.params if obj != sweep_obj])
    ip = integration_parameters(vals)
    t0 = ip["TINITIAL"]
    base = [0.0 if obj == sweep_obj else vals.param(obj) for obj in c.params]
    n = len(c.unknown_names)
    param_rows: list[list[float]] = []
    if job.sweep is not None:
        obj, unit, start, stop, step = job.sweep
        try:
            factor = job.unit_system.to_internal(unit)
        except UnitError as exc:
            raise NumericsError(f"{job.where}: {exc}") from None
        values = output_times(float(start), float(stop), float(step))
        try:
            index = c.params.index(obj)
        except ValueError:
            index = None
        for v in values:
            p = list(base)
            if index is not None:
                p[index] = v * factor
            param_rows.append(p)
    else:
        param_rows.append(base)
    rows = []
    for p in param_rows:
        if n:
            try:
                a = np.array(c.jacobian(t0, *p), dtype=float).reshape(n, n)
                b = np.array(c.rhs(t0, *p), dtype=float)
            except (ValueError, ZeroDivisionError, OverflowError) as exc:
                raise NumericsError(
                    f"{job.where}: the equations: {exc}{vals.zero_hint()}"
                ) from None
            try:
                x = np.linalg.solve(a, b).tolist()
            except np.linalg.LinAlgError:
                raise NumericsError(
                    f"{job.where}: the equations are singular (no unique"
                    f" solution){vals.zero_hint()}"
                ) from None
        else:
            x = []
        rows.append((x, p))
    result = _static_result(job, vals, c, t0, rows)
    if job.sweep is not None:
        obj, unit, start, stop, step = job.sweep
        name = label_of(obj, job.names)
        result.solution.setdefault(
            name, output_times(float(start), float(stop), float(step))
        )
        result.solution_units.setdefault(name, unit)
        if not any(not s.encoded for s in job.outputs) and result.tables:
            table = result.tables[0]
            table.columns.insert(0, Column(name, unit))
            table.data = np.column_stack([result.solution[name], table.data])
    return result
