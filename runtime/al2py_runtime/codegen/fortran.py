"""The Fortran spelling of a :class:`~.program.Program`: fixed source form
(``.f``, 72 columns) in Fortran 90 (``implicit none``, ``do``/``end do``),
printed by sympy's ``fcode``; ``gfortran -Wall`` compiles it silently."""

from __future__ import annotations

import math
import re
import textwrap
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.printing.fortran import FCodePrinter

from ..jobs import backends
from ..jobs.run import NumericsError
from .printers import Remembering
from .program import Assign, Program, one_based_target

__all__ = ["fortran_source"]

_W = 72  # last column of fixed source form


class _Printer(Remembering, FCodePrinter):
    """sympy's Fortran printer, the same text faster (see
    :class:`.printers.Remembering`; and the names already used are a set,
    where sympy searches a list for each new name)."""

    def __init__(self) -> None:
        super().__init__({"source_format": "fixed", "standard": 95, "strict": True})
        self._used_names: set[str] = set()

    def plain_lines(self, text: str) -> list[str]:
        """sympy's fixed form: a line after six blanks (no block indents a
        single line), wrapped when longer than 72 columns, a line beginning
        with ``!`` a comment (by sympy's ``_format_code`` then)."""
        line = "      " + text
        if len(line) > _W or text[:1] in ("", " ", "\t", "!") or "\n" in text:
            return self._format_code(text.splitlines())
        return [line.rstrip()]

    def _print_sign(self, expr: Any) -> str:
        x = self._print(expr.args[0])
        return f"merge(0d0, sign(1d0, {x}), {x} == 0d0)"

    def _print_Symbol(self, expr: Any) -> str:
        # FCodePrinter._print_Symbol, with its name_mangling setting on (the
        # default, which this printer keeps)
        if expr not in self.mangled_symbols:
            name = expr.name
            while name.lower() in self._used_names:
                name += "_"
            self.used_name.append(name.lower())
            self._used_names.add(name.lower())
            if name == expr.name:
                self.mangled_symbols[expr] = expr
            else:
                self.mangled_symbols[expr] = sp.Symbol(name)
        expr = expr.xreplace(self.mangled_symbols)
        return super(FCodePrinter, self)._print_Symbol(expr)

    def _print_Add(self, expr: Any) -> str:
        # FCodePrinter._print_Add: complex numbers apart
        number = self.remembered_number
        for arg in expr.args:
            if number(arg) and not arg.is_real and arg.is_imaginary:
                return super()._print_Add(expr)
        return self.print_ordered_add(expr)

    def _print_Mul(self, expr: Any) -> str:
        # FCodePrinter._print_Mul, then CodePrinter._print_Mul, with the
        # number tests, precedences and sort keys remembered
        if self.remembered_number(expr) and expr.is_imaginary:
            return super()._print_Mul(expr)
        order = None if self.order in ("old", "none") else self.remembered_factors
        sign, a_str, b_str = backends.product_parts(
            self, expr, self.remembered_precedence(expr), order
        )[::2]
        return backends.join_product(sign, a_str, b_str)


def _d(x: float) -> str:
    x = float(x) if math.isfinite(x) else 0.0
    return repr(x).replace("e", "d") if "e" in repr(x) else f"{x!r}d0"


def _code(printer: _Printer, expr: Any, target: str, symbol: Any = None) -> list[str]:
    """The statement ``target = expr`` (``symbol``: a name's, when the
    program has it, the real symbol ``target`` names)."""
    found = printer.statements.get((expr, target))
    if found is not None:
        return list(found)
    to: Any = symbol
    if to is None:
        to = target if "(" in target else sp.Symbol(target, real=True)
    try:
        text = printer.doprint(sp.sympify(expr), assign_to=to)
    except Exception as exc:  # noqa: BLE001 - PrintMethodNotImplementedError, ...
        what = str(exc).split("\n")[0]
        raise NumericsError(f"Fortran cannot print {expr}: {what}") from None
    lines = [ln for ln in text.splitlines() if not ln.lstrip().startswith("!")]
    printer.statements[expr, target] = tuple(lines)
    return lines


def _comment(text: str) -> list[str]:
    return [f"C     {text}"[:_W].rstrip()]


def _string_write(unit: str, text: str, advance: bool = False) -> list[str]:
    """``write(unit, '(A)') 'text'`` split over continuation lines (with
    ``advance``: no new line after it)."""
    size = 30 if advance else 40
    quoted = [text[i : i + size].replace("'", "''") for i in range(0, len(text), size)]
    fmt = "'(A)', advance='no'" if advance else "'(A)'"
    if not quoted:
        return [f"      write({unit}, {fmt}) ''"]
    lines = [f"      write({unit}, {fmt}) '{quoted[0]}'"]
    lines += [f"     &  // '{q}'" for q in quoted[1:]]
    return lines


def _string_assign(target: str, text: str) -> list[str]:
    """``target = 'text'`` split over continuation lines."""
    quoted = [text[i : i + 40].replace("'", "''") for i in range(0, len(text), 40)]
    lines = [f"      {target} = '{quoted[0] if quoted else ''}'"]
    lines += [f"     &  // '{q}'" for q in quoted[1:]]
    return lines


