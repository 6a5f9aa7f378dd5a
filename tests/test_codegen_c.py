"""``al2py code``: the C program of a CODE Dynamics job compiles without
warnings and writes the tables ``run()`` writes."""

from __future__ import annotations

import importlib.util
import shutil
import subprocess
import sys

import numpy as np
import pytest
from al2py_runtime.jobs import backends
from conftest import ROOT, SHARED

from al2py.cli import main as al2py_main

CC = backends.find_compiler()
pytestmark = pytest.mark.skipif(
    CC is None, reason="no C compiler (cc, gcc, clang or $CC) to build the C code"
)


def _pendulum_source(n: int) -> str:
    spec = importlib.util.spec_from_file_location(
        "_bench_pendulum", ROOT / "benchmarks" / "pendulum.py"
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.autolev_source(n)


def _build(script, outdir, capsys) -> list:
    """``al2py code SCRIPT -o OUTDIR`` then ``cc -Wall``; returns the programs."""
    return _build_with([], script, outdir, capsys)


def _build_with(options, script, outdir, capsys) -> list:
    assert al2py_main(["code", *options, str(script), "-o", str(outdir)]) == 0
    printed = capsys.readouterr().out.split()
    sources = sorted(outdir.glob("*.c"))
    assert sources and all(str(s) in printed for s in sources)
    programs = []
    for source in sources:
        exe = source.with_suffix("")
        build = subprocess.run(
            [*CC.split(), "-O2", "-std=c99", "-Wall", "-Wextra", "-o", str(exe)]
            + [str(source), "-lm"],
            capture_output=True,
            text=True,
            timeout=600,
        )
        assert build.returncode == 0, build.stderr
        assert build.stderr == "", build.stderr  # no warnings
        programs.append(exe)
    return programs


def _run_c(program, workdir, *args) -> subprocess.CompletedProcess:
    return subprocess.run(
        [str(program), *args], cwd=workdir, capture_output=True, text=True, timeout=600
    )


def _same_tables(result, workdir, rtol, atol) -> None:
    expected = workdir / "py"
    result.write(expected)
    for name in result.files():
        ours = (workdir / name).read_text().splitlines()
        theirs = (expected / name).read_text().splitlines()
        assert ours[:5] == theirs[:5]  # the same header, character for character
        a = np.loadtxt(workdir / name, comments="%", ndmin=2)
        b = np.loadtxt(expected / name, comments="%", ndmin=2)
        assert a.shape == b.shape
        assert np.all(np.abs(a - b) <= np.asarray(atol) + rtol * np.abs(b)), abs(
            a - b
        ).max(0)


@pytest.fixture
def tutor6_program(tmp_path, capsys):
    shutil.copy(SHARED / "tutor6.al", tmp_path / "tutor6.al")
    (program,) = _build(tmp_path / "tutor6.al", tmp_path / "c", capsys)
    assert program.name == "tutor6"  # the name CODE Dynamics() tutor6.c gives
    return program


def test_tutor6_program_writes_the_table_run_writes(tutor6_program, tutorial):
    workdir = tutor6_program.parent
    done = _run_c(tutor6_program, workdir)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "Wrote tutor6.1"
    result = tutorial("tutor6").run()
    # Two integrators with absErr = relErr = 1e-7 over 20 s: T exactly, the
    # stretch (m) to 1e-5, angles (deg) to 1e-3, the energy check (itself
    # integration error, about 1e-6 J) to 1e-5.
    _same_tables(result, workdir, rtol=0, atol=[0, 1e-5, 1e-3, 1e-3, 1e-5])
    a = np.loadtxt(workdir / "tutor6.1", comments="%")
    assert a[-1, 2] == pytest.approx(50.123, abs=5e-4)
    assert np.ptp(a[:, 4]) < 1e-4


def test_tutor6_program_with_tight_tolerances_and_overrides(tutor6_program, tutorial):
    workdir = tutor6_program.parent
    values = {"ABSERR": 1e-11, "RELERR": 1e-11, "QA": 30, "TFINAL": 5}
    done = _run_c(tutor6_program, workdir, *(f"{k}={v}" for k, v in values.items()))
    assert done.returncode == 0, done.stderr
    result = tutorial("tutor6").run(values)
    assert float(result["QA"][0]) == pytest.approx(30) and len(result["T"]) == 26
    _same_tables(result, workdir, rtol=1e-8, atol=1e-8)


def test_tutor6_program_rejects_unknown_names(tutor6_program):
    done = _run_c(tutor6_program, tutor6_program.parent, "NOPE=1")
    assert done.returncode == 2
    assert "NOPE is not an input; inputs: C D G K LA LB" in done.stderr
    done = _run_c(tutor6_program, tutor6_program.parent, "QA=abc")
    assert done.returncode == 2 and "'abc' is not a number" in done.stderr
    done = _run_c(tutor6_program, tutor6_program.parent, "--help")
    assert done.returncode == 0 and "QA = 20" in done.stdout


def test_eight_link_pendulum_program_matches_run(tmp_path, capsys, convert_and_import):
    script = tmp_path / "pendulum8.al"
    script.write_text(_pendulum_source(8))
    (program,) = _build(script, tmp_path, capsys)
    # A chaotic system: compare over 2 s, where both integrators stay close.
    done = _run_c(program, tmp_path, "TFINAL=2")
    assert done.returncode == 0, done.stderr
    module, _ = convert_and_import(script)
    result = module.run(TFINAL=2)
    assert len(result["T"]) == 21
    _same_tables(result, tmp_path, rtol=1e-5, atol=1e-5)


def test_lang_c_and_a_nonlinear_job(tmp_path, capsys):
    script = tmp_path / "odes.al"
    script.write_text(
        "Variables X'\nX' = -X\nInput X=1\nOutput T, X\nCODE ODE() odes.m\n"
    )
    # --lang c writes C whatever the extension; the program solves X' = -X.
    (program,) = _build_with(["--lang", "c"], script, tmp_path / "c", capsys)
    done = _run_c(program, program.parent, "TFINAL=1")
    assert done.returncode == 0, done.stderr
    table = np.loadtxt(program.parent / "odes.1", comments="%")
    assert table[-1] == pytest.approx([1.0, np.exp(-1.0)], rel=1e-6)
    script.write_text(
        "Variables X\nConstants A\nE[1] = X^2 - A\nInput A=4, X=1\n"
        "CODE Nonlinear(E, X) roots.c\n"
    )
    (program,) = _build_with([], script, tmp_path / "n", capsys)
    done = _run_c(program, program.parent)
    assert done.returncode == 0, done.stderr
    assert np.loadtxt(program.parent / "roots.1", comments="%") == pytest.approx(2)
    done = _run_c(program, program.parent, "X=-3")  # another guess, another root
    assert np.loadtxt(program.parent / "roots.1", comments="%") == pytest.approx(-2)


def test_script_without_code_statement(tmp_path, capsys):
    script = tmp_path / "none.al"
    script.write_text("Constants A\nB = A + 1\n")
    assert al2py_main(["code", str(script)]) == 2
    assert "has no CODE statement" in capsys.readouterr().err


def test_script_errors_are_reported_with_location(tmp_path, capsys):
    script = tmp_path / "bad.al"
    script.write_text("Variables X'\nX' = -Y +\n")
    assert al2py_main(["code", str(script)]) == 2
    assert "bad.al:2:" in capsys.readouterr().err


def test_code_subcommand_help_lists_languages():
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "code", "--help"],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0
    assert "MATLAB/Octave" in run.stdout and "NOSUBS" in run.stdout


