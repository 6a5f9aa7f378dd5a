"""The shortcuts of naming (``Intermediates._scan`` and its kept unions of
the intermediates' variables) give exactly what a plain walk with sympy's
own traversal finds, at random expressions over a book's intermediates
(canonical ones, ones taken elsewhere than at their own variables, and
their partial derivatives); and the check is shown to find a wrong set."""

from __future__ import annotations

import functools
import random

import pytest
import sympy as sp
from al2py_runtime.intermediates import autoz
from al2py_runtime.intermediates.autoz import Intermediates
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols

q1, q2, q3, u1, u2 = dynamicsymbols("q1 q2 q3 u1 u2")
L, M = sp.symbols("L M")
t = dynamicsymbols._t
VARIABLES = [q1, q2, q3, u1, u2, L, M, t, q1.diff(t), u2.diff(t)]


def _variables(expr) -> set:
    """sympy's traversal: symbols, functions of time and derivatives, each
    outside the others (an intermediate's number is not one)."""
    out = set()
    walk = sp.preorder_traversal(expr)
    for x in walk:
        if isinstance(x, sp.Derivative | AppliedUndef) or x.is_Symbol:
            out.add(x)
            walk.skip()
    return out


def _stray(book, expr) -> list:
    """The intermediates not at their own variables, in the order of a
    depth-first walk that stacks each part's arguments in order and takes
    the last first (each distinct part once), not entering a canonical one."""
    found, seen, stack = [], set(), [expr]
    while stack:
        e = stack.pop()
        if isinstance(e, book.Z):
            if tuple(e.args[1:]) == book.canonical(e.args[0].p)[0]:
                continue
            found.append(e)
            args = e.args[1:]
        else:
            args = e.args
        for a in args:
            if a not in seen and not a.is_Atom:
                seen.add(a)
                stack.append(a)
    return found


@pytest.fixture(scope="module")
def pool():
    rng = random.Random(5)
    book = Intermediates()
    book.rates = frozenset([q1.diff(t), u2.diff(t)])
    parts = [sp.sin(q1), sp.cos(q2), q3, u1, L, M, t * u2, q1.diff(t), u2.diff(t)]
    zs = []
    for _ in range(60):
        terms = [
            sp.Rational(rng.choice([-3, -1, 1, 2]), rng.choice([1, 2]))
            * sp.Mul(*rng.sample(parts, rng.randint(1, 3)))
            for _ in range(rng.randint(2, 4))
        ]
        z = book.name(sp.Add(*terms))
        if not isinstance(z, book.Z):
            z = -z  # named with its sign taken out
        if isinstance(z, book.Z):
            zs.append(z)
            parts.append(z)
    # partial derivatives (named), and intermediates at other arguments
    assert len(zs) > 30
    for z in rng.sample(zs, 20):
        for x in rng.sample(VARIABLES, 3):
            d = book.derivative(z, x)
            if isinstance(d, book.Z):
                parts.append(d)
    stray = [
        z.xreplace({x: rng.choice([L * q2, sp.S(2), u1 + M, sp.sin(q3)])})
        for z in rng.sample(zs, 10)
        for x in [a for a in z.args[1:] if a != t and not a.is_Derivative][:1]
    ]
    return rng, book, parts, stray


def _cases(pool, n=400):
    rng, book, parts, stray = pool
    out = []
    for _ in range(n):
        chosen = rng.sample(parts + stray, rng.randint(1, 6))
        terms = [
            sp.Mul(*rng.sample(chosen, rng.randint(1, len(chosen))))
            for _ in range(rng.randint(1, 4))
        ]
        e = sp.Add(*terms)
        if rng.random() < 0.3:
            e = sp.cos(e) * rng.choice(VARIABLES) + rng.choice(chosen) ** 2
        out.append(e)
    return book, out


def test_scan_finds_sympys_variables(pool):
    book, cases = _cases(pool)
    n_stray = 0
    for e in cases:
        variables, derivatives, bad = book._scan(e)
        want = _variables(e)
        assert set(variables) == want, e
        assert set(derivatives) == {x for x in want if isinstance(x, sp.Derivative)}
        assert bad == _stray(book, e), e
        n_stray += bool(bad)
    assert n_stray > 20  # the stray intermediates are met


