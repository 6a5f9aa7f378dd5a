"""Vector helpers and rotation kinematics for :mod:`al2py_runtime.model.model`.

Everything here is pure: functions of sympy expressions, ``Vector``/``Dyadic``
objects and ``ReferenceFrame``s, with no workspace state.

Conventions (Kane & Levinson, as Autolev):

* ``A_B[i, j] = Dot(Ai>, Bj>)`` -- sympy's ``A.dcm(B)``.
* Euler parameters ``e1, e2, e3, e4``: ``e1..e3`` are the vector part
  (``lambda_i*sin(theta/2)``), ``e4 = cos(theta/2)`` the scalar part.
* Rodrigues parameters ``r_i = lambda_i*tan(theta/2)``.
* Angular velocities from ``Angvel``/``Kindiffs`` are expressed in ``B``.
"""

from __future__ import annotations

import operator
from collections import deque
from collections.abc import Callable, Iterable
from typing import Any

import sympy as sp
from sympy.core.assumptions import assumptions
from sympy.core.function import Application, AppliedUndef
from sympy.physics.vector import Dyadic, ReferenceFrame, Vector, dynamicsymbols
from sympy.utilities.iterables import iterable

from .. import walks
from ..intermediates.autoz import Intermediate
from ..walks import vmap

__all__ = [
    "vmap",
    "ang_vel_in",
    "frame_path",
    "dot",
    "exact_dot",
    "is_vector",
    "is_dyadic",
    "as_dyadic",
    "as_vector",
    "tidy",
    "Tidier",
    "tidy_vector",
    "vdot",
    "vcross",
    "rotation_dcm",
    "angvel_from_dcm",
    "euler_parameter_rates",
    "euler_parameter_angvel",
    "scalar_dt",
]

t = dynamicsymbols._t
_ZERO = sp.S.Zero

#: Size above which ``tidy`` does not try ``trigsimp`` (it gets slow).
TRIGSIMP_LIMIT = 300


def is_vector(x: Any) -> bool:
    return isinstance(x, Vector)


def doit_derivatives(expr: Any) -> Any:
    """Evaluate derivatives of expressions, keeping derivatives of declared
    functions of time (``U1'``); matrices elementwise."""
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(doit_derivatives)
    if isinstance(expr, sp.Basic):
        # sympy's expr.replace(query, value), each shared part walked once;
        # without a derivative to evaluate, replace changes nothing and
        # gives expr itself: found by a plain walk (most resolved values)
        if all(_kept_derivative(d) for d in walks.atoms(expr, sp.Derivative)):
            return expr
        return walks.replace(
            expr,
            lambda e: isinstance(e, sp.Derivative) and not _kept_derivative(e),
            lambda e: e.doit(),
        )
    return expr


def _kept_derivative(d: sp.Derivative) -> bool:
    """A derivative of a declared function of time (``U1'``), which
    :func:`doit_derivatives` keeps."""
    return isinstance(d.expr, AppliedUndef)


def one_or_tuple(items: list[Any]) -> Any:
    """One value, or a tuple of several (how declarations bind names)."""
    return items[0] if len(items) == 1 else tuple(items)


def is_dyadic(x: Any) -> bool:
    return isinstance(x, Dyadic)


def as_vector(x: Any) -> Vector:
    """``0`` (Autolev's ``0>`` after normalization) or a Vector -> Vector.

    >>> as_vector(0)
    0
    """
    return _zero_or(Vector, x, "vector")


def as_dyadic(x: Any) -> Dyadic:
    """``0`` (Autolev's ``0>>`` after normalization) or a Dyadic -> Dyadic.

    >>> as_dyadic(0) == Dyadic(0)
    True
    """
    return _zero_or(Dyadic, x, "dyadic")


def _zero_or(kind: type, x: Any, what: str) -> Any:
    if isinstance(x, kind):
        return x
    if x == 0:
        return kind(0)
    raise TypeError(f"expected a {what}, not {x!r}")


def _row_times(row: list, b: sp.MatrixBase) -> list:
    """The entries of ``r * b`` for the row ``r`` of entries ``row``, as
    sympy sums them (``Add`` of the nonzero products), without its test
    for infinities."""
    return [
        sp.Add(*[x * b[k, j] for k, x in enumerate(row) if x != 0 and b[k, j] != 0])
        for j in range(b.cols)
    ]


def _zero_times_is_zero(x: Any) -> bool:
    """Whether ``0 * x`` is 0, as sympy's sparse product asks of each entry
    (``0 * oo`` is ``nan``), answered without sympy's assumptions for a
    commutative intermediate over variables, whose facts follow from
    ``commutative`` and ``real`` alone (never ``finite=False``), or a
    rational multiple of one, and for an entry that holds no infinity
    (only then can it be known infinite, as for :func:`exact_dot`: the
    script's names are never declared infinite); sympy's query walks the
    whole of a large entry (a rotation about a vector's axis) for each of
    several facts.

    >>> q = sp.Symbol("q")
    >>> _zero_times_is_zero(sp.sin(q) / (1 + q**2)), _zero_times_is_zero(q + sp.oo)
    (True, False)
    """
    if x.is_Mul:
        if all(f.is_Rational or _finite_intermediate(f) for f in x.args):
            return True
    elif _finite_intermediate(x):
        return True
    if not walks.atoms(x, *_INFINITIES):
        return True
    return sp.S.Zero * x == sp.S.Zero


