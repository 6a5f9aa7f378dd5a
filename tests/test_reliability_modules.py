"""Issue 12: generated modules never write outside their folder, never show a
traceback and never run forever (items 2, 4, 5, 6, 7, 14, 15, 16)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import al2py_runtime
import pytest
from conftest import load_module

from al2py import convert
from al2py.errors import AutolevError

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def module(tmp_path: Path, name: str, text: str) -> Path:
    """Convert ``text`` (as NAME.al) into tmp_path/NAME.py."""
    code = convert(textwrap.dedent(text), f"{name}.al").code
    path = tmp_path / f"{name}.py"
    path.write_text(code)
    return path


def run_module(path: Path, *args: str, cwd: Path | None = None, env=None, timeout=120):
    return subprocess.run(
        [sys.executable, str(path), *args],
        capture_output=True,
        text=True,
        cwd=cwd or path.parent,
        env={**os.environ, **(env or {})},
        timeout=timeout,
    )


def import_module(path: Path, code: str = ""):
    return subprocess.run(
        [sys.executable, "-c", f"import {path.stem}\n{code}"],
        capture_output=True,
        text=True,
        cwd=path.parent,
        timeout=120,
    )


def tree(root: Path) -> set[str]:
    return {
        p.relative_to(root).as_posix()
        for p in root.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts
    }


# ------------------------------------------------ item 2: Save is confined

SAVES = """\
Constants A
B = A + 1
Save ../escaped.all
Save {abs}/absolute.py
Save sub/dir/nested.all
"""


def test_save_writes_only_into_outdir_under_base_names(tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    outside = tmp_path / "elsewhere"
    outside.mkdir()
    (outside / "absolute.py").write_text("# precious\n")
    mod = module(work, "saves", SAVES.format(abs=outside))
    run = run_module(mod)
    assert run.returncode == 0, run.stderr
    assert tree(tmp_path) == {
        "work/saves.py",
        "work/escaped.all",
        "work/absolute.py",
        "work/nested.all",
        "elsewhere/absolute.py",
    }
    assert (outside / "absolute.py").read_text() == "# precious\n"
    assert "-> (3) B = 1 + A" in (work / "escaped.all").read_text()
    assert (work / "absolute.py").read_text().startswith("Constants A\n")


def test_save_follows_outdir_and_no_run_writes_nothing(tmp_path):
    mod = module(tmp_path, "saves", SAVES.format(abs=tmp_path / "abs"))
    before = tree(tmp_path)
    quiet = run_module(mod, "--no-run")
    assert quiet.returncode == 0, quiet.stderr
    assert "(3) B = 1 + A" in quiet.stdout.replace("-> ", "")
    assert tree(tmp_path) == before  # --no-run writes nothing
    run = run_module(mod, "--outdir", "out")
    assert run.returncode == 0, run.stderr
    assert tree(tmp_path) - before == {
        "out/escaped.all",
        "out/absolute.py",
        "out/nested.all",
    }


def test_run_outside_the_script_tree_is_a_located_error(tmp_path):
    (tmp_path / "lib").mkdir()
    (tmp_path / "outside.al").write_text("Constants B\n")
    (tmp_path / "lib" / "inside.al").write_text("Constants C\n")
    script = tmp_path / "lib" / "main.al"
    script.write_text("Constants A\nRUN inside.al\nRUN ../outside.al\n")
    with pytest.raises(AutolevError) as info:
        convert(script.read_text(), str(script))
    assert info.value.span.line == 3 and info.value.span.col == 1
    assert "outside the script's folder and AUTOLEVPATH" in info.value.message
    # on AUTOLEVPATH it is allowed
    ok = convert(script.read_text(), str(script), autolevpath=str(tmp_path))
    assert "al.declare_constants(B, line=3)" in ok.code  # the RUN line


# ----------------------------- item 4: errors at conversion, never later

CONVERSION_ERRORS = [
    ("Constants A\nB = 1e400*A\n", 2, 5, "the number 1e400 is too large"),
    ("Constants A\nC = 1e-400 + A\n", 2, 5, "the number 1e-400 is too small"),
    ("Constants A % note \x00 here\n", 1, 20, "a NUL character"),
    (
        "Variables X'\nX' = -X\nInput X = 1 furlong\nOutput X\nCODE ODE() f.c\n",
        3,
        13,
        "unknown unit 'furlong'",
    ),
    (
        "Variables X'\nX' = -X\nInput X = 1 mm\nOutput X metrs\n",
        4,
        10,
        "unknown unit 'metrs'; did you mean metres?",
    ),
    (
        "Constants A\nM = [1, 2; 3, 4]\nN = M + A*[1, 2, 3]\n",
        3,
        5,
        "cannot add a 2x2 matrix and a 1x3 matrix",
    ),
]


@pytest.mark.parametrize("text, line, col, message", CONVERSION_ERRORS)
def test_caught_at_conversion(tmp_path, text, line, col, message):
    src = tmp_path / "bad.al"
    src.write_bytes(text.encode())
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "bad.al", "-o", "bad.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
    )
    assert run.returncode == 2
    first, source, caret = run.stderr.splitlines()[:3]
    assert first.startswith(f"bad.al:{line}:{col}: error: {message}")
    assert caret == " " * (4 + col - 1) + "^"
    assert "Traceback" not in run.stderr
    assert not (tmp_path / "bad.py").exists()


RUNTIME_ERRORS = [
    (
        "Variables X, Y\nZ = [X + Y - 1; X - Y; X + 2*Y]\nSolve(Z, X, Y)\n",
        3,
        "Solve: 3 equations for 2 unknowns",
    ),
    ("Newtonian N\nPoints P, Q\nD = Mag(P_P_Q>)\n", 3, "P_P_Q> is not defined"),
    (
        "Newtonian N\nBodies A\nPoints Ao\nH> = Momentum(BOGUS, Ao)\n",
        4,
        "Momentum takes LINEAR, ANGULAR or GENERALIZED",
    ),
    (
        "Variables X, Y\nZ = [X + Y - 1; 2*X + 2*Y - 2]\nSolve(Z, X, Y)\n",
        3,
        "Solve: the equations are singular",
    ),
]


@pytest.mark.parametrize("text, line, message", RUNTIME_ERRORS)
def test_run_time_errors_name_the_al_line(tmp_path, text, line, message):
    mod = module(tmp_path, "late", text)
    run = run_module(mod)
    assert run.returncode == 2
    assert "Traceback" not in run.stderr
    lines = run.stderr.splitlines()
    assert lines[0].startswith(f"late.al:{line}: error: {message}"), run.stderr
    assert lines[1].strip() == text.splitlines()[line - 1].strip()
    # the same from `import`: one documented exception class
    imported = import_module(mod)
    assert imported.returncode == 2 and "Traceback" not in imported.stderr
    assert imported.stderr.splitlines()[0] == lines[0]
    try:
        load_module(mod.read_text(), tmp_path, "late_again")
    except al2py_runtime.AutolevRuntimeError as exc:
        assert exc.filename == "late.al" and exc.line == line
        assert exc.message.startswith(message)
    else:  # pragma: no cover - the module must fail
        pytest.fail("importing the module did not raise")


def test_an_interrupt_names_the_al_line_without_a_traceback(tmp_path):
    """Ctrl-C while a module derives (here raised after its third
    statement) ends it with ``FILE.al:LINE: interrupted`` and status 130,
    as ``al2py`` ends when interrupted, from ``python model.py`` and from
    an ``import`` in a script; never with Python's traceback."""
    mod = module(tmp_path, "stop", "Variables X, Y\nZ = X + Y\nW = Z^2\n")
    text = mod.read_text()
    stopped = text.replace("AUTOLEV = al.names()", "raise KeyboardInterrupt", 1)
    assert stopped != text
    mod.write_text(stopped)
    for run in (run_module(mod), import_module(mod)):
        assert run.returncode == 130, run.stderr
        assert run.stderr == "stop.al:3: interrupted\n", run.stderr


