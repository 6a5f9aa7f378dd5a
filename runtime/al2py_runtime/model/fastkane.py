"""Kane's method with intermediate variables: the runtime's one engine.

Kane's equations are formed here, in one way, for every user of the
runtime: a script's ``Fr()`` and ``FrStar()`` (:mod:`.equations`), the
``KanesMethod`` a module exports (:mod:`.kane`) and :class:`FastKane`, the
same derivation for models written directly in ``sympy.physics.mechanics``.
Each names its short subexpressions in an
:class:`~al2py_runtime.intermediates.autoz.Intermediates` book (Autolev's
``AutoZ``).

How it stays small (see ``docs/intermediates.md``):

* Every direction-cosine matrix between two frames is a product of the
  frames' own (short) matrices along the orientation tree; each entry of each
  product is named (:func:`named_dcm`).
* Every velocity and angular velocity is kept as an explicit *linear form* in
  the generalized speeds, ``v = sum_r V_r u_r + V_t``, with each measure
  number of each ``V_r`` (a partial velocity) named (:func:`linear_form`).
  Each component is split in its own frame, then rotated, so nothing large
  is formed and split (:func:`measure_split`).
* The time derivative of an intermediate is another intermediate, defined by
  the chain rule through its (short) definition.  Accelerations are then
  ``a = sum_r V_r u_r' + sum_r V_r' u_r + V_t'`` with no differentiation of
  anything large (:func:`form_rate`).
* The rows are dot products of these measure numbers, each named
  (:func:`inertia_rows`, :func:`active_rows`).
* Nothing is ever expanded or simplified.

The formulas are those of ``KanesMethod`` (same rows, same signs, the same
reduction by the dependent speeds), so :class:`FastKane`'s ``mass_matrix``
and ``forcing`` equal ``KanesMethod``'s once the intermediates are
substituted.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.core.parameters import global_parameters
from sympy.physics.mechanics import (
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
)
from sympy.physics.vector import Vector
from sympy.printing.numpy import NumPyPrinter

from ..intermediates.autoz import Intermediate, Intermediates, product_with
from .arrange import split_linear_named
from .kinematics import ang_vel_in

__all__ = [
    "FastKane",
    "Motion",
    "Splits",
    "active_rows",
    "form_rate",
    "inertia_rows",
    "linear_form",
    "measure_split",
    "named_dcm",
    "named_measures",
    "times",
]

_T = dynamicsymbols._t

#: ``dcm(A, B)``: the direction cosines of ``A`` and ``B`` (``A``'s measure
#: numbers are ``dcm(A, B)`` times ``B``'s), entries named.
Dcm = Callable[[ReferenceFrame, ReferenceFrame], Any]


def _sympy_dcm(a: ReferenceFrame, b: ReferenceFrame) -> Any:
    return a.dcm(b)


def _matmul(a: sp.Matrix, b: sp.Matrix) -> sp.Matrix:
    """Plain product (sympy's own converts large entries to a domain first)."""
    return sp.Matrix(
        a.rows,
        b.cols,
        lambda i, j: sp.Add(
            *[a[i, k] * b[k, j] for k in range(a.cols) if a[i, k] != 0 and b[k, j] != 0]
        ),
    )


@dataclass(frozen=True)
class Motion:
    """A velocity (or an angular velocity) and its time derivative, as
    measure numbers in one frame: the shape in which Kane's equations are
    formed (:func:`inertia_rows`, :func:`active_rows`).

    ``partials[r]``: the partial velocity for row ``r`` (three entries, or
    ``None`` for zero); ``rates[s]``: the coefficient of speed ``s``'s
    derivative in the time derivative (``None``: zero); ``rest``: the rest
    of the time derivative.

    >>> m = Motion(partials=[[1, 0, 0]], rates=[[1, 0, 0]], rest=[0, 0, 0])
    >>> m.partials[0]
    [1, 0, 0]
    """

    partials: Sequence[Sequence[Any] | None]
    rates: Sequence[Sequence[Any] | None] = ()
    rest: Sequence[Any] = (0, 0, 0)


def times(a: Any, b: Any) -> Any:
    """``a * b`` as sympy forms it.  For an intermediate and a different
    intermediate, a symbol, a function of time or a derivative, or a
    rational number (not 0 or 1) and an intermediate -- most products of
    named measure numbers -- ``Mul.flatten`` only puts the number first
    and sorts the factors by ``Basic.compare`` (which
    :meth:`Intermediate.compare` is): that is done directly, without
    sympy's general case and its cache.

    >>> book = Intermediates()
    >>> q1, q2 = dynamicsymbols("q1 q2")
    >>> z1, z2 = book.name(sp.sin(q1) * q2 + q1), book.name(sp.cos(q2) * q1 + q2)
    >>> times(z2, z1) == z1 * z2, times(-2, z1) == -2 * z1
    (True, True)
    """
    if isinstance(a, Intermediate):
        if isinstance(b, _FACTOR):
            if a != b and global_parameters.evaluate:
                if a.is_commutative and b.is_commutative:
                    pair = (a, b) if a.compare(b) < 0 else (b, a)
                    return sp.Mul._from_args(pair, is_commutative=True)
        elif getattr(b, "is_Rational", False):
            return _rational_times(b, a)
    elif isinstance(b, Intermediate):
        if isinstance(a, _FACTOR):
            return times(b, a)
        if getattr(a, "is_Rational", False):
            return _rational_times(a, b)
    if isinstance(b, _FACTOR) and getattr(a, "is_Mul", False):
        return _product_times(a, b)
    if isinstance(a, _FACTOR) and getattr(b, "is_Mul", False):
        return _product_times(b, a)
    return a * b


def _product_times(m: Any, x: Any) -> Any:
    """``m * x``, ``m`` a product with an intermediate among its factors:
    ``Mul(*args[:i], f * x, *args[i + 1:])`` for that factor ``f``
    (:func:`~al2py_runtime.intermediates.autoz.product_with`, which forms
    what sympy's ``Mul`` would, or asks it)."""
    if not global_parameters.evaluate or not m.is_commutative:
        return m * x
    for i, f in enumerate(m.args):
        if isinstance(f, Intermediate):
            d = times(f, x)
            if d.is_Mul or isinstance(d, _FACTOR):
                return product_with(m.args, i, d)
            break
    return m * x


#: factors that are their own base and not numbers: a product of one of
#: them and an intermediate is the two sorted
_FACTOR = (Intermediate, AppliedUndef, sp.Derivative, sp.Symbol)


def _rational_times(c: Any, z: Any) -> Any:
    """``c * z``: ``c`` rational, ``z`` an intermediate."""
    if c is sp.S.Zero or c is sp.S.One or not global_parameters.evaluate:
        return c * z
    if not z.is_commutative:
        return c * z
    return sp.Mul._from_args((c, z), is_commutative=True)


def dot3(a: Sequence[Any], b: Sequence[Any]) -> Any:
    """The dot product of two measure-number triples (zeros skipped)."""
    return sp.Add(
        *[times(x, y) for x, y in zip(a, b, strict=True) if x != 0 and y != 0]
    )


def cross3(a: Sequence[Any], b: Sequence[Any]) -> list[Any]:
    """The cross product of two measure-number triples."""
    return [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]


# ---------------------------------------------------------------- kinematics


def named_dcm(
    x: ReferenceFrame, f: ReferenceFrame, book: Intermediates, cache: dict
) -> sp.Matrix:
    """``X_F`` (``x``'s measure numbers are ``X_F`` times ``f``'s): the
    product of the frames' own matrices along the orientation tree, each
    entry of each product named in ``book``; ``cache`` keeps every pair
    formed (and its transpose).

    >>> from sympy.physics.mechanics import ReferenceFrame, dynamicsymbols
    >>> q1, q2 = dynamicsymbols("q1 q2")
    >>> n = ReferenceFrame("N")
    >>> a = n.orientnew("A", "Axis", [q1, n.z])
    >>> b = a.orientnew("B", "Axis", [q2, a.z])
    >>> book = Intermediates("z")
    >>> m = named_dcm(b, n, book, {})
    >>> sp.simplify(book.expand(m) - b.dcm(n))
    Matrix([
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0]])
    """
    if x is f:
        return sp.eye(3)
    found = cache.get((x, f))
    if found is not None:
        return found
    if f in x._dcm_dict:
        out = x.dcm(f).applyfunc(book.name)
    else:
        path = x._dict_list(f, 0)
        left = named_dcm(x, path[-2], book, cache)
        right = named_dcm(path[-2], f, book, cache)
        out = sp.Matrix(
            3,
            3,
            lambda i, j: book.name(
                sp.Add(*[left[i, k] * right[k, j] for k in range(3)])
            ),
        )
    cache[(x, f)] = out
    cache[(f, x)] = out.T
    return out


class Splits:
    """What :func:`measure_split` has formed with one book, kept by the
    book's owner (:class:`FastKane`, the script's model) and passed in.

    ``exprs``: (expression, xs, book.rates, book.exclude) -> the expression's
    ``linear_terms`` in ``xs`` after :meth:`Intermediates.name_linear`.
    Naming is a function of the expression once the book has named it (an
    intermediate is never unnamed), given the book's ``rates`` and
    ``exclude``, so a measure number split again -- the same velocity for
    ``Fr()``'s partial velocities and ``FrStar()``'s linear forms, two loads
    at one point, a velocity formed again from the same terms -- is answered
    with the same result, and no intermediate is made again.

    ``vectors``: (a vector's components with their direction cosines, xs,
    book.rates, book.exclude) -> :func:`measure_split`'s answer (the same
    rule: nothing is named again)."""

    __slots__ = ("book", "exprs", "vectors")

    def __init__(self, book: Intermediates) -> None:
        self.book = book
        self.exprs: dict = {}
        self.vectors: dict = {}


_NONE = object()


def _split_named(
    expr: Any, xs: tuple, book: Intermediates, memo: Splits
) -> tuple[list[Any], Any] | None:
    """``linear_terms(book.name_linear(expr, xs), xs)``
    (:meth:`Intermediates.name_linear_terms`), once in ``memo`` for each
    expression (see :class:`Splits`)."""
    key = (expr, xs, book.rates, book.exclude)
    try:
        return memo.exprs[key]
    except KeyError:
        pass
    found = memo.exprs[key] = book.name_linear_terms(expr, xs)
    return found


def _memo_of(book: Intermediates, memo: Splits | None) -> Splits:
    """``memo`` (the book's), or a new one for this call alone."""
    if memo is None:
        return Splits(book)
    if memo.book is not book:
        raise ValueError("a Splits memo is used with another book than its own")
    return memo


def measure_split(
    vec: Vector,
    frame: ReferenceFrame,
    xs: Sequence[Any],
    book: Intermediates,
    dcm: Dcm = _sympy_dcm,
    memo: Splits | None = None,
) -> list[tuple[list[Any], Any]] | None:
    """``vec``'s measure numbers in ``frame`` as ``sum c_j x_j + rest``,
    each ``c_j`` and ``rest`` named: ``(coefficients, rest)`` per measure
    number, or None when one is not linear in ``xs``.

    Each component is split in its own frame, then rotated with the
    direction cosines ``dcm(frame, f)``, so no large expression (a vector
    expressed in another frame) is formed and split.  ``memo`` is the
    book's :class:`Splits` (kept by the book's owner; without one, nothing
    is remembered beyond this call).

    >>> from sympy.physics.mechanics import ReferenceFrame, dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> n = ReferenceFrame("N")
    >>> a = n.orientnew("A", "Axis", [q, n.z])
    >>> measure_split(u * a.x + n.y, n, [u], Intermediates())
    [([cos(q(t))], 0), ([sin(q(t))], 1), ([0], 0)]
    """
    xs = tuple(xs)
    memo = _memo_of(book, memo)
    if dcm is not _sympy_dcm:  # it may name (in turn with the components)
        return _measure_split(vec, frame, xs, book, dcm, memo)
    # sympy's direction cosines name nothing: the same vector split again
    # (Fr()'s partial velocities and FrStar()'s linear forms of one
    # velocity) has the same answer, and nothing to name
    try:
        cosines = {f: frame.dcm(f) for _, f in vec.args}
    except ValueError:  # frames not connected: raised in turn, as it is met
        return _measure_split(vec, frame, xs, book, dcm, memo)
    key = (
        tuple((tuple(comps), f, tuple(cosines[f])) for comps, f in vec.args),
        xs,
        book.rates,
        book.exclude,
    )
    found = memo.vectors.get(key, _NONE)
    if found is _NONE:
        found = _measure_split(vec, frame, xs, book, lambda _, f: cosines[f], memo)
        memo.vectors[key] = found
    return None if found is None else [(list(c), r) for c, r in found]


def _measure_split(
    vec: Vector,
    frame: ReferenceFrame,
    xs: tuple,
    book: Intermediates,
    dcm: Dcm,
    memo: Splits,
) -> list[tuple[list[Any], Any]] | None:
    """:func:`measure_split`, formed."""
    terms: list[tuple[list[list[Any]], list[Any]]] = [
        ([[] for _ in xs], []) for _ in range(3)
    ]
    for comps, f in vec.args:
        m = dcm(frame, f)
        for k in range(3):
            if comps[k] == 0:
                continue
            split = _split_named(comps[k], xs, book, memo)
            if split is None:
                return None
            for i in range(3):
                c = m[i, k]
                if c == 0:
                    continue
                c = book.name(c)
                coefs, rest = terms[i]
                for j, x in enumerate(split[0]):
                    if x != 0:
                        coefs[j].append(times(c, x))
                if split[1] != 0:
                    rest.append(times(c, split[1]))
    return [
        ([book.name(sp.Add(*c)) for c in coefs], book.name(sp.Add(*rest)))
        for coefs, rest in terms
    ]


def named_measures(
    vec: Vector,
    frame: ReferenceFrame,
    book: Intermediates,
    dcm: Dcm = _sympy_dcm,
    memo: Splits | None = None,
) -> list[Any]:
    """``vec``'s three measure numbers in ``frame``, named (formed
    component by component, as :func:`measure_split`)."""
    split = measure_split(vec, frame, [], book, dcm, memo)
    assert split is not None  # nothing to be linear in
    return [rest for _, rest in split]


def linear_form(
    vec: Vector,
    frame: ReferenceFrame,
    speeds: Sequence[Any],
    book: Intermediates,
    dcm: Dcm = _sympy_dcm,
    memo: Splits | None = None,
) -> tuple[list[list[Any]], list[Any]] | None:
    """``vec`` (a velocity or an angular velocity) as ``(columns, rest)``:
    for each speed its three named measure numbers in ``frame`` (the
    partial velocity), and the rest; None when it is not linear in the
    speeds."""
    columns: list[list[Any]] = [[sp.S.Zero] * 3 for _ in speeds]
    rest: list[Any] = [sp.S.Zero] * 3
    if vec == Vector(0):
        return columns, rest
    split = measure_split(vec, frame, speeds, book, dcm, memo)
    if split is None:
        return None
    for i, (coefs, r) in enumerate(split):
        for col, c in zip(columns, coefs, strict=True):
            col[i] = c
        rest[i] = r
    return columns, rest


def form_rate(
    form: tuple[Sequence[Sequence[Any]], Sequence[Any]],
    speeds: Sequence[Any],
    book: Intermediates,
    rate: Callable[[Any], Any],
    memo: dict,
) -> list[Any]:
    """The derivative, in the form's frame, of the vector given by its
    linear form ``(columns, rest)`` in ``speeds`` is
    ``sum c_j u_j' + sum c_j' u_j + rest'``: the coefficients of the
    speeds' derivatives are the columns themselves, and this returns the
    other terms, ``sum c_j' u_j + rest'``, for each measure number.
    ``rate(x)`` is the derivative of the variable ``x``
    (:meth:`Intermediates.time_derivative`, whose ``memo`` belongs to
    ``rate``).

    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> q, u = dynamicsymbols("q u")
    >>> rate = lambda x: u if x == q else sp.Derivative(x, _T)
    >>> zero = sp.S.Zero
    >>> form_rate(([[sp.cos(q), zero, zero]], [zero] * 3), [u], Intermediates(), rate, {})
    [-u(t)**2*sin(q(t)), 0, 0]
    """
    columns, rest = form
    out = []
    for i in range(3):
        terms = [book.time_derivative(rest[i], rate, memo)]
        for col, u in zip(columns, speeds, strict=True):
            c = col[i]
            if c != 0:
                terms.append(times(book.time_derivative(c, rate, memo), u))
        out.append(sp.Add(*terms))
    return out


# ---------------------------------------------------------------- the rows


def inertia_rows(
    translations: Iterable[tuple[Any, Motion]],
    rotations: Iterable[tuple[Sequence[Sequence[Any]], Sequence[Any], Motion]],
    rows: int,
    columns: int,
    name: Any,
) -> tuple[list[list[Any]], list[Any]]:
    """Kane's generalized inertia forces, the one place they are formed (a
    script's ``FrStar()`` and :class:`FastKane` both call it):
    ``Fr*[r] = -(sum_s M[r][s] u_s' + N[r])``; returns ``(M, N)``.

    ``translations``: ``(mass, motion of the mass center)``, measure numbers
    in the inertial frame; ``rotations``: ``(central inertia matrix, angular
    velocity, motion)`` with measure numbers in the body's frame (there the
    rate of the angular velocity is the angular acceleration).  Each dot
    product is named by ``name``.

    >>> M, N = inertia_rows([(2, Motion([[1, 0, 0]], [[1, 0, 0]], [0, 3, 0]))],
    ...                     [], 1, 1, lambda e: e)
    >>> M, N
    ([[2]], [0])
    """
    mm: list[list[Any]] = [[sp.S.Zero] * columns for _ in range(rows)]
    non: list[Any] = [sp.S.Zero] * rows
    for mass, mo in translations:
        for r, vr in enumerate(mo.partials):
            if vr is None:
                continue
            for s, a in enumerate(mo.rates):
                if a is not None:
                    mm[r][s] += times(mass, name(dot3(vr, a)))
            non[r] += times(mass, name(dot3(vr, mo.rest)))
    for imat, omega, mo in rotations:
        i_omega = [name(dot3(imat[i], omega)) for i in range(3)]
        torque = [
            name(dot3(imat[i], mo.rest) + c)
            for i, c in enumerate(cross3(omega, i_omega))
        ]
        iw = [
            None if a is None else [name(dot3(imat[i], a)) for i in range(3)]
            for a in mo.rates
        ]
        for r, wr in enumerate(mo.partials):
            if wr is None:
                continue
            for s, a in enumerate(iw):
                if a is not None:
                    mm[r][s] += name(dot3(wr, a))
            non[r] += name(dot3(wr, torque))
    return mm, non


def active_rows(
    loads: Iterable[tuple[Sequence[Any], Any]],
    rows: int,
    name: Any,
    dot: Callable[[Any, Any], Any] = dot3,
) -> list[Any]:
    """Kane's generalized active forces, ``Fr[r] = sum V_r . F``: each load
    is ``(partials, force)``, the partial velocities (or partial angular
    velocities) of where it acts, per row (``None``: zero), and the force
    (or torque), all as measure numbers in one frame -- or, with another
    ``dot``, as sympy vectors (a script's ``Fr()`` with ``AutoZ OFF``, whose
    rows keep the script's form).

    >>> import sympy as sp
    >>> m, g = sp.symbols("m g")
    >>> active_rows([([[0, 1, 0], None], [0, -m * g, 0])], 2, lambda e: e)
    [-g*m, 0]
    """
    fr: list[Any] = [sp.S.Zero] * rows
    for partials, force in loads:
        for r, vr in enumerate(partials):
            if vr is not None:
                fr[r] += name(dot(vr, force))
    return fr


def _nonzero(columns: Iterable[Sequence[Any]]) -> list[Sequence[Any] | None]:
    return [c if any(x != 0 for x in c) else None for c in columns]


# ---------------------------------------------------------------- FastKane


class FastKane:
    """Kane's equations of motion with intermediate variables.

    Parameters are those of ``KanesMethod`` (``frame``, ``q_ind``, ``u_ind``,
    ``kd_eqs``, ``q_dependent``, ``configuration_constraints``,
    ``u_dependent``, ``velocity_constraints``, ``acceleration_constraints``,
    ``u_auxiliary``), plus ``bodies`` and ``loads`` (or call
    :meth:`kanes_equations` later, as with ``KanesMethod``) and ``prefix``,
    the stem of the intermediates' names.

    After :meth:`kanes_equations`:

    * ``mass_matrix``, ``forcing`` (``KanesMethod``'s: the reduced dynamic rows
      followed by the acceleration constraints), ``mass_matrix_kin``,
      ``forcing_kin``, ``mass_matrix_full``, ``forcing_full`` and
      ``auxiliary_eqs``, written with intermediates: plain symbols ``z1``,
      ``z2``, ...;
    * ``intermediates``: the ordered list of ``(symbol, expression)``; each
      expression uses only coordinates, speeds, constants and earlier
      symbols, so numeric code evaluates them in order;
    * :meth:`substitute` gives fully substituted expressions;
    * :meth:`numeric` builds a numeric function that evaluates in order.

    The derivation is the runtime's own (the functions of this module, the
    intermediates in an :class:`~al2py_runtime.intermediates.autoz.Intermediates`
    book, :attr:`book`), the one that forms a converted script's ``Fr()``
    and ``FrStar()``.

    Limitations: masses and inertia dyadics must be constant (no
    ``dynamicsymbols``), as in almost every model; ``KanesMethod``'s implicit
    kinematics option is not offered.

    >>> from sympy.physics.mechanics import Point, Particle, ReferenceFrame
    >>> q, u = dynamicsymbols("q u")
    >>> m, g = sp.symbols("m g")
    >>> n = ReferenceFrame("N")
    >>> p = Point("P")
    >>> p.set_vel(n, u * n.x)
    >>> fk = FastKane(n, [q], [u], kd_eqs=[q.diff() - u],
    ...               bodies=[Particle("Pa", p, m)], loads=[(p, -m * g * n.x)])
    >>> fk.substitute(fk.mass_matrix), fk.substitute(fk.forcing)
    (Matrix([[m]]), Matrix([[-g*m]]))
    """

    def __init__(
        self,
        frame: ReferenceFrame,
        q_ind: Sequence[Any],
        u_ind: Sequence[Any],
        kd_eqs: Sequence[Any] | None = None,
        q_dependent: Sequence[Any] | None = None,
        configuration_constraints: Sequence[Any] | None = None,
        u_dependent: Sequence[Any] | None = None,
        velocity_constraints: Sequence[Any] | None = None,
        acceleration_constraints: Sequence[Any] | None = None,
        u_auxiliary: Sequence[Any] | None = None,
        bodies: Sequence[Any] | None = None,
        loads: Sequence[Any] | None = None,
        prefix: str = "z",
    ) -> None:
        if not isinstance(frame, ReferenceFrame):
            raise TypeError("an inertial ReferenceFrame must be supplied")
        self._inertial = frame
        self._q = list(q_ind) + list(q_dependent or [])
        self._q_dep = list(q_dependent or [])
        self._u_ind = list(u_ind)
        self._u_dep = list(u_dependent or [])
        self._u = self._u_ind + self._u_dep
        self._u_aux = list(u_auxiliary or [])
        self._f_h = sp.Matrix(list(configuration_constraints or []))
        if len(self._f_h) != len(self._q_dep):
            raise ValueError(
                "there must be as many configuration constraints as dependent "
                "coordinates"
            )
        kd_eqs = list(kd_eqs or [])
        if len(kd_eqs) != len(self._q):
            raise ValueError(
                "there must be as many kinematic differential equations as "
                "coordinates"
            )
        vel = list(velocity_constraints or [])
        if len(vel) != len(self._u_dep):
            raise ValueError(
                "there must be as many velocity constraints as dependent speeds"
            )
        acc = list(acceleration_constraints or [])
        if acc and len(acc) != len(self._u_dep):
            raise ValueError(
                "there must be as many acceleration constraints as dependent speeds"
            )
        self._bodies = bodies
        self._loads = loads

        taken = {
            s.name for e in [*kd_eqs, *vel, *acc] for s in sp.sympify(e).free_symbols
        }
        #: the intermediates (an ``Intermediates`` book, labels ``z1``, ...)
        self.book = Intermediates(prefix, taken)
        #: what :func:`measure_split` formed with the book
        self._splits = Splits(self.book)
        self._dcms: dict = {}
        self._forms: dict = {}
        self._memo: dict = {}  # time derivatives, for :meth:`_derivative_of`
        self._public: list[sp.Symbol] = []  # plain symbol of z_k at [k - 1]
        self._plain: dict[sp.Symbol, Any] = {}  # plain symbol -> definition

        self._speed_set = set(self._u + self._u_aux)
        # Kinematic differential equations: q' = K u + k.
        self._solve_kinematics(kd_eqs)
        # Velocity and acceleration constraints.
        self._solve_constraints(vel, acc)
        self._fr = self._frstar = None
        if bodies is not None:
            self.kanes_equations(bodies, loads)

    @classmethod
    def from_inputs(cls, inputs: Any, **kw: Any) -> FastKane:
        """Derive from an object with ``KanesMethod``'s inputs as attributes
        (``frame``, ``q_ind``, ``u_ind``, ``kd_eqs``, ``bodies``, ``loads`` and
        optionally ``q_dependent``, ``configuration_constraints``,
        ``u_dependent``, ``velocity_constraints``, ``u_auxiliary``), such as
        the runtime's ``KaneInputs``."""
        optional = (
            "q_dependent",
            "configuration_constraints",
            "u_dependent",
            "velocity_constraints",
            "acceleration_constraints",
            "u_auxiliary",
        )
        args = {name: getattr(inputs, name, None) for name in optional}
        return cls(
            inputs.frame,
            inputs.q_ind,
            inputs.u_ind,
            kd_eqs=inputs.kd_eqs,
            bodies=inputs.bodies,
            loads=inputs.loads,
            **{k: v for k, v in args.items() if v},
            **kw,
        )

    # ------------------------------------------------------------------
    # kinematics

    def _derivative_of(self, x: Any) -> Any:
        """The time derivative of the variable ``x``: a coordinate's by its
        kinematical differential equation, any other's as sympy writes it."""
        found = self._qdot.get(x)
        if found is not None:
            return found
        if isinstance(x, sp.Derivative):
            return sp.Derivative(x.expr, (_T, x.derivative_count + 1))
        return sp.Derivative(x, _T)

    def _actual(self, expr: Any) -> Any:
        """``expr`` with each coordinate's derivative replaced by its form
        in the speeds."""
        expr = sp.sympify(expr)
        return expr.xreplace(self._qdot_rule) if expr.has(sp.Derivative) else expr

    def _actual_vector(self, vec: Vector) -> Vector:
        """``vec`` with :meth:`_actual` measure numbers, each part free of
        speeds and larger than the book's limit named (:meth:`_shrink`)."""
        memo: dict = {}
        return Vector(
            [
                (m.applyfunc(lambda e: self._shrink(self._actual(e), memo)), f)
                for m, f in vec.args
            ]
        )

    def _shrink(self, expr: Any, memo: dict) -> Any:
        """``expr`` with each part that holds no speed and is larger than
        :attr:`Intermediates.LIMIT` nodes named, bottom-up: sympy's own
        vectors (``v2pt_theory`` through a chain of frames) hold long
        products of direction cosines, which splitting by the speeds would
        walk once per speed.  ``memo`` keeps parts shared between measure
        numbers."""
        speeds = self._speed_set
        limit = self.book.LIMIT
        name = self.book.name

        def walk(e: Any) -> tuple[Any, int, bool]:
            found = memo.get(e)
            if found is not None:
                return found
            if e.is_Atom:
                out = (e, 1, False)
            elif isinstance(e, AppliedUndef | sp.Derivative):
                out = (e, 1, e in speeds or isinstance(e, sp.Derivative))
            else:
                args, size, moving = [], 1, False
                for a in e.args:
                    b, n, m = walk(a)
                    args.append(b)
                    size += n
                    moving = moving or m
                changed = any(a is not b for a, b in zip(args, e.args, strict=True))
                new = e.func(*args) if changed else e
                if not moving and size > limit and isinstance(new, sp.Expr):
                    new, size = name(new), 1
                out = (new, size, moving)
            memo[e] = out
            return out

        return walk(sp.sympify(expr))[0]

    def _frame_dcm(self, x: ReferenceFrame, f: ReferenceFrame) -> sp.Matrix:
        return named_dcm(x, f, self.book, self._dcms)

    def _solve(self, a: sp.Matrix, b: sp.Matrix) -> sp.Matrix:
        """``a x = b`` by elimination, each entry named; pivots non-zero at
        the coordinates' zero (the usual reference configuration, e.g. an
        upright bicycle) if possible."""
        return self.book.solve(a, b, self._q)

    def _solve_kinematics(self, kd_eqs: list[Any]) -> None:
        qdots = [q.diff(_T) for q in self._q]
        speeds = self._u + self._u_aux
        n = len(kd_eqs)
        try:
            a, rest = split_linear_named(kd_eqs, qdots, self.book)
            b, k = split_linear_named(list(rest), speeds, self.book)
        except ValueError:
            a = None
        if a is None or any(c.has(*qdots, *speeds) for c in [*a, *b, *k]):
            raise ValueError(
                "the kinematic differential equations must be linear in "
                "the speeds and the coordinates' derivatives"
            )
        x = self._solve(a, -b.row_join(k)) if n else sp.zeros(0, len(speeds) + 1)
        # q' = sum x[i, j] u_j + x[i, -1]
        self._qdot: dict[Any, Any] = {}
        self._qdot_ind: list[Any] = []  # without the auxiliary speeds
        for i, q in enumerate(self._q):
            terms = [x[i, j] * u for j, u in enumerate(speeds)]
            self._qdot[q] = sp.Add(*terms, x[i, -1])
            self._qdot_ind.append(sp.Add(*terms[: len(self._u)], x[i, -1]))
        self._qdot_rule = {
            qd: self._qdot[q] for qd, q in zip(qdots, self._q, strict=True)
        }

    def _solve_constraints(self, vel: list[Any], acc: list[Any]) -> None:
        """``KanesMethod``'s constraint matrices: ``k_nh u + f_nh = 0``,
        ``k_dnh u' + f_dnh = 0`` and ``u_dep = Ars u_ind``."""
        m, o = len(self._u_dep), len(self._u)
        p = o - m
        self._k_nh = sp.zeros(m, o)
        self._f_nh = sp.zeros(m, 1)
        self._k_dnh = sp.zeros(m, o)
        self._f_dnh = sp.zeros(m, 1)
        self._ars = sp.zeros(m, p)
        if not m:
            return
        name = self.book.name
        a, b = split_linear_named([self._actual(e) for e in vel], self._u, self.book)
        self._k_nh, self._f_nh = a.applyfunc(name), b.applyfunc(name)
        if acc:
            udots = [u.diff(_T) for u in self._u]
            a, b = split_linear_named([self._actual(e) for e in acc], udots, self.book)
            self._k_dnh, self._f_dnh = a.applyfunc(name), b.applyfunc(name)
        else:
            self._k_dnh = self._k_nh
            for i in range(m):
                terms = [
                    self.book.time_derivative(
                        self._k_nh[i, j], self._derivative_of, self._memo
                    )
                    * u
                    for j, u in enumerate(self._u)
                ]
                d = self.book.time_derivative(
                    self._f_nh[i], self._derivative_of, self._memo
                )
                self._f_dnh[i] = name(sp.Add(*terms, d))
        x = self._solve(self._k_nh[:, p:], self._k_nh[:, :p])
        self._ars = (-x).applyfunc(name)

    def _form(
        self, vec: Vector, frame: ReferenceFrame
    ) -> tuple[list[list[Any]], list[Any]]:
        """A velocity's :func:`linear_form` in every speed (auxiliary ones
        last), its coordinates' derivatives replaced by their forms."""
        key = (vec, frame)
        try:
            found = self._forms.get(key)
        except TypeError:  # unhashable
            key, found = None, None
        if found is None:
            speeds = self._u + self._u_aux
            found = linear_form(
                self._actual_vector(vec),
                frame,
                speeds,
                self.book,
                self._frame_dcm,
                self._splits,
            )
            if found is None:
                raise ValueError("a velocity is not linear in the speeds")
            if key is not None:
                self._forms[key] = found
        return found

    def _motion(self, form: tuple[list[list[Any]], list[Any]]) -> Motion:
        """A velocity and its time derivative (the auxiliary speeds zero
        there) as :class:`Motion`."""
        columns, rest = form
        o = len(self._u)
        rate = form_rate(
            (columns[:o], rest), self._u, self.book, self._derivative_of, self._memo
        )
        return Motion(
            partials=_nonzero(columns),
            rates=_nonzero(columns[:o]),
            rest=[self.book.name(r) for r in rate],
        )

    # ------------------------------------------------------------------
    # Kane's equations
    def kanes_equations(
        self, bodies: Sequence[Any], loads: Sequence[Any] | None = None
    ) -> tuple[sp.Matrix, sp.Matrix]:
        """Form ``Fr`` and ``Fr*`` (returned like ``KanesMethod``'s)."""
        self._bodies, self._loads = list(bodies), list(loads or [])
        book = self.book
        n_frame = self._inertial
        o, m = len(self._u), len(self._u_dep)
        p = o - m
        rows = o + len(self._u_aux)

        # Fr, including auxiliary rows.
        loads_in = []
        for load in self._loads:
            where, what = load[0], load[1]
            if isinstance(where, Point):
                form = self._form(where.vel(n_frame), n_frame)
                frame = n_frame
            elif isinstance(where, ReferenceFrame):
                form = self._form(ang_vel_in(where, n_frame), where)
                frame = where
            else:
                raise TypeError(
                    f"a load acts on a Point or a ReferenceFrame, not {where!r}"
                )
            force = named_measures(
                self._actual_vector(what), frame, book, self._frame_dcm, self._splits
            )
            loads_in.append((_nonzero(form[0]), force))
        fr = active_rows(loads_in, rows, book.name)

        # Fr*: mass matrix (all speeds' derivatives) and the rest.
        translations, rotations = [], []
        for body in self._bodies:
            if isinstance(body, RigidBody):
                point, frame = body.masscenter, body.frame
            elif isinstance(body, Particle):
                point, frame = body.point, None
            else:
                raise TypeError("bodies must be RigidBody or Particle objects")
            mass = sp.sympify(body.mass)
            if mass.has(_T):
                raise NotImplementedError("masses that vary in time")
            form = self._form(point.vel(n_frame), n_frame)
            translations.append((mass, self._motion(form)))
            if frame is None:
                continue
            inertia = body.central_inertia
            if any(sp.sympify(c).has(_T) for c, _, _ in inertia.args):
                raise NotImplementedError("inertia dyadics that vary in time")
            imat = self._inertia_matrix(inertia, frame)
            form = self._form(ang_vel_in(frame, n_frame), frame)
            columns, rest = form
            omega = [
                book.name(
                    sp.Add(
                        rest[i],
                        *[c[i] * u for c, u in zip(columns[:o], self._u, strict=True)],
                    )
                )
                for i in range(3)
            ]
            rotations.append((imat, omega, self._motion(form)))
        mm, non = inertia_rows(translations, rotations, rows, o, book.name)

        mm_mat = sp.Matrix(mm[:o]) if o else sp.zeros(0, 0)
        non_mat = sp.Matrix(non[:o]) if o else sp.zeros(0, 1)
        fr_mat = sp.Matrix(fr[:o]) if o else sp.zeros(0, 1)
        if m:
            ars_t = self._ars.T
            mm_mat = mm_mat[:p, :] + _matmul(ars_t, mm_mat[p:, :])
            non_mat = non_mat[:p, :] + _matmul(ars_t, non_mat[p:, :])
            fr_mat = fr_mat[:p, :] + _matmul(ars_t, fr_mat[p:, :])
        udot = sp.Matrix([u.diff(_T) for u in self._u])
        self._k_d = mm_mat
        self._f_d = -(fr_mat - non_mat)
        self._fr = fr_mat
        self._frstar = -(_matmul(mm_mat, udot) + non_mat)
        if self._u_aux:
            na = len(self._u_aux)
            mma = sp.Matrix(mm[o:]) if o else sp.zeros(na, 0)
            self._aux = sp.Matrix(fr[o:]) - (_matmul(mma, udot) + sp.Matrix(non[o:]))
        else:
            self._aux = None
        return self.fr, self.frstar

    def _inertia_matrix(self, dyadic: Any, frame: ReferenceFrame) -> list[list[Any]]:
        out = [[sp.S.Zero] * 3 for _ in range(3)]
        for coef, v1, v2 in dyadic.args:
            c1 = named_measures(v1, frame, self.book, self._frame_dcm, self._splits)
            c2 = named_measures(v2, frame, self.book, self._frame_dcm, self._splits)
            for i in range(3):
                for j in range(3):
                    if c1[i] != 0 and c2[j] != 0:
                        out[i][j] += coef * c1[i] * c2[j]
        return [[self.book.name(e) for e in row] for row in out]

    # ------------------------------------------------------------------
    # results: the book's intermediates as plain symbols z1, z2, ...

    def _symbols(self) -> list[sp.Symbol]:
        """The plain symbol of each intermediate made so far (``[k - 1]``
        for number ``k``)."""
        book = self.book
        for k in range(len(self._public) + 1, len(book) + 1):
            self._public.append(sp.Symbol(book.label_of(k)))
        return self._public

    def _to_plain(self, expr: Any) -> Any:
        """``expr`` with each intermediate as its plain symbol (one walk,
        no intermediate made again)."""
        symbols = self._symbols()
        Z = self.book.Z
        memo: dict = {}

        def walk(e: Any) -> Any:
            if isinstance(e, Z):
                return symbols[int(e.args[0]) - 1]
            if not e.args:
                return e
            found = memo.get(e)
            if found is None:
                args = [walk(a) for a in e.args]
                same = all(a is b for a, b in zip(args, e.args, strict=True))
                found = memo[e] = e if same else e.func(*args)
            return found

        if isinstance(expr, sp.MatrixBase):
            return sp.ImmutableMatrix(expr.rows, expr.cols, [walk(x) for x in expr])
        return walk(sp.sympify(expr))

    def _plain_definitions(self) -> dict[sp.Symbol, Any]:
        """Each plain symbol's definition, over the plain symbols."""
        symbols = self._symbols()
        for k in range(len(self._plain) + 1, len(symbols) + 1):
            self._plain[symbols[k - 1]] = self._to_plain(self.book.canonical(k)[1])
        return self._plain

    def _need(self) -> None:
        if self._fr is None:
            raise ValueError("call kanes_equations(bodies, loads) first")

    @property
    def q(self) -> sp.Matrix:
        return sp.Matrix(self._q)

    @property
    def u(self) -> sp.Matrix:
        return sp.Matrix(self._u)

    @property
    def fr(self) -> sp.Matrix:
        """``Fr`` (the reduced rows), written with intermediates."""
        self._need()
        return self._to_plain(self._fr)

    @property
    def frstar(self) -> sp.Matrix:
        """``Fr*`` (the reduced rows), written with intermediates."""
        self._need()
        return self._to_plain(self._frstar)

    @property
    def mass_matrix(self) -> sp.Matrix:
        """``KanesMethod.mass_matrix``: reduced dynamic rows, then constraints."""
        self._need()
        return self._to_plain(self._k_d.col_join(self._k_dnh))

    @property
    def forcing(self) -> sp.Matrix:
        self._need()
        return self._to_plain((-self._f_d).col_join(-self._f_dnh))

    @property
    def mass_matrix_kin(self) -> sp.Matrix:
        return sp.eye(len(self._q))

    @property
    def forcing_kin(self) -> sp.Matrix:
        return self._to_plain(sp.Matrix(self._qdot_ind))

    @property
    def mass_matrix_full(self) -> sp.Matrix:
        o, n = len(self._u), len(self._q)
        return self.mass_matrix_kin.row_join(sp.zeros(n, o)).col_join(
            sp.zeros(o, n).row_join(self.mass_matrix)
        )

    @property
    def forcing_full(self) -> sp.Matrix:
        return self.forcing_kin.col_join(self.forcing)

    @property
    def auxiliary_eqs(self) -> sp.Matrix:
        self._need()
        if self._aux is None:
            raise ValueError("no auxiliary speeds have been declared")
        return self._to_plain(self._aux)

    @property
    def intermediates(self) -> list[tuple[sp.Symbol, Any]]:
        """``(symbol, expression)`` pairs in evaluation order."""
        return list(self._plain_definitions().items())

    def substitute(self, expr: Any) -> Any:
        """``expr`` with every intermediate replaced by its full expression
        (:meth:`Intermediates.expand`: each intermediate written out once)."""
        number = {s: k for k, s in enumerate(self._symbols(), 1)}
        expr = sp.sympify(expr)
        back = {}
        for s in expr.free_symbols:
            k = number.get(s)
            if k is not None:
                back[s] = self.book.Z(sp.Integer(k), *self.book.canonical(k)[0])
        expr = expr.xreplace(back)
        if isinstance(expr, sp.MatrixBase):  # one pass for every entry
            flat = self.book.expand(sp.Tuple(*expr))
            return sp.Matrix(expr.rows, expr.cols, list(flat))
        return self.book.expand(expr)

    def numeric(self, args: Sequence[Any], exprs: Any):
        """A numpy function of ``args`` computing ``exprs`` (a matrix, an
        expression, or a list of them), evaluating the intermediates it needs
        in order.  ``args``: coordinates, speeds, constants, ...; every other
        symbol in ``exprs`` must be among them.  Complex arguments work (for
        complex-step derivatives)."""
        defs = dict(self.intermediates)
        rename = {sp.sympify(a): sp.Symbol(f"_x{k}") for k, a in enumerate(args)}
        rename.update({z: sp.Symbol(f"_{z.name}") for z in defs})

        def convert(e: Any) -> Any:
            if isinstance(e, list | tuple):
                return [convert(x) for x in e]
            e = sp.sympify(e)
            if isinstance(e, sp.MatrixBase):
                return e.applyfunc(lambda x: x.xreplace(rename))
            return e.xreplace(rename)

        plain = convert(exprs)
        used = _used(plain, defs)
        printer = NumPyPrinter({"order": "none", "fully_qualified_modules": True})
        names = ", ".join(str(rename[sp.sympify(a)]) for a in args)
        lines = [f"def _numeric({names}):"]
        for z, e in defs.items():
            if z in used:
                lines.append(f"    {rename[z]} = {printer.doprint(e.xreplace(rename))}")

        def emit(e: Any) -> str:
            if isinstance(e, list):
                return "[" + ", ".join(emit(x) for x in e) + "]"
            if isinstance(e, sp.MatrixBase):
                rows = ", ".join(
                    "[" + ", ".join(printer.doprint(x) for x in e.row(i)) + "]"
                    for i in range(e.rows)
                )
                return f"numpy.array([{rows}])"
            return printer.doprint(e)

        lines.append(f"    return {emit(plain)}")
        import numpy as np

        namespace: dict[str, Any] = {"numpy": np}
        exec("\n".join(lines), namespace)  # noqa: S102  (generated from sympy)
        return namespace["_numeric"]


def _used(expr: Any, defs: dict[sp.Symbol, Any]) -> set[sp.Symbol]:
    """The intermediates (plain symbols, keys of ``defs``) that ``expr`` --
    written with them renamed ``_z1``, ... -- needs, directly or through
    others."""
    parts = expr if isinstance(expr, list | tuple) else [expr]
    found: set[Any] = set()
    for e in parts:
        found |= sp.sympify(e).free_symbols
    byname = {sp.Symbol(f"_{z.name}"): z for z in defs}
    todo = [byname[s] for s in found if s in byname]
    seen: set[Any] = set()
    while todo:
        z = todo.pop()
        if z in seen:
            continue
        seen.add(z)
        todo.extend(s for s in defs[z].free_symbols if s in defs)
    return seen