def _decl(names: list[str], kind: str = "double precision") -> list[str]:
    lines: list[str] = []
    row: list[str] = []
    for name in names:
        if row and len(f"      {kind} {', '.join(row + [name])}") > _W:
            lines.append(f"      {kind} {', '.join(row)}")
            row = []
        row.append(name)
    if row:
        lines.append(f"      {kind} {', '.join(row)}")
    return lines


@dataclass
class _Step:
    """One statement of a routine: its lines, the names it defines and
    those it uses, and its assignment (None for the solve)."""

    lines: list[str]
    defines: list[str]
    uses: set[str]
    assign: Assign | None


def _steps(program: Program, block: list[Assign], printer: _Printer) -> list[_Step]:
    """The statements of ``block`` (the solve at ``solve_at`` in eqns)."""
    n = program.nu
    solve = [
        f"      call alsolve({n}, mm, ud, ierr)",
        "      if (ierr .ne. 0) return",
    ]
    steps = []
    for k, a in enumerate(block):
        kind = a.target[0]
        if k == program.solve_at and n and block is program.eqns:
            steps.append(_Step(list(solve), [], set(), None))
        if kind == "ud":
            line = f"      {a.target[2]} = ud({a.target[1] + 1})"
            steps.append(_Step([line], [a.target[2]], set(), a))
            continue
        target = one_based_target(a)
        uses = {s.name for s in program.free_symbols(a.expr)}
        defines = [a.target[1]] if kind == "tmp" else []
        steps.append(_Step(_code(printer, a.expr, target, a.symbol), defines, uses, a))
    if block is program.eqns and program.solve_at == len(block) and n:
        steps.append(_Step(list(solve), [], set(), None))
    return steps


def _loads(program: Program, block: list[Assign]) -> list[str]:
    """The constants and states ``block`` uses, from ``p`` and ``y``."""
    lines = []
    for i, e in program.params_used(block):
        lines.append(f"      {e.ident} = p({i + 1})")
    for i, e in program.states_used(block):
        lines.append(f"      {e.ident} = y({i + 1})")
    return lines


def _body(program: Program, block: list[Assign], printer: _Printer) -> list[str]:
    lines = _loads(program, block)
    for step in _steps(program, block, printer):
        lines += step.lines
    return lines


#: a routine of more printed lines is written in parts of about this many:
#: gfortran's optimizer takes time growing faster than a routine's length
#: (the bicycle's 7,700-line outputs routine took 36 s at -O2)
PART_LINES = 1000


@dataclass
class _Routine:
    """A routine's statements in parts (:func:`_parts`)."""

    calls: list[str]  # the routine's statements: a call of each part
    sources: list[str]  # the parts, each a subroutine
    work: str  # the work array's name
    size: int  # its size (0: none)
    uses_t: bool = False
    uses_y: bool = False
    uses_p: bool = False


def _parts(
    program: Program, steps: list[_Step], prefix: str, arrays: dict[str, str]
) -> _Routine:
    """``steps`` as subroutines ``{prefix}1, {prefix}2, ...`` of about
    :data:`PART_LINES` lines each, called in turn: the same statements in
    the same order.  A value one part defines and a later one uses passes
    through the routine's work array (stored after the statements that
    define it, loaded before those that use it).  ``arrays``: the routine's
    arrays that parts may use, with their declarations (``mm(6, 6)``)."""
    groups: list[list[_Step]] = [[]]
    size = 0
    for step in steps:
        if size and size + len(step.lines) > PART_LINES:
            groups.append([])
            size = 0
        groups[-1].append(step)
        size += len(step.lines)
    taken = {e.ident.lower() for e in program.constants + program.initials}
    taken |= {d.lower() for step in steps for d in step.defines}
    taken |= {x.lower() for step in steps for x in step.uses}
    work = _free_name("alw", taken)
    names = [_free_name(f"{prefix}{k}", taken) for k in range(1, len(groups) + 1)]
    later: list[set[str]] = []  # the names used after each group
    seen: set[str] = set()
    for group in reversed(groups):
        later.append(set(seen))
        for step in group:
            seen |= step.uses
    later.reverse()
    slots: dict[str, int] = {}
    defined: set[str] = set()
    planned = []
    for group, after in zip(groups, later, strict=True):
        uses = set().union(*(step.uses for step in group))
        loads = sorted(uses & defined, key=lambda x: slots[x])
        own = [d for step in group for d in step.defines]
        stores = [d for d in own if d in after]
        for d in stores:
            slots.setdefault(d, len(slots) + 1)
        defined |= set(own)
        planned.append((loads, own, stores, group))
    out = _Routine([], [], work, len(slots))
    ny, np_ = max(program.ny, 1), max(program.np, 1)
    for name, (loads, own, stores, group) in zip(names, planned, strict=True):
        assigns = [step.assign for step in group if step.assign is not None]
        text = "\n".join(line for step in group for line in step.lines)
        use_t = _uses(program, assigns, "T")
        use_y = bool(program.states_used(assigns))
        use_p = bool(program.params_used(assigns))
        used_arrays = [a for a in arrays if re.search(rf"\b{a}\b", text)]
        solve = any(step.assign is None for step in group)
        args = [a for a, on in (("T", use_t), ("y", use_y), ("p", use_p)) if on]
        args += used_arrays
        if loads or stores:
            args.append(work)
        if solve:
            args.append("ierr")
        out.uses_t |= use_t
        out.uses_y |= use_y
        out.uses_p |= use_p
        out.calls += _continued(f"      call {name}({', '.join(args)})")
        if solve:
            out.calls.append("      if (ierr .ne. 0) return")
        lines = _continued(f"      subroutine {name}({', '.join(args)})")
        lines.append("      implicit none")
        decls = [x for x, on in (("T", use_t),) if on]
        decls += [f"y({ny})"] if use_y else []
        decls += [f"p({np_})"] if use_p else []
        decls += [arrays[a] for a in used_arrays]
        decls += [f"{work}({len(slots)})"] if loads or stores else []
        lines += _decl(decls)
        if solve:
            lines.append("      integer ierr")
        local = [e.ident for _i, e in program.params_used(assigns)]
        local += [e.ident for _i, e in program.states_used(assigns)]
        lines += _decl(local + loads + own)
        lines += _loads(program, assigns)
        lines += [f"      {x} = {work}({slots[x]})" for x in loads]
        lines += [line for step in group for line in step.lines]
        lines += [f"      {work}({slots[x]}) = {x}" for x in stores]
        out.sources += [*lines, "      end", ""]
    return out


