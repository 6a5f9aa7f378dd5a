"""Autolev's ``AutoZ``: intermediate variables that sympy can differentiate.

With ``AutoZ ON`` Autolev names the subexpressions it creates (``Z1``,
``Z2``, ...) so that a bicycle's equations stay small.  Here an intermediate
is a sympy *function* of the variables it depends on::

    Z12(q1, q4, lam) = cos(q4)*Z3(q1, lam) + ...

An :class:`Intermediates` book owns the definitions.  Each intermediate is an
instance of the book's own ``Function`` subclass; its first argument is its
number and the others are the coordinates, speeds, constants (and ``t`` if it
appears explicitly) it depends on.  Because these are real arguments:

* ``expr.diff(t)``, ``expr.diff(q1)`` and ``expr.diff(lam)`` follow the chain
  rule through sympy's own machinery; the partial derivative of an
  intermediate is again an intermediate, named once and reused;
* ``expr.has(q1)`` is true exactly when ``expr`` depends on ``q1``;
* substituting a value for ``q1`` evaluates every intermediate there.

Numeric code evaluates the intermediates in order (:meth:`Intermediates.flatten`),
and :meth:`Intermediates.expand` gives the full expression.

>>> import sympy as sp
>>> from sympy.physics.mechanics import dynamicsymbols
>>> q = dynamicsymbols("q")
>>> book = Intermediates()
>>> z = book.name(sp.cos(q) ** 2 + sp.sin(q))
>>> z
Z1
>>> sp.simplify(book.expand(z.diff(q)) - (-2*sp.sin(q)*sp.cos(q) + sp.cos(q)))
0
"""

from __future__ import annotations

import bisect
import functools
import itertools
import math
import operator
import random
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import sympy as sp
from sympy.core.assumptions import StdFactKB, _assume_defined
from sympy.core.basic import ordering_of_classes
from sympy.core.exprtools import decompose_power
from sympy.core.function import AppliedUndef
from sympy.core.parameters import global_parameters
from sympy.physics.vector import dynamicsymbols

from ..linear import linear_terms
from ..vocabulary import complex_functions
from ..walks import allow_deep_recursion, appearing, atoms, vmap, xreplace
from .elimination import eliminate

__all__ = [
    "Intermediate",
    "Intermediates",
    "has_intermediates",
    "substitute",
    "trivial",
]

_T = dynamicsymbols._t
_VARIABLE = (AppliedUndef, sp.Derivative)
#: the functions whose argument ``trivial`` looks at (a tuple: ``isinstance``
#: with ``a | b`` would build the union on every call)
_TRIG = (sp.sin, sp.cos, sp.tan)
#: sympy's zero is one object (``Integer(0) is S.Zero``): comparing by identity
#: is the same test as ``== 0`` for sympy results, without sympy's ``__eq__``.
_ZERO = sp.S.Zero


#: sympy's own ``is_<fact>`` getters (``Basic``'s), asked when an
#: intermediate has no table of facts
_SYMPY_FACT = {f: getattr(sp.Basic, "is_" + f).fget for f in _assume_defined}


def _fact_property(fact: str) -> property:
    """``Intermediate.is_<fact>``: sympy's answer, from the book's table of
    facts when the instance has one (see :meth:`Intermediates.facts`)."""
    sympys = _SYMPY_FACT[fact]

    def getit(self: Intermediate) -> bool | None:
        try:
            return self._assumptions[fact]
        except KeyError:
            pass
        table = self.book.facts(self)
        if table is None:
            return sympys(self)
        self._assumptions = table
        return table[fact]

    return property(getit)


def _is_commutative(self: Intermediate) -> bool | None:
    # sympy's handler (Function._eval_is_commutative), without the search,
    # found once per instance (sympy asks it of every factor of a product).
    found = self.__dict__.get("_commutative", _UNKNOWN)
    if found is _UNKNOWN:
        if all(a.is_commutative for a in self.args):
            found = True
        else:
            found = _SYMPY_FACT["commutative"](self)
        self.__dict__["_commutative"] = found
    return found


_UNKNOWN = object()


class Intermediate(sp.Function):
    """``Z_k(vars)``: intermediate number ``k`` of a book, at ``vars``.

    Each :class:`Intermediates` book makes its own subclass; the class
    attribute ``book`` leads to the definitions."""

    book: Intermediates

    @classmethod
    def eval(cls, *args: Any) -> None:
        return None

    def fdiff(self, argindex: int = 1) -> Any:
        if argindex == 1:
            return sp.S.Zero  # the number is not a variable
        return self.book.partial(self, argindex - 2)

    def _eval_derivative(self, s: Any) -> Any:
        # The chain rule of Function._eval_derivative, without asking each of
        # the (many) arguments for its derivative when the answer is plain:
        # arguments are usually functions of time and symbols.
        args = self.args[1:]
        if not all(a.is_Symbol or isinstance(a, _VARIABLE) for a in args):
            return super()._eval_derivative(s)
        if s == _T:
            terms = []
            for j, a in enumerate(args):
                if a == _T:
                    terms.append(self.book.partial(self, j))
                elif isinstance(a, _VARIABLE):
                    rate = self.book.time_rate(a)
                    if rate is not None:
                        terms.append(self.book.partial(self, j) * rate)
            return sp.Add(*terms)
        for j, a in enumerate(args):
            if a == s:
                return self.book.partial(self, j)
        if s.is_Symbol or isinstance(s, _VARIABLE):
            return sp.S.Zero
        return super()._eval_derivative(s)

    def _eval_evalf(self, prec: int) -> Any:
        return self.book.evalf(self, prec)

    def _sympystr(self, printer: Any) -> str:
        return self.book.label(self)

    def compare(self, other: Any) -> int:
        """``Basic.compare`` (:func:`_compare`: two intermediates of one book
        with as many arguments are decided by their numbers, which is most
        of the cost of sorting the factors and terms of large models' sums
        and products)."""
        return _compare(self, other)

    def _latex(self, printer: Any) -> str:
        label = self.book.label(self)
        return label[0] + "_{" + label[1:] + "}"

    def _pretty(self, printer: Any) -> Any:
        from sympy.printing.pretty.stringpict import prettyForm

        return prettyForm(self.book.label(self))

    def _eval_is_real(self) -> bool | None:
        return self.book.is_real(self)

    def __hash__(self) -> int:
        """sympy's hash is of the class's name and every argument (one call
        of each argument's ``__hash__``: 45 for an intermediate over 45
        variables, the most of any object a partial derivative makes).
        An intermediate at its own variables hashes its class's name, its
        number and its book's set of its variables (one object, which
        keeps its hash); any other instance hashes as sympy's.  Equal
        instances have equal arguments, so both are at the intermediate's
        own variables or neither: they hash alike."""
        h = self._mhash
        if h is None:
            varset = self.__dict__.get("_varset")
            if varset is None:
                varset = self.book.own_variables(self)
            if varset is None:
                return super().__hash__()
            h = self._mhash = hash((type(self).__name__, self.args[0].p, varset))
        return h

    # sympy's assumption properties, answered from the book's one table of
    # facts for the intermediate's number (Intermediates.facts) when it has
    # one; ``is_commutative`` is found once per instance.
    is_algebraic = _fact_property("algebraic")
    is_antihermitian = _fact_property("antihermitian")
    is_commutative = property(_is_commutative)
    is_complex = _fact_property("complex")
    is_composite = _fact_property("composite")
    is_even = _fact_property("even")
    is_extended_negative = _fact_property("extended_negative")
    is_extended_nonnegative = _fact_property("extended_nonnegative")
    is_extended_nonpositive = _fact_property("extended_nonpositive")
    is_extended_nonzero = _fact_property("extended_nonzero")
    is_extended_positive = _fact_property("extended_positive")
    is_extended_real = _fact_property("extended_real")
    is_finite = _fact_property("finite")
    is_hermitian = _fact_property("hermitian")
    is_imaginary = _fact_property("imaginary")
    is_infinite = _fact_property("infinite")
    is_integer = _fact_property("integer")
    is_irrational = _fact_property("irrational")
    is_negative = _fact_property("negative")
    is_noninteger = _fact_property("noninteger")
    is_nonnegative = _fact_property("nonnegative")
    is_nonpositive = _fact_property("nonpositive")
    is_nonzero = _fact_property("nonzero")
    is_odd = _fact_property("odd")
    is_polar = _fact_property("polar")
    is_positive = _fact_property("positive")
    is_prime = _fact_property("prime")
    is_rational = _fact_property("rational")
    is_real = _fact_property("real")
    is_transcendental = _fact_property("transcendental")
    is_zero = _fact_property("zero")

    def walk_parts(self) -> frozenset:
        """Every part of the arguments (the number too), and the arguments:
        found once per instance, for :mod:`al2py_runtime.walks`."""
        found = self.__dict__.get("_parts")
        if found is None:
            parts: set = set()
            stack = list(self.args)
            while stack:
                e = stack.pop()
                if e not in parts:
                    parts.add(e)
                    stack.extend(e.args)
            found = self.__dict__["_parts"] = frozenset(parts)
        return found

    @classmethod
    def class_key(cls) -> Any:
        # sympy's Function.class_key, found once per class (sympy builds a
        # table of function names on each call, for every sort of a product)
        found = cls.__dict__.get("_class_key")
        if found is None:
            found = super().class_key()
            cls._class_key = found
        return found


_ONE_KEY = sp.S.One.sort_key()


#: what is one node of a tree for naming: an intermediate, a function of time
#: or a derivative
_OWN_NODE = (Intermediate, AppliedUndef, sp.Derivative)


def trivial(expr: Any) -> bool:
    """Not worth a name: numbers, symbols, ``-x``, ``2*x``, ``sin(q)``, an
    intermediate."""
    if expr.is_Atom or isinstance(expr, _OWN_NODE):
        return True
    if expr.is_Mul and len(expr.args) == 2 and expr.args[0].is_Number:
        return trivial(expr.args[1]) and not expr.args[1].is_Mul
    if isinstance(expr, _TRIG) and (
        expr.args[0].is_Atom or isinstance(expr.args[0], AppliedUndef)
    ):
        return True
    if expr.is_Pow and expr.exp.is_Number and trivial(expr.base):
        return not expr.base.is_Pow and not expr.base.is_Mul
    return False


def _number(z: Intermediate) -> int:
    """An intermediate's number (its first argument)."""
    return z.args[0].p


def _minus_term(term: Any) -> bool:
    """``term.could_extract_minus_sign()`` for a term of a sum.  For a
    product with a rational coefficient sympy's answer is the coefficient's
    sign (``term == -term`` only for an infinite or undefined coefficient),
    found here without forming ``-term``."""
    if term.is_Mul:
        c = term.args[0]
        if not c.is_Number:
            return False  # sympy: False whether or not term == -term
        if c.is_Rational:
            return c.p < 0
    return term.could_extract_minus_sign()


def minus_first(expr: Any, key: Callable[[Any], Any] | None = None) -> bool:
    """``expr.could_extract_minus_sign()``, found faster for a sum.

    sympy counts the terms with a minus sign; on a tie it compares the sort
    keys of ``expr`` and ``-expr`` in full, term by term in the order of
    ``as_ordered_terms``.  When no two terms share a monomial (and no term
    is a number, which ``as_ordered_terms`` places by a rule of its own),
    ``-expr``'s terms come in the same order, each the negation of
    ``expr``'s, so the comparison is decided at the first term.  A term's
    sort key and its negation's differ only in the coefficient (the last
    part of ``Expr.sort_key``: ``c*rest`` and ``-c*rest`` share ``rest``), so
    for a rational coefficient the first term's sign decides; otherwise the
    two keys are compared.  ``key`` (default ``default_sort_key``) orders
    the generators of the terms' monomials, as ``as_terms`` does; a cached
    one saves most of the cost."""
    if not expr.is_Add:
        return expr.could_extract_minus_sign()
    args = expr.args
    negative = 0
    for a in args:  # (_minus_term of each, without a call for each)
        if a.is_Mul:
            c = a.args[0]
            if not c.is_Number:
                continue
            if c.is_Rational:
                if c.p < 0:
                    negative += 1
                continue
        if a.could_extract_minus_sign():
            negative += 1
    if 2 * negative != len(args):
        return 2 * negative > len(args)
    if any(a.is_Number or a.is_NumberSymbol for a in args):
        return expr.could_extract_minus_sign()
    first = _first_term(args, key or sp.default_sort_key)
    if first is not None:
        c = first.as_coeff_Mul()[0]
        if c.is_Rational:
            return c.p < 0
    terms, _ = as_terms(expr, key or sp.default_sort_key)
    seen = set()
    for term, (_, monom, ncpart) in terms:
        found = (monom, tuple(ncpart))
        if term.is_Order or found in seen:
            return expr.could_extract_minus_sign()
        seen.add(found)
    order, reverse = expr._parse_order(None)
    first = sorted(terms, key=order, reverse=reverse)[0][0]
    c = first.as_coeff_Mul()[0]
    if c.is_Rational:
        return c.p < 0
    for term, _ in sorted(terms, key=order, reverse=reverse):
        mine, theirs = sp.default_sort_key(term), sp.default_sort_key(-term)
        if mine != theirs:
            return bool(mine < theirs)
    return False


def _first_term(args: Sequence[Any], key: Callable[[Any], Any]) -> Any:
    """The first of a sum's terms ``args`` in the order of
    ``as_ordered_terms``, for :func:`minus_first`: the term with the
    largest monomial, lexicographically, over the generators sorted by
    ``key`` (:func:`as_terms`).  That term is found without sorting the
    generators: the first generator (by ``key``) whose exponent is not the
    same in every remaining term decides between them, the largest
    exponent staying.  None (ask :func:`as_terms`) when a term is not
    commutative or has a numeric factor besides its coefficient, or two
    terms share a monomial."""
    terms = []
    seen = set()
    for term in args:
        if term.is_Order or not term.is_commutative:
            return None
        # term.as_coeff_Mul()'s factors after the coefficient, without
        # forming their product
        if term.is_Mul:
            factors = term.args
            if factors[0].is_Number:
                factors = factors[1:]
        elif term.is_Number:
            if not term:
                return None  # (0's coefficient is 1, the factor 0 a number)
            factors = ()
        else:
            factors = (term,)
        cpart: dict = {}
        for factor in factors:
            if factor.is_number:
                return None
            if factor.is_Pow or isinstance(factor, sp.exp):
                base, exp = decompose_power(factor)
                cpart[base] = exp
            else:
                cpart[factor] = 1
        monomial = frozenset(cpart.items())
        if monomial in seen:
            return None
        seen.add(monomial)
        terms.append((term, cpart))
    while len(terms) > 1:
        exponents: dict[Any, list] = {}
        for _, cpart in terms:
            for base, exp in cpart.items():
                exponents.setdefault(base, []).append(exp)
        n = len(terms)
        varying = [
            base
            for base, found in exponents.items()
            if len(found) < n or any(e != found[0] for e in found)
        ]
        # (min calls key even for one: a sum's key is long to make)
        if len(varying) == 1:
            base = varying[0]
        else:
            base = _least_generator(varying, key)
        top = max(cpart.get(base, 0) for _, cpart in terms)
        terms = [t for t in terms if t[1].get(base, 0) == top]
    return terms[0][0]


def _least_generator(varying: list, key: Callable[[Any], Any]) -> Any:
    """``min(varying, key=key)`` for :func:`_first_term`'s generators, where
    ``key`` orders as ``default_sort_key``.  That key starts with the
    class's key (``Expr.sort_key``; a power's: its base's class), so the
    class keys decide first, and only the generators of the least class
    key are compared further (intermediates by their numbers,
    :func:`_least_intermediate`, else by ``key``): a sum's key, long to
    make, is made only against another sum.  The first of equal ones
    stays first, as with ``min``."""
    firsts = []
    for b in varying:
        first = _class_first(b)
        if first is None:
            found = _least_intermediate(varying)
            return min(varying, key=key) if found is None else found
        firsts.append(first)
    least = min(firsts)
    if firsts.count(least) == 1:
        return varying[firsts.index(least)]
    tied = [b for b, first in zip(varying, firsts, strict=True) if first == least]
    found = _least_intermediate(tied)
    return min(tied, key=key) if found is None else found


#: the generators whose ``sort_key`` starts with their class's
#: ``class_key`` (or, for a power of one, its base's)
_CLASS_FIRST = (
    sp.Add,
    sp.Symbol,
    Intermediate,
    AppliedUndef,
    sp.Derivative,
    sp.sin,
    sp.cos,
)
#: the class_key of sympy's classes among those above (each a constant);
#: an intermediate's class (one per book) keeps its own
#: (:meth:`Intermediate.class_key`), and a function of time's is made of
#: its name
_CLASS_KEYS: dict[type, Any] = {
    kind: kind.class_key()
    for kind in (sp.Add, sp.Symbol, sp.Derivative, sp.sin, sp.cos)
}


def _class_first(b: Any) -> Any:
    """The first part of ``default_sort_key(b)`` for a generator of
    :func:`_first_term`: its class's key, a power's base's; None for a
    generator of another kind."""
    if b.is_Pow:
        b = b.base
        if b is sp.S.Exp1:
            return None
    if not isinstance(b, _CLASS_FIRST):
        return None
    kind = type(b)
    found = _CLASS_KEYS.get(kind)
    return kind.class_key() if found is None else found


