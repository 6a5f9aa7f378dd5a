"""Numerical CODE jobs: Input/Output with units, Dynamics/ODE/Nonlinear/Algebraic.

:class:`NumericsMixin` adds ``Input``, ``Output``, ``UnitSystem``, ``CODE`` and
``run()`` to :class:`Workspace`.
"""

from __future__ import annotations

__all__ = ["NumericsMixin"]


class NumericsMixin:
    """Inputs, outputs, units and the numerical job of a script."""