@pytest.mark.parametrize("debug", [False, True])
def test_library_failures_are_worded_by_al2py(tmp_path, monkeypatch, debug):
    """A failure inside sympy that al2py did not foresee names the .al line
    and the library, never the library's own text (AL2PY_DEBUG=1 adds it)."""
    import sympy as sp

    def broken(*args, **kw):
        x = sp.Symbol("x")
        return sp.Poly(sp.sin(x), x)  # sympy's PolynomialError

    if debug:
        monkeypatch.setenv("AL2PY_DEBUG", "1")
    else:
        monkeypatch.delenv("AL2PY_DEBUG", raising=False)
    mod = module(tmp_path, "lib", "Variables X\nY = D(X^2, X)\n")
    monkeypatch.setattr(sp, "diff", broken)
    with pytest.raises(al2py_runtime.AutolevRuntimeError) as caught:
        load_module(mod.read_text(), tmp_path, "lib_debug" if debug else "lib")
    exc = caught.value
    assert (exc.filename, exc.line) == ("lib.al", 2)
    assert exc.message.startswith("an unexpected failure in sympy (an al2py bug")
    assert ("PolynomialError" in exc.message) is debug
    assert ("generators" in exc.message) is debug  # sympy's own words


def test_matrix_errors_of_sympy_are_worded():
    import sympy as sp
    from al2py_runtime.safety import describe

    with pytest.raises(Exception) as caught:
        sp.Matrix([[1, 2]]) + sp.Matrix([[1], [2]])
    assert describe(caught.value) == "the sizes of the matrices do not agree"
    with pytest.raises(Exception) as caught:
        sp.Matrix([[1, 2], [2, 4]]).inv()
    assert describe(caught.value) == "the matrix is singular (not invertible)"


