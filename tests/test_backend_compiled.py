"""The numeric backends of run(): C (ctypes), SymEngine LLVM and lambdify.

Every backend must give the numbers sympy gives for the same equations, and
``run()`` must give the same tables whichever backend evaluates them.
"""

from __future__ import annotations

import os
import random
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp
from al2py_runtime.functions import nint, trunc
from al2py_runtime.jobs import backends
from al2py_runtime.jobs.run import NumericsError
from conftest import ROOT, SHARED

HAS_CC = backends.available("c")
needs_cc = pytest.mark.skipif(
    not HAS_CC, reason="no C compiler (cc, gcc, clang or $CC)"
)
COMPILED = [
    pytest.param("c", marks=needs_cc),
    pytest.param(
        "llvm",
        marks=pytest.mark.skipif(
            not backends.available("llvm"), reason="symengine with LLVM not installed"
        ),
    ),
]


@pytest.fixture(autouse=True)
def private_cache(tmp_path, monkeypatch):
    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path / "cache"))


def _spec(autolev_functions: bool = True):
    """Two accelerations, a derivative that uses one of them, an intermediate,
    Autolev's INT and ROUND (or floor and ceiling), and two output tables."""
    rounding = (trunc, nint) if autolev_functions else (sp.floor, sp.ceiling)
    t = sp.Dummy("t")
    q1, q2, u1, u2, w = sp.symbols("q1 q2 u1 u2 w")
    a1, a2 = sp.symbols("a1 a2")  # accelerations
    m, g, k = sp.symbols("m g k")
    z = sp.Symbol("z")  # intermediate
    mass = [m + sp.cos(q2) ** 2, m * sp.sin(q1 - q2), m * sp.sin(q1 - q2), 2 + m]
    forcing = [
        -g * sp.sin(q1) + u2**2 * z,
        -k * q2 + sp.exp(-t) * rounding[0](3.7 * q1),
    ]
    derivs = [u1, u2, a1, a2, a1 * q2 - w + rounding[1](2.5 * u1)]
    outputs = [[t, q1 * 180 / sp.pi], [a2 + z, sp.atan2(q1, q2), sp.sqrt(1 + u1**2)]]
    spec = backends.DynamicsSpec(
        t,
        [q1, q2, u1, u2, w],
        [a1, a2],
        [m, g, k],
        mass,
        forcing,
        derivs,
        outputs,
        [(z, sp.cos(q1) * u1 + 1)],
    )
    return spec


def _expected(spec, tt, y, p):
    subs = {spec.time: tt}
    subs.update(zip(spec.states, y, strict=True))
    subs.update(zip(spec.params, p, strict=True))
    ((z, zexpr),) = spec.intermediates
    subs[z] = zexpr.xreplace(subs)
    m = sp.Matrix(2, 2, [sp.N(e.xreplace(subs)) for e in spec.mass])
    f = sp.Matrix([sp.N(e.xreplace(subs)) for e in spec.forcing])
    ud = m.solve(f)
    subs.update(zip(spec.accels, ud, strict=True))
    dy = [float(sp.N(e.xreplace(subs))) for e in spec.derivs]
    rows = [[float(sp.N(e.xreplace(subs))) for e in row] for row in spec.outputs]
    return dy, rows


@pytest.mark.parametrize("name", [*COMPILED, "lambdify"])
def test_backend_matches_sympy_at_random_points(name):
    spec = _spec(autolev_functions=name != "llvm")
    compiled = backends.compile_dynamics(spec, name)
    assert compiled.backend == name
    rng = random.Random(11)
    for _ in range(5):
        y = [rng.uniform(-2, 2) for _ in spec.states]
        p = [rng.uniform(1, 3) for _ in spec.params]
        tt = rng.uniform(0, 2)
        bound = compiled.bind(p)
        dy, rows = _expected(spec, tt, y, p)
        assert bound.rhs(tt, np.array(y)) == pytest.approx(dy, rel=1e-10, abs=1e-12)
        got = bound.outputs(tt, y)
        for a, b in zip(got, rows, strict=True):
            assert a == pytest.approx(b, rel=1e-10, abs=1e-12)


@pytest.mark.skipif(not backends.available("llvm"), reason="no symengine LLVM")
def test_llvm_backend_refuses_functions_it_does_not_know(monkeypatch):
    with pytest.raises(backends.BackendError, match="llvm backend cannot compile"):
        backends.compile_dynamics(_spec(), "llvm")
    monkeypatch.setattr(backends, "_AVAILABLE", {"c": False, "llvm": True})
    assert backends.compile_dynamics(_spec(), "auto").backend == "lambdify"
    assert backends.compile_dynamics(_spec(False), "auto").backend == "llvm"