def _least_intermediate(bases: list) -> Any:
    """The first of ``bases`` by ``default_sort_key`` when all are
    intermediates of one class (else None): their keys (``Expr.sort_key``:
    the class's key, then the count of arguments and the arguments' keys,
    the number's first) order them by their count of arguments, then by
    their numbers, which decide when no two have the same pair."""
    kind = type(bases[0])
    if not issubclass(kind, Intermediate):
        return None
    least = None
    seen = set()
    for b in bases:
        if type(b) is not kind:
            return None
        args = b.args
        pair = (len(args), args[0].p)
        if pair in seen:
            return None
        seen.add(pair)
        if least is None or pair < least[0]:
            least = (pair, b)
    return least[1]


def _rational_left_zero(coeff: Any) -> complex:
    # The coefficient orders terms only after their monomials, which
    # minus_first has made distinct: a rational one is not evaluated
    # (sympy's complex() of it runs evalf).
    return complex(0) if coeff.is_Rational else complex(coeff)


def as_terms(
    expr: Any,
    key: Callable[[Any], Any],
    coefficient: Callable[[Any], complex] = _rational_left_zero,
    is_number: Callable[[Any], bool] = lambda factor: factor.is_number,
    to_complex: Callable[[Any], complex] = complex,
) -> tuple[list, list]:
    """sympy's ``Expr.as_terms`` (the same terms, monomials and generators),
    with the generators sorted by ``key``, which must order as
    ``default_sort_key`` does.  ``coefficient`` evaluates a term's leading
    number, ``is_number``/``to_complex`` test and evaluate its other
    factors (sympy's own steps, or remembering ones); by default, for
    :func:`minus_first`, a rational coefficient is left 0."""
    gens, terms = set(), []
    for term in sp.Add.make_args(expr):
        c, rest = term.as_coeff_Mul()
        coeff = coefficient(c)
        cpart, ncpart = {}, []
        if rest is not sp.S.One:
            for factor in sp.Mul.make_args(rest):
                if is_number(factor):
                    try:
                        coeff *= to_complex(factor)
                    except (TypeError, ValueError):
                        pass
                    else:
                        continue
                if factor.is_commutative:
                    base, exp = decompose_power(factor)
                    cpart[base] = exp
                    gens.add(base)
                else:
                    ncpart.append(factor)
        terms.append((term, ((coeff.real, coeff.imag), cpart, tuple(ncpart))))
    ordered = sorted(gens, key=key)
    indices = {g: i for i, g in enumerate(ordered)}
    result = []
    for term, (coeff, cpart, ncpart) in terms:
        monom = [0] * len(ordered)
        for base, exp in cpart.items():
            monom[indices[base]] = exp
        result.append((term, (coeff, tuple(monom), ncpart)))
    return result, ordered


def _linear_parts(w: Any, xs: Sequence[Any]) -> tuple[list[Any], Any] | None:
    """``w = sum(c_k * x_k) + rest`` when ``w`` is built of sums and
    products in which at most one factor holds an ``x`` (each of ``xs`` a
    symbol): one walk for all ``xs``, each distinct part once.  None when
    another part (a power, a function, a product of two such factors)
    holds an ``x``.

    The results are those of differentiating by each ``x`` with
    :meth:`Intermediates._pd` and setting the ``xs`` to zero with
    ``xreplace``: a product ``a*f*b`` whose factor ``f`` holds the ``xs``
    gives ``Mul(a, c, b)`` for each coefficient ``c`` of ``f`` and
    ``Mul(a, r, b)`` for its rest ``r``, as both make them, and a sum the
    sums of its terms' (sympy's constructors do not depend on the order of
    the arguments), each formed as :func:`product_with` and :func:`total`
    form them."""
    wanted = set(xs)
    memo: dict[Any, Any] = {}
    nonlinear = False

    def walk(e: Any) -> Any:
        # None: no x inside; else ({x: coefficient}, rest)
        nonlocal nonlinear
        if e in wanted:
            return {e: sp.S.One}, sp.S.Zero
        if e.is_Atom or nonlinear:
            return None
        if e in memo:
            return memo[e]
        if isinstance(e, Intermediate):
            # its parts are kept (walk_parts): an x among them is inside a
            # function (nonlinear), and without one it holds none
            if wanted.isdisjoint(e.walk_parts()):
                return None
            nonlinear = True
            return None
        args = e.args
        parts = [walk(a) for a in args]  # noqa: F821 - deleted after the walk
        if nonlinear:
            return None
        held = [i for i, p in enumerate(parts) if p is not None]
        if not held:
            out = None
        elif e.is_Add:
            coefs: dict[Any, list] = {}
            rest = []
            for a, p in zip(args, parts, strict=True):
                if p is None:
                    rest.append(a)
                    continue
                for x, c in p[0].items():
                    coefs.setdefault(x, []).append(c)
                rest.append(p[1])
            out = {x: total(c) for x, c in coefs.items()}, total(rest)
        elif e.is_Mul and len(held) == 1:
            i = held[0]
            inner, r = parts[i]
            factors = _Factors(args)
            out = (
                {x: product_with(args, i, c, factors) for x, c in inner.items()},
                product_with(args, i, r, factors),
            )
        else:
            nonlinear = True
            return None
        memo[e] = out
        return out

    try:
        top = walk(w)
    finally:
        del walk  # it refers to itself: freed now with its memo, not by a collection
    if nonlinear:
        return None
    if top is None:
        return [sp.S.Zero] * len(xs), w
    coefs, rest = top
    return [coefs.get(x, sp.S.Zero) for x in xs], rest


def substitute(expr: Any, rule: dict, memo: dict | None = None) -> Any:
    """``expr.xreplace(rule)``, as :func:`al2py_runtime.walks.xreplace`
    gives it, each distinct part once, where a product in which one factor
    is replaced is formed by :func:`product_with` and a sum by
    :func:`total` (sympy's results, without sympy's general case when the
    parts allow).  ``memo`` may be shared by calls with the same ``rule``."""
    return xreplace(expr, rule, memo, rebuild=_rebuilt)


def _rebuilt(e: Any, new: list, changed: list[int]) -> Any:
    """``e.func(*new)`` for :func:`substitute`."""
    if e.is_Mul:
        if len(changed) == 1:
            i = changed[0]
            return product_with(e.args, i, new[i])
        return products_with(e.args, new, changed)
    if e.is_Add:
        return total(new)
    if e.func is sp.Pow:
        return power(*new)
    return e.func(*new)


def products_with(args: tuple, new: list, changed: list[int]) -> Any:
    """``sp.Mul(*new)``, where ``args`` are a product's (canonical)
    arguments and ``new`` the same with the factors at ``changed`` (two or
    more) replaced, each by a rational number, a plain factor or a
    rational times plain factors (:func:`_plain_base`), as
    :func:`product_with` takes one.

    sympy's ``Mul.flatten`` then multiplies the rational coefficients and
    sorts the factors (by ``Basic.compare``), when no factor is a number
    or a power of one and no two share a base, and the result is not a
    number times one sum (sympy distributes it): that is done here
    directly.  Otherwise sympy forms the product."""
    first = args[0]
    start = 1 if first.is_Number else 0
    if (
        (start and (changed[0] == 0 or not first.is_Rational))
        or not all(a.is_commutative for a in new)
        or not global_parameters.evaluate
    ):
        return sp.Mul(*new)
    coeff = first if start else sp.S.One
    kept = [a for j, a in enumerate(args) if j >= start and j not in changed]
    bases = set()
    for a in kept:
        base = _plain_base(a)
        if base is None or base in bases:
            return sp.Mul(*new)
        bases.add(base)
    factors = list(kept)
    for i in changed:
        d = new[i]
        if isinstance(d, Intermediate):
            parts: tuple = (d,)
        elif d.is_Rational:
            coeff = coeff * d
            continue
        elif d.is_Mul:
            parts = d.args
            if parts[0].is_Number:
                if not parts[0].is_Rational:
                    return sp.Mul(*new)
                coeff = coeff * parts[0]
                parts = parts[1:]
        elif d.is_Number:
            return sp.Mul(*new)
        else:
            parts = (d,)
        for a in parts:
            base = _plain_base(a)
            if base is None or base in bases:
                return sp.Mul(*new)
            bases.add(base)
            factors.append(a)
    if coeff is sp.S.Zero:
        return sp.Mul(*new)  # (0, or nan with an infinite factor)
    if len(factors) == 1 and factors[0].is_Add and coeff is not sp.S.One:
        return sp.Mul(*new)  # sympy distributes it
    if len(factors) == 2:  # the one comparison sort makes, without its keys
        if _compare(factors[1], factors[0]) < 0:
            factors.reverse()
    else:
        factors.sort(key=_BY_COMPARE)
    return _product_of(coeff, factors)


def power(base: Any, exp: Any) -> Any:
    """``sp.Pow(base, exp)``, the same power, without sympy's question
    whether a term of a two-term sum is infinite, which walks every part of
    the terms (a resolved length, ``sqrt(x**2 + y**2)`` over a
    musculoskeletal model's positions) for each of a dozen facts.

    ``Pow.__new__`` with a rational exponent other than 0 and 1 and a sum
    for base goes straight to ``Add._eval_power`` (its other cases are for
    other exponents, or for a number or a product for base).  For a sum of
    two terms, that asks whether a term is infinite: if one is, it returns
    a value only for a literal ``a + I*b`` (``b.coeff(I)`` nonzero: a term
    with the imaginary unit as a factor); otherwise (and for any other
    sum), only for a number ``a + I*b`` (``pure_complex``: again a term
    with the factor ``I``).  So for a sum none of whose terms has the
    factor ``I``, the answer is nothing either way, and sympy forms the
    power unevaluated: ``Pow(base, exp, evaluate=False)``, its same last
    step."""
    if _stays_power(base, exp):
        return sp.Pow(base, exp, evaluate=False)
    return sp.Pow(base, exp)


def _stays_power(base: Any, exp: Any) -> bool:
    """Whether sympy's ``Pow(base, exp)`` is ``base**exp`` unevaluated,
    found without its queries (see :func:`power`): a sum, a rational
    exponent other than 0 and 1, and no term with the factor ``I``."""
    return (
        type(base) is sp.Add
        and exp.is_Rational
        and exp is not sp.S.Zero
        and exp is not sp.S.One
        and not any(
            sp.S.ImaginaryUnit in sp.Mul.make_args(term)
            for a in base.args
            for term in sp.Add.make_args(a)
        )
    )


def _compare(a: Any, b: Any) -> int:
    """``Basic.compare(a, b)`` (sympy's canonical order), the same steps
    without sympy's overheads: a class's place in ``ordering_of_classes``
    is looked up once per class name (sympy searches the list on every
    comparison of two classes), two intermediates of one book are decided
    by their numbers (:meth:`Intermediate.compare`), and parts are compared
    by this function unless their class defines a ``compare`` of its own
    (sympy then calls that, as ``Basic.compare`` does)."""
    if a is b:
        return 0
    ta, tb = type(a), type(b)
    if ta is not tb:
        na, nb = ta.__name__, tb.__name__
        if na != nb:
            if not isinstance(b, sp.Basic):
                return -1
            # (_class_place, without the calls once both are known)
            pa, pb = _PLACES.get(na), _PLACES.get(nb)
            if pa is None or pb is None:
                pa, pb = _class_place(na), _class_place(nb)
            return 1 if pa > pb else -1
    elif ta.compare is _Z_COMPARE:
        x, y = a.args, b.args
        if len(x) != len(y):
            return 1 if len(x) > len(y) else -1
        if x[0].p != y[0].p:
            return 1 if x[0].p > y[0].p else -1
    st, ot = a._hashable_content(), b._hashable_content()
    if len(st) != len(ot):
        return 1 if len(st) > len(ot) else -1
    for left, right in zip(st, ot, strict=True):
        if left is right:
            continue
        if isinstance(left, sp.Basic):
            own = type(left).compare
            if own is _BASIC_COMPARE or own is _Z_COMPARE:
                c = _compare(left, right)
            else:
                c = left.compare(right)
        elif isinstance(left, frozenset):
            other = sp.Basic(*right) if isinstance(right, frozenset) else right
            c = sp.Basic(*left).compare(other)
        else:
            c = (left > right) - (left < right)
        if c:
            return c
    return 0


_BASIC_COMPARE = sp.Basic.compare
_Z_COMPARE = Intermediate.compare
#: class name -> its place in sympy's ``ordering_of_classes`` (``_cmp_name``):
#: (index, "") for a listed name, (after the list, name) for another
_PLACES: dict[str, tuple[int, str]] = {}


def _class_place(name: str) -> tuple[int, str]:
    found = _PLACES.get(name)
    if found is None:
        try:
            found = (ordering_of_classes.index(name), "")
        except ValueError:
            found = (len(ordering_of_classes) + 1, name)
        _PLACES[name] = found
    return found


#: the order of a product's factors and of a sum's terms (``Mul.flatten``
#: and ``Add.flatten`` sort by it)
_BY_COMPARE = functools.cmp_to_key(_compare)


def _prefix(x: Any, kinds: dict) -> tuple | None:
    """The start of :func:`_compare`'s decision about ``x``, as a tuple that
    orders as :func:`_compare` does whenever two prefixes differ: the
    class's place, the length of the hashable content, and its first part's
    class place and number (an intermediate's count of arguments and
    number, a rational's numerator and denominator).  ``kinds`` records
    which form each class place takes; None when a class place took two
    (an intermediate and another function of one name), or the first part
    compares by a rule of its own."""
    hc = x._hashable_content()
    top = _class_place(type(x).__name__)
    if not hc:
        return top, 0, (), ()
    first = hc[0]
    if not isinstance(first, sp.Basic):
        kind, place, extra = "other", (-1, ""), ()
    else:
        own = type(first).compare
        place = _class_place(type(first).__name__)
        if own is _Z_COMPARE:
            args = first.args
            kind, extra = "z", (len(args), args[0].p)
        elif own is not _BASIC_COMPARE:
            return None
        elif first.is_Rational:
            kind, extra = "q", (first.p, first.q)
        else:
            kind, extra = "basic", ()
    if kinds.setdefault((top, len(hc)), kind == "other") != (kind == "other"):
        return None  # a first part that is a sympy object here, not there
    if kinds.setdefault(place, kind) != kind:
        return None
    return top, len(hc), place, extra


#: the key of a (key, item) pair
_KEY = operator.itemgetter(0)
_MUL_PLACE = _class_place("Mul")


#: a symbol's class key (``default_sort_key``'s first part), and a mark
#: after every class key
_SYMBOL_CLASS = sp.Symbol.class_key()
_END = ((math.inf,),)

#: the functions whose values :meth:`Intermediates._products_pd` takes as
#: factors (of a variable)
_SINE_COSINE = frozenset([sp.sin, sp.cos])
#: the functions whose values :meth:`Intermediates._products_pd` takes as
#: factors (of a variable or of a sum)
_TRIG_OF = frozenset([sp.sin, sp.cos, sp.tan])

#: the kinds of factors of :meth:`Intermediates._products_plan`
_PLAN_Z, _PLAN_SINE, _PLAN_OTHER, _PLAN_SUM = range(4)
#: a sum's place in sympy's order of classes
_ADD_PLACE = _class_place("Add")
#: a power's place in sympy's order of classes
_POW_PLACE = _class_place("Pow")
#: the walk facts of a sum (:meth:`Intermediates._products_pd` leaves its
#: derivative to be walked when it is named)
_SUM_FACTS = object()


def _base_key(key: tuple) -> tuple:
    """The tuple of a factor's base (:meth:`Intermediates._plain_key`):
    a power's base's, else the factor's own."""
    return key[2] if key[0] == _POW_PLACE else key


def _plain_factor_key(f: Any) -> tuple | None:
    """A tuple that orders as ``Basic.compare`` (:func:`_plain_atom_key`,
    parts by their own tuples), for the factors that are their own base in
    a product and commute: a symbol, a function of time, a variable's
    derivative, the sine or cosine of a symbol or function of time; None
    for another."""
    if not f.is_commutative:
        return None
    if type(f) is sp.Symbol:
        return _plain_atom_key(f)
    if type(f) in _SINE_COSINE:
        inner = f.args[0]
        if inner.is_Symbol or isinstance(inner, AppliedUndef):
            inner_key = _plain_factor_key(inner)
            return None if inner_key is None else _nested_key(f, [inner_key])
        return None
    if isinstance(f, AppliedUndef):
        if all(type(a) is sp.Symbol for a in f.args):
            return _nested_key(f, [_plain_atom_key(a) for a in f.args])
        return None
    if type(f) is sp.Derivative and isinstance(f.expr, AppliedUndef):
        expr_key = _plain_factor_key(f.expr)
        counts = f.args[1:]
        if expr_key is None or not all(
            type(v) is sp.Symbol and n.is_Integer for v, n in counts
        ):
            return None
        return _nested_key(
            f,
            [
                expr_key,
                *[_nested_key(c, [_plain_atom_key(a) for a in c.args]) for c in counts],
            ],
        )
    return None


def _nested_key(e: Any, arg_keys: list) -> tuple:
    """The tuple of ``e``, whose hashable content is its arguments, from
    their tuples ``arg_keys``."""
    return (_class_place(type(e).__name__), len(arg_keys), *arg_keys)


