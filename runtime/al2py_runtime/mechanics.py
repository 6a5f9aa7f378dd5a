"""Physical entities and Kane's method (tutorial §3, §4.4-4.5, §5.2-5.9).

:class:`MechanicsMixin` adds the physics commands to :class:`Workspace`.
"""

from __future__ import annotations

__all__ = ["MechanicsMixin"]


class MechanicsMixin:
    """Frames, bodies, points, kinematics, mass, loads and Kane's method."""
