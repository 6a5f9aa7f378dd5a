"""The shortcuts of naming and resolution give what the plain steps give:

* a sum named with its sign taken out is split (``Intermediates._split``)
  only when a term of its negation may exceed the limit: the same
  intermediates, with the same numbers and definitions, as when every
  negation is split, at random sums whose terms sit around the limit;
* ``Intermediates._parts_within`` answers as ``_within`` of each part;
* ``workspace._may_hold_floats`` with the parts kept from earlier calls
  answers as a fresh walk;
* the workspace's resolvers, sharing one table and memo while the
  right-hand sides do not change, follow a new right-hand side at once,
  and Factoring's kept ``factor_terms`` is sympy's.

Each random check is shown to find a wrong answer."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime import Workspace, workspace
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates
from al2py_runtime.model.kinematics import is_small
from sympy.physics.mechanics import dynamicsymbols

q1, q2, q3, u1, u2, u3 = dynamicsymbols("q1 q2 q3 u1 u2 u3")
A, B, C, D = sp.symbols("A B C D")
t = dynamicsymbols._t
ATOMS = [q1, q2, q3, u1, u2, u3, A, B, C, D]


def _factor(rng: random.Random, depth: int) -> sp.Expr:
    kind = rng.random()
    if depth <= 0 or kind < 0.45:
        return rng.choice(ATOMS)
    if kind < 0.65:
        return rng.choice([sp.sin, sp.cos])(rng.choice([q1, q2, q3]))
    if kind < 0.8:
        return _factor(rng, depth - 1) ** rng.choice([2, -1, 3])
    return sp.Add(*[_term(rng, depth - 1) for _ in range(rng.randint(2, 5))])


def _term(rng: random.Random, depth: int) -> sp.Expr:
    factors = [_factor(rng, depth) for _ in range(rng.randint(1, 5))]
    c = rng.choice([1, 1, -1, -1, -1, 2, -3, sp.Rational(1, 2)])
    return c * sp.Mul(*factors)


def _sum(rng: random.Random) -> sp.Expr:
    """A sum leaning negative, its terms of every size around the limit
    (often one large term with atoms, whose negation is just over it)."""
    if rng.random() < 0.4:
        while True:
            big = _term(rng, 2)
            if 21 <= _size(big) <= 26:
                break
        if rng.random() < 0.3:
            big = -big
        atoms = [-x for x in rng.sample(ATOMS, rng.choice([1, 1, 1, 2, 3]))]
        return sp.Add(big, *atoms)
    n = rng.randint(2, 7)
    terms = [_term(rng, rng.randint(1, 3)) for _ in range(n)]
    if rng.random() < 0.7:
        terms = [-x for x in terms]
    return sp.Add(*terms)


def _definitions(book: Intermediates) -> list[str]:
    return [
        f"{book.label_of(k)} {sp.srepr(book.canonical(k))}"
        for k in range(1, len(book) + 1)
    ]


class _AlwaysSplit(Intermediates):
    """The plain steps: a negated sum is always split (``small`` ignored)."""

    def _name(self, expr, negated, small=False):
        return super()._name(expr, negated, False)


def _names_agree(seed: int, fast_book: type = Intermediates, cases: int = 30) -> bool:
    rng = random.Random(seed)
    exprs = [_sum(rng) for _ in range(cases)]
    fast, plain = fast_book(), _AlwaysSplit()
    got = [sp.srepr(fast.name(e)) for e in exprs]
    want = [sp.srepr(plain.name(e)) for e in exprs]
    return got == want and _definitions(fast) == _definitions(plain)


SEEDS = range(8)


@pytest.mark.parametrize("seed", SEEDS)
def test_negated_sums_are_named_as_when_each_is_split(seed):
    assert _names_agree(seed)


class _WrongBound(Intermediates):
    """A bound one node short: a negation with a term just over the limit
    is left whole where the plain steps split it."""

    def _name(self, expr, negated, small=False):
        if negated is not None and not small and expr.is_Add:
            if max(_size(a) for a in expr.args) == self.LIMIT + 1:
                small = True
        return super()._name(expr, negated, small)


def test_the_naming_check_finds_a_wrong_bound():
    assert not all(_names_agree(seed, _WrongBound) for seed in SEEDS)


def _size(e) -> int:
    if e.is_Atom or isinstance(e, autoz._OWN_NODE):
        return 1
    return 1 + sum(_size(a) for a in e.args)


def _random_parts(seed: int) -> list:
    rng = random.Random(seed)
    book = Intermediates()
    z = book.name(sp.cos(q1) * u1 + sp.sin(q2) * A * u2 + q3 * u3 * B)
    pool = [*ATOMS, z, z.subs(q1, q2)]
    out = []
    for _ in range(60):
        ATOMS.extend(pool[-2:])
        try:
            out.append((book, _sum(rng)))
        finally:
            del ATOMS[-2:]
    for _ in range(40):  # flat parts of about the limit's size, leaves only
        flat = rng.sample(MANY, rng.randint(20, 27))
        part = rng.choice([sp.Add, sp.Mul])(*flat)
        out.append((book, sp.Add(part, rng.choice(pool), rng.choice(pool) * A)))
    return out


MANY = [*sp.symbols("x0:30"), q1, q2, u1]


@pytest.mark.parametrize("seed", range(5))
def test_parts_within_answers_as_within_of_each_part(seed):
    for book, e in _random_parts(seed):
        one = book._one_node
        want = all(
            a.is_Atom or isinstance(a, one) or book._within(a, book.LIMIT)
            for a in e.args
        )
        assert book._parts_within(e.args, one) == want


def test_the_parts_check_finds_a_wrong_count():
    class Short(Intermediates):
        LIMIT = Intermediates.LIMIT  # (the check's own count is one short)

        def _parts_within(self, parts, one):
            return all(
                a.is_Atom or isinstance(a, one) or len(a.args) < self.LIMIT - 1
                for a in parts
            )

    differ = False
    for book, e in _random_parts(0):
        one = book._one_node
        want = all(
            a.is_Atom or isinstance(a, one) or book._within(a, book.LIMIT)
            for a in e.args
        )
        differ |= Short._parts_within(book, e.args, one) != want
    assert differ


def _values(seed: int) -> list:
    rng = random.Random(seed)
    out = []
    for _ in range(80):
        e = _sum(rng)
        if rng.random() < 0.3:  # a float deep in a part met before
            e = e.xreplace({rng.choice([A, B, C, D]): sp.Float(rng.choice([0.5, 2.0]))})
        out.append(rng.choice([e, sp.Matrix([e, 1]), [e, _sum(rng)]]))
    return out


@pytest.mark.parametrize("seed", range(4))
def test_floats_are_found_as_by_a_fresh_walk(seed):
    clean: set = set()
    for v in _values(seed):
        assert workspace._may_hold_floats(v, clean) == workspace._may_hold_floats(
            v, set()
        )
        fresh = sp.Matrix(v) if isinstance(v, list) else v
        assert workspace._may_hold_floats(v, clean) == bool(
            sp.Matrix([fresh]).atoms(sp.Float)
        )


def test_the_float_check_finds_a_kept_part_wrongly_clean():
    clean: set = set()
    e = A * sp.Float(0.5) + B
    assert workspace._may_hold_floats(e, clean)
    clean.add(e)  # a wrong entry: the walk trusts it
    assert not workspace._may_hold_floats(e, clean)


def _script():
    al = Workspace("naming_speed.al")
    q, r = al.variables("Q'", "R'")
    u, w = al.variables("U", "W")
    c = al.constants("C")
    al.assign("Q'", u * c, line=3)
    al.assign("R'", w + q, line=4)
    return al, q, r, u, w, c


def test_resolvers_share_a_table_and_follow_new_right_hand_sides():
    al, q, r, u, w, c = _script()
    qd, rd = q.diff(t), r.diff(t)
    e = qd * sp.sin(rd) + rd
    assert al.resolve(e) == u * c * sp.sin(w + q) + w + q
    assert al.resolve(e, keep=[u]) == al.resolve(e)  # u has no right-hand side
    assert al.resolve(e, keep=[qd]) == qd * sp.sin(w + q) + w + q
    assert al._table_without([u]) is al._table_without([])
    assert al._table_without([qd]) is not al._table_without([])
    al.assign("Q'", 2 * u, line=5)
    assert al.resolve(e) == 2 * u * sp.sin(w + q) + w + q
    al.assign("C", 3, line=6)
    assert al.resolve(c * qd) == 6 * u


def test_factoring_keeps_sympys_factor_terms():
    al, q, r, u, w, c = _script()
    al.settings.factoring = True
    rng = random.Random(5)
    for _ in range(30):
        e = _sum(rng)
        for _ in range(2):  # the second answer is the one kept
            got = al._normalized(e, True, False)
            want = sp.factor_terms(e) if e.is_Add and is_small(e) else e
            assert sp.srepr(got) == sp.srepr(want)


def test_factoring_of_floats_is_sympys_at_each_precision():
    al, q, r, u, w, c = _script()
    al.settings.factoring = True
    for digits in (15, 30, 15):
        e = -sp.Float(0.5, digits) * u * c - w
        got = al._normalized(e, True, False)
        assert sp.srepr(got) == sp.srepr(sp.factor_terms(e))