def _free_name(base: str, taken: set[str]) -> str:
    """``base`` (``base_`` ... when a name of the program is ``base``)."""
    name = base
    while name.lower() in taken:
        name += "_"
    taken.add(name.lower())
    return name


def _continued(line: str) -> list[str]:
    """A long statement of the program's own over continuation lines."""
    if len(line) <= _W:
        return [line]
    out = []
    rest = line
    while len(rest) > _W:
        cut = rest.rfind(", ", 0, _W - 1) + 1
        out.append(rest[:cut])
        rest = "     &  " + rest[cut:].lstrip()
    return [*out, rest]


def _locals(program: Program, block: list[Assign]) -> list[str]:
    names = [e.ident for _i, e in program.params_used(block)]
    names += [e.ident for _i, e in program.states_used(block)]
    names += [a.target[1] for a in block if a.target[0] == "tmp"]
    names += [a.target[2] for a in block if a.target[0] == "ud"]
    return names


def _uses(program: Program, block: list[Assign], name: str) -> bool:
    """Whether an equation of ``block`` uses the symbol ``name``."""
    symbol = sp.Symbol(name, real=True)
    return any(symbol in program.free_symbols(a.expr) for a in block)


def _guards(program: Program, block: list[Assign], args: dict[str, bool]) -> list[str]:
    """A NaN check for each argument the equations do not use (gfortran
    warns about unused dummy arguments)."""
    lines = []
    for name, used in args.items():
        if not used:
            ref = name if name == "T" else f"{name}(1)"
            lines.append(f"      if ({ref} .ne. {ref}) ierr = 2")
    return lines


def equations(program: Program) -> list[str]:
    """The subroutines ``eqns`` and ``outputs`` (and their parts, when
    longer than :data:`PART_LINES`), and ``alsolve``."""
    printer = _Printer()
    n, ny, np_, nout = program.nu, max(program.ny, 1), program.np, program.nout
    e = program.eqns
    doc = textwrap.wrap(" ".join(program.eqns_doc), _W - 8)
    lines = [c for text in doc for c in _comment(text)]
    lines += _comment("ierr is the code.")
    lines += [
        "      subroutine eqns(T, y, p, dy, ud, ierr)",
        "      implicit none",
        f"      double precision T, y({ny}), p({max(np_, 1)}), dy({ny})",
        f"      double precision ud({max(n, 1)})",
        "      integer ierr" + (", i" if program.ny else ""),
    ]
    if n:
        lines.append(f"      double precision mm({n}, {n})")
    steps = _steps(program, e, printer)
    parts = None
    if sum(len(step.lines) for step in steps) > PART_LINES * 3 // 2:
        arrays = {"dy": f"dy({ny})", "ud": f"ud({max(n, 1)})"}
        if n:
            arrays["mm"] = f"mm({n}, {n})"
        parts = _parts(program, steps, "aleq", arrays)
        if parts.size:
            lines += _decl([f"{parts.work}({parts.size})"])
        used = {"T": parts.uses_t, "y": parts.uses_y, "p": parts.uses_p}
    else:
        lines += _decl(_locals(program, e))
        used = {
            "T": _uses(program, e, "T"),
            "y": bool(program.states_used(e)),
            "p": bool(program.params_used(e)),
        }
    lines.append("      ierr = 0")
    lines += _guards(program, e, used)
    if not n:
        lines.append("      ud(1) = 0d0")
    if parts is not None:
        lines += parts.calls
    else:
        lines += _loads(program, e)
        lines += [line for step in steps for line in step.lines]
    if program.ny:
        lines += [
            f"      do i = 1, {ny}",
            "        if (dy(i) .ne. dy(i) .or. abs(dy(i)) .gt. huge(1d0)) then",
            "          ierr = 2",
            "        end if",
            "      end do",
        ]
    else:
        lines.append("      dy(1) = 0d0")
    lines += ["      end", ""]
    if parts is not None:
        lines += parts.sources
    o = program.outputs
    lines += _comment("The output quantities at (T, y), all tables in order.")
    lines += [
        "      subroutine outputs(T, y, p, out, ierr)",
        "      implicit none",
        f"      double precision T, y({ny}), p({max(np_, 1)}), out({max(nout, 1)})",
        f"      double precision dy({ny}), ud({max(n, 1)})",
        "      integer ierr",
    ]
    steps = _steps(program, o, printer)
    parts = None
    if sum(len(step.lines) for step in steps) > PART_LINES * 3 // 2:
        arrays = {"out": f"out({max(nout, 1)})", "ud": f"ud({max(n, 1)})"}
        parts = _parts(program, steps, "alout", arrays)
        if parts.size:
            lines += _decl([f"{parts.work}({parts.size})"])
    else:
        lines += _decl(_locals(program, o))
    lines += [
        "      call eqns(T, y, p, dy, ud, ierr)",
        "      if (ierr .ne. 0) return",
    ]
    if not nout:
        lines.append("      out(1) = 0d0")
    if parts is not None:
        lines += parts.calls
    else:
        lines += _loads(program, o)
        lines += [line for step in steps for line in step.lines]
    lines += ["      end", ""]
    if parts is not None:
        lines += parts.sources
    if n:
        lines += _SOLVE_F.splitlines()
    return lines


