"""Code generation: one small emitter per IR node, found by node type.

Statement emitters (``stmt_<Node>``) return lines of Python; expression
emitters (``expr_<Node>``) return ``(code, precedence)`` so parentheses appear
only where Python needs them.  Built-in functions are spelled through the
rows of :mod:`al2py_runtime.vocabulary`.  Every string that comes from the ``.al``
file reaches the output through :func:`repr` or a ``#`` comment, so a script
cannot inject code.
"""

from __future__ import annotations

import ast
import bisect
import io
import re
import tokenize
from collections import defaultdict

from al2py_runtime import vocabulary as vocab
from al2py_runtime.safety import ECHO, echo_lines
from al2py_runtime.vocabulary import (
    BUILTINS,
    Builtin,
    Decl,
    Form,
    Kind,
    Match,
    Style,
)
from al2py_runtime.vocabulary.calls import MODEL_COMMANDS

from . import ir
from .analysis import (
    SOLVE_OPTIONS,
    Facts,
    StmtFacts,
    Symbol,
    input_names,
    int_literal,
)
from .errors import InternalError, SemanticError
from .static_checks import unknown_call_message

__all__ = ["Generator", "Imports", "attach_echoes"]

# Python operator precedence (higher binds tighter).
ATOM, POWER, UNARY, MUL, ADD = 100, 90, 80, 70, 60

_RUNTIME = "al2py_runtime"
_FUNCTIONS = "al2py_runtime.functions"
_VECTOR = "sympy.physics.vector"
_UNIT_AXES = {"1": "x", "2": "y", "3": "z"}
_POINT_THEORIES = {
    "V2PTS": "v2pt_theory",
    "A2PTS": "a2pt_theory",
    "V1PT": "v1pt_theory",
    "A1PT": "a1pt_theory",
}
#: syntactical forms whose assignment is sympy's own setter
#: (``P_O_P> = v`` is ``P.set_pos(O, v)``), by form
_SYMPY_SETTERS = {
    Form.POS: "set_pos",
    Form.VEL: "set_vel",
    Form.ACC: "set_acc",
    Form.ANGVEL: "set_ang_vel",
    Form.ANGACC: "set_ang_acc",
}


#: syntactical forms that are loads (``Force_P>``, ``Torque_B>``)
_LOADS = (Form.FORCE, Form.TORQUE)


class Imports:
    """The names a generated module imports, by module."""

    def __init__(self) -> None:
        self._by_module: dict[str, set[str]] = defaultdict(set)

    def use(self, module: str, name: str) -> str:
        self._by_module[module].add(name)
        return name

    def lines(self) -> list[str]:
        out = []
        for module in sorted(self._by_module):
            names = ", ".join(sorted(self._by_module[module], key=_isort_key))
            out.append(f"from {module} import {names}")
        return out