def scalar_dt(e: Any) -> Any:
    """``sp.diff(e, t)``, the same expression, each distinct sum and
    product differentiated once, as sympy's rules do: a sum's derivative is
    the sum of its terms', a product's the sum over its factors of the
    product with that factor's derivative in its place (the factors in
    order, as sympy takes them: an intermediate named on the way gets the
    same number).  Anything else is sympy's own ``diff``.

    sympy builds a ``Derivative`` for every part, walks each part's free
    symbols and its derivative's ``Derivative`` objects, asks each
    derivative whether it is zero, and multiplies the factors' zero
    derivatives by the other factors, asking each of those whether it is
    infinite (``0 * oo`` is ``nan``).  Here a zero term is left out, which
    is what sympy's product comes to when no factor is known infinite:
    only an infinity in ``e`` makes one so (the script's names are never
    declared infinite, and an intermediate's facts come from
    ``commutative`` and ``real``), and then ``e`` is sympy's.

    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> e = sp.sqrt(1 - sp.sin(q) ** 2) * u * (q + 2 * u**2) + q * t
    >>> scalar_dt(e) == sp.diff(e, t)
    True
    >>> scalar_dt(sp.zoo * q * u + u) == sp.diff(sp.zoo * q * u + u, t)
    True
    """
    if not isinstance(e, sp.Expr) or walks.atoms(e, *_INFINITIES):
        return sp.diff(e, t)
    walks.allow_deep_recursion()  # (as deep as sympy's own walk)
    memo: dict = {}

    def walk(x: Any) -> Any:
        if x.is_Atom:
            return sp.S.One if x == t else _ZERO
        if not (x.is_Add or x.is_Mul):
            return x.diff(t)
        found = memo.get(x)
        if found is None:
            args = x.args
            if x.is_Add:
                found = sp.Add(*[walk(a) for a in args])  # noqa: F821
            else:
                terms = []
                for i, a in enumerate(args):
                    d = walk(a)  # noqa: F821 - deleted after the walk
                    if d is not _ZERO:
                        terms.append(sp.Mul(*args[:i], d, *args[i + 1 :]))
                found = sp.Add(*terms)
            memo[x] = found
        return found

    try:
        return walk(e)
    finally:
        del walk  # it refers to itself: freed now with its memo, not by a collection


def _times(a: Any, b: Any) -> Any:
    """``a * b`` where neither is known infinite (:func:`_holds_infinity`
    found none): a zero times anything is zero, without sympy's query of
    the other factor's assumptions (``0 * oo`` is ``nan``), which walks the
    whole of a large factor the first time it is asked.

    >>> q = sp.Symbol("q")
    >>> _times(sp.S.Zero, sp.sin(q) * q), _times(q, sp.S.Zero), _times(2, q)
    (0, 0, 2*q)
    """
    if a is _ZERO or b is _ZERO:
        return _ZERO
    return a * b


def _holds_infinity(matrices: Iterable[Any]) -> bool:
    """Whether an entry of ``matrices`` holds an infinity: only then can an
    entry be known infinite (the script's names are never declared
    infinite, and an intermediate's facts come from ``commutative`` and
    ``real``)."""
    return any(walks.atoms(x, *_INFINITIES) for m in matrices for x in m)


def _finite_intermediate(x: Any) -> bool:
    """An intermediate whose assumptions come from ``commutative`` and
    ``real`` only (:meth:`Intermediates.facts`): never known infinite."""
    if not isinstance(x, Intermediate):
        return False
    args = x.args[1:]
    return (
        x.is_commutative is True
        and all(a.is_commutative for a in args)
        and not all(a.is_number for a in args)
    )


#: the matrix classes whose products :func:`named_product` forms
_DENSE = frozenset({sp.MutableDenseMatrix, sp.ImmutableDenseMatrix})


def finite_entries(m: sp.MatrixBase) -> bool:
    """Whether ``0 * x`` is 0 for every entry ``x`` of ``m`` (no entry is
    known infinite): what :func:`named_product` needs of both matrices."""
    return all(_zero_times_is_zero(v) for v in m.todok().values())


def _rows(dok: dict) -> dict:
    """A dictionary of keys as rows (``{i: {j: entry}}``), each in the
    dictionary's order: the order of sympy's sparse matrix."""
    rows: dict = {}
    for (i, j), v in dok.items():
        rows.setdefault(i, {})[j] = v
    return rows


def _sparse_product(da: dict, db: dict) -> dict:
    """The entries of the product, as sympy's ``sdm_matmul_exraw`` forms
    and orders them (see :func:`named_product`), no entry infinite."""
    rows_b = _rows(db)
    dok: dict = {}
    for i, ai in _rows(da).items():
        terms: dict = {}
        for k in sorted(ai.keys() & rows_b.keys()):
            x = ai[k]
            for j, y in rows_b[k].items():
                terms.setdefault(j, []).append(x * y)
        for j, products in terms.items():
            entry = sp.Add(*products)
            if entry:
                dok[(i, j)] = entry
    return dok


def _entry_product(da: dict, db: dict, shape: tuple) -> dict:
    """The entries of the product, as sympy's ``_eval_matrix_rmul`` forms
    them (``sum`` of the row's products, a product with a zero factor
    zero: no entry infinite), in row-major order."""
    rows, inner, cols = shape
    zero = sp.S.Zero
    dok: dict = {}
    for i in range(rows):
        for j in range(cols):
            products = []
            for k in range(inner):
                x, y = da.get((i, k), zero), db.get((k, j), zero)
                products.append(zero if x is zero or y is zero else x * y)
            entry = sum(products)
            if entry != 0:
                dok[(i, j)] = entry
    return dok


