"""Research at interactive speed (issue 36): ``evaluate()`` compiled once,
``sweep()`` over grids on any executor, ``linearize()`` of a job.

The bicycle is our own ``tests/models/whipple_linear.al``, written as
research scripts are (``AMAT = D(XDOT, X)`` in the script, roll, steer and
pedal torques as Specified quantities); its linearization must give
Meijaard et al. (2007), Table 2.  Timings live in
``benchmarks/research.py``, not here."""

from __future__ import annotations

import io
import json
import multiprocessing
import os
import pickle
import random
import subprocess
import sys
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from al2py_runtime import progress
from al2py_runtime.jobs import quantities
from al2py_runtime.jobs.records import NumericsError
from al2py_runtime.jobs.run import evaluate_with_inputs, input_values
from conftest import SHARED, load_module
from test_whipple import TABLE2  # Meijaard et al. (2007), Table 2

from al2py import convert

HERE = Path(__file__).resolve().parent
BICYCLE = HERE / "models" / "whipple_linear.al"
TUTOR6 = HERE.parent / "examples" / "tutor6.al"
RR = 0.3  # the rear wheel's radius: the forward speed is -U6*RR


def _module(path: Path, tmp: Path, text: str | None = None):
    result = convert(text if text is not None else path.read_text(), str(path))
    return load_module(result.code, tmp, result.module)


def _contains(got, wanted, tol):
    """Every value of ``wanted`` is within ``tol`` of one of ``got``."""
    got = np.asarray(got, dtype=complex)
    worst = max(float(np.min(np.abs(got - w))) for w in wanted)
    assert worst < tol, (np.sort_complex(got), wanted)


SMALL = """\
Constants A, B, C
Variables X', Y'
Specified F
E = A*X^2 + B*SIN(Y) + F
M = [A*X, B; C*COS(Y), X*Y + F]
R = SQRT(X)
X' = Y
Y' = -A*X - B*Y + F
Input A=2, B=0.5
Input X=0.3, Y=-0.2
"""


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    return _module(Path("small.al"), tmp_path_factory.mktemp("small"), SMALL)


# ----------------------------------------------------------- evaluate()


def test_compiled_evaluate_equals_substitution(small):
    """The compiled quantity gives the substituting path's numbers at random
    points (C and lambdify kernels alike)."""
    job = small.al.numerics._make_job("ALGEBRAIC")  # noqa: SLF001 - the old path
    rng = random.Random(36)
    for _ in range(5):
        point = {"X": rng.uniform(-2, 2), "Y": rng.uniform(-2, 2), "C": rng.random()}
        point["F"] = rng.uniform(-1, 1)
        for name in ("E", "M"):
            want = evaluate_with_inputs(job, small.al.value(name), name, point)
            for backend in ("lambdify", "c"):
                got = small.evaluate(name, point, backend=backend)
                assert np.allclose(got, want, rtol=1e-13, atol=1e-13)


def test_evaluate_is_compiled_once(small):
    first = small.al.numerics.compiled_quantity("M", {"C": 1.0})
    small.evaluate("M", C=1.0)
    small.evaluate("M", C=2.0, X=0.1)  # a new name given: another signature
    assert small.al.numerics.compiled_quantity("M", {"C": 5.0}) is first


def test_evaluate_broadcasts_arrays(small):
    """Any value may be an array: the result has the broadcast shape in
    front (before issue 36 an array was refused)."""
    xs = np.linspace(-1, 1, 5)
    cs = np.array([[0.0], [1.0], [2.0]])
    out = small.evaluate("M", X=xs, C=cs)
    assert out.shape == (3, 5, 2, 2)
    for i in range(3):
        for j in range(5):
            one = small.evaluate("M", X=xs[j], C=cs[i, 0])
            assert np.array_equal(out[i, j], one)
    assert small.evaluate("E", X=xs).shape == (5,)
    assert isinstance(small.evaluate("E"), float)


def test_evaluate_without_a_specified_is_zero_and_noted(small, capsys, monkeypatch):
    """A Specified quantity nobody gives is 0, noted, as in a run."""
    from al2py_runtime import MissingValueWarning

    with pytest.warns(MissingValueWarning, match="F is Specified with no equation"):
        value = small.evaluate("E", X=1.0, Y=0.0)
    assert value == pytest.approx(2.0)


