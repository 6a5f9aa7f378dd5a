"""The shortcuts that make ``al2py code`` write its programs with less work
(issue 35) give what the long paths give:

* the renaming walk with its rebuilding written in (``codegen.program``'s
  ``_renamed`` and ``_kept_args``) gives ``xreplace``'s expression, node
  for node, for random sums and products of names;
* ``jobs.run._Slots._definition`` decides each part by a table of classes
  (``_part_kind``) as the chain of ``isinstance`` tests did;
* a deferred definition whose intermediate's variables are all known is
  not walked (``_Slots._variables_known``): the programs are the same text
  as when every definition is walked;
* an integer statement is printed as a plain one (``ProgramPrinter.is_plain``)
  and a name is assigned to through the program's own symbol
  (``Assign.symbol``): the same text as sympy's ``doprint``.
"""

from __future__ import annotations

import random

import pytest
import sympy as sp
from al2py_runtime.codegen import printers
from al2py_runtime.codegen.c import _Printer as CProgramPrinter
from al2py_runtime.codegen.fortran import _code as fortran_code
from al2py_runtime.codegen.fortran import _Printer as FortranPrinter
from al2py_runtime.codegen.octave import _code as octave_code
from al2py_runtime.codegen.octave import _Printer as OctavePrinter
from al2py_runtime.codegen.program import CompareKeys, renamed_evaluated
from al2py_runtime.intermediates import autoz
from al2py_runtime.jobs import run
from conftest import ROOT
from program_texts import every_language
from sympy.core.basic import _args_sortkey
from sympy.core.function import AppliedUndef

from al2py.transpile import convert

# ---------------------------------------------------------------- renaming

OBJECTS = sp.symbols("a b c d e f g h")  # no assumptions, as the book's
NAMES = sp.symbols("z1 z10 z2 Q3 U7 x z1_1 A", real=True)
NUMBERS = [sp.Integer(2), sp.Integer(-3), sp.Rational(1, 2), sp.Float(1.5)]


def _random_sums(n: int, seed: int) -> list[sp.Expr]:
    """Sums of products of objects (most with -1 or a number), products
    alone, a power, a sine: the shapes of a program's intermediates."""
    rng = random.Random(seed)
    nc = sp.Symbol("n", commutative=False)

    def product() -> sp.Expr:
        factors = rng.sample(OBJECTS, rng.randint(1, 4))
        if rng.random() < 0.5:
            factors.append(-1)
        elif rng.random() < 0.2:
            factors.append(rng.choice(NUMBERS))
        if rng.random() < 0.1:
            factors.append(rng.choice([sp.sin(rng.choice(OBJECTS)), OBJECTS[0] ** 2]))
        if rng.random() < 0.03:
            factors.append(nc)
        return sp.Mul(*factors)

    out = []
    for _ in range(n):
        terms = [product() for _ in range(rng.randint(1, 7))]
        if rng.random() < 0.2:
            terms.append(rng.choice(NUMBERS))
        out.append(sp.Add(*terms))
    return out


def _same(e: sp.Expr, rule: dict) -> None:
    got, want = renamed_evaluated(e, rule), e.xreplace(rule)
    assert got == want and sp.srepr(got) == sp.srepr(want), (e, got, want)


@pytest.mark.parametrize("seed", range(4))
def test_renamed_sums_of_names_are_xreplaces(seed):
    rng = random.Random(seed)
    for e in _random_sums(400, seed):
        names = rng.sample(NAMES, len(OBJECTS))
        _same(e, dict(zip(OBJECTS, names, strict=True)))


def test_renamed_with_one_memo_is_xreplace():
    """One memo for many expressions and a rule that grows, as
    ``named_intermediates`` renames a program's definitions."""
    memo: dict = {}
    rule = dict(zip(OBJECTS, NAMES, strict=True))
    for e in _random_sums(300, 9):
        got = renamed_evaluated(e, rule, memo)
        assert sp.srepr(got) == sp.srepr(e.xreplace(rule))


