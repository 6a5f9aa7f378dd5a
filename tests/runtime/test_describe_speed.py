"""The shortcuts of describing a program (issue 35, eighth pass) give what
the longer ways give:

* a product of two names formed by the renaming learns its key
  (``CompareKeys.learn``): the key ``CompareKeys.key`` finds for it, and
  the product is sympy's;
* ``_Slots._variables_known`` answers once per set of variables: the
  programs are the same text without that memo;
* ``Intermediates._intermediates_in`` finds what the walk that hashes each
  part twice found.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen.program import CompareKeys, _sorted_only, renamed_evaluated
from al2py_runtime.intermediates import autoz
from al2py_runtime.jobs import run
from conftest import ROOT
from program_texts import every_language

from al2py.transpile import convert

NAMES = sp.symbols("z1 z10 z2 Q3 U7 x z1_1 A Z3 q3p", real=True)
OTHERS = sp.symbols("b c", positive=True) + (sp.Symbol("n", commutative=False),)


@pytest.mark.parametrize("seed", range(3))
def test_learned_product_keys_are_the_keys_found(seed):
    rng = random.Random(seed)
    keys = CompareKeys()
    products = []
    for _ in range(300):
        pool = NAMES + OTHERS if rng.random() < 0.2 else NAMES
        a, b = rng.choice(pool), rng.choice(pool)
        args = [a, b] if rng.random() < 0.5 else [sp.S.NegativeOne, a, b]
        part = _sorted_only(sp.Mul(*NAMES[:2]), args, keys)
        want = sp.Mul(*args)
        assert part == want and sp.srepr(part) == sp.srepr(want), args
        assert part.args == want.args
        products.append(part)
        if rng.random() < 0.3 and len(products) > 2:
            terms = rng.sample(products, 3)
            total = _sorted_only(sp.Add(*NAMES[:2]), terms, keys)
            want = sp.Add(*terms)
            assert sp.srepr(total) == sp.srepr(want), terms
    fresh = CompareKeys()
    for part in products:
        if part in keys.parts:
            assert keys.parts[part] == fresh.key(part), part


def test_learned_keys_sort_sums_as_sympy():
    rng = random.Random(7)
    objects = sp.symbols("a b c d e f g")
    rule = dict(zip(objects, NAMES, strict=False))
    memo: dict = {}
    for _ in range(400):
        terms = []
        for _ in range(rng.randint(2, 6)):
            factors = rng.sample(objects, 2)
            if rng.random() < 0.5:
                factors.append(-1)
            terms.append(sp.Mul(*factors))
        e = sp.Add(*terms)
        got, want = renamed_evaluated(e, rule, memo), e.xreplace(rule)
        assert sp.srepr(got) == sp.srepr(want), e


def test_intermediates_in_is_the_twice_hashing_walk():
    book = _workspace((ROOT / "tests" / "models" / "rolling_disc.al").read_text()).book
    assert book is not None and len(book) > 10

    def walk(expr):
        found, stack, seen = set(), [expr], set()
        while stack:
            e = stack.pop()
            if isinstance(e, book.Z):
                found.add(e)
                if book._canonical(e):
                    continue
            if e.args and e not in seen:
                seen.add(e)
                stack.extend(e.args)
        return found

    for k in range(1, len(book)):
        _vars, body = book.canonical(k)
        assert book._intermediates_in(body) == walk(body)


def _workspace(text: str):
    code = convert(text, "disc.al", formatted=False).code
    namespace: dict = {"__name__": "disc", "__file__": "disc.py"}
    exec(compile(code, "disc.py", "exec"), namespace)  # noqa: S102
    return namespace["al"]


def _jobs(text: str) -> list:
    return _workspace(text).numerics.jobs


def test_variables_known_per_set_gives_the_same_programs(monkeypatch):
    text = (ROOT / "tests" / "models" / "rolling_disc.al").read_text()
    text += "E1 = ZERO[1]\nE3 = ZERO[3]\nEncode E1, E3\nCODE Algebraic() outs.m\n"
    jobs = _jobs(text)
    quick = every_language(jobs)
    sets: list = []
    known = run._Slots._variables_known

    def counted(self, z):
        sets.append(len(self._variable_sets))
        return known(self, z)

    monkeypatch.setattr(run._Slots, "_variables_known", counted)
    assert every_language(_jobs(text)) == quick
    assert max(sets) > 0  # the memo served
    monkeypatch.setattr(autoz.Intermediates, "own_variables", lambda self, z: None)
    assert every_language(_jobs(text)) == quick