def test_evaluate_names_a_constant_without_value(small):
    with pytest.raises(NumericsError, match=r"C \(declared on line 1\)"):
        small.evaluate("M", X=1.0)
    got = small.evaluate("M", X=1.0, Y=0.0, zero_missing=True)
    assert got[1, 0] == 0.0


def test_evaluate_falls_back_where_the_compiled_value_is_not_finite(small):
    """SQRT of a negative number: the substituting path's complex value."""
    assert small.evaluate("R", X=4.0) == pytest.approx(2.0)
    assert complex(small.evaluate("R", X=-4.0)) == pytest.approx(2j)
    out = small.evaluate("R", X=np.array([4.0, -4.0]))
    assert out.tolist() == pytest.approx([2.0, 2j])


def test_kernel_pickles_as_source(small):
    """What goes to a worker is the kernel's source, not sympy trees."""
    for backend in ("lambdify", "c"):
        plan = small.al.numerics.compiled_quantity("M", {"C": 1.0}, backend)
        data = pickle.dumps(plan.kernel)
        assert b"sympy" not in data
        again = pickle.loads(data)
        assert again is plan.kernel  # this process built it already
        rows = np.random.default_rng(0).random((4, plan.kernel.n_params))
        ts = np.zeros(4)
        assert np.array_equal(again.table(ts, rows), plan.kernel.table(ts, rows))


# ---------------------------------------------------------------- sweep()


def test_sweep_spans_the_product_grid(small):
    s = small.sweep("M", X=[0.1, 0.2, 0.3], C=[1.0, 2.0], Y=0.5)
    assert s.shape == (3, 2) and s.values.shape == (3, 2, 2, 2)
    assert list(s.axes) == ["X", "C"] and s.fixed == {"Y": 0.5}
    assert np.array_equal(s.values[2, 1], small.evaluate("M", X=0.3, C=2.0, Y=0.5))
    frame = s.to_pandas()
    assert list(frame.columns) == ["X", "C", "name", "value"]
    assert len(frame) == 6 * 4
    assert set(frame["name"]) == {"M[1,1]", "M[1,2]", "M[2,1]", "M[2,2]"}
    with pytest.raises(NumericsError, match="over one name"):
        s.plot()
    assert "Sweep" in s._repr_html_() and "M" in repr(s)


def test_sweep_refuses_other_shapes(small):
    with pytest.raises(NumericsError, match="1-D arrays"):
        small.sweep("M", X=np.zeros((2, 2)), C=1.0)


def test_eigenvalues_follow_branches():
    """Two branches that cross keep their columns (sorting would swap them)."""
    from al2py_runtime.jobs.sweep import follow_branches

    v = np.linspace(0, 2, 21)
    raw = np.stack([v, 2 - v], axis=1)  # they cross at v = 1
    raw[11:] = raw[11:, ::-1]  # as eig would order them: smaller first
    got = follow_branches(raw, (21,))
    assert np.allclose(got[:, 0].real, v) and np.allclose(got[:, 1].real, 2 - v)


def test_progress_line_on_a_terminal(monkeypatch):
    class Tty(io.StringIO):
        def isatty(self):
            return True

    monkeypatch.setattr(progress, "AFTER", 0.0)
    monkeypatch.setattr(progress, "EVERY", 0.01)
    stream = Tty()
    with progress.Steps("sweeping AMAT", 101, stream=stream) as steps:
        steps.advance(40)
        import time

        time.sleep(0.1)
    assert "sweeping AMAT: 40/101" in stream.getvalue()
    quiet = io.StringIO()
    with progress.Steps("sweeping AMAT", 3, stream=quiet):
        pass
    assert quiet.getvalue() == ""