def _program_name(program: Program) -> str:
    stem = program.stem
    if (
        re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,30}", stem)
        and stem.lower()
        not in {
            "eqns",
            "outputs",
            "kutta",
            "alsolve",
            "alrow",
            "alread",
            "alargs",
        }
        and not re.fullmatch(r"al((eq|out)\d+|w)_*", stem.lower())
    ):
        return stem
    return "alprog"


def fortran_source(program: Program, target: str) -> str:
    job = program.job
    lines = _comment(f"{target}: generated by al2py {program.version}")
    lines += _comment(f"from {program.source} ({job.where}).")
    lines += _comment("Edit the .al file and generate again.")
    if program.nosubs:
        lines += _comment("NOSUBS: the equations only (eqns and outputs).")
        lines += _comment("p(i): " + ", ".join(e.name for e in program.constants))
        lines += _comment("y(i): " + ", ".join(e.name for e in program.initials))
        return "\n".join(lines + [""] + equations(program)) + "\n"
    stem = program.stem
    lines += _comment(f"Build: gfortran -O2 -o {stem} {target}")
    lines += _comment(f"Run:   ./{stem} [NAME=VALUE ...]   (reads {stem}.in when")
    lines += _comment("present, the values from column 60, a blank line after")
    lines += _comment("each group, else the script's Input values; NAME=VALUE")
    lines += _comment("changes one, in its Input's unit).")
    for text in textwrap.wrap(program.task, 64):
        lines += _comment(text)
    if program.kind == "NONLINEAR":
        lines += _nonlinear_main(program)
        tail = _NEWTON_F + _READ_F + _ARGS_F
    elif program.kind == "ALGEBRAIC":
        lines += _algebraic_main(program)
        tail = _READ_F + _ARGS_F
    else:
        lines += _dynamics_main(program)
        tail = _KUTTA_F + _READ_F + _ARGS_F
    lines += equations(program)
    lines += _row_routine(program.tables)
    lines += tail.splitlines()
    return "\n".join(lines) + "\n"


def _prologue(program: Program, decls: list[str]) -> list[str]:
    """The main program up to the constants p and the values y: the
    declarations (with ``decls``), the Input values, ``STEM.in``."""
    entries = program.entries
    nin, ny, nout = len(entries), max(program.ny, 1), program.nout
    np_ = len(program.inputs)
    tables = program.tables
    groups = [len(g) for g in program.groups]
    lines = [
        f"      program {_program_name(program)}",
        "      implicit none",
        f"      integer, parameter :: nin = {nin}, ny = {ny},"
        f" np = {max(program.np, 1)}",
        f"      integer, parameter :: nout = {max(nout, 1)}, nt = {max(len(tables), 1)}",
        "      double precision v(nin), fac(nin), y(ny), p(np), of(nout)",
        "      integer ncol(nt), iw(nt), ngrp(3), ierr"
        + (", i" if np_ or program.ny else ""),
        "      logical there",
        f"      character(len={max([len(e.setting) for e in entries] + [1])})"
        " names(nin)",
        *decls,
    ]
    for k, e in enumerate(entries, start=1):
        lines.append(f"      v({k}) = {_d(e.value)}")
        lines.append(f"      fac({k}) = {_d(e.factor)}")
    for k, f in enumerate([x for t in tables for x in t.factors], start=1):
        lines.append(f"      of({k}) = {_d(f)}")
    if not nout:
        lines.append("      of(1) = 1d0")
    for k, t in enumerate(tables, start=1):
        lines.append(f"      ncol({k}) = {t.columns}")
        lines.append(f"      iw({k}) = {t.width}")
    if not tables:
        lines += ["      ncol(1) = 0", "      iw(1) = 0"]
    for k in range(3):
        lines.append(f"      ngrp({k + 1}) = {groups[k] if k < len(groups) else 0}")
    stem = program.stem
    for k, e in enumerate(entries, start=1):
        lines += _string_assign(f"names({k})", e.setting)
    lines += [
        f"      inquire(file='{stem}.in', exist=there)",
        "      if (there) then",
        f"        call alread('{stem}.in', nin, ngrp, v, ierr)",
        "        if (ierr .ne. 0) stop 2",
        "      end if",
        "      call alargs(nin, names, v, ierr)",
        "      if (ierr .ne. 0) stop 2",
    ]
    for note in program.notes:
        lines += _string_write("0", f"note: {note}")
    # a model without constants still passes p(1)
    if np_:
        lines += [
            f"      do i = 1, {np_}",
            "        p(i) = v(i) * fac(i)",
            "      end do",
        ]
    else:
        lines.append("      p(1) = 0d0")
    if program.ny:
        lines += [
            "      do i = 1, ny",
            f"        y(i) = v({np_} + i) * fac({np_} + i)",
            "      end do",
        ]
    else:
        lines.append("      y(1) = 0d0")
    return lines


