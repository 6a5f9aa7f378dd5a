"""What the MATLAB and Fortran printers share: sympy's printing, the same
text, with what it asks again and again remembered.

sympy's MATLAB and Fortran printers order a sum's terms by
``as_ordered_terms`` (the monomials' exponents in generators sorted by
``default_sort_key``) and a product's factors by ``as_ordered_factors``,
and ask ``is_number`` and ``precedence`` at every node they visit: each walks
the subtree again, and sympy's cache of sort keys (1,000 entries) is soon
overrun by a large program, so the keys were formed again down to the
leaves.  :class:`Remembering` forms each once per printer (one program).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import sympy as sp
from sympy.tensor.indexed import IndexedBase

from ..intermediates.autoz import as_terms
from ..jobs import backends
from ..names.printing import is_number_in, sort_key_in

__all__ = ["PrintedOnce", "Remembering", "holds_instance", "printed_once"]

#: what doprint's statement is walked for (see Remembering)
_WALKED_FOR = (sp.re, IndexedBase)


class PrintedOnce:
    """A mixin for a strict sympy code printer (before it in the bases):
    the parts that its methods decorated with :func:`printed_once` (or
    going through :meth:`print_once`) print -- sums, products, powers,
    function calls -- printed once per printer (one program), their text
    remembered.

    A program's statements share many parts (``sin(Q3)``, ``z12**2``, a
    product of constants), which sympy prints again wherever they occur.
    A part's text depends only on the part (sympy's ``==`` is structural;
    parts of different classes are never equal) and the printer's
    settings, with these kept out: the part a statement's printing starts
    from (``_print_level`` 1: sympy prints a Float alone with its zeros,
    without them inside), a part holding a number constant (``pi``, ...,
    which a printer may record for the statement's declarations, forgotten
    after each statement) and calls with more arguments.  A strict printer
    raises on an object it cannot print (a printer that is not strict
    records it, and remembers nothing here)."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings)  # type: ignore[call-arg]
        self.start_remembering(bool(settings and settings.get("strict") is True))

    def start_remembering(self, strict: bool) -> None:
        """Nothing remembered yet; ``strict``: whether the printer is."""
        self._printed: dict = {}
        self._constants: dict = {}  # part -> whether it holds a NumberSymbol
        self._remembers = strict

    def remembered_text(self, expr: Any) -> str | None:
        """The text of ``expr`` printed before as a part, or None."""
        if self._print_level <= 1:  # type: ignore[attr-defined]
            return None
        return self._printed.get(expr)

    def remember_text(self, expr: Any, text: str) -> None:
        """Keep ``text`` as ``expr``'s, where it depends on ``expr`` alone."""
        if (
            self._remembers
            and self._print_level > 1  # type: ignore[attr-defined]
            and not holds_instance(expr, sp.NumberSymbol, self._constants)
        ):
            self._printed[expr] = text

    def print_once(
        self, method: Callable[..., str], expr: Any, *args: Any, **kwargs: Any
    ) -> str:
        """``method(expr, *args, **kwargs)`` (a bound printing method of this
        printer, ``super()``'s), remembered (see :class:`PrintedOnce`)."""
        if args or kwargs:
            return method(expr, *args, **kwargs)
        found = self.remembered_text(expr)
        if found is None:
            found = method(expr)
            self.remember_text(expr, found)
        return found

    # the sympy printer's powers and function calls, remembered (a printer
    # with its own, MATLAB's powers, decorates it with printed_once)
    def _print_Pow(self, expr: Any, *args: Any, **kwargs: Any) -> str:  # noqa: N802
        return self.print_once(super()._print_Pow, expr, *args, **kwargs)  # type: ignore[misc]

    def _print_Function(
        self, expr: Any, *args: Any, **kwargs: Any
    ) -> str:  # noqa: N802
        return self.print_once(super()._print_Function, expr, *args, **kwargs)  # type: ignore[misc]


def printed_once(method: Callable[..., str]) -> Callable[..., str]:
    """A printing method of a :class:`PrintedOnce` printer whose text is
    remembered (see there)."""

    def printed(self: Any, expr: Any, *args: Any, **kwargs: Any) -> str:
        return self.print_once(method.__get__(self), expr, *args, **kwargs)

    printed.__name__ = getattr(method, "__name__", "printed")
    printed.__doc__ = getattr(method, "__doc__", None)
    return printed