class Generator:
    """Turns analysed statements into the body of a Python module."""

    def __init__(self, facts: Facts, lines: tuple[str, ...]) -> None:
        self.facts = facts
        self.lines = lines
        self.imports = Imports()
        self.imports.use(_RUNTIME, "Workspace")
        self._facts = StmtFacts()
        self._line = 0
        self.stopped_at: int | None = None
        self.has_job = False  # a CODE statement was generated
        #: what ``--help`` lists: Inputs ``(name, value as written, unit)``
        #: and CODE jobs ``(kind, file, line)``, in script order
        self.help_inputs: list[tuple[str, str, str | None]] = []
        self.help_jobs: list[tuple[str, str | None, int]] = []
        self.has_kane = False  # Fr() or FrStar() was generated
        self._kd_started = False  # ``kd_eqs = []`` was emitted
        self._loads_started = False  # ``loads = al.model.loads`` was emitted
        self._complex_set = False  # a Complex setting was seen
        self._echoed = 0  # lines of the .al echoed so far
        # What is known at this point of the script, statically, for the
        # statements written as sympy calls whose Autolev rule would
        # otherwise differ (docs/semantics.md, "Sympy calls in the module"):
        #: (point, frame) keys whose velocity sympy's Point holds
        self._known_vel: set[tuple[str, str]] = set()
        #: point key -> points joined to it by given positions
        self._pos_edges: dict[str, set[str]] = defaultdict(set)
        #: frame key -> frames joined to it by orientations or W_ assignments
        self._frame_edges: dict[str, set[str]] = defaultdict(set)
        #: bodies and particles in declaration order: (key, sympy body ident)
        self._massive: list[tuple[str, str]] = []
        #: keys of bodies and particles given a (nonzero) mass
        self._has_mass: set[str] = set()
        #: keys of bodies and particles whose mass may be zero
        self._unsure_mass: set[str] = set()

    # ------------------------------------------------------------ driving

    def body(self, stmts: tuple[ir.Stmt, ...]) -> list[str]:
        """Python lines for ``stmts`` (checked in order by the analysis)."""
        out: list[str] = []
        for stmt in stmts:
            if self.stopped_at is not None:
                break
            try:
                out.extend(self.statement(stmt))
            except RecursionError:
                raise SemanticError(
                    "this statement is too deeply nested to convert", stmt.span
                ) from None
        out.extend(self.echo_through(len(self.lines)))
        return _model_calls(out)

    def statement(self, stmt: ir.Stmt, *, line: int | None = None) -> list[str]:
        self._facts = self.facts.of(stmt)
        self._line = line if line is not None else stmt.span.line
        emit = getattr(self, "stmt_" + type(stmt).__name__, None)
        if emit is None:
            raise InternalError(f"no emitter for {type(stmt).__name__}")
        code = emit(stmt)
        if line is not None:
            return code
        span = stmt.span
        return [*self.echo_through(max(span.end_line, span.line)), *code]

    def echo_through(self, last: int) -> list[str]:
        """The ``.al`` lines up to ``last`` not yet echoed, as ``# al>``
        comments: each line of the file appears once in the module, and the
        transcript reads its source from them (``names.transcript``)."""
        out: list[str] = []
        while self._echoed < min(last, len(self.lines)):
            out.extend(echo_lines(self.lines[self._echoed]))
            self._echoed += 1
        return out

    # -------------------------------------------------------- statements

    def stmt_Comment(self, stmt: ir.Comment) -> list[str]:
        return []  # its line is echoed as it stands

    def stmt_Setting(self, stmt: ir.Setting) -> list[str]:
        value = stmt.value or ""
        arg = value if re.fullmatch(r"\d+", value) else repr(value.upper())
        if stmt.name == "AUTOEPSILON":
            arg = _number_code(value)
        if stmt.name == "COMPLEX":  # constants' assumptions follow it
            self._complex_set = True
        return [f"al.settings.set({stmt.name.title()!r}, {arg})"]

    def stmt_Declaration(self, stmt: ir.Declaration) -> list[str]:
        decl = Decl.of_keyword(stmt.keyword)
        if decl in vocab.OBJECT_DECLS:
            return self._objects(stmt)
        if stmt.keyword == "MASS":
            return self._mass(stmt)
        if stmt.keyword == "INERTIA":
            return self._inertia(stmt)
        if decl is None:
            raise InternalError(f"no emitter for declaration {stmt.keyword}")
        method = stmt.keyword.lower()  # the runtime's declaration command
        if stmt.motion:
            method = "motion_variables"
        names: list[str] = []
        specs: list[str] = []
        assigns: list[str] = []
        for item in stmt.items:
            target = item.target
            if isinstance(target, ir.IndexedNames):
                spellings = target.expand()
                primes = target.primes
            else:
                assert isinstance(target, ir.Name)
                spellings = (target.name,)
                primes = target.primes
            for spelling in spellings:
                sym = self.facts.quantity(spelling)
                names.append(sym.ident)
                specs.append(repr(sym.key + "'" * primes + (item.sign or "")))
            if item.values:
                sym = self.facts.quantity(spellings[-1])
                value = self.expr(item.values[0])
                assigns.append(f"al.assign({sym.key!r}, {value}, line={self._line})")
        if method == "constants" and not self._complex_set:
            # real symbols, as sympy writes them; the runtime declares them
            keys = [spec[1:-1] for spec in specs]
            return [
                *self._symbols(names, keys),
                f"al.declare_constants({', '.join(names)}, line={self._line})",
                *assigns,
            ]
        if method in ("variables", "specified") and not self._complex_set:
            # functions of time, as sympy writes them (``dynamicsymbols``)
            keys = [spec[1:-1].rstrip("'") for spec in specs]
            if all(re.fullmatch(r"\w+", k) for k in keys):
                # sympy's dynamicsymbols, each function keeping its hash
                make = self.imports.use(_RUNTIME, "dynamicsymbols")
                orders = [
                    len(spec[1:-1]) - len(k)
                    for spec, k in zip(specs, keys, strict=True)
                ]
                primes = "" if not any(orders) else f", primes={orders[0]}"
                if len(set(orders)) > 1:
                    primes = f", primes=({', '.join(map(str, orders))})"
                return [
                    f"{', '.join(names)} = {make}({' '.join(keys)!r}, real=True)",
                    f"al.declare_{method}({', '.join(names)}{primes},"
                    f" line={self._line})",
                    *assigns,
                ]
        call = f"al.{method}({', '.join(specs)}, line={self._line})"
        return [f"{', '.join(names)} = {call}", *assigns]

    def _objects(self, stmt: ir.Declaration) -> list[str]:
        names = [n for item in stmt.items for n in _target_names(item.target)]
        syms = [self.facts.object(n) for n in names]
        idents = ", ".join(s.ident for s in syms)
        keys = ", ".join(repr(s.key) for s in syms)
        out = self._sympy_objects(stmt.keyword, syms)
        if not out:
            out = [f"{idents} = al.{stmt.keyword.lower()}({keys})"]
        if (
            Decl.of_keyword(stmt.keyword) in vocab.FRAME_DECLS
            and stmt.keyword != "BODIES"  # a body's mass center is its own
        ):
            for s in syms:
                point = self.facts.table.physical(s.key + "O")
                if point is not None and point.key in self.facts.mentioned:
                    out.append(f"{point.ident} = al.point({point.key!r})")
        return out

    def _sympy_objects(self, keyword: str, syms: list) -> list[str]:
        """``Newtonian N``, ``Frames A``, ``Points O``, ``Particles P`` as
        the sympy objects (``N = ReferenceFrame("N")``, ``O_ = Point("O")``,
        ``P_particle = Particle("P", P, 0)``), then the runtime's record of
        them under their Autolev names; ``[]`` for other declarations."""
        frames = ("NEWTONIAN", "FRAMES", "BODIES")
        cls = "ReferenceFrame" if keyword in frames else None
        if keyword in ("POINTS", "PARTICLES"):
            cls = "Point"
        if cls is None:
            return []
        make = self.imports.use(_VECTOR, cls)
        idents = ", ".join(s.ident for s in syms)
        news = ", ".join(f"{make}({s.key!r})" for s in syms)
        out = [f"{idents} = {news}"]
        if keyword == "BODIES":
            return out + self._rigid_bodies(syms)
        if keyword != "PARTICLES":
            out.append(f"al.declare_{keyword.lower()}({idents})")
            return out
        self._massive += [(s.key, self._sympy_body(s) or "") for s in syms]
        particle = self.imports.use("sympy.physics.mechanics", "Particle")
        lhs = [
            self.facts.helper_ident(s.key + "_particle", s.ident + "_particle")
            for s in syms
        ]
        rhs = [f"{particle}({s.key!r}, {s.ident}, 0)" for s in syms]
        out.append(f"{', '.join(lhs)} = {', '.join(rhs)}")
        out.append(f"al.declare_particles({', '.join(lhs)})")
        return out

    def _symbols(self, idents: list[str], specs: list[str]) -> list[str]:
        """``A, B = symbols("A B", real=True)`` for constants spelled ``A``,
        ``B`` (``A+``: ``nonnegative=True``, ``A-``: ``nonpositive=True``)."""
        assume = {"+": "nonnegative=True", "-": "nonpositive=True"}
        parts = [
            (spec.rstrip("+-"), assume.get(spec[-1:], "real=True")) for spec in specs
        ]
        make = self.imports.use("sympy", "symbols")
        if len({a for _, a in parts}) == 1:
            spelled = " ".join(k for k, _ in parts)
            return [f"{', '.join(idents)} = {make}({spelled!r}, {parts[0][1]})"]
        news = ", ".join(f"{make}({k!r}, {a})" for k, a in parts)
        return [f"{', '.join(idents)} = {news}"]

    def _rigid_bodies(self, syms: list[Symbol]) -> list[str]:
        """``Bodies A``: after ``A = ReferenceFrame("A")``, its mass center
        ``Ao = Point("AO")`` and ``A_body = RigidBody("A", Ao, A, 0,
        (Dyadic(0), Ao))`` (``Mass`` and ``Inertia`` give the rest), then the
        runtime's record of them."""
        point = self.imports.use(_VECTOR, "Point")
        dyadic = self.imports.use(_VECTOR, "Dyadic")
        body = self.imports.use("sympy.physics.mechanics", "RigidBody")
        centers = []
        for s in syms:
            center = self.facts.table.physical(s.key + "O")
            centers.append(
                center.ident
                if center is not None
                else self.facts.helper_ident(s.key + "O", s.ident + "o")
            )
        lhs = [self._sympy_body(s) or "" for s in syms]
        self._massive += [(s.key, b) for s, b in zip(syms, lhs, strict=True)]
        news = ", ".join(f"{point}({s.key + 'O'!r})" for s in syms)
        rigid = [
            f"{body}({s.key!r}, {c}, {s.ident}, 0, ({dyadic}(0), {c}))"
            for s, c in zip(syms, centers, strict=True)
        ]
        return [
            f"{', '.join(centers)} = {news}",
            *(f"{b} = {r}" for b, r in zip(lhs, rigid, strict=True)),
            f"al.declare_bodies({', '.join(lhs)})",
        ]

    def _declare_new(self) -> list[str]:
        """The constants a Mass/Inertia declaration introduced (``MP+``: a
        nonnegative symbol), declared as the Constants statement does."""
        new = self._facts.new_constants
        if not new:
            return []
        idents = [s.ident for s in new]
        if self._complex_set:
            specs = ", ".join(repr(s.key + (s.sign or "")) for s in new)
            return [f"{', '.join(idents)} = al.constants({specs}, line={self._line})"]
        return [
            *self._symbols(idents, [s.key + (s.sign or "") for s in new]),
            f"al.declare_constants({', '.join(idents)}, line={self._line})",
        ]

    def _mass(self, stmt: ir.Declaration) -> list[str]:
        """``Mass P=MP``: the mass of the module's sympy ``Particle`` or
        ``RigidBody`` (``P_particle.mass = MP``), then the runtime's record
        of it (Autolev's normal form, the body's central inertia)."""
        out = self._declare_new()
        bodies = []
        for item in stmt.items:
            assert isinstance(item.target, ir.Name)
            obj = self.facts.object(item.target.name)
            first = item.values[0]
            if len(item.values) == 2:
                sym = self._symbol_for_name(first)
                value = self.expr(item.values[1])
                out.append(f"al.assign({sym.key!r}, {value}, line={self._line})")
            body = self._sympy_body(obj)
            if body is None:  # not declared as a body or particle: its error
                out.append(f"al.set_mass({obj.ident}, {self.expr(first)})")
                continue
            out.append(f"{body}.mass = {self.expr(first)}")
            bodies.append(body)
            if self._nonzero_mass(first):
                self._has_mass.add(obj.key)
                self._unsure_mass.discard(obj.key)
            else:  # perhaps zero: Gravity's rule is then the runtime's
                self._has_mass.discard(obj.key)
                self._unsure_mass.add(obj.key)
        if bodies:
            out.append(f"al.given_masses({', '.join(bodies)}, line={self._line})")
        return out

    def _nonzero_mass(self, node: ir.Expr) -> bool:
        """A mass that is surely not zero: a nonzero number, or a constant
        with no right-hand side."""
        if isinstance(node, ir.Number):
            return node.value != 0
        if not isinstance(node, ir.Name) or node.primes:
            return False
        sym = self.facts.table.quantity(node.name)
        return sym is not None and sym.kind == Decl.CONSTANT and not sym.has_rhs

    def _sympy_body(self, obj: Symbol) -> str | None:
        """The module's name for the sympy ``RigidBody``/``Particle`` of a
        declared body or particle (None for anything else)."""
        suffix = {Decl.BODY: "_body", Decl.PARTICLE: "_particle"}.get(obj.kind)
        if suffix is None:
            return None
        return self.facts.helper_ident(obj.key + suffix, obj.ident + suffix)

    def _inertia(self, stmt: ir.Declaration) -> list[str]:
        out = self._declare_new()
        body, *rest = stmt.items
        target = body.target
        basis = ""
        if isinstance(target, ir.Call):  # Inertia C(B), ...: in B's basis
            basis = f", basis={self._object(target.args[0].name)}"  # type: ignore[attr-defined]
            target = ir.Name(target.span, target.func)
        assert isinstance(target, ir.Name)
        obj = self.facts.object(target.name)
        about = ""
        first = rest[0].target if rest else None
        if isinstance(first, ir.Name) and self.facts.is_point(first.name):
            point = self.facts.object(first.name)
            about = f", about={point.ident}"
            rest = rest[1:]
        for item in rest:
            if item.values:
                sym = self._symbol_for_name(item.target)
                value = self.expr(item.values[0])
                out.append(f"al.assign({sym.key!r}, {value}, line={self._line})")
        scalars = ", ".join(self.expr(item.target) for item in rest)
        body_ident = self._sympy_body(obj)
        if about or basis or body_ident is None or not 1 <= len(rest) <= 6:
            # about another point (its position may come later) or in
            # another basis: Autolev's rule, the runtime's
            out.append(f"al.set_inertia({obj.ident}, {scalars}{about}{basis})")
            return out
        inertia = self.imports.use("sympy.physics.mechanics", "inertia")
        zeros = ", 0" * (3 - len(rest)) if len(rest) < 3 else ""
        out.append(
            f"{body_ident}.central_inertia = {inertia}({obj.ident}, {scalars}{zeros})"
        )
        out.append(f"al.given_inertia({body_ident}, line={self._line})")
        return out

    def stmt_Assign(self, stmt: ir.Assign) -> list[str]:
        target = stmt.target
        if self._facts.form is not None:
            assert isinstance(target, ir.Name)
            value = self._form_value(stmt.value)
            if stmt.op not in ("=", ":="):
                op = {"+=": "+", "-=": "-", "*=": "*", "/=": "/", "^=": "**"}[stmt.op]
                value = f"{self.expr(target)} {op} ({value})"
            form = self._facts.form
            self._note_form(form)
            setter = form.row.setter
            if setter is None or target.primes:
                return [f"al.assign({target.key!r}, {value}, line={self._line})"]
            objs = [self._object(form.parts[i]) for i in form.row.setter_order]
            if form.kind in _LOADS and stmt.op in ("+=", "-="):
                # Force_P> += v: one more sympy load on P, then the runtime's
                # record of P's resultant (Autolev's response)
                sign = "-" if stmt.op == "-=" else ""
                value = self._form_value(stmt.value)
                load = self._load(
                    form.kind, objs[0], f"{sign}({value})" if sign else value
                )
                return [
                    *self._loads_start(),
                    f"{self._loads_ident()}.append({load})",
                    f"al.given_{setter[4:]}({objs[0]}, line={self._line})",
                ]
            sympy_setter = _SYMPY_SETTERS.get(form.kind)
            if sympy_setter is not None:
                # sympy is told; the runtime reads it back with Autolev's rules
                obj, other = objs
                return [
                    f"{obj}.{sympy_setter}({other}, {value})",
                    f"al.given_{setter[4:]}({obj}, {other}, line={self._line})",
                ]
            return [f"al.{setter}({', '.join(objs)}, {value}, line={self._line})"]
        sym = self._facts.target
        if sym is None:
            raise InternalError("assignment without a target symbol")
        value = self.expr(stmt.value)
        if stmt.op not in ("=", ":="):
            current = (
                self.expr(target)
                if isinstance(target, ir.Element)
                else self._current(sym)
            )
            op = {"+=": "+", "-=": "-", "*=": "*", "/=": "/", "^=": "**"}[stmt.op]
            value = f"{current} {op} ({value})"
        if (
            isinstance(target, ir.Name)
            and target.primes == 1
            and stmt.op == "="
            and sym.kind == "variable"
            and self.facts.kind(stmt.value) is Kind.SCALAR
        ):
            return self._kinematical(sym, value)
        label = self._label(target)
        call = _named_call("assign", label, value, self._line)
        if isinstance(target, ir.Name) and (
            target.primes or sym.kind in vocab.QUANTITY_DECLS
        ):
            return [call]
        return [f"{sym.ident} = {call}"]

    def _note_form(self, form: Match) -> None:
        """What an assignment to ``P_O_P>``, ``V_P_N>``, ``W_A_N>`` or
        ``N_A`` makes known (:meth:`_two_point`)."""
        if form.kind not in (Form.POS, Form.VEL, Form.ANGVEL, Form.DCM):
            return
        keys = [self.facts.object(part).key for part in form.parts]
        if form.kind is Form.POS:
            self._pos_edges[keys[0]].add(keys[1])
            self._pos_edges[keys[1]].add(keys[0])
        elif form.kind is Form.VEL:
            self._known_vel.add((keys[0], keys[1]))
        elif form.kind in (Form.ANGVEL, Form.DCM):
            self._frame_edges[keys[0]].add(keys[1])
            self._frame_edges[keys[1]].add(keys[0])

    def _kinematical(self, sym: Symbol, value: str) -> list[str]:
        """``Q' = rhs``: a sympy equation the module keeps in ``kd_eqs``
        (the runtime assigns it as ``al.assign("Q'", rhs)`` would)."""
        eqs = self.facts.helper_ident("KD_EQS", "kd_eqs")
        eq = self.imports.use("sympy", "Eq")
        time = self.imports.use(_RUNTIME, "t")
        out = []
        if not self._kd_started:
            self._kd_started = True
            out.append(f"{eqs} = []  # kinematical differential equations, Eq(q', rhs)")
        out.append(
            f"{eqs}.append(al.kd({eq}({sym.ident}.diff({time}), {value}),"
            f" line={self._line}))"
        )
        return out

    def _form_value(self, node: ir.Expr) -> str:
        if isinstance(node, ir.Number) and node.value == 0:
            self.imports.use(_VECTOR, "Vector")
            return "Vector(0)"
        return self.expr(node)

    def _current(self, sym: Symbol) -> str:
        if sym.kind in (Decl.MATRIX, Decl.VECTOR, Decl.DYADIC):
            return sym.ident
        return f"al.val({sym.ident})"

    def _label(self, target: ir.Expr) -> str:
        if isinstance(target, ir.Element):
            idx = []
            for i in target.indices:
                if not isinstance(i, ir.Number) or not i.is_integer:
                    raise SemanticError(
                        "an assigned element needs whole-number indices", i.span
                    )
                idx.append(str(int(i.text)))
            return f"{target.base.key}[{','.join(idx)}]"
        assert isinstance(target, ir.Name)
        return target.autolev

    def stmt_ExprStmt(self, stmt: ir.ExprStmt) -> list[str]:
        expr = stmt.expr
        if self._facts.noop:
            word = expr.name.title()  # type: ignore[union-attr]
            return [f"# {word}: {self._facts.noop}"]
        if self._facts.stop:
            self.stopped_at = stmt.span.line
            word = expr.name.title()  # type: ignore[union-attr]
            return [
                f"# {word}: Autolev stops reading the script here.",
                f"al.exit(line={self._line})",
            ]
        if isinstance(expr, ir.Call):
            b = BUILTINS.get(expr.key)
            if b is not None and b.statement:
                self._note_orientation(expr, b)
                return (
                    self._loads_call(expr, b)
                    or self._sympy_call(expr, b)
                    or self._two_point(expr, b)
                    or [self._command(expr, b)]
                )
            if b is not None and b.dual and self._facts.target is not None:
                sym = self._facts.target
                value = self.expr(expr)
                bind = "" if sym.kind in vocab.QUANTITY_DECLS else f"{sym.ident} = "
                return [f"{bind}{_named_call('update', sym.key, value, self._line)}"]
            if b is not None and b.name == "EIG" and len(expr.args) >= 2:
                return self._eig_outputs(expr)
            if b is not None and b.name == "SOLVE":
                return [self._solve(expr)]
        label = ir.autolev_text(expr)  # also from RUN files and macros
        return [f"al.show({label!r}, {self.expr(expr)}, line={self._line})"]

    def _loads_ident(self) -> str:
        return self.facts.helper_ident("LOADS", "loads")

    def _loads_start(self) -> list[str]:
        """``loads = al.model.loads`` before the module's first load: the
        runtime's list of sympy loads, which Fr() and kanes_method() read."""
        if self._loads_started:
            return []
        self._loads_started = True
        return [f"{self._loads_ident()} = al.model.loads  # sympy Force/Torque loads"]

    def _note_orientation(self, call: ir.Call, b: Builtin) -> None:
        """Frames that a rotation command joins (their angular velocity
        follows from it), for :meth:`_two_point`."""
        if b.name in ("SIMPROT", "DIRCOS", "ANGVEL") and len(call.args) >= 2:
            first, second = call.args[:2]
            if isinstance(first, ir.Name) and isinstance(second, ir.Name):
                a = self.facts.table.physical(first.name)
                c = self.facts.table.physical(second.name)
                if a is not None and c is not None:
                    self._frame_edges[a.key].add(c.key)
                    self._frame_edges[c.key].add(a.key)

    def _load(self, kind: Form, where: str, value: str) -> str:
        cls = "Force" if kind is Form.FORCE else "Torque"
        self.imports.use("sympy.physics.mechanics", cls)
        return f"{cls}({where}, {value})"

    def _loads_call(self, call: ir.Call, b: Builtin) -> list[str]:
        """``Force(P, v>)``, ``Force(O/Q, v>)`` (and ``Torque``) as sympy
        loads the module appends to its ``loads`` (``-v>`` on O, ``v>`` on Q)."""
        if b.name == "GRAVITY":
            return [*self._loads_start(), *self._gravity(call, b)]
        if b.name not in ("FORCE", "TORQUE") or len(call.args) != 2:
            return []
        kind = Form.FORCE if b.name == "FORCE" else Form.TORQUE
        where, vec = call.args
        value = self._form_value(vec)
        loads = self._loads_ident()
        if isinstance(where, ir.BinOp):
            if not (
                isinstance(where.left, ir.Name) and isinstance(where.right, ir.Name)
            ):
                return []
            first = self._load(kind, self._object(where.left.name), f"-({value})")
            second = self._load(kind, self._object(where.right.name), value)
            return [*self._loads_start(), f"{loads} += [{first}, {second}]"]
        if not isinstance(where, ir.Name):
            return []
        load = self._load(kind, self._object(where.name), value)
        return [*self._loads_start(), f"{loads}.append({load})"]

    def _gravity(self, call: ir.Call, b: Builtin) -> list[str]:
        """``Gravity(G*N1>)``: Autolev's rule is mass*g> on every body and
        particle whose mass is declared so far (or on those listed), which
        are known here: sympy's ``gravity(G*N.x, P_particle, ...)`` added to
        the loads.  Where a mass may be zero, the runtime's rule."""
        vec, *objs = call.args
        if objs:
            if not all(isinstance(o, ir.Name) for o in objs):
                return [self._command(call, b)]
            keys = [self.facts.object(o.name).key for o in objs]  # type: ignore[attr-defined]
        else:
            keys = [k for k, _ in self._massive]
        bodies = dict(self._massive)
        if any(k in self._unsure_mass or k not in bodies for k in keys):
            return [self._command(call, b)]
        with_mass = [bodies[k] for k in keys if k in self._has_mass]
        if not with_mass:
            return [self._command(call, b)]
        value = self.expr(vec)
        gravity = self.imports.use("sympy.physics.mechanics.loads", "gravity")
        return [
            f"{self._loads_ident()} += {gravity}({value}, {', '.join(with_mass)})",
            f"al.given_gravity({value})",
        ]

    def _two_point(self, call: ir.Call, b: Builtin) -> list[str]:
        """``V2pts(N, A, O, P)`` as sympy's ``P.v2pt_theory(O, N, A)`` where
        ``V_O_N>``, ``P_O_P>`` (given directly) and ``W_A_N>`` are known here (Autolev
        forms ``V_P_N>`` later, when it is used, if they are not: the
        runtime's rule), then the runtime's record of it; ``[]`` else."""
        args = call.args
        if b.name not in _POINT_THEORIES or len(args) != 4:
            return []
        if not all(isinstance(a, ir.Name) for a in args):
            return []
        n, a, o, p = (self.facts.object(x.name) for x in args)  # type: ignore[attr-defined]
        if b.name != "V2PTS":
            # A2pts (sympy differentiates velocities its own way), V1pt and
            # A1pt (P's motion in A): the runtime's rule; V1pt's result is
            # known afterwards, the others may be formed later
            if b.name == "V1PT":
                self._known_vel.add((p.key, n.key))
            return []
        known = (
            (o.key, n.key) in self._known_vel
            and p.key in self._pos_edges[o.key]
            and self._joined(self._frame_edges, a.key, n.key)
        )
        if not known:
            self._known_vel.discard((p.key, n.key))  # perhaps formed later
            return []
        self._known_vel.add((p.key, n.key))
        theory = _POINT_THEORIES[b.name]
        return [
            f"{p.ident}.{theory}({o.ident}, {n.ident}, {a.ident})",
            f"al.formed_vel({p.ident}, {n.ident}, line={self._line})",
        ]

    @staticmethod
    def _joined(edges: dict[str, set[str]], a: str, b: str) -> bool:
        """Whether ``a`` and ``b`` are joined by a chain of ``edges``."""
        seen, todo = {a}, [a]
        while todo:
            x = todo.pop()
            if x == b:
                return True
            for y in edges.get(x, ()):
                if y not in seen:
                    seen.add(y)
                    todo.append(y)
        return False

    def _sympy_call(self, call: ir.Call, b: Builtin) -> list[str]:
        """A rotation command as sympy's own call (``A.orient_axis(N, N.z,
        QA)``), then the runtime's record of it (its response, its named
        direction cosines); ``[]`` where Autolev's command is the runtime's
        (an axis given as a vector, Euler parameters, Rodrigues)."""
        args = call.args
        if b.name not in ("SIMPROT", "DIRCOS") or len(args) < 4:
            return []
        if not all(isinstance(a, ir.Name) for a in args[:2]):
            return []
        parent, child = self.expr(args[0]), self.expr(args[1])
        record = f"al.given_orientation({child}, {parent}, line={self._line})"
        if b.name == "SIMPROT":
            axis = int_literal(args[2])
            if axis is None or not 1 <= abs(axis) <= 3:
                return []
            sign = "-" if axis < 0 else ""
            unit = f"{parent}.{'xyz'[abs(axis) - 1]}"
            angle = self.expr(args[3])
            return [f"{child}.orient_axis({parent}, {sign}{unit}, {angle})", record]
        if b.name == "DIRCOS" and len(args) == 6 and isinstance(args[2], ir.Name):
            kind = args[2].key.upper()
            m = re.fullmatch(r"(BODY|SPACE)([123]{3})", kind)
            if m is None:
                return []
            how = "orient_body_fixed" if m.group(1) == "BODY" else "orient_space_fixed"
            angles = ", ".join(self.expr(a) for a in args[3:])
            return [
                f"{child}.{how}({parent}, ({angles}), {m.group(2)!r})",
                record,
            ]
        return []

    def _command(self, call: ir.Call, b: Builtin) -> str:
        if b.name == "AUTOTAYLOR":
            order, *points = call.args
            return f"al.autotaylor({self.expr(order)}, {self._points(points)})"
        args = list(call.args)
        method = b.python
        if b.name in ("FORCE", "TORQUE") and isinstance(args[0], ir.BinOp):
            method = "force_between" if b.name == "FORCE" else "torque_between"
            pair = args.pop(0)
            assert isinstance(pair, ir.BinOp)
            args = [pair.left, pair.right, *args]
        if b.name == "CONSTRAIN":
            # Constrain(AUXILIARY[U1], DEPENDENT[U4]): one call per list.
            calls = []
            for element in args:
                assert isinstance(element, ir.Element)
                speeds = ", ".join(self.expr(i) for i in element.indices)
                code = f"{element.base.key!r}, [{speeds}], line={self._line}"
                calls.append(f"al.constrain({code})")
            return "\n".join(calls)
        else:
            code = self._args(tuple(args), b)
        if b.responds:  # it prints a response: say which line
            code += f"{', ' if code else ''}line={self._line}"
        if b.name == "ANIMATE":  # a code command, recorded for the CODE jobs
            return f"al.numerics.animate({code}, line={self._line})"
        if b.name == "KANE":
            # Kane rewrites ZERO (the independent speeds' rows, the forces
            # solved for): the script's name for it follows.
            zero = self.facts.table.quantity("ZERO")
            if zero is not None and zero.kind not in vocab.QUANTITY_DECLS:
                return f"{zero.ident} = al.{method}({code})"
        return f"al.{method}({code})"

    def _eig_outputs(self, call: ir.Call) -> list[str]:
        outs = [self._symbol_for_name(a) for a in call.args[1:]]
        idents = ", ".join(s.ident for s in outs)
        keys = ", ".join(repr(s.key) for s in outs)
        matrix = self.expr(call.args[0])
        source = (
            f"al.eig_vectors({matrix})" if len(outs) == 2 else f"[al.eig({matrix})]"
        )
        lhs = idents if len(outs) > 1 else idents + ","
        return [
            f"{lhs} = al.assign_all(({keys}{',' if len(outs) == 1 else ''}), {source}, line={self._line})"
        ]

    def _solve(self, call: ir.Call) -> str:
        args = list(call.args)
        if (
            isinstance(args[0], ir.Name)
            and args[0].key in SOLVE_OPTIONS
            and self.facts.table.quantity(args[0].name) is None
        ):
            args = args[1:]
        if len(args) < 2:
            raise SemanticError(
                "Solve needs equations and at least one unknown", call.span
            )
        eqs = self.expr(args[0])
        unknowns: list[str] = []
        for a in args[1:]:
            if isinstance(a, ir.IndexedNames):
                unknowns.extend(self._indexed(a))
            elif isinstance(a, ir.MatrixLit):
                unknowns.extend(self.expr(e) for row in a.rows for e in row)
            else:
                unknowns.append(self.expr(a))
        return f"al.solve({eqs}, [{', '.join(unknowns)}], line={self._line})"

    def stmt_MacroCall(self, stmt: ir.MacroCall) -> list[str]:
        name = stmt.source.replace("\\", "/").rsplit("/", 1)[-1]
        what = "runs" if stmt.name == "RUN" else "expands macro"
        out = [f"# ... {what} {name}:"]
        for inner in stmt.body:
            if self.stopped_at is not None:
                break
            out.extend(self.statement(inner, line=self._line))
        out.append(f"# ... end of {name}")
        return out

    def stmt_FileCommand(self, stmt: ir.FileCommand) -> list[str]:
        return [f"al.save({stmt.filename!r}, line={self._line})"]

    def stmt_ListCommand(self, stmt: ir.ListCommand) -> list[str]:
        if stmt.name == "ENCODE":
            names = ", ".join(repr(item.autolev) for item in stmt.items)  # type: ignore[attr-defined]
            return [f"al.numerics.encode({names}, line={self._line})"]
        if stmt.name == "UNITS":
            pairs = []
            for item in stmt.items:
                assert isinstance(item, ir.Equation) and isinstance(item.lhs, ir.Name)
                rhs = item.rhs
                word = (
                    rhs.text
                    if isinstance(rhs, ir.UnitExpr)
                    else ir.autolev_text(rhs, upper=False)
                )
                pairs.append(f"{item.lhs.autolev!r}: {word!r}")
            return [f"al.numerics.units_of({{{', '.join(pairs)}}}, line={self._line})"]
        raise InternalError(f"no emitter for {stmt.name}")

    def stmt_UnitSystemStmt(self, stmt: ir.UnitSystemStmt) -> list[str]:
        return [f"al.numerics.unit_system({', '.join(repr(u) for u in stmt.units)})"]

    def stmt_InputStmt(self, stmt: ir.InputStmt) -> list[str]:
        items = []
        for item in stmt.items:
            value = self.expr(item.value)
            if item.unit is not None:
                value = f"({value}, {item.unit.text!r})"
            for name in input_names(item.name):
                items.append(f"{name.autolev!r}: {value}")
                unit = item.unit.text if item.unit is not None else None
                self.help_inputs.append(
                    (name.autolev, ir.autolev_text(item.value), unit)
                )
        return [f"al.numerics.input({{{', '.join(items)}}}, line={self._line})"]

    def stmt_OutputStmt(self, stmt: ir.OutputStmt) -> list[str]:
        columns = []
        for item in stmt.items:
            label = ir.autolev_text(item.expr)  # also from RUN files and macros
            unit = repr(item.unit.text) if item.unit is not None else "None"
            columns.append(f"({label!r}, {self.expr(item.expr)}, {unit})")
        return [f"al.numerics.output([{', '.join(columns)}], line={self._line})"]

    def stmt_CodeStmt(self, stmt: ir.CodeStmt) -> list[str]:
        self.has_job = True
        self.help_jobs.append((stmt.option, stmt.filename, self._line))
        args = [repr(stmt.option)]
        if stmt.args:
            eqs, *unknowns = stmt.args
            names = [self.expr(n) for u in unknowns for n in input_names(u)]
            args += [f"eqs={self.expr(eqs)}", f"unknowns=[{', '.join(names)}]"]
        if stmt.sweep is not None:
            sw = stmt.sweep
            unit = repr(sw.unit.text) if sw.unit is not None else "None"
            parts = [self.expr(sw.name), unit, self.expr(sw.start), self.expr(sw.stop)]
            args.append(f"sweep=({', '.join(parts)}, {self.expr(sw.step)})")
        if stmt.filename is not None:
            args.append(f"file={stmt.filename!r}")
        if stmt.options:
            args.append(f"options={tuple(stmt.options)!r}")
        return [f"al.numerics.code({', '.join(args)}, line={self._line})"]

    # -------------------------------------------------------- expressions

    def expr(self, node: ir.Expr) -> str:
        return self._expr(node)[0]

    def _expr(self, node: ir.Expr) -> tuple[str, int]:
        emit = getattr(self, "expr_" + type(node).__name__, None)
        if emit is None:
            raise SemanticError(
                f"{type(node).__name__.lower()} is not allowed here", node.span
            )
        return emit(node)

    def _wrap(self, node: ir.Expr, min_prec: int) -> str:
        code, prec = self._expr(node)
        return f"({code})" if prec < min_prec else code

    def expr_Number(self, node: ir.Number) -> tuple[str, int]:
        return _number_code(node.text), ATOM

    def expr_Name(self, node: ir.Name) -> tuple[str, int]:
        if node.key == "0>":
            self.imports.use(_VECTOR, "Vector")
            return "Vector(0)", ATOM
        if node.key == "1>>":
            return "al.unit_dyadic()", ATOM
        sym = self.facts.resolution(node)
        if isinstance(sym, Match):
            return self._form(sym), ATOM
        if sym.kind == Decl.SPEEDS:
            return self._speed_matrix(sym, node), ATOM
        ident = sym.ident
        if sym.kind == Decl.TIME:
            self.imports.use(_RUNTIME, "t")
        elif ident == "pi":
            self.imports.use("sympy", "pi")
        elif ident == "I":
            self.imports.use("sympy", "I")
        if not node.primes:
            return ident, ATOM
        if sym.kind == Decl.SCALAR:
            code = f"al.dt({ident})"
            for _ in range(node.primes - 1):
                code = f"al.dt({code})"
            return code, ATOM
        self.imports.use(_RUNTIME, "t")
        order = "" if node.primes == 1 else f", {node.primes}"
        return f"{ident}.diff(t{order})", ATOM

    def _form(self, form: Match) -> str:
        if form.kind is Form.UNIT:
            frame = self._object(form.parts[0])
            return f"{frame}.{_UNIT_AXES[form.parts[1]]}"
        objs = [self._object(p) for p in form.parts]
        sympy_getter = self._sympy_getter(form)
        if sympy_getter is not None:
            first, second = objs
            if form.kind is Form.POS:  # P_O_Q> is Q.pos_from(O)
                first, second = second, first
            return f"{first}.{sympy_getter}({second})"
        return f"al.{form.row.getter}({', '.join(objs)})"

    def _sympy_getter(self, form: Match) -> str | None:
        """sympy's own getter for ``P_O_Q>``, ``W_A_N>`` and ``V_Q_N>``
        where it gives what Autolev's rule gives: the chain of positions or
        of orientations is known here, the velocity was given or formed (not
        derived, nor formed later); else None (the runtime's rule).

        A position is sympy's only where it was given directly: along a
        chain Autolev adds the steps from ``O``, sympy's ``pos_from`` from
        the far end, and the terms would print in another order."""
        keys = [self.facts.object(part).key for part in form.parts]
        if form.kind is Form.POS and keys[1] in self._pos_edges[keys[0]]:
            return "pos_from"
        if form.kind is Form.ANGVEL and self._joined(self._frame_edges, *keys):
            return "ang_vel_in"
        if form.kind is Form.VEL and tuple(keys) in self._known_vel:
            return "vel"
        return None

    def _object(self, name: str) -> str:
        return self.facts.object(name).ident

    def expr_Element(self, node: ir.Element) -> tuple[str, int]:
        base = self._resolved_ident(node.base)
        idx = ", ".join(self._index(i) for i in node.indices)
        return f"{base}[{idx}]", ATOM

    def _index(self, node: ir.Expr) -> str:
        if isinstance(node, ir.Number) and node.is_integer:
            return str(int(node.text) - 1)
        return f"int({self.expr(node)}) - 1"

    def expr_UnaryOp(self, node: ir.UnaryOp) -> tuple[str, int]:
        return f"{node.op}{self._wrap(node.operand, UNARY)}", UNARY

    def expr_BinOp(self, node: ir.BinOp) -> tuple[str, int]:
        if node.op == "^":
            base = self._exact(node.left) or self._wrap(node.left, POWER + 1)
            return f"{base} ** {self._wrap(node.right, UNARY)}", POWER
        if (
            node.op == "/"
            and int_literal(node.left) is not None
            and int_literal(node.right) is not None
        ):
            self.imports.use("sympy", "Rational")
            return f"Rational({self.expr(node.left)}, {self.expr(node.right)})", ATOM
        if node.op == "*" and self.facts.kind(node) is Kind.DYADIC:
            kinds = (self.facts.kind(node.left), self.facts.kind(node.right))
            if kinds == (Kind.VECTOR, Kind.VECTOR):
                self.imports.use(_VECTOR, "outer")
                return f"outer({self.expr(node.left)}, {self.expr(node.right)})", ATOM
        prec = ADD if node.op in "+-" else MUL
        left = self._exact(node.left) if node.op == "/" else None
        left = left or self._wrap(node.left, prec)
        right = self._wrap(node.right, prec + 1)
        op = {"+": "+", "-": "-", "*": "*", "/": "/"}[node.op]
        return f"{left} {op} {right}", prec

    def _exact(self, node: ir.Expr) -> str | None:
        """``Integer(n)`` for a pure-number left operand, so Python keeps
        exactness (a number: nothing below it to walk, so a long ``A/B/C``
        chain costs linear time)."""
        if isinstance(node, ir.Number) and node.is_integer:
            self.imports.use("sympy", "Integer")
            return f"Integer({int(node.text)})"
        return None

    def expr_MatrixLit(self, node: ir.MatrixLit) -> tuple[str, int]:
        blocks = any(
            self.facts.kind(e) is Kind.MATRIX for row in node.rows for e in row
        )
        rows = ["[" + ", ".join(self.expr(e) for e in row) + "]" for row in node.rows]
        if self.facts.is_vector_matrix(node):
            return f"al.vector_matrix([{', '.join(rows)}])", ATOM
        if blocks:
            return f"al.block([{', '.join(rows)}])", ATOM
        self.imports.use("sympy", "Matrix")
        if all(len(r) == 1 for r in node.rows) and len(node.rows) > 1:
            return f"Matrix([{', '.join(self.expr(r[0]) for r in node.rows)}])", ATOM
        return f"Matrix([{', '.join(rows)}])", ATOM

    def expr_String(self, node: ir.String) -> tuple[str, int]:
        raise SemanticError("a string is not a value here", node.span)

    def expr_Range(self, node: ir.Range) -> tuple[str, int]:
        return f"({self.expr(node.lo)}, {self.expr(node.hi)})", ATOM

    def expr_Equation(self, node: ir.Equation) -> tuple[str, int]:
        raise SemanticError("'name=value' is not allowed in this argument", node.span)

    def expr_IndexedNames(self, node: ir.IndexedNames) -> tuple[str, int]:
        return f"[{', '.join(self._indexed(node))}]", ATOM

    def _indexed(self, node: ir.IndexedNames) -> list[str]:
        return [self.expr(n) for n in node.names]

    def expr_Call(self, node: ir.Call) -> tuple[str, int]:
        b = BUILTINS.get(node.key)
        if b is None:
            raise SemanticError(unknown_call_message(node.func), node.span)
        emit = getattr(self, "call_" + b.python, None)
        if emit is not None:
            return emit(node, b), ATOM
        if b.style is Style.FUNC:
            name = b.python
            if self._facts.degrees and b.degrees is not None:
                name = b.degrees
            self.imports.use(_FUNCTIONS, name)
            return f"{name}({self._args(node.args)})", ATOM
        if b.style is Style.METHOD:
            if b.python in ("fr", "frstar"):
                self.has_kane = True  # the module offers kanes_method()
            return f"al.{b.python}({self._args(node.args, b)})", ATOM
        if b.name == "SOLVE":
            raise SemanticError(
                "Solve is a stand-alone command; use it alone on a line", node.span
            )
        raise InternalError(f"no emitter for built-in {b.name}")

    def _args(self, args: tuple[ir.Expr, ...], b: Builtin | None = None) -> str:
        words = b.words if b is not None else ()
        return ", ".join(
            repr(a.key) if i in words and isinstance(a, ir.Name) else self.expr(a)
            for i, a in enumerate(args)
        )

    def call_evaluate(self, node: ir.Call, b: Builtin) -> str:
        subject, *pairs = node.args
        if not pairs:
            return f"al.evaluate({self.expr(subject)})"
        return f"al.evaluate({self.expr(subject)}, {self._substitutions(pairs, 'Evaluate')})"

    def call_replace(self, node: ir.Call, b: Builtin) -> str:
        subject, *pairs = node.args
        items = []
        for p in pairs:
            if not isinstance(p, ir.Equation) or isinstance(p.rhs, ir.Range):
                raise SemanticError("Replace takes old=new pairs", p.span)
            items.append(f"({self.expr(p.lhs)}, {self.expr(p.rhs)})")
        return f"al.replace({self.expr(subject)}, [{', '.join(items)}])"

    def call_taylor(self, node: ir.Call, b: Builtin) -> str:
        subject, order, *points = node.args
        if isinstance(order, ir.Equation):
            raise SemanticError(
                "Taylor's second argument is the order, e.g. 0:2", order.span
            )
        return f"al.taylor({self.expr(subject)}, {self.expr(order)}, {self._points(points)})"

    def _points(self, points: list[ir.Expr]) -> str:
        """Expansion points ``X=0`` / ``X=0:dX`` as ``[(X, 0), (X, 0, dX)]``."""
        items = []
        for p in points:
            if isinstance(p, ir.Name):  # a bare name expands about 0
                items.append(f"({self.expr(p)}, 0)")
                continue
            if not isinstance(p, ir.Equation):
                raise SemanticError(
                    "expand about name=value or name=value:increment", p.span
                )
            self._check_substitutable(p.lhs)
            if isinstance(p.rhs, ir.Range):
                lo, hi = self.expr(p.rhs.lo), self.expr(p.rhs.hi)
                items.append(f"({self.expr(p.lhs)}, {lo}, {hi})")
            else:
                items.append(f"({self.expr(p.lhs)}, {self.expr(p.rhs)})")
        return f"[{', '.join(items)}]"

    def call_input_value(self, node: ir.Call, b: Builtin) -> str:
        name = node.args[0]
        if not isinstance(name, ir.Name):
            raise SemanticError("Input(X) takes a name", name.span)
        if len(node.args) == 2:
            word = node.args[1]
            if not isinstance(word, ir.Name) or word.key != "UNITSYSTEM":
                raise SemanticError(
                    "Input(X, UnitSystem): the second argument is the word UnitSystem",
                    word.span,
                )
        extra = ", unit_system=True" if len(node.args) == 2 else ""
        return f"al.numerics.input_value({name.autolev!r}{extra})"

    def call_units(self, node: ir.Call, b: Builtin) -> str:
        texts = [ir.autolev_text(a, upper=False) for a in node.args]
        return f"al.numerics.units({texts[0]!r}, {texts[1]!r})"

    def call_eig(self, node: ir.Call, b: Builtin) -> str:
        if len(node.args) != 1:
            raise SemanticError(
                "Eig(A, values, vectors) is a stand-alone command", node.span
            )
        return f"al.eig({self.expr(node.args[0])})"

    def call_solve(self, node: ir.Call, b: Builtin) -> str:
        raise SemanticError(
            "Solve is a stand-alone command; use it alone on a line", node.span
        )

    def _substitutions(self, pairs: list[ir.Expr], command: str) -> str:
        items = []
        for p in pairs:
            if not isinstance(p, ir.Equation) or isinstance(p.rhs, ir.Range):
                raise SemanticError(f"{command} takes name=value pairs", p.span)
            self._check_substitutable(p.lhs)
            items.append(f"{self.expr(p.lhs)}: {self.expr(p.rhs)}")
        return "{" + ", ".join(items) + "}"

    def _check_substitutable(self, lhs: ir.Expr) -> None:
        if not isinstance(lhs, ir.Name):
            raise SemanticError("expected a name on the left of '='", lhs.span)

    # ------------------------------------------------------------- helpers

    def _symbol_for_name(self, node: ir.Expr) -> Symbol:
        assert isinstance(node, ir.Name)
        return self.facts.quantity(node.name)

    def _resolved_ident(self, node: ir.Name) -> str:
        sym = self.facts.resolution(node)
        if isinstance(sym, Match):
            return self._form(sym)
        if sym.kind == Decl.SPEEDS:
            return self._speed_matrix(sym, node)
        return sym.ident

    @staticmethod
    def _speed_matrix(sym: Symbol, node: ir.Name) -> str:
        """``U_INDEPENDENT'`` -> ``al.speed_matrix("U_INDEPENDENT", 1)``."""
        primes = f", {node.primes}" if node.primes else ""
        return f'al.speed_matrix("{sym.key}"{primes})'