def _open(program: Program) -> list[str]:
    lines = []
    for k, t in enumerate(program.tables, start=1):
        if not t.written:
            continue
        lines.append(
            f"      open({10 + k}, file='{program.stem}.{k}', status='replace',"
        )
        lines.append("     &     action='write')")
        for text in t.header[:-1].split("\n"):
            lines += _string_write(str(10 + k), text)
    return lines


def _close(program: Program, errors: list[str]) -> list[str]:
    """Close the files, report ``errors`` (``(code, message lines)``) or
    the files written; stop 2 after an error."""
    written = [t.written for t in program.tables] or [False]
    lines = [f"      close({10 + k})" for k, w in enumerate(written, start=1) if w]
    lines += [
        ln.replace("      else if", "      if", 1) if i == 0 else ln
        for i, ln in enumerate(errors)
    ]
    lines.append("      else" if errors else "      if (ierr .eq. 0) then")
    for k, w in enumerate(written, start=1):
        if w:
            lines.append(f"        write(*, '(A)') 'Wrote {program.stem}.{k}'")
    lines += ["      end if", "      if (ierr .ne. 0) stop 2", "      end", ""]
    return lines


def _dynamics_main(program: Program) -> list[str]:
    np_, ny = program.np, program.ny
    lines = _prologue(
        program,
        [
            f"      double precision dy(ny), ud({max(program.nu, 1)})",
            "      double precision t, t0, t1, step, prnt, atol, rtol, hc",
            "      integer cuts, count",
            "      logical last",
        ],
    )
    base = np_ + ny
    lines += [
        f"      t0 = v({base + 1}) * fac({base + 1})",
        f"      t1 = v({base + 2}) * fac({base + 2})",
        f"      step = v({base + 3}) * fac({base + 3})",
        f"      prnt = v({base + 4})",
        f"      atol = v({base + 5})",
        f"      rtol = v({base + 6})",
        "      if (step .eq. 0d0 .or. prnt .le. 0d0 .or. atol .le. 0d0",
        "     &    .or. rtol .le. 0d0 .or. prnt .ne. aint(prnt)) then",
        "        write(*, '(A)') 'error: INTEGSTP must not be 0; PRINTINT'",
        "     &    // ' (whole), ABSERR and RELERR must be positive'",
        "        stop 2",
        "      end if",
        "      if ((t1 - t0) * step .lt. 0d0) step = -step",
    ]
    lines += _open(program)
    lines += [
        "      t = t0",
        "      hc = 0d0",
        "      cuts = 20",
        "      count = 0",
        "      call eqns(t, y, p, dy, ud, ierr)",
        "      do while (ierr .eq. 0)",
        "        if (t1 .ge. t0) then",
        "          last = t + 0.01d0 * abs(step) .ge. t1",
        "        else",
        "          last = t - 0.01d0 * abs(step) .le. t1",
        "        end if",
        "        if (count .le. 0 .or. last) then",
        "          call alrow(t, y, p, nout, of, nt, ncol, iw, "
        + (f"{program.digits - 1}, ierr)"),
        "          if (ierr .ne. 0 .or. last) exit",
        "          count = nint(prnt)",
        "        end if",
        "        call kutta(t, step, ny, y, p, hc, cuts, atol, rtol, ierr)",
        "        count = count - 1",
        "      end do",
    ]
    errors = [
        "      else if (ierr .eq. 1) then",
        "        write(*, '(A, ES14.6)') 'error: the mass matrix is singular'",
        "     &    // ' at t =', t",
        "      else if (ierr .eq. 2) then",
        "        write(*, '(A, ES14.6)') 'error: a value is not finite at t ='",
        "     &    , t",
        "      else if (ierr .eq. 3) then",
        "        write(*, '(A, ES14.6)') 'error: integration failed (the step'",
        "     &    // ' was halved too often) at t =', t",
    ]
    return lines + _close(program, errors)


def _row(program: Program) -> str:
    return (
        f"        call alrow({_d(program.t0)}, y, p, nout, of, nt, ncol, iw,"
        f" {program.digits - 1},\n     &    ierr)"
    )


def _error(program: Program, condition: str, *writes: str) -> list[str]:
    """A branch of :func:`_close`: ``error: CODE ... (line N): `` and then
    ``writes`` when ``condition`` holds."""
    where = _string_write("*", f"error: {program.job.where}: ", advance=True)
    return [f"      else if ({condition}) then", *where, *writes]