class Remembering(PrintedOnce):
    """A mixin for a sympy code printer (before it in the bases): sort keys,
    number tests and precedences remembered; the order of terms and of
    factors formed with them; sums printed as ``StrPrinter._print_Add``."""

    def __init__(self, settings: dict | None = None) -> None:
        super().__init__(settings)  # type: ignore[call-arg]
        self._keys: dict = {}
        self._numbers: dict = {}
        self._precs: dict = {}
        self._plain_statement: Any = None
        #: part -> whether it holds a _WALKED_FOR object
        self._walked: dict = {}
        #: (expression, target) -> its printed statement: a program's
        #: outputs routine assigns again the intermediates its equations have
        self.statements: dict = {}

    def remembered_precedence(self, item: Any) -> int:
        found = self._precs.get(item)
        if found is None:
            found = self._precs[item] = backends.precedence_of(item)
        return found

    def remembered_number(self, item: Any) -> bool:
        return is_number_in(item, self._numbers)

    def parenthesize(self, item: Any, level: int, strict: bool = False) -> str:
        prec = self.remembered_precedence(item)
        if prec < level or (not strict and prec <= level):
            return f"({self._print(item)})"  # type: ignore[attr-defined]
        return self._print(item)  # type: ignore[attr-defined]

    def _handle_UnevaluatedExpr(self, expr: Any) -> Any:  # noqa: N802 - sympy's
        # doprint's statement (an Assignment) walked once for both ``re``
        # (sympy's UnevaluatedExpr handling) and ``IndexedBase``
        # (_print_Assignment's loops), instead of once for each
        if isinstance(expr, sp.Basic) and not self._holds_walked_for(expr):
            self._plain_statement = expr
            return expr
        if backends.without_re(expr):
            return expr
        return super()._handle_UnevaluatedExpr(expr)  # type: ignore[misc]

    def _holds_walked_for(self, expr: Any) -> bool:
        return holds_instance(expr, _WALKED_FOR, self._walked)

    def _print_Assignment(self, expr: Any) -> str:  # noqa: N802 - sympy's
        # sympy's last case (lhs = rhs) when the statement has no
        # IndexedBase (walked above), the left side is a symbol and the
        # right side is not a Piecewise
        if (
            expr is self._plain_statement
            and isinstance(expr.lhs, sp.Symbol)
            and not isinstance(expr.rhs, sp.Piecewise)
        ):
            lhs_code = self._print(expr.lhs)  # type: ignore[attr-defined]
            rhs_code = self._print(expr.rhs)  # type: ignore[attr-defined]
            return self._get_statement(f"{lhs_code} = {rhs_code}")  # type: ignore
        return super()._print_Assignment(expr)  # type: ignore[misc]

    def _as_ordered_terms(self, expr: Any, order: Any = None) -> list:
        if (order or self.order) is not None or not expr.is_Add:  # type: ignore
            return super()._as_ordered_terms(expr, order)  # type: ignore[misc]
        return _ordered_terms(expr, self._keys, self._numbers)

    def remembered_factors(self, expr: Any) -> list:
        """``expr.as_ordered_factors()``."""
        if not isinstance(expr, sp.Mul):
            return expr.as_ordered_factors()
        cpart, ncpart = expr.args_cnc()
        keys = self._keys
        cpart.sort(key=lambda x: sort_key_in(x, keys))
        return cpart + ncpart

    def print_ordered_add(self, expr: Any, order: Any = None) -> str:
        """``StrPrinter._print_Add``."""
        terms = self._as_ordered_terms(expr, order=order)
        return backends.join_sum(
            self, terms, self.remembered_precedence(expr), self.remembered_precedence
        )


def holds_instance(expr: Any, kinds: Any, memo: dict) -> bool:
    """``any(isinstance(x, kinds) for x in iterargs(expr))`` (and so
    ``expr.has(kind)`` of one class): each part asked once per ``memo``
    (kept for one ``kinds``), where ``iterargs`` walks a part again
    wherever it occurs."""
    found = memo.get(expr)
    if found is not None:
        return found
    found = isinstance(expr, kinds)
    if not found:
        for a in expr.args:
            held = memo.get(a)
            if held is None:
                held = holds_instance(a, kinds, memo)
            if held:
                found = True
                break
    memo[expr] = found
    return found


def _complex(x: Any, memo: dict) -> complex:
    """``complex(x)``, each number's formed once per ``memo`` (sympy goes
    through ``evalf`` and ``as_real_imag`` each time)."""
    key = ("complex", x)
    found = memo.get(key)
    if found is None:
        found = memo[key] = complex(x)
    return found


def _ordered_terms(expr: Any, keys: dict, numbers: dict) -> list:
    """``expr.as_ordered_terms()`` of a sum (sympy's lexicographic order of
    monomials in the generators sorted by ``default_sort_key``), the same
    list, with the sort keys and number tests remembered in ``keys`` and
    ``numbers``."""

    def plain(x: Any) -> bool:
        return not isinstance(x, sp.Number | sp.NumberSymbol)

    add_args = sorted(expr.args, key=plain)
    if (
        len(add_args) == 2
        and isinstance(add_args[0], sp.Number | sp.NumberSymbol)
        and isinstance(add_args[1], sp.Mul)
    ):
        mul_args = sorted(sp.Mul.make_args(add_args[1]), key=plain)
        if (
            len(mul_args) == 2
            and isinstance(mul_args[0], sp.Number)
            and add_args[0].is_positive
            and mul_args[0].is_negative
        ):
            return add_args
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