def test_scan_of_named_partials(pool):
    """Each intermediate's variables (its arguments) are those of its
    definition, as sympy finds them: also for the partial derivatives."""
    _, book, _, _ = pool
    for k in range(1, len(book) + 1):
        variables, body = book.canonical(k)
        assert set(variables) == _variables(body)
        assert set(book._scan(body)[0]) == set(variables)


def test_the_check_finds_a_wrong_set(pool):
    """A walk that stops at every intermediate (reads no variables off the
    canonical ones) is told apart."""
    book, cases = _cases(pool, 50)

    def shallow(e):
        out = set()
        walk = sp.preorder_traversal(e)
        for x in walk:
            if isinstance(x, book.Z):
                walk.skip()
            elif isinstance(x, sp.Derivative | AppliedUndef) or x.is_Symbol:
                out.add(x)
                walk.skip()
        return out

    assert any(shallow(e) != _variables(e) for e in cases)


def _sums(pool, n=400):
    """Sums of distinct monomials over intermediates, functions of time,
    symbols, sines and sums, with powers (some terms differ in one
    exponent only)."""
    rng, book, parts, _ = pool
    bases = [*parts[:40], q1, u1, L, M, sp.sin(q2), L + q3, q1.diff(t)]
    out = []
    while len(out) < n:
        common = rng.sample(bases, rng.randint(0, 2))
        terms = []
        for _ in range(rng.randint(2, 5)):
            own = rng.sample(bases, rng.randint(1, 3))
            factors = [b ** rng.choice([1, 1, 2, 3, -1]) for b in own + common]
            coeff = rng.choice([1, -1, 2, sp.Rational(-3, 2), sp.Rational(1, 3)])
            terms.append(coeff * sp.Mul(*factors))
        e = sp.Add(*terms)
        if e.is_Add:
            out.append(e)
    return book, out


def test_the_first_term_is_sympys(pool):
    """``_first_term`` is the first of ``as_ordered_terms`` (the term that
    decides the sign of a sum), with the book's kept sort keys and with
    sympy's."""
    book, sums = _sums(pool)
    found = 0
    for e in sums:
        want = e.as_ordered_terms()[0]
        for key in (book._sort_key, sp.default_sort_key):
            got = autoz._first_term(e.args, key)
            if got is not None:
                assert got == want, e
                found += 1
    assert found > 500


def test_the_check_finds_a_wrong_first_term(pool, monkeypatch):
    """Deciding by the last generator instead of the first is told apart
    (the class keys, which decide first, and the sort keys reversed)."""
    book, sums = _sums(pool, 100)
    real = autoz._class_first
    monkeypatch.setattr(autoz, "_class_first", lambda b: _reversed(real(b)))

    wrong = 0
    for e in sums:
        got = autoz._first_term(e.args, lambda x: _Reversed(book._sort_key(x)))
        wrong += got is not None and got != e.as_ordered_terms()[0]
    assert wrong > 10


def test_the_least_generator_is_mins(pool):
    """``_least_generator`` (class keys first) picks what ``min`` by the
    whole sort key picks, the first of equal ones included."""
    rng, book, parts, _ = pool
    D = sp.Dummy("L")
    bases = [*parts[:30], q1, u1, L, M, D, sp.Symbol("L", positive=True), L + M]
    bases += [sp.sin(q2), sp.cos(q1), L + q3, parts[3] + parts[4], q1.diff(t)]
    bases += [sp.sqrt(L + M), sp.sqrt(parts[5]), parts[6] ** sp.Rational(1, 3)]
    bases += [sp.exp(q1), u1 ** sp.Rational(1, 2)]
    for _ in range(3000):
        varying = rng.sample(bases, rng.randint(2, 7))
        for key in (book._sort_key, sp.default_sort_key):
            assert autoz._least_generator(varying, key) is min(varying, key=key)


def _reversed(key):
    return None if key is None else _Reversed(key)


class _Reversed:
    """A key ordered the other way round."""

    def __init__(self, key):
        self.key = key

    def __lt__(self, other):
        return other.key < self.key

    def __eq__(self, other):
        return isinstance(other, _Reversed) and other.key == self.key

    __hash__ = None


