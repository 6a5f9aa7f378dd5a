"""Physical entities and Kane's method (tutorial §3, §4.4-4.5, §5.2-5.9).

:class:`MechanicsMixin` adds the physics commands to :class:`Workspace`.
"""

from __future__ import annotations

from typing import Any

import sympy as sp

__all__ = ["MechanicsMixin"]


class MechanicsMixin:
    """Frames, bodies, points, kinematics, mass, loads and Kane's method."""

    # Hooks called by Workspace; the defaults handle nothing.

    def _assign_form(self, key: Any, value: Any, *, line: int | None) -> Any:
        """Store a syntactical form (``P_O_Q>``, ``V_P_N>``, ``N_A``...).

        Return the Python binding, or ``NotImplemented`` if ``key`` is not a
        syntactical form of declared frames/points/bodies."""
        return NotImplemented

    def _form_value(self, key: Any) -> Any:
        """The value of a syntactical form, or ``NotImplemented``."""
        return NotImplemented

    def _vector_d(self, y: Any, x: Any, frame: Any) -> Any:
        raise NotImplementedError("D(vector, x, frame) is not supported yet")

    def _vector_dt(self, y: Any, frame: Any) -> Any:
        raise NotImplementedError("Dt(vector, frame) is not supported yet")

    def trace(self, y: Any) -> Any:
        """``Trace(A)`` of a matrix (the physics layer adds dyadics)."""
        from .matrices import trace

        return trace(self.val(y))