def _plain_atom_key(a: Any) -> tuple:
    """A rational number's or a symbol's place in ``Basic.compare``'s
    order, as a tuple: its class's place, then its hashable content's
    length and parts (:func:`_compare`'s steps)."""
    content = a._hashable_content()
    return (_class_place(type(a).__name__), len(content), *content)


def _sort_by_compare(items: list) -> None:
    """``items.sort(key=cmp_to_key(Basic.compare))`` for distinct items:
    sorted first by :func:`_prefix` (tuples, compared without calls), and
    only items of one prefix by :func:`_compare`.  Where prefixes differ,
    they order as ``Basic.compare`` (a total order), so the result is the
    same list; where a prefix cannot be formed, every item is compared.
    (Forming the prefixes costs more than it saves below about 20 items.)"""
    if len(items) < 20:
        items.sort(key=_BY_COMPARE)
        return
    kinds: dict = {}
    keyed = []
    for x in items:
        key = _prefix(x, kinds)
        if key is None:
            items.sort(key=_BY_COMPARE)
            return
        keyed.append((key, x))
    keyed.sort(key=_KEY)
    out = []
    for _, group in itertools.groupby(keyed, key=_KEY):
        group = [x for _, x in group]
        if len(group) > 1:
            group.sort(key=_BY_COMPARE)
        out += group
    items[:] = out


def _product(args: Sequence[Any]) -> Any:
    """A product of commutative arguments already in sympy's canonical form
    and order (``Mul._from_args``, told they commute)."""
    return _MUL_FROM_ARGS(args, True)


#: ``Mul._from_args``, looked up once (called for every product formed)
_MUL_FROM_ARGS = sp.Mul._from_args


def _product_of(coeff: Any, factors: list) -> Any:
    """The product of the rational ``coeff`` and ``factors`` (distinct
    bases, sorted by ``Basic.compare``), as ``Mul.flatten`` leaves it: the
    coefficient first unless it is 1; 1 for no factor, and a factor alone
    as itself.  (``factors`` is changed.)"""
    if coeff is not sp.S.One:
        factors.insert(0, coeff)
    if not factors:
        return sp.S.One
    if len(factors) == 1:
        return factors[0]
    return _product(factors)  # these arguments as they are


def _plain_base(a: Any) -> Any:
    """The base of ``a`` if ``a`` is a factor that ``Mul.flatten`` only
    sorts (given that no other factor has its base): not a number, not a
    power of a number, not ``exp``; else None.  An intermediate or a
    function of time (most factors) is its own base."""
    if isinstance(a, _PLAIN):
        return a if a.is_commutative else None
    b = a.base if a.is_Pow else a
    if (
        b.is_Number
        or b.is_NumberSymbol
        or b is sp.S.ImaginaryUnit
        or isinstance(a, sp.exp)
        or not a.is_commutative
    ):
        return None
    return a.as_base_exp()[0]


_PLAIN = (Intermediate, AppliedUndef)


class _Factors:
    """What :func:`product_with` needs of a product's arguments, found once
    per product (the chain rule asks it once per factor that holds the
    variable, and per variable): the rational coefficient and where the
    other factors start, each factor's base (:func:`_plain_base`), the
    factors with none, and whether the bases are distinct."""

    __slots__ = ("coeff", "start", "bases", "plain", "odd", "distinct", "simple")

    def __init__(self, args: tuple) -> None:
        first = args[0]
        if first.is_Number:
            self.coeff, self.start = first, 1
        else:
            self.coeff, self.start = sp.S.One, 0
        self.bases = [_plain_base(a) for a in args[self.start :]]
        self.odd = frozenset(
            j + self.start for j, b in enumerate(self.bases) if b is None
        )
        self.plain = {b for b in self.bases if b is not None}
        self.distinct = len(self.plain) + len(self.odd) == len(self.bases)
        #: every factor plain, with distinct bases, after a rational
        #: coefficient other than 1 (or none): a factor replaced by an
        #: intermediate of another base is only placed in order
        self.simple = (
            self.distinct
            and not self.odd
            and self.coeff.is_Rational
            and not (self.start and self.coeff is sp.S.One)
        )


def _place(seq: Sequence[Any], x: Any, lo: int) -> int:
    """Where ``x`` goes among ``seq[lo:]``, sorted by ``Basic.compare``:
    ``bisect_left`` by :func:`_compare`, without sort keys."""
    hi = len(seq)
    while lo < hi:
        mid = (lo + hi) // 2
        if _compare(seq[mid], x) < 0:
            lo = mid + 1
        else:
            hi = mid
    return lo


def product_with(args: tuple, i: int, d: Any, factors: _Factors | None = None) -> Any:
    """``sp.Mul(*args[:i], d, *args[i + 1:])`` where ``args`` are a
    product's (canonical) arguments and ``d`` the derivative of factor
    ``i`` by the chain rule: a rational number, an intermediate, another
    plain factor (``sin(q)``), or a rational times plain factors.
    ``factors``: ``_Factors(args)``, when the caller keeps it.

    sympy's ``Mul.flatten`` then only multiplies the rational coefficients
    and sorts the factors (by ``Basic.compare``), when no factor is a
    number or a power of one and no two share a base (they would combine
    into a power), and the result is not a number times one sum (sympy
    distributes it): that is done here directly.  Otherwise (or for any
    other ``d``) sympy forms the product."""
    if (
        factors is not None
        and factors.simple
        and isinstance(d, Intermediate)
        and i >= factors.start
        and d.is_commutative
        and (d not in factors.plain or d == factors.bases[i - factors.start])
    ):
        # the chain rule's common case (the steps below, for it): the
        # coefficient stays first and the intermediate takes its place
        # among the other factors, by a binary search on Basic.compare
        rest = args[:i] + args[i + 1 :]
        lo = _place(rest, d, factors.start)
        return _product((*rest[:lo], d, *rest[lo:]))
    if isinstance(d, Intermediate):
        n, new_factors = sp.S.One, (d,)
    elif d.is_Rational:
        n, new_factors = d, ()
    elif d.is_Mul and d.is_commutative:
        if d.args[0].is_Rational:
            n, new_factors = d.args[0], d.args[1:]
        elif d.args[0].is_Number:
            return sp.Mul(*args[:i], d, *args[i + 1 :])
        else:
            n, new_factors = sp.S.One, d.args
    elif d.is_commutative and not d.is_Number:
        # a sum is a factor as any other (its base is itself); a number
        # times one sum alone is distributed by sympy (below)
        n, new_factors = sp.S.One, (d,)
    else:
        return sp.Mul(*args[:i], d, *args[i + 1 :])
    if factors is None:
        factors = _Factors(args)
    start = factors.start
    c = factors.coeff
    if i < start or not c.is_Rational or not factors.distinct:
        return sp.Mul(*args[:i], d, *args[i + 1 :])
    odd = factors.odd
    if odd and (len(odd) > 1 or i not in odd):
        return sp.Mul(*args[:i], d, *args[i + 1 :])  # another factor is not plain
    own = factors.bases[i - start]  # factor i's base, no longer there
    plain = factors.plain
    if len(new_factors) == 1:
        z = new_factors[0]
        if isinstance(z, Intermediate):  # _plain_base, without the call
            base = z if z.is_commutative else None
        else:
            base = _plain_base(z)
        if base is None or (base in plain and base != own):
            return sp.Mul(*args[:i], d, *args[i + 1 :])
    else:
        seen = set()
        for a in new_factors:
            base = _plain_base(a)
            if base is None or base in seen or (base in plain and base != own):
                return sp.Mul(*args[:i], d, *args[i + 1 :])
            seen.add(base)
    coeff = c if n is sp.S.One else n if c is sp.S.One else c * n
    if coeff is sp.S.Zero:
        return sp.S.Zero
    rest = args[start:i] + args[i + 1 :]
    if len(rest) + len(new_factors) == 1 and (*rest, *new_factors)[0].is_Add:
        if coeff is not sp.S.One:
            return sp.Mul(*args[:i], d, *args[i + 1 :])  # sympy distributes it
    if len(new_factors) == 1:
        lo = _place(rest, z, 0)
        new = [*rest[:lo], z, *rest[lo:]]
    else:
        new = sorted((*rest, *new_factors), key=_BY_COMPARE)
    return _product_of(coeff, new)


def minus(expr: Any) -> Any:
    """``-expr``, as sympy makes it, for a sum: each term negated by its
    coefficient alone (sympy multiplies ``-1`` into each term with
    ``Mul.flatten`` and collects them again with ``Add.flatten``), then the
    terms sorted as ``Add.flatten`` sorts them (a number first, the rest
    by ``Basic.compare``).  A term with a sum among its factors stays a
    product (``-(2*(a + b))`` is ``-2*(a + b)``, as sympy's ``Mul.__neg__``
    makes it), unless the negation leaves the sum alone (``-(-(a + b))``:
    sympy adds its terms to the sum); that case and non-commutative terms
    go to sympy."""
    if not expr.is_Add:
        return -expr
    number, terms = sp.S.Zero, []
    for term in expr.args:
        if term.is_Number:
            number = -term
            continue
        if term.is_Mul and term.args[0].is_Number:
            c, rest = -term.args[0], term.args[1:]
        else:
            c, rest = sp.S.NegativeOne, term.args if term.is_Mul else (term,)
        if not term.is_commutative or any(r.is_Number for r in rest):
            return -expr
        if c is sp.S.One and len(rest) == 1 and rest[0].is_Add:
            return -expr  # -(-(a + b)): sympy adds a + b's terms to the sum
        if c is sp.S.One:
            terms.append(rest[0] if len(rest) == 1 else _product(rest))
        else:
            terms.append(_product((c, *rest)))
    return _sum(number, terms)


def total(terms: Sequence[Any]) -> Any:
    """``sp.Add(*terms)``, as ``Add.flatten`` makes it, for the sums of the
    chain rule: finite numbers, and products or other terms that are not
    sums (a number's power, an ``Order``, a non-commutative term or one that
    is not an ``Expr`` go to sympy).  Like terms are collected by their
    coefficients, zeros dropped, the rest sorted by ``Basic.compare`` with
    the number first, as sympy does, without sympy's general case.

    A term is collected under the tuple of its factors other than the
    coefficient (``(x,)`` for a term that is not a product), which is
    what sympy's key, that product, is made of: no product is formed
    to be a key."""
    if not global_parameters.evaluate:
        return sp.Add(*terms)
    if len(terms) < 2:  # sympy's Add of one term is the term
        return terms[0] if terms else sp.S.Zero
    number = sp.S.Zero
    #: key -> [its coefficient, the term itself while no other term has
    #: joined it, else None] (one lookup per term: a key's hash is its
    #: factors', not kept by the tuple)
    collected: dict[tuple, list] = {}
    seq = list(terms)
    for o in seq:  # a sum's terms join the end, as in Add.flatten
        if o.is_Mul:
            args = o.args
            c = args[0]
            if c.is_Number:
                if not c.is_Rational and not c.is_finite:
                    return sp.Add(*terms)
                key = args[1:]
            else:
                c, key = sp.S.One, args
            if not o.is_commutative:
                return sp.Add(*terms)
        elif o.is_Add and o.is_commutative:
            seq.extend(o.args)
            continue
        elif o.is_Number:
            if not o.is_Rational and not o.is_finite:
                return sp.Add(*terms)
            number += o
            continue
        elif (
            o.is_Order
            or not isinstance(o, sp.Expr)
            or not o.is_commutative
            or (o.is_Pow and o.base.is_Number)
        ):
            return sp.Add(*terms)
        else:
            c, key = sp.S.One, (o,)
        entry = [c, o]
        found = collected.setdefault(key, entry)
        if found is not entry:
            found[0] = found[0] + c
            found[1] = None
    out = []
    for key, (c, o) in collected.items():
        # a rational zero is sympy's one zero
        zero = c is _ZERO if c.is_Rational else c.is_zero
        if o is not None:
            # sympy's Add.flatten rebuilds it from its coefficient and key
            # as it is (a product's arguments, a product with a sum, a
            # plain factor times a number): the term itself
            if zero:
                continue
            if c is sp.S.One or len(key) > 1 or isinstance(key[0], _SIMPLE):
                out.append(o)
                continue
        elif zero:
            continue
        if c is sp.S.One:
            out.append(key[0] if len(key) == 1 else _product(key))
        elif len(key) > 1:
            out.append(_product((c, *key)))
        elif key[0].is_Add:  # 2*(a + b) stays a product, as in Add.flatten
            out.append(sp.Mul(c, key[0], evaluate=False))
        elif type(key[0]) is sp.Pow and _stays_power(*key[0].args):
            # c * (a + b)**r: Mul.flatten forms Pow(a + b, r) again, which
            # is the power itself (asking each term whether it is
            # infinite), and puts the number first
            out.append(sp.Mul(c, key[0], evaluate=False))
        else:
            out.append(sp.Mul(c, key[0]))
    return _sum(number, out)


#: factors ``f`` for which ``Mul(c, f)`` (``c`` a finite number, not 0 or
#: 1) is the product of exactly these two arguments, ``c`` first
_SIMPLE = (Intermediate, AppliedUndef, sp.Symbol, sp.Derivative, sp.sin, sp.cos)


def _sum(number: Any, terms: list) -> Any:
    """The sum of a number and of commutative terms in sympy's canonical
    form, none a number and no two alike, as ``Add.flatten`` orders them:
    the number first, the rest by ``Basic.compare``."""
    if len(terms) == 2:  # the one comparison list.sort makes, without its keys
        if _compare(terms[1], terms[0]) < 0:
            terms.reverse()
    else:
        _sort_by_compare(terms)
    if number is not sp.S.Zero:
        terms.insert(0, number)
    if not terms:
        return sp.S.Zero
    return (
        terms[0] if len(terms) == 1 else sp.Add._from_args(terms, is_commutative=True)
    )


def _is_variable_x(e: Any, x: Any) -> bool:
    """``e == x`` for the variable ``x`` (equal only with an equal type:
    functions of time made twice are equal classes, not one, and only a
    function of time's class compares equal to another), without sympy's
    ``__eq__`` on every node walked, nor the metaclass's unless the classes
    hash alike (its test builds sympy's class keys of both, a tenth of a
    derivative's walk over the other functions of time; a function of
    time's class keeps its hash).  Two objects of one type are compared
    only when they hash alike (sympy keeps each object's hash): another
    derivative than ``x`` is told apart without comparing its parts."""
    return e is x or (
        (
            type(e) is type(x)
            or (
                isinstance(e, AppliedUndef)
                and hash(type(e)) == hash(type(x))
                and type(e) == type(x)  # noqa: E721
            )
        )
        and hash(e) == hash(x)
        and e == x
    )


def _variable_pd(e: Any, x: Any, rate: Callable[[Any], Any] | None) -> Any:
    """``Intermediates._pd`` of an atom or a variable ``e``: 1 for ``x``,
    else 0, or ``rate(e)`` of a variable when a total derivative is
    taken."""
    if _is_variable_x(e, x):
        return sp.S.One
    if rate is None or e.is_Atom:
        return sp.S.Zero
    return rate(e)


def has_intermediates(expr: Any) -> bool:
    """True if ``expr`` (a sympy object, matrix or vector) holds intermediates
    (:func:`book_of`'s walk: each distinct part once)."""
    try:
        expr = sp.sympify(expr)
    except (sp.SympifyError, AttributeError, TypeError):
        return False
    return book_of(expr) is not None


def book_of(*exprs: Any) -> Intermediates | None:
    """The book of the first intermediate in ``exprs`` (sympy objects or
    matrices of them), None if they hold none; each distinct part is
    walked once."""
    for e in exprs:
        for item in e if isinstance(e, sp.MatrixBase) else [e]:
            if isinstance(item, sp.Basic):
                for z in atoms(item, Intermediate):
                    return z.book
    return None


