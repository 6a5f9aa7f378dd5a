"""The Autolev workspace: names, their right-hand sides, settings and responses.

A generated module creates one :class:`Workspace` and calls it once per Autolev
statement.  The workspace reproduces how Autolev treats names:

* Declared constants are real sympy ``Symbol`` objects, variables and specified
  quantities are functions of time (``dynamicsymbols``), both named exactly as
  Autolev prints them (``QA``, ``U1``).
* An assigned scalar quantity (``E = ...``) is a ``Symbol`` with a right-hand
  side (RHS).  Later expressions refer to the symbol, as Autolev's responses do;
  ``D``, ``Dt``, ``Evaluate``, ``Taylor``, ``Solve`` and ``Explicit`` see
  through symbols to their RHS.  ``AutoRHS`` decides which RHS are substituted
  when an expression is assigned (see ``docs/semantics.md``).
* Matrices, vectors and dyadics are stored as values.

>>> ws = Workspace("demo.al")
>>> A, B = ws.constants("A", "B")
>>> X = ws.assign("X", 4 * (A + B) - 3 * (A - B), line=2)
>>> ws["X"]
A + 7*B
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import replace
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols
from sympy.physics.vector import Dyadic, Vector

from . import algebra, collector, matrices, progress, walks
from .intermediates.autoz import substitute
from .jobs.numerics import Numerics
from .model.kinematics import (
    doit_derivatives,
    factor_terms,
    is_small,
    one_or_tuple,
    scalar_dt,
)
from .model.model import Model
from .names.keys import Key, parse_key
from .names.settings import Response, Settings
from .names.table import Entry, NameTable
from .names.variables import TimeFunction, time_function
from .progress import ImportWatch
from .safety import Statements, statement
from .safety import register as register_module
from .vocabulary import OBJECT_DECLS

__all__ = ["Workspace", "Settings", "Response", "t"]

#: Autolev's reserved time variable ``T`` (shared with sympy.physics.mechanics).
t = dynamicsymbols._t


class Workspace(Mapping):
    """Names, values and responses of one Autolev script.

    The workspace is a read-only mapping from Autolev spellings to current
    values, e.g. ``ws["ZERO[2]"]`` or ``ws["STRETCH'"]`` (case-insensitive).
    """

    def __init__(
        self, filename: str = "<autolev>", module_file: str | None = None
    ) -> None:
        self.filename = filename
        #: the generated module this workspace serves (its ``__file__``):
        #: its failures name the .al line (:mod:`.safety`)
        generated = register_module(filename, module_file)
        self.statements = Statements(filename, module_file)
        #: a progress line while a long import derives (stopped by names())
        self._watch = ImportWatch(filename, module_file)
        self._watch.start()
        #: while a generated module derives, each of its statements runs
        #: with the cyclic garbage collector paused, and what it made is
        #: then moved out of the collector's sight
        #: (:func:`~.collector.settled`): sympy's expressions are trees and
        #: the model keeps them, so passes over millions of new objects
        #: found nothing (a tenth of a bicycle's import, a twentieth of
        #: DAS3's); names() ends it
        self.statements.settle = generated
        self.settings = Settings(statements=self.statements)
        self.responses: list[Response] = []
        #: the script's names (:class:`~.names.table.NameTable`)
        self.table = NameTable()
        self._saves: list[tuple[str, int | None]] = []  # (file, line)
        self._exit_line: int | None = None
        #: Quantities the script constrains to unit norm (the Euler parameters
        #: of ``Dircos``/``Angvel``/``Kindiffs(..., EULER, E1, E2, E3, E4)``):
        #: ``al2py check`` draws its random points on that sphere.
        self.unit_norms: list[tuple[Any, ...]] = []
        self._autotaylor: tuple[tuple[int, int], list[tuple]] | None = None
        #: AutoRHS ON's table of numeric right-hand sides, with the count of
        #: the table's changes and the kept quantities it was made for
        #: (:meth:`_simple_rhs`)
        self._simple: tuple[int, frozenset, dict] | None = None
        #: :meth:`resolver`'s substitution tables, each with the memo of its
        #: substitutions, by the kept quantities that have a right-hand
        #: side, for the count of the table's changes they were made at
        #: (a resolve per ``D()`` of a bicycle, all with one table)
        self._tables: tuple[int, dict[frozenset, tuple[dict, dict]]] | None = None
        #: the parts found to hold no derivative to evaluate
        #: (:func:`_derivatives_done`: it depends on the part only)
        self._no_derivatives: set = set()
        #: the parts found to hold no ``Float`` (:func:`_may_hold_floats`:
        #: the values normalized share most of their parts)
        self._no_floats: set = set()
        #: a sum Factoring rearranges -> what it becomes
        #: (sympy's ``factor_terms`` if it is small, else itself): a bicycle
        #: rearranges a third of its sums more than once
        self._factored: dict[Any, Any] = {}
        #: Frames, points, bodies, loads and Kane's method (mechanics.py).
        self.model = Model(
            self,
            table=self.table,
            settings=self.settings,
            statements=self.statements,
            unit_norms=self.unit_norms,
        )
        #: Inputs, Outputs, UnitSystem and CODE jobs.  Generated modules call
        #: it directly (``al.numerics.input(...)``, ``al.numerics.run(...)``):
        #: an Input value or a ``backend`` reaches the job without a forwarder.
        self.numerics = Numerics(
            self,
            filename=filename,
            table=self.table,
            settings=self.settings,
            statements=self.statements,
            model=self.model,
        )
        self.table.declare("T", "variable", t)
        self.table.declare("PI", "constant", sp.pi)
        self.table.declare("I", "imaginary", sp.I)

    # The model's commands are :class:`Model`'s own methods: a module calls
    # them as ``al.model.simprot(...)``, ``al.model.fr()``...

    def main(
        self, source: str | Sequence[str], argv: Sequence[str] | None = None
    ) -> int:
        """The ``python module.py`` entry point (see :mod:`.cli`): ``source``
        is the module's file, whose ``# al>`` lines are the ``.al`` source
        the transcript echoes (or those source lines themselves)."""
        from .cli import main
        from .safety import module_source

        lines = module_source(source) if isinstance(source, str) else list(source)
        return main(self, lines, argv)

    # ------------------------------------------------------------ mapping API

    def __getitem__(self, name: str) -> Any:
        """The value of ``name`` as the script sees it: with ``AutoZ OFF``
        written out (:meth:`form`); :meth:`value` keeps intermediates."""
        return self.form(self.value(name))

    def __iter__(self) -> Iterator[str]:
        seen = []
        for name, entry in self.table.entries.items():
            if name in ("T", "PI", "I"):
                continue
            seen.append(name)
            if entry.kind == "variable":
                for k in range(1, entry.order + 1):
                    if self.table.rhs_key(name, k) in self.table.rhs:
                        seen.append(name + "'" * k)
        seen.extend(n for n in self.table.stored if n not in self.table.entries)
        return iter(seen)

    def __len__(self) -> int:
        return sum(1 for _ in self)

    def __contains__(self, name: object) -> bool:
        if not isinstance(name, str):
            return False
        try:
            self.value(name)
        except KeyError:
            return False
        return True

    # ----------------------------------------------------------- declarations

    def _assumptions(self, sign: str | None) -> dict[str, bool]:
        if self.settings.complex == "ON":
            return {}
        if sign == "+":
            return {"nonnegative": True}
        if sign == "-":
            return {"nonpositive": True}
        return {"real": True}

    @statement
    def constants(self, *names: str, line: int | None = None) -> Any:
        """``Constants A, B+, C-``: real symbols (``+`` non-negative, ``-``
        non-positive).  Returns one symbol or a tuple, in order; ``line`` is
        the script's line, named when a job lacks a value."""
        out = []
        for spec in names:
            name, sign = _split_sign(spec)
            sym = sp.Symbol(name.upper(), **self._assumptions(sign))
            out.append(self.table.declare(name, "constant", sym, sign=sign, line=line))
        return one_or_tuple(out)

    @statement
    def declare_constants(self, *symbols: sp.Symbol, line: int | None = None) -> None:
        """After ``G, L = symbols("G L", real=True)`` (``Constants G, L``):
        the module's sympy symbols become the constants of those names.  They
        must carry Autolev's assumptions (real unless ``Complex ON``)."""
        for sym in symbols:
            for sign in (None, "+", "-"):  # ``A``, ``A+``, ``A-``
                if sym == sp.Symbol(sym.name, **self._assumptions(sign)):
                    break
            else:
                raise ValueError(
                    f"constant {sym.name} must be declared with"
                    f" {self._assumptions(None) or 'no assumptions'}"
                    " (or nonnegative/nonpositive, for A+ and A-)"
                )
            self.table.declare(sym.name, "constant", sym, sign=sign, line=line)

    @statement
    def declare_variables(
        self, *functions: Any, primes: int | Sequence[int] = 0, line: int | None = None
    ) -> None:
        """After ``U1, U2 = dynamicsymbols("U1 U2", real=True)`` (``Variables
        U{2}'``): the module's functions of time become the variables of those
        names; ``primes`` is the order of the derivatives declared (one for
        all, or one per function)."""
        self._declare_time_functions(functions, "variable", primes, line)

    @statement
    def declare_specified(
        self, *functions: Any, primes: int | Sequence[int] = 0, line: int | None = None
    ) -> None:
        """After ``PHI = dynamicsymbols("PHI", real=True)`` (``Specified PHI``):
        as :meth:`declare_variables`, for specified quantities."""
        self._declare_time_functions(functions, "specified", primes, line)

    def _declare_time_functions(
        self,
        functions: Sequence[Any],
        kind: str,
        primes: int | Sequence[int],
        line: int | None,
    ) -> None:
        orders = [primes] * len(functions) if isinstance(primes, int) else primes
        if len(orders) != len(functions):
            raise ValueError(f"{len(orders)} orders for {len(functions)} functions")
        for func, order in zip(functions, orders, strict=True):
            name = getattr(func, "name", None)
            want = (
                None if name is None else time_function(name, **self._assumptions(None))
            )
            if func != want:
                raise ValueError(
                    f"{name or func} must be dynamicsymbols({name!r},"
                    f" {self._assumptions(None) or 'no assumptions'})"
                )
            # the module's own function when it keeps its hash (the runtime's
            # dynamicsymbols), so that both are one object
            own = isinstance(func.func, TimeFunction)
            self.table.declare(
                name, kind, func if own else want, order=order, line=line
            )

    @statement
    def variables(self, *names: str, line: int | None = None) -> Any:
        """``Variables X', Y''``: functions of time; primes give the order."""
        return self._time_functions(names, "variable", line)

    @statement
    def specified(self, *names: str, line: int | None = None) -> Any:
        """``Specified PHI``: a function of time given by the user."""
        return self._time_functions(names, "specified", line)

    def _time_functions(
        self, names: Iterable[str], kind: str, line: int | None = None
    ) -> Any:
        out = []
        for spec in names:
            base = spec.rstrip("'")
            order = len(spec) - len(base)
            func = time_function(base.upper(), **self._assumptions(None))
            out.append(self.table.declare(base, kind, func, order=order, line=line))
        return one_or_tuple(out)

    @statement
    def imaginary(self, name: str, line: int | None = None) -> Any:
        """``Imaginary j``: ``j`` is the imaginary unit."""
        return self.table.declare(name, "imaginary", sp.I, line=line)

    # -------------------------------------------------------------- lookups

    def kind(self, name: str) -> str | None:
        """The kind of a declared or assigned name, or None."""
        entry = self.table.entries.get(parse_key(name).name)
        if entry is not None:
            return entry.kind
        if parse_key(name).name in self.table.stored:
            return "value"
        return None

    def symbol(self, name: str) -> Any:
        """The sympy object standing for ``name`` (``"X'"`` -> ``X(t).diff(t)``)."""
        key = parse_key(name)
        entry = self.table.entries.get(key.name)
        if entry is None:
            raise KeyError(f"{name!r} is not declared")
        obj = entry.obj
        if key.primes:
            obj = sp.Derivative(obj, t, key.primes) if obj is not t else None
            if obj is None:
                raise KeyError(f"{name!r}: T has no derivatives")
        return obj

    def value(self, name: str) -> Any:
        """The current value of an Autolev name, element or derivative."""
        key = parse_key(name)
        form = self.model.form_value(key)
        if form is not NotImplemented:
            return form
        if key.name in self.table.stored:
            val = self.table.stored[key.name]
            if key.index:
                return _element(val, key.index, name)
            if key.primes:
                raise KeyError(f"{name!r}: only scalars have derivatives here")
            return val
        entry = self.table.entries.get(key.name)
        if entry is None:
            raise KeyError(f"{name!r} is not defined")
        if key.index:
            raise KeyError(f"{name!r}: {key.name} is not a matrix")
        rhs_key = self.table.rhs_key(key.name, key.primes)
        if rhs_key in self.table.rhs:
            return self.table.rhs[rhs_key]
        return self.symbol(name)

    @statement
    def rhs(self, x: Any) -> Any:
        """``Rhs(y)``: the right-hand side of a name (or ``y`` itself)."""
        if isinstance(x, str):
            return self.value(x)
        return self.table.rhs.get(x, x)

    @statement
    def val(self, x: Any) -> Any:
        """The value behind a quantity symbol (used by dual functions)."""
        if isinstance(x, sp.Basic) and x in self.table.rhs:
            return self.table.rhs[x]
        return x

    @statement
    def form(self, x: Any) -> Any:
        """The value behind ``x`` as a command that reads its *form* sees it
        (``Coef``, ``Exclude``, ``Factor``, small ``Solve``...).  With
        ``AutoZ OFF`` the intermediates the derivation made are written out
        (they are internal: issue 21); with it ON they stay, as Autolev's
        ``Z``'s did."""
        x = self.val(x)
        book = self.book_if_made()
        if book is None or self.settings.autoz:
            return x
        return book.expand(x)

    # ------------------------------------------------------------ resolution

    @statement
    def explicit(self, y: Any, x: Any = None) -> Any:
        """``Explicit(y)``: ``y`` with every right-hand side substituted.

        (``Explicit(y, x)`` gives the same result: substituting everything makes
        ``y`` an explicit function of ``x``.)
        """
        return self.form(self.resolve(self.val(y)))

    def resolve(self, expr: Any, keep: Iterable[Any] = ()) -> Any:
        """Substitute right-hand sides until none is left.

        Objects in ``keep`` are left alone, so ``D(y, x)`` can see through every
        name except ``x`` itself.
        """
        return self.resolver(keep)(expr)

    def resolver(self, keep: Iterable[Any] = ()) -> Callable[[Any], Any]:
        """:meth:`resolve` with the substitution table built once, for applying
        to many expressions (the measure numbers of a vector)."""
        table, memo = self._table_without(keep)
        done = self._no_derivatives  # parts with no derivative to evaluate

        def apply(expr: Any) -> Any:
            for _ in range(100 if table else 0):
                new = _xreplace(expr, table, memo)
                if _same(new, expr):
                    break
                expr = new
            else:
                if table:  # pragma: no cover - assign() prevents cycles
                    raise RecursionError("right-hand sides refer to each other")
            return _derivatives_done(expr, done)

        return apply

    def _table_without(self, keep: Iterable[Any]) -> tuple[dict, dict]:
        """The right-hand sides but those of ``keep``, and the memo of
        substitutions by them (a part's answer depends on the part and the
        table only): kept while the table does not change, when every
        right-hand side is a sympy object (a mutable matrix may change in
        place).  A kept quantity without a right-hand side changes
        nothing, so the tables are found by those with one."""
        rhs = self.table.rhs
        kept = frozenset(k for k in (sp.sympify(x) for x in keep) if k in rhs)
        changes = self.table.rhs_changes
        tables = self._tables
        if tables is None or tables[0] != changes:
            tables = self._tables = (changes, {})
        found = tables[1].get(kept)
        if found is None:
            found = ({k: v for k, v in rhs.items() if k not in kept}, {})
            if all(isinstance(v, sp.Basic) for v in rhs.values()):
                tables[1][kept] = found
        return found

    # ------------------------------------------------------------ assignment

    @statement
    def assign(self, target: str, value: Any, *, line: int | None = None) -> Any:
        """``target = value``: store, respond, and return the Python binding.

        Scalar quantities bind to their symbol; matrices, vectors and dyadics
        bind to their value.  Settings (AutoRHS, Degrees, AutoEpsilon,
        Factoring) shape the stored value as in Autolev.
        """
        return self._store(target, value, line=line, rearrange=self.settings.factoring)

    @statement
    def assign_vector(self, *, line: int | None = None, **named: Any) -> Any:
        """``UVEC> = v`` written ``UVEC_vec = al.assign_vector(UVEC=v, line=56)``:
        one vector named by the keyword (the Autolev name without its ``>``);
        stored and answered as :meth:`assign` does, and returned."""
        return self._assign_named(named, ">", line)

    @statement
    def assign_dyadic(self, *, line: int | None = None, **named: Any) -> Any:
        """``I>> = d`` written ``I_dyad = al.assign_dyadic(I=d, line=9)``: as
        :meth:`assign_vector`, for a dyadic (``>>``)."""
        return self._assign_named(named, ">>", line)

    @statement
    def update_vector(self, *, line: int | None = None, **named: Any) -> Any:
        """``Express(V>, A)`` written ``V_vec = al.update_vector(V=..., line=9)``:
        :meth:`update` of the vector named by the keyword."""
        return self._assign_named(named, ">", line, self.update)

    @statement
    def update_dyadic(self, *, line: int | None = None, **named: Any) -> Any:
        """As :meth:`update_vector`, for a dyadic (``>>``)."""
        return self._assign_named(named, ">>", line, self.update)

    def _assign_named(
        self,
        named: dict[str, Any],
        suffix: str,
        line: int | None,
        store: Callable[..., Any] | None = None,
    ) -> Any:
        if len(named) != 1:
            raise TypeError(f"give one name=value, not {len(named)}")
        ((name, value),) = named.items()
        return (store or self.assign)(name.upper() + suffix, value, line=line)

    @statement
    def kd(self, eq: sp.Eq, *, line: int | None = None) -> sp.Eq:
        """``Q' = rhs`` given as the sympy equation ``Eq(Q.diff(t), rhs)``:
        assigned as :meth:`assign` does (same response), and returned, so a
        module holds its kinematical differential equations as sympy
        objects (``kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=32))``).
        """
        self.assign(self.name_of(eq.lhs), eq.rhs, line=line)
        return eq

    @statement
    def update(self, target: str, value: Any, *, line: int | None = None) -> Any:
        """Like :meth:`assign` but without automatic factoring (dual functions);
        the response prints the value as the command produced it."""
        count = len(self.responses)
        out = self._store(target, value, line=line, rearrange=False)
        self.responses[count:] = [
            replace(r, verbatim=True) for r in self.responses[count:]
        ]
        return out

    @statement
    def assign_all(
        self, targets: Iterable[str], values: Iterable[Any], *, line: int | None = None
    ) -> Any:
        """Assign several results (``Solve``, ``Eig(M, L, V)``); returns bindings."""
        targets = list(targets)
        values = list(values)
        if len(targets) != len(values):
            raise ValueError(f"{len(targets)} names for {len(values)} values")
        out = [
            self.assign(n, v, line=line) for n, v in zip(targets, values, strict=True)
        ]
        return one_or_tuple(out)

    def _store(
        self, target: str, value: Any, *, line: int | None, rearrange: bool
    ) -> Any:
        key = parse_key(target)
        value = self.normalize(value, rearrange=rearrange)
        form = self.model.assign_form(key, value, line=line)
        if form is not NotImplemented:
            return form
        if key.index:
            binding = self._store_element(key, value)
            label = str(Key(key.name, 0, key.index))
        elif key.name.endswith(">") or _is_nonscalar(value):
            if key.primes:
                raise ValueError(
                    f"cannot assign to derivative {target} of a non-scalar"
                )
            old = self.table.entries.get(key.name)
            if old is not None and old.kind == "quantity":
                del self.table.entries[key.name]
            self.table.stored[key.name] = value
            binding = value
            label = key.name
        else:
            binding = self._store_scalar(key, value)
            label = key.name + "'" * key.primes
        self.respond(label, self.value(label), line=line)
        return binding

    def _store_scalar(self, key: Key, value: Any) -> Any:
        entry = self.table.entries.get(key.name)
        self.table.stored.pop(key.name, None)
        if entry is not None and entry.kind in OBJECT_DECLS and not key.primes:
            entry = None  # a quantity named like a frame or point (ruletest7)
        if entry is None or entry.kind == "quantity":
            if key.primes:
                raise ValueError(f"{key.name} is not a variable; cannot assign {key}")
            if entry is None:
                sym = sp.Symbol(key.name, **self._assumptions(None))
                entry = Entry("quantity", sym)
                self.table.entries[key.name] = entry
                self.table.by_obj[sym] = key.name
            sym = entry.obj
            old = self.table.rhs.get(sym)
            if walks.appearing(value, [sym]):  # (shared parts walked once)
                if old is None:
                    raise ValueError(f"{key.name} is defined in terms of itself")
                value = value.xreplace({sym: old})
            self.table.set_rhs(sym, value)
            return sym
        if entry.kind in OBJECT_DECLS:
            raise ValueError(f"{key.name} is a {entry.kind}, not a scalar")
        rkey = self.table.rhs_key(key.name, key.primes)
        if rkey in self.table.rhs and walks.appearing(value, [rkey]):
            value = value.xreplace({rkey: self.table.rhs[rkey]})
        if key.primes > entry.order:
            entry.order = key.primes
        self.table.set_rhs(rkey, value)
        return self.symbol(str(key))

    def _store_element(self, key: Key, value: Any) -> Any:
        current = self.table.stored.get(key.name)
        if current is None:
            current = sp.zeros(*_shape_for(key.index))
        elif not isinstance(current, sp.MatrixBase):
            raise ValueError(f"{key.name} is not a matrix")
        # A new matrix each time (a value handed out earlier never changes);
        # a mutable one copies its entries as they are (no conversion).
        current = (
            current.copy()
            if isinstance(current, sp.MutableDenseMatrix)
            else sp.Matrix(current)
        )
        if len(key.index) == 1:
            (i,) = key.index
            if current.cols == 1 or current.rows == 0:
                if i > current.rows:
                    current = current.col_join(
                        sp.zeros(i - current.rows, max(current.cols, 1))
                    )
                current[i - 1, 0] = value
            elif current.rows == 1:
                if i > current.cols:
                    current = current.row_join(sp.zeros(1, i - current.cols))
                current[0, i - 1] = value
            else:
                raise ValueError(
                    f"{key.name} has {current.rows} rows and {current.cols}"
                    " columns; use two indices"
                )
        else:
            i, j = key.index
            if i > current.rows:
                current = current.col_join(sp.zeros(i - current.rows, current.cols))
            if j > current.cols:
                current = current.row_join(sp.zeros(current.rows, j - current.cols))
            current[i - 1, j - 1] = value
        old = self.table.entries.get(key.name)
        if old is not None and old.kind == "quantity":
            del self.table.entries[key.name]
        self.table.stored[key.name] = current
        return current

    # ---------------------------------------------------------- normalizing

    def normalize(self, value: Any, *, rearrange: bool = False) -> Any:
        """Apply Autolev's automatic treatment of a new value."""
        # Floats are looked for once in all of a vector's or a matrix's
        # entries, whose parts are mostly shared (the entries of a Jacobian
        # over the same intermediates), rather than entry by entry.
        return self._normalized(
            value, rearrange, _may_hold_floats(value, self._no_floats)
        )

    def _normalized(self, value: Any, rearrange: bool, floats: bool) -> Any:
        """:meth:`normalize`; ``floats``: whether ``value`` may hold a
        float (if not, :meth:`_numbers` would change nothing)."""
        if _is_vectorial(value):
            return walks.vmap(value, lambda e: self._normalized(e, rearrange, floats))
        if isinstance(value, list | tuple):
            if any(_is_vectorial(v) for v in value):
                return tuple(self._normalized(v, rearrange, floats) for v in value)
            value = sp.Matrix(value)
        if isinstance(value, sp.MatrixBase):
            return sp.Matrix(value).applyfunc(
                lambda e: self._normalized(e, rearrange, floats)
            )
        if not isinstance(value, sp.Basic):
            try:
                value = sp.sympify(value)
            except (sp.SympifyError, TypeError):
                return value
        if not isinstance(value, sp.Expr):
            return value
        if floats:
            value = self._numbers(value)
        if self._autotaylor is not None:
            from .algebra import taylor

            orders, points = self._autotaylor
            value = taylor(
                self.resolve(value, keep=[p[0] for p in points]), orders, points
            )
        mode = self.settings.autorhs
        # Auxiliary speeds stay symbols (Constrain made them 0 or solved
        # them, but later velocities need them for the partial velocities).
        kept = self.model.auxiliary_kept()
        if mode == "ALL":
            value = self.resolve(value, kept)
        elif mode == "ON":
            simple = self._simple_rhs(kept)
            if simple:
                value = _xreplace(value, simple)
        if rearrange and self.settings.factoring and value.is_Add:
            # (sympy's == tells floats of two precisions apart: a value is
            # found only by one with the same text)
            found = self._factored.get(value)
            if found is None:
                found = factor_terms(value) if is_small(value) else value
                self._factored[value] = found
            value = found
        return value

    def _simple_rhs(self, kept: list) -> dict:
        """The right-hand sides that are numbers (AutoRHS ON substitutes
        them), but the ``kept`` quantities': made once while the table's
        right-hand sides do not change (``NameTable.set_rhs`` counts every
        change; a number is immutable), not for each value normalized (each
        entry of a matrix, each measure number of a vector)."""
        changes, keep = self.table.rhs_changes, frozenset(kept)
        found = self._simple
        if found is None or found[0] != changes or found[1] != keep:
            table = {
                k: v
                for k, v in self.table.rhs.items()
                if _is_simple(v) and k not in keep
            }
            found = self._simple = (changes, keep, table)
        return found[2]

    def _numbers(self, value: sp.Expr) -> sp.Expr:
        floats = walks.atoms(value, sp.Float)
        if not floats:
            return value
        eps = self.settings.autoepsilon
        table = {}
        for f in floats:
            nearest = round(float(f))
            if abs(float(f) - nearest) <= eps:
                table[f] = sp.Integer(nearest)
            else:
                text = sp.sstr(f, full_prec=False)
                digits = text.lstrip("-").replace(".", "").lstrip("0").split("e")[0]
                if len(digits.rstrip("0")) <= 12:
                    table[f] = sp.Rational(text)
        return walks.xreplace(value, table) if table else value

    # ------------------------------------------------------------ responses

    def respond(self, label: str, value: Any, *, line: int | None = None) -> None:
        """Record a ``-> (n) LABEL = value`` response (printed by ``transcript``)."""
        self.responses.append(
            Response(
                line,
                label.upper(),
                value,
                self.settings.digits,
                autoz=self.settings.autoz,
            )
        )

    @property
    def intermediates(self) -> Any:
        """The book of ``Z`` intermediates (:mod:`al2py_runtime.intermediates.autoz`) while
        ``AutoZ`` is ON (None while it is OFF).  Intermediates made while it
        was ON stay valid."""
        if not self.settings.autoz:
            return None
        return self.book

    @property
    def book(self) -> Any:
        """The book of ``Z`` intermediates, made on first use whatever
        ``AutoZ`` says: with ``AutoZ OFF`` the large linear solves
        (:meth:`solver_book`) name their entries too, and responses write
        them out."""
        book = self.__dict__.get("_book")
        if book is None:
            from .intermediates.autoz import Intermediates

            book = self._book = Intermediates(taken=self.table.entries)
        book.rates = frozenset(
            u for u in self.model.generalized_speeds() if isinstance(u, sp.Derivative)
        )
        zee_not = self.table.stored.get("ZEE_NOT")
        if isinstance(zee_not, sp.MatrixBase):
            book.exclude = frozenset(sp.sympify(x) for x in zee_not)
        return book

    #: with ``AutoZ OFF``, equations larger than this (tree nodes, written
    #: out) are solved by elimination, whatever the number of unknowns
    CLOSED_FORM_LIMIT = 5000

    def solver_book(self, unknowns: int, eqs: Any = None) -> Any:
        """The book for a linear solve of ``unknowns`` unknowns: the
        intermediates while ``AutoZ`` is ON; with it OFF, the same book for a
        system larger than :data:`al2py_runtime.intermediates.elimination.SMALL` (a closed
        form swells with the size: a 9x9 Cramer's rule did not finish in 15
        minutes) or for equations ``eqs`` larger than
        :attr:`CLOSED_FORM_LIMIT` written out (a 2x2 Cramer's rule over a
        rolling disc's written-out equations did not finish in 5 minutes),
        else None (closed forms, readable, as Autolev prints them)."""
        from .intermediates.elimination import SMALL

        book = self.intermediates
        if book is None and unknowns > SMALL:
            book = self.book
        if book is None and eqs is not None:
            if _larger_than(list(sp.Matrix(eqs)), self.CLOSED_FORM_LIMIT):
                book = self.book
        return book

    def book_if_made(self) -> Any:
        """The book if any intermediate was ever made (for expansion)."""
        return self.__dict__.get("_book")

    @statement
    def show(self, label: str, value: Any, *, line: int | None = None) -> Any:
        """A bare expression statement: respond with its value."""
        value = self.normalize(value)
        self.respond(label, value, line=line)
        return value

    def names(self) -> Mapping[str, Any]:
        """A read-only, case-insensitive view: Autolev name -> current value
        (a generated module asks for it last: its derivation is done)."""
        self._watch.stop()
        if self.statements.settle:
            self.statements.settle = False
            # the derived model lives as long as its module: moved out of
            # the collector's sight (``gc.freeze``), as each statement's
            # objects were, so that no later collection -- nor the several
            # at the process's exit, a tenth of a bicycle's import -- walks
            # its objects again.  A derivation leaves next to no cyclic
            # garbage behind (a few thousand small objects for DAS3's
            # million), so nothing of note is kept that a collection would
            # have freed.
            gc.freeze()
        return AutolevNames(self)

    def name_of(self, obj: Any) -> str:
        """The Autolev spelling of a declared symbol or derivative (``"X'"``)."""
        primes = 0
        if (
            isinstance(obj, sp.Derivative)
            and len(obj.variables)
            and set(obj.variables) == {t}
        ):
            primes = len(obj.variables)
            obj = obj.expr
        name = self.table.by_obj.get(obj)
        if name is None:
            raise KeyError(f"{obj} is not an Autolev name")
        return name + "'" * primes

    # ------------------------------------------------------------- files

    @statement
    def save(self, filename: str, *, line: int | None = None) -> None:
        """``SAVE file.all``/``SAVE file.al``: written by ``python module.py``."""
        self._saves.append((filename, line))

    @statement
    def exit(self, *, line: int | None = None) -> None:
        """``Exit``/``Quit``: the script ends here (the transcript stops too)."""
        self._exit_line = line

    def transcript(self, source: Iterable[str], copies: int = 1) -> list[str]:
        """The transcript lines Autolev would print for ``source``.

        ``copies`` 2: a long transcript is printed by this process and a
        forked copy of it at once (:mod:`.names.responses`; ``python
        model.py`` asks for it where it may, :func:`.names.responses.side_by_side`):
        the same lines."""
        from .names.responses import ResponseLines
        from .names.transcript import printed_transcript

        lines = list(source)
        if self._exit_line is not None:
            lines = lines[: self._exit_line]
        # printed once: ``python model.py`` prints it and saves it (``.all``)
        key = (tuple(lines), len(self.responses))
        memo = self.__dict__.get("_transcript")
        if memo is not None and memo[0] == key:
            return list(memo[1])
        # the printer's memos make many small objects that all stay: the
        # garbage collector, run at its default pace, walks them again and
        # again (a fifth of the printing) and finds nothing
        with collector.Quiet():
            with progress.task("printing the transcript", unit="responses") as task:
                task.doing("naming intermediates")
                shown = self._with_intermediates(self.responses)
            # a copy is forked (if any) before the next progress line's
            # thread starts
            printed = ResponseLines(shown, self.model.displayed, copies)
            with progress.task(
                "printing the transcript", len(shown), unit="responses"
            ) as task:
                out = printed_transcript(lines, printed, task.advance)
        self.__dict__["_transcript"] = (key, out)
        return list(out)

    def _with_intermediates(self, responses: list[Response]) -> list[Response]:
        """Responses given while AutoZ was ON show intermediates by name, each
        defined (``Z12 = ...``) just before the first response that uses it;
        those given while it was OFF write them out."""
        book = self.book_if_made()
        if book is None:
            return list(responses)

        from .intermediates.autoz import has_intermediates

        out: list[Response] = []
        defined: set[Any] = set()
        for r in responses:
            if r.autoz and not r.verbatim:
                r = replace(r, value=_named_for_display(book, r.value))
            value = r.value
            parts = [value]
            if isinstance(value, sp.MatrixBase):
                parts = list(value)
            elif isinstance(value, Vector):
                parts = [m for m, _frame in value.args]
            if not any(has_intermediates(p) for p in parts):
                out.append(r)
            elif not r.autoz:
                out.append(replace(r, value=book.expand(value)))
            else:
                for z in book.ordered(parts, defined):
                    defined.add(z)
                    out.append(
                        Response(
                            r.line, book.label(z), book.definition(z), r.digits, True
                        )
                    )
                out.append(r)
        return out

    def print_transcript(self, source: Iterable[str], copies: int = 1) -> None:
        """Print :meth:`transcript` (``copies``: as there)."""
        for line in self.transcript(source, copies):
            print(line)

    def write_saved_files(self, source: Iterable[str], outdir: str = ".") -> list[str]:
        """Write the files named by ``SAVE`` into ``outdir`` under their base
        names (``Save ../x.all`` writes ``OUTDIR/x.all``), never overwriting an
        existing ``.al`` file.  A file the system refuses (a name too long,
        a folder that cannot be made) stops with the ``Save`` statement's
        line: :class:`~.safety.AutolevRuntimeError`."""
        from .safety import AutolevRuntimeError, output_path

        written = []
        source = list(source)
        for name, line in self._saves:
            path = output_path(outdir, name)
            if path is None:
                print(f"note: Save {name}: not a file name; nothing written")
                continue
            try:
                if name.lower().endswith(".all"):
                    text = "\n".join(self.transcript(source)) + "\n"
                elif path.exists():
                    print(f"note: not overwriting existing {path}")
                    continue
                else:
                    text = "\n".join(source) + "\n"
                path.parent.mkdir(parents=True, exist_ok=True)
                with open(path, "w", encoding="utf-8") as f:
                    f.write(text)
            except OSError as exc:
                raise AutolevRuntimeError(
                    f"Save {name}: cannot write {path}: {exc.strerror or exc}",
                    self.filename,
                    line,
                    self._source_line(source, line),
                ) from None
            written.append(str(path))
        return written

    @staticmethod
    def _source_line(source: list[str], line: int | None) -> str:
        """Line ``line`` (1-based) of ``source``, or ""."""
        if line is None or not 0 < line <= len(source):
            return ""
        return source[line - 1]

    # ------------------------------------------------ mathematical commands

    @statement
    def d(self, y: Any, x: Any, frame: Any = None) -> Any:
        """``D(y, x)``: partial derivative, seeing through right-hand sides.

        With a matrix ``x`` (``D(Xp, Xm)``) the result is the Jacobian whose
        row i, column j is the derivative of element i of ``y`` by element j.
        """
        x = (
            x.applyfunc(self._through_alias)
            if isinstance(x, sp.MatrixBase)
            else self._through_alias(x)
        )
        if frame is not None or _is_vectorial(self.val(y)):
            return self.model.vector_d(self.resolve(self.val(y), keep=[x]), x, frame)
        diff = _Partial(self.book_if_made())
        if isinstance(x, sp.MatrixBase):
            xs = list(x)
            y = self.resolve(self.val(y), keep=xs)
            ys = list(y) if isinstance(y, sp.MatrixBase) else [y]
            return sp.Matrix(len(ys), len(xs), lambda i, j: diff(ys[i], xs[j]))
        y = self.resolve(self.val(y), keep=[x])
        if isinstance(y, sp.MatrixBase):
            return y.applyfunc(lambda e: diff(e, x))
        return diff(y, x)

    def _through_alias(self, x: Any) -> Any:
        """An assigned name that stands for one quantity (``T4 = Tphi``) is
        that quantity in ``D(y, T4)``: Autolev substitutes an assigned name's
        value wherever it is used, so ``D(u4', T4)`` is ``D(u4', Tphi)``
        (WhippleDynamics.c's ``bMat`` column of ``T4``).  A name for an
        expression, or a declared quantity, stays a name."""
        if not isinstance(x, sp.Symbol) or x not in self.table.rhs:
            return x
        entry = self.table.entries.get(self.table.by_obj.get(x, ""))
        if entry is None or entry.kind != "quantity":
            return x
        value = self.resolve(x)
        atom = isinstance(value, sp.Symbol | sp.Derivative | AppliedUndef)
        return value if atom else x

    @statement
    def dt(self, y: Any, frame: Any = None) -> Any:
        """``Dt(y)``: total time derivative, seeing through right-hand sides
        (except the auxiliary speeds', see ``Model._auxiliary_kept``)."""
        keep = self.model.auxiliary_kept()
        if frame is not None or _is_vectorial(self.val(y)):
            return self.model.vector_dt(self.resolve(self.val(y), keep), frame)
        y = self.resolve(self.val(y), keep)
        if isinstance(y, sp.MatrixBase):
            return y.applyfunc(scalar_dt)
        return scalar_dt(y)

    @statement
    def evaluate(self, y: Any, subs: Mapping[Any, Any] | None = None) -> Any:
        """``Evaluate(y, a=x, b=2)``: substitute, seeing through other names."""
        subs = {sp.sympify(k): sp.sympify(v) for k, v in (subs or {}).items()}
        # form() after resolve: other names' values may hold intermediates
        y = self.form(self.resolve(self.val(y), keep=subs))
        y = doit_derivatives(_xreplace(y, subs))
        book = self.book_if_made()
        if self.settings.degrees and self.settings.autoz and book is not None:
            # numbers reach trig arguments inside intermediates' definitions
            # (with AutoZ OFF form() has written them out already)
            y = book.expand(y)
        if self.settings.degrees:
            y = (
                y.applyfunc(degrees_pass)
                if isinstance(y, sp.MatrixBase)
                else degrees_pass(y)
            )
        return y

    @statement
    def taylor(self, y: Any, order: Any, points: Iterable[tuple[Any, ...]]) -> Any:
        """``Taylor(y, 0:2, w=a, x=0:dx)``; see :func:`algebra.taylor`."""
        from . import algebra

        pts = [(p[0], p[1], p[2] if len(p) > 2 else None) for p in points]
        orders = tuple(order) if isinstance(order, tuple | list) else (0, int(order))
        y = self.form(self.resolve(self.val(y), keep=[p[0] for p in pts]))
        return algebra.taylor(y, orders, pts)

    @statement
    def solve(
        self, eqs: Any, unknowns: Iterable[Any], *, line: int | None = None
    ) -> tuple:
        """``Solve(A, x1, x2)``: solve linear equations and assign the unknowns."""
        from . import algebra

        # Solve(Zero, qdd): a matrix of unknowns stands for its elements.
        unknowns = [
            x
            for u in unknowns
            for x in (list(u) if isinstance(u, sp.MatrixBase) else [u])
        ]
        if isinstance(eqs, sp.MatrixBase):
            eqs = sp.Matrix(eqs)
        else:
            eqs = sp.Matrix([self.val(eqs)])
        eqs = self.resolve(eqs, keep=[*unknowns, *self.specified_inputs(unknowns)])
        book = self.solver_book(len(unknowns), eqs)
        if book is None:  # a closed form reads the equations' form
            eqs = self.form(eqs)
        zero = self.model.configuration_variables() if book is not None else ()
        solutions = algebra.solve_linear(eqs, unknowns, book, zero)
        names = [self.name_of(u) for u in unknowns]
        return self.assign_all(names, solutions, line=line)

    def specified_inputs(self, unknowns: list[Any]) -> list[Any]:
        """Specified quantities with an equation that ``Solve`` keeps as
        names: Autolev's programs compute them first ("Quantities which were
        specified") and solve with the name (PendulumDynamics.c's
        ``D(omega', torque)`` is not zero).  One whose value involves an
        unknown is substituted, so the equations stay complete."""
        keep = []
        for entry in self.table.entries.values():
            if entry.kind != "specified" or entry.obj not in self.table.rhs:
                continue
            if not sp.sympify(self.resolve(entry.obj)).has(*unknowns):
                keep.append(entry.obj)
        return keep

    @statement
    def eig(self, m: Any) -> Any:
        from . import algebra

        return algebra.eig(self.val(m))

    @statement
    def eig_vectors(self, m: Any) -> tuple[Any, Any]:
        from . import algebra

        return algebra.eig_vectors(self.val(m))

    @statement
    def autotaylor(self, order: Any, points: Iterable[tuple[Any, ...]]) -> None:
        """``AutoTaylor(0:2, w=a, x=0)``: expand every later assigned value in a
        Taylor series about these points (linearization)."""
        pts = [(p[0], p[1], p[2] if len(p) > 2 else None) for p in points]
        orders = tuple(order) if isinstance(order, tuple | list) else (0, int(order))
        self._autotaylor = (orders, pts)

    @statement
    def zee(self, y: Any, x: Any = None) -> Any:
        """``Zee(y)``: Autolev's display with Z variables; values are unchanged
        (numerical code always uses common subexpressions)."""
        return self.val(y)

    autoz = zee

    # Autolev's algebra and matrix commands (their first argument resolved)

    @statement
    def expand(self, y: Any, *args: Any) -> Any:
        """Autolev ``Expand``: see :func:`al2py_runtime.algebra.expand`."""
        return algebra.expand(self.form(y), *args)

    @statement
    def factor(self, y: Any, *args: Any) -> Any:
        """Autolev ``Factor``: see :func:`al2py_runtime.algebra.factor`."""
        return algebra.factor(self.form(y), *args)

    @statement
    def polynomial(self, y: Any, *args: Any) -> Any:
        """Autolev ``Polynomial``: see :func:`al2py_runtime.algebra.polynomial`."""
        return algebra.polynomial(self.form(y), *args)

    @statement
    def roots(self, y: Any, *args: Any) -> Any:
        """Autolev ``Roots``: see :func:`al2py_runtime.algebra.roots`."""
        return algebra.roots(self.form(y), *args)

    @statement
    def coef(self, y: Any, *args: Any) -> Any:
        """Autolev ``Coef``: see :func:`al2py_runtime.algebra.coef`."""
        return algebra.coef(self.form(y), *args)

    @statement
    def exclude(self, y: Any, *args: Any) -> Any:
        """Autolev ``Exclude``: see :func:`al2py_runtime.algebra.exclude`."""
        return algebra.exclude(self.form(y), *args)

    @statement
    def include(self, y: Any, *args: Any) -> Any:
        """Autolev ``Include``: see :func:`al2py_runtime.algebra.include`."""
        return algebra.include(self.form(y), *args)

    @statement
    def arrange(self, y: Any, *args: Any) -> Any:
        """Autolev ``Arrange``: see :func:`al2py_runtime.algebra.arrange`."""
        return algebra.arrange(self.form(y), *args)

    @statement
    def replace(self, y: Any, *args: Any) -> Any:
        """Autolev ``Replace``: see :func:`al2py_runtime.algebra.replace`."""
        return algebra.replace(self.form(y), *args)

    @statement
    def epsilon(self, y: Any, *args: Any) -> Any:
        """Autolev ``Epsilon``: see :func:`al2py_runtime.algebra.epsilon`."""
        return algebra.epsilon(self.form(y), *args)

    @statement
    def rows(self, y: Any, *args: Any) -> Any:
        """Autolev ``Rows``: see :func:`al2py_runtime.matrices.rows`."""
        return matrices.rows(self.val(y), *args)

    @statement
    def cols(self, y: Any, *args: Any) -> Any:
        """Autolev ``Cols``: see :func:`al2py_runtime.matrices.cols`."""
        return matrices.cols(self.val(y), *args)

    @statement
    def det(self, y: Any, *args: Any) -> Any:
        """Autolev ``Det``: see :func:`al2py_runtime.matrices.det`."""
        return matrices.det(self.form(y), *args)

    @statement
    def diagmat(self, y: Any, *args: Any) -> Any:
        """Autolev ``Diagmat``: see :func:`al2py_runtime.matrices.diagmat`."""
        return matrices.diagmat(self.val(y), *args)

    @statement
    def element(self, y: Any, *args: Any) -> Any:
        """Autolev ``Element``: see :func:`al2py_runtime.matrices.element`."""
        return matrices.element(self.val(y), *args)

    @statement
    def inv(self, y: Any, *args: Any) -> Any:
        """Autolev ``Inv``: see :func:`al2py_runtime.matrices.inv`."""
        return matrices.inv(self.form(y), *args)

    @statement
    def transpose(self, y: Any, *args: Any) -> Any:
        """Autolev ``Transpose``: see :func:`al2py_runtime.matrices.transpose`."""
        return matrices.transpose(self.val(y), *args)

    @statement
    def block(self, rows: Any) -> Any:
        from .matrices import block

        return block(rows)


