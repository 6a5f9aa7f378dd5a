"""Print sympy values in Autolev's syntax, as Autolev prints its responses.

>>> import sympy as sp
>>> from sympy.physics.mechanics import dynamicsymbols
>>> X, Y = dynamicsymbols("X Y")
>>> autolev_str(-sp.pi + (X + 2*Y)**2 + 3*X.diff()**2)
"-3.141593 + (X+2*Y)^2 + 3*X'^2"
>>> autolev_str(sp.Matrix([[1, sp.pi], [X.diff(), sp.Rational(1, 12)]]))
"[1, 3.141593; X', 0.08333333]"

Conventions (see ``docs/semantics.md``):

* names print in upper case, variables ``X(t)`` as ``X``, derivatives with
  primes (``X''``), ``t`` as ``T`` and the imaginary unit as ``i``;
* integers print exactly; every other number (rationals, floats, ``pi``,
  ``sqrt(2)``, complex numbers) prints with ``digits`` significant digits and
  numeric subexpressions collapse to one number (``-pi + C*X`` prints
  ``-3.141593 + C*X``);
* sums print with spaces around ``+``/``-`` at the top level only, as Autolev
  does (``A^2 + B*C`` but ``B*(A+D)``);
* powers use ``^``; ``sqrt(y)`` prints ``y^0.5``; negative powers go into a
  denominator (``D/(A*D-B*C)``).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols

from ..intermediates.autoz import Intermediate
from ..model.kinematics import VectorMatrix
from ..vocabulary import printed_name

__all__ = [
    "autolev_str",
    "element_labels",
    "format_response",
    "format_number",
    "is_number_in",
    "Printing",
    "sort_key_in",
]

_T = dynamicsymbols._t

# Precedence levels: a child printed with a lower level than its context needs
# parentheses.
_ADD, _MUL, _NEG, _POW, _ATOM = 10, 20, 15, 30, 40


def format_number(value: Any, digits: int = 7) -> str:
    """Print a real number like Autolev: ``digits`` significant digits.

    Integers print exactly; trailing zeros are dropped; very small or large
    magnitudes use ``1.0E-07`` style.

    >>> format_number(sp.pi), format_number(sp.Rational(1, 720)), format_number(1e-7)
    ('3.141593', '0.001388889', '1.0E-07')
    """
    value = sp.sympify(value)
    if isinstance(value, sp.Integer):
        return str(int(value))
    special = _special_number(value)
    if special is not None:
        return special
    mpf = mpmath.mpf(value.evalf(digits + 10)._mpf_)
    if mpf == 0:
        return "0"
    x = float(mpf)
    if math.isfinite(x) and x != 0:
        text = format(x, f".{digits}g")
    else:  # beyond double range
        text = mpmath.nstr(mpf, digits, min_fixed=-4, max_fixed=digits)
    return _exponent_style(text)


def _special_number(value: Any) -> str | None:
    """``INF``, ``-INF`` or ``NAN`` (as C's printf, upper case, which is how
    Autolev's numerical output spells them) for sympy's ``oo``, ``-oo``,
    ``zoo`` (complex infinity, from ``1/0``) and ``nan`` (``0/0``)."""
    if value is sp.nan:
        return "NAN"
    if value is sp.oo or value is sp.zoo:
        return "INF"
    if value is sp.S.NegativeInfinity:
        return "-INF"
    if isinstance(value, sp.Basic) and value.has(sp.nan, sp.oo, sp.zoo, -sp.oo):
        x = complex(value.evalf()) if value.is_number else None
        if x is not None:
            if math.isnan(x.real) or math.isnan(x.imag):
                return "NAN"
            return "-INF" if x.real < 0 and not x.imag else "INF"
    return None


def _exponent_style(text: str) -> str:
    """``1e-07`` -> ``1.0E-07``; ``1.234568e+07`` -> ``1.234568E+07``."""
    if "e" not in text:
        return text
    mantissa, exp = text.split("e")
    if "." not in mantissa:
        mantissa += ".0"
    sign = "-" if exp.startswith("-") else "+"
    return f"{mantissa}E{sign}{exp.lstrip('+-').zfill(2)}"


class _AutolevPrinter:
    """Recursive printer; each method returns ``(text, precedence)``."""

    def __init__(self, digits: int, memos: _Memos | None = None) -> None:
        if not 1 <= digits <= 17:
            raise ValueError(f"digits must be between 1 and 17, not {digits}")
        self.digits = digits
        # what is already known of each subexpression: shared by every value
        # a :class:`Printing` prints, else this printer's own
        if memos is None:
            memos = _Memos()
        self.keys = memos.keys
        self.numbers = memos.numbers
        #: printed forms ``(text, precedence)``, nested and at the top level
        #: (sums spaced)
        self.shown = memos.shown.setdefault((digits, False), {})
        self.shown_top = memos.shown.setdefault((digits, True), {})
        self.coefficients = memos.coefficients.setdefault(digits, {})
        self.negative = memos.negative
        self.negations = memos.negations

    # ------------------------------------------------------------ dispatch

    def text(self, expr: Any, top: bool = False) -> str:
        return self.show(expr, top)[0]

    def paren(self, expr: Any, level: int) -> str:
        """Print ``expr`` (nested), parenthesized if it binds looser than level."""
        text, prec = self.show(expr, False)
        return f"({text})" if prec < level else text

    def show(self, expr: Any, top: bool) -> tuple[str, int]:
        """``(text, precedence)`` of ``expr``, each subexpression's formed
        once (a dict finds the same object by identity before comparing)."""
        if isinstance(expr, sp.MatrixBase):
            return self.matrix(expr), _ATOM
        if not isinstance(expr, sp.Basic):
            return self.form(expr, top)
        memo = self.shown_top if top else self.shown
        found = memo.get(expr)
        if found is None:
            found = memo[expr] = self.form(expr, top)
        return found

    def form(self, expr: Any, top: bool) -> tuple[str, int]:
        """``show`` without the memo."""
        if not isinstance(expr, sp.Basic):
            try:
                expr = sp.sympify(expr)
            except (sp.SympifyError, TypeError):
                return str(expr), _ATOM
        if (
            isinstance(expr, sp.Expr)
            and self.is_number(expr)
            and not expr.has(AppliedUndef)
        ):
            return self.number(expr, top)
        if isinstance(expr, sp.Symbol):
            return ("T" if expr == _T else expr.name.upper()), _ATOM
        if isinstance(expr, sp.Add):
            return self.add(expr, top)
        if isinstance(expr, sp.Mul):
            return self.mul(expr)
        if isinstance(expr, sp.Pow):
            return self.power(expr)
        if isinstance(expr, sp.Derivative):
            return self.derivative(expr), _ATOM
        if isinstance(expr, Intermediate):
            return expr.book.label(expr).upper(), _ATOM
        if isinstance(expr, AppliedUndef):
            name = expr.func.__name__.upper()
            if expr.args == (_T,):
                return name, _ATOM
            return f"{name}({self.args(expr.args)})", _ATOM
        if isinstance(expr, sp.Function | sp.Max | sp.Min):
            return self.function(expr), _ATOM
        if isinstance(expr, sp.Equality):
            return f"{self.text(expr.lhs, top)} = {self.text(expr.rhs, top)}", 0
        return str(expr), _ATOM

    def args(self, args: Any) -> str:
        return ", ".join(self.text(a) for a in args)

    # ------------------------------------------------------------- numbers

    def number(self, expr: sp.Expr, top: bool) -> tuple[str, int]:
        if isinstance(expr, sp.Integer):
            return str(int(expr)), (_NEG if expr < 0 else _ATOM)
        special = _special_number(expr)
        if special is not None:
            return special, (_NEG if special.startswith("-") else _ATOM)
        value = expr.evalf(self.digits + 10)
        re, im = value.as_real_imag()
        if not (re.is_number and im.is_number):
            return str(expr), _ATOM
        re = self.round_part(re)
        im = self.round_part(im)
        if im == 0:
            text = format_number(re, self.digits)
            return text, (_NEG if text.startswith("-") else _ATOM)
        imag = self.imaginary(im)
        if re == 0:
            return imag, (_NEG if imag.startswith("-") else _MUL)
        sep = " " if top else ""
        real = format_number(re, self.digits)
        if imag.startswith("-"):
            return f"{real}{sep}-{sep}{imag[1:]}", _ADD
        return f"{real}{sep}+{sep}{imag}", _ADD

    def round_part(self, x: sp.Expr) -> sp.Expr:
        """Exact integers stay exact (``2.0`` from evalf prints ``2``)."""
        if x == 0:
            return sp.Integer(0)
        return x

    def imaginary(self, im: sp.Expr) -> str:
        mag = format_number(abs(im), self.digits)
        body = "i" if mag == "1" else f"{mag}*i"
        return "-" + body if im < 0 else body

    # ---------------------------------------------------------------- sums

    def add(self, expr: sp.Add, top: bool) -> tuple[str, int]:
        numeric, others = [], []
        for a in expr.args:
            if self.is_constant(a):
                numeric.append(a)
            else:
                others.append(a)
        terms = sorted(others, key=self.term_key) if len(others) > 1 else others
        if numeric:
            const = sp.Add(*numeric)
            if const != 0:
                terms.insert(0, const)
        sep = " " if top else ""
        memo = self.shown_top if top else self.shown
        out = ""
        for k, term in enumerate(terms):
            # :meth:`show`, its memo read here (a term is never a matrix)
            found = memo.get(term)
            text, prec = found if found is not None else self.show(term, top)
            if prec < _NEG and k:
                text = f"({text})"
            if k == 0:
                out = text
            elif text.startswith("-"):
                out += f"{sep}-{sep}{text[1:]}"
            else:
                out += f"{sep}+{sep}{text}"
        return out or "0", _ADD

    # ------------------------------------------------------------ products

    def mul(self, expr: sp.Mul) -> tuple[str, int]:
        numeric, num, den = [], [], []
        sums = False
        for factor in expr.args:
            if self.is_constant(factor):
                numeric.append(factor)
                continue
            base, exp = factor.as_base_exp()
            if exp.is_number and exp.is_extended_negative and not factor.is_Function:
                den.append(sp.Pow(base, -exp))
                sums = True  # (flip_signs looks at each)
            else:
                num.append(factor)
                if isinstance(factor, sp.Add):
                    sums = True
        coeff = numeric[0] if len(numeric) == 1 else sp.Mul(*numeric)
        if sums:  # only a sum can have its sign flipped
            num, flips = self.flip_signs(num)
            den, flips_den = self.flip_signs(den)
            if (flips + flips_den) % 2:
                coeff = -coeff
        if len(num) > 1:
            num = self.sorted_factors(num)
        if len(den) > 1:
            den = self.sorted_factors(den)
        sign, coeff_text = self.coefficient(coeff)
        shown = self.shown
        parts = [coeff_text] if coeff_text else []
        for f in num:
            # :meth:`paren` at ``_MUL``, the memo read here (a factor is
            # never a matrix)
            found = shown.get(f)
            text, prec = found if found is not None else self.show(f, False)
            parts.append(f"({text})" if prec < _MUL else text)
        text = "*".join(parts) if parts else "1"
        if den:
            dens = [self.paren(f, _POW if len(den) == 1 else _MUL) for f in den]
            if len(den) == 1:
                text += "/" + dens[0]
            else:
                text += "/(" + "*".join(dens) + ")"
        return sign + text, (_NEG if sign else _MUL)

    def flip_signs(self, factors: list[sp.Expr]) -> tuple[list[sp.Expr], int]:
        """Negate sums that would print with a leading minus: ``-(B-D)/A``."""
        out, flips = [], 0
        for factor in factors:
            if isinstance(factor, sp.Add) and self.leading_negative(factor):
                factor = self.negated(factor)
                flips += 1
            out.append(factor)
        return out, flips

    def coefficient(self, coeff: sp.Expr) -> tuple[str, str]:
        """Split a numeric coefficient into its sign and magnitude text."""
        if coeff is _ONE or coeff == 1:
            return "", ""
        if coeff is _MINUS_ONE or coeff == -1:
            return "-", ""
        found = self.coefficients.get(coeff)
        if found is None:
            found = self.coefficients[coeff] = self.split_coefficient(coeff)
        return found

    def split_coefficient(self, coeff: sp.Expr) -> tuple[str, str]:
        """:meth:`coefficient` of a number other than 1 and -1."""
        value = coeff.evalf(self.digits + 10)
        re, im = value.as_real_imag()
        if im == 0 and re.is_number:
            text = format_number(
                abs(coeff) if coeff.is_Integer else abs(re), self.digits
            )
            return ("-" if re < 0 else ""), text
        if re == 0:
            imag = self.imaginary(im)
            return ("-", imag[1:]) if imag.startswith("-") else ("", imag)
        text, _ = self.number(coeff, False)
        return "", f"({text})"

    # -------------------------------------------------------------- powers

    def power(self, expr: sp.Pow) -> tuple[str, int]:
        base, exp = expr.as_base_exp()
        if exp.is_number and exp.is_extended_negative:
            return self.mul(sp.Mul(1, expr, evaluate=False))
        base_text, base_prec = self.show(base, False)
        if base_prec <= _POW or base_text.startswith("-"):
            base_text = f"({base_text})"
        exp_text, exp_prec = self.show(exp, False)
        if exp_prec < _ATOM and not exp_text.startswith("-"):
            exp_text = f"({exp_text})"
        elif exp_text.startswith("-") and not exp.is_number:
            exp_text = f"({exp_text})"
        return f"{base_text}^{exp_text}", _POW

    # -------------------------------------------------------- derivatives

    def derivative(self, expr: sp.Derivative) -> str:
        inner = expr.expr
        counts = expr.variable_count
        if isinstance(inner, AppliedUndef) and inner.args == (_T,):
            if all(v == _T for v, _ in counts):
                return self.text(inner) + "'" * sum(int(n) for _, n in counts)
        text = self.text(inner)
        for var, n in counts:
            for _ in range(int(n)):
                if var == _T:
                    text = f"DT({text})"
                else:
                    text = f"D({text}, {self.text(var)})"
        return text

    # ----------------------------------------------------------- functions

    def function(self, expr: sp.Function) -> str:
        name = type(expr).__name__
        label = printed_name(expr)
        args = expr.args
        if name in ("Max", "Min") and len(args) > 2:
            head = type(expr)(*args[1:])
            return f"{label}({self.text(args[0])}, {self.function(head)})"
        return f"{label}({self.args(args)})"

    # -------------------------------------------------------- what is known

    def is_number(self, expr: Any) -> bool:
        """``expr.is_number``, each subexpression's answer formed once."""
        return _number_in(expr, self.numbers)

    def is_constant(self, expr: Any) -> bool:
        """Whether ``expr`` is a number and holds no function of time: a
        sum's or a product's constant part."""
        return _number_in(expr, self.numbers) and not expr.has(AppliedUndef)

    def leading_negative(self, expr: sp.Add) -> bool:
        """Whether the sum prints with a leading minus (first term negative)."""
        found = self.negative.get(expr)
        if found is None:
            found = self.negative[expr] = self.first_negative(expr)
        return found

    def negated(self, expr: sp.Add) -> sp.Add:
        """The sum of the terms' negatives, formed once per sum."""
        found = self.negations.get(expr)
        if found is None:
            found = self.negations[expr] = sp.Add(*[-a for a in expr.args])
        return found

    def first_negative(self, expr: sp.Add) -> bool:
        numeric = [a for a in expr.args if self.is_number(a)]
        const = sp.Add(*numeric)
        if const != 0:
            first = const
        else:
            first = min(
                (a for a in expr.args if not self.is_number(a)), key=self.term_key
            )
        coeff = first.as_coeff_Mul()[0] if not self.is_number(first) else first
        re = (
            coeff.evalf(5).as_real_imag()[0] if self.is_number(coeff) else sp.Integer(1)
        )
        return bool(re.is_negative)

    def sorted_factors(self, factors: list[sp.Expr]) -> list[sp.Expr]:
        """``factors`` ordered as a product prints them: names and functions
        first, sums (and powers of sums) last, each group by sort key; ties
        kept in their order by the factor's position."""
        keys = self.keys
        decorated = []
        for k, factor in enumerate(factors):
            if type(factor).as_base_exp is _EXPR_AS_BASE_EXP:  # its own base
                in_sums = isinstance(factor, sp.Add)
            else:
                in_sums = isinstance(factor.as_base_exp()[0], sp.Add)
            decorated.append((in_sums, _sort_key(factor, keys), k))
        decorated.sort()
        return [factors[k] for _, _, k in decorated]

    def term_key(self, term: sp.Expr) -> tuple:
        """Order terms of a sum roughly as Autolev does: by degree, then by
        the number of factors (``4*X^2 + 7*X*Y``), then by name."""
        degree = 0
        args = term.args if term.is_Mul else (term,)
        factors = []
        numbers = self.numbers
        for factor in args:
            if _number_in(factor, numbers):  # :meth:`is_number`
                continue
            factors.append(factor)
            if type(factor).as_base_exp is _EXPR_AS_BASE_EXP:  # exponent 1
                degree += 1
                continue
            _, exp = factor.as_base_exp()
            power = int(exp) if exp.is_Integer else 0
            degree += power if power > 0 else 1
        keys = self.keys
        if len(factors) == len(args):  # the term itself (no numbers to drop)
            if len(args) == 1:
                rest = factors[0]
            elif type(term) is sp.Mul and term.is_commutative is True:
                # :func:`_new_sort_key` of a product without numbers, read
                # off its factors' keys here
                key = keys.get(term)
                if key is None:
                    key = keys[term] = _product_key(args, keys, _ONE)
                return (degree, len(factors), key)
            else:
                rest = term
        elif len(factors) < 2:
            rest = factors[0] if factors else _ONE
        elif term.is_commutative:  # the key of their product, not formed
            return (degree, len(factors), _product_key(factors, keys, _ONE))
        else:  # a canonical product's factors stay canonical without numbers
            rest = sp.Mul._from_args(factors)
        return (degree, len(factors), _sort_key(rest, keys))

    # ------------------------------------------------------------ matrices

    def matrix(self, m: sp.MatrixBase) -> str:
        rows = []
        for i in range(m.rows):
            rows.append(", ".join(self.text(m[i, j], True) for j in range(m.cols)))
        return "[" + "; ".join(rows) + "]"


class _Memos:
    """Everything the printer remembers (see :class:`Printing`)."""

    def __init__(self) -> None:
        #: sort keys and number tests (a dict finds the same object by
        #: identity before comparing, and an equal tree formed elsewhere)
        self.keys: dict[Any, tuple] = {}
        self.numbers: dict[Any, bool] = {}
        #: printed forms (by digits and level) and coefficients' texts (by
        #: digits)
        self.shown: dict[tuple[int, bool], dict] = {}
        self.coefficients: dict[int, dict] = {}
        #: whether a sum prints with a leading minus, and the sum of its
        #: terms' negatives
        self.negative: dict[Any, bool] = {}
        self.negations: dict[Any, Any] = {}
        #: the printers that share these memos, by digits
        self.printers: dict[int, _AutolevPrinter] = {}


_EXPR_IS_NUMBER = sp.Expr.is_number


def _number_in(expr: Any, known: dict) -> bool:
    """``expr.is_number``, each node's answer formed once per ``known``:
    sympy's generic rule, all arguments numbers, is followed here with the
    memo (sympy's walks the whole subtree again at each node); a class with
    its own rule answers itself."""
    found = known.get(expr)
    if found is None:
        if type(expr).is_number is _EXPR_IS_NUMBER and expr.args:
            found = True
            for a in expr.args:  # as ``all()``, stopping at the first no
                if not _number_in(a, known):
                    found = False
                    break
        else:
            found = bool(expr.is_number)
        known[expr] = found
    return found


def _sort_key(expr: Any, known: dict) -> tuple:
    """``sp.default_sort_key(expr)``, an equal tuple (an integer's number a
    Python int), each node's formed once
    per ``known`` (sympy's ``Expr.sort_key``, written with the memo; a
    product's key is read off its arguments, without forming the product
    after its coefficient as sympy's ``as_coeff_Mul`` does)."""
    key = known.get(expr)
    if key is None:
        key = known[expr] = _new_sort_key(expr, known)
    return key


def _new_sort_key(expr: Any, known: dict) -> tuple:
    if type(expr) is sp.Integer:
        # sympy's key with the integer as a Python int: it compares (and
        # hashes) with every number as the Integer does, without calling
        # sympy's comparisons (intermediates' keys differ in their numbers)
        return (_NUMBER_KEY, (0, ()), (), expr.p)
    if not isinstance(expr, sp.Basic) or type(expr).sort_key is not _EXPR_SORT_KEY:
        return sp.default_sort_key(expr)
    if expr.is_Mul:
        args = expr.args
        coeff, factors = (args[0], args[1:]) if args[0].is_Number else (_ONE, args)
        if len(factors) > 1 and _plain_factors(expr, factors):
            return _product_key(factors, known, coeff, type(expr).class_key())
    coeff, rest = expr.as_coeff_Mul()
    exp = sp.S.One
    if rest.is_Pow:
        base, exp = rest.as_base_exp()
        if base is sp.S.Exp1:  # as sympy: E**x sorts as exp(x)
            base, exp = sp.Function("exp")(exp), sp.S.One
        rest = base
    if rest.is_Dummy:
        args = (rest.sort_key(),)
    elif rest.is_Atom:
        args = (str(rest),)
    else:
        if rest.is_Add:
            parts = rest.as_ordered_terms()
        elif rest.is_Mul:
            cpart, ncpart = rest.args_cnc()
            cpart.sort(key=lambda e: _sort_key(e, known))
            parts = cpart + ncpart
        else:
            parts = rest.args
        args = tuple([_sort_key(a, known) for a in parts])
    return (rest.class_key(), (len(args), args), _sort_key(exp, known), coeff)


def _product_key(
    factors: Sequence[Any], known: dict, coeff: Any, head: tuple | None = None
) -> tuple:
    """sympy's sort key of ``coeff`` times the product of ``factors`` (none
    a number, all commutative; ``head`` the product's class key, ``Mul``'s
    by default), read off the factors' keys."""
    keys = sorted([_sort_key(f, known) for f in factors])
    return (head or _MUL_KEY, (len(keys), tuple(keys)), _ONE_KEY, coeff)


def _plain_factors(product: sp.Mul, factors: tuple) -> bool:
    """No number among ``factors`` (a canonical product has at most one, its
    first argument) and all commutative: the factors sympy's
    ``args_cnc`` gives back as they are."""
    if product.is_commutative is not True:
        return False
    for f in factors:
        if f.is_Number:
            return False
    return True


_ONE = sp.S.One
_MINUS_ONE = sp.S.NegativeOne
_ONE_KEY = sp.S.One.sort_key()
_MUL_KEY = sp.Mul.class_key()
_NUMBER_KEY = sp.Number.class_key()
_EXPR_SORT_KEY = sp.Expr.sort_key
_EXPR_AS_BASE_EXP = sp.Expr.as_base_exp


def sort_key_in(expr: Any, memo: dict) -> tuple:
    """``sp.default_sort_key(expr)`` (an equal tuple, ordered alike), each
    node's key formed once per ``memo`` (a dict the caller keeps: the
    program printers use one)."""
    return _sort_key(expr, memo)


def is_number_in(expr: Any, memo: dict) -> bool:
    """``expr.is_number``, each node's answer formed once per ``memo``."""
    return _number_in(expr, memo)


# ------------------------------------------------------- vectors, dyadics


def _is_vector(value: Any) -> bool:
    from sympy.physics.vector import Vector

    return isinstance(value, Vector)


def _is_dyadic(value: Any) -> bool:
    from sympy.physics.vector import Dyadic

    return isinstance(value, Dyadic)


def _unit_name(frame: Any, index: int) -> str:
    return f"{str(frame.name).upper()}{index + 1}>"


def _unit_vector_name(vec: Any) -> str:
    (components, frame), *_ = vec.args
    for k in range(3):
        if components[k] != 0:
            return _unit_name(frame, k)
    raise ValueError("not a unit vector")


def _join_terms(
    printer: _AutolevPrinter, terms: list[tuple[Any, str]], zero: str
) -> str:
    out = ""
    for coef, tail in terms:
        coef = sp.sympify(coef)
        if coef == 1:
            text = tail
        elif coef == -1:
            text = "-" + tail
        else:
            ctext, prec = printer.show(coef, False)
            if prec < _NEG or (prec == _ADD):
                ctext = f"({ctext})"
            text = f"{ctext}*{tail}"
        if not out:
            out = text
        elif text.startswith("-"):
            out += " - " + text[1:]
        else:
            out += " + " + text
    return out or zero


def _vector_str(printer: _AutolevPrinter, vec: Any) -> str:
    terms = []
    for components, frame in vec.args:
        for k in range(3):
            if components[k] != 0:
                terms.append((components[k], _unit_name(frame, k)))
    return _join_terms(printer, terms, "0>")


def _dyadic_str(printer: _AutolevPrinter, dyad: Any) -> str:
    terms = []
    for coef, v1, v2 in dyad.args:
        if coef != 0:
            terms.append((coef, f"{_unit_vector_name(v1)}*{_unit_vector_name(v2)}"))
    return _join_terms(printer, terms, "0>>")


# ------------------------------------------------------------------ API


class Printing:
    """Autolev's printed forms of values, one :class:`Printing` per
    transcript: every value it prints shares one memo of sort keys (sympy's
    own cache holds 1000 and is soon overrun by a large model's transcript,
    so each key was formed again, down to the leaves), of which
    subexpressions are numbers, and of printed forms (a transcript's
    responses share most of their subexpressions).  The text is what
    :func:`autolev_str` prints without the memos.

    >>> import sympy as sp
    >>> A, B = sp.symbols("A B")
    >>> printing = Printing()
    >>> printing.format_response("E", (A + B) ** 2)
    ['E = (A+B)^2']
    >>> printing.autolev_str(A + B)
    'A + B'
    """

    def __init__(self) -> None:
        self._memos = _Memos()

    def _printer(self, digits: int) -> _AutolevPrinter:
        """The printer of ``digits`` significant digits (one per number of
        digits, over the shared memos)."""
        printers = self._memos.printers
        found = printers.get(digits)
        if found is None:
            found = printers[digits] = _AutolevPrinter(digits, self._memos)
        return found

    def autolev_str(self, value: Any, digits: int = 7) -> str:
        """``value`` written in Autolev syntax (:func:`autolev_str`)."""
        printer = self._printer(digits)
        if isinstance(value, sp.Expr):  # none of the kinds below
            return printer.text(value, True)
        if isinstance(value, VectorMatrix):  # ``[N1> + N3>, 3*N2>]``
            return (
                "["
                + "; ".join(
                    ", ".join(_vector_str(printer, v) for v in row)
                    for row in value.rows
                )
                + "]"
            )
        if _is_vector(value):
            return _vector_str(printer, value)
        if _is_dyadic(value):
            return _dyadic_str(printer, value)
        if isinstance(value, str):
            return value
        if not isinstance(value, sp.Basic | sp.MatrixBase) and hasattr(value, "name"):
            return str(value.name).upper()
        if isinstance(value, bool):
            return "ON" if value else "OFF"
        return printer.text(value, True)

    def format_response(
        self, label: str, value: Any, digits: int = 7, width: int = 80
    ) -> list[str]:
        """Lines of an Autolev response (:func:`format_response`)."""
        if isinstance(value, sp.MatrixBase):
            line = f"{label} = {self.autolev_str(value, digits)}"
            if value.rows * value.cols > 1 and (
                len(line) > width or _has_denominator(value)
            ):
                names = element_labels(label, value.rows, value.cols)
                return [
                    f"{name} = {self.autolev_str(element, digits)}"
                    for name, element in zip(names, value, strict=True)
                ]
            return [line]
        return [f"{label} = {self.autolev_str(value, digits)}"]


def autolev_str(value: Any, digits: int = 7) -> str:
    """Return ``value`` written in Autolev syntax.

    >>> import sympy as sp
    >>> A, B, C, D = sp.symbols("A B C D")
    >>> autolev_str(D/(A*D - B*C))
    'D/(A*D-B*C)'
    >>> autolev_str(sp.Matrix([-1.650629, -0.1746854 - 1.546869*sp.I]))
    '[-1.650629; -0.1746854 - 1.546869*i]'
    """
    return Printing().autolev_str(value, digits)


def format_response(
    label: str, value: Any, digits: int = 7, width: int = 80
) -> list[str]:
    """Lines of an Autolev response ``LABEL = value`` (without ``-> (n)``).

    A matrix whose one-line form is longer than ``width``, or which has an
    element with a symbolic denominator (as Autolev's ``Inv`` and ``Roots``
    responses), prints one element per line.

    >>> import sympy as sp
    >>> A, B = sp.symbols("A B")
    >>> format_response("M", sp.Matrix([[A, B]]))
    ['M = [A, B]']
    >>> format_response("R", sp.Matrix([1/A, 2/B]))
    ['R[1] = 1/A', 'R[2] = 2/B']
    """
    return Printing().format_response(label, value, digits, width)


def element_labels(label: str, rows: int, cols: int) -> list[str]:
    """The names of a matrix's elements, row by row, as Autolev's responses
    spell them: ``R[1]``, ``R[2]`` for a row or column matrix, else
    ``M5[1,1]``, ``M5[1,2]``, ..."""
    if rows == 1 or cols == 1:
        return [f"{label}[{k + 1}]" for k in range(rows * cols)]
    return [f"{label}[{i + 1},{j + 1}]" for i in range(rows) for j in range(cols)]


def _has_denominator(value: sp.MatrixBase) -> bool:
    for element in value:
        if not isinstance(element, sp.Expr) or element.is_number:
            continue
        _, den = sp.fraction(element)
        if not den.is_number:
            return True
    return False