def test_renamed_unevaluated_parts_are_xreplaces():
    """Parts sympy's evaluation would change (a number 1 or 0 among the
    arguments, a number times a sum, a power or ``exp`` evaluated again, a
    sum in a sum) are rebuilt by sympy, as ``xreplace`` rebuilds them."""
    a, b, c, d = OBJECTS[:4]
    k = sp.Symbol("k")
    rule = dict(zip(OBJECTS, NAMES, strict=True))
    un = {"evaluate": False}
    for e in (
        sp.Mul(1, a, b, **un),
        sp.Mul(0, a, b, **un),
        sp.Mul(sp.oo, a, b, **un),
        sp.Mul(-1, a, -1, **un),
        sp.Mul(2, sp.Add(a, b), **un),
        sp.Add(0, a, b, **un),
        sp.Add(sp.Mul(2, sp.Add(a, b), **un), c, **un),
        sp.Add(sp.Mul(2, sp.exp(a), **un), c, **un),
        sp.Add(sp.Mul(2, sp.Pow(a, 1, **un), **un), c, **un),
        sp.Add(sp.Add(a, b, **un), c, **un),
        sp.Add(sp.Mul(-1, a, **un), sp.Mul(3, a, **un), d, **un),
        sp.Mul(sp.Pow(a, 2), sp.Pow(a, -1), b, **un),
        sp.Mul(sp.exp(a), sp.exp(b), c, **un),
        sp.Add(a, a, b, **un),
        # a sum's term c*s left as it is (k is not renamed), which sympy
        # forms again as Mul(c, s): 2*k**1 is 2*k, 2*E**k is 2*exp(k)
        sp.Add(sp.Mul(2, sp.Pow(k, 1, **un), **un), a, **un),
        sp.Add(sp.Mul(2, sp.Pow(sp.E, k, **un), **un), a, **un),
        sp.Add(sp.Mul(2, sp.Pow(sp.Integer(2), 3, **un), **un), a, **un),
        sp.Add(sp.Mul(3, sp.exp(k), **un), a, **un),
    ):
        _same(e, rule)


#: names of the same spelling class with other assumptions (their
#: ``_hashable_content`` is shorter or longer: Basic.compare orders by its
#: length before the name)
MIXED = [
    *NAMES,
    *sp.symbols("z3 Z3 b2", positive=True),
    *sp.symbols("z4 a1 x"),
    sp.Symbol("n2", integer=True),
    sp.Dummy("z5"),
]


def test_renamed_to_names_of_other_assumptions_is_xreplace():
    rng = random.Random(5)
    for e in _random_sums(600, 5):
        names = rng.sample(MIXED, len(OBJECTS))
        _same(e, dict(zip(OBJECTS, names, strict=True)))