# ---------------------------------------------------------------- helpers


def _split_sign(spec: str) -> tuple[str, str | None]:
    if spec.endswith(("+", "-")):
        return spec[:-1], spec[-1]
    return spec, None


def _is_nonscalar(value: Any) -> bool:
    if isinstance(value, sp.MatrixBase):
        return True
    return not isinstance(value, sp.Basic | int | float | complex)


def _is_simple(value: Any) -> bool:
    """AutoRHS ON substitutes numbers (see docs/semantics.md)."""
    return isinstance(value, sp.Expr) and value.is_number


def _shape_for(index: tuple[int, ...]) -> tuple[int, int]:
    return (0, 1) if len(index) == 1 else (0, 0)


def _element(val: Any, index: tuple[int, ...], name: str) -> Any:
    if not isinstance(val, sp.MatrixBase):
        raise KeyError(f"{name!r}: not a matrix")
    try:
        if len(index) == 1:
            if val.cols == 1:
                return val[index[0] - 1, 0]
            if val.rows == 1:
                return val[0, index[0] - 1]
            raise KeyError(f"{name!r}: matrix is not a row or column; use two indices")
        i, j = index
        if i < 1 or j < 1:
            raise IndexError
        return val[i - 1, j - 1]
    except IndexError:
        raise KeyError(
            f"{name!r}: index out of range for a {val.rows}x{val.cols} matrix"
        ) from None


