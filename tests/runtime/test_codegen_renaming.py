"""Programs rename their objects (``codegen.program.renamed_evaluated``)
without sympy's evaluation of every rebuilt sum and product: each result
must be ``xreplace``'s own expression, node for node (the programs' text
follows the order of arguments)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen.program import renamed_evaluated
from al2py_runtime.jobs.run import renamed

a, b, c, d = sp.symbols("a b c d")  # no assumptions, as the jobs' dummies
f = sp.Function("f")
X, Y, Z, W = sp.symbols("X Y Z W", real=True)  # the programs' names
RULE = {a: Z, b: Y, c: X, d: W}  # a new order: Z sorts after Y and X


def same(e: sp.Basic, rule: dict) -> None:
    got, want = renamed_evaluated(e, rule), e.xreplace(rule)
    assert got == want and sp.srepr(got) == sp.srepr(want), (e, got, want)


@pytest.mark.parametrize(
    "expr",
    [
        a * b + c,
        3 * a * b**2 - sp.sin(c) * d + 7,
        a * (b + c) * 2,
        sp.Mul(2, a + b, evaluate=False),  # evaluation distributes it
        -(2 * (a + b)),  # Mul.__neg__ keeps 2*(a + b) a product
        sp.sqrt(a**2) * b,  # Abs(X) once X is real
        sp.exp(a) * sp.exp(b) * c,  # exp's base is E
        sp.sqrt(2) * sp.sqrt(3 + a) * b,
        2**a * 3**a * c,  # powers of numbers combine
        sp.I * a * b,
        sp.pi * a + sp.E * b,
        sp.re(a) * b + sp.im(c),  # re(X) is X, im(X) is 0
        sp.Abs(a) ** 2 + b,  # Abs(X)**2 is X**2
        sp.Add(a, a, evaluate=False) + b,
        sp.Mul(a, a, b, evaluate=False),
        a**b * a**c * d,
        a ** (-(b + c)) * d,  # exponent -b - c, rebuilt
        f(a, b) * c + f(b, a),
        sp.atan2(a, b) + sp.cos(a - b) * c,
        1.5 * a * b + 0.5,
        sp.Mul(1.0, a, b, evaluate=False),
        sp.Add(0, a, b, evaluate=False),
        (a + b) ** 2 * (c - d),
        sp.Mul(a + b, a + b, evaluate=False),
    ],
)
def test_renamed_as_xreplace(expr: sp.Basic) -> None:
    same(expr, RULE)


def test_renaming_two_objects_to_one_name() -> None:
    # not a renaming: products and sums combine (a*c -> X**2, a - c -> 0)
    rule = {a: X, c: X, b: Y}
    for e in (a * c * b, a - c + b, a * b + c * b, sp.sin(a) * sp.sin(c)):
        same(e, rule)


def test_random_expressions() -> None:
    rng = random.Random(1)
    atoms = [a, b, c, d, sp.Integer(2), sp.Rational(1, 2), sp.pi]
    funcs = [sp.sin, sp.cos, sp.sqrt, sp.exp, sp.Abs, lambda x: x**2]

    def build(depth: int) -> sp.Basic:
        if depth == 0:
            return rng.choice(atoms)
        k = rng.randrange(4)
        parts = [build(depth - 1) for _ in range(rng.randint(2, 4))]
        if k == 0:
            return sp.Add(*parts)
        if k == 1:
            return sp.Mul(*parts)
        if k == 2:
            return rng.choice(funcs)(parts[0])
        return sp.Mul(*parts) - sp.Add(*parts)

    for _ in range(300):
        same(build(rng.randint(1, 4)), RULE)


def _old_renamed(expr: sp.Basic, rule: dict) -> sp.Basic:
    """run.renamed as it was: sympy's constructors with evaluate=False."""
    if expr in rule:
        return rule[expr]
    if not expr.args:
        return expr
    args = [_old_renamed(x, rule) for x in expr.args]
    if isinstance(expr, sp.Add | sp.Mul | sp.Pow):
        return expr.func(*args, evaluate=False)
    return expr.func(*args)


