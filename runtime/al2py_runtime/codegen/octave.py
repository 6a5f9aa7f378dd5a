"""The MATLAB spelling of a :class:`~.program.Program`: one function file
(``STEM.m``) printed by sympy's ``octave_code``; runs under MATLAB and GNU
Octave (``octave --eval STEM``) without warnings."""

from __future__ import annotations

import math
import operator
import textwrap
from typing import Any

import sympy as sp
from sympy.core.numbers import equal_valued
from sympy.printing.octave import OctaveCodePrinter

from ..jobs import backends
from ..jobs.run import NumericsError
from .printers import Remembering, names_sorted
from .program import Assign, Program, one_based_target

__all__ = ["octave_source"]


def _num(x: float) -> str:
    return repr(float(x)) if math.isfinite(x) else "0"


def _str(text: str) -> str:
    return "'" + text.replace("'", "''") + "'"


class _Printer(Remembering, OctaveCodePrinter):
    """sympy's MATLAB printer, the same text faster (see
    :class:`.printers.Remembering`)."""

    # doprint prints a sum, product, name or function's value without
    # walking it first (see ProgramPrinter.doprint)
    watches = True
    plain_calls = True

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings)
        #: sympy's ``order`` setting, read once (a property of the printer)
        self._order_setting = self.order
        #: whether the printer orders a product's factors
        self._orders_factors = self._order_setting not in ("old", "none")
        #: a power -> its inverse (backends.product_parts)
        self._inverses: dict = {}
        #: name -> (name, its text, the symbol): see _name_entry
        self._named: dict[str, tuple] = {}

    def _print_Add(self, expr: Any, order: Any = None) -> str:
        if order is not None or self._order_setting is not None:
            return self.print_ordered_add(expr, order)
        keyed = self._names_order(expr.args)
        if keyed is not _UNKNOWN:
            if keyed is None:
                return self.print_unnamed_add(expr)
            return _joined_sum([(term, text) for _key, term, text in keyed], self)
        found = names_sorted(expr.args)
        if found is None:
            return self.print_unnamed_add(expr)
        return self._names_sum(expr, found)

    def _names_order(self, terms: tuple) -> list | None | object:
        """:func:`.printers.names_sorted`'s order of a sum's ``terms``
        (None where it gives None) as ``(key, term, text)``, ``text`` the
        term's as :meth:`_names_sum` prints a name or a product of names
        after -1 or nothing (None for other terms), read off the names'
        entries (:meth:`_name_entry`); ``_UNKNOWN`` for a sum of a name
        without an entry, or of a symbol named as another's entry (then
        ``names_sorted`` decides).

        The key of a term is its names sorted, then the end, after every
        name (names_sorted's keys, ``(0, name)`` for a name and ``(1, "")``
        for the end, compare so)."""
        for term in terms:  # (what names_sorted gives None for, first)
            kind = type(term)
            if kind is sp.Mul:
                args = term.args
                if type(args[0]) is not _NAME and not args[0].is_Number:
                    return None
                for f in args[1:]:
                    if type(f) is not _NAME:
                        return None
            elif kind is not _NAME:
                return None
        named = self._named
        keyed = []
        for term in terms:
            kind = type(term)
            if kind is _NAME:
                factors: tuple = (term,)
                lead = None
            elif kind is sp.Mul:
                factors = term.args
                lead = factors[0]
                if lead.is_Number:
                    factors = factors[1:]
                else:
                    lead = None
                if not factors:
                    return None
            else:
                return None
            entries = self._entries(factors, named)
            if type(entries) is not list:
                return entries  # (None or _UNKNOWN)
            if len(entries) > 1:
                entries.sort(key=_first)
                for i in range(1, len(entries)):
                    if entries[i][0] == entries[i - 1][0]:
                        return None  # a name twice
                key = (*[entry[0] for entry in entries], _END)
                text = ".*".join([entry[1] for entry in entries])
            else:
                key = (entries[0][0], _END)
                text = entries[0][1]
            if lead is not None:
                text = "-" + text if lead is _MINUS_ONE else None
            keyed.append((key, term, text))
        keyed.sort(key=_first)
        for i in range(1, len(keyed)):
            if keyed[i][0] == keyed[i - 1][0]:
                return None  # two terms of one monomial
        return keyed

    def _entries(self, names: tuple, named: dict) -> list | None | object:
        """The entries (:meth:`_name_entry`) of ``names``, in order; None
        where one is not a name, ``_UNKNOWN`` where a name has no entry or
        is not its entry's symbol (``named``: the printer's entries)."""
        entries = []
        for f in names:
            if type(f) is not _NAME:
                return None
            entry = named.get(f.name)
            if entry is None:
                entry = self._name_entry(f)
            if entry is None or entry[2] is not f:
                return _UNKNOWN
            entries.append(entry)
        return entries

    def _name_entry(self, name: Any) -> tuple | None:
        """A new entry ``(its name, its text, name)`` of a name (a plain
        symbol) that commutes, whose name comes before ``_END``, kept per
        name for the printer (the first such symbol of its name); None for
        another."""
        key = name.name
        if not name.is_commutative or not key < _END or key in self._named:
            return None
        entry = self._named[key] = (key, self.print_part(name), name)
        return entry

    def _names_sum(self, expr: Any, found: list) -> str:
        """``print_ordered_add(expr)`` of a sum of names and products of
        names (after a number), most sums of a program: the terms in
        ``as_ordered_terms``'s order (``found``: :func:`.printers.names_sorted`
        of its terms, each with its names sorted by name), joined by
        :func:`~al2py_runtime.jobs.backends.join_sum`, which is given each
        product of names (after -1 or nothing) as :meth:`names_product`
        prints it, from those sorted names (not sorted again)."""
        part = self.print_part
        texts = []
        for term, names in found:
            text = None
            if type(term) is sp.Mul:
                first = term.args[0]
                if first is _MINUS_ONE:
                    text = "-" + ".*".join([part(a) for a in names])
                elif not first.is_Number:
                    text = ".*".join([part(a) for a in names])
            texts.append((term, text))
        return _joined_sum(texts, self)

    def _print_Mul(self, expr: Any) -> str:
        # OctaveCodePrinter._print_Mul with the number tests, precedences
        # and sort keys remembered
        order = self.remembered_factors if self._orders_factors else None
        if order is not None:
            text = self.names_product(expr)
            if text is not None:
                return text
        number = self.remembered_number
        if (
            number(expr)
            and expr.is_imaginary
            and (sp.S.ImaginaryUnit * expr).is_Integer
        ):
            return f"{self._print(-sp.S.ImaginaryUnit * expr)}i"
        sign, a, a_str, b, b_str = backends.product_parts(
            self,
            expr,
            self.remembered_precedence(expr),
            order if order is None or not expr.is_commutative else self.commuting_order,
            rationals=True,
            lone_minus=False,
            inverses=self._inverses,
        )

        def multjoin(a: list, a_str: list) -> str:
            r = a_str[0]
            for i in range(1, len(a)):
                r = r + ("*" if number(a[i - 1]) else ".*") + a_str[i]
            return r

        if not b:
            return sign + multjoin(a, a_str)
        if len(b) == 1:
            divsym = "/" if number(b[0]) else "./"
            return sign + multjoin(a, a_str) + divsym + b_str[0]
        divsym = "/" if all(number(bi) for bi in b) else "./"
        return sign + multjoin(a, a_str) + divsym + f"({multjoin(b, b_str)})"

    def names_product(self, expr: Any) -> str | None:
        """:meth:`_print_Mul`'s text of a product of names alone, or of -1
        and names, that commute (most products), when the printer orders
        factors: ordered by name (``remembered_factors``), each as it is,
        joined by ``.*``; None for any other product."""
        if not self._orders_factors:
            return None
        args = expr.args  # (as backends.signed_names splits it)
        sign = ""
        if args[0] is _MINUS_ONE:
            sign, args = "-", args[1:]
        if not args:
            return None
        entries = self._entries(args, self._named)
        if entries is None:
            return None
        if entries is not _UNKNOWN:
            if len(entries) > 1:
                entries.sort(key=_first)  # by name
            return sign + ".*".join([entry[1] for entry in entries])
        for a in args:  # (each name asked and printed here)
            if type(a) is not _NAME or not a.is_commutative:
                return None
        ordered = sorted(args, key=_name)
        return sign + ".*".join([self.print_part(a) for a in ordered])

    def joined_terms(self, expr: Any, terms: list) -> str:
        """The text of the sum ``expr`` of ``terms`` in that order (its
        products of names printed at once: :meth:`names_product`)."""
        return backends.join_sum(
            self,
            terms,
            self.remembered_precedence(expr),
            self.remembered_precedence,
            self.names_product,
        )

    def _print_Pow(self, expr: Any) -> str:
        # OctaveCodePrinter._print_Pow with the number tests and precedences
        # remembered
        number = self.remembered_number
        powsymbol = "^" if all(number(x) for x in expr.args) else ".^"
        prec = self.remembered_precedence(expr)
        whole = expr.exp.is_Integer  # then only -1 can match below
        if not whole and equal_valued(expr.exp, 0.5):
            return f"sqrt({self.print_part(expr.base)})"
        if expr.is_commutative:
            if not whole and equal_valued(expr.exp, -0.5):
                sym = "/" if number(expr.base) else "./"
                return "1" + sym + f"sqrt({self.print_part(expr.base)})"
            if expr.exp.p == -1 if whole else equal_valued(expr.exp, -1):
                sym = "/" if number(expr.base) else "./"
                return "1" + sym + self.parenthesize(expr.base, prec)
        base = self.parenthesize(expr.base, prec)
        return f"{base}{powsymbol}{self.parenthesize(expr.exp, prec)}"