def _named_call(method: str, label: str, value: str, line: int) -> str:
    """``al.assign("X", v, line=3)``; for a vector or dyadic, named by a
    keyword rather than Autolev's spelling: ``UVEC> = v`` is
    ``al.assign_vector(UVEC=v, line=3)`` (``I>>``: ``assign_dyadic``)."""
    bare = label.rstrip(">")
    if label.endswith(">") and bare.isidentifier() and len(label) - len(bare) < 3:
        what = "dyadic" if label.endswith(">>") else "vector"
        return f"al.{method}_{what}({bare}={value}, line={line})"
    return f"al.{method}({label!r}, {value}, line={line})"


def _isort_key(name: str) -> tuple[int, str]:
    """isort's order-by-type: CONSTANTS, then Classes, then functions."""
    kind = 0 if name.isupper() else 1 if name[0].isupper() else 2
    return kind, name.lower()


def _target_names(target: ir.Expr) -> tuple[str, ...]:
    if isinstance(target, ir.IndexedNames):
        return target.expand()
    assert isinstance(target, ir.Name)
    return (target.name,)


def _number_code(text: str) -> str:
    """A Python literal for an Autolev number (``1.0E-07`` -> ``1.0e-07``)."""
    text = text.strip().lower()
    if text.isdigit():
        return str(int(text))
    if text.startswith("."):
        text = "0" + text
    text = text.replace(".e", ".0e")
    if text.endswith("."):
        text += "0"
    return text