def test_errors_outside_generated_modules_keep_their_tracebacks(tmp_path):
    """The hook leaves other programs' exceptions alone."""
    mod = module(tmp_path, "fine", "Constants A\nB = A + 1\n")
    code = "import fine\nraise KeyError('mine')\n"
    run = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=mod.parent
    )
    assert run.returncode == 1
    assert "Traceback" in run.stderr and "KeyError: 'mine'" in run.stderr


# -------------------------------------------- item 5: INF and NAN responses


def test_transcript_prints_infinities_and_nan(tmp_path):
    text = "Constants A\nB = 1/(A-A)\nC = 0/0\nD = [1/(A-A), 2]\nE = A + 1/0\n"
    run = run_module(module(tmp_path, "inf", text))
    assert run.returncode == 0, run.stderr
    responses = [line for line in run.stdout.splitlines() if line.startswith("->")]
    assert responses == [
        "-> (3) B = INF",
        "-> (5) C = NAN",
        "-> (7) D = [INF, 2]",
        "-> (9) E = INF",
    ]


# ------------------------------------------------ item 6: runs that end

STIFF = """\
Variables X'
X' = -1e8*(X - cos(T))
Input X = 0, tFinal = 10
Output T, X
CODE ODE() stiff.c
"""

#: stiff enough that Kutta-Merson needs about 400 sub-steps per integStp
STIFFISH = STIFF.replace("-1e8", "-1e4")


def test_too_stiff_integration_stops_at_once(tmp_path):
    """As Autolev's programs: the step may be halved 20 times (net)."""
    mod = module(tmp_path, "stiff", STIFF)
    run = run_module(mod, timeout=60)
    assert run.returncode == 2
    assert "Traceback" not in run.stderr
    (line,) = run.stderr.splitlines()
    assert line == (
        "stiff.al:5: error: CODE Ode stiff.c (line 5): integration failed at"
        " t = 0: the step was halved too often (ABSERR, RELERR)"
    )