def test_jobs_renaming_keeps_the_structure() -> None:
    # run.renamed builds sums, products and powers without sympy's
    # constructors: the same objects as evaluate=False gives
    rule = {a: Z, b: Y, c: X}
    for e in (
        sp.Mul(2, a + b, evaluate=False) + a**b * sp.sin(b),
        sp.Mul(a, a, c, evaluate=False) + sp.Pow(a, 1, evaluate=False),
        3 * a * b**2 - sp.sin(c) * d + sp.sqrt(a**2),
    ):
        got, want = renamed(e, rule), _old_renamed(e, rule)
        assert sp.srepr(got) == sp.srepr(want)
        assert got.is_commutative is want.is_commutative


def test_one_walk_from_the_objects_is_the_two_walks_through_dummies() -> None:
    """A definition renamed straight from its objects to the programs'
    names (``jobs.run.Deferred``) is the one renamed to the jobs' dummies
    and then to those names, node for node; equal parts formed from
    either are one object."""
    rng = random.Random(2)
    q = sp.Function("q")(sp.Symbol("t"))
    objs = [a, b, c, q]
    dummies = [sp.Dummy(f"p{i}") for i in range(len(objs))]
    to_dummies = dict(zip(objs, dummies, strict=True))
    names = [Y, X, W, Z]  # another order than the objects'
    to_names = dict(zip(dummies, names, strict=True))
    straight = dict(zip(objs, names, strict=True))
    atoms = [*objs, sp.Integer(3), sp.Rational(-1, 2), sp.pi]

    def build(depth: int) -> sp.Basic:
        if depth == 0:
            return rng.choice(atoms)
        parts = [build(depth - 1) for _ in range(rng.randint(2, 3))]
        k = rng.randrange(4)
        if k == 0:
            return sp.Add(*parts)
        if k == 1:
            return sp.Mul(*parts)
        if k == 2:
            return sp.sin(parts[0]) ** parts[1]
        return sp.Mul(*parts) - sp.cos(sp.Add(*parts))

    memo: dict = {}
    for _ in range(300):
        e = build(rng.randint(1, 4))
        two = renamed_evaluated(renamed(e, to_dummies), to_names)
        one = renamed_evaluated(e, straight, memo)
        assert sp.srepr(one) == sp.srepr(two), e
        # one object for equal parts, whichever walk formed them
        again = renamed_evaluated(renamed(e, to_dummies), to_names, memo)
        assert again is one or not again.args


def test_programs_from_deferred_definitions_are_the_same(tmp_path, monkeypatch):
    """Programs formed with the intermediates' definitions deferred (one
    renaming walk) and made numeric first (two walks): the same text."""
    from pathlib import Path

    from al2py_runtime.codegen import form, program, static
    from al2py_runtime.jobs import run

    from al2py.transpile import convert

    root = Path(__file__).resolve().parents[2]
    text = (root / "tests" / "models" / "rolling_disc.al").read_text()
    text += "E1 = ZERO[1]\nE3 = ZERO[3]\nEncode E1, E3\nCODE Algebraic() outs.m\n"
    module_file = str(tmp_path / "rolling_disc.py")
    code = convert(text, "rolling_disc.al", formatted=False).code
    namespace: dict = {"__name__": "rolling_disc", "__file__": module_file}
    exec(compile(code, module_file, "exec"), namespace)  # noqa: S102
    jobs = namespace["al"].numerics.jobs
    assert [j.kind for j in jobs] == ["DYNAMICS", "ALGEBRAIC"]
    deferred = [form(job, lang, None) for job in jobs for lang in ("c", "m")]
    calls = []

    def made_numeric(real):
        def call(job, keep, deferred=False):
            calls.append(deferred)
            return real(job, keep, False)

        return call

    monkeypatch.setattr(
        program, "dynamics_equations", made_numeric(run.dynamics_equations)
    )
    monkeypatch.setattr(static, "static_equations", made_numeric(run.static_equations))
    numeric = [form(job, lang, None) for job in jobs for lang in ("c", "m")]
    assert calls == [True] * 4  # both ask for deferred definitions
    for x, y in zip(deferred, numeric, strict=True):
        assert x.error is None and (x.name, x.text) == (y.name, y.text)
