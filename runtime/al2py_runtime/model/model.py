"""Physical entities and Kane's method (tutorial §3, §4.4-4.5, §5.2-5.9).

:class:`Model` holds the physics of a script; generated modules call its
commands (:data:`MODEL_COMMANDS`) as ``al.model.NAME(...)``.

Objects.  A frame or body *is* its ``sympy.physics.vector.ReferenceFrame``
(named with the Autolev name, ``A1>`` is ``A.x``); points, particles and mass
centers *are* ``Point``s (``"O"``, ``"AO"``).  Positions, velocities,
orientations and angular velocities are stored on the sympy objects
themselves (``set_pos``, ``set_vel``, ``orient_axis``,
``set_ang_vel``), so sympy's algebra -- ``pos_from``, ``vel``, ``dcm``,
``express``, ``dot`` -- works; the model's registry keeps what sympy lacks
(which velocities are Autolev's, the accelerations Autolev forms, loads,
speeds: :class:`~.state.ModelState`).

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

from ..names.settings import Settings
from ..names.table import NameTable
from ..safety import Statements
from ..vocabulary.calls import MODEL_COMMANDS
from .bodies import MassAndLoads
from .energy import Energy
from .equations import KaneEquations
from .kinematics import Tidier
from .objects import Objects
from .points import Kinematics
from .resolutions import Resolutions
from .script import ScriptNames
from .speeds import Speeds
from .state import ModelState
from .vectors import VectorCommands

__all__ = ["Model", "MODEL_COMMANDS"]


class Model(
    Objects, Kinematics, VectorCommands, MassAndLoads, Speeds, KaneEquations, Energy
):
    """Frames, bodies, points, kinematics, mass, loads and Kane's method of
    one script: the workspace's ``model`` part.

    It is given the small objects of the script it uses (see
    :class:`~.state.ModelPart`): ``script``, the operations on Autolev names
    it calls (:class:`~.script.ScriptNames`: evaluate, normalize, assign,
    respond); ``table``, the script's names; ``settings``; ``statements``;
    ``unit_norms``, the list of unit-norm quantities it adds to."""

    def __init__(
        self,
        script: ScriptNames,
        *,
        table: NameTable,
        settings: Settings,
        statements: Statements,
        unit_norms: list[tuple[Any, ...]],
    ) -> None:
        self.script = script
        self.table = table
        self.settings = settings
        #: where the script's statement calls stand (errors of a module's
        #: call name its ``.al`` line)
        self.statements = statements
        self.unit_norms = unit_norms
        #: The model's state: frames, points, bodies, loads, speeds (shared by
        #: the parts; read by :mod:`.kane` to build ``KanesMethod``'s inputs).
        self.registry = ModelState()
        #: the right-hand sides' substitutions made so far (while the
        #: right-hand sides stay the same)
        self.resolutions = Resolutions(script, table)
        #: tidy's results, each formed once (responses at import and in the
        #: transcript show the same measure numbers many times)
        self.tidier = Tidier()
