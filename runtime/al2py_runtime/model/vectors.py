"""VectorCommands: part of :class:`al2py_runtime.model.model.Model`.

Autolev's vector and dyadic commands: ``Express``, ``Represent``, ``Dot``, ``Cross``, ``Mag``, ``UnitVec``, ``1>>``, ``D`` and ``Dt`` of vectors.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.physics.vector import (
    Dyadic,
    ReferenceFrame,
    Vector,
)

from . import kinematics as kin
from .state import ModelPart, command

__all__ = ["VectorCommands"]


class VectorCommands(ModelPart):
    """Autolev's vector and dyadic commands: ``Express``, ``Represent``, ``Dot``, ``Cross``, ``Mag``, ``UnitVec``, ``1>>``, ``D`` and ``Dt`` of vectors."""

    # ------------------------------------------------ vector operations

    @command
    def express(self, v: Any, frame: ReferenceFrame) -> Any:
        """``Express(v>, A)``: ``v>`` in terms of A1>, A2>, A3>.  The unit
        dyadic ``1>>`` is the identity in every frame, whether or not A is
        oriented relative to the frame it was written in."""
        if isinstance(v, Vector):
            return self.tidier.vector(v.express(frame))
        if isinstance(v, Dyadic):
            if kin.is_unit_dyadic(v):
                return kin.unit_dyadic(frame)
            return self.tidier.vector(v.express(frame, frame))
        return v

    @command
    def represent(self, x: Any, frame: ReferenceFrame) -> Any:
        """``Represent(x, A)``: a vector -> the row matrix of its A measure
        numbers, a dyadic -> the 3x3 matrix; and back: a 3-element matrix ->
        vector, a 3x3 matrix -> dyadic."""
        x = self.script.val(x)
        if isinstance(x, Vector):
            return sp.Matrix(
                [[self.tidier(x.dot(e)) for e in (frame.x, frame.y, frame.z)]]
            )
        if isinstance(x, Dyadic):
            return x.to_matrix(frame).applyfunc(self.tidier)
        if isinstance(x, sp.MatrixBase):
            if x.shape == (3, 3):
                return kin.frame_dyadic(frame, x)
            if len(x) == 3:
                return kin.frame_vector(frame, list(x))
        if x == 0:
            return sp.zeros(1, 3)
        raise TypeError(f"cannot represent {x!r} in {frame}")

    @command
    def matrix(self, frame: ReferenceFrame, x: Any) -> sp.Matrix:
        """``Matrix(A, v>)``: see :meth:`represent`."""
        x = self.script.val(x)
        if not isinstance(x, Vector | Dyadic) and x != 0:
            raise TypeError("Matrix(A, x) needs a vector or dyadic")
        return self.represent(x, frame)

    @command
    def vector(self, frame: ReferenceFrame, *m: Any) -> Vector:
        """``Vector(A, x, y, z)`` or ``Vector(A, M)``."""
        if len(m) == 1:
            m = list(self.script.val(m[0]))
        return kin.frame_vector(frame, m)

    @command
    def dyadic(self, frame: ReferenceFrame, *m: Any) -> Dyadic:
        """``Dyadic(A, M)`` (3x3), nine scalars (row by row) or three (diagonal)."""
        if len(m) == 1:
            mat = sp.Matrix(self.script.val(m[0]))
        elif len(m) == 9:
            mat = sp.Matrix(3, 3, list(m))
        elif len(m) == 3:
            mat = sp.diag(*m)
        else:
            raise ValueError("Dyadic(A, ...) takes a 3x3 matrix, 9 or 3 scalars")
        if mat.shape != (3, 3):
            raise ValueError("Dyadic(A, M) needs a 3x3 matrix")
        return kin.frame_dyadic(frame, mat)

    @command
    def dot(self, a: Any, b: Any) -> Any:
        a, b = self.script.val(a), self.script.val(b)
        if isinstance(a, kin.VectorMatrix) or isinstance(b, kin.VectorMatrix):
            return kin.vdot_matrix(a, b).applyfunc(self.tidier)
        return self.tidier(kin.vdot(a, b))

    @command
    def cross(self, a: Any, b: Any) -> Any:
        return self.tidier.vector(kin.vcross(self.script.val(a), self.script.val(b)))

    @command
    def magsq(self, v: Any) -> Any:
        v = self.script.val(v)
        if isinstance(v, Vector):
            return self.tidier(kin.dot(v, v))
        return sp.sympify(v) ** 2

    @command
    def mag(self, v: Any) -> Any:
        v = self.script.val(v)
        if isinstance(v, Vector):
            return sp.sqrt(self.magsq(v))
        return sp.Abs(sp.sympify(v))

    @command
    def unitvec(self, v: Any) -> Vector:
        v = self.script.val(v)
        m = self.mag(v)
        if m == 0:
            raise ValueError("UnitVec of the zero vector")
        return kin.vmap(v, lambda e: e / m)

    @command
    def unit_dyadic(self) -> Dyadic:
        """``1>>``, expressed in the Newtonian frame (without one, in the first
        declared frame; ``Express(1>>, A)`` gives it in any frame)."""
        st = self.registry
        n = st.newtonian or next(iter(st.frames.values()), None)
        if n is None:
            raise ValueError("1>> needs a frame: declare one first")
        return kin.unit_dyadic(n)

    @command
    def vector_matrix(self, rows: list) -> kin.VectorMatrix:
        """A matrix literal of vectors, ``[V1>; V2>]`` (an argument of Dot)."""
        return kin.VectorMatrix(
            [[kin.as_vector(self.script.val(e)) for e in r] for r in rows]
        )

    @command
    def trace(self, y: Any) -> Any:
        """``Trace(A)`` of a matrix or a dyadic."""
        y = self.script.val(y)
        if isinstance(y, Dyadic):
            if not y.args:
                return sp.Integer(0)
            frame = y.args[0][1].args[0][1]
            return self.tidier(y.to_matrix(frame).trace())
        from ..matrices import trace

        return trace(y)

    def vector_d(self, y: Any, x: Any, frame: Any) -> Any:
        """``D(v>, x, A)``: partial derivative of a vector in frame A."""
        if frame is None:
            frame = self.registry.newtonian
        if isinstance(y, Dyadic):
            if frame is None:
                return kin.vmap(y, lambda e: sp.diff(e, x))
            return kin.vmap(y.express(frame, frame), lambda e: sp.diff(e, x))
        if not isinstance(y, Vector):
            return sp.diff(y, x)
        if frame is None:
            return kin.vmap(y, lambda e: sp.diff(e, x))
        return self.tidier.vector(y.diff(x, frame))

    def vector_dt(self, y: Any, frame: Any) -> Any:
        """``Dt(v>, A)``: time derivative in frame A (default: Newtonian)."""
        if frame is None:
            frame = self.newtonian_frame()
        if not isinstance(y, Vector | Dyadic):
            return self.resolved_dt(y, frame)
        return self.tidier.vector(self.resolved_dt(y, frame))
