"""The script's mechanics as a ``sympy.physics.mechanics`` model.

:mod:`.kane` holds the one place where the model's bodies, loads, kinematical
differential equations and constraints become a ``KanesMethod``
(:class:`KaneInputs`, :func:`kanes_method`)."""

from .kane import KaneInputs, kane_inputs, kanes_method

__all__ = ["KaneInputs", "kane_inputs", "kanes_method"]
