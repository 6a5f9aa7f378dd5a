"""The program printers' machinery, shared by the C, MATLAB and Fortran
printers (:mod:`.c`, :mod:`.octave`, :mod:`.fortran`): sympy's printing,
the same text, with what it does again and again done once.

:class:`ProgramPrinter` (every dialect's) finds the printing method of a
part's class once per printer (sympy's rule, walked again for every part
by sympy's ``_print``), prints each part once per program (its text
remembered), and prints a plain assignment -- what nearly every statement
of a program is -- without ``doprint``'s walks and wrappers.

:class:`Remembering` (MATLAB's and Fortran's): sympy's MATLAB and Fortran
printers order a sum's terms by ``as_ordered_terms`` (the monomials'
exponents in generators sorted by ``default_sort_key``) and a product's
factors by ``as_ordered_factors``, and ask ``is_number`` and
``precedence`` at every node they visit: each walks the subtree again, and
sympy's cache of sort keys (1,000 entries) is soon overrun by a large
program, so the keys were formed again down to the leaves.
:class:`Remembering` forms each once per printer (one program).
"""

from __future__ import annotations

import operator
from typing import Any

import sympy as sp
from sympy.core.exprtools import decompose_power
from sympy.tensor.indexed import IndexedBase

from ..intermediates.autoz import as_terms
from ..jobs import backends
from ..names.printing import is_number_in, sort_key_in

__all__ = [
    "ProgramPrinter",
    "Remembering",
    "holds_instance",
    "key_order",
    "names_sorted",
]

#: what a statement holding one of is printed by sympy's ``doprint``, and
#: a part holding one of is printed each time (see ProgramPrinter)
_SPECIAL = (sp.re, IndexedBase, sp.NumberSymbol)