def test_dask_executor_names_the_extra(small, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(NumericsError, match=r"pip install 'al2py\[dask\]'"):
        small.sweep("E", X=[1.0, 2.0], executor="dask")


# ------------------------------------------------------------- the bicycle


@pytest.fixture(scope="module")
def bicycle(tmp_path_factory):
    return _module(BICYCLE, tmp_path_factory.mktemp("bicycle"))


def test_bicycle_evaluate_gives_table2(bicycle):
    """The script's own AMAT, evaluated at the Inputs (upright, no torque
    given: they are 0) but the speed, has Table 2's eigenvalues."""
    for v in (0.0, 4.0, 5.0, 10.0):
        a = bicycle.evaluate("AMAT", U6=-v / RR)
        assert a.shape == (11, 11)
        _contains(np.linalg.eigvals(a), TABLE2[v], 1e-8)


def test_bicycle_sweep_eigenvalues_give_table2(bicycle):
    speeds = np.linspace(0, 10, 101)
    s = bicycle.sweep("AMAT", U6=-speeds / RR)
    assert s.values.shape == (101, 11, 11)
    ev = s.eigenvalues()
    assert ev.shape == (101, 11)
    for v in (4.0, 5.0, 10.0):
        _contains(ev[int(round(v * 10))], TABLE2[v], 1e-8)
    # one column is one branch: the capsize eigenvalue is real all along,
    # and the weave pair's imaginary parts keep their signs once it forms
    weave = [k for k in range(11) if abs(ev[60, k].imag) > 1]
    assert len(weave) == 2
    assert all(np.ptp(np.sign(ev[10:, k].imag)) == 0 for k in weave)
    frame = s.to_pandas(eigenvalues=True)
    assert list(frame.columns) == ["U6", "branch", "real", "imag"]
    assert len(frame) == 101 * 11
    fig = s.plot(x=speeds, xlabel="speed (m/s)")
    assert "7 zero everywhere" in fig.axes[0].get_title()
    assert len(fig.axes[0].lines) == 2 * 4 + 1  # four modes, real and imaginary


def test_bicycle_linearize_equals_the_scripts_amat(bicycle):
    """linearize() of the Dynamics job equals the script's own D(XDOT, X)
    and D(XDOT, [TPHI; TDELTA]); its A has Table 2's eigenvalues."""
    lin = bicycle.linearize(U6=-5.0 / RR)
    assert lin.states == ["Q1", "Q2", "Q3", "Q4", "Q5", "Q6", "Q7", "Q8"] + [
        "U4",
        "U6",
        "U7",
    ]
    assert lin.inputs == ["TPHI", "TDELTA", "TTHETAR"]
    amat = bicycle.evaluate("AMAT", U6=-5.0 / RR)
    bmat = bicycle.evaluate("BMAT", U6=-5.0 / RR)
    assert np.allclose(lin.A, amat, rtol=0, atol=1e-10)
    assert np.allclose(lin.B[:, :2], bmat, rtol=0, atol=1e-10)
    _contains(lin.eigenvalues(), TABLE2[5.0], 1e-8)
    a, b = lin
    assert a is lin.A and b is lin.B


def test_bicycle_linearize_without_the_scripts_d(tmp_path):
    """The same bicycle with no D() in the script: linearize() derives the
    Jacobians itself (the intermediates' chain rule) and gives Table 2."""
    text = BICYCLE.read_text()
    text = "\n".join(
        line for line in text.splitlines() if not line.startswith(("AMAT", "BMAT"))
    )
    module = _module(BICYCLE, tmp_path, text)
    for v in (4.0, 10.0):
        _contains(module.linearize(U6=-v / RR).eigenvalues(), TABLE2[v], 1e-8)


@pytest.mark.slow
def test_bicycle_sweep_on_dask_is_identical(bicycle):
    """The 101-speed sweep on a local Dask cluster of two worker processes
    gives the serial arrays bit for bit."""
    distributed = pytest.importorskip(
        "distributed", reason="needs dask: pip install 'al2py[dask]'"
    )
    speeds = np.linspace(0, 10, 101)
    serial = bicycle.sweep("AMAT", U6=-speeds / RR)
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None
        ) as cluster,
        distributed.Client(cluster) as client,
    ):
        on_dask = bicycle.sweep("AMAT", U6=-speeds / RR, executor=client.get_executor())
        built = client.run(quantities.kernels_built)
    assert np.array_equal(on_dask.values, serial.values)
    assert np.array_equal(on_dask.eigenvalues(), serial.eigenvalues())
    # each worker built the model once, whatever the number of chunks
    assert sorted(built.values()) == [1, 1]


