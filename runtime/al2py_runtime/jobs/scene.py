"""What an animation shows, and where: points, frames and the lines joining
them, at every output row of a job.

Autolev's ``Animate(N, O, A, B)`` names the Newtonian frame, a point, and
the frames and bodies to animate.  :class:`Geometry` is the model's geometry
as a ``CODE`` statement finds it (the positions the script gave, the bodies'
mass centers, the frames and points by name); :func:`layout` decides what is
drawn, from an ``Animate`` statement or from the options of
``result.animate()`` (docs/animation.md):

* each animated frame as a triad (its unit vectors) at its body's mass
  center; a frame that is not a body at its origin when the script locates
  it, else at the point fixed in it nearest ``O`` along the positions (a
  link's hinge);
* a line for each position the script gave that is fixed in an animated
  frame (its measure numbers in that frame are constants): a body's mass
  center and the points fixed on it, the links of a pendulum;
* the points: ``O``, the ends of those lines, the anchors of the triads,
  every point and particle the script declared that positions locate from
  ``O`` (a wheel's contact point), and the points asked for.

:func:`scene` then computes each point's position from ``O`` (measure
numbers in ``N``) and each triad's direction cosines at all output rows at
once (:meth:`~al2py_runtime.jobs.run.Motion.evaluate`, one numpy function).

A pendulum of two links, as a generated module builds it:

>>> from al2py_runtime import Workspace
>>> al = Workspace("links.al")
>>> N = al.model.newtonian("N")
>>> A, B = al.model.frames("A", "B")
>>> O, P, Q = al.model.points("O", "P", "Q")
>>> QA, QB = al.variables("QA", "QB")
>>> LA, LB = al.constants("LA", "LB")
>>> _ = al.model.simprot(N, A, 3, QA), al.model.simprot(N, B, 3, QB)
>>> _ = al.model.set_pos(P, O, LA * A.x), al.model.set_pos(Q, P, LB * B.x)
>>> shown = layout(Geometry.of(al.model), frames=["A", "B"])
>>> shown.origin.name, [p.name for p in shown.points], shown.lines
('O', ['O', 'P', 'Q'], [(0, 1), (1, 2)])
>>> [(f.name, shown.points[k].name) for f, k in zip(shown.frames, shown.anchors)]
[('A', 'O'), ('B', 'P')]
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import sympy as sp
from sympy.physics.vector import Point, ReferenceFrame, Vector, dynamicsymbols

from .records import NumericsError

if TYPE_CHECKING:
    import numpy as np

    from ..model.model import Model

__all__ = ["Geometry", "Layout", "Scene", "layout", "scene"]

t = dynamicsymbols._t


@dataclass(frozen=True)
class Geometry:
    """The model's geometry at a ``CODE`` statement (a snapshot: later
    statements do not change a job's)."""

    newtonian: ReferenceFrame | None
    frames: dict[str, ReferenceFrame]  # declared frames and bodies, by name
    points: dict[str, Point]  # points, particles, mass centers, origins
    #: the positions the script gave: ``(P, Q, P_P_Q>)``, in order
    positions: tuple[tuple[Point, Point, Vector], ...]
    masscenters: dict[ReferenceFrame, Point]  # bodies
    #: the script's ``Points`` and ``Particles`` (not origins, mass centers)
    declared: tuple[Point, ...]
    #: points fixed in the Newtonian frame (its origin) or given ``V_P_N> = 0>``
    at_rest: tuple[Point, ...]
    gravity: tuple[Vector, ...] = ()

    @classmethod
    def of(cls, model: Model) -> Geometry:
        """The geometry of ``model`` (a workspace's ``al.model``) now."""
        st = model.registry
        n = st.newtonian
        centers = {f: rec.point for f, rec in st.bodies.items()}
        seen: set[frozenset] = set()
        given = []
        for p in st.points.values():
            for q in p._pos_dict:  # the positions given (sympy's set_pos)
                pair = frozenset((p, q))
                if pair not in seen:
                    seen.add(pair)
                    given.append((p, q, q._pos_dict[p]))  # P_P_Q>
        rest = [p for p, f in st.fixed_in.items() if f is n]
        rest += [p for (p, f) in st.vel_given if f is n and not p.vel(f).args]  # ``0>``
        return cls(
            n,
            dict(st.frames),
            dict(st.points),
            tuple(given),
            centers,
            tuple(
                p
                for p in st.points.values()
                if p not in st.fixed_in and p not in centers.values()
            ),
            tuple(dict.fromkeys(rest)),
            tuple(st.gravity),
        )

    def frame(self, name: Any) -> ReferenceFrame:
        if isinstance(name, ReferenceFrame):
            return name
        found = self.frames.get(str(name).upper())
        if found is None:
            raise NumericsError(f"animate: {name} is not a frame or body of the model")
        return found

    def point(self, name: Any) -> Point:
        if isinstance(name, Point):
            return name
        found = self.points.get(str(name).upper())
        if found is None:
            raise NumericsError(
                f"animate: {name} is not a point, particle or mass center of the model"
            )
        return found