def _model_calls(lines: list[str]) -> list[str]:
    """``al.simprot(...)`` spelled ``al.model.simprot(...)`` for each command
    of the runtime's :class:`Model` (the class that owns it), in code only
    (comments and strings are left as they are).

    One pass of :data:`_CODE_PARTS` over the text, which reads strings and
    comments as Python's tokenizer does, finds each ``al.NAME`` of the code
    (``tests/test_model_calls.py`` compares it with the tokenizer's reading)."""
    text = "\n".join(lines)
    out: list[str] = []
    done = 0
    for m in _CODE_PARTS.finditer(text):
        name = m.group("name")
        if name in MODEL_COMMANDS and m.group("after") is None:
            start = m.start("name")
            out += (text[done:start], "model.")
            done = start
    if not out:
        return list(lines)
    out.append(text[done:])
    return "".join(out).split("\n")


#: a string (prefixed or not, in any of Python's quotes; escapes skipped),
#: a comment, or the name ``al`` followed by ``.NAME`` (``after`` a dot: an
#: attribute ``x.al``, left alone): the parts of generated code that
#: :func:`_model_calls` tells apart, as Python's tokenizer reads them
_STRINGS = [
    r"'''(?:[^\\]|\\.)*?'''",  # triple-quoted, escapes skipped
    r'"""(?:[^\\]|\\.)*?"""',
    r"'(?:[^\\'\n]|\\.)*'",  # one line
    r'"(?:[^\\"\n]|\\.)*"',
]
_CODE_PARTS = re.compile(
    r"[A-Za-z]{0,3}(?:"  # a string's prefix (r, b, f, rb, ...)
    + "|".join(_STRINGS)
    + r")|#[^\n]*"
    + r"|(?P<after>\.[ \t]*)?(?<!\w)al[ \t]*\.[ \t]*(?P<name>\w+)",
    re.S,
)