def test_an_intermediates_commutativity_is_sympys(pool):
    """Whether a new intermediate commutes (kept per set of variables when
    it is made) is sympy's answer from its arguments, also when one of them
    does not commute."""
    _, book, parts, stray = pool
    sympys = sp.Basic.is_commutative.fget
    A = sp.Symbol("A", commutative=False)
    other = Intermediates()
    made = [other.name(sp.cos(q1) * L + sp.sin(q2) * A + M * u1)]
    made += [other.name(sp.cos(q1) * L + sp.sin(q2) * M + A)]
    made += [other.name(sp.cos(q1) * L + sp.sin(q2) * M + q3)]
    zs = [z for z in parts + stray + made if hasattr(z, "book")]
    assert sum(1 for z in zs if not z.is_commutative) == 2
    for z in zs:
        assert z.is_commutative is sympys(z.func(*z.args)), z


def _tree_size(book, expr) -> int:
    """Tree nodes as ``_split`` counts them, by sympy's traversal: an
    intermediate, a function of time or a derivative is one node."""
    n = 0
    walk = sp.preorder_traversal(expr)
    for x in walk:
        n += 1
        if isinstance(x, book.Z | AppliedUndef | sp.Derivative):
            walk.skip()
    return n


def test_the_size_read_by_the_scan_is_splits(pool):
    """The size ``_walk`` reads on the way is the tree's, as ``_split``
    counts it (more with a stray intermediate, whose arguments it walks;
    unknown when a part repeats), and an expression of at most ``LIMIT + 1``
    nodes is one that ``_split`` leaves alone (naming skips it)."""
    book, cases = _cases(pool)
    rng = random.Random(9)
    small = [sp.Add(*rng.sample(cases, 2)) * q1 for _ in range(50)]
    small += [sp.cos(q1) * L + sp.sin(q2) * M, (L + M) * (q1 + u1) + u1]
    exact = short = 0
    for e in cases + small:
        size = book._walk(e)[3]
        want = _tree_size(book, e)
        if size == float("inf"):
            continue
        if book._scan(e)[2]:
            assert size >= want, e
        else:
            assert size == want, e
            exact += 1
        if size <= book.LIMIT + 1:
            assert book._split(e) is e
            short += 1
    assert exact > 200 and short > 50


def test_no_part_of_a_definition_is_long():
    """Naming splits every part longer than ``LIMIT`` nodes, also in an
    expression only a little longer than that (which naming walks only
    once, with its variables)."""
    book = Intermediates()
    rng = random.Random(4)
    atoms = [q1, q2, q3, u1, u2, L, M]
    for n in range(2, 40):
        part = sp.Add(*[rng.choice(atoms) * rng.choice(atoms) for _ in range(n)])
        book.name(sp.cos(q1) * part + rng.choice(atoms))
        book.name(sp.sin(q2) * part * L + M * q1 * q2)
    assert len(book) > 40
    for k in range(1, len(book) + 1):
        body = book.canonical(k)[1]
        assert all(_tree_size(book, a) <= book.LIMIT for a in body.args), body


def _term_lists(pool, n=300):
    """Lists of distinct terms, as sums sort them: products with and
    without coefficients, intermediates, functions of time, symbols,
    powers, sines, floats and sums."""
    rng, book, parts, stray = pool
    atoms = [q1, q2, u1, L, M, sp.sin(q2), L + q3, q1.diff(t), sp.Float(0.5) * L]
    pieces = parts[:50] + stray[:5] + atoms
    out = []
    for _ in range(n):
        terms = set()
        for _ in range(rng.randint(2, 40)):
            chosen = rng.sample(pieces, rng.randint(1, 3))
            c = rng.choice([1, 1, -1, 2, sp.Rational(-3, 2), sp.Rational(1, 3)])
            terms.add(c * sp.Mul(*[f ** rng.choice([1, 1, 2]) for f in chosen]))
        terms.discard(sp.S.Zero)
        out.append([x for x in terms if not x.is_Number])
    return out


def test_sorting_by_a_prefix_is_sorting_by_compare(pool):
    """``_sort_by_compare`` orders as ``Basic.compare`` (sympy's order of a
    sum's terms), and the prefixes decide most pairs."""
    by_compare = functools.cmp_to_key(sp.Basic.compare)
    decided = 0
    for terms in _term_lists(pool):
        want = sorted(terms, key=by_compare)
        got = list(terms)
        autoz._sort_by_compare(got)
        assert got == want and all(a is b for a, b in zip(got, want, strict=True))
        kinds: dict = {}
        keys = [autoz._prefix(x, kinds) for x in terms]
        decided += None not in keys and len(set(keys)) > len(keys) // 2
    assert decided > 100