def _larger_than(exprs: list, limit: int) -> bool:
    """Whether ``exprs`` written out (intermediates by their definitions)
    have more than ``limit`` tree nodes; at most ``limit`` nodes are
    visited."""
    from .intermediates.autoz import Intermediate

    count = 0
    stack = [e for e in exprs if isinstance(e, sp.Basic)]
    while stack:
        e = stack.pop()
        count += 1
        if count > limit:
            return True
        if isinstance(e, Intermediate):
            stack.append(e.book.definition(e))
        else:
            stack.extend(e.args)
    return False


def _xreplace(expr: Any, table: dict, memo: dict | None = None) -> Any:
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: _xreplace(e, table, memo))
    if isinstance(expr, sp.Basic):
        # sympy's result, shared parts once, the products and sums rebuilt
        # without sympy's general case where their parts allow
        return substitute(expr, table, memo)
    if hasattr(expr, "xreplace"):
        return expr.xreplace(table)
    return expr


def _derivatives_done(expr: Any, done: set) -> Any:
    """``doit_derivatives(expr)``, which gives ``expr`` itself when none of
    its derivatives is one to evaluate.  ``done``: parts found to hold no
    derivative to evaluate by earlier calls (the resolved expressions of
    one resolver share most of their parts); not walked again, and the
    parts of ``expr`` join them when it holds none either."""
    if not isinstance(expr, sp.Basic) or isinstance(expr, sp.MatrixBase):
        return doit_derivatives(expr)
    seen = {expr}
    todo = [] if expr in done else [expr]
    while todo:
        e = todo.pop()
        if isinstance(e, sp.Derivative) and doit_derivatives(e) is not e:
            return doit_derivatives(expr)
        for a in e.args:
            if a not in seen and a not in done:
                seen.add(a)
                todo.append(a)
    done.update(seen)
    return expr