def named_product(
    a: sp.MatrixBase, b: sp.MatrixBase, name: Callable, *, finite_b: bool = False
) -> Any:
    """``(a * b).applyfunc(name)``, the same matrix with each entry named
    in the same order, without sympy's conversion of each product to a
    domain and its test of every entry for an infinity by ``0 * x``
    (which asks each new intermediate's assumptions).  ``finite_b``: the
    caller found :func:`finite_entries` of ``b`` (a matrix multiplied many
    times).

    sympy's product of two matrices of expressions is the class of the
    immutable one if either is (the other first rebuilt as one, from its
    entries in row-major order).  ``a * b`` is then, when ``a`` is
    immutable and ``b`` mutable, ``b.__rmul__(a)``, formed entry by entry
    in row-major order (:func:`_entry_product`); else the sparse product
    (``sdm_matmul_exraw``), which walks ``a``'s rows in its sparse order,
    for each the ``k`` of ``a``'s nonzero entries with a nonzero row of
    ``b`` ascending, and appends ``a[i, k] * b[k, j]`` to entry ``j`` in
    the order of ``b``'s row: each entry the ``Add`` of its products, the
    entries of a row in the order they were first met
    (:func:`_sparse_product`).  ``applyfunc`` then names the entries in
    that order (which numbers the intermediates), and the new matrix keeps
    it.  Where an entry might be infinite, both matrices are of numbers
    (sympy then multiplies in its integer or rational domain), or for other
    classes of matrices, sympy's own product is used."""
    kinds = (type(a), type(b))
    if not set(kinds) <= _DENSE or a.cols != b.rows:
        return (a * b).applyfunc(name)
    da, db = a.todok(), b.todok()
    if all(v.is_Rational for v in da.values()) and all(
        v.is_Rational for v in db.values()
    ):
        return (a * b).applyfunc(name)
    if not all(_zero_times_is_zero(v) for v in da.values()) or not (
        finite_b or all(_zero_times_is_zero(v) for v in db.values())
    ):
        return (a * b).applyfunc(name)
    cls = sp.ImmutableDenseMatrix if sp.ImmutableDenseMatrix in kinds else sp.Matrix
    if kinds == (sp.ImmutableDenseMatrix, sp.MutableDenseMatrix):
        dok = _entry_product(da, db, (a.rows, a.cols, b.cols))
    else:
        if type(a) is not cls:  # rebuilt in row-major order
            da = dict(sorted(da.items()))
        dok = _sparse_product(da, db)
    named = {v: name(v) for v in dok.values()}
    rows, cols = a.rows, b.cols
    if len(dok) < rows * cols and (zero := name(sp.S.Zero)) is not sp.S.Zero:
        flat = [zero] * (rows * cols)
        for (i, j), v in dok.items():
            flat[i * cols + j] = named[v]
        return cls(rows, cols, flat)
    return cls.from_dok(rows, cols, {ij: named[v] for ij, v in dok.items()})


#: sympy's infinities: a product of 0 and an entry known to be infinite is
#: ``nan``, which :func:`dot` does not form
_INFINITIES = (
    type(sp.S.Infinity),
    type(sp.S.NegativeInfinity),
    type(sp.S.ComplexInfinity),
    type(sp.S.NaN),
)


def exact_dot(a: Vector, b: Vector) -> Any:
    """``a & b``, exactly sympy's: :func:`dot` unless a measure number
    holds an infinity (only then can an entry be known infinite: the
    script's names are never declared infinite), else sympy's own.

    >>> from sympy.physics.vector import ReferenceFrame, dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [q, N.z])
    >>> a, b = u * N.x + q * A.y, 2 * A.x + sp.zoo * N.z
    >>> exact_dot(a, b) == a & b, exact_dot(b, a) == b & a
    (True, True)
    """
    if _holds_infinity(m for v in (a, b) for m, _frame in v.args):
        return a & b
    return dot(a, b)


def dot(a: Vector, b: Vector) -> Any:
    """``a & b`` of two vectors, as sympy forms it (for each component of
    ``a`` and each of ``b``, the row of ``b``'s measure numbers times the
    direction cosines times ``a``'s column, summed in turn), without
    sympy's test of each product's entries for an infinity.

    >>> from sympy.physics.vector import ReferenceFrame, dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [q, N.z])
    >>> a, b = u * N.x + q * A.y, 2 * A.x + u * N.z
    >>> dot(a, b) == a & b
    True
    """
    if Vector.simp:  # sympy then simplifies: its own
        return a & b
    out = sp.S.Zero
    for m1, f1 in a.args:
        for m2, f2 in b.args:
            out += _row_times(_row_times(list(m2), f2.dcm(f1)), m1)[0]
    return out


def cross(a: Vector, b: Vector) -> Vector:
    """``a ^ b`` of two vectors, as sympy forms it (each component of ``b``
    in its frame ``F``: ``a``'s measure numbers along ``F`` by the direction
    cosines, then the three-term products), without sympy's unit-vector dot
    products and 3x3 symbolic determinant.

    >>> from sympy.physics.vector import ReferenceFrame, dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [q, N.z])
    >>> a, b = u * N.x + q * A.y, 2 * A.x + u * N.z
    >>> cross(a, b) == a ^ b
    True
    """
    if not isinstance(b, Vector) or not isinstance(a, Vector):
        return a ^ b
    if not b.args:
        return Vector(0)
    out = []
    a_infinite = _holds_infinity(m1 for m1, _f1 in a.args)
    for m, f in b.args:
        parts = [(f.dcm(f1), m1) for m1, f1 in a.args]  # each frame's once
        # sympy's own products where a factor may be infinite (0 * oo: nan)
        infinite = a_infinite or _holds_infinity([m, *(d for d, _m1 in parts)])
        times = operator.mul if infinite else _times
        w = []
        for k in range(3):
            total = sp.S.Zero
            for d, m1 in parts:
                total += sp.Add(*[times(d[k, j], m1[j]) for j in range(3)])
            w.append(total)
        out.append(
            (
                sp.Matrix(
                    [
                        times(w[1], m[2]) - times(w[2], m[1]),
                        times(w[2], m[0]) - times(w[0], m[2]),
                        times(w[0], m[1]) - times(w[1], m[0]),
                    ]
                ),
                f,
            )
        )
    return Vector(out)


