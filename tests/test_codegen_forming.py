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