def test_workers_build_the_kernel_once(small):
    """On a pool of fresh processes each worker builds the model once, not
    once per chunk, and the result is the serial one."""
    xs = np.linspace(-1, 1, 40)
    serial = small.sweep("M", X=xs, C=1.0)
    spawn = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(2, mp_context=spawn) as pool:
        pooled = small.sweep("M", X=xs, C=1.0, executor=pool, chunksize=4)
        built = [pool.submit(quantities.kernels_built).result() for _ in range(8)]
    assert np.array_equal(pooled.values, serial.values)
    assert set(built) <= {0, 1} and max(built) == 1


# ----------------------------------------------------------- job sweeps


@pytest.fixture(scope="module")
def tutor6(tmp_path_factory):
    return _module(TUTOR6, tmp_path_factory.mktemp("tutor6"))


def test_job_sweep_on_a_pool_equals_single_runs(tutor6):
    """200 runs of tutor6 over two Inputs on a process pool give the tables
    of 200 single run() calls."""
    qa = np.linspace(10, 40, 10)
    k = np.linspace(100, 300, 20)
    with ProcessPoolExecutor(2) as pool:
        s = tutor6.sweep(job="tutor6", QA=qa, K=k, tfinal=4, executor=pool)
    assert s.results.shape == (10, 20)
    for i, a in enumerate(qa):
        for j, b in enumerate(k):
            one = tutor6.run(QA=float(a), K=float(b), tfinal=4)
            got = s.results[i, j]
            assert len(got.tables) == len(one.tables)
            for x, y in zip(got.tables, one.tables, strict=True):
                assert np.array_equal(x.data, y.data)
    frame = s.to_pandas()
    assert list(frame.columns[:2]) == ["QA (swept)", "K"]
    assert s.plot().axes[0].get_ylabel() == "STRETCH"


# ------------------------------------------------------------ linearize()


def _finite_differences(module, lin):
    f, y0, names = module.ode_function()
    y0 = np.asarray(y0)
    jac = np.zeros((len(y0), len(y0)))
    for j in range(len(y0)):
        h = 1e-6 * max(1.0, abs(y0[j]))
        e = np.zeros(len(y0))
        e[j] = h
        jac[:, j] = (f(0.0, y0 + e) - f(0.0, y0 - e)) / (2 * h)
    order = [names.index(s) for s in lin.states]
    return jac[np.ix_(order, order)]


def _kanes_linearize(module, lin, constants=None):
    """sympy's ``KanesMethod.linearize`` of the module's model at the same
    point (with the accelerations there), numeric, in ``lin``'s order."""
    from sympy.physics.mechanics import dynamicsymbols

    job = module.al.numerics.job()
    vals, _ = input_values(job, {})
    consts = {
        obj: vals.values[n]
        for n, (kind, obj) in job.entries.items()
        if kind == "constant" and n in vals.values
    }
    km = module.kanes_method()
    q, u = list(km.q), list(km.u)
    op = {x: lin.point[job.names[x]] for x in q + u}
    rates = {x.diff(dynamicsymbols._t): lin.point[job.names[x] + "'"] for x in u}
    rates.update(
        {k: float(v.xreplace(consts).xreplace(op)) for k, v in km.kindiffdict().items()}
    )
    a, _b, _r = km.linearize(A_and_B=True, op_point=[rates, op])
    a = sp.Matrix(a).xreplace(consts).xreplace(rates).xreplace(op)
    extra = constants or {}
    a = a.xreplace({s: extra[s.name] for s in a.free_symbols if s.name in extra})
    order = [lin.states.index(job.names[x]) for x in q + u]
    return np.array(a.evalf(), dtype=float), order


def test_tutor6_linearize_equals_kanesmethod(tutor6):
    lin = tutor6.linearize()
    theirs, order = _kanes_linearize(tutor6, lin)
    assert np.allclose(lin.A[np.ix_(order, order)], theirs, rtol=1e-10, atol=1e-10)
    assert np.allclose(lin.A, _finite_differences(tutor6, lin), atol=1e-6)
    assert lin.inputs == [] and lin.B.shape == (len(lin.states), 0)