class Intermediates:
    """The book of one script's intermediates (``Z1``, ``Z2``, ...).

    :meth:`name` gives a short expression a name; partial derivatives are
    named by :meth:`partial` when sympy asks for them."""

    def __init__(self, prefix: str = "Z", taken: Iterable[str] = ()) -> None:
        self.prefix = prefix
        self.Z = type(prefix, (Intermediate,), {"book": self})
        self._taken = set(taken)
        self._vars: list[tuple[Any, ...]] = [()]  # k -> canonical variables
        self._dvars: list[tuple[Any, ...]] = [()]  # k -> the derivatives among them
        self._varsets: list[frozenset] = [frozenset()]  # k -> its variables, a set
        #: variables -> (sorted, as a set, the derivatives among them)
        self._orders: dict[frozenset, tuple[tuple, frozenset, tuple]] = {}
        self._time_rates: dict[Any, Any] = {}  # variable -> its diff(t), or None
        self._values: dict[int, dict] = {}  # point -> part -> value (values_at)
        self._defs: list[Any] = [None]  # k -> definition (canonical variables)
        self._labels: list[str] = [""]
        self._named: dict[Any, Any] = {}
        self._partials: dict[tuple[int, int], Any] = {}
        #: definition -> what :meth:`_products_pd` needs of it (or None)
        self._plans: dict[Any, tuple | None] = {}
        #: factors -> :meth:`_rest_facts` of them (for :meth:`_products_plan`:
        #: many definitions share a factor, or a pair)
        self._kept_facts: dict[tuple, tuple | None] = {}
        #: (class, numerator, denominator) of a rational coefficient -> its
        #: :func:`_plain_atom_key` (for :meth:`_products_pd`)
        self._coeff_keys: dict[tuple, tuple] = {}
        #: variable -> a number of its own, and an intermediate's set of
        #: variables -> their places by their numbers (:meth:`_variable_places`)
        self._ids: dict[Any, int] = {}
        self._varset_ids: dict[frozenset, dict[int, int]] = {}
        self._dt_memo: dict[Any, Any] = {}  # expression -> total_dt
        #: variable -> (expression -> partial derivative by it): the answer
        #: depends only on the expression (the intermediates' partials are
        #: named once, in :attr:`_partials`), so every ``D()`` of a script
        #: and every intermediate's partial share one memo per variable
        self._pd_memos: dict[Any, dict[Any, Any]] = {}
        self._real: dict[int, bool | None] = {}
        self._busy: set[int] = set()
        self._positions: dict[Any, dict[Any, int]] = {}
        self._facts: dict[int, Any] = {}
        self._full: dict[Any, Any] = {}
        self._probes: dict[tuple[int, frozenset], dict] = {}
        self._count = 0
        #: derivatives that are variables (speeds written Q'), not accelerations
        self.rates: frozenset = frozenset()
        #: ZEE_NOT: quantities that no intermediate may contain
        self.exclude: frozenset = frozenset()
        self._rebased: dict[Any, Any] = {}
        self._children: dict[Any, Any] = {}  # k, or a z not at its own variables
        #: an intermediate not at its own variables -> its definition there
        #: (:meth:`definition`; a program's writer asks for it many times)
        self._elsewhere: dict[Any, Any] = {}
        self._numbers: dict[Any, Any] = {}
        self._keys: dict[Any, Any] = {}
        self._name_keys: dict[Any, tuple[int, str]] = {}
        self._factors: dict[Any, _Factors] = {}  # product -> _Factors(its args)
        #: where the intermediates' class goes in sympy's order of classes
        self._z_place = _class_place(self.Z.__name__)
        #: factor -> its :func:`_plain_factor_key`
        self._plain_keys: dict[Any, tuple | None] = {}
        #: one node of a tree for _split (a tuple, for isinstance)
        self._one_node = (self.Z, AppliedUndef, sp.Derivative)
        #: a set of variables -> the sort keys of its variables, in order
        self._var_keys: dict[frozenset, tuple] = {}
        #: a set of variables -> whether each commutes (:meth:`_new_z`)
        self._commutes: dict[frozenset, bool] = {}
        #: sets of variables of intermediates -> (their union, the
        #: derivatives among them), for :meth:`_scan`
        self._unions: dict[frozenset, tuple[frozenset, frozenset]] = {}
        #: a set of variables -> the one object kept for it (:meth:`_one_set`)
        self._sets: dict[frozenset, frozenset] = {}
        #: (variables outside intermediates, the intermediates' union) ->
        #: :meth:`_met`'s answer
        self._mets: dict[tuple, tuple[frozenset, frozenset]] = {}
        #: a set of derivatives -> whether all are :attr:`rates` (for the
        #: rates :attr:`_rated_for`; reset when they change)
        self._rated: dict[frozenset, bool] = {}
        self._rated_for: frozenset | None = None
        #: a part -> what :meth:`_split` makes of it (the part, its parts
        #: named, and its size), for the rates and excluded quantities
        #: :attr:`_parts_for` (reset when either changes)
        self._parts: dict[Any, tuple[Any, int]] = {}
        self._parts_for: tuple[frozenset, frozenset] | None = None

    def __len__(self) -> int:
        return len(self._defs) - 1

    # ------------------------------------------------------------- naming

    def name(self, expr: Any) -> Any:
        """``expr`` itself if trivial (or holding derivatives), else the
        intermediate that stands for it (the same one for the same
        expression)."""
        return self._name(sp.sympify(expr), None)

    def _name(self, expr: Any, negated: set | None, small: bool = False) -> Any:
        """:meth:`name`; ``negated``: the variables of ``-expr``, which was
        being named when its sign was taken out (``expr`` then needs no
        scan, and its sign is not taken out again: sympy's
        ``could_extract_minus_sign`` is not true of both an expression and
        its negation); ``small``: no argument of ``expr`` has more than
        :attr:`LIMIT` nodes (:meth:`_split` would leave it as it is)."""
        if not isinstance(expr, sp.Expr) or trivial(expr):
            return expr
        found = self._named.get(expr)
        if found is not None:
            return found
        if negated is not None:
            return self._new_name(expr, negated, None, split=not small)
        return self._name_walked(expr, *self._walk(expr))

    def _name_walked(
        self,
        expr: Any,
        variables: set | frozenset,
        derivatives: set | frozenset,
        bad: list,
        size: int | float,
        negative: bool | None = None,
        short: bool = False,
        opposite: tuple | None = None,
    ) -> Any:
        """:meth:`_name` of ``expr`` (not trivial, not named yet), given
        what :meth:`_walk` finds in it; ``negative``: ``minus_first(expr)``
        when the caller knows it (it holds while no part is split off),
        ``short``: no part of ``expr`` has more than :attr:`LIMIT` nodes
        (:meth:`_split` leaves it as it is), and ``opposite``: the terms
        :meth:`_products_pd` formed ``expr`` from, of which
        :meth:`_products_opposite` forms ``minus(expr)`` (while no part is
        split off)."""
        if derivatives and not self._all_rates(derivatives):
            return expr  # accelerations stay visible
        if self.exclude and expr.has(*self.exclude):
            # ZEE_NOT: these quantities stay explicit (Kane(F1, F2) solves for
            # them), so only their coefficients are named.
            return self.name_linear(expr, [x for x in self.exclude if expr.has(x)])
        if bad:
            expr = self._rebase(expr, bad)
            found = self._named.get(expr)
            if found is not None:
                return found
            variables, _, _, size = self._walk(expr)
        if size > self.LIMIT + 1 and not short:
            found, expr, original = self._in_parts(expr)
            if found is not None:
                return found
        else:
            original = None  # no part is larger than LIMIT: _split keeps it
        if negative is None or original is not None:
            negative = minus_first(expr, self._sort_key)
        if negative:
            # ``-expr``'s arguments (a sum's terms negated, a product's
            # factors with the coefficient negated) have at most two nodes
            # more than ``expr``'s, each of which has at most ``size`` less
            # the number of arguments (the root and one node for each other
            # argument): below the limit, ``-expr`` is not split
            small = (
                original is None
                and (expr.is_Add or expr.is_Mul)
                and size - len(expr.args) + 2 <= self.LIMIT
            )
            if opposite is not None and original is None and not bad:
                negated = self._products_opposite(*opposite)
            else:
                negated = minus(expr)
            return minus(self._name(negated, variables, small))
        return self._new_name(expr, variables, original, split=False)

    def _all_rates(self, derivatives: set | frozenset) -> bool:
        """``derivatives <= self.rates``, kept per set of derivatives (most
        are one of the book's kept sets, :meth:`_union`, found by
        identity; a derivative may be an object equal to a rate's but
        not the same, compared by sympy's ``__eq__``)."""
        rates = self.rates
        if type(derivatives) is not frozenset:
            return derivatives <= rates
        if self._rated_for is not rates:
            self._rated, self._rated_for = {}, rates
        found = self._rated.get(derivatives)
        if found is None:
            found = self._rated[derivatives] = derivatives <= rates
        return found

    def _in_parts(self, expr: Any) -> tuple[Any, Any, Any]:
        """``expr`` named in parts (:meth:`_split`), so that a derivative or
        substitution then walks short definitions (a tree walk sees a
        repeated part each time): ``(found, split, original)``, the
        intermediate that already stands for the split form (or None), the
        split form, and ``expr`` if it was split (else None)."""
        small = self._split(expr)
        if small is expr:
            return None, expr, None
        found = self._named.get(small)
        if found is not None:
            self._named[expr] = found
        return found, small, expr

    def _new_name(
        self, expr: Any, variables: set, original: Any, *, split: bool
    ) -> Any:
        """A new intermediate for ``expr`` (over ``variables``), named in
        parts first if ``split``; ``original``: what ``expr`` was split
        from, named by the same intermediate."""
        if split:
            found, expr, split_from = self._in_parts(expr)
            if found is not None:
                return found
            original = split_from if split_from is not None else original
        variables, varset, derivatives = self._shared_variables(variables)
        k = len(self._defs)
        while True:
            self._count += 1
            label = f"{self.prefix}{self._count}"
            if label not in self._taken:
                break
        self._defs.append(expr)
        self._vars.append(variables)
        self._dvars.append(derivatives)
        self._varsets.append(varset)
        self._labels.append(label)
        z = self._new_z(k, variables, varset)
        self._named[expr] = z
        if original is not None:
            self._named[original] = z
        return z

    #: largest definition (in tree nodes) named whole; larger ones are
    #: named in parts, as Autolev's Z's are short.
    LIMIT = 24

    def _split(self, expr: Any) -> Any:
        """``expr`` with each part larger than :attr:`LIMIT` nodes named
        (bottom-up), so that no definition is long."""
        Z = self.Z
        one = self._one_node
        if self._parts_within(expr.args, one):
            return expr  # no part is larger: the walk below changes nothing
        # one memo for every split: a part's answer depends on the part, on
        # what is named already (a part named once is found again by
        # :meth:`name`) and on the rates and excluded quantities, which
        # :meth:`name` reads (a shared part of many large expressions is
        # walked once, not once for each)
        kept = self._parts_for
        if kept is None or kept[0] is not self.rates or kept[1] is not self.exclude:
            self._parts = {}
            self._parts_for = (self.rates, self.exclude)
        memo = self._parts

        def walk(e: Any, top: bool) -> tuple[Any, int]:
            if e.is_Atom or isinstance(e, one):
                return e, 1
            found = memo.get(e)
            if found is not None and not top:
                return found
            args, size, changed = [], 1, []
            for i, a in enumerate(e.args):
                b, n = walk(a, False)  # noqa: F821 - deleted after the walk
                args.append(b)
                size += n
                if b is not a:
                    changed.append(i)
            # (sympy's e.func(*args), formed as substitute forms it)
            new = _rebuilt(e, args, changed) if changed else e
            out = (new, size)
            if (
                not top
                and size > self.LIMIT
                and isinstance(new, sp.Expr)
                and not trivial(new)
            ):
                named = self.name(new)
                if isinstance(named, Z):
                    out = (named, 1)
                elif (-named).func is Z:
                    out = (named, 3)
            if not top:  # (the whole is not named here: not an answer for a part)
                memo[e] = out
            return out

        try:
            return walk(expr, True)[0]
        finally:
            del walk  # it refers to itself: freed now, not by a collection

    def _parts_within(self, parts: tuple, one: tuple) -> bool:
        """Whether each of ``parts`` has at most :attr:`LIMIT` nodes
        (:meth:`_within` of each, in one loop: a part whose arguments are
        all leaves, as most are, is counted without a walk)."""
        limit = self.LIMIT
        for a in parts:
            if a.is_Atom or isinstance(a, one):
                continue
            args = a.args
            if len(args) >= limit:
                return False  # (1 + its arguments > limit)
            for b in args:
                if not (b.is_Atom or isinstance(b, one)):
                    if not self._within(a, limit):
                        return False
                    break
        return True

    def _within(self, e: Any, limit: int) -> bool:
        """Whether ``e`` has at most ``limit`` tree nodes as :meth:`_split`
        counts them (an intermediate, a function of time or a derivative is
        one node), counting no further than ``limit + 1``."""
        one = self._one_node
        if e.is_Atom or isinstance(e, one):
            return limit >= 1
        # a node's arguments are counted when it is met, and only those
        # with arguments of their own are stacked (most are leaves)
        stack = [e]
        n = 1
        while stack:
            args = stack.pop().args
            n += len(args)
            if n > limit:
                return False
            for a in args:
                if not (a.is_Atom or isinstance(a, one)):
                    stack.append(a)
        return True

    def time_rate(self, x: Any) -> Any:
        """``x.diff(t)`` of a variable (None if ``x`` does not depend on
        ``t``), made once per variable."""
        found = self._time_rates.get(x, _UNKNOWN)
        if found is _UNKNOWN:
            found = self._time_rates[x] = x.diff(_T) if x.has(_T) else None
        return found

    def own_variables(self, z: Intermediate) -> frozenset | None:
        """The set of variables of ``z``'s intermediate if ``z`` is taken at
        its own variables (kept on the instance), else None (for
        :meth:`Intermediate.__hash__`: also for an instance whose first
        argument is not the number of one of the book's intermediates)."""
        args = z.args
        first = args[0] if args else None
        if not (
            first is not None and first.is_Integer and 0 < first.p < len(self._defs)
        ):
            return None
        if not self._canonical(z):
            return None
        varset = z.__dict__["_varset"] = self._varsets[first.p]
        return varset

    def _canonical(self, z: Intermediate) -> bool:
        """Whether ``z`` is taken at its own variables (kept per instance:
        neither changes)."""
        found = z.__dict__.get("_canonical")
        if found is None:
            found = tuple(z.args[1:]) == self._vars[_number(z)]
            z.__dict__["_canonical"] = found
        return found

    def _scan(self, expr: Any) -> tuple[set | frozenset, set | frozenset, list]:
        """One walk over ``expr``: the variables it depends on (derivatives,
        functions of time and symbols, each outside the others), the
        derivatives among them, and the intermediates taken elsewhere than
        at their own variables (:meth:`_walk`)."""
        return self._walk(expr)[:3]

    def _walk(
        self, expr: Any
    ) -> tuple[set | frozenset, set | frozenset, list, int | float]:
        """One walk over ``expr``: the variables it depends on (derivatives,
        functions of time and symbols, each outside the others; a canonical
        intermediate's are read off its arguments, not walked into), the
        derivatives among them, and the intermediates taken elsewhere than
        at their own variables (in the order of a depth-first walk).

        A part is classified when it is met as an argument: a variable or
        an atom is only recorded (never stacked), a canonical intermediate
        contributes its set of variables, and only sums, products,
        functions and the other intermediates are walked into.  When every
        variable found is among the canonical intermediates', the sets
        returned are the book's own (frozen, shared) union of theirs
        (:meth:`_union`): callers only read them.

        Last, an upper bound of ``expr``'s size as :meth:`_split` counts it
        (tree nodes, an intermediate, a function of time or a derivative
        one), or infinity when a part was met twice (its second subtree is
        not walked)."""
        #: the variables and derivatives met
        found: set = set()
        among: set = set()
        bad: list = []
        seen: set = set()  # the parts stacked (an equal part: walked once)
        #: the sets of variables of the canonical intermediates met (many
        #: share one, and each is kept as one object: their union is taken
        #: once per combination of sets)
        shared: set = set()
        varsets = self._varsets
        Z = self.Z
        derivative = sp.Derivative
        stack: list = []
        todo: Any = (expr,)
        size: int | float = 0
        while True:
            size += len(todo)
            for a in todo:
                if a.is_Atom:
                    if a.is_Symbol:
                        found.add(a)
                    continue
                if a.is_Mul or a.is_Add:
                    pass  # (most parts: walked into)
                elif isinstance(a, Z):
                    # its set of variables, kept on a canonical instance
                    varset = a.__dict__.get("_varset")
                    if varset is None and self._canonical(a):
                        varset = a.__dict__["_varset"] = varsets[a.args[0].p]
                    if varset is not None:
                        shared.add(varset)
                        continue
                elif isinstance(a, AppliedUndef):
                    found.add(a)
                    continue
                elif isinstance(a, derivative):
                    found.add(a)
                    among.add(a)
                    continue
                if a not in seen:
                    seen.add(a)
                    stack.append(a)
                else:
                    size = math.inf  # (its subtree counted once)
            if not stack:
                break
            e = stack.pop()
            if isinstance(e, Z):
                bad.append(e)  # not canonical: only those are stacked
                todo = e.args[1:]
            else:
                todo = e.args
        if bad:
            # in the order of a walk that meets each distinct part once (an
            # equal copy of a part, another object, is not walked again)
            bad = self._stray(expr)
        return (*self._met(found, among, shared), bad, size)

    def _met(
        self, found: set, among: set, shared: set
    ) -> tuple[set | frozenset, set | frozenset]:
        """:meth:`_walk`'s variables and derivatives, from the variables
        ``found`` outside the canonical intermediates (``among``: the
        derivatives among them) and those intermediates' sets of variables
        ``shared``."""
        if not shared:
            return found, among
        union, within = self._union(shared)
        if not found or found <= union:
            # (the derivatives are among its own)
            return union, within
        # kept per combination (the union is one object per combination
        # of sets, :meth:`_union`; ``among`` is the derivatives in
        # ``found``): the sets returned are then one object for one set,
        # which :meth:`_shared_variables` finds by identity
        key = (frozenset(found), union)
        met = self._mets.get(key)
        if met is None:
            variables = self._one_set(union | found)
            met = self._mets[key] = (variables, within | among if among else within)
        return met

    def _stray(self, expr: Any) -> list:
        """The intermediates in ``expr`` taken elsewhere than at their own
        variables, in the order of a depth-first walk (each distinct part
        once, equal parts being one), for :meth:`_scan`."""
        bad: list = []
        seen: set = set()
        Z = self.Z
        stack = [expr]
        while stack:
            e = stack.pop()
            if isinstance(e, Z):
                if self._canonical(e):
                    continue
                bad.append(e)
                todo = e.args[1:]
            elif e.is_Atom or isinstance(e, _VARIABLE):
                continue
            else:
                todo = e.args
            for a in todo:
                if a not in seen:
                    seen.add(a)
                    stack.append(a)
        return bad

    def _union(self, shared: set) -> tuple[frozenset, frozenset]:
        """The union of the sets of variables ``shared`` (each an
        intermediate's, from :attr:`_varsets`) and the derivatives among
        them: kept per combination of sets (the combination's hash is made
        of its sets' hashes, which Python keeps)."""
        key = frozenset(shared)
        found = self._unions.get(key)
        if found is None:
            if len(key) == 1:
                (union,) = key
                among = frozenset(self._orders[union][2])
            else:
                union = self._one_set(frozenset().union(*key))
                # (the derivatives of each set, kept as a set: no hashing)
                among = frozenset().union(*[self._union({s})[1] for s in key])
            found = self._unions[key] = (union, among)
        return found

    def _one_set(self, variables: frozenset) -> frozenset:
        """The one object kept for the set of variables ``variables``
        (the first met): the book's dicts keyed by sets of variables then
        find it by identity, without comparing its variables (a
        derivative met twice may be two equal objects, compared by
        sympy's ``__eq__``)."""
        return self._sets.setdefault(variables, variables)

    def _shared_variables(self, variables: set) -> tuple[tuple, frozenset, tuple]:
        """``variables`` sorted by ``default_sort_key``, as a set, and the
        derivatives among them: made once per set of variables and shared
        by the intermediates over it (many are over one set)."""
        key = frozenset(variables)
        found = self._orders.get(key)
        if found is None:
            key = self._one_set(key)
            ordered = tuple(sorted(variables, key=self._sort_key))
            derivatives = tuple(a for a in ordered if isinstance(a, sp.Derivative))
            found = self._orders[key] = (ordered, key, derivatives)
        return found

    def _new_z(self, k: int, variables: tuple[Any, ...], varset: frozenset) -> Any:
        """``self.Z(k, *variables)``, made as sympy's ``Application.__new__``
        makes it (``Intermediate.eval`` declines, no argument is a float, so
        nothing is evaluated), without the cache lookup: sympy's cache key
        hashes the class of every function of time among the arguments,
        which costs more than making the object."""
        z = sp.Basic.__new__(self.Z, sp.Integer(k), *variables)
        z.nargs = sp.S.Naturals0
        z.__dict__["_canonical"] = True  # (:meth:`_canonical`: at its own)
        z.__dict__["_varset"] = varset  # (for :meth:`_walk`)
        # _is_commutative's search of the arguments, once per set of
        # variables ``varset`` (the number commutes): many share one
        commutes = self._commutes.get(varset)
        if commutes is None:
            commutes = self._commutes[varset] = all(a.is_commutative for a in variables)
        if commutes:
            z.__dict__["_commutative"] = True
        return z

    def _sort_key(self, x: Any) -> Any:
        """``default_sort_key(x)``, kept; an intermediate's is made from its
        arguments' kept keys, as ``Expr.sort_key`` makes it (class key, the
        arguments' keys, exponent 1's key, coefficient 1)."""
        found = self._keys.get(x)
        if found is None:
            if isinstance(x, self.Z):
                args = x.args
                if self._canonical(x):
                    # its variables' keys, kept per set of variables (many
                    # intermediates share one)
                    varset = self._varsets[args[0].p]
                    keys = self._var_keys.get(varset)
                    if keys is None:
                        keys = self._var_keys[varset] = tuple(
                            [self._sort_key(a) for a in args[1:]]
                        )
                    keys = (self._sort_key(args[0]), *keys)
                else:
                    keys = tuple([self._sort_key(a) for a in args])
                found = (x.class_key(), (len(args), keys), _ONE_KEY, sp.S.One)
            elif x.is_Add or x.is_Mul:
                found = self._compound_key(x)
            else:
                found = sp.default_sort_key(x)
            self._keys[x] = found
        return found

    def _compound_key(self, x: Any) -> Any:
        """``default_sort_key`` of a sum or product, as ``Expr.sort_key``
        makes it, from its parts' kept keys (sympy's walks the whole tree
        each time: most of the cost of a sum's sign, :func:`minus_first`,
        when its factors are sums).  A sum's terms come in the order of
        ``as_ordered_terms``, by their monomials (:func:`as_terms`); sympy's
        own key is taken where that order needs more (a number among the
        terms, two terms with one monomial, a non-commutative part), and for
        a product whose rest is a power, an atom or non-commutative."""
        coeff, expr = x.as_coeff_Mul()
        if expr.is_Add:
            args = expr.args
            if not expr.is_commutative or any(
                a.is_Number or a.is_NumberSymbol or a.is_Order for a in args
            ):
                return sp.default_sort_key(x)
            terms, _ = as_terms(expr, self._sort_key)
            monomials = {monom for _, (_, monom, _) in terms}
            if len(monomials) != len(terms):
                return sp.default_sort_key(x)
            # as_ordered_terms: the largest monomial (lexicographic) first
            ordered = [
                term for term, _ in sorted(terms, key=lambda t: t[1][1], reverse=True)
            ]
        elif expr.is_Mul and expr.is_commutative:
            ordered = sorted(expr.args, key=self._sort_key)
        elif expr.is_Pow or expr.is_Atom or not expr.is_commutative:
            return sp.default_sort_key(x)
        else:
            ordered = expr.args
        keys = tuple([self._sort_key(a) for a in ordered])
        return expr.class_key(), (len(keys), keys), _ONE_KEY, coeff

    def rebase(self, expr: Any) -> Any:
        """``expr`` with each intermediate that is taken elsewhere than at its
        own variables (a variable was substituted, e.g. a dependent speed by
        its expression) replaced by an intermediate of its own, so numeric
        code evaluates every intermediate once."""
        bad = self._scan(expr)[2]
        return self._rebase(expr, bad) if bad else expr

    def _rebase(self, expr: Any, bad: Iterable[Any]) -> Any:
        allow_deep_recursion()
        rule = {}
        for z in bad:
            found = self._rebased.get(z)
            if found is None:
                found = self._rebased[z] = self.name(self.definition(z))
            rule[z] = found
        return substitute(expr, rule)

    def _name_rates(self, expr: Any) -> Any:
        """:meth:`name`, and for an expression with derivatives that are not
        :attr:`rates` (accelerations a ``Solve`` does not solve for), its
        coefficients of them and the rest named (:meth:`name_linear`)."""
        expr = sp.sympify(expr)
        derivatives = self._scan(expr)[1] - self.rates if not trivial(expr) else ()
        if not derivatives:
            return self.name(expr)
        return self.name_linear(expr, sorted(derivatives, key=sp.default_sort_key))

    def name_linear(self, expr: Any, xs: Sequence[Any]) -> Any:
        """``expr = rest + sum(c_k * x_k)`` with ``rest`` and each ``c_k``
        named, so that the terms in ``xs`` (speeds, their derivatives) stay
        visible; an expression not linear in ``xs`` is named whole."""
        whole, present, coefs, rest = self._name_linear_parts(expr, xs)
        if whole is not None:
            return whole
        return rest + sp.Add(*[c * x for c, x in zip(coefs, present, strict=True)])

    def _name_linear_parts(self, expr: Any, xs: Sequence[Any]) -> tuple:
        """:meth:`name_linear`'s naming: ``(whole, present, coefficients,
        rest)``, ``whole`` the result when ``expr`` is named whole (or kept:
        not linear), else None and the ``xs`` present in ``expr`` (in the
        order of ``xs``, then the ``ZEE_NOT`` quantities), their named
        coefficients and the named rest (named first, as ever)."""
        expr = sp.sympify(expr)
        found = appearing(expr, xs)
        present = [x for x in xs if x in found]
        if not present:
            return self.name(expr), None, None, None
        if any(x in self.exclude for x in present):
            more = appearing(expr, [x for x in self.exclude if x not in present])
            present += [x for x in self.exclude if x in more]
        split = self.linear_split(expr, present)
        if split is None:
            return expr, None, None, None  # not linear: keep it as it is
        coefs, rest = split
        rest = self.name(rest)
        return None, present, [self.name(c) for c in coefs], rest

    def name_linear_terms(
        self, expr: Any, xs: Sequence[Any]
    ) -> tuple[list[Any], Any] | None:
        """``linear_terms(self.name_linear(expr, xs), xs)``, the same
        coefficients and rest (and the same intermediates, made in the same
        order), read off the named parts without forming their sum where
        that sum's terms are plainly ``rest`` and ``c_k * x_k``: the rest
        and each coefficient a rational number, an intermediate or a
        rational multiple of one, none holding an ``x`` (as :func:`linear_terms`
        would find it), and the ``xs`` distinct."""
        whole, present, coefs, rest = self._name_linear_parts(expr, xs)
        if whole is not None:
            return linear_terms(whole, xs)
        wanted = frozenset(xs)
        if (
            len(wanted) == len(xs)
            and wanted.issuperset(present)
            and self._plain_named(rest, wanted)
            and all(self._plain_named(c, wanted) for c in coefs)
        ):
            by_x = dict(zip(present, coefs, strict=True))
            return [by_x.get(x, sp.S.Zero) for x in xs], rest
        terms = [c * x for c, x in zip(coefs, present, strict=True)]
        return linear_terms(rest + sp.Add(*terms), xs)

    def _plain_named(self, e: Any, wanted: frozenset) -> bool:
        """Whether ``e`` (a named part) is a rational number, an
        intermediate or a rational times one, holding none of ``wanted``: a
        term of its own in a sum (a coefficient, with its ``x``), which
        :func:`linear_terms` reads back as it is."""
        if e.is_Rational:
            return True
        if e.is_Mul and len(e.args) == 2 and e.args[0].is_Rational:
            e = e.args[1]
        return isinstance(e, self.Z) and wanted.isdisjoint(e.walk_parts())

    def linear_split(
        self, expr: Any, xs: Sequence[Any], direct: bool = True
    ) -> tuple[list[Any], Any] | None:
        """``expr = rest + sum(c_k * x_k)`` as ``(coefficients, rest)``, none
        of them holding an ``x`` (None when ``expr`` is not linear in
        ``xs``): :meth:`name_linear`'s split, nothing named.

        The split is read over placeholders (each ``x`` a symbol of its
        own): term by term (:func:`linear_terms`), through sums and products
        (:func:`_linear_parts`), or by differentiating.  Where each ``x``
        occurs only as a term or a factor of sums and products (most
        velocities), it is read from ``expr`` directly, with the same
        answer and no substitution (``direct=False`` always substitutes):
        the substitution is one to one and changes no other part, so the
        same terms and factors are read, and sympy's sums and products of
        them do not depend on their order."""
        if direct:
            split = linear_terms(expr, xs)
            if split is None:
                split = _linear_parts(expr, xs)
            if split is not None:
                return split
        plain = [sp.Dummy() for _ in xs]
        held = self._held_derivatives(expr, xs)
        if held:  # each a variable of its own while the xs are placeholders
            expr = substitute(expr, held)
        w = substitute(expr, dict(zip(xs, plain, strict=True)))
        split = self._placeholder_split(w, plain)
        if split is None or not held:
            return split
        back = {h: d for d, h in held.items()}
        coefs, rest = split
        return [substitute(c, back) for c in coefs], substitute(rest, back)

    def _held_derivatives(self, expr: Any, xs: Sequence[Any]) -> dict:
        """A placeholder for each derivative in ``expr`` of one of ``xs``
        that is not itself among them (``u1'`` when splitting by ``u1``):
        putting a symbol for ``u1`` inside ``Derivative(u1, t)`` would make
        it ``Derivative(p, t)``, zero, and lose the term (Kane's method
        holds a speed and its rate as independent variables)."""
        derivatives = self._scan(expr)[1]
        if not derivatives:
            return {}
        xset = set(xs)
        found = [d for d in derivatives if d not in xset and d.has(*xs)]
        found.sort(key=self._sort_key)
        return {d: sp.Dummy() for d in found}

    def _placeholder_split(self, w: Any, plain: list) -> tuple | None:
        """:meth:`linear_split` of ``w`` by the symbols ``plain``."""
        split = linear_terms(w, plain)
        if split is not None:
            coefs, rest = split
            if any(appearing(c, plain) for c in coefs) or appearing(rest, plain):
                return None
        elif (split := _linear_parts(w, plain)) is not None:
            coefs, rest = split  # no x in the coefficients or the rest
        else:
            coefs = []
            for p in plain:
                c = self._pd(w, p, {})  # one memo per variable
                if appearing(c, plain):
                    return None  # not linear (found early)
                coefs.append(c)
            rest = substitute(w, dict.fromkeys(plain, sp.S.Zero))
            if appearing(rest, plain):
                return None
        return coefs, rest

    def label(self, z: Intermediate) -> str:
        k = _number(z)
        if self._canonical(z):
            return self._labels[k]
        return self._labels[k] + "(" + ", ".join(str(a) for a in z.args[1:]) + ")"

    def label_of(self, k: int) -> str:
        """Intermediate number ``k``'s name (``Z12``), at its own variables."""
        return self._labels[k]

    def canonical(self, k: int) -> tuple[tuple[Any, ...], Any]:
        """Intermediate number ``k``'s own variables and its definition over
        them."""
        return self._vars[k], self._defs[k]

    def definition(self, z: Intermediate) -> Any:
        """What ``z`` stands for, at its own arguments (one level)."""
        k = _number(z)
        body = self._defs[k]
        if self._canonical(z):
            return body
        found = self._elsewhere.get(z)
        if found is None:
            found = self._elsewhere[z] = substitute(
                body, dict(zip(self._vars[k], z.args[1:], strict=True))
            )
        return found

    def is_real(self, z: Intermediate) -> bool | None:
        k = _number(z)
        if k not in self._real:
            self._real[k] = None  # guards recursion
            self._busy.add(k)
            try:
                body = self._defs[k]
                self._real[k] = True if self._visibly_real(body) else body.is_real
            finally:
                self._busy.discard(k)
        return self._real[k]

    def _visibly_real(self, e: Any) -> bool:
        """True when ``e`` is real by its shape: real numbers, symbols and
        functions of time, real intermediates, and sums, products, rational
        powers, sines, cosines and tangents of such.  (A quotient, a square
        root or a tangent is real where it is defined in the reals, which is
        where Autolev evaluated it: its quantities are real, and its
        programs take ``sqrt`` of a negative number as an error.)  False
        means "ask sympy", whose search through the related facts is most of
        the cost of an intermediate's assumptions."""
        stack, seen = [e], set()
        while stack:
            x = stack.pop()
            if x in seen:
                continue
            seen.add(x)
            if isinstance(x, Intermediate):
                if x.book.is_real(x) is not True:
                    return False
            elif x.is_Add or x.is_Mul:
                stack.extend(x.args)
            elif x.is_Pow:
                if not x.exp.is_Rational:
                    return False
                stack.append(x.base)
            elif isinstance(x, _TRIG):
                stack.append(x.args[0])
            elif x.is_Number or x.is_Symbol or isinstance(x, AppliedUndef):
                if x.is_real is not True:
                    return False
            else:
                return False
        return True

    def facts(self, z: Intermediate) -> Any:
        """Every assumption of ``z`` (``None`` where unknown), or ``None`` to
        ask sympy.

        sympy derives an intermediate's assumptions from its handlers:
        ``real`` (:meth:`is_real`, by number), ``commutative`` (its
        arguments) and the sign by ``evalf`` when it is a number.  For an
        instance whose arguments are commutative and not all numbers, the
        answers are therefore those deduced from ``commutative`` and
        ``real``, the same for every instance of the number: found once
        here, rather than by sympy's search through the related facts on
        each new instance (it never stores what stays unknown)."""
        args = z.args[1:]
        if not all(a.is_commutative for a in args) or all(a.is_number for a in args):
            return None
        k = _number(z)
        table = self._facts.get(k)
        if table is None:
            real = self.is_real(z)
            if k in self._busy:
                return None
            known = [("commutative", True)]
            if real is not None:
                known.append(("real", real))
            table = StdFactKB()
            table.deduce_all_facts(known)
            for fact in _assume_defined:
                if fact not in table:
                    dict.__setitem__(table, fact, None)
            self._facts[k] = table
        return table

    # -------------------------------------------------------- derivatives

    def partial(self, z: Intermediate, j: int) -> Any:
        """``d z / d var_j`` (named), at ``z``'s own arguments.

        Most definitions are sums of products of intermediates: their
        derivative is formed, and named, by :meth:`_products_pd`."""
        k = z.args[0].p  # (_number)
        key = (k, j)
        found = self._partials.get(key)
        if found is None:
            x = self._vars[k][j]
            memo = self._pd_memos.get(x)
            if memo is None:
                memo = self._pd_memos[x] = {}
            body = self._defs[k]
            formed = None if body in memo else self._products_pd(body, x, memo)
            if formed is None:
                found = self.name(self._pd(body, x, memo))
            else:
                d, walked = formed
                memo[body] = d
                found = self._named.get(d) if walked else None
                if found is None:
                    found = self._name_walked(d, *walked) if walked else self.name(d)
            self._partials[key] = found
        canonical = z.__dict__.get("_canonical")  # (kept by _canonical)
        if canonical is None:
            canonical = self._canonical(z)
        if not canonical:
            args = tuple(z.args[1:])
            found = found.xreplace(dict(zip(self._vars[k], args, strict=True)))
        return found

    def _products_pd(self, e: Any, x: Any, memo: dict) -> tuple[Any, tuple] | None:
        """:meth:`_pd` of ``e`` by ``x`` when ``e`` is a sum of products (or
        one product) of rational numbers and plain factors (:meth:`_plain_key`:
        canonical intermediates, symbols, ...; most definitions are), with
        what :meth:`_walk` finds in the derivative when it is a sum (else
        ``()``): ``(derivative, walked)``.  None when ``e`` is not such a
        sum, or a factor's derivative is not a rational number times one
        such factor, or would square a factor, or leave a sum alone with a
        number.  A factor may also be a sum of such products
        (:meth:`_sum_key`; its derivative is taken by :meth:`_pd_new`):
        a derivative with a sum among its factors comes with ``()``, to be
        walked when it is named, as the long way names it.

        The chain rule's products are written as their factors' tuples
        (:meth:`_plain_key`: tuples that order as ``Basic.compare`` orders
        these factors), like ones collected by them, and the terms ordered
        by their tuples; each product and the sum are then formed once, as
        :func:`product_with` and :func:`total` form them (no sum per
        product, no comparison of sympy objects).  What does not depend on
        ``x`` (the terms' factors and tuples, each factor's rest and what
        :meth:`_walk` finds in it) is found once per definition
        (:meth:`_products_plan`): a definition is differentiated by each of
        its variables.  The factors' derivatives are taken in the order of
        :meth:`_pd`'s walk (each distinct factor at its first place), so
        that the intermediates named on the way get the same numbers; when
        the shortcut then declines, :meth:`_pd` finds them in ``memo``."""
        if not (e.is_Add or e.is_Mul) or not global_parameters.evaluate:
            return None
        plan = self._plans.get(e, _UNKNOWN)
        if plan is _UNKNOWN:
            plan = self._plans[e] = self._products_plan(e)
        if plan is None:
            return None
        order, places = plan
        one = sp.S.One
        key_of = self._plain_key
        z_type = self.Z
        varsets = self._varsets
        number = _ZERO
        #: the factors' keys -> [coefficient, factors, the rest's facts,
        #: the new factors' facts]
        collected: dict[tuple, list] = {}
        # only the factors that hold x (an intermediate over it, a sine of
        # it, x itself, a power of one): the others' derivatives are 0, and
        # name nothing
        xi = self._ids.get(x)
        bisect_left = bisect.bisect_left
        new_z = False
        for at_factor, (f, kind, held) in enumerate(order):
            if held is not None:
                j = held.get(xi)
                if j is None:
                    continue
            if kind == _PLAN_Z:
                d = memo.get(f)
                if d is None:
                    # _pd_new of a canonical intermediate of this book
                    d = memo[f] = self.partial(f, j)
            elif kind == _PLAN_OTHER:
                d = one
            else:  # a sine or cosine, a sum, a power: as _pd takes it
                d = memo.get(f)
                if d is None:
                    d = self._pd_new(f, x, memo, None, None)
            if d is _ZERO:
                continue
            if d.is_Rational:
                n, news, new_z = d, (), False
            else:
                n, new, new_z = one, d, False
                if d.is_Mul:
                    args = d.args
                    if len(args) == 2 and args[0].is_Rational:
                        n, new = args
                    else:
                        # several factors (a power's derivative)
                        many = self._new_factors(d)
                        if many is None:
                            return None
                        n, news, new_keys, facts = many
                        new = None
                if new is not None:
                    new_z = type(new) is z_type
                    if new_z:
                        # (:meth:`_plain_key`, read where it keeps it)
                        new_key = new.__dict__.get("_plain_key", _UNKNOWN)
                        if new_key is _UNKNOWN:
                            new_key = key_of(new)
                    else:
                        new_key = key_of(new)
                    if new_key is None:
                        return None
                    news, new_keys = (new,), (new_key,)
                    # (_base_key and _factor_facts, without the calls for
                    # an intermediate, most new factors: its tuple ends
                    # with its number)
                    if new_z:
                        new_base = new_key
                        facts = (varsets[new_key[2]], None, None)
                    else:
                        new_base = new_key
                        if new_key[0] == _POW_PLACE:
                            new_base = new_key[2]
                        facts = self._factor_facts(new)
            if new_z:
                # (the common case, as below: one new intermediate, its own
                # base, inserted among the rest unless a factor has its base)
                for c, rest, rest_keys, rest_facts, bases in places[at_factor]:
                    coeff = n if c is one else c if n is one else c * n
                    if bases is None:  # no power among the rest: its bases
                        at = bisect_left(rest_keys, new_key)
                        if at < len(rest_keys) and rest_keys[at] == new_key:
                            at = -1  # a common base: they combine
                    elif new_key in bases:
                        at = -1
                    else:
                        at = bisect_left(rest_keys, new_key)
                    if at >= 0:
                        if not rest:
                            rest_keys, rest = new_keys, news
                        elif len(rest) == 1:
                            if at:
                                rest_keys, rest = (rest_keys[0], new_key), (
                                    rest[0],
                                    new,
                                )
                            else:
                                rest_keys, rest = (new_key, rest_keys[0]), (
                                    new,
                                    rest[0],
                                )
                        else:
                            rest_keys = (*rest_keys[:at], new_key, *rest_keys[at:])
                            rest = (*rest[:at], new, *rest[at:])
                        entry = [coeff, rest, rest_facts, facts]
                    else:
                        merged = self._merged_entry(
                            coeff, rest, rest_keys, bases, news, new_keys
                        )
                        if merged is None:
                            return None
                        entry, rest_keys = merged
                        rest = entry[1]
                        if not rest:
                            number += coeff
                            continue
                        if len(rest) == 1 and rest[0].is_Add:
                            return None
                    found = collected.setdefault(rest_keys, entry)
                    if found is not entry:
                        found[0] += coeff
                continue
            for c, rest, rest_keys, rest_facts, bases in places[at_factor]:
                coeff = n if c is one else c if n is one else c * n
                if not news:
                    entry = [coeff, rest, rest_facts, None]
                    at = -1
                elif new is None:
                    at = -1  # several new factors
                elif bases is None:  # no power among the rest: its bases
                    at = bisect_left(rest_keys, new_base)
                    if at < len(rest_keys) and rest_keys[at] == new_base:
                        at = -1  # a common base: they combine
                    elif new_base is not new_key:
                        at = bisect_left(rest_keys, new_key)
                elif new_base in bases:
                    at = -1
                else:
                    at = bisect_left(rest_keys, new_key)
                if at >= 0:
                    # the common case: one new factor of its own base
                    rest_keys = (*rest_keys[:at], new_key, *rest_keys[at:])
                    rest = (*rest[:at], new, *rest[at:])
                    entry = [coeff, rest, rest_facts, facts]
                elif news:
                    merged = self._merged_entry(
                        coeff, rest, rest_keys, bases, news, new_keys
                    )
                    if merged is None:
                        return None
                    entry, rest_keys = merged
                    rest = entry[1]
                if not rest:
                    number += entry[0]
                    continue
                if len(rest) == 1 and rest[0].is_Add:
                    # a sum alone, times a number: sympy distributes it
                    # (or adds its terms to the sum)
                    return None
                found = collected.setdefault(rest_keys, entry)
                if found is not entry:
                    found[0] += entry[0]
        keyed = []
        kept = []
        for fkeys, entry in collected.items():
            coeff = entry[0]
            if coeff is _ZERO:
                continue
            kept.append(entry)
            keyed.append(self._keyed_term(coeff, entry[1], fkeys))
        keyed.sort(key=_KEY)
        terms = [args[0] if len(args) == 1 else _product(args) for _, args in keyed]
        if number is not _ZERO:
            terms.insert(0, number)
        if len(terms) < 2:
            if not terms:
                return _ZERO, ()
            d = terms[0]
            # one product of two factors or more (not a number, nor one
            # factor, nor trivial: named the long way): walked as a sum's
            # term is, below, without the sum
            if number is not _ZERO or len(keyed[0][1]) < 2 or trivial(d):
                return d, ()
            size: int | float = 1
        else:
            d = sp.Add._from_args(terms, is_commutative=True)
            size = 1 + len(terms)
        # :meth:`_walk`: each product's arguments are met once (the terms
        # are distinct), and a sine's or power's (its arguments) unless it
        # was met before; variables are recorded, a canonical intermediate
        # brings its set of variables (read off each rest's facts and the
        # new factors')
        found_vars, among, shared, seen = set(), set(), set(), set()
        short = True
        limit = self.LIMIT
        for coeff, rest, rest_facts, facts in kept:
            if rest_facts is None or facts is _SUM_FACTS:
                return d, ()  # a sum among the factors: walked when named
            r_shared, r_found, r_among, r_stacked, extra = rest_facts
            shared |= r_shared
            found_vars |= r_found
            among |= r_among
            for f in r_stacked:
                if f in seen:
                    size = math.inf
                seen.add(f)
            if facts is None:
                pass
            elif len(facts) == 3:  # one plain factor (:meth:`_factor_facts`)
                varset, variable, sine = facts
                if varset is not None:
                    shared.add(varset)
                else:
                    found_vars.add(variable)
                    if sine is not None:
                        extra += 1
                        if sine in seen:
                            size = math.inf
                        seen.add(sine)
                    elif type(variable) is sp.Derivative:
                        among.add(variable)
            else:
                f_shared, f_found, f_among, f_stacked, f_extra = facts
                shared |= f_shared
                found_vars |= f_found
                among |= f_among
                extra += f_extra
                for f in f_stacked:
                    if f in seen:
                        size = math.inf
                    seen.add(f)
            n = len(rest) if coeff is one else len(rest) + 1  # its arguments
            if n > 1:
                size += n
            size += extra
            if n + extra >= limit:
                short = False
        if len(terms) < 2:
            # a product's parts are its factors, none larger than
            # :attr:`LIMIT`; its sign is its rational coefficient's (sympy's
            # could_extract_minus_sign: a finite product is not its negation)
            c = keyed[0][1][0]
            return d, (
                *self._met(found_vars, among, shared),
                [],
                size,
                c.is_Rational and c.p < 0,
                True,
                None,
            )
        sign = self._products_sign(keyed, number)
        return d, (
            *self._met(found_vars, among, shared),
            [],
            size,
            sign,
            short,
            (collected, number) if sign else None,
        )

    def _products_opposite(self, collected: dict, number: Any) -> Any:
        """``minus(d)`` of the sum ``d`` that :meth:`_products_pd` formed
        from the terms ``collected`` (the factors' tuples -> [coefficient,
        factors, ...]) and ``number``: each coefficient negated, the terms
        ordered by their tuples as :meth:`_products_pd` orders ``d``'s
        (:func:`minus` negates each term by its coefficient and sorts the
        terms by ``Basic.compare``, which the tuples follow)."""
        keyed = [
            self._keyed_term(-entry[0], entry[1], fkeys)
            for fkeys, entry in collected.items()
            if entry[0] is not _ZERO
        ]
        keyed.sort(key=_KEY)
        terms = [args[0] if len(args) == 1 else _product(args) for _, args in keyed]
        if number is not _ZERO:
            terms.insert(0, -number)
        return sp.Add._from_args(terms, is_commutative=True)

    def _keyed_term(self, coeff: Any, rest: tuple, fkeys: tuple) -> tuple:
        """The term ``coeff`` times the factors ``rest`` (not zero; ``fkeys``:
        the factors' keys) as :meth:`_products_pd` sorts a sum's terms: its
        key (``Basic.compare``'s order) and its arguments (one factor alone,
        or a product's, the coefficient first unless it is 1)."""
        if coeff is sp.S.One:
            if len(rest) == 1:
                return fkeys[0], rest
            args, akeys = rest, fkeys
        else:
            coeff_keys = self._coeff_keys
            coeff_id = (type(coeff), coeff.p, coeff.q)
            coeff_key = coeff_keys.get(coeff_id)
            if coeff_key is None:
                coeff_key = coeff_keys[coeff_id] = _plain_atom_key(coeff)
            args, akeys = (coeff, *rest), (coeff_key, *fkeys)
        return (_MUL_PLACE, len(args), *akeys), args

    def _merged_entry(
        self,
        coeff: Any,
        rest: tuple,
        rest_keys: tuple,
        bases: Any,
        news: tuple,
        new_keys: tuple,
    ) -> tuple[list, tuple] | None:
        """A term of :meth:`_products_pd` whose new factors share a base with
        the rest's (:meth:`_merged`): ``(entry, its factors' keys)``, the
        entry as the chain rule's others (coefficient, factors, their walk
        facts, no new factor's facts); None when :meth:`_merged` declines."""
        merged = self._merged(rest, rest_keys, bases, news, new_keys)
        if merged is None:
            return None
        rest, rest_keys = merged
        return [coeff, rest, self._rest_facts(rest), None], rest_keys

    def _new_factors(self, d: Any) -> tuple | None:
        """The product ``d`` (a power's derivative by the chain rule) as
        :meth:`_products_pd` takes a factor's derivative: its rational
        coefficient, its other factors, their tuples (:meth:`_plain_key`)
        and their walk facts (:meth:`_factor_facts`); None when a factor
        has no tuple."""
        args = d.args
        n = sp.S.One
        if args[0].is_Rational:
            n, args = args[0], args[1:]
        if not d.is_commutative:
            return None
        keys = []
        for a in args:
            key = self._plain_key(a)
            if key is None:
                return None
            keys.append(key)
        facts = self._rest_facts(args)
        return n, args, tuple(keys), _SUM_FACTS if facts is None else facts

    def _factor_facts(self, f: Any) -> Any:
        """What :meth:`_walk` finds in the one new factor ``f``: for an
        intermediate, ``(its set of variables, None, None)``; for a sine or
        cosine ``(None, its argument, itself)``; for a power
        :meth:`_rest_facts`; for another plain factor ``(None, itself,
        None)``; :data:`_SUM_FACTS` for a sum or a power of one."""
        kind = type(f)
        if kind is self.Z:
            return (self._varsets[f.args[0].p], None, None)
        if kind in _TRIG_OF:
            return _SUM_FACTS if f.args[0].is_Add else (None, f.args[0], f)
        if kind is sp.Pow:
            found = self._rest_facts((f,))
            return _SUM_FACTS if found is None else found
        if f.is_Add:
            return _SUM_FACTS
        return (None, f, None)

    def _merged(
        self, rest: tuple, rest_keys: tuple, bases: dict, news: tuple, new_keys: tuple
    ) -> tuple[tuple, tuple] | None:
        """The factors ``rest`` (tuples ``rest_keys``, ``bases``: the
        places of their bases' tuples) times the factors ``news`` (tuples
        ``new_keys``), none numbers, as ``Mul.flatten`` forms the product:
        the exponents of a common base added (``b*b`` is ``b**2``, ``b**-1*b``
        is 1, ``b**-2*b`` is ``b**-1``), each power formed by ``Pow``, and
        the factors sorted by their tuples.  ``(factors, tuples)``; None when
        sympy's power is not ``Pow(base, exponent)`` itself, or has no
        tuple."""
        rest, rest_keys = list(rest), list(rest_keys)
        key_of = self._plain_key
        for new, new_key in zip(news, new_keys, strict=True):
            base_key = _base_key(new_key)
            at = None
            if bases is None or base_key in bases:
                for at, key in enumerate(rest_keys):  # noqa: B007 - used below
                    if _base_key(key) == base_key:
                        break
                else:
                    at = None
            if at is not None:
                old = rest[at]
                del rest[at], rest_keys[at]
                base, e = old.args if type(old) is sp.Pow else (old, sp.S.One)
                e = e + (new.args[1] if type(new) is sp.Pow else sp.S.One)
                if e.is_zero:
                    continue
                if e is sp.S.One:
                    new = base
                else:
                    new = sp.Pow(base, e)
                    if type(new) is not sp.Pow or new.args != (base, e):
                        return None
                new_key = key_of(new)
                if new_key is None:
                    return None
            at = bisect.bisect_left(rest_keys, new_key)
            if at < len(rest_keys) and rest_keys[at] == new_key:
                return None
            rest.insert(at, new)
            rest_keys.insert(at, new_key)
            bases = {_base_key(key) for key in rest_keys}
        return tuple(rest), tuple(rest_keys)

    def _products_plan(self, e: Any) -> tuple[tuple, tuple] | None:
        """What :meth:`_products_pd` needs of the sum of products ``e``
        whatever the variable (kept per definition): ``(order, places)``.
        ``order``: the distinct factors, in the order of :meth:`_pd`'s
        walk, each with its kind (a canonical intermediate, a sine or
        cosine, a sum or a power, or another plain factor) and the numbers
        (:attr:`_ids`) of the variables it holds, each with its place among
        an intermediate's arguments (:meth:`position`; -1 for another
        factor): its derivative by another variable is 0 (None: taken by
        every variable).  ``places``: for each factor, its places in the
        terms, as the term's rational coefficient, the other factors and
        their tuples (:meth:`_plain_key`), what :meth:`_walk` finds in
        those (:meth:`_rest_facts`) and the set of their bases' tuples
        (:func:`_base_key`).  None when a factor has no tuple."""
        one = sp.S.One
        key_of = self._plain_key
        z_type = self.Z
        kept_facts = self._kept_facts
        index: dict[Any, int] = {}
        order: list = []
        places: list[list] = []
        for term in e.args if e.is_Add else (e,):  # (a product: its one term)
            if term.is_Rational:
                continue
            c, factors = one, (term,)
            if term.is_Mul:
                factors = term.args
                if factors[0].is_Rational:
                    c, factors = factors[0], factors[1:]
            keys = tuple(
                [
                    (
                        f.__dict__.get("_plain_key", _UNKNOWN)
                        if type(f) is z_type
                        else _UNKNOWN
                    )
                    for f in factors
                ]
            )
            if _UNKNOWN in keys:
                keys = tuple([key_of(f) for f in factors])
            if None in keys:
                return None
            # (a power among the factors: the places of the others' bases
            # are kept, else None: their bases are their own)
            powers = False
            for f in factors:
                if type(f) is sp.Pow:
                    powers = True
                    break
            for i, f in enumerate(factors):
                at = index.get(f)
                if at is None:
                    at = index[f] = len(order)
                    places.append([])
                    if type(f) is z_type:
                        kind, held = _PLAN_Z, self._variable_places(f)
                    elif f.is_Add:
                        # (its derivative is taken by every variable: 0
                        # when it holds none, naming nothing)
                        kind, held = _PLAN_SUM, None
                    elif type(f) is sp.Pow:
                        # (taken as _pd takes it, by its base's variables)
                        kind, held = _PLAN_SUM, self._held(f.args[0])
                    elif type(f) in _TRIG_OF:
                        kind, held = _PLAN_SINE, self._held(f)
                    else:
                        kind, held = _PLAN_OTHER, self._held(f)
                    order.append((f, kind, held))
                rest = factors[:i] + factors[i + 1 :]
                rest_keys = keys[:i] + keys[i + 1 :]
                bases = None
                if powers:
                    bases = frozenset([_base_key(key) for key in rest_keys])
                facts = kept_facts.get(rest, _UNKNOWN)
                if facts is _UNKNOWN:
                    facts = kept_facts[rest] = self._rest_facts(rest)
                places[at].append((c, rest, rest_keys, facts, bases))
        return tuple(order), tuple(map(tuple, places))

    def _held(self, f: Any) -> dict[int, int] | None:
        """For :meth:`_products_plan`: the variables the plain factor ``f``
        holds, by their numbers (:attr:`_ids`), each with its place among
        an intermediate's arguments (-1 for a sine's argument or a
        variable itself); None for a sum (every variable)."""
        if type(f) is self.Z:
            return self._variable_places(f)
        a = f.args[0] if type(f) in _TRIG_OF else f
        if a.is_Add:
            return None
        ids = self._ids
        return {ids.setdefault(a, len(ids)): -1}

    def _variable_places(self, z: Intermediate) -> dict[int, int]:
        """The places of the canonical intermediate ``z``'s variables among
        its arguments (:meth:`position`), by the variables' numbers
        (:attr:`_ids`): kept per set of variables (many intermediates share
        one), so that a variable is looked up by its number."""
        varset = self._varsets[z.args[0].p]
        found = self._varset_ids.get(varset)
        if found is None:
            ids = self._ids
            found = {ids.setdefault(a, len(ids)): j for j, a in enumerate(z.args[1:])}
            self._varset_ids[varset] = found
        return found

    def _rest_facts(self, rest: tuple) -> tuple | None:
        """What :meth:`_walk` finds in the plain factors ``rest`` (no
        number among them), for :meth:`_products_plan`: the sets of
        variables of the intermediates, the variables (a sine's or
        cosine's argument, a power's base), the derivatives among them,
        the parts the walk stacks (sines, cosines and powers, and a
        power's sine or cosine) and their count of nodes beyond the
        factors themselves; None when a sum is among them (a derivative
        with it is walked when it is named)."""
        z_type = self.Z
        varsets = self._varsets
        shared, found, among, stacked = set(), set(), set(), []
        extra = 0
        for f in rest:
            if type(f) is sp.Pow:
                stacked.append(f)
                extra += 2  # (its base and exponent; a rational: an atom)
                f = f.args[0]
            if f.is_Add:
                return None  # (walked when the derivative is named)
            if type(f) is z_type:
                shared.add(varsets[f.args[0].p])
            elif type(f) in _TRIG_OF:
                a = f.args[0]
                if a.is_Add:
                    return None  # (walked when the derivative is named)
                stacked.append(f)
                extra += 1
                found.add(a)
            else:
                found.add(f)
                if type(f) is sp.Derivative:
                    among.add(f)
        return (
            frozenset(shared),
            frozenset(found),
            frozenset(among),
            tuple(stacked),
            extra,
        )

    def _products_sign(self, keyed: list, number: Any) -> bool | None:
        """:func:`minus_first` of a sum of :meth:`_products_pd`'s
        ``(key, args)`` terms and ``number``: more negative terms than
        positive ones, or on a tie the sign of the first term of
        ``as_ordered_terms`` (:func:`_first_term`).  The terms' monomials
        are their sets of factors, each to the power 1, ordered by
        ``default_sort_key``: the class's key, then for a symbol its name,
        for an intermediate its count of arguments and its number, for
        another factor its whole key.  The first term is the one whose
        least generator that is not in every term it is compared with is
        its own: the least of the terms' sorted generators, with an end
        mark after all.  None (ask :func:`minus_first`) on a tie with a
        number, or when two symbols share a name or another factor's class
        key is the intermediates' (their keys would tie)."""
        signs = [args[0].is_Rational and args[0].p < 0 for _, args in keyed]
        negative = sum(signs)
        n = len(keyed)
        if number is not _ZERO:
            negative += number.p < 0
            n += 1
        if 2 * negative != n:
            return 2 * negative > n
        if number is not _ZERO:
            return None
        z_type, z_class = self.Z, self.Z.class_key()
        generators = []
        symbols: dict[str, Any] = {}
        for _, args in keyed:
            keys = []
            for f in args:
                if type(f) is sp.Symbol:
                    if symbols.setdefault(f.name, f) != f:
                        return None
                    keys.append((_SYMBOL_CLASS, f.name))
                elif type(f) is z_type:
                    f_args = f.args
                    if len(f_args) == 1:
                        return None  # (a number to sympy's as_terms)
                    keys.append((z_class, len(f_args), f_args[0].p))
                elif type(f) is sp.Pow:
                    return None  # (a generator with an exponent)
                elif not f.is_Rational:
                    key = self._sort_key(f)
                    if key[0] == z_class or key[0] == _SYMBOL_CLASS:
                        return None
                    keys.append((key[0], key))
            keys.sort()
            keys.append(_END)
            generators.append(keys)
        first = min(range(len(keyed)), key=generators.__getitem__)
        return signs[first]

    def _plain_key(self, f: Any) -> tuple | None:
        """For :meth:`_products_pd`: a tuple that orders as ``Basic.compare``
        among rational numbers and the factors :func:`_plain_factor_key`
        takes, and this book's canonical intermediates (an intermediate's
        number and its variables' count decide, as :func:`_compare` finds),
        equal for equal factors; None for another factor (kept per factor
        but an intermediate's)."""
        if type(f) is self.Z:
            found = f.__dict__.get("_plain_key", _UNKNOWN)  # kept per instance
            if found is _UNKNOWN:
                args = f.args
                found = None
                if self._canonical(f) and f.is_commutative:
                    found = (self._z_place, len(args), args[0].p)
                f.__dict__["_plain_key"] = found
            return found
        found = self._plain_keys.get(f)
        if found is None and f not in self._plain_keys:
            if f.is_Add:
                found = self._sum_key(f)
            elif type(f) in _TRIG_OF:
                found = self._trig_key(f)
            elif type(f) is sp.Pow:
                found = self._power_key(f)
            else:
                found = _plain_factor_key(f)
            self._plain_keys[f] = found
        return found

    def _trig_key(self, f: Any) -> tuple | None:
        """:meth:`_plain_key` of a sine, cosine or tangent: the tuple of a
        function of one argument (its class's place, 1 and its argument's
        tuple), for an argument that is a symbol, a function of time (as
        :func:`_plain_factor_key` takes them) or a sum with a tuple; None
        for another."""
        if not f.is_commutative:
            return None
        arg = f.args[0]
        if arg.is_Add:
            arg_key = self._plain_key(arg)
        elif arg.is_Symbol or isinstance(arg, AppliedUndef):
            arg_key = _plain_factor_key(arg)
        else:
            return None
        return None if arg_key is None else _nested_key(f, [arg_key])

    def _power_key(self, f: Any) -> tuple | None:
        """:meth:`_plain_key` of a power: its class's place, 2 and the
        tuples of its base and exponent (its hashable content), for a
        rational exponent and a base that has a tuple and is not a number,
        a power or a product; None for another."""
        base, exp = f.args
        if not exp.is_Rational or not f.is_commutative or base.is_Pow or base.is_Mul:
            return None
        base_key = self._plain_key(base)
        if base_key is None:
            return None
        return (_POW_PLACE, 2, base_key, _plain_atom_key(exp))

    def _sum_key(self, f: Any) -> tuple | None:
        """:meth:`_plain_key` of a sum: its class's place, its count of
        terms and their tuples (a product's: the class's place, its count
        of arguments and theirs, a rational coefficient's by
        :func:`_plain_atom_key`), as :func:`_compare` decides between two
        sums (their hashable content is their terms); None when a part
        has no tuple."""
        if not f.is_commutative:
            return None
        keys = []
        for term in f.args:
            if term.is_Rational:
                keys.append(_plain_atom_key(term))
                continue
            if not term.is_Mul:
                key = self._plain_key(term)
                if key is None:
                    return None
                keys.append(key)
                continue
            factors = []
            for a in term.args:
                key = _plain_atom_key(a) if a.is_Rational else self._plain_key(a)
                if key is None:
                    return None
                factors.append(key)
            keys.append((_MUL_PLACE, len(factors), *factors))
        return (_ADD_PLACE, len(keys), *keys)

    def position(self, z: Intermediate, x: Any) -> int | None:
        """The first ``j`` with ``z.args[j + 1] == x`` (``None``: none), by a
        table per instance rather than by comparing ``x`` with each
        argument."""
        table = self._positions.get(z)
        if table is None:
            table = {}
            for j, a in enumerate(z.args[1:]):
                table.setdefault(a, j)
            self._positions[z] = table
        return table.get(x)

    @staticmethod
    def is_variable(x: Any) -> bool:
        """True for what :meth:`derivative` differentiates by: a symbol, a
        function of time or a derivative."""
        return bool(x.is_Symbol or isinstance(x, _VARIABLE))

    def derivative(self, e: Any, x: Any, memo: dict | None = None) -> Any:
        """``D(e, x)``, the partial derivative by the variable ``x`` (the
        intermediates' derivatives named).  Without ``memo``, the book's
        own memo of ``x`` (shared by every derivative by ``x``: each
        distinct part is differentiated once per book)."""
        if memo is None:
            memo = self._pd_memos.setdefault(x, {})
        return self._pd(sp.sympify(e), x, memo)

    def total_dt(self, e: Any) -> Any:
        """``de/dt``, as sympy's ``diff(e, t)`` gives it (each variable's
        derivative a ``Derivative``, each intermediate's by its partial
        derivatives, named, times its variables' derivatives), by the same
        walk as :meth:`derivative`: no ``Derivative`` object is built for a
        sum, product or intermediate, and each distinct part is walked once
        (the book's memo: the answer depends only on the part).

        >>> from sympy.physics.mechanics import dynamicsymbols
        >>> q, u = dynamicsymbols("q u")
        >>> book = Intermediates()
        >>> z = book.name(sp.sin(q) * u + q**3 * u)
        >>> e = z * sp.cos(q)
        >>> sp.simplify(book.expand(book.total_dt(e)) - book.expand(e).diff(_T))
        0
        """
        return self._pd(sp.sympify(e), _T, self._dt_memo, None, self._rate_or_zero)

    def _rate_or_zero(self, x: Any) -> Any:
        found = self.time_rate(x)
        return sp.S.Zero if found is None else found

    def _pd(
        self,
        e: Any,
        x: Any,
        memo: dict,
        given: dict | None = None,
        rate: Callable[[Any], Any] | None = None,
    ) -> Any:
        """Partial derivative of ``e`` by the variable ``x`` (a function of
        time, a symbol, or ``t`` meaning explicit time only): a walk over
        the expression that skips what does not depend on ``x`` and never
        builds ``Derivative`` objects.  With ``given``, the derivatives of
        the intermediates are looked up there (absent: 0) instead of
        named.  With ``rate`` (``x`` is then ``t``), the total derivative:
        a variable's is ``rate(variable)``, and an intermediate's goes
        through all of its arguments."""
        if e.is_Atom or isinstance(e, _VARIABLE):
            return _variable_pd(e, x, rate)
        found = memo.get(e)
        if found is not None:
            return found
        return self._pd_new(e, x, memo, given, rate)

    def _pd_new(
        self,
        e: Any,
        x: Any,
        memo: dict,
        given: dict | None,
        rate: Callable[[Any], Any] | None,
    ) -> Any:
        """:meth:`_pd` of ``e``, neither an atom nor a variable, not in
        ``memo``: found and kept there.  The parts of a sum or product are
        looked up in ``memo`` here, and an atom or variable among them is
        decided here, without a call (most factors are intermediates met
        before, functions of time or symbols)."""
        if isinstance(e, Intermediate):
            args = e.args[1:]
            if given is not None and e in given:
                out = given[e]
            elif given is not None and e.book is self and self._canonical(e):
                out = sp.S.Zero  # does not depend on x
            elif rate is None and (
                (e.book is self and self._canonical(e))
                or all(a.is_Atom or isinstance(a, _VARIABLE) for a in args)
            ):
                j = e.book.position(e, x)
                out = sp.S.Zero if j is None else e.book.partial(e, j)
            else:
                out = total(
                    [
                        e.book.partial(e, j) * d
                        for j, a in enumerate(args)
                        if (d := self._pd(a, x, memo, given, rate)) is not _ZERO
                    ]
                )
        elif e.is_Add or e.is_Mul:
            args = e.args
            product = e.is_Mul
            terms = []
            factors = None
            for i, a in enumerate(args):
                if a.is_Atom or isinstance(a, _VARIABLE):
                    # _variable_pd, without the call for a constant
                    if a is x or (
                        (type(a) is type(x) or isinstance(a, AppliedUndef))
                        and _is_variable_x(a, x)
                    ):
                        d = sp.S.One
                    elif rate is None or a.is_Atom:
                        continue
                    else:
                        d = rate(a)
                else:
                    d = memo.get(a)  # most parts are shared
                    if d is None:
                        d = self._pd_new(a, x, memo, given, rate)
                if d is not _ZERO:
                    if product:
                        if factors is None:
                            factors = self._factors_of(e)
                        terms.append(product_with(args, i, d, factors))
                    else:
                        terms.append(d)
            out = total(terms)
        elif e.is_Pow and not e.exp.has(x):
            d = self._pd(e.base, x, memo, given, rate)
            out = sp.S.Zero if d is _ZERO else e.exp * e.base ** (e.exp - 1) * d
        elif isinstance(e, sp.Function) and not isinstance(e, sp.Derivative):
            out = total(
                [
                    e.fdiff(i + 1) * d
                    for i, a in enumerate(e.args)
                    if (d := self._pd(a, x, memo, given, rate)) is not _ZERO
                ]
            )
        elif rate is not None:  # anything else: sympy's total derivative
            out = e.diff(_T)
        else:  # anything else: sympy, by a plain symbol
            s = sp.Dummy("x")
            if x == _T:
                funcs = {f: sp.Dummy() for f in e.atoms(AppliedUndef)}
                back = {d: f for f, d in funcs.items()}
                out = e.xreplace(funcs).diff(x).xreplace(back)
            else:
                out = e.xreplace({x: s}).diff(s).xreplace({s: x})
        memo[e] = out
        return out

    def _factors_of(self, e: Any) -> _Factors:
        """``_Factors(e.args)`` of a product, found once per product (it is
        differentiated by each of its variables)."""
        found = self._factors.get(e)
        if found is None:
            found = self._factors[e] = _Factors(e.args)
        return found

    def time_derivative(self, e: Any, rate: Callable[[Any], Any], memo: dict) -> Any:
        """``de/dt`` by the chain rule, where ``rate(x)`` is the derivative of
        the variable ``x`` (a function of time or a derivative).

        One walk of each definition: an intermediate's derivative is named
        once per ``memo`` (which belongs to one ``rate``), rather than formed
        from its partial derivative by each of its variables.

        >>> import sympy as sp
        >>> from sympy.physics.mechanics import dynamicsymbols
        >>> q, u = dynamicsymbols("q u")
        >>> book = Intermediates()
        >>> z = book.name(sp.sin(q) * sp.cos(q) + q**3)
        >>> d = book.time_derivative(z, lambda x: u if x == q else sp.Derivative(x, _T), {})
        >>> sp.simplify(book.expand(d) - sp.diff(sp.sin(q) * sp.cos(q) + q**3, q) * u)
        0
        """
        if e.is_Atom:
            return sp.S.One if e == _T else sp.S.Zero
        if isinstance(e, _VARIABLE):
            return rate(e)
        found = memo.get(e)
        if found is not None:
            return found
        if isinstance(e, Intermediate):
            d = self.time_derivative(e.book.definition(e), rate, memo)
            out = self.name(d)
        elif e.is_Add:
            out = total(
                [
                    d
                    for a in e.args
                    if (d := self.time_derivative(a, rate, memo)) is not _ZERO
                ]
            )
        elif e.is_Mul:
            args = e.args
            terms = []
            factors = None
            for i, a in enumerate(args):
                if a.is_Number:
                    continue
                d = self.time_derivative(a, rate, memo)
                if d is not _ZERO:
                    if factors is None:
                        factors = self._factors_of(e)
                    terms.append(product_with(args, i, d, factors))
            out = total(terms)
        elif e.is_Pow and not e.exp.has(_T):
            d = self.time_derivative(e.base, rate, memo)
            out = sp.S.Zero if d is _ZERO else e.exp * e.base ** (e.exp - 1) * d
        elif isinstance(e, sp.sin):
            out = sp.cos(e.args[0]) * self.time_derivative(e.args[0], rate, memo)
        elif isinstance(e, sp.cos):
            out = -sp.sin(e.args[0]) * self.time_derivative(e.args[0], rate, memo)
        elif isinstance(e, sp.Function) and not isinstance(e, sp.Derivative):
            out = total(
                [
                    e.fdiff(i + 1) * d
                    for i, a in enumerate(e.args)
                    if (d := self.time_derivative(a, rate, memo)) is not _ZERO
                ]
            )
        else:  # anything else: sympy's derivative, then the rates
            d = e.diff(_T)
            rates = {
                x: rate(x.expr)
                for x in d.atoms(sp.Derivative)
                if x.derivative_count == 1 and isinstance(x.expr, AppliedUndef)
            }
            out = d.xreplace(rates)
        memo[e] = out
        return out

    def taylor(
        self,
        exprs: Sequence[Any],
        point: dict,
        steps: dict,
        lo: int,
        hi: int,
    ) -> list[Any]:
        """Autolev ``Taylor`` of order ``lo..hi`` (``hi <= 1``) about
        ``point`` (variable -> value), each variable ``x`` moved by
        ``steps[x]``: ``value + sum(dy/dx * step)`` with the value and the
        derivatives at the point.

        One pass over the intermediates in order gives each one's value and
        derivatives at the point (named; most vanish there), so nothing
        is named at the general point and nothing is written out."""
        if hi > 1:
            raise ValueError("taylor: orders above 1 go through sympy")
        exprs = [self.rebase(sp.sympify(e)) for e in exprs]
        xs = list(point)
        zs = self.ordered(exprs)
        keep: dict = {}  # derivatives not moved stay whole (q' is not q)
        for e in exprs:
            for d in self._scan(e)[0]:
                if isinstance(d, sp.Derivative) and d not in point:
                    keep[d] = d
        for z in zs:
            for d in z.args[1:]:
                if isinstance(d, sp.Derivative) and d not in point:
                    keep[d] = d
        rule = {**keep, **{sp.sympify(x): sp.sympify(a) for x, a in point.items()}}
        grads: dict[Any, dict] = {x: {} for x in xs}
        memos: dict[Any, dict] = {x: {} for x in xs}
        moved = set(xs)
        for z in zs:
            args = set(z.args[1:])
            inner = self._uses(z)
            if not (args & moved) and all(rule.get(m, m) == m for m in inner):
                rule[z] = z  # unchanged at the point
                continue
            body = self.definition(z)
            if hi >= 1:
                for x in xs:
                    if x in args:
                        d = self._pd(body, x, {}, grads[x])
                        grads[x][z] = self.name(d.xreplace(rule))
            rule[z] = self.name(body.xreplace(rule))
        out = []
        for e in exprs:
            terms = []
            if lo <= 0:
                terms.append(e.xreplace(rule))
            if hi >= 1 >= lo:
                for x in xs:
                    d = self._pd(e, x, memos[x], grads[x])
                    if d != 0:
                        terms.append(d.xreplace(rule) * steps[x])
            out.append(sp.Add(*terms))
        return out

    # ---------------------------------------------------------- expansion

    def ordered(self, exprs: Iterable[Any], known: Any = ()) -> list[Any]:
        """Intermediates that ``exprs`` use, each after those it uses (those
        in ``known`` and what only they use are left out)."""
        seen: set[Any] = set()
        order: list[Any] = []
        stack: list[tuple[Any, bool]] = []
        found: set[Any] = set()
        for e in exprs:
            found |= self._intermediates_in(sp.sympify(e))
        # Sets iterate in hash order, which varies between processes: visit
        # in the order of the names, so every run writes the same sequence.
        for z in self._by_name(found, reverse=True):
            if z not in known:
                stack.append((z, False))
        while stack:
            z, done = stack.pop()
            if done:
                order.append(z)
                continue
            if z in seen:
                continue
            seen.add(z)
            stack.append((z, True))
            # those still to visit, then ordered (most are visited already)
            todo = [i for i in self._uses(z) if i not in seen and i not in known]
            if todo:
                stack += [(i, False) for i in self._by_name(todo, reverse=True)]
        return order

    def _by_name(self, zs: Iterable[Any], reverse: bool = False) -> list[Any]:
        """Intermediates by number (then by their arguments' text): sorted by
        number, and only instances of one number (at other arguments) by
        the text, which is most of the cost of the key.  Both sorts are
        stable, so the order is ``sorted(zs, key=self._name_key)``'s."""
        out: list[Any] = []
        for _, group in itertools.groupby(
            sorted(zs, key=_number, reverse=reverse), key=_number
        ):
            group = list(group)
            if len(group) > 1:
                group.sort(key=self._name_key, reverse=reverse)
            out += group
        return out

    def _name_key(self, z: Intermediate) -> tuple[int, str]:
        # Printing the arguments is most of the cost of ordering: once per z.
        found = self._name_keys.get(z)
        if found is None:
            found = self._name_keys[z] = (_number(z), str(z.args[1:]))
        return found

    def _uses(self, z: Intermediate) -> Any:
        """The intermediates in ``z``'s definition (kept for canonical ones)."""
        k = _number(z)
        if not self._canonical(z):  # (kept on the instance)
            found = self._children.get(z)
            if found is None:
                found = self._children[z] = self._intermediates_in(self.definition(z))
            return found
        found = self._children.get(k)
        if found is None:
            found = self._children[k] = self._intermediates_in(self._defs[k])
        return found

    def _intermediates_in(self, expr: Any) -> set[Any]:
        """The intermediates in ``expr`` (``expr.atoms(self.Z)``), walking
        the tree directly (a shared subtree once) and not into a canonical
        intermediate's arguments: they are its variables, which hold no
        intermediate, and most of a definition's nodes.

        As :meth:`_walk`, a part is classified when it is met as an
        argument: an atom, which holds no intermediate, is never stacked
        (nor hashed)."""
        Z = self.Z
        canonical = self._canonical
        found: set[Any] = set()
        seen: set[Any] = set()
        stack: list = []
        todo: Any = (expr,)
        while True:
            for a in todo:
                if a.is_Atom:
                    continue
                if a.is_Mul or a.is_Add:
                    pass  # (most parts: walked into)
                elif isinstance(a, Z):
                    found.add(a)
                    at_own = a.__dict__.get("_canonical")  # (kept by _canonical)
                    if at_own is None:
                        at_own = canonical(a)
                    if at_own:
                        continue
                # (one lookup: ``a`` is new when the set grows)
                n = len(seen)
                seen.add(a)
                if len(seen) != n:
                    stack.append(a)
            if not stack:
                return found
            todo = stack.pop().args

    def expand(self, expr: Any) -> Any:
        """``expr`` with every intermediate replaced by what it stands for
        (a matrix or vector: each element)."""
        if isinstance(expr, sp.MatrixBase):
            return expr.applyfunc(self.expand)
        if not isinstance(expr, sp.Basic):
            if hasattr(expr, "args") and not isinstance(expr, list | tuple):
                return vmap(expr, self.expand)
            return expr
        zs = self.ordered([expr])
        if not zs:
            return expr
        for z in zs:
            if z not in self._full:
                self._full[z] = self.definition(z).xreplace(self._full)
        return expr.xreplace(self._full)

    def expanded_size(self, expr: Any) -> int:
        """Tree nodes of ``expr`` written out (:meth:`expand`), counted
        without writing it out: each intermediate's size once, in order."""
        parts = list(expr) if isinstance(expr, sp.MatrixBase) else [expr]
        parts = [p for p in parts if isinstance(p, sp.Basic)]
        sizes: dict[Any, int] = {}

        def size(e: Any) -> int:
            found = sizes.get(e)
            if found is not None:
                return found
            if e.is_Atom:
                return 1
            return 1 + sum(size(a) for a in e.args)

        for z in self.ordered(parts):
            sizes[z] = size(self.definition(z))
        return sum(size(p) for p in parts)

    def flatten(
        self, exprs: Sequence[Any], symbol: str = "_z"
    ) -> tuple[list[tuple[Any, Any]], list[Any]]:
        """``(assignments, reduced)`` in the form of ``sympy.cse``: plain
        symbols for the intermediates, each defined after those it uses."""
        exprs = list(exprs)
        zs = self.ordered(exprs)
        rule = {z: sp.Symbol(f"{symbol}{i}") for i, z in enumerate(zs)}
        assignments = [(rule[z], self.definition(z).xreplace(rule)) for z in zs]
        reduced = [
            sp.sympify(e).xreplace(rule) if isinstance(e, sp.Basic) else e
            for e in exprs
        ]
        return assignments, reduced

    def evalf(self, z: Intermediate, prec: int) -> Any:
        """``z``'s value as a number (its arguments numbers): the
        intermediates it uses are evaluated once each, in order."""
        cache = self._numbers
        if len(cache) > 500_000:
            cache.clear()
        key = (z, prec)
        if key in cache:
            return cache[key]
        dps = sp.core.evalf.prec_to_dps(prec)
        values: dict[Any, Any] = {}
        for inner in self.ordered([z]):
            k = (inner, prec)
            if k not in cache:
                body = self.definition(inner).xreplace(values)
                cache[k] = body.evalf(dps) if body.free_symbols == set() else body
            values[inner] = cache[k]
        return cache[key]

    # ------------------------------------------------------------- probes

    def probe(self, expr: Any, point: int, zero: Iterable[Any] = ()) -> complex:
        """``expr``'s value at a probe point: the variables in ``zero`` are 0
        at point 0, every other variable takes a fixed random value.  The
        intermediates are evaluated once per point, by :func:`number`."""
        zero = frozenset(zero)
        env = self._probes.setdefault((point, zero), {})
        expr = self.rebase(sp.sympify(expr))

        def fill(variables: Iterable[Any]) -> None:
            for x in variables:
                if x not in env:
                    if point == 0 and x in zero:
                        env[x] = 0j
                    else:
                        rng = random.Random(f"{point}:{x}")
                        env[x] = complex(rng.uniform(0.5, 1.5))

        fill(self._scan(expr)[0])
        for z in self.ordered([expr], env):
            fill(z.args[1:])
            try:
                env[z] = _num_z(self, z, env)
            except (TypeError, ValueError, ZeroDivisionError, OverflowError):
                env[z] = complex("nan")
        try:
            out = _num(expr, env)
        except (TypeError, ValueError, ZeroDivisionError, OverflowError):
            return 0j
        return 0j if out != out else out

    def values_at(self, exprs: Iterable[Any], point: int) -> list[complex]:
        """The values of ``exprs`` at random point ``point``: every variable
        and every derivative (a speed's, a Specified quantity's) takes a
        random value fixed by its name and ``point``.  Nothing is rewritten
        first, and each distinct part (an intermediate, a shared
        subexpression) is evaluated once, so a large expression costs one
        walk; the values are kept per point for the next call (they depend
        only on the part and the point).  Raises ``ValueError`` (or
        ``ZeroDivisionError``, ``OverflowError``) where a value cannot be
        formed.

        >>> q = dynamicsymbols("q")
        >>> book = Intermediates()
        >>> z = book.name(sp.sin(q) ** 2 + sp.cos(q) ** 2 + q.diff() * q)
        >>> a, b = book.values_at([z, 1 + q.diff() * q], 1)
        >>> abs(a - b) < 1e-12
        True
        """
        allow_deep_recursion()
        env: dict[Any, complex] = self._values.setdefault(point, {})
        functions = complex_functions()

        def value(e: Any) -> complex:
            found = env.get(e)
            if found is not None:
                return found
            if e.is_Number:
                out = complex(e)
            elif e.is_Symbol or isinstance(e, _VARIABLE):
                out = complex(random.Random(f"{point}:{e}").uniform(0.5, 1.5))
            elif isinstance(e, Intermediate):
                out = value(e.book.definition(e))
            elif e.is_Add:
                out = sum((value(a) for a in e.args), 0j)
            elif e.is_Mul:
                out = 1 + 0j
                for a in e.args:
                    out *= value(a)
            elif e.is_Pow:
                base = value(e.base)
                out = base ** (int(e.exp) if e.exp.is_Integer else value(e.exp))
            elif e.func in functions and len(e.args) == 1:
                out = complex(functions[e.func](value(e.args[0])))
            elif e.func is sp.atan2:
                y, x = (value(a) for a in e.args)
                out = complex(math.atan2(y.real, x.real))
            elif e.is_number:
                out = complex(sp.N(e))
            else:
                raise ValueError(f"no value for {e.func}")
            env[e] = out
            return out

        return [value(sp.sympify(e)) for e in exprs]

    # ------------------------------------------------------ linear solves

    def solve(
        self,
        a: sp.Matrix,
        b: sp.Matrix,
        zero: Iterable[Any] = (),
        *,
        keep: bool = False,
    ) -> sp.Matrix:
        """Solve ``a x = b`` by Gaussian elimination, naming every entry.

        Pivots are chosen numerically: an entry non-zero with the variables in
        ``zero`` set to 0 (the usual reference configuration) if possible, the
        largest at a random point otherwise.  With ``keep``, the entries may
        hold derivatives that are not :attr:`rates` (accelerations a
        ``Solve`` does not solve for), linearly: they stay visible, their
        coefficients named."""
        zero = list(zero)
        name = self._name_rates if keep else self.name
        rows = [[name(a[i, j]) for j in range(a.cols)] for i in range(a.rows)]
        rhs = [[name(b[i, j]) for j in range(b.cols)] for i in range(b.rows)]
        x = eliminate(rows, rhs, name, lambda e, point: self.probe(e, point, zero))
        return sp.Matrix(a.rows, b.cols, lambda i, j: x[i][j])