def attach_echoes(code: str, width: int = 88) -> str:
    """``code`` (a formatted module) with each ``# al>`` echo that stands
    alone just above a statement moved to the end of the statement's first
    line, when the two fit ``width`` columns and that line is the whole
    statement or ends in an opening bracket::

        # al> Simprot(N, A, 3, QA)
        A.orient_axis(N, N.z, QA)

    becomes ``A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)``.  A
    line that fits is one black leaves as it is (and a comment after an
    opening bracket stays there), so the module stays black's; the
    transcript reads both forms back
    (:func:`al2py_runtime.safety.echo_records`).  Only plain echoes move
    (ASCII, no tab, not continued by ``# al+``); others keep their line.
    """
    lines = code.split("\n")
    candidates = {
        k + 2
        for k, echo in enumerate(lines[:-1])
        if echo.startswith(ECHO)
        and echo.isascii()
        and "\t" not in echo
        and len(lines[k + 1]) + 2 + len(echo) <= width
    }
    single = _single_rows(code, lines, candidates)
    out: list[str] = []
    k = 0
    while k < len(lines):
        echo, row = lines[k], k + 2  # the line below the echo is row k + 2
        below = lines[k + 1] if k + 1 < len(lines) else ""
        if (
            echo.startswith(ECHO)
            and row in single
            and echo.isascii()
            and "\t" not in echo
            and len(below) + 2 + len(echo) <= width
        ):
            out.append(f"{below}  {echo}")
            k += 2
            continue
        out.append(echo)
        k += 1
    return "\n".join(out)