def _same(a: Any, b: Any) -> bool:
    """Structurally the same (did a substitution change anything?)."""
    if isinstance(a, sp.MatrixBase) or isinstance(b, sp.MatrixBase):
        return isinstance(a, sp.MatrixBase) and isinstance(b, sp.MatrixBase) and a == b
    from sympy.physics.vector import Dyadic, Vector

    if isinstance(a, Vector | Dyadic) or isinstance(b, Vector | Dyadic):
        # Vector == Vector expands dot products in a frame: far too slow for
        # a "did anything change" test on large models.
        return type(a) is type(b) and a.args == b.args
    return a == b


_TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)
_ATRIG = (sp.asin, sp.acos, sp.atan, sp.acot, sp.atan2)


def degrees_pass(expr: sp.Expr) -> sp.Expr:
    """With ``Degrees ON``, numeric trig arguments and results are in degrees.

    Used by ``Evaluate``: substituting numbers can make a trig argument numeric.
    """
    if not expr.has(*_TRIG, *_ATRIG):
        return expr

    def convert(e: sp.Basic) -> sp.Basic:
        # Evaluate numerically so a value is never converted twice.
        if isinstance(e, _TRIG) and e.args[0].is_number:
            out = e.func(e.args[0] * sp.pi / 180)
            return out if out.is_Rational else out.evalf(20)
        if isinstance(e, _ATRIG) and all(a.is_number for a in e.args):
            return (e * 180 / sp.pi).evalf(20)
        return e

    return expr.replace(lambda e: isinstance(e, _TRIG + _ATRIG), convert)


