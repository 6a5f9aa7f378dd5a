"""Autolev's vocabulary is said once (issue 22): one row makes a built-in.

A made-up function, ``HAVERSINE(x) = (1 - COS(x))/2``, is added as one
registry row and nothing else; the analysis, the generator, the transcript's
printer, ``al2py check``'s evaluator and the numeric backend all accept it.
"""

from __future__ import annotations

import doctest
import math
import random

import pytest
import sympy as sp
from al2py_runtime import vocabulary
from conftest import load_module

from al2py import convert, naming
from al2py.checking import evaluate_text


class hav(sp.Function):  # noqa: N801 - named like a sympy function
    """The haversine, kept unevaluated for symbols."""

    nargs = 1

    @classmethod
    def eval(cls, x):
        if x.is_Number:
            return (1 - sp.cos(x)) / 2
        return None


def _hav_number(x: float) -> float:
    return (1 - math.cos(x)) / 2


@pytest.fixture
def haversine():
    """``HAVERSINE`` as one registry row, for the test only."""
    row = vocabulary.library("HAVERSINE", "hav", hav, numeric=_hav_number)
    with vocabulary.registered(row):
        yield row
    assert vocabulary.lookup("HAVERSINE") is None


SCRIPT = """\
Constants K
Variables Q'
H = Haversine(Q)
Q' = -K*Haversine(Q)
Input Q = 1.2, K = 2, tFinal = 1, integStp = 0.1, printInt = 10
Output T, Q, H
CODE ODE() hav.c
"""


def test_a_made_up_builtin_is_one_row(haversine, tmp_path):
    code = convert(SCRIPT, "hav.al").code  # analysis + generator
    assert "from al2py_runtime.functions import hav" in code
    m = load_module(code, tmp_path, "hav")
    # the printer names it with its Autolev name
    transcript = "\n".join(m.al.transcript(SCRIPT.splitlines()))
    assert "H = HAVERSINE(Q)" in transcript
    assert "Q' = -K*HAVERSINE(Q)" in transcript
    # the numeric backend integrates dQ/dT = -K*hav(Q): compare with an RK4
    r = m.run(backend="lambdify")
    q, k = 1.2, 2.0
    n = 1000
    dt = 1.0 / n
    for _ in range(n):
        a = -k * _hav_number(q)
        b = -k * _hav_number(q + dt / 2 * a)
        c = -k * _hav_number(q + dt / 2 * b)
        d = -k * _hav_number(q + dt * c)
        q += dt / 6 * (a + 2 * b + 2 * c + d)
    assert float(r["Q"][-1]) == pytest.approx(q, rel=1e-5)
    assert float(r["H"][-1]) == pytest.approx(_hav_number(q), rel=1e-5)
    # check's evaluator reads a response that uses it
    value = evaluate_text("HAVERSINE(0.5)", m.al)
    assert float(value) == pytest.approx(_hav_number(0.5))


def test_unknown_without_the_row():
    from al2py.errors import AutolevError

    with pytest.raises(AutolevError, match="(?i)haversine"):
        convert(SCRIPT, "hav.al")


def test_printed_names_and_numbers_come_from_the_rows():
    x = sp.Symbol("x")
    printed = {
        sp.ceiling(x): "CEIL",
        sp.Max(x, 2 * x): "MAX",
        vocabulary.lookup("INT").implementation(x): "INT",
        sp.sin(x): "SIN",
    }
    for expr, name in printed.items():
        assert vocabulary.printed_name(expr) == name
    space = vocabulary.numeric_namespace()
    rnd = random.Random(7)
    for _ in range(20):
        v = rnd.uniform(-5, 5)
        assert space["trunc"](v) == math.trunc(v)
        assert space["nint"](v) == math.copysign(math.floor(abs(v) + 0.5), v)
    assert vocabulary.complex_functions()[sp.sin] is __import__("cmath").sin


def test_forms_spell_what_they_match():
    frames, points = {"N", "B"}, {"O", "P"}
    for row in vocabulary.FORMS.values():
        if row.form is vocabulary.Form.UNIT:
            continue
        names = ["N" if r == "f" else "P" for r in row.roles]
        found = vocabulary.match(
            row.spell(*names), frames.__contains__, points.__contains__
        )
        assert found is not None and found.kind is row.form, row.spelling
        assert found.parts == tuple(names)


def test_naming_doctests():
    """The transpiler's naming examples (the runtime modules' examples,
    vocabulary included, run in tests/runtime/test_doctests.py)."""
    result = doctest.testmod(naming, optionflags=doctest.ELLIPSIS)
    assert result.failed == 0 and result.attempted > 0
