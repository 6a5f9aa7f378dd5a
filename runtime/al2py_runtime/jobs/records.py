"""What ``Input``, ``Output`` and ``CODE`` record: the :class:`Job` snapshot,
CODE options (:data:`KINDS`) and integration parameters
(:data:`INTEGRATION_DEFAULTS`), defined once for the runtime and the
transpiler."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import PurePath
from typing import TYPE_CHECKING, Any

from ..safety import AutolevRuntimeError
from .units import UnitSystem

if TYPE_CHECKING:  # annotations only: the transpiler reads KINDS without sympy
    import sympy as sp

__all__ = [
    "NumericsError",
    "INTEGRATION_DEFAULTS",
    "KINDS",
    "normalize_name",
    "InputValue",
    "OutputItem",
    "OutputSpec",
    "AnimateSpec",
    "Job",
]


class NumericsError(AutolevRuntimeError, ValueError):
    """A numerical job cannot run: bad input, no convergence, failed step."""


#: Integration parameters and their defaults (TFINAL, INTEGSTP, PRINTINT are
#: derived when missing: TFINAL = TINITIAL + 10, INTEGSTP = (TFINAL -
#: TINITIAL)/100, PRINTINT = 1).  PRINTINT counts integration steps: a row
#: is written every INTEGSTP*PRINTINT.
INTEGRATION_DEFAULTS: dict[str, float | None] = {
    "TINITIAL": 0.0,
    "TFINAL": None,
    "INTEGSTP": None,
    "PRINTINT": None,
    "ABSERR": 1.0e-8,
    "RELERR": 1.0e-7,
}

KINDS = ("DYNAMICS", "ODE", "NONLINEAR", "ALGEBRAIC")


def normalize_name(name: str) -> str:
    """``"config[ 1 ]"`` -> ``"CONFIG[1]"``, ``"x'"`` -> ``"X'"``."""
    return re.sub(r"\s+", "", str(name)).upper()


# ------------------------------------------------------------------ records


@dataclass(frozen=True)
class InputValue:
    """One ``Input NAME = value unit`` item."""

    value: float
    unit: str | None = None
    line: int | None = None


@dataclass(frozen=True)
class OutputItem:
    label: str
    expr: Any
    unit: str | None = None


@dataclass(frozen=True)
class OutputSpec:
    """One ``Output`` statement: its items, in order.

    ``encoded`` marks the quantities an ``Encode`` statement lists: computed
    at every output row like an Output, kept in the result, never written
    to a file.
    """

    items: tuple[OutputItem, ...]
    line: int | None = None
    encoded: bool = False


@dataclass(frozen=True)
class AnimateSpec:
    """``Animate(N, O, A, B)``: the Newtonian frame, a point, and the frames
    and bodies the CODE jobs that follow animate (see
    :mod:`al2py_runtime.jobs.scene`)."""

    newtonian: Any
    point: Any
    frames: tuple[Any, ...]
    line: int | None = None


@dataclass
class Job:
    """Everything a ``CODE`` statement needs, captured when it is recorded."""

    kind: str
    stem: str
    filename: str | None
    line: int | None
    source: str
    eqs: sp.Matrix | None
    eqs_name: str | None
    unknowns: list[Any]
    sweep: tuple | None
    rhs: dict
    zero: sp.Matrix | None
    outputs: list[OutputSpec]
    inputs: dict[str, InputValue]
    unit_system: UnitSystem
    digits: int
    variables: list[tuple[str, Any, int]]
    names: dict[Any, str]
    entries: dict[str, tuple[str, Any]]
    #: initial values of variables the script never inputs (``NiCheck``'s
    #: work variable starts at 0), by name
    initials: dict[str, float] = field(default_factory=dict)
    #: shapes of the ``Encode``d matrices (their elements are output items)
    encoded: dict[str, tuple[int, int]] = field(default_factory=dict)
    #: the script line declaring each name, where the module gave it
    declared: dict[str, int] = field(default_factory=dict)
    #: words after the file name (``CODE Dynamics() f.c, NOSUBS``), upper case
    options: tuple[str, ...] = ()
    #: the latest ``Animate`` before the CODE statement (None: none)
    animate: AnimateSpec | None = None
    #: the model's positions, frames and mass centers at the CODE statement
    #: (a :class:`~al2py_runtime.jobs.scene.Geometry`), for animations
    geometry: Any = field(default=None, repr=False)
    cache: dict = field(default_factory=dict, repr=False)

    @property
    def where(self) -> str:
        return job_where(self.kind, self.filename, self.line)


def job_stem(file: str | None, script: str) -> str:
    """The stem naming a job's output files: its CODE file's, else the
    script's (``job_stem("tutor6.c", "x.al")`` is ``"tutor6"``).

    >>> job_stem(None, "dir/tutor6.al")
    'tutor6'
    """
    # a Windows path too (BioMAC's ``CODE Algebraic() sub\x_raw.c``)
    path = file.replace("\\", "/") if file else script
    return PurePath(path).stem or "autolev"


def job_where(kind: str, filename: str | None, line: int | None) -> str:
    """How messages name a job: ``CODE Dynamics tutor6.c (line 57)``.

    >>> job_where("DYNAMICS", "tutor6.c", 57)
    'CODE Dynamics tutor6.c (line 57)'
    """
    what = f"CODE {kind.title()}"
    if filename:
        what += f" {filename}"
    if line is not None:
        what += f" (line {line})"
    return what


def output_stems(stems: list[str]) -> list[str]:
    """The stems of jobs whose CODE files have the stems ``stems``, in
    order: a stem an earlier job has (in any case) is named apart,
    ``STEM_2`` (``_3``, ...), so that no job writes another's files
    (Whipple.al's ``WhippleDynamics.m`` and ``WhippleDynamics.c`` write
    ``WhippleDynamics.1`` and ``WhippleDynamics_2.1``).

    >>> output_stems(["w", "W", "a", "w"])
    ['w', 'W_2', 'a', 'w_3']
    """
    used: set[str] = set()
    out = []
    for stem in stems:
        name, k = stem, 2
        while name.lower() in used:
            name, k = f"{stem}_{k}", k + 1
        used.add(name.lower())
        out.append(name)
    return out