def ang_vel_in(b: ReferenceFrame, a: ReferenceFrame) -> Vector:
    """``b.ang_vel_in(a)``, the same vector: the sum of the angular
    velocities along sympy's path of frames from ``b`` to ``a``, in order.

    sympy finds that path (``_dict_list``) by listing every simple path
    from ``b`` (its time grows with their number: fast for a chain, slow
    for a model's many frames with angular velocities given between
    distant ones), and takes the first shortest.  :func:`frame_path` finds
    the same path by one breadth-first walk.

    >>> from sympy.physics.vector import ReferenceFrame, dynamicsymbols
    >>> q1, q2 = dynamicsymbols("q1 q2")
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [q1, N.z])
    >>> B = A.orientnew("B", "Axis", [q2, A.x])
    >>> ang_vel_in(B, N) == B.ang_vel_in(N)
    True
    """
    path = frame_path(b, a)
    if path is None:
        return b.ang_vel_in(a)  # sympy's error: no path
    out = Vector(0)
    for x, y in zip(path, path[1:], strict=False):
        out = add_vectors(out, x._ang_vel_dict[y])
    return out


#: sympy's zero measure numbers, which ``Vector`` drops (compared, never
#: changed)
_ZERO3 = sp.ImmutableMatrix([0, 0, 0])


def add_vectors(a: Vector, b: Any) -> Vector:
    """``a + b`` of a vector and a vector, the same ``Vector`` as sympy's
    ``Vector.__add__`` forms (``b`` zero: ``a`` itself; else the measure
    numbers of each frame summed in the order met, and a frame whose sum
    is zero left out), without its new zero matrix for each frame's test.

    >>> from sympy.physics.vector import ReferenceFrame, dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> N = ReferenceFrame("N")
    >>> A = N.orientnew("A", "Axis", [q, N.z])
    >>> a, b = u * N.x + q * A.y, 2 * A.x - u * N.x
    >>> add_vectors(a, b).args == (a + b).args
    True
    """
    if not isinstance(b, Vector):
        return a + b  # sympy's answer (0) or its error
    if not b.args:
        return a
    d: dict = {}
    for m, f in a.args + b.args:
        d[f] = d[f] + m if f in d else m
    out = Vector(0)
    out.args = [(m, f) for f, m in d.items() if m != _ZERO3]
    return out


def frame_path(b: ReferenceFrame, a: ReferenceFrame) -> list | None:
    """``b._dict_list(a, 1)``: the frames from ``b`` to ``a`` along given
    angular velocities, or None where there is no path.

    sympy lists the simple paths from ``b`` breadth first (each path's
    extensions in the order of its last frame's ``_ang_vel_dict``) and
    takes the first of the shortest that end at ``a``.  The first path to
    reach a frame in that list is the path of an ordinary breadth-first
    walk, in the same order, that keeps the first frame to reach each
    frame (a shortest path's beginning is a shortest path): so the first
    to reach ``a`` is sympy's."""
    parent: dict = {b: None}
    todo = deque([b])
    while todo and a not in parent:
        x = todo.popleft()
        for y in x._ang_vel_dict:
            if y not in parent:
                parent[y] = x
                todo.append(y)
    if a not in parent:
        return None
    path = [a]
    while path[-1] is not b:
        path.append(parent[path[-1]])
    path.reverse()
    return path


def dyadic_matrix(d: Dyadic, frame: ReferenceFrame) -> sp.Matrix:
    """``d.to_matrix(frame)``: read off the components when every unit
    vector of ``d`` is ``frame``'s (an inertia dyadic in its body's frame),
    else sympy's (unit-vector dot products).

    >>> from sympy.physics.vector import ReferenceFrame, outer
    >>> from sympy import symbols
    >>> a, b = symbols("a b")
    >>> N = ReferenceFrame("N")
    >>> d = a * outer(N.x, N.x) + b * outer(N.x, N.y) + a * outer(N.z, N.z)
    >>> dyadic_matrix(d, N) == d.to_matrix(N)
    True
    """
    if not all(
        len(v.args) == 1 and v.args[0][1] == frame
        for _, v1, v2 in d.args
        for v in (v1, v2)
    ):
        return d.to_matrix(frame)
    entries = [[sp.S.Zero] * 3 for _ in range(3)]
    for c, v1, v2 in d.args:
        m1, m2 = v1.args[0][0], v2.args[0][0]
        for i in range(3):
            if m1[i] != 0:
                for j in range(3):
                    if m2[j] != 0:
                        entries[i][j] += c * m1[i] * m2[j]
    return sp.Matrix(entries)


def frame_dt(
    v: Vector, frame: ReferenceFrame, scalar_dt: Callable[[Any], Any]
) -> Vector:
    """The time derivative of ``v`` in ``frame``, ``scalar_dt`` taking
    each measure number's: a component fixed in another frame ``B`` adds
    ``B``'s angular velocity in ``frame`` crossed with it (sympy's
    ``time_derivative``, whose scalar derivative is sympy's ``diff``)."""
    out = Vector(0)
    for m, f in v.args:
        out = add_vectors(out, _frame_vector(m.applyfunc(scalar_dt), f))
        if f != frame:
            out = add_vectors(out, cross(ang_vel_in(f, frame), _frame_vector(m, f)))
    return out


def _frame_vector(m: sp.MatrixBase, f: ReferenceFrame) -> Vector:
    """``Vector([(m, f)])``: zero when ``m`` is."""
    out = Vector(0)
    if m != _ZERO3:
        out.args = [(m, f)]
    return out


#: Expressions with more nodes, or more speeds, than these are not simplified
#: for display: the simplification is cosmetic and large models must stay fast.
SMALL_NODES = 160
SMALL_GENS = 6


def is_small(expr: Any, limit: int = SMALL_NODES) -> bool:
    """True if ``expr`` has at most ``limit`` nodes (stops counting early):
    the nodes ``sp.preorder_traversal(expr)`` yields, a shared subtree once
    per use, counted without its generators."""
    count = 0
    stack = [expr]
    while stack:
        e = stack.pop()
        count += 1
        if count > limit:
            return False
        if isinstance(e, sp.Basic):
            stack.extend(e.args)
        elif iterable(e):
            stack.extend(e)
    return True