def _algebraic_main(program: Program) -> list[str]:
    """One row, or one per value of the range (the last constant) with
    run()'s values: start + k*step while within the final value (plus
    1e-9 of a step), and the final value last."""
    decls = []
    if program.ranges:
        decls = [
            "      double precision start, final, step, x",
            "      integer k, n, extra",
        ]
    lines = _prologue(program, decls)
    at: list[str] = []
    if not program.ranges:
        lines += _open(program)
        lines += ["      ierr = 0", _row(program).replace("        ", "      ", 1)]
    else:
        b = len(program.inputs) + 1
        name = program.ranges[0].name
        lines += [
            f"      start = v({b})",
            f"      final = v({b + 1})",
            f"      step = v({b + 2})",
            "      if (step .eq. 0d0 .and. final .ne. start) then",
            "        write(*, '(A)') 'error: the range step must not be 0'",
            "        stop 2",
            "      end if",
            "      if ((final - start) * step .lt. 0d0) step = -step",
            "      n = 0",
            "      if (final .ne. start) n = floor((final - start) / step + 1d-9)",
            "      extra = 0",
            "      if (abs(start + dble(n) * step - final) .gt.",
            "     &    1d-9 * max(1d0, abs(final))) extra = 1",
        ]
        lines += _open(program)
        lines += [
            "      ierr = 0",
            "      x = start",
            "      do k = 0, n + extra",
            "        if (k .lt. n .or. (k .eq. n .and. extra .eq. 1)) then",
            "          x = start + dble(k) * step",
            "        else",
            "          x = final",
            "        end if",
            f"        p(np) = x * fac({b})",
            _row(program),
            "        if (ierr .ne. 0) exit",
            "      end do",
        ]
        at = [f"        write(*, '(A, ES14.6)') ' at {name} =', x"]
    at = at or ["        write(*, '(A)') ''"]
    singular = [
        "        write(*, '(A)', advance='no') 'the equations are singular'",
        "     &    // ' (no unique solution)'",
    ]
    finite = ["        write(*, '(A)', advance='no') 'a value is not finite'"]
    errors = _error(program, "ierr .eq. 1", *singular, *at)
    errors += _error(program, "ierr .eq. 2", *finite, *at)
    return lines + _close(program, errors)


def _nonlinear_main(program: Program) -> list[str]:
    width = max(len(x) for x in program.labels)
    b = len(program.inputs) + program.ny
    lines = _prologue(
        program,
        [
            "      double precision res",
            "      integer worst, iters",
            f"      character(len={width}) label(ny)",
        ],
    )
    for k, text in enumerate(program.labels, start=1):
        lines.append(f"      label({k}) = '{text}'")
    lines += [
        f"      if (v({b + 1}) .le. 0d0 .or. v({b + 2}) .le. 0d0) then",
        "        write(*, '(A)') 'error: ABSERR and RELERR must be positive'",
        "        stop 2",
        "      end if",
        f"      call alnewt({_d(program.t0)}, ny, y, p, v({b + 1}), v({b + 2}),"
        " res,",
        "     &  worst, iters, ierr)",
        "      if (ierr .eq. 0) then",
        *_open(program),
        _row(program),
        "      end if",
    ]
    stem = program.stem
    singular = [
        "        write(*, '(A, I0, A)') 'the Jacobian of the equations is'",
        "     &    // ' singular after ', iters, ' Newton iterations; try'",
        f"     &    // ' other guesses in {stem}.in'",
    ]
    stalled = [
        "        write(*, '(A, A, A, ES10.3, A, I0, A)') 'no solution found'",
        f"     &    // ' from the guesses in {stem}.in: |', trim(label(worst)),",
        "     &    '| = ', res, ' after ', iters,",
        "     &    ' Newton iterations; try other guesses'",
    ]
    output = ["        write(*, '(A)') 'an output is not finite at the solution'"]
    errors = _error(program, "ierr .eq. 1", *singular)
    errors += _error(program, "ierr .eq. 4", *stalled)
    errors += _error(program, "ierr .ne. 0", *output)
    return lines + _close(program, errors)


def _row_routine(tables: list) -> list[str]:
    lines = _comment("One row of each output file (unit 10 + table number).")
    lines += [
        "      subroutine alrow(t, y, p, nout, of, nt, ncol, iw, nd, ierr)",
        "      implicit none",
        "      integer nout, nt, ncol(nt), iw(nt), nd, ierr, k, j",
        "      double precision t, y(*), p(*), of(nout), out(nout)",
        "      character(len=32) fmt",
        "      call outputs(t, y, p, out, ierr)",
        "      if (ierr .ne. 0) return",
        "      j = 0",
        "      do k = 1, nt",
    ]
    skip = [k for k, t in enumerate(tables, start=1) if not t.written]
    cond = " .and. ".join(f"k .ne. {k}" for k in skip)
    inner = [
        "          write(fmt, '(A, I0, A, I0, A, I0, A)') '(1X, ', ncol(k),",
        "     &      'ES', iw(k), '.', nd, ')'",
        "          write(10 + k, fmt) out(j + 1:j + ncol(k))",
        "     &      * of(j + 1:j + ncol(k))",
    ]
    if not tables:
        inner = ["          j = j + 0"]
    if cond:
        lines += [f"        if ({cond}) then", *inner, "        end if"]
    else:
        lines += ["        if (ncol(k) .gt. 0) then", *inner, "        end if"]
    lines += ["        j = j + ncol(k)", "      end do", "      end", ""]
    return lines


