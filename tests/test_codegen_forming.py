"""Forming the programs ``al2py code`` writes (``codegen.form``): what one
program works out it keeps to itself (its memo of free symbols), a job
named apart is formed once, and the copies take the largest jobs first."""

from __future__ import annotations

from conftest import ROOT

from al2py.transpile import convert

ROLLING_DISC = ROOT / "tests" / "models" / "rolling_disc.al"
# the rolling disc's Dynamics program, and an Algebraic one of two of its
# equations' elements (intermediates of their own)
DISC_JOBS = (
    ROLLING_DISC.read_text()
    + "E1 = ZERO[1]\nE3 = ZERO[3]\nEncode E1, E3\nCODE Algebraic() outs.m\n"
)


def _jobs(text: str, tmp_path, name: str = "model") -> list:
    module_file = str(tmp_path / f"{name}.py")
    code = convert(text, f"{name}.al", formatted=False).code
    namespace: dict = {"__name__": name, "__file__": module_file}
    exec(compile(code, module_file, "exec"), namespace)  # noqa: S102
    return namespace["al"].numerics.jobs


def test_each_program_owns_its_memo_of_free_symbols(tmp_path):
    """The free symbols of a program's expressions are remembered by the
    program (``Program.free``), not by a module: nothing to forget before
    the next program, and no program's expressions in another's memo."""
    from al2py_runtime.codegen import program_source
    from al2py_runtime.codegen.program import describe
    from al2py_runtime.codegen.static import describe_static
    from al2py_runtime.jobs import backends

    # no module-level memo (an lru_cache that had to be cleared)
    own = [
        v
        for v in vars(backends).values()
        if getattr(v, "__module__", "") == backends.__name__
    ]
    assert not any(hasattr(v, "cache_clear") for v in own)
    assert not hasattr(backends, "forget_free_symbols")
    dynamics, algebraic = _jobs(DISC_JOBS, tmp_path)
    first = describe(dynamics)
    kept = dict(first.free)
    second = describe_static(algebraic)
    again = describe(dynamics)
    assert first.free == kept  # the later programs kept theirs apart
    assert first.free is not again.free
    for p in (first, second, again):
        # the intermediates' definitions (z1, z2, ...): asked while forming
        zs = [
            a.expr
            for a in p.eqns + p.outputs
            if a.target[0] == "tmp" and a.target[1][0] == "z"
        ]
        assert len(zs) > 2
        for e in zs:  # remembered, rightly
            assert e in p.free and p.free[e] == e.free_symbols
    # printing asks the program's memo: the same text as a fresh program's
    assert program_source(first, "disc.c") == program_source(again, "disc.c")
    assert program_source(first, "disc.f") == program_source(again, "disc.f")


# a small ODE, a larger one (its Output of 12 items) and two naming one file
# and one stem: the fourth is named apart (bigger.c is the second's), the
# third shares bigger.in with the second
SEVERAL_JOBS = """\
Variables X', Y'
Constants A, B
Input A=2, B=0.5, X=1, Y=0, TFINAL=1
X' = -A*X + B*Y
Y' = X - B*Y
Output T, X
CODE ODE() small.c
Output T, X, Y, A*X, B*Y, X*Y, X^2, Y^2, X+Y, X-Y, A*Y, B*X
CODE ODE() bigger.c
CODE ODE() bigger.m
Input B=0.25
CODE ODE() bigger.c
"""


def test_a_job_named_apart_is_formed_once(tmp_path, monkeypatch, capsys):
    """A job whose file an earlier job's takes is named before it is
    printed, whichever process forms it: each program is described once
    (before, a copy formed it under the CODE statement's name and this
    process formed it again to rename it)."""
    from al2py_runtime import codegen

    from al2py.cli import main as al2py_main

    script = tmp_path / "several.al"
    script.write_text(SEVERAL_JOBS)
    calls = tmp_path / "calls.txt"
    real = codegen.describe

    def counted(job, *args, **kwargs):
        # appended by whichever process forms the job (the copies are forks)
        with calls.open("a") as f:
            f.write(f"{job.where}\n")
        return real(job, *args, **kwargs)

    monkeypatch.setattr(codegen, "describe", counted)
    seen = []
    for workers in ("1", "2", "3"):
        calls.write_text("")
        out = tmp_path / f"j{workers}"
        status = al2py_main(["code", "-j", workers, str(script), "-o", str(out)])
        captured = capsys.readouterr()
        assert status == 0, captured.err
        formed = calls.read_text().splitlines()
        assert sorted(formed) == sorted(j.where for j in _jobs_of(script, tmp_path))
        files = {p.name: p.read_bytes() for p in sorted(out.iterdir())}
        seen.append((files, captured.out.replace(str(out), "OUT"), captured.err))
    assert seen[1] == seen[0] and seen[2] == seen[0]
    files, _printed, notes = seen[0]
    assert sorted(files) == [
        "bigger.c",
        "bigger.in",
        "bigger.m",
        "bigger_2.c",
        "bigger_2.in",
        "small.c",
        "small.in",
    ]
    assert "is written as bigger_2.c (reading bigger_2.in" in notes
    assert "reads bigger.in, written for CODE Ode bigger.c (line 9)" in notes
    assert b"bigger_2.in" in files["bigger_2.c"] and b"0.25" in files["bigger_2.in"]