def _name(symbol: Any) -> str:
    return symbol.name


_MINUS_ONE = sp.S.NegativeOne
_NAME = sp.Symbol
#: after every name in :meth:`_Printer._names_order`'s keys (a name that
#: does not come before it has no entry)
_END = "\U0010ffff"
#: :meth:`_Printer._names_order` of a sum it does not decide
_UNKNOWN = object()
_first = operator.itemgetter(0)


def _joined_sum(texts: list, printer: Any) -> str:
    """The text of a sum of names and products of names (after a number),
    ``texts`` its terms in order with the text of each name or product of
    names after -1 or nothing (else None: printed by ``printer``), as
    :func:`~al2py_runtime.jobs.backends.join_sum` joins them.  No term is
    put in parentheses: a name's precedence is an atom's, a product's
    after a number a product's or, after a negative one, a sum's, none
    below the sum's."""
    out = []
    for term, text in texts:
        if text is None:
            text = printer.print_part(term)
        if text.startswith("-"):
            out += ["-", text[1:]]
        else:
            out += ["+", text]
    sign = out.pop(0)
    return ("" if sign == "+" else sign) + " ".join(out)


def _code(printer: Any, expr: Any, target: str, symbol: Any = None) -> str:
    """The statement ``target = expr`` (``symbol``: the target's, when the
    program has it: assigned to as the name ``target`` is)."""
    found = printer.statements.get((expr, target))
    if found is not None:
        return found
    to = target if symbol is None else symbol
    try:
        text = printer.doprint(sp.sympify(expr), assign_to=to)
    except Exception as exc:  # noqa: BLE001 - PrintMethodNotImplementedError, ...
        what = str(exc).split("\n")[0]
        raise NumericsError(f"MATLAB cannot print {expr}: {what}") from None
    printer.statements[expr, target] = text
    return text


