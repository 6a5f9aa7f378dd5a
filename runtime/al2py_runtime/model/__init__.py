"""The script's mechanics as a ``sympy.physics.mechanics`` model.

One concept per module; :class:`al2py_runtime.model.model.Model` assembles them:

* :mod:`.model` -- :class:`~.model.Model`, the parts below as one object
* :mod:`.kinematics` -- pure vector and rotation helpers (no model state)
* :mod:`.state` -- the model's registry: what sympy's objects lack (which
  velocities are Autolev's, accelerations, bodies, loads, speeds)
* :mod:`.script` -- :class:`~.script.ScriptNames`, what the model calls on
  its script (the workspace), as a typed protocol
* :mod:`.objects` -- declarations, mass and inertia, syntactical forms
* :mod:`.points` -- positions, velocities, orientations, two-point formulas
* :mod:`.vectors` -- Autolev's vector and dyadic commands
* :mod:`.bodies` -- mass distribution and loads
* :mod:`.speeds` -- generalized speeds, coordinates, partial velocities
* :mod:`.equations` -- Fr, Fr*, Constrain, Kane
* :mod:`.energy` -- kinetic energy, momentum, Gyrostat, NiCheck
* :mod:`.kane` -- the one place where the model becomes ``KanesMethod``'s
  inputs (:class:`KaneInputs`, :func:`kane_inputs`, :func:`kanes_method`).
* :mod:`.arrange` -- the pure algebra of ``ZERO`` after ``Kane()`` and of
  ``Constrain`` (no model state)
* :mod:`.fastkane` -- the one Kane engine: linear forms of velocities,
  their rates and the Fr/Fr* rows, over named intermediates;
  :class:`~.fastkane.FastKane` runs it on ``KanesMethod``'s inputs

The model of a falling particle, exported to ``KanesMethod``:

>>> from sympy import Eq
>>> from al2py_runtime import Workspace, t
>>> from al2py_runtime.model import kane_inputs, kanes_method
>>> al = Workspace("drop.al")
>>> N, P = al.model.newtonian("N"), al.model.particles("P")
>>> Q, G, U = al.variables("Q'"), al.constants("G"), al.model.motion_variables("U'")
>>> al.model.set_mass(P, 3)
>>> _ = al.kd(Eq(Q.diff(t), U)), al.model.set_vel(P, N, U * N.y)
>>> al.model.gravity(-G * N.y)
>>> inputs = kane_inputs(al.model)
>>> inputs.q, inputs.u, inputs.kd_eqs
([Q(t)], [U(t)], [-U(t) + Derivative(Q(t), t)])
>>> [type(b).__name__ for b in inputs.bodies], inputs.loads[0][1].dot(N.y)
(['Particle'], -3*G)
>>> kanes_method(inputs).forcing.T
Matrix([[-3*G]])
"""

from .kane import KaneInputs, kane_inputs, kanes_method

__all__ = ["KaneInputs", "kane_inputs", "kanes_method"]