def _may_hold_floats(value: Any, clean: set) -> bool:
    """False only when no scalar of ``value`` (a sympy object, or a vector,
    dyadic, matrix or list of them) holds a ``Float``: every distinct part
    of all of them walked once, but those in ``clean`` (parts found to hold
    none by earlier calls), which the parts walked join when none holds
    one."""
    roots: list = []
    todo = [value]
    while todo:
        v = todo.pop()
        if isinstance(v, Vector):
            roots.extend(x for m, _ in v.args for x in m)
        elif isinstance(v, Dyadic):
            roots.extend(c for c, _, _ in v.args)
        elif isinstance(v, sp.MatrixBase | list | tuple):
            todo.extend(v)
        elif isinstance(v, sp.Basic):
            roots.append(v)
        else:  # sympified later (a Python float is a Float)
            return True
    # the parts met join ``clean`` as they are met (one lookup each), and
    # leave it again if a Float is found (seldom)
    met = []
    for e in roots:
        if e not in clean:
            clean.add(e)
            met.append(e)
    todo = list(met)
    while todo:
        e = todo.pop()
        if isinstance(e, sp.Float):
            clean.difference_update(met)
            return True
        for a in e.args:
            if a not in clean:
                clean.add(a)
                met.append(a)
                todo.append(a)
    return False