def test_the_check_finds_a_wrong_prefix(pool, monkeypatch):
    """A prefix that orders rationals the other way round is found."""

    def wrong(x, kinds):
        key = real(x, kinds)
        if key is None:
            return key
        top, n, place, extra = key
        return top, n, place, tuple(-v for v in extra)

    real = autoz._prefix
    monkeypatch.setattr(autoz, "_prefix", wrong)
    by_compare = functools.cmp_to_key(sp.Basic.compare)
    bad = 0
    for terms in _term_lists(pool, 100):
        got = list(terms)
        autoz._sort_by_compare(got)
        bad += got != sorted(terms, key=by_compare)
    assert bad > 10


def test_the_least_intermediate_is_sympys(pool):
    """``_least_intermediate`` picks the first by ``default_sort_key`` among
    intermediates of one book (canonical, partial derivatives, taken at
    other arguments), and declines where their numbers do not decide."""
    rng, book, parts, stray = pool
    zs = [z for z in parts + stray if isinstance(z, book.Z)]
    other = Intermediates()
    foreign = other.name(sp.cos(q1) * L + sp.sin(q2) * M)
    decided = declined = 0
    for _ in range(400):
        bases = rng.sample(zs, rng.randint(2, 6))
        if rng.random() < 0.2:
            bases.append(rng.choice([foreign, q1, sp.sin(q2)]))
        got = autoz._least_intermediate(bases)
        if got is None:
            declined += 1
            pairs = [(len(b.args), b.args[0]) for b in bases]
            assert len(set(map(type, bases))) > 1 or len(set(pairs)) < len(pairs)
        else:
            assert got == min(bases, key=sp.default_sort_key)
            assert got == min(bases, key=book._sort_key)
            decided += 1
    assert decided > 200 and declined > 50


def test_ordering_keeps_no_book_alive():
    """The order's class keys are not kept per book's class of
    intermediates (each book has its own): a book dropped is freed (once
    sympy's own cache, bounded, lets go of its expressions)."""
    import gc
    import weakref

    book = Intermediates()
    z = book.name(sp.sin(q1) * u1 + sp.cos(q2) * u2 + L * q1 * u1)
    assert autoz._class_first(z) == type(z).class_key()
    assert autoz._least_generator([z, q1 + L], sp.default_sort_key) is min(
        [z, q1 + L], key=sp.default_sort_key
    )
    gone = weakref.ref(book)
    del book, z
    sp.core.cache.clear_cache()
    gc.collect()
    assert gone() is None


# ----------------------------------------------- what naming keeps (i35z)


def _fresh(z):
    """An instance equal to ``z``, made anew (not sympy's cached one): no
    hash and no facts kept on it yet."""
    return sp.Basic.__new__(type(z), *z.args)


def _hash_mismatches(book, zs) -> int:
    """How many intermediates hash otherwise than equal instances made
    anew, or are not found by them in a dict."""
    bad = 0
    for z in zs:
        other = _fresh(z)
        assert other == z and other is not z
        if hash(other) != hash(z) or {z: 1}.get(other) != 1:
            bad += 1
    return bad


def test_equal_intermediates_hash_alike(pool):
    """An intermediate at its own variables hashes its number and its kept
    set of variables: an equal instance made by sympy (or anew) hashes
    alike, whether it was hashed before its facts were kept or after; an
    intermediate taken elsewhere hashes as sympy's ``Basic.__hash__``."""
    _, book, parts, stray = pool
    zs = [book.Z(k, *book.canonical(k)[0]) for k in range(1, len(book) + 1)]
    zs += [p for p in parts if isinstance(p, book.Z)]
    assert _hash_mismatches(book, zs) == 0
    for z in zs:
        assert hash(z) == hash(
            (type(z).__name__, z.args[0].p, book._varsets[z.args[0].p])
        )
    strays = [
        e for s in stray for e in autoz.atoms(s, book.Z) if not book._canonical(e)
    ]
    assert strays
    for z in strays:
        other = _fresh(z)
        assert hash(other) == hash((type(z).__name__,) + z._hashable_content())
        assert hash(other) == hash(z)