def _compared_parts(n: int, seed: int) -> list[sp.Basic]:
    """Random parts as a program's sums and products hold them: names of
    other assumptions, dummies, numbers of each class, products, sums,
    powers, functions, unevaluated ones, and tuples of them."""
    rng = random.Random(seed)
    atoms = [*MIXED, sp.Integer(2), sp.Integer(-3), sp.S.NegativeOne, sp.S.One]
    atoms += [sp.S.Zero, sp.S.Half, sp.Rational(-2, 7), sp.Float(1.5), sp.Float(-2)]
    atoms += [sp.Float(1.5, 30), sp.Float(2), sp.Integer(3) / 2]
    atoms += [sp.pi, sp.E, sp.I, sp.Symbol("n", commutative=False)]

    def grow(depth: int) -> sp.Basic:
        if depth == 0:
            return rng.choice(atoms)
        kind = rng.randrange(7)
        parts = [grow(depth - 1) for _ in range(rng.randrange(1, 4))]
        if kind == 0:
            return sp.Add(*parts)
        if kind == 1:
            return sp.Mul(*parts)
        if kind == 2:
            return sp.Mul(*parts, evaluate=False)
        if kind == 3:
            return sp.Pow(parts[0], rng.choice([2, -1, sp.Rational(1, 2)]))
        if kind == 4:
            return rng.choice([sp.sin, sp.cos, sp.Abs])(parts[0])
        if kind == 5:
            return sp.Pow(parts[0], parts[-1], evaluate=False)
        return sp.Add(*parts, evaluate=False)

    out = [grow(rng.randrange(0, 4)) for _ in range(n)]
    return out + [sp.Tuple(*rng.sample(out, 2)) for _ in range(n // 10)]


def test_compare_keys_order_as_basic_compare():
    """``CompareKeys`` orders parts exactly as ``Basic.compare``: below,
    equal and above alike, each pair of many random parts (the order in
    which a renamed sum's or product's arguments are sorted)."""
    keys = CompareKeys()
    parts = _compared_parts(300, 3)
    parts += [sp.Subs(MIXED[0] ** 2, MIXED[0], 1)]  # content not known
    unknown = 0
    for a in parts:
        for b in parts:
            ka, kb = keys.key(a), keys.key(b)
            if ka is None or kb is None:
                unknown += 1
                continue
            assert (ka > kb) - (ka < kb) == a.compare(b), (a, b)
    assert unknown and unknown < len(parts) * 3
    assert keys.key(parts[-1]) is None


def test_compare_keys_leave_a_class_with_its_own_compare_to_it():
    """A class that compares in its own way (an intermediate's) has no key,
    nor has a part that holds it: sympy then calls its ``compare``."""

    class Own(sp.Symbol):
        def compare(self, other):  # the reverse of sympy's order
            return -sp.Basic.compare(self, other)

    keys = CompareKeys()
    assert keys.key(Own("a")) is None
    assert keys.key(Own("a") + sp.Symbol("b")) is None
    assert keys.key(sp.Symbol("b")) is not None


def test_canonical_sort_is_sympys_sort():
    """Lists of random parts sorted with ``CompareKeys`` (or by
    ``Basic.compare`` where a part has no key) as sympy sorts a sum's and
    a product's arguments."""
    from al2py_runtime.codegen.program import _sort_canonically

    keys = CompareKeys()
    rng = random.Random(4)
    parts = _compared_parts(400, 4) + [sp.Subs(MIXED[0] ** 2, MIXED[0], 1)]
    for _ in range(400):
        some = rng.sample(parts, rng.randrange(2, 9))
        got = list(some)
        _sort_canonically(got, keys)
        want = sorted(some, key=_args_sortkey)
        assert [id(x) for x in got] == [id(x) for x in want], some


def test_names_that_do_not_commute_keep_their_order():
    a, b = OBJECTS[:2]
    p, q = sp.symbols("p q", commutative=False)
    rule = {a: NAMES[0], b: NAMES[1], p: sp.Symbol("n1", commutative=False)}
    for e in (a * q, -a * q, q * a, p * q, q * p, -p * q, a * b * q, b * p + a * q):
        _same(e, rule)


def test_objects_renamed_to_one_name_combine():
    """Not a renaming: terms and factors that become equal combine, as
    sympy's evaluation combines them."""
    a, b, c, d = OBJECTS[:4]
    z1, z2 = NAMES[:2]
    rule = {a: z1, b: z1, c: z2, d: z2}
    for e in (a * b, a * c - b * c, -a * c + b * d, a + b, 2 * a * c + 3 * b * d):
        _same(e, rule)


# ---------------------------------------------------- _definition's table


def _isinstance_chain(e: sp.Basic) -> int:
    """The tests ``_Slots._definition`` made of each part, in their order."""
    if isinstance(e, autoz.Intermediate):
        return run._INTERMEDIATE
    if isinstance(e, sp.Derivative):
        return run._DERIVATIVE
    if isinstance(e, AppliedUndef):
        return run._FUNCTION
    if e.is_Symbol:
        return run._SYMBOL
    if e.is_Atom:
        return run._ATOM
    return run._WALKED


def test_part_kinds_are_the_isinstance_chain():
    t = sp.Symbol("t")
    q = sp.Function("q")(t)
    parts = [
        q,
        sp.Derivative(q, t),
        sp.Symbol("c"),
        sp.Dummy("d"),
        sp.Integer(2),
        sp.Float(1.5),
        sp.pi,
        sp.S.Half,
        q + t,
        q * t,
        q**2,
        sp.sin(q),
        sp.atan2(q, t),
        sp.Abs(t),
    ]
    for e in parts:
        assert run._part_kind(type(e)) == _isinstance_chain(e), e


# ------------------------------------------ definitions that are not walked


class _Z:
    """An intermediate's stand-in: its number, then its variables."""

    def __init__(self, *variables: sp.Basic) -> None:
        self.args = (sp.Integer(1), *variables)


def test_variables_known_only_of_known_objects():
    t = sp.Symbol("t")
    q, g = sp.Function("q")(t), sp.Function("g")(t)
    fg, dq = sp.Function("f")(g), sp.Derivative(q, t)
    c = sp.Symbol("c")
    slots = run._Slots(None, deferred=True)
    slots.known.update({q: sp.Dummy(), fg: sp.Dummy(), dq: sp.Dummy()})
    assert slots._variables_known(_Z(q, dq))
    assert not slots._variables_known(_Z(q, c))  # c is not known yet
    # a function of a function: its walk notes the inner one, known or not
    assert not slots._variables_known(_Z(q, fg))
    slots.known[c] = sp.Dummy()
    assert slots._variables_known(_Z(c, q)) and slots._variables_known(_Z(q, c))


ROLLING_DISC = ROOT / "tests" / "models" / "rolling_disc.al"
TUTOR6 = ROOT / "examples" / "tutor6.al"
# the rolling disc's Dynamics program, and an Algebraic one of two of its
# equations' elements (intermediates of their own)
DISC_JOBS = (
    ROLLING_DISC.read_text()
    + "E1 = ZERO[1]\nE3 = ZERO[3]\nEncode E1, E3\nCODE Algebraic() outs.m\n"
)


def _jobs(text: str, tmp_path, name: str) -> list:
    module_file = str(tmp_path / f"{name}.py")
    code = convert(text, f"{name}.al", formatted=False).code
    namespace: dict = {"__name__": name, "__file__": module_file}
    exec(compile(code, module_file, "exec"), namespace)  # noqa: S102
    return namespace["al"].numerics.jobs


@pytest.mark.parametrize("script", ["disc", "aux_spherical_pendulum", "tutor6"])
def test_definitions_not_walked_give_the_same_programs(script, tmp_path, monkeypatch):
    if script == "disc":
        text = DISC_JOBS
    elif script == "tutor6":
        text = TUTOR6.read_text()
    else:
        text = (ROOT / "tests" / "models" / f"{script}.al").read_text()
    jobs = _jobs(text, tmp_path, script)
    answers: list[bool] = []
    known = run._Slots._variables_known

    def counted(self, z):
        answers.append(known(self, z))
        return answers[-1]

    monkeypatch.setattr(run._Slots, "_variables_known", counted)
    quick = every_language(jobs)
    # most definitions are not walked (and in the disc's, some make a
    # parameter of what they hold first)
    assert answers.count(True) > answers.count(False)
    if script == "disc":
        assert answers.count(False) > 0
    monkeypatch.setattr(run._Slots, "_variables_known", lambda self, z: False)
    assert every_language(jobs) == quick


# ----------------------------------------------------------- plain printing


def _printers() -> list[tuple[str, printers.ProgramPrinter]]:
    return [
        ("c", CProgramPrinter()),
        ("m", OctavePrinter({"strict": True})),
        ("f", FortranPrinter()),
    ]


VALUES = [
    sp.Integer(0),
    sp.Integer(1),
    sp.Integer(-1),
    sp.Integer(-7),
    sp.Integer(10**40),
    sp.Float(1.5),
    sp.Float(-0.25),
    sp.Rational(1, 3),
    sp.Rational(-2, 7),
]
TARGETS = [None, "z12", "mm(1, 2)", sp.Symbol("x3", real=True), "a_long_name_" * 6]


def test_numbers_alone_are_printed_as_sympy_prints_them():
    for value in VALUES:
        for target in TARGETS:
            for (lang, mine), (_, theirs) in zip(_printers(), _printers(), strict=True):
                if lang == "c" and target is not None:
                    continue
                got = mine.doprint(value, assign_to=target)
                want = super(printers.ProgramPrinter, theirs).doprint(
                    value, assign_to=target
                )
                assert got == want, (lang, value, target)


def test_names_are_assigned_to_through_their_symbols():
    """A name's statement printed with the program's symbol of it is the
    statement printed with its name (MATLAB; Fortran, whose printer renames
    a name that another spells without case: ``z1`` after ``Z1``)."""
    rng = random.Random(5)
    names = [sp.Symbol(n, real=True) for n in ("z1", "Z1", "x3", "Q3", "z12", "end")]
    statements = []
    for e in _random_sums(60, 11):
        rule = dict(zip(OBJECTS, rng.sample(NAMES, len(OBJECTS)), strict=True))
        statements.append((rng.choice(names), e.xreplace(rule)))
    statements.append((names[0], sp.Integer(0)))
    for code, printer in (
        (octave_code, lambda: OctavePrinter({"strict": True})),
        (fortran_code, FortranPrinter),
    ):
        with_symbols, with_names = printer(), printer()
        for target, expr in statements:
            assert code(with_symbols, expr, target.name, target) == code(
                with_names, expr, target.name
            ), (target, expr)