# ---------------------------------------------------------------- numbers


def _num(e: Any, env: dict) -> complex:
    """The value of a numeric expression (its intermediates in ``env``)."""
    found = env.get(e)
    if found is not None:
        return found
    if e.is_Number:
        return complex(float(e))
    if e.is_Add:
        return sum((_num(a, env) for a in e.args), 0j)
    if e.is_Mul:
        out = 1 + 0j
        for a in e.args:
            out *= _num(a, env)
        return out
    if e.is_Pow:
        base, exp = _num(e.base, env), e.exp
        if exp.is_Integer:
            return base ** int(exp)
        return base ** _num(exp, env)
    f = complex_functions().get(e.func)
    if f is not None and len(e.args) == 1:
        return complex(f(_num(e.args[0], env)))
    if e.func is sp.atan2:
        import math

        y, x = (_num(a, env) for a in e.args)
        return complex(math.atan2(y.real, x.real))
    if e.is_Symbol or isinstance(e, _VARIABLE):
        raise ValueError(f"no value for {e}")
    if isinstance(e, Intermediate):
        return number(e, env)
    if e.is_number:
        return complex(sp.N(e))
    values = {
        k: sp.sympify(v) for k, v in env.items() if not isinstance(k, Intermediate)
    }
    rest = e.xreplace(values).xreplace(
        {z: sp.sympify(env[z]) for z in e.atoms(Intermediate) if z in env}
    )
    return complex(sp.N(rest))


def number(expr: Any, env: dict) -> complex:
    """The value of ``expr`` where ``env`` gives the values of its variables
    (symbols, functions of time, derivatives).  Its intermediates are
    evaluated once each, in order, and kept in ``env`` for the next
    expression at the same point (e.g. the entries of a matrix)."""
    expr = sp.sympify(expr)
    zs = expr.atoms(Intermediate)
    if zs:
        book = next(iter(zs)).book
        expr = book.rebase(expr)
        for z in book.ordered([expr], env):
            if z not in env:
                env[z] = _num_z(book, z, env)
    return _num(expr, env)


def _num_z(book: Intermediates, z: Any, env: dict) -> complex:
    variables, body = book.canonical(_number(z))
    args = tuple(z.args[1:])
    if args == variables:
        return _num(body, env)
    # Evaluated elsewhere than at its own variables: bind them.
    local = {v: _num(a, env) for v, a in zip(variables, args, strict=True)}
    return number(body, local)