_SOLVE_F = """\
C     Solve a x = b (n x n) by Gaussian elimination with partial
C     pivoting; x is left in b.  ierr = 1 when a is singular.
      subroutine alsolve(n, a, b, ierr)
      implicit none
      integer n, ierr, i, j, k, piv
      double precision a(n, n), b(n), s, d
      ierr = 0
      do k = 1, n
        piv = k
        do i = k + 1, n
          if (abs(a(i, k)) .gt. abs(a(piv, k))) piv = i
        end do
        if (a(piv, k) .eq. 0d0) then
          ierr = 1
          return
        end if
        if (piv .ne. k) then
          do j = k, n
            s = a(k, j)
            a(k, j) = a(piv, j)
            a(piv, j) = s
          end do
          s = b(k)
          b(k) = b(piv)
          b(piv) = s
        end if
        d = a(k, k)
        do i = k + 1, n
          s = a(i, k) / d
          if (s .ne. 0d0) then
            do j = k + 1, n
              a(i, j) = a(i, j) - s * a(k, j)
            end do
            b(i) = b(i) - s * b(k)
          end if
        end do
      end do
      do i = n, 1, -1
        s = b(i)
        do j = i + 1, n
          s = s - a(i, j) * b(j)
        end do
        b(i) = s / a(i, i)
      end do
      end
"""

_KUTTA_F = """\
C     Kutta-Merson (L. Fox, 1962) with the step control of Autolev's
C     programs: advance t by H in sub-steps hc, halved while the error
C     estimate exceeds ABSERR and RELERR*|y|, doubled (up to H) while it
C     is 64 times smaller.  ierr: the eqns code, or 3 (step too small).
      subroutine kutta(t, bigh, n, y, p, hc, cuts, atol, rtol, ierr)
      implicit none
      integer n, cuts, ierr, i
      double precision t, bigh, y(n), p(*), hc, atol, rtol
      double precision f0(n), f1(n), f2(n), y1(n), y2(n), ud(n + 1)
      double precision tend, h, tt, err, rel
      logical fail, grow
      tend = t + bigh
      if (hc * bigh .lt. 0d0) hc = -hc
      if (hc .eq. 0d0) hc = bigh
      h = hc
      tt = t + h
      ierr = 0
      do while (tt + h .ne. tt)
        call eqns(tt - h, y, p, f0, ud, ierr)
        if (ierr .ne. 0) return
        y1 = y + h / 3d0 * f0
        call eqns(tt - 2d0 * h / 3d0, y1, p, f1, ud, ierr)
        if (ierr .ne. 0) return
        y1 = y + h / 6d0 * (f0 + f1)
        call eqns(tt - 2d0 * h / 3d0, y1, p, f1, ud, ierr)
        if (ierr .ne. 0) return
        y1 = y + h / 8d0 * (f0 + 3d0 * f1)
        call eqns(tt - h / 2d0, y1, p, f2, ud, ierr)
        if (ierr .ne. 0) return
        y1 = y + h / 2d0 * (f0 - 3d0 * f1 + 4d0 * f2)
        call eqns(tt, y1, p, f1, ud, ierr)
        if (ierr .ne. 0) return
        y2 = y + h / 6d0 * (f0 + 4d0 * f2 + f1)
        fail = .false.
        grow = .true.
        do i = 1, n
          err = 0.2d0 * abs(y1(i) - y2(i))
          rel = rtol * abs(y1(i))
          if (err .ge. rel .and. err .ge. atol) then
            fail = .true.
            exit
          end if
          if (64d0 * err .gt. rel .and. 64d0 * err .gt. atol) then
            grow = .false.
          end if
        end do
        if (fail) then
          tt = tt - h / 2d0
          h = h / 2d0
          hc = h
          cuts = cuts - 1
          if (cuts .ge. 0) cycle
          t = tt - h
          ierr = 3
          return
        end if
        y = y2
        if (grow .and. abs(2d0 * h) .le. abs(bigh)) then
          if ((bigh .gt. 0d0 .and. tt + 2d0 * h .le. tend) .or.
     &        (bigh .lt. 0d0 .and. tt + 2d0 * h .ge. tend)) then
            h = 2d0 * h
            hc = h
            cuts = cuts + 1
          end if
        end if
        if (tt .eq. tend) then
          t = tend
          return
        end if
        tt = tt + h
        if ((h .gt. 0d0 .and. tt .gt. tend - 0.1d0 * h) .or.
     &      (h .lt. 0d0 .and. tt .lt. tend - 0.1d0 * h)) then
          h = tend - (tt - h)
          tt = tend
        end if
      end do
      t = tt
      ierr = 3
      end
"""