@needs_cc
def test_c_backend_is_cached_by_content(tmp_path):
    spec = _spec()
    first = backends.compile_dynamics(spec, "c")
    again = backends.compile_dynamics(spec, "c")
    assert (first.cache_hit, again.cache_hit) == (False, True)
    # the library, and the object of its one unit (kept, as every unit's is,
    # so that a process that finds the library cached compiles nothing)
    files = list((tmp_path / "cache").iterdir())
    assert len(files) == 2 and {p.suffix for p in files} == {".o", backends._SUFFIX}
    # A different model is a different library.
    spec.forcing[0] += 1
    assert not backends.compile_dynamics(spec, "c").cache_hit
    libraries = list((tmp_path / "cache").glob(f"*{backends._SUFFIX}"))
    assert len(libraries) == 2 and len(list((tmp_path / "cache").iterdir())) == 4


def test_a_stream_compiles_each_unit_as_it_comes(monkeypatch, tmp_path):
    """The first unit (the right-hand side) compiles while the next is still
    being printed; a second process with the library cached compiles
    nothing."""
    if backends.find_compiler() is None:
        pytest.skip("no C compiler")
    started = []
    real = subprocess.Popen

    def popen(cmd, *args, **kwargs):
        started.append(cmd)
        return real(cmd, *args, **kwargs)

    monkeypatch.setattr(backends.subprocess, "Popen", popen)
    asked = []

    def units():
        yield ("double al_f(double x) { return x; }\n", ("-O2",))
        asked.append(len(started))
        yield ("double al_g(double x) { return 2 * x; }\n", backends.OUT_FLAGS)

    lib, hit = backends.build_stream(units())
    assert asked == [1] and not hit and lib.exists()
    compiles = len(started)
    assert backends.build_stream(units()) == (lib, True)
    assert len(started) == compiles  # nothing compiled the second time


def test_cache_dir_is_the_user_cache(monkeypatch, tmp_path):
    monkeypatch.delenv("AL2PY_CACHE_DIR")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    if sys.platform.startswith("linux"):
        assert backends.cache_dir() == tmp_path / "xdg" / "al2py"
    assert backends.cache_dir().name == "al2py"


def _singular_spec(n):
    t = sp.Dummy("t")
    q = sp.symbols(f"q:{n}")
    a = sp.symbols(f"a:{n}")
    c = sp.Symbol("c")
    mass = [c * sp.cos(q[0]) if i == j else 0 for i in range(n) for j in range(n)]
    return backends.DynamicsSpec(t, list(q), list(a), [c], mass, [1] * n, list(a))


@pytest.mark.parametrize("n", [1, 3])
@pytest.mark.parametrize("name", [*COMPILED, "lambdify"])
def test_singular_mass_matrix_is_reported(name, n):
    bound = backends.compile_dynamics(_singular_spec(n), name).bind([0.0])
    with pytest.raises(backends.SingularMatrixError) as info:
        bound.rhs(0.25, np.zeros(n))
    assert info.value.t == 0.25
    ok = backends.compile_dynamics(_singular_spec(n), name).bind([2.0])
    assert ok.rhs(0.0, np.zeros(n)).tolist() == pytest.approx([0.5] * n)


@needs_cc
def test_c_backend_reports_values_that_are_not_finite():
    t = sp.Dummy("t")
    x, c = sp.symbols("x c")
    spec = backends.DynamicsSpec(t, [x], [], [c], [], [], [sp.log(x) / c])
    bound = backends.compile_dynamics(spec, "c").bind([0.0])
    with pytest.raises(ValueError, match="not finite"):
        bound.rhs(0.0, np.array([1.0]))


def test_unknown_backend_is_an_error():
    with pytest.raises(backends.BackendError, match="unknown backend 'fortran'"):
        backends.compile_dynamics(_spec(), "fortran")


def test_auto_falls_back_to_lambdify_with_one_line(monkeypatch, capsys):
    monkeypatch.setattr(backends, "_AVAILABLE", {"c": False, "llvm": False})
    monkeypatch.setattr(backends, "_SAID", set())
    compiled = backends.compile_dynamics(_spec(), "auto")
    assert compiled.backend == "lambdify"
    backends.compile_dynamics(_spec(), None)
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [
        "al2py: note: using the lambdify backend (slower): no C compiler found"
        " (set CC); symengine with LLVM is not installed"
    ]


def test_explicit_backend_that_is_missing_is_an_error(monkeypatch, tutorial):
    monkeypatch.setattr(backends, "_AVAILABLE", {"c": False})
    with pytest.raises(NumericsError, match="no C compiler found"):
        tutorial("tutor6").run(backend="c")


@needs_cc
def test_env_variable_chooses_the_backend(monkeypatch):
    monkeypatch.setenv("AL2PY_BACKEND", "lambdify")
    assert backends.compile_dynamics(_spec()).backend == "lambdify"
    monkeypatch.setenv("AL2PY_BACKEND", "c")
    assert backends.compile_dynamics(_spec()).backend == "c"
    monkeypatch.delenv("AL2PY_BACKEND")
    assert backends.compile_dynamics(_spec()).backend == "c"  # auto: fastest