class ProgramPrinter:
    """A mixin for a strict sympy code printer (before it in the bases) that
    prints one program's statements: each part printed once, sums,
    products and names through the printer's own method directly, a plain
    assignment printed without ``doprint``'s walks and wrappers.

    * **Parts.** The printer's own methods print a statement's parts with
      :meth:`print_part`: a sum, product or name (:data:`OWN`, almost every
      part of a program) with the method sympy's ``_print`` would find along
      the class's bases, without looking for it; any other part with sympy's
      ``_print``.
    * **Each part printed once.** A program's statements share many parts
      (``sin(Q3)``, ``z12**2``, a product of constants), which sympy prints
      again wherever they occur.  A part's text depends only on the part
      (sympy's ``==`` is structural; parts of different classes are never
      equal, but numbers are: a number is kept with its class, Fortran's
      ``literal_dp(1)`` prints ``1d0`` and ``Float(1.0)`` ``1.0d0``) and
      the printer's settings, with these kept out: the part a statement's
      printing starts from (``_print_level`` 1: sympy prints a Float alone
      with its zeros, without them inside; :meth:`print_part` prints parts
      within), a part holding a number constant (``pi``, ..., which a
      printer may record for the statement's declarations, forgotten after
      each statement) or what ``doprint`` rewrites (``re``,
      ``IndexedBase``).  A strict printer raises on an object it cannot
      print (a printer that is not strict records it, and remembers
      nothing here).
    * **Plain assignments.** ``doprint(expr, assign_to)`` builds an
      ``Assignment``, walks the statement for ``re`` (and for
      ``IndexedBase``: loops), then prints and formats its lines.  For a
      sum, product or name holding none of those nor a number constant
      (each part asked once per program), the same text is ``lhs = rhs``
      with the language's terminator, formatted as ``doprint`` formats it:
      the two sides printed as ``Assignment`` prints them, the left one
      first (Fortran names a symbol when it first prints it), the right one
      at one level less deep, which only a Float's text depends on."""

    #: the classes whose parts :meth:`print_part` prints with the printer's
    #: method for the class (``_print_Add``, ...), as sympy's ``_print``
    #: finds it, directly: their text does not depend on how deep they are
    OWN = (sp.Add, sp.Mul, sp.Symbol)
    #: whether :meth:`doprint` prints a plain statement without walking it
    #: first, watching for the parts that make it not plain
    #: (:meth:`_watched_text`), and whether a function's value is printed so
    #: too (:func:`_plain_call`)
    watches = False
    plain_calls = False

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings)  # type: ignore[call-arg]
        self.start_remembering(bool(settings and settings.get("strict") is True))

    def start_remembering(self, strict: bool) -> None:
        """Nothing remembered yet; ``strict``: whether the printer is."""
        self._texts: dict = {}
        self._special: dict = {}  # part -> whether it holds one of _SPECIAL
        self._precs: dict = {}
        self._remembers = strict
        self._plain = False  # printing a plain statement: nothing special
        #: printing a plain statement not walked first; a special part seen
        self._watching = self._watched = False
        self._own = {
            kind: getattr(self, f"_print_{kind.__name__}") for kind in self.OWN
        }

    def print_part(self, expr: Any) -> str:
        """The text of ``expr``, a part within the statement being printed,
        remembered (see :class:`ProgramPrinter`)."""
        if not isinstance(expr, sp.Basic):
            return self._print(expr)  # type: ignore[attr-defined]
        key = (type(expr), expr) if expr.is_Number else expr
        found = self._texts.get(key)
        if found is not None:
            return found
        method = self._own.get(type(expr))
        if method is None:
            text = self._print(expr)  # type: ignore[attr-defined]
            if self._watching and holds_instance(expr, _SPECIAL, self._special):
                self._watched = True
        else:
            text = method(expr)
        if self._remembers and (
            self._plain or not holds_instance(expr, _SPECIAL, self._special)
        ):
            self._texts[key] = text
        return text

    def remembered_precedence(self, item: Any) -> int:
        """sympy's ``precedence(item)``: a product's or a number's (which
        depend on its sign) formed once per part, any other's kept per
        class (:func:`~..jobs.backends.precedence_of`)."""
        if type(item) is not sp.Mul and not item.is_Number:
            return backends.precedence_of(item)
        found = self._precs.get(item)
        if found is None:
            found = self._precs[item] = backends.precedence_of(item)
        return found

    def parenthesize(self, item: Any, level: int, strict: bool = False) -> str:
        """sympy's ``parenthesize``: ``item``'s text, in parentheses when its
        precedence is below ``level`` (or at it, when not ``strict``)."""
        prec = self.remembered_precedence(item)
        if prec < level or (not strict and prec <= level):
            return f"({self.print_part(item)})"
        return self.print_part(item)

    def doprint(self, expr: Any, assign_to: Any = None) -> str:
        """sympy's ``CodePrinter.doprint``, the same text; a plain statement
        printed here (see :class:`ProgramPrinter`)."""
        if self.watches and self._watchable(expr, assign_to):
            text = self._watched_text(expr, assign_to)
            if text is not None:
                return text
        if not self.is_plain(expr, assign_to):
            return super().doprint(expr, assign_to)  # type: ignore[misc]
        return self.plain_text(expr, assign_to)

    def _watchable(self, expr: Any, assign_to: Any) -> bool:
        """Whether :meth:`_watched_text` prints ``doprint(expr,
        assign_to)``: a sum, product or name, or (``plain_calls``, in a
        strict printer) a function's value, assigned to nothing, a name or
        a symbol."""
        if not (
            type(expr) in self._own
            or (self.plain_calls and self._remembers and _plain_call(expr))
        ):
            return False
        return assign_to is None or isinstance(assign_to, str | sp.Symbol)

    def _watched_text(self, expr: Any, assign_to: Any) -> str | None:
        """``doprint(expr, assign_to)`` printed as a plain statement without
        walking the statement for the parts that make it not plain (as
        :meth:`is_plain` does): a part that :meth:`print_part` prints
        through sympy's ``_print`` is asked whether it holds one (what is
        not printed so is a sum, product or name, none of them, or was
        printed before and remembered, as only parts holding none are; a
        function's value is asked first); None when one does (or the
        printing fails), the parts' texts remembered since forgotten."""
        if type(expr) not in self._own and holds_instance(
            expr, _SPECIAL, self._special
        ):
            return None
        texts = self._texts
        start = len(texts)
        self._watching, self._watched = True, False
        try:
            text = self.plain_text(expr, assign_to)
        except Exception:  # noqa: BLE001 - printed again as the rule prints it
            self._watched = True
        finally:
            self._watching = False
        if not self._watched:
            return text
        for _ in range(len(texts) - start):
            texts.popitem()  # (the last remembered first)
        return None

    def plain_text(self, expr: Any, assign_to: Any) -> str:
        """``doprint(expr, assign_to)`` of a plain statement (see
        :meth:`is_plain`)."""
        self._plain = True
        try:
            if assign_to is None:
                text = self._print(expr)  # type: ignore[attr-defined]
            else:
                lhs = sp.Symbol(assign_to) if isinstance(assign_to, str) else assign_to
                # a name's text is the same at any depth (its own, remembered)
                lhs_code = self.print_part(lhs)
                rhs_code = self._print(expr)  # type: ignore[attr-defined]
                text = self._get_statement(f"{lhs_code} = {rhs_code}")  # type: ignore
        finally:
            self._plain = False
        return "\n".join(self.plain_lines(text))

    def plain_lines(self, text: str) -> list[str]:
        """The lines of a plain statement's ``text``, formatted as sympy's
        ``doprint`` formats them: one line that begins with no blank as it
        is (C and MATLAB indent a line by the blocks opened on the lines
        before it: none here), else by sympy's ``_format_code``."""
        if not text or "\n" in text or text[0] in " \t":
            return self._format_code(text.splitlines())  # type: ignore
        return [text]

    def is_plain(self, expr: Any, assign_to: Any) -> bool:
        """Whether ``doprint(expr, assign_to)`` is printed here: a sum,
        product or name holding none of ``re``, ``IndexedBase`` and number
        constants, or an integer (``out(3) = 0``: its text is the same at
        any depth), assigned to nothing, a name or a symbol."""
        if assign_to is not None and not isinstance(assign_to, str | sp.Symbol):
            return False
        if type(expr) in self._own:
            return not holds_instance(expr, _SPECIAL, self._special)
        return isinstance(expr, sp.Integer)