#: the statements that are never compound (no block, no decorator)
_SIMPLE = (
    ast.Expr,
    ast.Assign,
    ast.AugAssign,
    ast.AnnAssign,
    ast.Import,
    ast.ImportFrom,
    ast.Pass,
    ast.Return,
    ast.Delete,
    ast.Raise,
    ast.Global,
    ast.Nonlocal,
    ast.Assert,
    ast.Break,
    ast.Continue,
)


def _single_rows(code: str, lines: list[str], rows: set[int]) -> set[int]:
    """Those of ``rows`` (1-based) that are the first row of a top-level
    statement that can take a comment: it starts at column 0, its first row
    has no comment, and that row is the whole statement or ends in an
    opening bracket.

    Python's tokenizer (pure Python before 3.12) decides this for every
    statement of ``code``; here the syntax tree cuts the module into pieces
    that each start a logical line at column 0 (so that their tokens are the
    ones they have in the whole module), the simple statements whose first
    row says it at once are read from the tree, and only the pieces that
    hold the other rows are tokenized."""
    try:
        body = ast.parse(code).body
    except (SyntaxError, ValueError, MemoryError, RecursionError):
        return _tokenized_single_rows(code, 1) & rows
    offsets = [0]  # offsets[k]: where row k + 1 starts in code
    for line in lines:
        offsets.append(offsets[-1] + len(line) + 1)
    # pieces: (first row, the statements in it); the first from row 1
    pieces: list[tuple[int, list[ast.stmt]]] = [(1, [])]
    end = 0  # where the statement before ends in code
    for stmt in body:
        first = min([stmt.lineno] + [d.lineno for d in _decorators(stmt)])
        start = offsets[first - 1]
        gap = code[end:start]  # blanks and comments, or ";", "\\" (joined)
        if start != end and _col(lines, stmt) == 0 and "\n" in gap:
            if not any(c in gap for c in ";\\") and first > 1:
                pieces.append((first, []))
        pieces[-1][1].append(stmt)
        end = offsets[stmt.end_lineno - 1] + _col(lines, stmt, end=True)
    starts = [first for first, _ in pieces]
    single: set[int] = set()
    tokenized: set[int] = set()  # the pieces read by the tokenizer
    for row in sorted(rows):
        k = bisect.bisect_right(starts, row) - 1
        first, stmts = pieces[k]
        if (
            len(stmts) == 1
            and isinstance(stmts[0], _SIMPLE)
            and first == stmts[0].lineno
        ):
            if row > first:  # its other rows, then blanks and comments
                continue
            if _plainly_single(stmts[0], lines[row - 1]):
                single.add(row)
                continue
        if k not in tokenized:
            tokenized.add(k)
            last = starts[k + 1] - 1 if k + 1 < len(starts) else len(lines)
            text = code[offsets[first - 1] : offsets[last]]
            single |= _tokenized_single_rows(text, first)
    return single & rows