@pytest.mark.parametrize("name", COMPILED)
def test_tutor6_compiled_equals_lambdify(tutorial, name):
    module = tutorial("tutor6")
    fast = module.run(backend=name)
    slow = module.run(backend="lambdify")
    assert len(fast.tables) == len(slow.tables) == 1
    a, b = fast.tables[0], slow.tables[0]
    assert a.names == b.names == ["T", "STRETCH", "QA", "QB", "ECHECK"]
    # Same integrator, same equations: differences are round-off, far inside
    # the job's tolerances (absErr = relErr = 1e-7).
    np.testing.assert_allclose(a.data, b.data, rtol=1e-6, atol=1e-6)
    assert float(a["QA"][-1]) == pytest.approx(50.123, abs=5e-4)
    assert fast.nfev > 0


@needs_cc
def test_singular_zero_through_run_names_the_accelerations(
    tmp_path, convert_and_import
):
    script = tmp_path / "sing.al"
    script.write_text(
        "Variables X', Y'\nConstants C\nZero[1] = C*X'' + 1\nZero[2] = Y'' - X\n"
        "Input C=0, TFINAL=1\nOutput T, X\nCODE Dynamics() sing.c\n"
    )
    module, _ = convert_and_import(script)
    for name in ("c", "lambdify"):
        with pytest.raises(NumericsError, match=r"coefficient matrix of X'', Y''"):
            module.run(backend=name)


@needs_cc
def test_module_command_line_backend_option(tmp_path):
    from al2py import convert

    code = convert((SHARED / "tutor6.al").read_text(), str(SHARED / "tutor6.al")).code
    (tmp_path / "tutor6.py").write_text(code)
    env = {**os.environ, "AL2PY_CACHE_DIR": str(tmp_path / "cache")}
    tables = []
    for name in ("c", "lambdify"):
        out = tmp_path / name
        run = subprocess.run(
            [sys.executable, "tutor6.py", "--backend", name, "--outdir", str(out)],
            cwd=tmp_path,
            capture_output=True,
            text=True,
            timeout=600,
            env=env,
        )
        assert run.returncode == 0, run.stderr
        tables.append(np.loadtxt(out / "tutor6.1", comments="%"))
    np.testing.assert_allclose(tables[0], tables[1], rtol=1e-6, atol=1e-6)
    assert list((tmp_path / "cache").iterdir())  # compiled into the cache only
    suffixes = {p.suffix for p in tmp_path.iterdir() if p.is_file()}
    assert not suffixes & {".so", ".dll", ".c", ".o"}  # nothing beside the script


@pytest.mark.full
def test_numerics_suite_with_lambdify_forced(tmp_path):
    """The tutorial and numerics suites with ``AL2PY_BACKEND=lambdify``; the
    normal run of the suite uses the default (compiled) backend.  In the
    full tier (``make test-full``): ``make test`` compares the lambdify
    backend with the compiled ones case by case
    (:func:`test_ode_function_integrates_to_run_results` and others)."""
    cache = tmp_path / "cache"
    env = {**os.environ, "AL2PY_BACKEND": "lambdify", "AL2PY_CACHE_DIR": str(cache)}
    tests = [
        "tests/test_numerics_golden.py",
        "tests/runtime/test_numerics.py",
        "tests/test_regress_numerics.py",
        "tests/test_real_constructs.py",
    ]
    run = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:cacheprovider", *tests],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=1200,
        env=env,
    )
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    assert " passed" in run.stdout and "failed" not in run.stdout
    assert not cache.exists() or not any(cache.iterdir())  # nothing compiled


@pytest.mark.parametrize("name", [*COMPILED, "lambdify"])
def test_ode_function_integrates_to_run_results(tutorial, name):
    from scipy.integrate import solve_ivp

    module = tutorial("tutor6")
    f, y0, names = module.al.numerics.ode_function(QA=30, backend=name)
    assert names[:4] == ["U1", "U2", "QA", "QB"]  # declaration order
    assert y0[2] == pytest.approx(np.radians(30))
    result = module.run(QA=30, TFINAL=2, backend=name)
    sol = solve_ivp(f, (0.0, 2.0), y0, method="DOP853", rtol=1e-10, atol=1e-10)
    assert np.degrees(sol.y[2, -1]) == pytest.approx(float(result["QA"][-1]), abs=1e-4)
    assert np.degrees(sol.y[3, -1]) == pytest.approx(float(result["QB"][-1]), abs=1e-4)
    # the compiled and the lambdify right-hand sides agree at a state
    slow, _, _ = module.al.numerics.ode_function(QA=30, backend="lambdify")
    assert f(0.3, sol.y[:, -1]) == pytest.approx(slow(0.3, sol.y[:, -1]), rel=1e-12)
    assert f(0.3, list(sol.y[:, -1])) == pytest.approx(slow(0.3, sol.y[:, -1]))


