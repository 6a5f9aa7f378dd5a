"""The script's mechanics as a ``sympy.physics.mechanics`` model.

One concept per module; :class:`al2py_runtime.model.model.Model` assembles them:

* :mod:`.model` -- :class:`~.model.Model`, the parts below as one object
* :mod:`.kinematics` -- pure vector and rotation helpers (no model state)
* :mod:`.state` -- the model's registry (bodies, particles, positions...)
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
* :mod:`.fastkane` -- :class:`~.fastkane.FastKane`, Kane's equations with
  named intermediates (for large models)
"""

from .kane import KaneInputs, kane_inputs, kanes_method

__all__ = ["KaneInputs", "kane_inputs", "kanes_method"]