def tidy(expr: Any, gens: Iterable[Any] = ()) -> Any:
    """A light, bounded simplification used for responses and results.

    With ``gens`` (speeds and their derivatives), the expression is collected
    on monomials of ``gens`` and each coefficient is simplified separately.
    """
    if not isinstance(expr, sp.Expr) or expr.is_number:
        return expr
    return _tidy(expr, gens)


class Tidier:
    """:func:`tidy` that forms each expression's result once: the model's
    (``model.tidier``), whose responses and results show the same measure
    numbers many times, at import and again in the transcript.  A result is
    a function of the expression and ``gens`` alone, so it is the same as
    :func:`tidy`'s."""

    __slots__ = ("_done",)

    def __init__(self) -> None:
        self._done: dict = {}

    def __call__(self, expr: Any, gens: Iterable[Any] = ()) -> Any:
        """``tidy(expr, gens)``, remembered."""
        if not isinstance(expr, sp.Expr) or expr.is_number:
            return expr
        key = (expr, tuple(gens))
        found = self._done.get(key)
        if found is None:
            found = self._done[key] = _tidy(expr, key[1])
        return found

    def vector(self, v: Any) -> Any:
        """:func:`tidy_vector` of ``v``, each measure number remembered."""
        return vmap(v, self)


def _tidy(expr: sp.Expr, gens: Iterable[Any]) -> Any:
    """:func:`tidy` of an expression that is no number."""
    if not is_small(expr):
        return expr  # cosmetic only: large models stay fast
    nodes = _nodes(expr)  # ``expr.has(g)``, one walk
    gens = [g for g in gens if g in nodes]
    if len(gens) > SMALL_GENS:
        return expr
    if gens:
        parts = _collect(sp.expand(expr), gens)
        return sp.Add(*[_tidy_one(c) * m for m, c in parts.items()])
    return _tidy_one(expr)


def _nodes(expr: sp.Expr) -> set:
    """``set(sp.preorder_traversal(expr))``, a shared subtree walked once."""
    nodes: set = set()
    stack = [expr]
    while stack:
        e = stack.pop()
        if e in nodes:
            continue
        nodes.add(e)
        if isinstance(e, sp.Basic):
            stack.extend(e.args)
        elif iterable(e):
            stack.extend(e)
    return nodes


def _collect(expr: sp.Expr, gens: list) -> dict:
    """``sp.collect(expr, gens, evaluate=False)``, the same dictionary.

    sympy first puts a dummy symbol for each generator that is not a symbol
    (speeds ``U(t)`` and their derivatives) with ``subs``, which compares
    every rebuilt argument with the old one, node by node.  When nothing in
    ``expr`` gives a substitution of those generators a meaning of its own
    (only sums, products, powers, numbers, symbols and functions such as
    ``sin``; every derivative one of the generators), ``subs`` rebuilds the
    same tree as ``xreplace`` does: that is used, with sympy's dummies made
    the same way, in the same number, and the same rest of ``collect``.
    """
    if not all(isinstance(g, AppliedUndef | sp.Derivative) for g in gens):
        return sp.collect(expr, gens, evaluate=False)
    if not _plain_for(expr, set(gens)):
        return sp.collect(expr, gens, evaluate=False)
    reps = dict(zip(gens, [sp.Dummy(**assumptions(g)) for g in gens], strict=True))
    parts = sp.collect(expr.xreplace(reps), [reps[g] for g in gens], evaluate=False)
    urep = {v: k for k, v in reps.items()}
    return {urep.get(k, k).xreplace(urep): v.xreplace(urep) for k, v in parts.items()}


def _plain_for(expr: sp.Expr, gens: set) -> bool:
    """Whether ``expr.subs`` of ``gens`` by symbols is ``xreplace``: no node
    of ``expr`` outside ``gens`` is a derivative or has a rule of its own
    for substituting a function (``Subs``, ``Piecewise``, ``Integral``...)."""
    stack = [expr]
    seen: set = set()
    while stack:
        e = stack.pop()
        if e in gens or e in seen:
            continue
        seen.add(e)
        if type(e)._eval_subs not in _PLAIN_SUBS or isinstance(e, sp.Derivative):
            return False
        stack.extend(e.args)
    return True


#: ``_eval_subs`` rules that leave a function replaced by a symbol to the
#: generic rebuild (``Pow``'s replaces its base, as the rebuild does)
_PLAIN_SUBS = frozenset(
    {
        sp.Basic._eval_subs,
        sp.Add._eval_subs,
        sp.Mul._eval_subs,
        sp.Pow._eval_subs,
        sp.Number._eval_subs,
        sp.Symbol._eval_subs,
        sp.exp._eval_subs,
        Application._eval_subs,
    }
)


def _tidy_one(expr: sp.Expr) -> sp.Expr:
    if not isinstance(expr, sp.Expr) or expr.is_number:
        return expr
    if expr.has(sp.sin, sp.cos):
        ops = sp.count_ops(expr)
        if ops <= TRIGSIMP_LIMIT:
            expr = _trig_tidied(expr, ops)
    return factor_terms(expr)


def _trig_tidied(expr: sp.Expr, ops: int) -> sp.Expr:
    """``new if sp.count_ops(new) <= ops else expr`` for ``new = _trig(expr)``
    (``ops`` is ``expr``'s count), without sympy's ``TR10i`` where it is
    known to change nothing (:func:`_tr10i_fixed`): ``new`` is then the
    expansion of ``expr``, and ``expr`` itself when that is already
    expanded (most measure numbers of a named velocity)."""
    try:
        ex = sp.expand(expr)
    except Exception:  # pragma: no cover - _trig's best effort: expr
        return expr
    if not _tr10i_fixed(ex):
        new = _trig(expr)
        return new if sp.count_ops(new) <= ops else expr
    if ex == expr:
        return expr
    return ex if sp.count_ops(ex) <= ops else expr


#: factors that ``TR10i`` (``trig_split``) can never read as a sine, a
#: cosine or a square root
_BLOCKING = (sp.Symbol, AppliedUndef, Intermediate, sp.Derivative)