def _body(program: Program, block: list[Assign], printer: Any) -> list[str]:
    n = program.nu
    params, states = program.entries_used(block)
    lines = [f"  {e.ident} = p({i + 1});" for i, e in params]
    lines += [f"  {e.ident} = y({i + 1});" for i, e in states]
    solve = [
        "  if rcond(mm) == 0 || any(~isfinite(mm(:)))",
        "    ierr = 1;",
        "    return",
        "  end",
        "  ud = mm \\ ud;",
    ]
    for k, a in enumerate(block):
        kind = a.target[0]
        if k == program.solve_at and n and block is program.eqns:
            lines += solve
        if kind == "ud":
            lines.append(f"  {a.target[2]} = ud({a.target[1] + 1});")
            continue
        target = one_based_target(a)
        lines.append("  " + _code(printer, a.expr, target, a.symbol))
    if block is program.eqns and program.solve_at == len(block) and n:
        lines += solve
    return lines


def equations(program: Program, name: str) -> list[str]:
    printer = _Printer({"strict": True})
    n, ny, nout = program.nu, program.ny, program.nout
    lines = [
        f"function [dy, ud, ierr] = {name}(T, y, p)",
        *("  % " + text for text in program.eqns_doc),
        "  % ierr is the code.",
        "  ierr = 0;",
        f"  dy = zeros({ny}, 1);",
        f"  ud = zeros({max(n, 1)}, 1);",
    ]
    if n:
        lines.append(f"  mm = zeros({n}, {n});")
    lines += _body(program, program.eqns, printer)
    lines += [
        "  if any(~isfinite(dy))",
        "    ierr = 2;",
        "  end",
        "end",
        "",
        "function [out, ierr] = outputs(T, y, p)",
        "  % The output quantities at (T, y), all tables' columns in order.",
        f"  out = zeros({nout}, 1);",
        "  [dy, ud, ierr] = eqns(T, y, p);",
        "  if ierr",
        "    return",
        "  end",
    ]
    lines += _body(program, program.outputs, printer)
    lines += ["end", ""]
    return lines