def test_stiff_integration_stops_at_its_budget(tmp_path):
    mod = module(tmp_path, "stiff", STIFFISH)
    run = run_module(mod, env={"AL2PY_MAX_EVALS": "20000"}, timeout=60)
    assert run.returncode == 2
    assert "Traceback" not in run.stderr
    (line,) = run.stderr.splitlines()
    assert line.startswith(
        "stiff.al:5: error: CODE Ode stiff.c (line 5): stopped at t = "
    )
    assert "after 20000 right-hand-side evaluations" in line
    assert run_module(mod, timeout=60).returncode == 0  # 128,000 evaluations
    long = STIFFISH.replace("tFinal = 10", "tFinal = 100000, integStp = 0.1")
    mod = module(tmp_path, "long", long)
    timed = run_module(
        mod, "--max-seconds", "1", env={"AL2PY_MAX_EVALS": "1e12"}, timeout=60
    )
    assert timed.returncode == 2
    assert "after 1 s (the time budget" in timed.stderr


def test_tfinal_before_tinitial_is_refused(tmp_path):
    mod = tmp_path / "tutor6.py"
    mod.write_text(convert((EXAMPLES / "tutor6.al").read_text(), "tutor6.al").code)
    run = run_module(mod, "--tfinal", "-5", timeout=120)
    assert run.returncode == 2
    assert run.stderr.strip().endswith(
        "TFINAL = -5 is before TINITIAL = 0; Autolev integrates forward in time"
    )
    assert not (tmp_path / "tutor6.1").exists()


def test_budget_can_be_raised_from_python(tmp_path, monkeypatch):
    from al2py_runtime.jobs import budget

    m = load_module(convert(STIFF.replace("10", "0.0001"), "s.al").code, tmp_path, "s")
    monkeypatch.setitem(budget.LIMITS, "evaluations", 50)
    with pytest.raises(al2py_runtime.AutolevRuntimeError, match="after 50 right"):
        m.run()
    monkeypatch.setitem(budget.LIMITS, "evaluations", 10_000_000)
    result = m.run()
    assert result["X"][-1] == pytest.approx(1.0, abs=1e-3)  # x follows cos(t) ~ 1


# ------------------------------------------------------ item 7: | head -1


def test_module_output_into_a_closed_pipe_exits_quietly(tmp_path):
    mod = tmp_path / "tutor6.py"
    mod.write_text(convert((EXAMPLES / "tutor6.al").read_text(), "tutor6.al").code)
    proc = subprocess.Popen(
        [sys.executable, str(mod), "--no-run"],
        cwd=tmp_path,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        bufsize=0,
    )
    first = proc.stdout.readline()
    proc.stdout.close()
    err = proc.stderr.read().decode()
    proc.wait(timeout=120)
    assert first.startswith(b"(1) %")
    assert "Traceback" not in err and "BrokenPipe" not in err, err
    assert proc.returncode == 0


# ---------------------------------------------- item 14: results, run()


def test_results_fit_the_ecosystem(tmp_path):
    text = """\
    Variables X'
    X' = -X
    Input X = 2, tFinal = 1, integStp = 0.25, printInt = 2
    Output T, X
    CODE ODE() decay.c
    """
    m = load_module(convert(textwrap.dedent(text), "decay.al").code, tmp_path, "decay")
    import inspect

    params = inspect.signature(m.run).parameters
    assert params["X"].default == 2.0 and params["TFINAL"].default == 1.0
    assert "X = 2" in m.run.__doc__
    r = m.run()
    assert r.keys() == ["T", "X"]
    assert dict(r.items())["X"] == pytest.approx(
        2 * __import__("numpy").exp(-r["T"]), rel=1e-6
    )
    assert repr(r) == "<Result of CODE Ode decay: 3 rows of T, X>"
    assert repr(r.tables[0]) == "<Table 1: 3 rows of T, X>"
    assert list(r.tables[0]) == ["T", "X"]
    pandas = pytest.importorskip("pandas")
    frame = r.to_pandas()
    assert list(frame.columns) == ["T", "X"] and frame.shape == (3, 2)
    assert pandas.DataFrame(r.tables[0].to_dict())["X"].iloc[-1] == pytest.approx(
        2 * 2.718281828459045**-1, rel=1e-6
    )