def _tr10i_fixed(e: sp.Expr) -> bool:
    """Whether ``TR10i(e)`` is ``e`` and the undoing ``replace`` of
    :func:`_trig` finds nothing (no sine or cosine of an angle holding
    ``pi``).

    ``TR10i`` changes a sum only where ``trig_split(a, b, two=True)``
    succeeds for two of its terms: each of ``a`` and ``b``, once their
    common factors are divided out, must be a sine or cosine, times at
    most one more sine, cosine or square root and a number.  That fails
    when one of the two holds no sine or cosine at all, or has a factor
    (a symbol, a function of time, an intermediate, a derivative) that
    the other does not hold anywhere: that factor stays in its quotient.
    When that is so for every two terms of every sum in ``e``, no sum
    changes, and ``TR10i``'s ``bottom_up`` rebuilds nothing."""
    seen: set = set()
    stack = [e]
    while stack:
        x = stack.pop()
        if x in seen:
            continue
        seen.add(x)
        if isinstance(x, sp.sin | sp.cos) and x.args[0].has(sp.pi):
            return False
        if x.is_Add:
            trig = [a for a in x.args if a.has(sp.sin, sp.cos)]
            for i, a in enumerate(trig):
                for b in trig[i + 1 :]:
                    if not (_splits_never(a, b) or _splits_never(b, a)):
                        return False
        stack.extend(x.args)
    return True


def _splits_never(a: sp.Expr, b: sp.Expr) -> bool:
    """Whether ``a`` has a factor of :data:`_BLOCKING` that ``b`` does not
    hold anywhere (see :func:`_tr10i_fixed`)."""
    inside = None
    for f in sp.Mul.make_args(a):
        if isinstance(f, _BLOCKING):
            if inside is None:
                inside = _nodes(b)
            if f not in inside:
                return True
    return False


def factor_terms(expr: sp.Expr) -> sp.Expr:
    """``sp.factor_terms(expr)``: ``expr`` itself where that is known to
    change nothing (:func:`_factors_fixed`), else sympy's.  Used by
    :func:`tidy`, Factoring's rearranging and closed-form solutions.

    >>> x, y = sp.symbols("x y")
    >>> e = x * y - x
    >>> factor_terms(e) == sp.factor_terms(e), factor_terms(x - y) == x - y
    (True, True)
    """
    if _factors_fixed(expr):
        return expr
    return sp.factor_terms(expr)


def _plain_factor(f: Any) -> bool:
    """A plain atom (:func:`_plain_atom`), or the sine or cosine of one: a
    factor ``factor_terms`` leaves as it is (its content is 1, and nothing
    in it is a sum or a product); or a rational power of one of those or of
    a sum ``factor_terms`` leaves alone (``1/sqrt(1 - Z38**2)``, ``Z5**2``):
    ``factor_terms`` rebuilds a power from its base and exponent, and
    ``gcd_terms`` splits it into its base's root and an integer exponent
    (:func:`_factor_key` finds a base common to the terms of a sum)."""
    if isinstance(f, sp.sin | sp.cos):
        return _plain_atom(f.args[0])
    if f.is_Pow:
        b = f.base
        if not f.exp.is_Rational:
            return False
        if isinstance(b, sp.sin | sp.cos):
            return _plain_atom(b.args[0])
        return _plain_atom(b) or (b.is_Add and _factors_fixed(b))
    return _plain_atom(f)


def _factor_key(f: Any) -> Any:
    """What a factor of a term is compared by with the other terms'
    (:func:`_factors_fixed`): a power's base (``x`` and ``x**2`` share
    ``x``, which ``gcd_terms`` takes out), else the factor itself."""
    return f.base if f.is_Pow else f


def _plain_atom(f: Any) -> bool:
    """A symbol, a function of symbols (a function of time), its
    derivative by symbols, or an intermediate at such arguments (its
    number first): ``factor_terms`` rebuilds nothing inside (a function's
    argument may hold a sum it would factor: ``10*sin(2*pi*t + pi/6)``)."""
    if isinstance(f, sp.Symbol):
        return True
    if isinstance(f, AppliedUndef):
        return all(a.is_Symbol for a in f.args)
    if isinstance(f, sp.Derivative):
        return _plain_atom(f.expr) and all(v.is_Symbol for v in f.variables)
    if isinstance(f, Intermediate):
        args = f.args
        return bool(args) and args[0].is_Integer and all(map(_plain_atom, args[1:]))
    return False


def _monomial(term: Any) -> frozenset | None:
    """The factors (by :func:`_factor_key`) of a term that is a plain
    factor (:func:`_plain_factor`) or a product of plain factors and sums
    ``factor_terms`` leaves alone
    (:func:`_factors_fixed`), with -1 or no number: None for any other
    term.  ``-1`` times one sum alone is declined (sympy's ``Mul`` of the
    two would distribute it)."""
    if _plain_factor(term):
        return frozenset((_factor_key(term),))
    if not term.is_Mul:
        return None
    args = term.args
    if args[0] is sp.S.NegativeOne:
        args = args[1:]
        if len(args) == 1 and args[0].is_Add:
            return None
    if all(_plain_factor(f) or _factors_fixed(f) for f in args) and _in_order(args):
        return frozenset(map(_factor_key, args))
    return None


def _in_order(args: tuple) -> bool:
    """Whether ``args`` are in the order sympy's ``Add`` and ``Mul`` sort
    them (``Basic.compare``), which ``factor_terms`` rebuilds them in."""
    return all(sp.Basic.compare(a, b) < 0 for a, b in zip(args, args[1:], strict=False))