def _is_vectorial(value: Any) -> bool:
    from sympy.physics.vector import Dyadic, Vector

    return isinstance(value, Vector | Dyadic)


#: a response (given while AutoZ was ON) with more tree nodes than this is
#: printed with its parts named: its text would grow with every repetition
#: of a shared part (a tree of millions of nodes holds a few hundred
#: distinct ones)
SHOWN_NODES = 20000


def _named_for_display(book: Any, value: Any) -> Any:
    """``value`` with each scalar too large to print as a tree named as
    AutoZ names: linear in the derivatives it holds (accelerations stay
    visible), each coefficient and the rest an intermediate."""

    def one(e: Any) -> Any:
        if not isinstance(e, sp.Expr) or is_small(e, SHOWN_NODES):
            return e
        found = walks.atoms(e, sp.Derivative)
        return book.name_linear(e, sorted(found, key=sp.default_sort_key))

    if not isinstance(value, sp.Basic | sp.MatrixBase | Vector | Dyadic):
        return value
    return walks.vmap(value, one)


class _Partial:
    """``D(y, x)`` for the entries of one command: sympy's ``diff``, or with
    AutoZ on, the book's walk (the book's memo of each variable, shared by
    every ``D()`` of the script, whose arguments share subexpressions; no
    ``Derivative`` objects built)."""

    def __init__(self, book: Any) -> None:
        self.book = book

    def __call__(self, y: Any, x: Any) -> Any:
        if not isinstance(y, sp.Basic):
            return sp.Integer(0)
        book = self.book
        if book is None or x == t or not book.is_variable(x):
            return sp.diff(y, x)
        return book.derivative(y, x)