def test_to_pandas_without_pandas_says_how_to_get_it(tmp_path, monkeypatch):
    text = (
        "Variables X'\nX' = -X\nInput X = 2, tFinal = 1\nOutput T, X\nCODE ODE() d.c\n"
    )
    m = load_module(convert(text, "d.al").code, tmp_path, "d")
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match="pip install pandas"):
        m.run().to_pandas()


# ------------------------------------------- item 15: transcript fidelity


def test_factor_response_prints_what_factor_produced(tmp_path):
    text = (
        "Constants G, MP, MQ, Q\n"
        "Zero = -G*MP*Sin(Q) - G*MQ*Sin(Q) + MP\n"
        "Factor(Zero, G)\n"
    )
    run = run_module(module(tmp_path, "fac", text), "--no-run")
    responses = [line for line in run.stdout.splitlines() if line.startswith("->")]
    assert responses[-1] == "-> (5) ZERO = MP - G*(MP*SIN(Q)+MQ*SIN(Q))"


# ------------------------------------------------------ item 16: smaller

ALGEBRAIC = """\
Variables X
Constants A
Z = [2*X - A]
Input A = 4
CODE Algebraic(Z, X) alg.c
"""


def test_tfinal_on_a_job_without_time_is_an_error(tmp_path):
    run = run_module(module(tmp_path, "alg", ALGEBRAIC), "--tfinal", "3")
    assert run.returncode == 2
    assert "--tfinal: CODE Algebraic alg.c (line 5) has no time" in run.stderr
    assert run.stdout == ""


def test_plot_of_a_one_point_solution_is_skipped_with_a_reason(tmp_path):
    pytest.importorskip("matplotlib")
    run = run_module(module(tmp_path, "alg", ALGEBRAIC), "--plot")
    assert run.returncode == 0, run.stderr
    assert "X = 2" in run.stdout
    assert "note: no plot: CODE Algebraic alg.c (line 5) solves for one point" in (
        run.stderr
    )
    assert not list(tmp_path.glob("*.png"))


def test_unknown_and_unsupported_commands(tmp_path):
    with pytest.raises(AutolevError) as info:
        convert("Constants A\nB = Sni(A)\n", "x.al")
    assert info.value.message == "unknown function or command 'Sni' (did you mean Sin?)"
    # a longer spelling of a built-in is that built-in, as Autolev read
    # ``inverse(GTran)`` as Inv (docs/semantics.md, "Spellings")
    with pytest.raises(AutolevError) as info:
        convert("Newtonian N\nClear(N)\n", "x.al")
    assert info.value.message.startswith(
        "the Autolev command 'Clear' is not supported by al2py"
    )
    assert "unknown" not in info.value.message
    # Animate is translated (issue 34); its arguments are checked
    with pytest.raises(AutolevError) as info:
        convert("Newtonian N\nAnimate(N)\n", "x.al")
    assert info.value.message == "Animate takes at least 3 arguments, not 1"


def test_long_integration_shows_progress_on_a_terminal(monkeypatch, capsys):
    from al2py_runtime.jobs import budget

    clock = [100.0]
    monkeypatch.setattr(budget.time, "monotonic", lambda: clock[0])
    monkeypatch.setattr(budget, "PROGRESS", True)
    rhs = budget.guard(lambda tt, y: -y, "CODE Ode x.c (line 5)", 0.0, 10.0)
    for i in range(2048):
        clock[0] += 0.01  # 20 s of integration, t from 0 to 2.047
        assert rhs(i / 1000, 1.0) == -1.0
    budget.clear_progress()
    err = capsys.readouterr().err
    assert "\rintegrating: t = 0.255 of 10 (3%)" in err
    assert "\rintegrating: t = 2.047 of 10 (20%)" in err
    assert err.endswith("\r")  # the line is erased at the end
    monkeypatch.setattr(budget, "PROGRESS", False)
    quiet = budget.guard(lambda tt, y: y, "CODE", 0.0, 1.0)
    for _ in range(1024):
        clock[0] += 0.01
        quiet(0.5, 1.0)
    assert capsys.readouterr().err == ""
