"""Physical entities and Kane's method (tutorial §3, §4.4-4.5, §5.2-5.9).

:class:`Model` holds the physics of a script; the :class:`Workspace` offers
its commands (:data:`MODEL_COMMANDS`) to generated modules.

Objects.  A frame or body *is* its ``sympy.physics.vector.ReferenceFrame``
(named with the Autolev name, ``A1>`` is ``A.x``); points, particles and mass
centers *are* ``Point``s (``"O"``, ``"AO"``).  Masses, inertias, positions,
velocities, accelerations, forces and torques live in a registry kept by the
workspace (orientations and angular velocities are stored on the sympy frames
themselves, so sympy's frame algebra -- ``dcm``, ``express``, ``dot`` --
works).

Kinematic rules (as Autolev):

* Position vectors reverse and chain: ``P_R_Q>`` is ``-P_Q_R>`` and
  ``P_O_Q>`` is found along any chain of given positions ``O -> P -> Q``.
* A velocity that was not given (or formed by ``V2pts``...) is the velocity of
  the nearest point (along given positions) whose velocity in that frame is
  known, plus the time derivative of the position from it.  The origin of a
  frame (``NO``, ``AO``...) has zero velocity in its frame.
* Accelerations not given are time derivatives of velocities; angular
  velocities not given come from the direction cosine matrices; angular
  accelerations not given are time derivatives of angular velocities.

Internally every derivative is taken after substituting all right-hand sides
(``QA' = U1/LA``, dependent speeds, named quantities), so results are correct
whatever is kept symbolic in the responses.
"""

from __future__ import annotations

from typing import Any

from .bodies import MassAndLoads
from .energy import Energy
from .equations import KaneEquations
from .objects import Objects
from .points import Kinematics
from .speeds import Speeds
from .state import _State
from .vectors import VectorCommands

__all__ = ["Model", "MODEL_COMMANDS"]


class Model(
    Objects, Kinematics, VectorCommands, MassAndLoads, Speeds, KaneEquations, Energy
):
    """Frames, bodies, points, kinematics, mass, loads and Kane's method of
    one script: the workspace's ``model`` part.

    ``ws`` is the script's name table (declarations, right-hand sides,
    settings and responses); the model reads and writes names through it."""

    def __init__(self, ws: Any) -> None:
        self.ws = ws
        self._mech = _State()


#: The commands a :class:`Model` answers for its workspace (``al.simprot``,
#: ``al.v2pts``, ``al.fr``...): generated modules call them on the workspace.
MODEL_COMMANDS = frozenset(
    {
        "newtonian",
        "frames",
        "bodies",
        "particles",
        "points",
        "point",
        "frame",
        "set_mass",
        "set_inertia",
        "set_pos",
        "set_vel",
        "set_acc",
        "set_ang_vel",
        "set_ang_acc",
        "set_force",
        "set_torque",
        "set_dcm",
        "set_inertia_about",
        "pos",
        "vel",
        "acc",
        "ang_vel",
        "ang_acc",
        "dcm",
        "simprot",
        "dircos",
        "angvel",
        "kindiffs",
        "speed_matrix",
        "v2pts",
        "a2pts",
        "v1pt",
        "a1pt",
        "express",
        "represent",
        "matrix",
        "vector",
        "dyadic",
        "dot",
        "cross",
        "magsq",
        "mag",
        "unitvec",
        "unit_dyadic",
        "vector_matrix",
        "trace",
        "mass_of",
        "cm",
        "central_inertia",
        "inertia_dyadic",
        "inertia",
        "force_on",
        "torque_on",
        "add_force",
        "add_torque",
        "force_between",
        "torque_between",
        "gravity",
        "motion_variables",
        "partials",
        "remainder",
        "fr",
        "tstar",
        "frstar",
        "constrain",
        "kane",
        "kane_inputs",
        "kd_eqs",
        "kanes_method",
        "ke",
        "momentum",
        "gyrostat",
        "power",
        "nicheck",
    }
)