class AutolevNames(Mapping):
    """Read-only view of a workspace: ``AUTOLEV["ZERO[2]"]``, ``AUTOLEV["X'"]``.

    Values are full expressions: intermediates are written out (the
    workspace itself, ``al.value(name)``, keeps them), unless the full
    expression would exceed :attr:`WRITE_OUT` tree nodes: then the value
    comes back over its named intermediates (``Z12``, each a sympy function
    whose definition sympy can differentiate and evaluate), at once, and
    :meth:`written_out` writes it out in full (time and memory grow with
    the size: minutes for a bicycle's accelerations)."""

    __slots__ = ("_ws",)

    #: largest value (tree nodes, written out) that ``AUTOLEV[name]`` writes out
    WRITE_OUT = 20_000

    def __init__(self, ws: Workspace) -> None:
        self._ws = ws

    def __getitem__(self, name: str) -> Any:
        value = self._ws.value(name)
        book = self._ws.book_if_made()
        if book is None or not isinstance(value, sp.Basic | sp.MatrixBase):
            return value if book is None else book.expand(value)
        if book.expanded_size(value) > self.WRITE_OUT:
            return value
        return book.expand(value)

    def written_out(self, name: str) -> Any:
        """``AUTOLEV[name]`` with every intermediate written out, however
        large (may take minutes)."""
        value = self._ws.value(name)
        book = self._ws.book_if_made()
        return value if book is None else book.expand(value)

    def __iter__(self) -> Iterator[str]:
        return iter(self._ws)

    def __len__(self) -> int:
        return len(self._ws)

    def __contains__(self, name: object) -> bool:
        return name in self._ws

    def __repr__(self) -> str:
        return f"<Autolev names of {self._ws.filename}: {', '.join(self)}>"