@pytest.mark.parametrize("name", [*COMPILED, "lambdify"])
def test_rhs_outlives_its_bound_object(name):
    """``bind(p).rhs`` alone must keep the parameter values alive."""
    import gc

    spec = _spec(autolev_functions=name != "llvm")
    p = [1.5, 2.5, 3.5]
    rhs = backends.compile_dynamics(spec, name).bind(list(p)).rhs
    gc.collect()
    junk = [np.full(3, 1e9) for _ in range(1000)]  # reuse the freed memory
    y = [0.1, 0.2, 0.3, 0.4, 0.5]
    dy, _rows = _expected(spec, 0.5, y, p)
    assert rhs(0.5, np.array(y)) == pytest.approx(dy, rel=1e-10)
    assert len(junk) == 1000


def _chain_spec(n: int):
    """One acceleration and outputs over a chain of ``n`` intermediates
    (each uses the previous one, a state and the acceleration's forcing)."""
    t = sp.Dummy("t")
    q, u, a, c = sp.symbols("q u a c")
    zs = sp.symbols(f"z0:{n}")
    inter = [(zs[0], sp.sin(q) * c + u)]
    for k in range(1, n):
        inter.append((zs[k], sp.cos(zs[k - 1]) * q - zs[k - 1] ** 2 / (2 + u**2)))
    outputs = [[q, a * zs[-1]], [zs[k] + t for k in range(0, n, 3)]]
    return backends.DynamicsSpec(
        t, [q, u], [a], [c], [2 + sp.cos(q)], [-c * zs[2]], [u, a], outputs, inter
    )


@pytest.mark.skipif(not backends.available("c"), reason="no C compiler")
def test_large_outputs_compile_while_printed(monkeypatch, tmp_path):
    """build_stream compiles each unit as it is printed, keeps the objects,
    and names the library as build_units does; with the library cached it
    starts no compiler."""
    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(backends, "SPLIT", 10)
    monkeypatch.setattr(backends, "_CHUNK", 7)
    spec = _chain_spec(40)
    path, hit = backends.build_stream(backends.c_model_stream(spec))
    assert not hit and path.exists()
    units = backends.c_model_units(spec)
    assert len(list(tmp_path.glob("*.o"))) == len(units) >= 3
    assert backends.build_units(units) == (path, True)

    commands = []
    real = subprocess.Popen

    def recorded(cmd, **kwargs):
        commands.append(cmd)
        return real(cmd, **kwargs)

    monkeypatch.setattr(backends.subprocess, "Popen", recorded)
    assert backends.build_stream(backends.c_model_stream(spec)) == (path, True)
    assert commands == []
    path.unlink()  # the objects are kept: only the link runs
    assert backends.build_stream(backends.c_model_stream(spec)) == (path, False)
    assert len(commands) == 1 and "-shared" in commands[0]


@pytest.mark.skipif(not backends.available("c"), reason="no C compiler")
def test_large_outputs_compile_in_parallel_parts(monkeypatch):
    """Above SPLIT intermediates, al_out and its intermediates are compiled
    in several translation units (functions of _CHUNK statements, the
    intermediates in one array): the same numbers as lambdify."""
    monkeypatch.setattr(backends, "SPLIT", 10)
    monkeypatch.setattr(backends, "_CHUNK", 7)
    spec = _chain_spec(40)
    units = backends.c_model_units(spec)
    assert len(units) >= 3  # the right-hand side, the parts, al_out
    assert units[0][1] == ("-O2",) and units[-1][1] == backends.OUT_FLAGS
    # a function of the states alone is computed once, in al_out, before the
    # parts (which read it from z); functions of intermediates stay in place
    assert units[-1][0].count("sin(y[0])") == 1
    assert not any("sin(" in text for text, _flags in units[1:-1])
    assert all("cos(z[" in text for text, _flags in units[1:-1])
    compiled = backends.compile_dynamics(spec, "c")
    reference = backends.compile_dynamics(spec, "lambdify")
    rng = random.Random(5)
    for _ in range(4):
        y = np.array([rng.uniform(-1, 1), rng.uniform(-1, 1)])
        p = [rng.uniform(0.5, 2)]
        tt = rng.uniform(0, 1)
        ours, theirs = compiled.bind(p), reference.bind(p)
        assert ours.rhs(tt, y) == pytest.approx(theirs.rhs(tt, y), rel=1e-12)
        for a, b in zip(ours.outputs(tt, y), theirs.outputs(tt, y), strict=True):
            assert a == pytest.approx(b, rel=1e-12, abs=1e-14)
