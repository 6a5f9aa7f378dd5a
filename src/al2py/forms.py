"""Autolev's syntactical forms (tutorial §3.2): names built from object names.

``P_O_Q>`` is the position of Q from O, ``V_P_N>`` the velocity of P in N,
``N_A`` the direction-cosine matrix of N and A, ``A1>`` a unit vector of A...
A name is a form only when its parts are declared objects of the right kind;
otherwise it is an ordinary quantity (tutor2's ``I_SYSTEM_CM>>``).

>>> frames, points = {"N", "A"}, {"O", "P"}
>>> match("P_O_P>", frames.__contains__, points.__contains__)
Form(kind='pos', parts=('O', 'P'))
>>> match("N_A", frames.__contains__, points.__contains__)
Form(kind='dcm', parts=('N', 'A'))
>>> match("A2>", frames.__contains__, points.__contains__)
Form(kind='unit', parts=('A', '2'))
>>> match("UVEC>", frames.__contains__, points.__contains__) is None
True
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass

from .builtins import Kind

__all__ = ["Form", "match", "FORM_KINDS"]


@dataclass(frozen=True, slots=True)
class Form:
    kind: str  # pos vel acc angvel angacc inertia force torque dcm unit
    parts: tuple[str, ...]


#: (regex, form kind, what each captured part must be: "f" frame, "p" point)
_PATTERNS: tuple[tuple[re.Pattern[str], str, str], ...] = (
    (re.compile(r"^P_([A-Z0-9]+)_([A-Z0-9]+)>$"), "pos", "pp"),
    (re.compile(r"^V_([A-Z0-9]+)_([A-Z0-9]+)>$"), "vel", "pf"),
    (re.compile(r"^A_([A-Z0-9]+)_([A-Z0-9]+)>$"), "acc", "pf"),
    (re.compile(r"^W_([A-Z0-9]+)_([A-Z0-9]+)>$"), "angvel", "ff"),
    (re.compile(r"^ALF_([A-Z0-9]+)_([A-Z0-9]+)>$"), "angacc", "ff"),
    (re.compile(r"^FORCE_([A-Z0-9]+)>$"), "force", "p"),
    (re.compile(r"^TORQUE_([A-Z0-9]+)>$"), "torque", "f"),
    (re.compile(r"^I_([A-Z0-9]+)_([A-Z0-9]+)>>$"), "inertia", "bp"),
    (re.compile(r"^([A-Z0-9]+)_([A-Z0-9]+)$"), "dcm", "ff"),
    (re.compile(r"^([A-Z][A-Z0-9]*?)([123])>$"), "unit", "f-"),
)

#: The kind of value each form has.
FORM_KINDS = {
    "pos": Kind.VECTOR,
    "vel": Kind.VECTOR,
    "acc": Kind.VECTOR,
    "angvel": Kind.VECTOR,
    "angacc": Kind.VECTOR,
    "force": Kind.VECTOR,
    "torque": Kind.VECTOR,
    "unit": Kind.VECTOR,
    "inertia": Kind.DYADIC,
    "dcm": Kind.MATRIX,
}


def match(
    name: str,
    is_frame: Callable[[str], bool],
    is_point: Callable[[str], bool],
    is_body: Callable[[str], bool] | None = None,
) -> Form | None:
    """The form ``name`` spells with the declared objects, or None."""
    key = name.upper()
    body = is_body or (lambda n: is_frame(n) or is_point(n))
    tests = {"f": is_frame, "p": is_point, "b": body, "-": lambda _: True}
    for pattern, kind, roles in _PATTERNS:
        m = pattern.match(key)
        if m and all(tests[r](part) for r, part in zip(roles, m.groups(), strict=True)):
            return Form(kind, m.groups())
    return None