class Remembering(ProgramPrinter):
    """A mixin for a sympy code printer (before it in the bases): sort keys,
    number tests and precedences remembered; the order of terms and of
    factors formed with them; sums printed as ``StrPrinter._print_Add``."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings)  # type: ignore[call-arg]
        self._keys: dict = {}
        self._numbers: dict = {}
        self._powers: dict = {}  # factor -> its base and exponent in a term
        #: (expression, target) -> its printed statement: a program's
        #: outputs routine assigns again the intermediates its equations have
        self.statements: dict = {}

    def remembered_number(self, item: Any) -> bool:
        """``item.is_number``, each part's answer formed once (a plain
        symbol's is False)."""
        return type(item) is not sp.Symbol and is_number_in(item, self._numbers)

    def _as_ordered_terms(self, expr: Any, order: Any = None) -> list:
        if (order or self.order) is not None or not expr.is_Add:  # type: ignore
            return super()._as_ordered_terms(expr, order)  # type: ignore[misc]
        return _ordered_terms(expr, self._keys, self._numbers, self._powers)

    def remembered_factors(self, factors: list) -> list:
        """``as_ordered_factors()`` of the product of ``factors`` (its
        arguments): sympy's ``args_cnc``, the commutative ones sorted by
        their keys."""
        for i, f in enumerate(factors):
            if not f.is_commutative:
                cpart, ncpart = factors[:i], factors[i:]
                break
        else:
            cpart, ncpart = list(factors), []
        return self._ordered_factors(cpart, ncpart)

    def commuting_order(self, factors: list) -> list:
        """:meth:`remembered_factors` of the factors of a product that
        commutes (so do they all)."""
        return self._ordered_factors(list(factors), [])

    def _ordered_factors(self, cpart: list, ncpart: list) -> list:
        """:meth:`remembered_factors` of the commutative factors ``cpart``
        and the others ``ncpart``."""
        if (
            cpart
            and cpart[0].is_Number
            and cpart[0].is_extended_negative
            and cpart[0] is not sp.S.NegativeOne
        ):
            cpart[:1] = [sp.S.NegativeOne, -cpart[0]]
        # a number's key comes before any other's
        first = 1 if cpart and cpart[0].is_Number else 0
        cpart[first:] = key_order(  # type: ignore
            cpart[first:], self._keys, sums=(self._numbers, self._powers)
        )
        return cpart + ncpart

    def print_ordered_add(self, expr: Any, order: Any = None) -> str:
        """``StrPrinter._print_Add``."""
        terms = self._as_ordered_terms(expr, order=order)
        return self.joined_terms(expr, terms)

    def print_unnamed_add(self, expr: Any) -> str:
        """:meth:`print_ordered_add` of a sum (``order`` and the printer's
        None) that :func:`names_sorted` does not order."""
        terms = _ordered_terms(expr, self._keys, self._numbers, self._powers, False)
        return self.joined_terms(expr, terms)

    def joined_terms(self, expr: Any, terms: list) -> str:
        """The text of the sum ``expr`` of ``terms`` in that order."""
        return backends.join_sum(
            self, terms, self.remembered_precedence(expr), self.remembered_precedence
        )