def _factors_fixed(expr: sp.Expr) -> bool:
    """Whether ``sp.factor_terms(expr)`` is ``expr``: for a term as in
    :func:`_monomial` (its content is 1), or a sum of such terms (and the
    number 1) that are not all negative (else ``-1`` is taken out) with no
    factor common to all (else it is taken out)."""
    if not expr.is_Add:
        return _monomial(expr) is not None
    if not _in_order(expr.args):
        return False
    common = None
    negative = True
    for term in expr.args:
        # the number 1 is a term with no factor (its content is 1)
        factors = frozenset() if term is sp.S.One else _monomial(term)
        if factors is None:
            return False
        common = factors if common is None else common & factors
        negative = negative and term.is_Mul and term.args[0] is sp.S.NegativeOne
    return not common and not negative


def _trig(expr: sp.Expr) -> sp.Expr:
    """Combine products of sines and cosines of different angles
    (``cos(a)*cos(b) + sin(a)*sin(b)`` -> ``cos(a - b)``), cheaply."""
    from sympy.simplify.fu import TR10i

    def combine(e: sp.Expr) -> sp.Expr:
        out = TR10i(sp.expand(e))
        # TR10i also writes sin(x) + cos(x) as sqrt(2)*sin(x + pi/4): undo that
        # (Degrees ON would misread the pi, and it is not what Autolev prints)
        return out.replace(
            lambda f: isinstance(f, sp.sin | sp.cos) and f.args[0].has(sp.pi),
            lambda f: sp.expand_trig(f),
        )

    try:
        return combine(expr)
    except Exception:  # pragma: no cover - best effort
        return expr


def tidy_vector(v: Any) -> Any:
    return vmap(v, tidy)


def vdot(a: Any, b: Any) -> Any:
    """Autolev ``Dot``: vectors, dyadics (either side) or plain scalars."""
    if isinstance(a, Vector) and isinstance(b, Vector):
        return dot(a, b)
    if isinstance(a, Vector | Dyadic) and isinstance(b, Vector | Dyadic):
        return a & b
    if isinstance(a, Vector | Dyadic):
        if b == 0:
            return sp.Integer(0)
        raise TypeError("Dot of a vector and a scalar")
    if isinstance(b, Vector | Dyadic):
        if a == 0:
            return sp.Integer(0)
        raise TypeError("Dot of a scalar and a vector")
    return sp.sympify(a) * sp.sympify(b)


class VectorMatrix:
    """A matrix of vectors (``[V1>; 2*V2>]``); ``Dot`` makes it scalars."""

    def __init__(self, rows: list[list[Vector]]) -> None:
        self.rows = rows

    def __repr__(self) -> str:
        return f"VectorMatrix({self.rows!r})"

    @property
    def shape(self) -> tuple[int, int]:
        return len(self.rows), len(self.rows[0]) if self.rows else 0

    def __getitem__(self, index: Any) -> Vector:
        """``VCA[1]`` (row by row, as a matrix's single index counts) or
        ``VCA[i,j]``, with Python's 0-based indices."""
        rows, cols = self.shape
        if isinstance(index, tuple):
            i, j = (int(k) for k in index)
        else:
            i, j = divmod(int(index), cols)
        if not (0 <= i < rows and 0 <= j < cols):
            raise IndexError(
                f"element {i + 1},{j + 1} of a {rows}x{cols} matrix of vectors"
            )
        return self.rows[i][j]


def vdot_matrix(a: Any, b: Any) -> sp.Matrix:
    """``Dot`` with a matrix of vectors on either side: elementwise."""
    if isinstance(a, VectorMatrix) and isinstance(b, VectorMatrix):
        raise TypeError("Dot of two matrices of vectors")
    if isinstance(a, VectorMatrix):
        return sp.Matrix([[vdot(e, b) for e in row] for row in a.rows])
    return sp.Matrix([[vdot(a, e) for e in row] for row in b.rows])


def unit_dyadic(frame: ReferenceFrame) -> Dyadic:
    """``1>>`` in terms of ``frame``'s unit vectors."""
    return (frame.x | frame.x) + (frame.y | frame.y) + (frame.z | frame.z)


def is_unit_dyadic(d: Dyadic) -> bool:
    """True if ``d`` is ``1>>``, written in terms of a single frame."""
    frames = {f for _, a, b in d.args for f in _frames_of(a) | _frames_of(b)}
    if len(frames) != 1:
        return False
    m = d.to_matrix(frames.pop())
    return all(sp.simplify(x) == 0 for x in m - sp.eye(3))


def _frames_of(v: Vector) -> set:
    return {frame for _, frame in v.args}


def axis_dcm(axis: sp.Matrix, angle: Any) -> sp.Matrix:
    """``A_B`` for B rotated by ``angle`` about the direction whose A measure
    numbers are ``axis`` (Rodrigues' rotation formula)."""
    k = sp.Matrix(axis)
    norm = sp.sqrt(sum(x**2 for x in k))
    # Tidy a numeric axis (N1>, [1;1;0]); a symbolic one (parameters of a
    # musculoskeletal model) is left alone: simplify() there takes minutes.
    tidy = sp.simplify if all(x.is_number for x in k) else (lambda e: e)
    k = (k / norm).applyfunc(tidy)
    c, s = sp.cos(angle), sp.sin(angle)
    m = c * sp.eye(3) + (1 - c) * k * k.T + s * _skew(k)
    return m.applyfunc(tidy)


def vcross(a: Any, b: Any) -> Any:
    """Autolev ``Cross`` of vectors (or a vector and a dyadic)."""
    if isinstance(a, Vector | Dyadic) and isinstance(b, Vector | Dyadic):
        return a ^ b
    if (not isinstance(a, Vector | Dyadic) and a == 0) or (
        not isinstance(b, Vector | Dyadic) and b == 0
    ):
        return Vector(0)
    raise TypeError("Cross needs two vectors")


# ------------------------------------------------------------ rotations


