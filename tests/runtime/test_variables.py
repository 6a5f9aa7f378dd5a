"""A script's functions of time (``names.variables``) behave as the ones
``dynamicsymbols`` makes: users mix the two (``kanes_method()``, their own
``dynamicsymbols("Q1", real=True)``), so they must be interchangeable."""

from __future__ import annotations

import pickle

import sympy as sp
from al2py_runtime.names.variables import TimeFunction, time_function
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols

T = dynamicsymbols._t


def test_equal_to_and_hashed_as_dynamicsymbols_either_way():
    mine, theirs = time_function("Q1", real=True), dynamicsymbols("Q1", real=True)
    assert type(mine.func) is TimeFunction
    assert mine == theirs and theirs == mine and not (mine != theirs)
    assert mine.func == theirs.func and theirs.func == mine.func
    assert hash(mine) == hash(theirs) and hash(mine.func) == hash(theirs.func)
    assert {mine: 1}[theirs] == 1 and len({mine, theirs}) == 1
    assert mine != dynamicsymbols("Q1") and mine != time_function("Q2", real=True)
    assert time_function("Q1").func != mine.func  # other assumptions
    assert mine.is_real and time_function("P", nonnegative=True).is_nonnegative


def test_expressions_mix_with_dynamicsymbols():
    q, u = time_function("Q", real=True), time_function("U", real=True)
    q2, u2 = dynamicsymbols("Q U", real=True)
    e = sp.sin(q) * u**2 + q.diff(T)
    assert e.xreplace({q2: 1, u2: 2}) == e.xreplace({q: 1, u: 2}) != e
    assert e.diff(q2) == sp.cos(q) * u**2
    assert e.subs(q2.diff(T), 5).has(q.diff(T)) is False
    assert sp.simplify(e - (sp.sin(q2) * u2**2 + q2.diff(T))) == 0
    f = sp.lambdify((q2, u2), sp.sin(q) * u)
    assert abs(f(0.5, 2.0) - 2.0 * 0.958851077208406 / 2) < 1e-12


def test_the_kept_hash_is_sympys():
    for name, assumptions in [
        ("A", {}),
        ("B", {"real": True}),
        ("C", {"positive": True}),
    ]:
        mine = TimeFunction(name, **assumptions)
        assert hash(mine) == hash(sp.Function(name, **assumptions))
    # pickled by value, as sympy's undefined functions are
    q = time_function("Q9", real=True)
    back = pickle.loads(pickle.dumps(sp.sin(q) + 1))
    assert (
        back == sp.sin(q) + 1
        and type(back.atoms(AppliedUndef).pop().func) is TimeFunction
    )


def test_the_books_derivative_by_an_equal_function_of_time():
    """``D(e, x)`` by a function of time made elsewhere (an equal class, not
    the same object) is the derivative by the script's own."""
    from al2py_runtime.intermediates.autoz import Intermediates

    q, u = time_function("Q", real=True), time_function("U", real=True)
    book = Intermediates()
    e = book.name(sp.sin(q) * u + q**3 * u**2) * q + u
    theirs = dynamicsymbols("Q", real=True)
    assert theirs is not q and theirs.func is not q.func
    by_theirs = book.expand(book.derivative(e, theirs))
    assert sp.simplify(by_theirs - book.expand(e).diff(q)) == 0
    assert by_theirs != 0