def _plain_call(expr: Any) -> bool:
    """Whether ``expr`` is a function's value (``sin(Q3)``), not a
    ``Piecewise`` (which an assignment prints apart): its text as a
    statement is ``lhs = rhs`` (sympy's ``_print_Assignment``), ``rhs``
    printed one level less deep than ``doprint`` prints it, which only a
    Float's text depends on, not a function's."""
    return isinstance(expr, sp.Function) and not isinstance(expr, sp.Piecewise)


def holds_instance(expr: Any, kinds: Any, memo: dict) -> bool:
    """``any(isinstance(x, kinds) for x in iterargs(expr))`` (and so
    ``expr.has(kind)`` of one class): each part asked once per ``memo``
    (kept for one ``kinds``), where ``iterargs`` walks a part again
    wherever it occurs."""
    found = memo.get(expr)
    if found is not None:
        return found
    return _holds(expr, kinds, memo, not _NAME_HELD.get(kinds, True))


def _holds(expr: Any, kinds: Any, memo: dict, skip_names: bool) -> bool:
    """:func:`holds_instance` of a part not in ``memo`` (``skip_names``:
    a name is not one of ``kinds``)."""
    found = isinstance(expr, kinds)
    if not found:
        for a in expr.args:
            if skip_names and type(a) is _NAME:
                continue  # a name (most arguments), not one of kinds
            if isinstance(a, sp.Atom):
                held = isinstance(a, kinds)  # (an atom's answer is not kept)
            else:
                held = memo.get(a)
                if held is None:
                    held = _holds(a, kinds, memo, skip_names)
            if held:
                found = True
                break
    memo[expr] = found
    return found


_NAME = sp.Symbol
#: whether a name is one of the kinds :func:`holds_instance` is asked of
#: (the printers ask of ``_SPECIAL`` alone)
_NAME_HELD = {_SPECIAL: issubclass(sp.Symbol, _SPECIAL)}


def _complex(x: Any, memo: dict) -> complex:
    """``complex(x)``, each number's formed once per ``memo`` (sympy goes
    through ``evalf`` and ``as_real_imag`` each time)."""
    key = ("complex", x)
    found = memo.get(key)
    if found is None:
        found = memo[key] = complex(x)
    return found


def _ordered_terms(
    expr: Any, keys: dict, numbers: dict, powers: dict, named: bool = True
) -> list:
    """``expr.as_ordered_terms()`` of a sum (sympy's lexicographic order of
    monomials in the generators sorted by ``default_sort_key``), the same
    list, with the sort keys, number tests and factors' powers remembered
    in ``keys``, ``numbers`` and ``powers`` (:func:`_ordered_by_names`
    unless ``named`` is False: the caller found it gives None; then
    :func:`_ordered_by_monomials`; else sympy's ``as_terms``)."""

    if named:
        by_names = _ordered_by_names(expr.args)
        if by_names is not None:
            return by_names

    add_args = sorted(expr.args, key=_not_numeric)
    if (
        len(add_args) == 2
        and isinstance(add_args[0], _NUMERIC)
        and isinstance(add_args[1], sp.Mul)
    ):
        mul_args = sorted(sp.Mul.make_args(add_args[1]), key=_not_numeric)
        if (
            len(mul_args) == 2
            and isinstance(mul_args[0], sp.Number)
            and add_args[0].is_positive
            and mul_args[0].is_negative
        ):
            return add_args
    ordered = _ordered_by_monomials(add_args, keys, numbers, powers)
    if ordered is not None:
        return ordered
    key, reverse = expr._parse_order(None)
    result, _ = as_terms(
        expr,
        lambda g: sort_key_in(g, keys),
        coefficient=lambda c: _complex(c, numbers),
        is_number=lambda f: is_number_in(f, numbers),
        to_complex=lambda f: _complex(f, numbers),
    )
    if not any(term.is_Order for term, _ in result):
        return [term for term, _ in sorted(result, key=key, reverse=reverse)]
    plain_terms = [t for t in result if not t[0].is_Order]
    orders = [t for t in result if t[0].is_Order]
    ordered = sorted(plain_terms, key=key, reverse=True)
    ordered += sorted(orders, key=key, reverse=True)
    return [term for term, _ in ordered]