_READ_F = """\

C     Read the values of name.in: 6 header lines, then each group's
C     values from column 60, one more line after each group.
      subroutine alread(name, nin, ngrp, v, ierr)
      implicit none
      character(len=*) name
      integer nin, ngrp(3), ierr, g, i, k, line, ios
      double precision v(nin)
      character(len=4096) text
      ierr = 0
      open(9, file=name, status='old', action='read', iostat=ios)
      if (ios .ne. 0) return
      line = 0
      do i = 1, 6
        line = line + 1
        read(9, '(A)', iostat=ios) text
        if (ios .ne. 0) go to 90
      end do
      k = 0
      do g = 1, 3
        if (ngrp(g) .eq. 0) cycle
        do i = 1, ngrp(g)
          k = k + 1
          line = line + 1
          read(9, '(A)', iostat=ios) text
          if (ios .ne. 0) go to 90
          read(text(60:), *, iostat=ios) v(k)
          if (ios .ne. 0) go to 80
        end do
        line = line + 1
        read(9, '(A)', iostat=ios) text
        if (ios .ne. 0) go to 90
      end do
      close(9)
      return
   80 write(*, '(A, A, I0, A)') name, ' line ', line,
     &  ': expected a number from column 60'
      ierr = 1
      close(9)
      return
   90 write(*, '(A, A, I0)') name, ' ends before its last value, line ',
     &  line
      ierr = 1
      close(9)
      end
"""

_ARGS_F = """\

C     The arguments NAME=VALUE: VALUE (in the Input's unit) replaces the
C     value of the input NAME (any case), as in the C program.
      subroutine alargs(nin, names, v, ierr)
      implicit none
      integer nin, ierr, i, k, eq, ios, c
      character(len=*) names(nin)
      double precision v(nin), x
      character(len=4096) arg
      ierr = 0
      do i = 1, command_argument_count()
        call get_command_argument(i, arg)
        eq = index(arg, '=')
        if (eq .le. 1) then
          write(0, '(A, A, A)') 'error: ', trim(arg),
     &      ': expected NAME=VALUE'
          ierr = 1
          return
        end if
        do k = 1, eq - 1
          c = ichar(arg(k:k))
          if (c .ge. 97 .and. c .le. 122) arg(k:k) = char(c - 32)
        end do
        ios = 1
        if (len_trim(arg(eq + 1:)) .gt. 0 .and.
     &      scan(trim(adjustl(arg(eq + 1:))), ' ,/') .eq. 0) then
          read(arg(eq + 1:), *, iostat=ios) x
        end if
        if (ios .ne. 0) then
          write(0, '(A, A, A, A, A)') 'error: ', trim(arg), ': ',
     &      trim(arg(eq + 1:)), ' is not a number'
          ierr = 1
          return
        end if
        do k = 1, nin
          if (arg(1:eq - 1) .eq. names(k)) exit
        end do
        if (k .gt. nin) then
          write(0, '(A, A, A)', advance='no') 'error: ', arg(1:eq - 1),
     &      ' is not an input; inputs:'
          do k = 1, nin
            write(0, '(A, A)', advance='no') ' ', trim(names(k))
          end do
          write(0, '(A)') ''
          ierr = 1
          return
        end if
        v(k) = x
      end do
      end
"""

_NEWTON_F = """\
C     Newton's method from the guesses y: eqns leaves the residuals F
C     in f and the step dx solving J dx = -F in dx.  A step is halved
C     (up to 30 times) until max|F| decreases.  Converged when max|F| <=
C     ABSERR * max(1, max|F(guesses)|) and every |dx(i)| <= ABSERR +
C     RELERR*|y(i)|; that last step is taken.  ierr: 0, 1 (J singular),
C     2 (not finite) or 4 (no convergence in 100 iterations); res: max|F|,
C     worst: its i.
      subroutine alnewt(t, n, y, p, abserr, relerr, res, worst, iters,
     &  ierr)
      implicit none
      integer n, worst, iters, ierr, i, half, w, c
      double precision t, y(n), p(*), abserr, relerr, res
      double precision f(n), dx(n), yn(n), fn(n), dxn(n), tol, lam, next
      logical small
      call eqns(t, y, p, f, dx, ierr)
      call alnorm(n, f, res, worst)
      tol = abserr * max(1d0, res)
      iters = 0
      do while (iters .lt. 100)
        if (ierr .ne. 0) return
        small = .true.
        do i = 1, n
          if (abs(dx(i)) .gt. abserr + relerr * abs(y(i))) then
            small = .false.
          end if
        end do
        if (small .and. res .le. tol) then
          y = y + dx
          return
        end if
        lam = 1d0
        half = 0
        do
          yn = y + lam * dx
          call eqns(t, yn, p, fn, dxn, c)
          call alnorm(n, fn, next, w)
          if (c .ne. 2 .and. next .lt. res) exit
          if (half .eq. 30) then
            ierr = 4
            return
          end if
          half = half + 1
          lam = lam / 2d0
        end do
        y = yn
        dx = dxn
        res = next
        worst = w
        ierr = c
        iters = iters + 1
      end do
      ierr = 4
      end

C     m = max|f(i)| (a NaN is the largest), worst: its i.
      subroutine alnorm(n, f, m, worst)
      implicit none
      integer n, worst, i
      double precision f(n), m
      m = 0d0
      worst = 1
      do i = 1, n
        if (.not. (abs(f(i)) .le. m)) then
          m = abs(f(i))
          worst = i
        end if
      end do
      end
"""
