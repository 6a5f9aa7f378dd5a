"""sympy's own ``KanesMethod`` derivation, the reference the exported model
(``kanes_method()``, derived by the runtime's FastKane) is compared with.

Only tests build it: the runtime never calls sympy's derivation."""

from __future__ import annotations

import random

import numpy as np
import sympy as sp
from sympy.physics import mechanics as me

T = me.dynamicsymbols._t


def sympy_kanes_method(inputs) -> me.KanesMethod:
    """``KanesMethod(...).kanes_equations(...)`` on the runtime's ``KaneInputs``."""
    kw = {}
    if inputs.u_dependent:
        kw["u_dependent"] = inputs.u_dependent
        kw["velocity_constraints"] = inputs.velocity_constraints
    if inputs.u_auxiliary:
        kw["u_auxiliary"] = inputs.u_auxiliary
    km = me.KanesMethod(
        inputs.frame, q_ind=inputs.q_ind, u_ind=inputs.u_ind, kd_eqs=inputs.kd_eqs, **kw
    )
    # calls sympy's own method even if a subclass overrides it
    me.KanesMethod.kanes_equations(km, inputs.bodies, inputs.loads)
    assert type(km) is me.KanesMethod
    return km


def results(km) -> dict[str, sp.Matrix]:
    """What a user reads from a ``KanesMethod``."""
    out = {
        "mass_matrix_full": km.mass_matrix_full,
        "forcing_full": km.forcing_full,
        "mass_matrix": km.mass_matrix,
        "forcing": km.forcing,
        # KanesMethod keeps what kanes_equations() returned here
        "fr": km._fr,
        "frstar": km._frstar,
    }
    if len(km._uaux):
        out["auxiliary_eqs"] = km.auxiliary_eqs
    return out


def assert_same_kane(ours, ref, seed: str, points: int = 2, rtol=1e-9) -> None:
    """``ours`` and ``ref`` have the same results, plain expressions of the
    same symbols (no intermediates), equal at random points."""
    assert isinstance(ours, me.KanesMethod)
    assert list(ours.q) == list(ref.q) and list(ours.u) == list(ref.u)
    mine, theirs = results(ours), results(ref)
    assert mine.keys() == theirs.keys()
    dyn, consts = set(), set()
    for name, m in mine.items():
        assert m.shape == theirs[name].shape, name
        free = m.free_symbols - {T}
        assert free <= theirs[name].free_symbols | {T}, (name, free)
        consts |= free | theirs[name].free_symbols - {T}
        dyn |= me.find_dynamicsymbols(m) | me.find_dynamicsymbols(theirs[name])
        dyn |= m.atoms(sp.Derivative) | theirs[name].atoms(sp.Derivative)
    names = list(mine)
    rng = random.Random(seed)
    for _ in range(points):
        at = {x: sp.Float(rng.uniform(0.3, 1.2)) for x in sorted(dyn | consts, key=str)}
        for name in names:
            a, b = value_at(mine[name], at), value_at(theirs[name], at)
            assert np.allclose(a, b, rtol=rtol, atol=rtol), (seed, name, a, b)


def value_at(m: sp.Matrix, at: dict) -> np.ndarray:
    """``m``'s value with ``at``'s numbers for its symbols, functions of time
    and derivatives, each shared subexpression evaluated once (written-out
    equations of a large model are trees far bigger than the graphs they
    are made of; lambdify and subs walk the trees)."""
    done: dict = {}

    def walk(e):
        found = at.get(e)
        if found is not None or not e.args:
            return e if found is None else found
        found = done.get(e)
        if found is None:
            found = done[e] = e.func(*[walk(a) for a in e.args])
        return found

    return np.array([[complex(walk(x)) for x in row] for row in m.tolist()])