def test_tutor6_linearize_symbolic(tutor6):
    """symbolic=True keeps the constants: substituting the Inputs gives
    the numeric A."""
    lin = tutor6.linearize()
    sym = tutor6.linearize(symbolic=True)
    job = tutor6.al.numerics.job()
    vals, _ = input_values(job, {})
    consts = {
        obj: vals.values[n]
        for n, (kind, obj) in job.entries.items()
        if kind == "constant" and n in vals.values
    }
    assert isinstance(sym.A, sp.MatrixBase)
    assert {s.name for s in sym.A.free_symbols} <= {s.name for s in consts}
    assert sym.A.free_symbols  # the constants are kept
    num = np.array(sym.A.xreplace(consts).evalf(), dtype=float)
    assert np.allclose(num, lin.A, rtol=1e-10, atol=1e-10)


@pytest.mark.parametrize("name", ["tutor6", "tutor7", "tutor8", "tutor9"])
def test_tutorial_linearize_equals_finite_differences(tutorial, name):
    if not SHARED.exists():
        pytest.skip("needs ../shared/tutorial")
    module = tutorial(name)
    lin = module.linearize()
    assert np.allclose(lin.A, _finite_differences(module, lin), atol=1e-6)


def test_tutor8_linearize_equals_its_own_d(tutorial):
    """tutor8's A = D(Xp, Xm) (Taylor's perturbation equations) is the
    job's linearization: its perturbation block anywhere, and its own block
    at X = THETA = U1 = U2 = 0; also KanesMethod's there."""
    if not SHARED.exists():
        pytest.skip("needs ../shared/tutorial")
    module = tutorial("tutor8")
    own = module.evaluate("A")  # Xm = [dX, dTHETA, dU1, dU2], at the Inputs' K
    lin = module.linearize(X=0, THETA=0, U1=0, U2=0)
    for names in (["DX", "DTHETA", "DU1", "DU2"], ["X", "THETA", "U1", "U2"]):
        idx = [lin.states.index(n) for n in names]
        assert np.allclose(lin.A[np.ix_(idx, idx)], own, rtol=1e-12, atol=1e-12)
    theirs, order = _kanes_linearize(
        module, lin, {"L": 1, "MA": 10, "MB": 1, "G": 9.81}
    )
    assert np.allclose(lin.A[np.ix_(order, order)], theirs, rtol=1e-10, atol=1e-10)


def test_job_sweep_results_from_workers_animate_as_local_ones(tutor6):
    """A worker's result travels without its sympy model; the parent joins
    its numbers to its own model, so it can be shown as a local one."""
    with ProcessPoolExecutor(1) as pool:
        s = tutor6.sweep(job="tutor6", QA=[20.0, 30.0], tfinal=1, executor=pool)
    local = tutor6.run(QA=30.0, tfinal=1)
    got = s.results[1]
    assert got.motion is not None and got.motion.job is local.motion.job
    assert np.array_equal(got.motion.ys, local.motion.ys)


def test_evaluate_arrays_of_an_input_others_are_computed_from(tmp_path):
    """``Input E4 = COS(QQ1/2)*2``: an array of QQ1 (degrees) changes E4 at
    each point, as a run would."""
    src = (
        "Constants qq1, e4, k\nVariables x'\nx' = -k*x\nY = e4*x\n"
        "Input qq1 = 60 deg, e4 = cos(qq1/2)*2, k = e4\n"
        "Input x=1, tFinal=1, integStp=0.5\nOutput T, x\nCODE ODE() f.c\n"
    )
    module = _module(Path("computed.al"), tmp_path, src)
    angles = np.array([0.0, 60.0, 120.0])
    got = module.evaluate("Y", QQ1=angles, X=3.0)
    assert np.allclose(got, 3 * 2 * np.cos(np.radians(angles) / 2), rtol=1e-13)
    assert module.evaluate("Y", QQ1=120.0, X=3.0) == pytest.approx(got[2], rel=1e-13)


# ------------------------------------------- numpy tape and the disk cache


def _relative_gap(a, b):
    """The largest difference of ``a`` and ``b`` relative to each entry's
    size (entries that are exactly 0 in both count as equal)."""
    a, b = np.asarray(a), np.asarray(b)
    scale = np.maximum(np.abs(a), np.abs(b))
    gap = np.abs(a - b)
    return float(np.max(np.where(scale > 0, gap / np.where(scale > 0, scale, 1), 0)))