def _ordered_by_monomials(
    terms: list, keys: dict, numbers: dict, powers: dict
) -> list | None:
    """``terms`` (a sum's) in ``as_ordered_terms``'s order, found from each
    term's factors without sympy's ``as_terms``, or None where this does
    not decide it: a term holding a number factor (sympy multiplies it into
    the coefficient), a factor that does not commute, ``O(...)``, one base
    twice in a term, or two terms of one monomial (sympy then compares
    their coefficients).

    sympy's key of a term is its monomial: its exponents in the generators
    (every term's bases, sorted by ``default_sort_key``), negated, the
    coefficient's only after it.  Each factor's base and exponent (sympy's
    ``decompose_power``) is found once per ``powers``, the sort keys once
    per ``keys``, the number tests once per ``numbers``."""
    found: list = []
    gens = set()
    for term in terms:
        if type(term) is sp.Mul:
            factors = term.args
            if factors[0].is_Number:
                factors = factors[1:]
        elif term.is_Number:
            factors = ()
        elif term.is_Order:
            return None
        else:
            factors = (term,)
        monomial = []
        for f in factors:
            power = powers.get(f)
            if power is None:
                power = powers[f] = _base_and_exponent(f, numbers)
            if not power:
                return None
            monomial.append(power)
            gens.add(power[0])
        found.append(monomial)
    ordered = key_order(gens, keys, True, (numbers, powers))
    if ordered is None:
        return None  # two keys alike: sympy's order of them is the set's
    rank = {g: i for i, g in enumerate(ordered)}
    size = len(rank)
    keyed = []
    for term, monomial in zip(terms, found, strict=True):
        exponents = [0] * size
        for base, exp in monomial:
            i = rank[base]
            if exponents[i]:
                return None  # one base twice (sympy keeps the last)
            exponents[i] = -exp
        keyed.append((tuple(exponents), term))
    keyed.sort(key=_first)
    for i in range(1, len(keyed)):
        if keyed[i][0] == keyed[i - 1][0]:
            return None
    return [term for _, term in keyed]


def key_order(
    items: Any, keys: dict, distinct: bool = False, sums: tuple | None = None
) -> list | None:
    """``sorted(items, key=default_sort_key)`` (equal keys in their order
    in ``items``), each key formed once per ``keys``; with ``distinct``,
    None when two keys are equal.

    A plain name's key is its class's key (``Symbol.class_key()``), then
    its name: names are sorted by name alone.  When every other item's key
    begins with a class key above the names' (a sum, a function, their
    powers: :func:`_head`), the names come first, then the others by their
    keys, and a lone other item's key is not formed.  ``sums``: the number
    tests and factors' powers remembered (:func:`_ordered_terms`), with
    which a sum's key is formed (:func:`_key`)."""
    names = []
    others = []
    for x in items:
        if type(x) is _NAME:
            names.append(x)
        else:
            others.append(x)
    names.sort(key=_BY_NAME)
    if distinct:
        for i in range(1, len(names)):
            if names[i].name == names[i - 1].name:
                return None
    if not others:
        return names
    if len(others) == 1:
        if not names or _head(others[0], keys) > _NAME_CLASS_KEY:
            return names + others
        return _by_keys(list(items), keys, distinct, sums)
    ordered = _by_keys(others, keys, distinct, sums)
    if not names or ordered is None:
        return ordered
    if keys[ordered[0]][0] > _NAME_CLASS_KEY:
        return names + ordered
    return _by_keys(list(items), keys, distinct, sums)


def _by_keys(
    items: list, keys: dict, distinct: bool, sums: tuple | None
) -> list | None:
    """:func:`key_order` of ``items`` by their keys."""
    # (a key found is read here: most were keyed before)
    marked = [(keys.get(x) or _key(x, keys, sums), i) for i, x in enumerate(items)]
    marked.sort(key=_first)
    if distinct:
        for i in range(1, len(marked)):
            if marked[i][0] == marked[i - 1][0]:
                return None
    return [items[i] for _, i in marked]


def _key(item: Any, keys: dict, sums: tuple | None) -> tuple:
    """``sort_key_in(item, keys)``; with ``sums`` (the number tests and
    factors' powers remembered), the key of a sum or a power of a sum
    formed here, sympy's ``Expr.sort_key`` of it (the sum's class key, the
    keys of its terms in ``as_ordered_terms``'s order, the exponent's key,
    the coefficient 1) with the terms ordered by :func:`_ordered_terms`
    (sympy's ``as_ordered_terms`` walks the sum again each time)."""
    if sums is not None:
        kind = type(item)
        if kind is sp.Add:
            base, exp = item, _ONE
        elif kind is sp.Pow and type(item.base) is sp.Add:
            base, exp = item.args
        else:
            return sort_key_in(item, keys)
        terms = _ordered_terms(base, keys, sums[0], sums[1])
        args = tuple([sort_key_in(t, keys) for t in terms])
        key = (_ADD_CLASS_KEY, (len(args), args), sort_key_in(exp, keys), _ONE)
        keys[item] = key
        return key
    return sort_key_in(item, keys)