def octave_source(program: Program, target: str) -> str:
    job = program.job
    stem = program.stem
    head = [
        f"% {target}: generated by al2py {program.version} from {program.source}",
        f"% ({job.where}); edit the .al file and generate again.",
    ]
    if program.nosubs:
        lines = [
            f"function [dy, out] = {stem}(T, y, p)",
            *head,
            "% NOSUBS: the equations only.  dy = y'(T); out (when asked for):",
            "% the outputs, all tables in order.  p holds the constants "
            + ", ".join(e.name for e in program.constants),
            "% and y the states "
            + ", ".join(e.name for e in program.initials)
            + " (internal units).",
            "  [dy, ~, ierr] = eqns(T, y, p);",
            "  if nargout > 1 && ~ierr",
            "    [out, ierr] = outputs(T, y, p);",
            "  end",
            "  if ierr",
            "    error('%s: singular mass matrix or a value not finite at T = %g',"
            f" {_str(stem)}, T);",
            "  end",
            "end",
            "",
        ]
        lines += equations(program, "eqns")
        return "\n".join(lines)
    entries = program.entries
    np_ = len(program.inputs)
    base = np_ + program.ny
    lines = [
        f"function {stem}(varargin)",
        *head,
        "%",
        f"% Run: octave --eval {stem}  (or {stem} at the MATLAB prompt).  Reads",
        f"% {stem}.in when it is in the current folder (values from column 60, a",
        "% blank line after each group), else starts from the script's Input",
        "% values; NAME=VALUE arguments change them, in their Input's units",
        f'% ({stem} NAME=VALUE at the prompt, octave --eval "{stem} NAME=VALUE").',
        *["% " + x for x in textwrap.wrap(program.task, 70)],
        "  % Inputs: value (in the Input's unit), factor to internal units",
        "  v = [" + "; ".join(_num(e.value) for e in entries) + "];",
        "  fac = [" + "; ".join(_num(e.factor) for e in entries) + "];",
        "  groups = [" + ", ".join(str(len(g)) for g in program.groups) + "];",
        f"  v = read_in({_str(stem + '.in')}, v, groups);",
        "  names = {" + "; ".join(_str(e.setting) for e in entries) + "};",
        "  v = set_args(names, v, varargin);",
        *[f"  fprintf(2, '%s\\n', {_str('note: ' + x)});" for x in program.notes],
        "  raw = v;",
        "  v = v .* fac;",
        f"  p = v(1:{np_});" if np_ else "  p = 0;",
        f"  y = v({np_ + 1}:{base});" if program.ny else "  y = 0;",
    ]
    if program.kind == "NONLINEAR":
        lines += _nonlinear_main(program, base)
        tail = _NEWTON_M
    elif program.kind == "ALGEBRAIC":
        lines += _algebraic_main(program, base)
        tail = ""
    else:
        lines += _dynamics_main(base)
        tail = _KUTTA_M
    lines += ["end", ""]
    lines += _files(program)
    lines += equations(program, "eqns")
    lines += (tail + _READ_M + _ARGS_M).splitlines()
    return "\n".join(lines) + "\n"