def test_bicycle_sweep_runs_the_tape_and_equals_the_compiled_function(bicycle):
    """A 101-speed sweep of the bicycle's AMAT (5,000 intermediates) runs its
    numpy tape (no printing, no compiler) and gives the compiled function's
    numbers within 1e-12 relative; evaluate() keeps the compiled function."""
    speeds = np.linspace(0, 10, 101)
    numerics = bicycle.al.numerics
    tape = numerics.compiled_quantity("AMAT", {"U6": speeds}, points=101)
    assert tape.origin == "numpy" and tape.kernel.tape.zs > quantities.SMALL
    compiled = numerics.compiled_quantity("AMAT", {"U6": 0.0})
    assert compiled.origin in ("compiled", "disk") and compiled.kernel.backend == "c"
    s = bicycle.sweep("AMAT", U6=-speeds / RR)
    c = bicycle.sweep("AMAT", U6=-speeds / RR, backend="c")
    assert _relative_gap(s.values, c.values) < 1e-12
    assert np.max(np.abs(s.values - c.values)) > 0  # two ways, truly
    # the rule reads no cache: more points than ONE_SHOT_POINTS, another
    # backend, or evaluate() take the compiled function
    assert not quantities.takes_tape(tape, quantities.ONE_SHOT_POINTS + 1, None)
    assert not quantities.takes_tape(tape, 101, "c")
    assert not quantities.takes_tape(tape, None, None)
    assert quantities.takes_tape(tape, 101, "numpy")


def test_tape_rule_follows_al2py_backend(bicycle, monkeypatch):
    tape = bicycle.al.numerics.compiled_quantity("AMAT", {"U6": 0.0}, points=5)
    monkeypatch.setenv("AL2PY_BACKEND", "c")
    assert not quantities.takes_tape(tape, 5, None)
    monkeypatch.setenv("AL2PY_BACKEND", "auto")
    assert quantities.takes_tape(tape, 5, None)


def test_numpy_backend_equals_lambdify_and_falls_back_where_not_finite(small):
    """backend="numpy" (the tape, whatever the size) gives lambdify's numbers
    within 1e-12; a point where it is not finite is evaluated exactly."""
    xs = np.linspace(-1, 1, 7)
    for name in ("E", "M"):
        got = small.sweep(name, X=xs, C=[1.0, 2.0], F=0.3, backend="numpy")
        want = small.sweep(name, X=xs, C=[1.0, 2.0], F=0.3, backend="lambdify")
        assert _relative_gap(got.values, want.values) < 1e-12
    r = small.sweep("R", X=[4.0, -4.0], backend="numpy")
    assert r.values.tolist() == pytest.approx([2.0, 2j])
    assert small.evaluate("E", X=0.5, F=0.0, backend="numpy") == pytest.approx(
        small.evaluate("E", X=0.5, F=0.0)
    )


def test_numpy_tape_on_a_pool_is_the_serial_one(small):
    """A tape travels as operation names and slots, is made once per worker,
    and gives the serial arrays bit for bit."""
    xs = np.linspace(-1, 1, 40)
    serial = small.sweep("M", X=xs, C=1.0, backend="numpy")
    plan = small.al.numerics.compiled_quantity("M", {"X": xs}, "numpy")
    data = pickle.dumps(plan.kernel)
    assert b"sympy.core" not in data
    spawn = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(2, mp_context=spawn) as pool:
        pooled = small.sweep(
            "M", X=xs, C=1.0, executor=pool, chunksize=4, backend="numpy"
        )
        built = [pool.submit(quantities.kernels_built).result() for _ in range(8)]
    assert np.array_equal(pooled.values, serial.values)
    assert set(built) <= {0, 1} and max(built) == 1


CACHED = SMALL.replace("Input A=2, B=0.5", "Input A=2, B=0.5, C=0.25")


def _fresh(tmp: Path, text: str, stem: str = "cached"):
    tmp.mkdir(parents=True, exist_ok=True)
    return _module(Path(f"{stem}.al"), tmp, text)


