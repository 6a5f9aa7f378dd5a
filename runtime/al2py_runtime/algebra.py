"""Pure functions behind Autolev's mathematical and simplification commands.

Every function takes sympy values (expressions, matrices, integers) and
returns sympy values; the workspace resolves names before calling them.
Functions documented as *elementwise* accept a matrix and apply to each
element.

Variables are functions of time (``X(t)``); their derivatives are distinct
quantities for every command here (``Coef(y, U1)`` does not see ``U1'``), so
derivatives are frozen into placeholder symbols before any substitution.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Sequence
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols
from sympy.physics.vector import Dyadic, Vector

from . import walks
from .matrices import as_matrix
from .model.kinematics import factor_terms, is_small

__all__ = [
    "expand",
    "factor",
    "taylor",
    "polynomial",
    "roots",
    "eig",
    "eig_vectors",
    "solve_linear",
    "coef",
    "exclude",
    "include",
    "arrange",
    "replace",
    "epsilon",
]

t = dynamicsymbols._t

Range = tuple[int, int]


# ---------------------------------------------------------------- helpers


def _elementwise(func: Callable[[sp.Expr], sp.Expr], y: Any) -> Any:
    """Apply ``func`` to ``y``, to each element of a matrix ``y``, or to each
    measure number of a vector or dyadic ``y`` (``Replace(W_DA_N>, ...)``)."""
    if isinstance(y, sp.MatrixBase | Vector | Dyadic):
        return walks.vmap(y, func)
    return func(sp.sympify(y))


def _range(orders: int | Sequence[int], what: str) -> Range:
    """``n`` -> ``(0, n)``; ``(n, m)`` stays; both non-negative, n <= m."""
    if isinstance(orders, int | sp.Integer):
        lo, hi = 0, int(orders)
    else:
        try:
            lo, hi = (int(k) for k in orders)
        except (TypeError, ValueError):
            raise TypeError(
                f"{what}: expected n or a range n:m, not {orders!r}"
            ) from None
    if lo < 0 or hi < lo:
        raise ValueError(f"{what}: {lo}:{hi} is not a valid range of degrees")
    return lo, hi


def _is_time_function(e: sp.Basic) -> bool:
    return isinstance(e, AppliedUndef) and t in e.args


def _is_time_derivative(e: sp.Basic) -> bool:
    return isinstance(e, sp.Derivative) and isinstance(e.expr, AppliedUndef)


def _freeze_table(exprs: Iterable[Any], targets: Iterable[Any] = ()) -> dict:
    """Placeholders for all derivatives in ``exprs`` and for each target."""
    table: dict = {}
    for e in exprs:
        items = e if isinstance(e, sp.MatrixBase) else [e]
        for item in items:
            if isinstance(item, sp.Basic):
                # each distinct part once: large equations share most parts
                for d in sorted(
                    walks.atoms(item, sp.Derivative), key=sp.default_sort_key
                ):
                    table.setdefault(d, sp.Dummy("d"))
    for x in targets:
        x = sp.sympify(x)
        if not x.is_Symbol:
            table.setdefault(x, sp.Dummy("x"))
    return table


def _freeze(expr: Any, table: dict) -> Any:
    return walks.xreplace(expr, table) if table and isinstance(expr, sp.Basic) else expr


def _thaw(expr: Any, table: dict) -> Any:
    if not table or not isinstance(expr, sp.Basic | sp.MatrixBase):
        return expr
    back = {v: k for k, v in table.items()}
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: walks.xreplace(e, back))
    return walks.xreplace(expr, back)


def _variables(expr: sp.Expr) -> set:
    """Functions of time and their derivatives appearing in ``expr``."""
    found = set(expr.atoms(sp.Derivative))
    found |= {f for f in expr.atoms(AppliedUndef) if _is_time_function(f)}
    return found


def _expand_terms(expr: sp.Expr) -> sp.Expr:
    """Expand products and integer powers, not function arguments."""
    table = {
        f: sp.Dummy("f") for f in expr.atoms(sp.Function) if not _is_time_function(f)
    }
    table.update({d: sp.Dummy("d") for d in expr.atoms(sp.Derivative)})
    frozen = expr.xreplace(table)
    out = sp.expand(frozen, deep=True, power_exp=False, power_base=False, log=False)
    return _thaw(out, table)


def _degree(term: sp.Expr, gens: set) -> int:
    """Total degree of a product ``term`` in ``gens`` (0 for other factors)."""
    degree = 0
    for factor in sp.Mul.make_args(term):
        base, exp = factor.as_base_exp()
        if base in gens and exp.is_Integer:
            degree += int(exp)
    return degree


def _numeric(m: sp.MatrixBase) -> bool:
    return all(sp.sympify(e).is_number for e in m)


def _clean(x: complex, tol: float = 1e-12) -> sp.Expr:
    """A numpy number as a sympy number; tiny imaginary parts and
    near-integers (relative 1e-12) are snapped."""
    z = complex(x)
    scale = max(1.0, abs(z))
    re, im = z.real, z.imag
    if abs(im) <= tol * scale:
        im = 0.0
    if abs(re - round(re)) <= tol * scale:
        re = float(round(re))
    if im and abs(im - round(im)) <= tol * scale:
        im = float(round(im))
    real = sp.Integer(int(re)) if re.is_integer() else sp.Float(re)
    if not im:
        return real
    imag = sp.Integer(int(im)) if im.is_integer() else sp.Float(im)
    return real + imag * sp.I


# ------------------------------------------------------------------ expand


def expand(y: Any, degrees: Range | None = None) -> Any:
    """Autolev ``Expand(y)`` / ``Expand(y, n:m)``: clear parentheses.

    With ``degrees=(n, m)`` keep only terms whose total degree in the
    variables (functions of t and their derivatives; if there are none, in
    all free symbols) lies in n..m.  Factors such as ``SIN(X)`` count as
    degree 0.  Elementwise.

    >>> X, Y = dynamicsymbols("X Y")
    >>> expand((X + 2*Y)**2 + 3*(7 + X)*(X + Y), (2, 2))
    4*X(t)**2 + 7*X(t)*Y(t) + 4*Y(t)**2
    """
    rng = None if degrees is None else _range(degrees, "Expand")

    def one(e: sp.Expr) -> sp.Expr:
        out = _expand_terms(e)
        if rng is None:
            return out
        gens = _variables(out) or out.free_symbols
        return sp.Add(
            *[a for a in sp.Add.make_args(out) if rng[0] <= _degree(a, gens) <= rng[1]]
        )

    return _elementwise(one, y)


# ------------------------------------------------------------------ factor


def factor(y: Any, *xs: Any) -> Any:
    """Autolev ``Factor(y)`` and ``Factor(y, x, ...)`` ("factored on x").

    Without ``xs`` this is sympy's ``factor``.  With ``xs``, the terms of each
    sum (also sums nested in products) that have ``x`` as a factor are
    grouped as ``x*(...)``; several ``xs`` apply in turn.  Nothing is
    expanded, so this is cheap on large expressions.  Elementwise.

    >>> X, Y = dynamicsymbols("X Y")
    >>> factor(21*X + 21*Y + 4*X**2 + 4*Y**2 + 7*X*Y, X)
    (4*X(t) + 7*Y(t) + 21)*X(t) + 4*Y(t)**2 + 21*Y(t)
    """
    if not xs:
        return _elementwise(sp.factor, y)

    def one(e: sp.Expr) -> sp.Expr:
        for x in xs:
            table = _freeze_table([e], [x])
            frozen = _freeze(e, table)
            e = _thaw(_factor_on(frozen, _freeze(sp.sympify(x), table)), table)
        return e

    return _elementwise(one, y)


def _factor_on(e: sp.Expr, x: sp.Expr) -> sp.Expr:
    """Group, innermost sums first, the terms having ``x`` as a factor."""
    if isinstance(e, sp.Mul):
        return sp.Mul(*[_factor_on(a, x) for a in e.args])
    if not isinstance(e, sp.Add):
        return e
    with_x, rest = [], []
    for term in (_factor_on(a, x) for a in e.args):
        quotient = _divide_out(term, x)
        if quotient is None:
            rest.append(term)
        else:
            with_x.append(quotient)
    if len(with_x) < 2:
        return sp.Add(*rest, *[q * x for q in with_x])
    return sp.Add(*rest) + x * _factor_on(sp.Add(*with_x), x)


def _divide_out(term: sp.Expr, x: sp.Expr) -> sp.Expr | None:
    """``term/x`` if ``x`` is a factor of the product ``term``, else None."""
    have = term.as_powers_dict()
    for base, exp in x.as_powers_dict().items():
        if base.is_number:
            continue
        got = sp.sympify(have.get(base, 0))
        if not (exp.is_number and got.is_number and got >= exp > 0):
            return None
    return term / x


# ------------------------------------------------------------------ taylor


def taylor(y: Any, orders: int | Range, points: Sequence[tuple[Any, Any, Any]]) -> Any:
    """Autolev ``Taylor(y, n:m, x=a, ...)``: multivariable Taylor polynomial.

    ``points`` holds ``(x, a, None)`` for ``x=a`` and ``(x, a, dx)`` for the
    perturbation form ``x=a:dx``.  Each ``x`` is replaced by ``a + e*(x-a)``
    (or ``a + e*dx``) and the terms of degree n..m in ``e`` are kept (a
    single order n means 0:n).  ``x`` may be a constant, a variable or a
    derivative (``U1'``); derivatives are kept apart from their variables.
    Elementwise.

    >>> X, Y = dynamicsymbols("X Y")
    >>> taylor(X*sp.cos(Y), (0, 4), [(X, 0, None), (Y, 0, None)])
    -X(t)*Y(t)**2/2 + X(t)
    """
    lo, hi = _range(orders, "Taylor")
    if not points:
        raise ValueError("Taylor needs at least one expansion point such as X=0")
    eps = sp.Dummy("epsilon")
    xs = [sp.sympify(p[0]) for p in points]
    for x in xs:
        if not (x.is_Symbol or _is_time_function(x) or _is_time_derivative(x)):
            raise ValueError(f"Taylor: cannot expand about {x}; it is not a name")
    from .intermediates.autoz import book_of

    book = book_of(y)
    if book is not None and hi <= 1:
        # AutoZ: values and derivatives at the point, intermediate by
        # intermediate (the written-out expression may be huge).
        point = {x: sp.sympify(a) for (_, a, _), x in zip(points, xs, strict=True)}
        steps = {
            x: x - sp.sympify(a) if dx is None else sp.sympify(dx)
            for (_, a, dx), x in zip(points, xs, strict=True)
        }
        items = list(y) if isinstance(y, sp.MatrixBase) else [sp.sympify(y)]
        out = book.taylor(items, point, steps, lo, hi)
        return (
            sp.Matrix(y.rows, y.cols, out) if isinstance(y, sp.MatrixBase) else out[0]
        )
    # Variables get placeholders too (derivatives are frozen first).
    table = _freeze_table([y], xs)
    shift = {}
    for (_, a, dx), xx in zip(points, xs, strict=True):
        key = table.get(xx, xx)
        step = key - sp.sympify(a) if dx is None else sp.sympify(dx)
        shift[key] = sp.sympify(a) + eps * step

    def one(e: sp.Expr) -> sp.Expr:
        frozen = _freeze(e, table).xreplace(shift)
        terms, deriv = [], frozen
        for k in range(hi + 1):
            if k:
                deriv = deriv.diff(eps)
            if k >= lo:
                value = deriv.subs(eps, 0) / math.factorial(k)
                terms.append(value)
        return _thaw(sp.Add(*terms), table)

    return _elementwise(one, y)


# -------------------------------------------------------------- polynomial


def polynomial(y: Any, x: Any, n: int | None = None) -> Any:
    """Autolev ``Polynomial``: coefficients <-> polynomial in ``x``.

    A matrix ``y`` holds coefficients, highest power first, and the
    polynomial is returned; an expression ``y`` gives the column matrix of
    its coefficients of ``x^n ... x^0`` (``n`` defaults to the degree).

    >>> A, B, C, X = sp.symbols("A B C X")
    >>> polynomial(sp.Matrix([A, B, C]), X)
    A*X**2 + B*X + C
    >>> polynomial(A*X**2 + C, X).T
    Matrix([[A, 0, C]])
    """
    x = sp.sympify(x)
    if isinstance(y, sp.MatrixBase | list | tuple):
        coeffs = list(sp.Matrix(y))
        if n is not None:
            raise ValueError("Polynomial(A, x): no degree is taken when A is a matrix")
        size = len(coeffs)
        return sp.Add(*[c * x ** (size - 1 - k) for k, c in enumerate(coeffs)])
    return sp.Matrix(_coefficients(sp.sympify(y), x, n))


def _coefficients(y: sp.Expr, x: sp.Expr, n: int | None) -> list[sp.Expr]:
    """Coefficients of ``x^n .. x^0`` in the polynomial ``y``."""
    table = _freeze_table([y], [x])
    gen = table.get(x, x)
    frozen = _expand_terms(_freeze(y, table))
    by_power: dict[int, list[sp.Expr]] = {}
    for term in sp.Add.make_args(frozen):
        power = _degree(term, {gen})
        rest = term / gen**power if power else term
        if rest.has(gen):
            raise ValueError(f"Polynomial: {y} is not a polynomial in {x}")
        by_power.setdefault(power, []).append(rest)
    degree = max(by_power) if by_power else 0
    if n is None:
        n = degree
    elif degree > n:
        raise ValueError(f"Polynomial: {y} has degree {degree} in {x}, more than {n}")
    out = [sp.Add(*by_power.get(k, [])) for k in range(n, -1, -1)]
    return [_thaw(c, table) for c in out]


# ------------------------------------------------------------------- roots


def roots(y: Any, x: Any = None, n: int | None = None) -> sp.Matrix:
    """Autolev ``Roots(A)`` and ``Roots(y, x, n)``: a column of roots.

    ``Roots(A)``: ``A`` holds the coefficients, highest power first.  Numeric
    coefficients use ``numpy.roots``; the roots are sorted by real part, then
    imaginary part.  ``Roots(y, x, n)``: ``y`` is a polynomial of degree
    ``n`` in ``x``; a quadratic gives ``(-B+sqrt(B^2-4AC))/(2A)`` first.

    >>> roots(sp.Matrix([1, -3, 2])).T
    Matrix([[1, 2]])
    >>> A, B, C, X = sp.symbols("A B C X")
    >>> roots(A*X**2 + B*X + C, X, 2)[0]
    (-B + sqrt(-4*A*C + B**2))/(2*A)
    """
    if x is None:
        if n is not None:
            raise TypeError("Roots(A) takes no degree; use Roots(y, x, n)")
        coeffs = list(as_matrix(y, "Roots(A)"))
    else:
        if isinstance(y, sp.MatrixBase):
            raise TypeError("Roots(y, x, n): y must be a polynomial, not a matrix")
        coeffs = _coefficients(sp.sympify(y), sp.sympify(x), n)
    while coeffs and coeffs[0] == 0:
        coeffs.pop(0)
    if len(coeffs) < 2:
        raise ValueError("Roots: the polynomial has no roots (degree is less than 1)")
    if all(sp.sympify(c).is_number for c in coeffs):
        import numpy as np

        values = np.roots(np.array([complex(c) for c in coeffs]))
        found = sorted((_clean(v) for v in values), key=_sort_key)
        return sp.Matrix(found)
    return sp.Matrix(_symbolic_roots(coeffs))


def _sort_key(z: sp.Expr) -> tuple[float, float]:
    value = complex(z)
    return (value.real, value.imag)


def _symbolic_roots(coeffs: list[sp.Expr]) -> list[sp.Expr]:
    if len(coeffs) == 2:
        a, b = coeffs
        return [-b / a]
    if len(coeffs) == 3:
        a, b, c = coeffs
        disc = sp.sqrt(b**2 - 4 * a * c)
        return [(-b + disc) / (2 * a), (-b - disc) / (2 * a)]
    z = sp.Dummy("z")
    poly = sp.Poly(
        sp.Add(*[c * z ** (len(coeffs) - 1 - k) for k, c in enumerate(coeffs)]), z
    )
    found = sp.roots(poly, multiple=True)
    if len(found) != len(coeffs) - 1:
        raise ValueError(
            f"Roots: cannot find the roots of degree-{len(coeffs) - 1} "
            "polynomial symbolically"
        )
    return found


# --------------------------------------------------------------------- eig


def eig(m: Any) -> sp.Matrix:
    """Autolev ``Eig(A)``: the column matrix of eigenvalues of ``A``.

    Numeric matrices use numpy (``eigh`` for real symmetric ones) and are
    sorted by real part, then imaginary part; symbolic matrices use sympy
    (values repeated by multiplicity).

    >>> eig(sp.Matrix([[2, 0], [0, 1]])).T
    Matrix([[1, 2]])
    """
    return eig_vectors(m, vectors=False)[0]


def eig_vectors(m: Any, vectors: bool = True) -> tuple[sp.Matrix, sp.Matrix | None]:
    """Autolev ``Eig(A, LAMBDA, V)``: eigenvalues and unit eigenvectors.

    Returns ``(values, V)`` where ``values`` is a column and row k of ``V``
    is the unit-length eigenvector of value k (numpy's signs).

    >>> values, vecs = eig_vectors(sp.Matrix([[2, 0], [0, 1]]))
    >>> vecs
    Matrix([
    [0, 1],
    [1, 0]])
    """
    a = _square(m, "Eig")
    if _numeric(a):
        return _numeric_eig(a, vectors)
    if not vectors:
        return sp.Matrix(a.eigenvals(multiple=True)), None
    values, rows = [], []
    for value, mult, basis in a.eigenvects():
        if len(basis) < mult:
            raise ValueError("Eig: the matrix is defective (too few eigenvectors)")
        for v in basis:
            norm = sp.sqrt(sum(e * sp.conjugate(e) for e in v))
            values.append(value)
            rows.append(list(v / norm))
    return sp.Matrix(values), sp.Matrix(rows)


def _numeric_eig(a: sp.Matrix, vectors: bool) -> tuple[sp.Matrix, sp.Matrix | None]:
    real = all(sp.sympify(e).is_real for e in a)
    import numpy as np

    arr = np.array(a.evalf(), dtype=float if real else complex)
    if real and a.is_symmetric():
        values_np, vecs_np = np.linalg.eigh(arr)
    else:
        values_np, vecs_np = np.linalg.eig(arr)
    values = [_clean(v) for v in values_np]
    order = sorted(range(len(values)), key=lambda k: _sort_key(values[k]))
    col = sp.Matrix([values[k] for k in order])
    if not vectors:
        return col, None
    rows = [[_clean(vecs_np[i, k]) for i in range(a.rows)] for k in order]
    return col, sp.Matrix(rows)


def _square(m: Any, what: str) -> sp.Matrix:
    a = as_matrix(m, what)
    if a.rows != a.cols or a.rows == 0:
        raise ValueError(f"{what}: expected a square matrix, not {a.rows}x{a.cols}")
    return a


# ------------------------------------------------------------------- solve


def solve_linear(
    eqs: Any, unknowns: Sequence[Any], book: Any = None, zero: Sequence[Any] = ()
) -> tuple[sp.Expr, ...]:
    """Autolev ``Solve(A, x1, x2, ...)``: solve linear equations ``A = 0``.

    ``unknowns`` may be symbols, variables or derivatives.  Returns the
    solutions in order; raises ValueError for nonlinear or singular systems.
    With a book of intermediates (``AutoZ ON``, :mod:`al2py_runtime.intermediates.autoz`)
    the elimination names every entry (pivots chosen non-zero where the
    variables in ``zero`` vanish).

    >>> X, Y = dynamicsymbols("X Y")
    >>> solve_linear(sp.Matrix([3*X + 4*Y - 37, 4*X - 2*Y + 2]), [X, Y])
    (3, 7)
    """
    equations = list(eqs) if isinstance(eqs, sp.MatrixBase | list | tuple) else [eqs]
    xs = [sp.sympify(u) for u in unknowns]
    if not xs:
        raise ValueError("Solve needs at least one unknown")
    if len(set(xs)) != len(xs):
        raise ValueError("Solve: an unknown is listed twice")
    if len(equations) != len(xs):
        raise ValueError(f"Solve: {len(equations)} equations for {len(xs)} unknowns")
    # With a book, only the unknowns are frozen: the other derivatives stay
    # in the equations, so that the intermediates are made over them (not
    # over placeholders, which thawed would leave each ``Z`` taken elsewhere
    # than at its own variables) and the solutions show them.
    linear = book is not None and _linear_in_others(equations, xs, book)
    table = _freeze_table([] if linear else equations, xs)
    syms = [table.get(x, x) for x in xs]
    frozen = [_freeze(sp.sympify(e), table) for e in equations]
    a, b = _linear_system(frozen, syms, xs, book)
    singular = "Solve: the equations are singular (determinant is zero)"
    if book is not None:
        try:
            zero = [table.get(z, z) for z in zero]
            sols = list(book.solve(a, b, zero, keep=linear))
        except ValueError:
            raise ValueError(singular) from None
    elif len(xs) <= 3:  # Cramer's rule keeps small solutions readable
        det = a.det(method="berkowitz")
        if sp.expand(det) == 0:
            raise ValueError(singular)
        den = _factor_small(det)
        sols = [
            _factor_small(_replace_col(a, k, b).det(method="berkowitz")) / den
            for k in range(len(xs))
        ]
    else:
        try:
            sols = [sp.together(s) for s in a.LUsolve(b)]
        except ValueError:
            raise ValueError(singular) from None
        if any(s.has(sp.nan, sp.zoo, sp.oo) for s in sols):
            raise ValueError(singular)
    return tuple(_thaw(s, table) for s in sols)


def _linear_in_others(equations: list[Any], xs: list[Any], book: Any) -> bool:
    """Whether ``equations`` are linear in their derivatives other than the
    unknowns ``xs`` (no coefficient of one holds one): walks that take each
    shared part once."""
    for e in equations:
        e = sp.sympify(e)
        others = [
            d
            for d in sorted(walks.atoms(e, sp.Derivative), key=sp.default_sort_key)
            if d not in xs
        ]
        for d in others:
            if walks.appearing(book.derivative(e, d), others):
                return False
    return True


#: ``factor_terms`` (which reads a closed-form solution as Autolev printed
#: it) on larger expressions can take minutes: they are left as they are
_FACTOR_LIMIT = 300


def _factor_small(expr: sp.Expr) -> sp.Expr:
    """``factor_terms(expr)`` for an expression of at most
    :data:`_FACTOR_LIMIT` tree nodes; a larger one as it is."""
    return factor_terms(expr) if is_small(expr, _FACTOR_LIMIT) else expr


def _linear_system(
    eqs: list[sp.Expr], syms: list, xs: list, book: Any = None
) -> tuple[sp.Matrix, sp.Matrix]:
    """The coefficients and right-hand sides of linear ``eqs`` in ``syms``.
    With a book, the derivatives are its walk (one memo per unknown, shared
    by the equations) and every other walk visits each distinct part once:
    large equations share most of their parts, which sympy's ``diff``,
    ``has`` and ``xreplace`` walk each time they occur."""
    rows, rhs = [], []
    memos: dict = {s: {} for s in syms}
    zero = {s: 0 for s in syms}
    for e in eqs:
        if book is not None:
            row = [book.derivative(e, s, memos[s]) for s in syms]
        else:
            row = [e.diff(s) for s in syms]
        for s, c in zip(syms, row, strict=True):
            if walks.appearing(c, syms):
                raise ValueError(
                    f"Solve: the equations are not linear in {_name(s, syms, xs)}"
                )
        rows.append(row)
        rhs.append(-walks.xreplace(e, zero))
    return sp.Matrix(rows), sp.Matrix(rhs)


def _name(s: Any, syms: list, xs: list) -> Any:
    return xs[syms.index(s)]


def _replace_col(a: sp.Matrix, k: int, col: sp.Matrix) -> sp.Matrix:
    out = a.copy()
    out[:, k] = col
    return out


# ----------------------------------------------------- simplifications


def coef(y: Any, x: Any) -> Any:
    """Autolev ``Coef(y, x)``: the coefficient of ``x`` (y linear in x).

    With a matrix ``x`` the result is the matrix of coefficients: row i,
    column j holds the coefficient of ``x[j]`` in ``y[i]``.

    >>> X, Y = dynamicsymbols("X Y")
    >>> A, B = sp.symbols("A B")
    >>> coef(A*X + B*Y + 1, X)
    A
    >>> coef(sp.Matrix([A*X + Y, X - B*Y]), sp.Matrix([X, Y]))
    Matrix([
    [A,  1],
    [1, -B]])
    """
    if isinstance(x, sp.MatrixBase | list | tuple):
        xs = list(sp.Matrix(x))
        ys = list(y) if isinstance(y, sp.MatrixBase) else [y]
        return sp.Matrix([[_coef_one(sp.sympify(e), xx) for xx in xs] for e in ys])
    return _elementwise(lambda e: _coef_one(e, sp.sympify(x)), y)


#: expressions with more tree nodes than this are taken apart by walks that
#: visit each distinct part once (large ones share most of their parts),
#: rather than by sympy's ``diff`` and ``expand``
_LARGE = 1000


def _coef_one(y: sp.Expr, x: sp.Expr) -> sp.Expr:
    table = _freeze_table([y], [x])
    s = table.get(x, x)
    if not s.is_Symbol:
        raise ValueError(f"Coef: cannot take the coefficient of {x}")
    frozen = _freeze(y, table)
    if is_small(frozen, _LARGE):
        c = frozen.diff(s)
    else:
        from .intermediates.autoz import Intermediates, book_of

        c = (book_of(frozen) or Intermediates()).derivative(frozen, s)
    if walks.appearing(c, [s]):
        raise ValueError(f"Coef: {_short(y)} is not linear in {x}")
    return _thaw(c, table)


def _short(e: Any) -> str:
    """``e`` for a message: its text if short, else a mention of its size."""
    return str(e) if is_small(e, 60) else "the expression"


def _split_terms(y: sp.Expr, x: Any) -> tuple[sp.Expr, sp.Expr]:
    """(terms containing x, other terms) of the expanded ``y``; a matrix
    ``x`` lists several names, and a term containing any of them counts."""
    xs = list(x) if isinstance(x, sp.MatrixBase) else [sp.sympify(x)]
    table = _freeze_table([y], xs)
    ss = [table.get(e, e) for e in xs]
    frozen = _freeze(y, table)
    if not is_small(frozen, _LARGE):
        split = _split_polynomial(frozen, ss)
        if split is not None:
            return _thaw(split[0], table), _thaw(split[1], table)
    terms = sp.Add.make_args(_expand_terms(frozen))
    has = [a for a in terms if any(a.has(s) for s in ss)]
    rest = [a for a in terms if not any(a.has(s) for s in ss)]
    return _thaw(sp.Add(*has), table), _thaw(sp.Add(*rest), table)


def _split_polynomial(y: sp.Expr, ss: list) -> tuple[sp.Expr, sp.Expr] | None:
    """:func:`_split_terms` of a large ``y`` without expanding it, when
    ``y`` is a polynomial in the symbols ``ss`` (functions, as there, count
    as whole: their arguments are not looked into): the terms of expanded
    ``y`` without any of ``ss`` are then ``y`` with ``ss`` set to 0, and
    the others the difference.  None if ``y`` is not such a polynomial."""
    funcs = {
        f: sp.Dummy("f")
        for f in sorted(walks.atoms(y, sp.Function), key=sp.default_sort_key)
        if not _is_time_function(f)
    }
    opaque = walks.xreplace(y, funcs)
    if not _polynomial_in(opaque, set(ss)):
        return None
    rest = walks.xreplace(opaque, dict.fromkeys(ss, sp.S.Zero))
    back = {d: f for f, d in funcs.items()}
    rest = walks.xreplace(rest, back)
    return walks.xreplace(opaque, back) - rest, rest


def _polynomial_in(e: sp.Expr, ss: set) -> bool:
    """Whether ``e`` is a polynomial in the symbols ``ss``: they appear only
    in sums, products and powers with non-negative integer exponents (each
    distinct part looked at once)."""
    memo: dict = {}  # part -> whether it holds one of ss

    def holds(a: Any) -> bool:
        found = memo.get(a)
        if found is None:
            found = memo[a] = a in ss or any(holds(b) for b in a.args)
        return found

    seen: set = set()
    stack = [e]
    while stack:
        a = stack.pop()
        if a in seen or a in ss or not holds(a):
            continue
        seen.add(a)
        if a.is_Pow:
            if not (a.exp.is_Integer and a.exp >= 0) or holds(a.exp):
                return False
        elif not (a.is_Add or a.is_Mul):
            return False
        stack.extend(a.args)
    return True


def _names_arg(x: Any) -> Any:
    return sp.Matrix(x) if isinstance(x, sp.MatrixBase | list | tuple) else x


def exclude(y: Any, x: Any) -> Any:
    """Autolev ``Exclude(y, x)``: the terms of expanded ``y`` without ``x``
    (``Exclude(F, [U4, U5])``: without any of them; y's shape is kept).

    >>> A, B, X, Y = sp.symbols("A B X Y")
    >>> exclude(A*(X + B) + 3, X)
    A*B + 3
    >>> exclude(A*X + B*Y + 3, sp.Matrix([X, Y]))
    3
    """
    x = _names_arg(x)
    return _elementwise(lambda e: _split_terms(e, x)[1], y)


def include(y: Any, x: Any) -> Any:
    """Autolev ``Include(y, x)``: the terms of expanded ``y`` containing ``x``
    (or any name of a matrix ``x``).

    >>> A, B, X = sp.symbols("A B X")
    >>> include(A*(X + B) + 3, X)
    A*X
    """
    x = _names_arg(x)
    return _elementwise(lambda e: _split_terms(e, x)[0], y)


def arrange(y: Any, n: int, x: Any) -> Any:
    """Autolev ``Arrange(y, n, x)``: group the terms of degree ``n`` in ``x``.

    The terms of expanded ``y`` of degree ``n`` in ``x`` become
    ``x^n*(...)`` (the bracket with common factors pulled out); the other
    terms are left as they are.  Elementwise.

    >>> A, B, X = sp.symbols("A B X")
    >>> arrange(A*X + B*X + A*B, 1, X)
    A*B + X*(A + B)
    """
    n = int(n)
    if n < 0:
        raise ValueError(f"Arrange: degree {n} must not be negative")
    x = sp.sympify(x)

    def one(e: sp.Expr) -> sp.Expr:
        table = _freeze_table([e], [x])
        s = table.get(x, x)
        group, rest = [], []
        for term in sp.Add.make_args(_expand_terms(_freeze(e, table))):
            quotient = term / s**n
            if _degree(term, {s}) == n and not quotient.has(s):
                group.append(quotient)
            else:
                rest.append(term)
        grouped = s**n * sp.factor_terms(sp.Add(*group))
        return _thaw(sp.Add(*rest) + grouped, table)

    return _elementwise(one, y)


def replace(y: Any, pairs: Sequence[tuple[Any, Any]]) -> Any:
    """Autolev ``Replace(y, old=new, ...)``: substitute subexpressions.

    ``old`` may be any subexpression (``SIN(X)``); derivatives are separate
    names, so replacing ``X`` leaves ``X'`` alone.  All pairs apply at once.

    >>> X = dynamicsymbols("X")
    >>> replace(sp.sin(X)**2 + X.diff(), [(sp.sin(X), 3)])
    Derivative(X(t), t) + 9
    """
    pairs = [(sp.sympify(a), sp.sympify(b)) for a, b in pairs]
    if not pairs:
        return y

    def one(e: sp.Expr) -> sp.Expr:
        table = _freeze_table([e])
        subs = [(_freeze(a, table), b) for a, b in pairs]
        out = _freeze(e, table).subs(subs, simultaneous=True)
        return _thaw(out, table)

    return _elementwise(one, y)


def epsilon(y: Any, tol: Any = 1.0e-7) -> Any:
    """Autolev ``Epsilon(y, tol)``: numbers within ``tol`` of an integer
    become that integer (``tol`` defaults to AutoEpsilon's default, 1.0E-7).

    >>> X = sp.Symbol("X")
    >>> epsilon(2.00001*X + 0.5, 0.001)
    2*X + 0.5
    """
    tol = float(tol)
    if tol < 0:
        raise ValueError(f"Epsilon: tolerance {tol} must not be negative")

    def one(e: sp.Expr) -> sp.Expr:
        table = {}
        for num in e.atoms(sp.Float, sp.Rational):
            if num.is_Integer:
                continue
            nearest = round(float(num))
            if abs(float(num) - nearest) <= tol:
                table[num] = sp.Integer(nearest)
        return e.xreplace(table) if table else e

    return _elementwise(one, y)