def _files(program: Program) -> list[str]:
    """``open_files`` (the output files with their headers) and
    ``write_row`` (one row of each, from the outputs at (t, y))."""
    stem, tables = program.stem, program.tables
    lines = [
        "function fids = open_files()",
        "  % The output files (0 for Encode's quantities), headers written.",
        f"  fids = zeros(1, {len(tables)});",
    ]
    for k, t in enumerate(tables, start=1):
        if not t.written:
            continue
        lines += [
            f"  fids({k}) = fopen({_str(f'{stem}.{k}')}, 'w');",
            f"  if fids({k}) < 0",
            f"    error('cannot write %s', {_str(f'{stem}.{k}')});",
            "  end",
        ]
        for text in t.header[:-1].split("\n"):
            lines.append(f"  fprintf(fids({k}), '%s\\n', {_str(text)});")
    fmts = ", ".join(
        _str(
            " "
            + "".join(f"%{t.width}.{program.digits - 1}E" for _ in range(t.columns))
            + "\\n"
        )
        for t in tables
    )
    lines += [
        "end",
        "",
        "function ierr = write_row(fids, t, y, p)",
        "  % One row of each output file: the outputs at (t, y) in their units.",
        "  ncol = [" + ", ".join(str(t.columns) for t in tables) + "];",
        "  ofac = [" + "; ".join(_num(x) for t in tables for x in t.factors) + "];",
        "  fmts = {" + fmts + "};",
        "  [out, ierr] = outputs(t, y, p);",
        "  if ierr",
        "    return",
        "  end",
        "  out = out .* ofac;",
        "  j = 0;",
        "  for k = 1:numel(ncol)",
        "    if fids(k) > 0",
        "      fprintf(fids(k), fmts{k}, out(j + 1:j + ncol(k)));",
        "    end",
        "    j = j + ncol(k);",
        "  end",
        "end",
        "",
        "function close_files(fids)",
        "  % Close the output files and list them.",
        "  for k = find(fids > 0)",
        "    fclose(fids(k));",
        "  end",
        "  for k = find(fids > 0)",
        f"    fprintf('Wrote %s.%d\\n', {_str(stem)}, k);",
        "  end",
        "end",
        "",
    ]
    return lines


def _dynamics_main(base: int) -> list[str]:
    return [
        f"  t0 = v({base + 1}); t1 = v({base + 2}); step = v({base + 3});",
        f"  printint = raw({base + 4});",
        f"  abserr = v({base + 5}); relerr = v({base + 6});",
        "  if step == 0 || printint <= 0 || abserr <= 0 || relerr <= 0 ...",
        "      || printint ~= fix(printint)",
        "    error('INTEGSTP must not be 0; PRINTINT (whole), ABSERR and RELERR"
        " must be positive');",
        "  end",
        "  if (t1 - t0) * step < 0",
        "    step = -step;",
        "  end",
        "  fids = open_files();",
        "  % As Autolev's programs: a row at TINITIAL, after every PRINTINT steps",
        "  % of INTEGSTP, and at the first step within INTEGSTP/100 of TFINAL.",
        "  t = t0; hc = 0; cuts = 20; count = 0;",
        "  [~, ~, ierr] = eqns(t, y, p);",
        "  while ~ierr",
        "    if t1 >= t0",
        "      last = t + 0.01 * abs(step) >= t1;",
        "    else",
        "      last = t - 0.01 * abs(step) <= t1;",
        "    end",
        "    if count <= 0 || last",
        "      ierr = write_row(fids, t, y, p);",
        "      if ierr || last",
        "        break",
        "      end",
        "      count = printint;",
        "    end",
        "    [t, y, hc, cuts, ierr] = kutta(t, step, y, p, hc, cuts, abserr, relerr);",
        "    count = count - 1;",
        "  end",
        "  if ierr",
        "    fclose('all');",
        "  end",
        "  if ierr == 1",
        "    error('the mass matrix is singular at t = %g', t);",
        "  elseif ierr == 2",
        "    error('a value is not finite at t = %g', t);",
        "  elseif ierr == 3",
        "    error('integration failed at t = %g: the step was halved too often', t);",
        "  end",
        "  close_files(fids);",
    ]