def test_disk_cache_serves_a_new_model_and_never_a_stale_one(tmp_path, monkeypatch):
    """A compiled quantity is kept on disk under its tape's digest, with a
    sidecar: a new model object of the same script loads it; another
    script or another runtime compile anew;
    another Input value reuses it (the value is an argument) with the new
    value; a library gone or a sidecar spoiled is compiled again."""
    from al2py_runtime.jobs import fingerprint

    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path / "cache"))
    if not quantities.backends.available("c"):
        pytest.skip("needs a C compiler")
    backend = "c"

    def plan(module, **given):
        return module.al.numerics.compiled_quantity("M", given, backend)

    first = _fresh(tmp_path / "a", CACHED)
    assert plan(first).origin == "compiled"
    want = first.evaluate("M", X=0.7, Y=0.1, F=0.0, backend=backend)
    sidecars = sorted((tmp_path / "cache" / "quantities").glob("*[0-9a-f].json"))
    assert len(sidecars) == 1
    again = _fresh(tmp_path / "b", CACHED)
    assert plan(again).origin == "disk"
    got = again.evaluate("M", X=0.7, Y=0.1, F=0.0, backend=backend)
    assert np.array_equal(got, want)
    # another script (a coefficient of M): compiled anew, its own numbers
    other = _fresh(tmp_path / "c", CACHED.replace("X*Y + F", "X*Y + 2*F"))
    assert plan(other).origin == "compiled"
    m = other.evaluate("M", X=0.7, Y=0.1, F=1.0, backend=backend)
    assert m[1, 1] == pytest.approx(0.07 + 2.0, rel=1e-14)
    # another Input value: the same function, the new value
    changed = _fresh(tmp_path / "e", CACHED.replace("C=0.25", "C=0.75"))
    assert plan(changed).origin == "disk"
    m = changed.evaluate("M", X=0.7, Y=0.1, F=0.0, backend=backend)
    assert m[1, 0] == pytest.approx(0.75 * np.cos(0.1), rel=1e-14)
    # another runtime: compiled anew
    monkeypatch.setattr(fingerprint, "runtime_digest", lambda: "another runtime")
    assert plan(_fresh(tmp_path / "f", CACHED)).origin == "compiled"
    monkeypatch.undo()
    monkeypatch.setenv("AL2PY_CACHE_DIR", str(tmp_path / "cache"))
    # a spoiled sidecar, a library removed: compiled again
    sidecars[0].write_text("{not json")
    assert plan(_fresh(tmp_path / "g", CACHED)).origin == "compiled"
    meta = json.loads(sidecars[0].read_text())
    (tmp_path / "cache" / meta["library"]).unlink()
    assert plan(_fresh(tmp_path / "h", CACHED)).origin == "compiled"
    # a kernel loaded from disk still travels to workers as its source
    loaded = plan(_fresh(tmp_path / "i", CACHED))
    assert loaded.origin == "disk"
    assert pickle.loads(pickle.dumps(loaded.kernel)) is loaded.kernel
    units = loaded.kernel.source
    assert units and all(isinstance(text, str) for text, _flags in units)
    # lambdify (milliseconds to build) is not kept on disk
    lam = _fresh(tmp_path / "j", CACHED).al.numerics
    assert lam.compiled_quantity("M", {}, "lambdify").origin == "compiled"
    assert (
        _fresh(tmp_path / "k", CACHED)
        .al.numerics.compiled_quantity("M", {}, "lambdify")
        .origin
        == "compiled"
    )


def test_disk_key_is_the_same_in_every_process(tmp_path):
    """The key is computed without Python's per-process string hashing:
    two processes with different hash seeds find the same key, and the
    second loads the library the first compiled."""
    result = convert(CACHED, "cached.al")
    (tmp_path / "cached.py").write_text(result.code)
    code = (
        "import cached, json; p = cached.al.numerics.compiled_quantity('M', {}, 'c');"
        " from al2py_runtime.jobs import quantities as q;"
        " t = cached.al.numerics.compiled_quantity('M', {}, 'numpy');"
        " print(json.dumps([q.disk_key(t, 'c'), p.origin]))"
    )
    seen = []
    for seed in ("1", "2"):
        env = {
            **os.environ,
            "PYTHONHASHSEED": seed,
            "AL2PY_CACHE_DIR": str(tmp_path / "cache"),
        }
        out = subprocess.run(
            [sys.executable, "-c", code],
            cwd=tmp_path,
            env=env,
            capture_output=True,
            text=True,
            check=True,
        )
        seen.append(json.loads(out.stdout.splitlines()[-1]))
    assert seen[0][0] == seen[1][0]
    assert [s[1] for s in seen] == ["compiled", "disk"]