def _decorators(stmt: ast.stmt) -> list[ast.expr]:
    return getattr(stmt, "decorator_list", [])


def _col(lines: list[str], stmt: ast.stmt, end: bool = False) -> int:
    """The column (in characters) where ``stmt`` starts, or ``end`` ends
    (the tree counts UTF-8 bytes)."""
    row, col = (
        (stmt.end_lineno, stmt.end_col_offset)
        if end
        else (stmt.lineno, stmt.col_offset)
    )
    line = lines[row - 1]
    return col if line.isascii() else len(line.encode()[:col].decode())


def _plainly_single(stmt: ast.stmt, line: str) -> bool:
    """Whether the simple statement ``stmt`` whose first row is ``line`` can
    take a comment, as its syntax tree and that row show with no doubt (no
    comment, string or backslash on the row); False when in doubt."""
    if not isinstance(stmt, _SIMPLE) or stmt.col_offset != 0 or not line.isascii():
        return False
    if stmt.end_lineno == stmt.lineno:  # the row is the whole statement
        return len(line) == stmt.end_col_offset
    plain = not any(c in line for c in "#'\"\\")
    return plain and line.rstrip()[-1:] in ("(", "[", "{")


def _tokenized_single_rows(code: str, first: int) -> set[int]:
    """The single rows of ``code``, whose first row is row ``first`` of the
    module, read from its tokens."""
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(code).readline))
    except (tokenize.TokenError, SyntaxError):  # pragma: no cover - our own code
        raise InternalError("generated code does not tokenize") from None
    #: first rows (1-based) of top-level statements that can take a comment
    single: set[int] = set()
    row = 0  # the first row of the statement being read (0: between them)
    ok = False  # it starts at column 0 and its first row has no comment
    last = ""  # the last token of its first row
    more = False  # it goes on below its first row
    skip = (tokenize.NL, tokenize.INDENT, tokenize.DEDENT, tokenize.ENCODING)
    for tok in tokens:
        if tok.type in skip or tok.type == tokenize.ENDMARKER:
            continue
        if tok.type == tokenize.NEWLINE:
            if row and ok and (last in "([{" if more else last != ":"):  # ":" a block
                single.add(row + first - 1)
            row = 0
        elif row == 0:
            if tok.type != tokenize.COMMENT:
                row, ok, last, more = tok.start[0], tok.start[1] == 0, tok.string, False
        elif tok.start[0] == row:
            ok = ok and tok.type != tokenize.COMMENT
            last = tok.string
            more = more or tok.end[0] > row
        else:
            more = True
    return single