@dataclass
class Layout:
    """What an animation draws (sympy: positions from ``origin``)."""

    newtonian: ReferenceFrame
    origin: Point
    points: list[Point]
    positions: list[Vector]  # of each point from ``origin``
    frames: list[ReferenceFrame]
    anchors: list[int]  # the point (index) each frame's triad stands at
    lines: list[tuple[int, int]]
    gravity: Vector = field(default_factory=lambda: Vector(0))


def _fixed_in(v: Vector, frame: ReferenceFrame) -> bool:
    """Whether the measure numbers of ``v`` in ``frame`` are constants."""
    for measures, f in v.args:
        if measures.has(t):
            return False
        if f is not frame:
            try:
                if sp.Matrix(frame.dcm(f)).has(t):
                    return False
            except ValueError:  # not oriented relative to each other
                return False
    return True


def _default_origin(geometry: Geometry, located: set[Point]) -> Point:
    """A point at rest in N that positions reach (``NO``, or a point given
    ``V_O_N> = 0>``), else the first point of the first position given."""
    for p in geometry.at_rest:
        if p in located:
            return p
    if geometry.positions:
        return geometry.positions[0][0]
    raise NumericsError(
        "animate: the script gives no positions (P_O_P> = ...), so there is"
        " nothing to place"
    )


def _reach(geometry: Geometry, origin: Point) -> dict[Point, Vector]:
    """Every point the given positions chain to from ``origin``, with its
    position from it (breadth first: the shortest chain, as ``P_O_Q>``),
    nearest first."""
    edges: dict[Point, list[tuple[Point, Vector]]] = {}
    for p, q, v in geometry.positions:
        edges.setdefault(p, []).append((q, v))
        edges.setdefault(q, []).append((p, -v))
    found = {origin: Vector(0)}
    todo = deque([origin])
    while todo:
        p = todo.popleft()
        for q, v in edges.get(p, []):
            if q not in found:
                found[q] = found[p] + v
                todo.append(q)
    return found


