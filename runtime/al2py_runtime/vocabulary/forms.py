"""Autolev's syntactical forms (tutorial §3.2): names built from object names.

``P_O_Q>`` is the position of Q from O, ``V_P_N>`` the velocity of P in N,
``N_A`` the direction-cosine matrix of N and A, ``A1>`` a unit vector of A...
A name is a form only when its parts are declared objects of the right role;
otherwise it is an ordinary quantity (tutor2's ``I_SYSTEM_CM>>``).

Each :class:`NameForm` row gives the pattern, the role of each part, the
kind of value, the runtime's getter and setter (named after the sympy calls
they make), and how the name is spelled from its objects' names.

>>> frames, points = {"N", "A"}, {"O", "P"}
>>> match("p_o_p>", frames.__contains__, points.__contains__)
Match(kind=<Form.POS: 'pos'>, parts=('O', 'P'))
>>> match("N_A", frames.__contains__, points.__contains__).row.getter
'dcm'
>>> match("A2>", frames.__contains__, points.__contains__).parts
('A', '2')
>>> match("UVEC>", frames.__contains__, points.__contains__) is None
True
>>> Form.VEL.row.spell("P", "N"), Form.VEL.row.value_kind
('V_P_N>', <Kind.VECTOR: 'vector'>)
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum
from typing import NamedTuple

from .kinds import Kind

__all__ = ["Form", "NameForm", "Match", "FORMS", "match", "unit_vector"]


class Form(Enum):
    """The syntactical forms."""

    POS = "pos"
    VEL = "vel"
    ACC = "acc"
    ANGVEL = "angvel"
    ANGACC = "angacc"
    FORCE = "force"
    TORQUE = "torque"
    INERTIA = "inertia"
    DCM = "dcm"
    UNIT = "unit"

    @property
    def row(self) -> NameForm:
        return FORMS[self]


@dataclass(frozen=True, slots=True)
class NameForm:
    """One syntactical form.

    ``roles`` says what each captured part must be: ``f`` a frame, ``p`` a
    point, ``b`` a body or particle, ``-`` anything (a unit vector's axis).
    ``getter(*objects)`` reads the value and ``setter(*objects, value)``
    assigns it (runtime method names); ``setter_order`` lists the parts in
    the order the setter takes them (``P_O_P> = v`` is ``set_pos(P, O, v)``,
    sympy's ``P.set_pos(O, v)``)."""

    form: Form
    pattern: re.Pattern[str]
    roles: str
    value_kind: Kind
    spelling: str  # ``P_{0}_{1}>``
    getter: str | None
    setter: str | None
    setter_order: tuple[int, ...] = ()

    def spell(self, *names: str) -> str:
        """The Autolev name of the form for objects called ``names``."""
        return self.spelling.format(*names)


_PART = "([A-Z0-9]+)"


def _row(
    form: Form,
    spelling: str,
    roles: str,
    kind: Kind,
    getter: str | None,
    setter: str | None = None,
    order: tuple[int, ...] | None = None,
) -> NameForm:
    # Spellings hold letters, '_' and '>' only: no regex syntax to escape.
    regex = spelling.replace("{0}", _PART).replace("{1}", _PART)
    return NameForm(
        form,
        re.compile(f"^{regex}$"),
        roles,
        kind,
        spelling,
        getter,
        setter if setter is not None else f"set_{getter}",
        order if order is not None else tuple(range(len(roles))),
    )


_V = Kind.VECTOR

#: The forms, in the order names are tried.
FORMS: dict[Form, NameForm] = {
    row.form: row
    for row in (
        _row(Form.POS, "P_{0}_{1}>", "pp", _V, "pos", order=(1, 0)),
        _row(Form.VEL, "V_{0}_{1}>", "pf", _V, "vel"),
        _row(Form.ACC, "A_{0}_{1}>", "pf", _V, "acc"),
        _row(Form.ANGVEL, "W_{0}_{1}>", "ff", _V, "ang_vel"),
        _row(Form.ANGACC, "ALF_{0}_{1}>", "ff", _V, "ang_acc"),
        _row(Form.FORCE, "FORCE_{0}>", "p", _V, "force_on", "set_force"),
        _row(Form.TORQUE, "TORQUE_{0}>", "f", _V, "torque_on", "set_torque"),
        _row(
            Form.INERTIA,
            "I_{0}_{1}>>",
            "bp",
            Kind.DYADIC,
            "inertia_dyadic",
            "set_inertia_about",
        ),
        _row(Form.DCM, "{0}_{1}", "ff", Kind.MATRIX, "dcm"),
        NameForm(
            Form.UNIT,
            re.compile(r"^([A-Z][A-Z0-9]*?)([123])>$"),
            "f-",
            _V,
            "{0}{1}>",
            None,  # a frame's basis vector: ``A.x``
            None,
        ),
    )
}


class Match(NamedTuple):
    """A name read as a form: which form, and its parts' names (upper case)."""

    kind: Form
    parts: tuple[str, ...]

    @property
    def row(self) -> NameForm:
        return FORMS[self.kind]


def match(
    name: str,
    is_frame: Callable[[str], bool],
    is_point: Callable[[str], bool],
    is_body: Callable[[str], bool] | None = None,
) -> Match | None:
    """The form ``name`` spells with the declared objects, or None.

    ``is_body`` (by default: a frame or a point) tells a body or particle,
    whose inertia ``I_B_P>>`` is."""
    key = name.upper()
    body = is_body or (lambda n: is_frame(n) or is_point(n))
    tests = {"f": is_frame, "p": is_point, "b": body, "-": lambda _: True}
    for row in FORMS.values():
        m = row.pattern.match(key)
        if m and all(
            tests[r](part) for r, part in zip(row.roles, m.groups(), strict=True)
        ):
            return Match(row.form, m.groups())
    return None


def unit_vector(name: str) -> tuple[str, int] | None:
    """``("A", 2)`` for a unit vector's name ``A2>`` (any frame name), else
    None.

    >>> unit_vector("b3>"), unit_vector("X>")
    (('B', 3), None)
    """
    m = FORMS[Form.UNIT].pattern.match(name.upper())
    return (m.group(1), int(m.group(2))) if m else None