def _skew(v: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def simprot_dcm(axis: int, angle: Any) -> sp.Matrix:
    """``A_B`` for ``Simprot(A, B, axis, angle)`` (axis in +-1, +-2, +-3)."""
    if axis not in (1, 2, 3, -1, -2, -3):
        raise ValueError(f"Simprot axis must be 1, 2, 3, -1, -2 or -3, not {axis}")
    if axis < 0:
        angle = -angle
    k = abs(axis) - 1
    c, s = sp.cos(angle), sp.sin(angle)
    m = sp.eye(3)
    i, j = (k + 1) % 3, (k + 2) % 3
    m[i, i] = c
    m[j, j] = c
    m[i, j] = -s
    m[j, i] = s
    return m


def rotation_dcm(kind: str, qs: list[Any]) -> sp.Matrix:
    """``A_B`` for ``Dircos(A, B, kind, q1, q2, q3[, q4])``.

    ``kind`` is ``BODYijk``, ``SPACEijk``, ``EULER`` (4 parameters) or
    ``RODRIGUES`` (3 parameters)."""
    kind = kind.upper()
    if kind.startswith(("BODY", "SPACE")):
        order = kind[4:] if kind.startswith("BODY") else kind[5:]
        if len(order) != 3 or any(ch not in "123" for ch in order):
            raise ValueError(f"unknown rotation sequence {kind}")
        if order[0] == order[1] or order[1] == order[2]:
            raise ValueError(f"{kind}: consecutive axes must differ")
        if len(qs) != 3:
            raise ValueError(f"{kind} needs 3 angles")
        mats = [simprot_dcm(int(ch), q) for ch, q in zip(order, qs, strict=True)]
        if kind.startswith("BODY"):
            return mats[0] * mats[1] * mats[2]
        return mats[2] * mats[1] * mats[0]
    if kind == "EULER":
        if len(qs) != 4:
            raise ValueError("EULER needs 4 Euler parameters e1, e2, e3, e4")
        # Autolev's form (its generated programs write A_B[1,1] as
        # 1 - 2*e2^2 - 2*e3^2): the unit norm of the parameters is used on
        # the diagonal, so e4 appears only off the diagonal.
        e = sp.Matrix(qs[:3])
        e4 = qs[3]
        return (
            (1 - 2 * (e.T * e)[0]) * sp.eye(3) + 2 * e * e.T + 2 * e4 * _skew(e)
        ).applyfunc(sp.expand)
    if kind == "RODRIGUES":
        if len(qs) != 3:
            raise ValueError("RODRIGUES needs 3 Rodrigues parameters")
        r = sp.Matrix(qs)
        rr = (r.T * r)[0]
        return ((1 - rr) * sp.eye(3) + 2 * r * r.T + 2 * _skew(r)) / (1 + rr)
    raise ValueError(f"unknown orientation type {kind}")


def angvel_from_dcm(dcm: sp.Matrix) -> list[Any]:
    """Measure numbers in ``B`` of ``W_B_A>`` given ``A_B`` (functions of t)."""
    c = sp.Matrix(dcm)
    w = c.T * c.diff(t)
    return [simplify_small(w[2, 1]), simplify_small(w[0, 2]), simplify_small(w[1, 0])]


def simplify_small(expr: Any) -> Any:
    """Thorough simplification for the few, small expressions of rotation
    kinematics (``trigsimp`` for angles, ``factor`` for parameters)."""
    expr = sp.sympify(expr)
    if expr.has(sp.sin, sp.cos):
        return sp.factor_terms(sp.trigsimp(sp.expand(expr)))
    return sp.factor_terms(sp.factor(sp.cancel(expr)))


def euler_parameter_angvel(es: list[Any]) -> list[Any]:
    """The ``B`` measure numbers of ``W_B_A>`` from Euler parameters and their
    rates: ``w = 2*(e4*e' - e4'*e - e x e')`` (Kane, Likins and Levinson,
    *Spacecraft Dynamics*), the inverse of :func:`euler_parameter_rates`."""
    e = sp.Matrix(es[:3])
    e4 = es[3]
    de = e.diff(t)
    w = 2 * (e4 * de - sp.diff(e4, t) * e - e.cross(de))
    return [sp.expand(x) for x in w]


def euler_parameter_rates(es: list[Any], w: list[Any]) -> list[Any]:
    """``e1'..e4'`` from the ``B`` measure numbers ``w`` of ``W_B_A>``."""
    e1, e2, e3, e4 = es
    w1, w2, w3 = w
    half = sp.Rational(1, 2)
    return [
        half * (w1 * e4 - w2 * e3 + w3 * e2),
        half * (w1 * e3 + w2 * e4 - w3 * e1),
        half * (-w1 * e2 + w2 * e1 + w3 * e4),
        -half * (w1 * e1 + w2 * e2 + w3 * e3),
    ]


def frame_vector(frame: ReferenceFrame, measures: Iterable[Any]) -> Vector:
    m = list(measures)
    if len(m) != 3:
        raise ValueError(f"a vector needs 3 measure numbers, not {len(m)}")
    return m[0] * frame.x + m[1] * frame.y + m[2] * frame.z


def frame_dyadic(frame: ReferenceFrame, m: sp.Matrix) -> Dyadic:
    """The dyadic whose measure numbers in ``frame`` are ``m``: the sum of
    ``m[i, j] * (u_i | u_j)`` over the nonzero entries, in order, as sympy
    forms it (each term's coefficient ``m[i, j] * 1``, the pairs distinct),
    without the outer products' nine-term sums and ``Dyadic``'s comparison
    of each pair with the earlier ones by their printed text.

    >>> from sympy.physics.vector import ReferenceFrame
    >>> a, b = sp.symbols("a b")
    >>> N = ReferenceFrame("N")
    >>> m = sp.Matrix([[a, 0, 0], [0, b, 1], [0, 0, 0]])
    >>> frame_dyadic(N, m).args == (a * (N.x | N.x) + b * (N.y | N.y) + (N.y | N.z)).args
    True
    """
    units = (frame.x, frame.y, frame.z)
    out = Dyadic(0)
    out.args = [
        (m[i, j] * sp.S.One, units[i], units[j])
        for i in range(3)
        for j in range(3)
        if m[i, j] != 0
    ]
    return out
