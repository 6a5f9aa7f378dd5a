"""Kane's method through ``sympy.physics.mechanics.KanesMethod``.

:class:`KaneInputs` is what ``KanesMethod`` takes -- the Newtonian frame,
coordinates, speeds, kinematical differential equations, bodies, loads and
motion constraints -- built from an Autolev script by
``Workspace.kane_inputs()``.  :func:`kanes_method` forms the equations.  Other
formulations (a faster Kane with intermediate variables, compiled backends)
start from the same inputs.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from sympy.physics.mechanics import KanesMethod
from sympy.physics.vector import ReferenceFrame

__all__ = ["KaneInputs", "kanes_method"]


@dataclass
class KaneInputs:
    """Everything ``KanesMethod`` needs, as sympy objects.

    ``bodies`` are ``RigidBody``/``Particle`` objects whose mass centers know
    their velocities and accelerations in ``frame``; ``loads`` are
    ``(Point, Vector)`` forces and ``(ReferenceFrame, Vector)`` torques.
    ``speed_names`` maps each speed to its Autolev spelling (a speed that is a
    coordinate's derivative, ``Q1'``, is a new function ``Q1_U``)."""

    frame: ReferenceFrame
    q_ind: list[Any]
    u_ind: list[Any]
    kd_eqs: list[Any]
    bodies: list[Any]
    loads: list[tuple[Any, Any]]
    u_dependent: list[Any] = field(default_factory=list)
    velocity_constraints: list[Any] = field(default_factory=list)
    u_auxiliary: list[Any] = field(default_factory=list)
    speed_names: dict[Any, str] = field(default_factory=dict)

    @property
    def q(self) -> list[Any]:
        return list(self.q_ind)

    @property
    def u(self) -> list[Any]:
        return [*self.u_ind, *self.u_dependent]


def kanes_method(inputs: KaneInputs) -> KanesMethod:
    """A ``KanesMethod`` with its equations formed (``mass_matrix_full``,
    ``forcing_full``, ``fr``, ``frstar``)."""
    kw: dict[str, Any] = {}
    if inputs.u_dependent:
        kw["u_dependent"] = inputs.u_dependent
        kw["velocity_constraints"] = inputs.velocity_constraints
    if inputs.u_auxiliary:
        kw["u_auxiliary"] = inputs.u_auxiliary
    km = KanesMethod(
        inputs.frame,
        q_ind=inputs.q_ind,
        u_ind=inputs.u_ind,
        kd_eqs=inputs.kd_eqs,
        **kw,
    )
    km.kanes_equations(inputs.bodies, inputs.loads)
    return km
