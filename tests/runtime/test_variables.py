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


def test_the_kept_rate_is_sympys():
    """``Q1(t).diff(t)`` is formed once (``TimeValue``): the kept answer is
    what sympy forms, in every expression whose time derivative uses it,
    and any other call of ``diff`` (or one under ``evaluate(False)``) is
    sympy's own."""
    q, u = time_function("Q7", real=True), time_function("U7", real=True)
    theirs_q, theirs_u = dynamicsymbols("Q7 U7", real=True)
    kept = q.diff(T)
    assert q.diff(T) is kept and sp.diff(q, T) is kept
    assert kept == theirs_q.diff(T) == sp.Derivative(theirs_q, T)
    assert type(kept) is sp.Derivative and kept.args == (q, sp.Tuple(T, 1))
    # time derivatives of expressions of both, at random points: the same
    rng = __import__("random").Random(7)
    x = sp.Symbol("x")
    atoms = [q, u, x, sp.sin(q), sp.cos(u) * q, q * u, u**2, sp.exp(q)]
    subs_of = {theirs_q: q, theirs_u: u}
    for _ in range(60):
        e = sp.Integer(rng.randint(1, 4))
        for _ in range(rng.randint(1, 4)):
            term = rng.choice(atoms) * rng.choice(atoms)
            e = e + term if rng.random() < 0.5 else e * term
        mine = e.diff(T)
        sympys = e.xreplace({q: theirs_q, u: theirs_u}).diff(T).xreplace(subs_of)
        assert mine == sympys  # the same expression, node for node
        # and the chain rule's value: along q = sin(t) + 1/2, u = cos(2 t)
        q_t, u_t = sp.sin(T) + sp.Rational(1, 2), sp.cos(2 * T)
        along = {q.diff(T): q_t.diff(T), u.diff(T): u_t.diff(T), q: q_t, u: u_t}
        at = {T: rng.uniform(-2, 2), x: rng.uniform(-2, 2)}
        expected = complex(e.xreplace({q: q_t, u: u_t}).diff(T).evalf(subs=at))
        got = complex(mine.xreplace(along).evalf(subs=at))
        assert abs(got - expected) <= 1e-9 * max(1.0, abs(expected))
    # other calls: sympy's
    assert q.diff(T, 2) == theirs_q.diff(T, 2) and q.diff(q) == 1
    assert q.diff(x) == 0 and q.diff(T, evaluate=False) == sp.Derivative(q, T)
    with sp.evaluate(False):
        unevaluated = q.diff(T)
    with sp.evaluate(False):
        assert unevaluated == theirs_q.diff(T).xreplace(subs_of)
    assert unevaluated is not kept