def test_module_emit_code_writes_the_same_program(tutor6_program, tmp_path):
    from al2py import convert

    code = convert((SHARED / "tutor6.al").read_text(), str(SHARED / "tutor6.al")).code
    (tmp_path / "tutor6.py").write_text(code)
    run = subprocess.run(
        [sys.executable, "tutor6.py", "--emit-code", "emitted"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == [
        "Wrote",
        "emitted/tutor6.c",
        "Wrote",
        "emitted/tutor6.in",
    ]
    ours = (tmp_path / "emitted" / "tutor6.c").read_text().splitlines()
    theirs = tutor6_program.with_suffix(".c").read_text().splitlines()
    assert ours[1:] == theirs[1:]  # the first line names the source file
    assert not (tmp_path / "tutor6.1").exists()  # nothing was run


def test_every_function_printer_hoists():
    """Each printing method of a sympy function is written in ``CPrinter``'s
    body through ``_hoisting`` (none attached at import, none missing after
    a sympy upgrade adds one)."""
    import sympy as sp

    wrapped = {
        attr
        for attr in dir(backends.CPrinter)
        if attr.startswith("_print_")
        and isinstance(getattr(sp, attr[len("_print_") :], None), type)
        and issubclass(getattr(sp, attr[len("_print_") :]), sp.Function)
    }
    assert "_print_sin" in wrapped and "_print_Function" in wrapped
    for attr in sorted(wrapped):
        assert attr in backends.CPrinter.__dict__, attr
        assert getattr(backends.CPrinter, attr).__qualname__.startswith("_hoisting")


def test_hoisted_calls_are_kept_once():
    """A call of the hoisted symbols alone (sympy's ``sin`` and our own
    ``sign``) is printed once and kept in ``z``; others stay in place."""
    import sympy as sp

    x, y = sp.symbols("x y")
    printer = backends.CPrinter(hoist=({x}, 10))
    text = printer.doprint(
        sp.sin(x) * sp.cos(y) + sp.sin(x) ** 5 + sp.sign(x) + sp.exp(x + y)
    )
    assert text == "pow(z[10], 5) + cos(y)*z[10] + exp(x + y) + z[11]"
    assert printer.hoisted == {
        "sin(x)": "z[10]",
        "(double)((((x) > 0) - ((x) < 0)))": "z[11]",
    }