def _jobs_of(script, tmp_path) -> list:
    return _jobs(script.read_text(), tmp_path, script.stem)


def test_the_largest_jobs_are_formed_first(tmp_path, monkeypatch):
    """The copies are given the independent jobs largest first
    (``estimated_work``), and a job whose name an earlier one's may take
    once that one is written."""
    import concurrent.futures

    from al2py_runtime import codegen, copies

    jobs = _jobs(SEVERAL_JOBS, tmp_path, "several")
    work = [codegen.estimated_work(job) for job in jobs]
    assert work[0] < work[1] == work[2] == work[3]
    # bigger.m may be named apart only if bigger.in differs: it does not
    # wait; the second bigger.c waits for the last job of its stem
    assert codegen.meeting(jobs, None) == [None, None, None, 2]
    assert codegen.meeting(jobs, "m") == [None, None, 1, 2]
    submitted: list[int] = []

    class Recording(concurrent.futures.ProcessPoolExecutor):
        def submit(self, fn, /, *args, **kwargs):
            submitted.append(args[0])
            return super().submit(fn, *args, **kwargs)

    monkeypatch.setattr(copies, "ProcessPoolExecutor", Recording)
    formers = codegen.Formers(jobs, None, None, 2)
    try:
        assert submitted == [2, 1, 0]  # the larger first, the other waits
        made: dict = {}
        for i, job in enumerate(jobs):
            got = formers.formed(i)
            assert got is not None and got.error is None
            codegen.write_one(job, got, tmp_path / "out", [], [], [], made)
            formers.written(i, made)
    finally:
        formers.stop()
    assert submitted == [2, 1, 0, 3]


def test_remembered_free_symbols_are_sympy_s():
    """``free_symbols_of`` with a memo (each part's remembered) gives
    sympy's ``free_symbols``, also of parts that bind their symbols."""
    import random

    import sympy as sp
    from al2py_runtime.jobs import backends

    x, y, z, n = sp.symbols("x y z n", real=True)
    f = sp.Function("f")
    t = sp.Symbol("t")
    leaves = [x, y, z, sp.Integer(3), sp.pi, sp.Dummy("d"), f(t), sp.Rational(1, 2)]
    rng = random.Random(35)

    def build(depth: int) -> sp.Basic:
        if depth == 0:
            return rng.choice(leaves)
        a, b = build(depth - 1), build(depth - 1)
        return rng.choice(
            [
                a + b,
                a * b,
                sp.sin(a) * b,
                sp.Pow(a, 2) + b,
                sp.Derivative(f(t) * a, t),
                sp.Integral(a * x, (x, 0, n)),
                sp.IndexedBase("F")[n] * a,
            ]
        )

    memo: dict = {}
    for _ in range(200):
        e = build(rng.randint(1, 4))
        assert backends.free_symbols_of(e, memo) == e.free_symbols, e
        assert backends.free_symbols_of(e) == e.free_symbols


# a program of bigger.c's stem in another language, whose bigger.in would
# hold other values: named apart after all
OTHER_VALUES = SEVERAL_JOBS.replace(
    "CODE ODE() bigger.m\nInput B=0.25\n", "Input B=0.25\nCODE ODE() bigger.m\n"
)


def test_a_job_of_one_stem_in_another_language_is_named_apart(tmp_path, capsys):
    """``bigger.m`` after ``bigger.c``, formed by a copy before ``bigger.c``
    is written, reads other values: it is formed again here, named apart,
    as one process forms it."""
    from al2py.cli import main as al2py_main

    assert OTHER_VALUES != SEVERAL_JOBS
    script = tmp_path / "other.al"
    script.write_text(OTHER_VALUES)
    seen = []
    for workers in ("1", "3"):
        out = tmp_path / f"j{workers}"
        status = al2py_main(["code", "-j", workers, str(script), "-o", str(out)])
        captured = capsys.readouterr()
        assert status == 0, captured.err
        files = {p.name: p.read_bytes() for p in sorted(out.iterdir())}
        seen.append((files, captured.out.replace(str(out), "OUT"), captured.err))
    assert seen[1] == seen[0]
    files, _printed, notes = seen[0]
    assert "is written as bigger_2.m (reading bigger_2.in" in notes
    assert "is written as bigger_3.c (reading bigger_3.in" in notes
    assert sorted(files) == [
        "bigger.c",
        "bigger.in",
        "bigger_2.in",
        "bigger_2.m",
        "bigger_3.c",
        "bigger_3.in",
        "small.c",
        "small.in",
    ]