def _algebraic_main(program: Program, base: int) -> list[str]:
    """One row, or one per value of the range (the last constant) with
    run()'s values: start + k*step while within the final value (plus
    1e-9 of a step), and the final value last."""
    where = _str(program.job.where)
    t0 = _num(program.t0)
    if not program.ranges:
        return [
            "  fids = open_files();",
            f"  ierr = write_row(fids, {t0}, y, p);",
            "  if ierr",
            "    fclose('all');",
            f"    error('%s: the equations are singular (no unique solution)"
            f" or a value is not finite', {where});",
            "  end",
            "  close_files(fids);",
        ]
    name = _str(program.ranges[0].name)
    return [
        f"  start = raw({base + 1}); final = raw({base + 2}); step = raw({base + 3});",
        "  if step == 0 && final ~= start",
        "    error('the range step must not be 0');",
        "  end",
        "  if (final - start) * step < 0",
        "    step = -step;",
        "  end",
        "  n = 0;",
        "  if final ~= start",
        "    n = floor((final - start) / step + 1e-9);",
        "  end",
        "  extra = abs(start + n * step - final) > 1e-9 * max(1, abs(final));",
        "  fids = open_files();",
        "  for k = 0:n + extra",
        "    if k < n || (k == n && extra)",
        "      x = start + k * step;",
        "    else",
        "      x = final;",
        "    end",
        f"    p({program.np}) = x * fac({base + 1});",
        f"    if write_row(fids, {t0}, y, p)",
        "      fclose('all');",
        f"      error('%s: the equations are singular (no unique solution)"
        f" or a value is not finite at %s = %g', {where}, {name}, x);",
        "    end",
        "  end",
        "  close_files(fids);",
    ]


def _nonlinear_main(program: Program, base: int) -> list[str]:
    where = _str(program.job.where)
    labels = "{" + ", ".join(_str(x) for x in program.labels) + "}"
    stem = _str(program.stem + ".in")
    return [
        f"  abserr = v({base + 1}); relerr = v({base + 2});",
        "  if abserr <= 0 || relerr <= 0",
        "    error('ABSERR and RELERR must be positive');",
        "  end",
        f"  [y, res, worst, iters, ierr] = newton({_num(program.t0)}, y, p,"
        " abserr, relerr);",
        f"  labels = {labels};",
        "  if ierr == 1",
        "    error(['%s: the Jacobian of the equations is singular after %d Newton'"
        " ...",
        f"           ' iterations; try other guesses in %s'], {where}, iters, {stem});",
        "  elseif ierr",
        "    error(['%s: no solution found from the guesses in %s: |%s| = %.3g' ...",
        "           ' after %d Newton iterations; try other guesses'],"
        f" {where}, {stem}, ...",
        "          labels{worst}, res, iters);",
        "  end",
        "  fids = open_files();",
        f"  if write_row(fids, {_num(program.t0)}, y, p)",
        "    fclose('all');",
        f"    error('%s: an output is not finite at the solution', {where});",
        "  end",
        "  close_files(fids);",
    ]


_KUTTA_M = r"""function [t, y, hc, cuts, ierr] = kutta(t, bigh, y, p, hc, cuts, abserr, relerr)
  % Kutta-Merson (L. Fox, 1962) with the step control of Autolev's
  % programs: advance t by bigh in sub-steps hc, halved while the error
  % estimate exceeds ABSERR and RELERR*|y|, doubled (up to bigh) while it
  % is 64 times smaller.  ierr: the eqns code, or 3 (step too small).
  tend = t + bigh;
  if hc * bigh < 0
    hc = -hc;
  end
  if hc == 0
    hc = bigh;
  end
  h = hc;
  tt = t + h;
  ierr = 0;
  while tt + h ~= tt
    [f0, ~, ierr] = eqns(tt - h, y, p);
    if ierr, return; end
    [f1, ~, ierr] = eqns(tt - 2 * h / 3, y + h / 3 * f0, p);
    if ierr, return; end
    [f1, ~, ierr] = eqns(tt - 2 * h / 3, y + h / 6 * (f0 + f1), p);
    if ierr, return; end
    [f2, ~, ierr] = eqns(tt - h / 2, y + h / 8 * (f0 + 3 * f1), p);
    if ierr, return; end
    y1 = y + h / 2 * (f0 - 3 * f1 + 4 * f2);
    [f1, ~, ierr] = eqns(tt, y1, p);
    if ierr, return; end
    y2 = y + h / 6 * (f0 + 4 * f2 + f1);
    err = 0.2 * abs(y1 - y2);
    rel = relerr * abs(y1);
    if any(err >= rel & err >= abserr)
      tt = tt - h / 2;
      h = h / 2;
      hc = h;
      cuts = cuts - 1;
      if cuts >= 0
        continue
      end
      t = tt - h;
      ierr = 3;
      return
    end
    y = y2;
    grow = ~any(64 * err > rel & 64 * err > abserr);
    if grow && abs(2 * h) <= abs(bigh) && ...
        ((bigh > 0 && tt + 2 * h <= tend) || (bigh < 0 && tt + 2 * h >= tend))
      h = 2 * h;
      hc = h;
      cuts = cuts + 1;
    end
    if tt == tend
      t = tend;
      return
    end
    tt = tt + h;
    if (h > 0 && tt > tend - 0.1 * h) || (h < 0 && tt < tend - 0.1 * h)
      h = tend - (tt - h);
      tt = tend;
    end
  end
  t = tt;
  ierr = 3;
end

"""