def layout(
    geometry: Geometry,
    newtonian: Any = None,
    origin: Any = None,
    frames: Iterable[Any] | None = None,
    points: Iterable[Any] = (),
) -> Layout:
    """What to draw (see the module's docstring).  Frames and points are
    objects or names; ``frames=None`` animates every body, or every frame
    but ``N`` when there are no bodies; ``origin=None`` takes a point at
    rest in ``N`` that the positions reach."""
    n = geometry.frame(newtonian) if newtonian is not None else geometry.newtonian
    if n is None:
        raise NumericsError("animate: the model has no Newtonian frame")
    everything = {p for pair in geometry.positions for p in pair[:2]}
    o = geometry.point(origin) if origin is not None else None
    if o is None:
        o = _default_origin(geometry, everything)
    where = _reach(geometry, o)
    if frames is None:
        chosen = list(geometry.masscenters) or [
            f for f in geometry.frames.values() if f is not n
        ]
    else:
        chosen = [geometry.frame(f) for f in frames]
    shown: dict[Point, None] = {o: None}
    lines: list[tuple[Point, Point]] = []
    fixed: dict[ReferenceFrame, list[Point]] = {f: [] for f in chosen}
    hops = {p: i for i, p in enumerate(where)}  # nearer O first
    for p, q, v in geometry.positions:
        if p not in where:
            continue
        if hops[q] < hops[p]:
            p, q, v = q, p, -v
        for f in chosen:
            if _fixed_in(v, f):
                lines.append((p, q))
                fixed[f] += [p, q]
                break
    lines.sort(key=lambda pq: (hops[pq[0]], hops[pq[1]]))
    anchors: list[Point] = []
    missing = []
    for f in chosen:
        mc = geometry.masscenters.get(f)
        origin_f = geometry.points.get(f.name + "O")
        if mc is not None:
            anchor = mc
        elif origin_f is not None and origin_f in where:
            anchor = origin_f
        elif fixed[f]:
            anchor = min(fixed[f], key=hops.__getitem__)  # nearest O
        else:
            anchor = None
        if anchor is None or anchor not in where:
            missing.append(f.name + (f" (mass center {mc.name})" if mc else ""))
            continue
        anchors.append(anchor)
    if missing:
        raise NumericsError(
            f"animate: no position from {o.name} locates "
            + ", ".join(missing)
            + f"; give one (P_{o.name}_X> = ...) or animate other frames"
        )
    for p, q in lines:
        shown.update({p: None, q: None})
    shown.update(dict.fromkeys(anchors))
    shown.update({p: None for p in geometry.declared if p in where})
    for name in points:
        p = geometry.point(name)
        if p not in where:
            raise NumericsError(f"animate: no position from {o.name} locates {p.name}")
        shown[p] = None
    order = list(shown)
    index = {p: i for i, p in enumerate(order)}
    gravity = Vector(0)
    for g in geometry.gravity:
        gravity += g
    return Layout(
        n,
        o,
        order,
        [where[p] for p in order],
        chosen,
        [index[p] for p in anchors],
        [(index[p], index[q]) for p, q in lines],
        gravity,
    )


@dataclass
class Scene:
    """A :class:`Layout` at every output row: ``positions`` (rows, points, 3)
    are measure numbers in ``N`` from the origin, in the unit system's
    length unit; ``axes`` (rows, frames, 3, 3) hold each frame's unit
    vectors as columns (``axes[r, k] = N_F``, Autolev's direction cosines);
    ``gravity`` is the Gravity vector's measure numbers at the first row."""

    layout: Layout
    times: np.ndarray
    positions: np.ndarray
    axes: np.ndarray
    gravity: np.ndarray
    time_unit: str | None = None
    length_unit: str | None = None

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.layout.points]

    @property
    def frame_names(self) -> list[str]:
        return [f.name for f in self.layout.frames]

    def position(self, name: str) -> np.ndarray:
        """The position of the point ``name`` from the origin at every row
        (rows, 3)."""
        names = [n.upper() for n in self.names]
        if name.upper() not in names:
            raise KeyError(f"{name} is not a point of this animation: {self.names}")
        return self.positions[:, names.index(name.upper())]


def _measures(v: Vector, n: ReferenceFrame) -> list[Any]:
    return [0, 0, 0] if v == Vector(0) else list(v.to_matrix(n))


def scene(
    evaluate: Callable[[list[Any]], np.ndarray],
    shown: Layout,
    times: np.ndarray,
    units: Sequence[str | None] = (),
) -> Scene:
    """The :class:`Scene` of ``shown`` at ``times``: ``evaluate(exprs)``
    gives the values of sympy expressions at every row, an array (rows,
    expressions) (a run's :meth:`~al2py_runtime.jobs.run.Motion.evaluate`)."""
    import numpy as np

    n = shown.newtonian
    exprs: list[Any] = []
    for v in shown.positions:
        exprs += _measures(v, n)
    for f in shown.frames:
        exprs += list(sp.Matrix(n.dcm(f)))
    exprs += _measures(shown.gravity, n)
    values = evaluate(exprs)
    rows, k = len(times), 3 * len(shown.points)
    m = 9 * len(shown.frames)
    positions = values[:, :k].reshape(rows, len(shown.points), 3)
    axes = values[:, k : k + m].reshape(rows, len(shown.frames), 3, 3)
    gravity = np.array(values[0, k + m :]) if rows else np.zeros(3)
    time_unit, length_unit = (list(units) + [None, None])[:2]
    return Scene(shown, times, positions, axes, gravity, time_unit, length_unit)