def test_the_check_finds_a_wrong_hash(pool, monkeypatch):
    """Instances made by sympy that hash as sympy's (not told they are at
    their own variables) are told apart from the book's own."""
    _, book, _, _ = pool
    zs = [book.Z(k, *book.canonical(k)[0]) for k in range(1, len(book) + 1)]
    for z in zs:
        hash(z)
    monkeypatch.setattr(Intermediates, "own_variables", lambda self, z: None)
    assert _hash_mismatches(book, zs) > 20


def _nodes(book, e) -> int:
    """Tree nodes as ``_split`` counts them (:func:`_tree_size`)."""
    return _tree_size(book, e)


def test_within_counts_the_tree(pool):
    """``_within(e, limit)``, which counts an expression's leaves when it
    meets their parent, is ``_split``'s count of tree nodes against the
    limit, for every part of random expressions and every limit near it."""
    book, cases = _cases(pool, 150)
    seen = 0
    for e in cases:
        for part in sp.preorder_traversal(e):
            n = _nodes(book, part)
            for limit in {0, 1, n - 2, n - 1, n, n + 1, book.LIMIT}:
                if limit >= 0:
                    assert book._within(part, limit) == (n <= limit), (part, limit)
                    seen += 1
    assert seen > 2000


def _sets_made_anew(book, cases) -> tuple[int, int]:
    """How many of the sets of variables ``_walk`` finds in ``cases`` are
    another object when met again (another way), and how many were
    checked; each holds exactly what sympy finds."""
    anew = met = 0
    for e in cases:
        variables, derivatives, bad, _ = book._walk(e)
        if bad or not isinstance(variables, frozenset):
            continue
        assert variables == _variables(e)
        assert derivatives == {x for x in variables if isinstance(x, sp.Derivative)}
        again = book._walk(sp.Add(e, 1, evaluate=False))[0]
        anew += again is not variables
        anew += book._shared_variables(set(variables))[1] is not variables
        met += 1
    for k in range(1, len(book) + 1):
        own = book._varsets[k]
        anew += book._union({own})[0] is not own
        anew += book._shared_variables(set(own))[1] is not own
    return anew, met


def test_a_set_of_variables_is_one_object(pool):
    """The sets of variables the walk finds are the book's kept objects:
    an intermediate's own, a union of several intermediates' (kept once per
    combination), and a union with variables outside them are the same
    object whichever way they are met (by ``_walk`` or by
    ``_shared_variables``), and hold exactly what sympy finds."""
    book, cases = _cases(pool, 300)
    anew, met = _sets_made_anew(book, cases)
    assert anew == 0 and met > 100


def test_the_check_finds_sets_made_anew(pool, monkeypatch):
    """Without one kept object per set, equal sets met two ways are two
    objects, and are told apart."""
    _, book, _, _ = pool
    monkeypatch.setattr(Intermediates, "_one_set", lambda self, v: v)
    for kept in ["_unions", "_mets", "_orders"]:
        monkeypatch.setattr(book, kept, dict(getattr(book, kept)))
        getattr(book, kept).clear()
    # (the intermediates' own sets stay the keys of their order)
    for k in range(1, len(book) + 1):
        book._shared_variables(book._varsets[k])
    book, cases = _cases(pool, 300)
    anew, met = _sets_made_anew(book, cases)
    assert anew > 50 and met > 100


def test_the_rates_check_follows_the_rates(pool):
    """``_all_rates`` is ``derivatives <= rates``, also after the rates
    change (its answers are kept per set of rates)."""
    _, book, _, _ = pool
    sets = {d for _, d in book._unions.values() if d}
    sets |= {frozenset([q1.diff(t)]), frozenset([q1.diff(t), q3.diff(t)])}
    assert len(sets) > 3
    before = book.rates
    try:
        for rates in [before, frozenset([q1.diff(t)]), frozenset(), before]:
            book.rates = rates
            answers = [book._all_rates(d) for d in sets]
            assert answers == [d <= rates for d in sets]
            assert answers == [book._all_rates(set(d)) for d in sets]
        assert any(d <= before for d in sets) and not all(d <= before for d in sets)
    finally:
        book.rates = before