def _head(item: Any, keys: dict) -> tuple:
    """``default_sort_key(item)[0]`` (the class key sympy's key begins
    with): a sum's or a function's class key, read off its class (its
    key, ``Expr.sort_key``, begins with it: the coefficient 1, not a
    power), else its key's, formed once per ``keys``."""
    found = keys.get(item)
    if found is not None:
        return found[0]
    cls = type(item)
    if cls.sort_key is _EXPR_SORT_KEY and (
        cls is sp.Add or isinstance(item, _FUNCTION)
    ):
        return cls.class_key()
    if cls is sp.Pow and type(item.base) is sp.Add:
        return _ADD_CLASS_KEY  # (a power's key is its base's, then ...)
    return sort_key_in(item, keys)[0]


def _ordered_by_names(terms: tuple) -> list | None:
    """``terms`` (a sum's) in ``as_ordered_terms``'s order when each is a
    name or a product of names (after a number), what most sums of a
    program are, else None (:func:`_ordered_by_monomials` decides).

    Every exponent is 1 and the generators are names, sorted by name: of
    two terms, the one holding the first name (in that order) that the
    other lacks comes first (its monomial's exponent there is the larger).
    That is the order of the terms' sorted names, a term that runs out
    coming after one that goes on: each name ``n`` is keyed ``(0, n)``, the
    end ``(1, "")``.  None where :func:`_ordered_by_monomials` would give
    None (two names alike, two terms of one monomial) or sympy sorts
    otherwise (a number term, a power, a function, a name twice in a
    term, a factor that does not commute)."""
    found = names_sorted(terms)
    return None if found is None else [term for term, _names in found]


def names_sorted(terms: tuple) -> list[tuple[Any, list]] | None:
    """:func:`_ordered_by_names`'s order of ``terms``, each with its names
    sorted by name (how a product of names is printed); None where that
    gives None."""
    seen: dict[str, Any] = {}
    keyed = []
    for term in terms:
        if type(term) is sp.Symbol:
            factors: tuple = (term,)
        elif type(term) is sp.Mul:
            factors = term.args
            if factors[0].is_Number:
                factors = factors[1:]
        else:
            return None
        for f in factors:
            if type(f) is not sp.Symbol or not f.is_commutative:
                return None
            known = seen.setdefault(f.name, f)
            if known is not f and known != f:
                return None  # two names alike
        if not factors:
            return None
        names = sorted(factors, key=_BY_NAME)
        key = [(0, f.name) for f in names]
        for i in range(1, len(key)):
            if key[i] == key[i - 1]:
                return None  # a name twice
        key.append((1, ""))
        keyed.append((tuple(key), term, names))
    keyed.sort(key=_first)
    for i in range(1, len(keyed)):
        if keyed[i][0] == keyed[i - 1][0]:
            return None
    return [(term, names) for _, term, names in keyed]


def _base_and_exponent(factor: Any, numbers: dict) -> tuple | bool:
    """sympy's ``decompose_power(factor)`` of a factor of a term that
    ``as_terms`` puts in the monomial, else False (a number, or a factor
    that does not commute)."""
    if type(factor) is sp.Symbol:
        return (factor, 1) if factor.is_commutative else False
    if is_number_in(factor, numbers) or not factor.is_commutative:
        return False
    return decompose_power(factor)


_BY_NAME = operator.attrgetter("name")
_NAME_CLASS_KEY = sp.Symbol.class_key()
_EXPR_SORT_KEY = sp.Expr.sort_key
_FUNCTION = sp.Function
_ADD_CLASS_KEY = sp.Add.class_key()
_ONE = sp.S.One
#: the terms ``_ordered_terms`` puts first (as ``Expr.as_ordered_terms`` does)
_NUMERIC = (sp.Number, sp.NumberSymbol)


def _not_numeric(x: Any) -> bool:
    return not isinstance(x, _NUMERIC)


def _first(pair: tuple) -> Any:
    return pair[0]


def _name(symbol: Any) -> str:
    return symbol.name
