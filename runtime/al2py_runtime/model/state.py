"""The state of a script's model, and small helpers shared by its parts."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, TypeVar

import sympy as sp
from sympy.physics.vector import Point, ReferenceFrame, Vector, dynamicsymbols

from ..safety import Statements, statement

if TYPE_CHECKING:
    from ..names.settings import Settings
    from ..names.table import NameTable
    from .kinematics import Tidier
    from .resolutions import Resolutions
    from .script import ScriptNames

F = TypeVar("F", bound=Callable[..., Any])

t = dynamicsymbols._t

SPEED_NAME = re.compile(r"U(\d+)$")


@dataclass
class BodyRecord:
    """What Autolev keeps of a body beside its sympy ``RigidBody`` (whose
    mass and central inertia are the body's): the inertia as the script
    gave it, about any point (``Inertia B, ...`` or ``I_B_P>> = ...``),
    whose central dyadic follows by the transfer theorem when it is used
    (sympy's ``RigidBody.inertia`` forms it at once, which needs the
    position and the mass then)."""

    frame: ReferenceFrame
    point: Point
    inertia: Any = None  # Dyadic about ``inertia_point`` (None: not given)
    inertia_point: Point | None = None


@dataclass
class ModelState:
    newtonian: ReferenceFrame | None = None
    frames: dict = field(default_factory=dict)  # name -> ReferenceFrame
    points: dict = field(default_factory=dict)  # name -> Point
    fixed_in: dict = field(default_factory=dict)  # Point -> frame (origins)
    bodies: dict = field(default_factory=dict)  # ReferenceFrame -> BodyRecord
    particles: set = field(default_factory=set)  # the particles' points
    #: the bodies (frames) and particles (points) whose mass was declared, in
    #: order (a dict used as an ordered set); the mass itself is the sympy
    #: ``RigidBody``/``Particle``'s (``sympy_bodies``), Autolev's "not
    #: declared" is the absence here
    mass_given: dict = field(default_factory=dict)
    massive: list = field(default_factory=list)  # bodies' frames and particles
    sympy_bodies: dict = field(
        default_factory=dict
    )  # frame/Point -> RigidBody/Particle
    # Positions, velocities, orientations and angular velocities are stored
    # once, on the sympy objects (``Q.set_pos(P, v)``, ``P.set_vel(N, v)``,
    # ``B.orient_axis(...)``, ``B.set_ang_vel(A, w)``; Kinematics reads them
    # back).  The model keeps only what sympy lacks (docs/semantics.md,
    # "Kinematics stored on the sympy objects").
    #: ``(P, N)`` whose velocity ``P.vel(N)`` the script gave or V2pts/V1pt
    #: formed, in order (a dict used as an ordered set: every value is
    #: None); Autolev forms any other velocity from positions when used
    vel_given: dict = field(default_factory=dict)
    #: ``(P, N) -> A_P_N>`` given or formed by A2pts/A1pt, and ``(B, A) ->
    #: ALF_B_A>`` given (both ways): Autolev's accelerations, which are not
    #: sympy's (their dependent speeds' derivatives are substituted, which
    #: sympy's KanesMethod, reading ``P.acc(N)``, would count twice)
    acc: dict = field(default_factory=dict)
    angacc: dict = field(default_factory=dict)
    #: ``ALF_B_A> = v`` as the script wrote it: B -> [(A, v)], in order
    angacc_given: dict = field(default_factory=dict)
    #: the loads, sympy ``Force``/``Torque`` objects (or ``(Point, Vector)``,
    #: ``(ReferenceFrame, Vector)`` pairs) in the order they were applied: the
    #: list a module appends to (``loads.append(Force(P, v))``), and the one
    #: source of ``Force_P>``, ``Torque_B>``, ``Fr()`` and ``kanes_method()``
    loads: list = field(default_factory=list)
    gravity: list = field(default_factory=list)  # Gravity(v>)'s vectors, in order
    dependent: list = field(default_factory=list)
    auxiliary: list = field(default_factory=list)
    speed_dt: dict = field(default_factory=dict)  # U' -> expression (Constrain)
    deferred_vel: dict = field(default_factory=dict)  # (P, N) -> (A, O): V2pts
    deferred_acc: dict = field(default_factory=dict)  # (P, N) -> (A, O): A2pts
    motion: list = field(default_factory=list)  # MotionVariables, in order
    checks: list = field(default_factory=list)  # NiCheck's work variables
    gyrostat: bool = False  # Gyrostat(FRSTAR...) terms were formed
    speeds: list | None = None  # the speeds, fixed when Fr/FrStar are formed
    fr_speeds: list | None = None
    kane: dict | None = None
    #: what :func:`~.fastkane.measure_split` formed with the script's book
    #: (a :class:`~.fastkane.Splits`, made on first use)
    splits: Any = None

    @property
    def forces(self) -> dict:
        """Point -> the resultant of its force loads, points in the order
        of their first load."""
        return _resultants(self.loads, Point)

    @property
    def torques(self) -> dict:
        """Frame -> the resultant of its torque loads, in order."""
        return _resultants(self.loads, ReferenceFrame)


class ModelPart:
    """What every part of :class:`~.model.Model` works with, given to its
    constructor: the model's own state, and the small objects of the script
    it uses (no reference to the workspace as a whole)."""

    #: frames, points, bodies, loads, speeds (the parts' shared state)
    registry: ModelState
    #: the script's operations on Autolev names (:class:`~.script.ScriptNames`)
    script: ScriptNames
    #: the script's names: declarations, right-hand sides, stored values
    table: NameTable
    #: ``AutoZ``, ``Factoring``, ``Digits``...
    settings: Settings
    #: where the script's statement calls stand (errors name the .al line)
    statements: Statements
    #: quantities constrained to unit norm (Euler parameters), for
    #: ``al2py check``'s random points
    unit_norms: list[tuple[Any, ...]]
    #: the script's resolvers, remembered while its right-hand sides stay
    resolutions: Resolutions
    #: :func:`~.kinematics.tidy`, each result formed once
    tidier: Tidier


def _resultants(loads: list, kind: type) -> dict:
    out: dict = {}
    for load in loads:
        where, vec = load[0], load[1]
        if isinstance(where, kind):
            out[where] = out[where] + vec if where in out else vec
    return out


def command(method: F) -> F:
    """Mark a model method as an Autolev command that a generated module
    calls (``al.model.simprot(...)``, listed in
    :data:`al2py_runtime.model.model.MODEL_COMMANDS`): a failure of the
    module's call names its ``.al`` line (:func:`~al2py_runtime.safety.statement`)."""
    marked = statement(method)
    marked.autolev_command = True  # type: ignore[attr-defined]
    return marked


def query(method: F) -> F:
    """Mark a model method that a generated module's own functions call
    (``kanes_method()``): a command whose errors are the caller's, raised
    unchanged."""
    method.autolev_command = True  # type: ignore[attr-defined]
    return method


def mentions(x: Any, objs: list) -> bool:
    """Whether a vector (or scalar) contains any of ``objs``."""
    if isinstance(x, Vector):
        return any(m.has(*objs) for m, _frame in x.args)
    return isinstance(x, sp.Basic) and x.has(*objs)