_NEWTON_M = r"""function [y, res, worst, iters, ierr] = newton(t, y, p, abserr, relerr)
  % Newton's method from the guesses y: eqns gives the residuals F and the
  % step dx solving J dx = -F.  A step is halved (up to 30 times) until
  % max|F| decreases.  Converged when max|F| <= ABSERR * max(1,
  % max|F(guesses)|) and every |dx(i)| <= ABSERR + RELERR*|y(i)|; that last
  % step is taken.  ierr: 0, 1 (J singular), 2 (not finite) or 4 (no
  % convergence in 100 iterations); res: max|F|, worst: its i.
  [f, dx, ierr] = eqns(t, y, p);
  [res, worst] = maxabs(f);
  tol = abserr * max(1, res);
  iters = 0;
  while iters < 100
    if ierr
      return
    end
    if all(abs(dx) <= abserr + relerr * abs(y)) && res <= tol
      y = y + dx;
      return
    end
    lam = 1;
    for half = 0:30
      yn = y + lam * dx;
      [fn, dxn, c] = eqns(t, yn, p);
      [next, w] = maxabs(fn);
      if c ~= 2 && next < res
        break
      end
      lam = lam / 2;
    end
    if c == 2 || next >= res || isnan(next)
      ierr = 4;
      return
    end
    y = yn;
    dx = dxn;
    res = next;
    worst = w;
    ierr = c;
    iters = iters + 1;
  end
  ierr = 4;
end

function [m, worst] = maxabs(f)
  % max|f(i)| (a NaN is the largest) and its i.
  a = abs(f);
  a(isnan(a)) = Inf;
  [m, worst] = max(a);
end

"""

_ARGS_M = r"""
function v = set_args(names, v, args)
  % NAME=VALUE arguments (STEM QA=30 at the prompt, or octave --eval
  % "STEM QA=30"): VALUE, in the Input's unit, replaces the value of the
  % input NAME (any case), as in the C program.
  for i = 1:numel(args)
    arg = args{i};
    eq = strfind(arg, '=');
    if isempty(eq) || eq(1) == 1
      error('%s: expected NAME=VALUE', arg);
    end
    name = upper(arg(1:eq(1) - 1));
    text = arg(eq(1) + 1:end);
    x = str2double(text);
    if isnan(x) && ~strcmpi(strtrim(text), 'nan')
      error('%s: ''%s'' is not a number', arg, text);
    end
    k = find(strcmp(names, name), 1);
    if isempty(k)
      error('%s is not an input; inputs: %s', name, strjoin(names', ' '));
    end
    v(k) = x;
  end
end
"""

_READ_M = r"""
function v = read_in(name, v, groups)
  % name.in: 6 header lines, then each group's values from column 60, one
  % more line after each group.  Keeps v when the file is absent.
  fid = fopen(name, 'r');
  if fid < 0
    return
  end
  for i = 1:6
    fgetl(fid);
  end
  k = 0;
  line = 6;
  for g = groups
    for i = 1:g
      text = fgetl(fid);
      line = line + 1;
      x = NaN;
      if ischar(text) && numel(text) >= 60
        x = str2double(text(60:end));
      end
      if isnan(x)
        fclose(fid);
        error('%s line %d: expected one number from column 60', name, line);
      end
      k = k + 1;
      v(k) = x;
    end
    fgetl(fid);
    line = line + 1;
  end
  fclose(fid);
end
"""
