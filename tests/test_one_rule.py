"""One rule for each behaviour a user cannot otherwise predict (issue 32):
which job ``run()`` performs, what a value nobody gave is, which files a
run or ``al2py code`` writes, ``NAME=VALUE`` for every program language,
``Fr()`` with no speed in any velocity, a division by a mass nobody gave,
lint-clean modules and a located ``Save`` error.  docs/jobs.md states the
rules; each test here fails on the code before them."""

from __future__ import annotations

import shutil
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from al2py_runtime import AutolevRuntimeError, MissingValueWarning
from al2py_runtime.jobs import backends

from al2py import convert
from al2py.cli import main as al2py_main

ROOT = Path(__file__).resolve().parent.parent
TUTOR6 = ROOT / "examples" / "tutor6.al"
FC = shutil.which("gfortran")
CC = backends.find_compiler()
RUFF = Path(sys.executable).with_name("ruff")

# An ODE job, then an Algebraic job (the shape of Moore's Whipple.al: its
# Dynamics jobs come before CODE Algebraic() WhippleAlgebraic.m).
ODE_THEN_ALGEBRAIC = """\
Variables X'
Constants A
X' = -A*X
Input A=2, X=1, TFINAL=1
Output T, X
CODE ODE() decay.c
Y = 2*X
CODE Algebraic() decayalg.c
"""

# A pendulum-like body whose torque is a Specified quantity no Input gives.
SPECIFIED = """\
Newtonian N
Bodies A
Variables Q'
MotionVariables' U'
Constants K, M
Specified TQ
Mass A = M
Inertia A, 1, 1, 1
Q' = U
Simprot(N, A, 3, Q)
W_A_N> = U*A3>
V_Ao_N> = 0>
Torque_A> = (TQ - K*Q)*A3>
Zero = Fr() + FrStar()
Kane()
Input M = 2, Q = 0.1, U = 0, TFINAL = 1
Output T, Q
CODE Dynamics() spec.c
"""

# Parameters declared as Variables and given no Input (the gait models').
TRUNK = """\
Newtonian N
Bodies TRUNK
Variables Q'
MotionVariables' U'
Variables MT, IT
Constants G
Mass TRUNK = MT
Inertia TRUNK, 0, 0, IT
Q' = U
Simprot(N, TRUNK, 3, Q)
V_TRUNKo_N> = 0>
Torque_TRUNK> = -G*Q*N3>
Zero = Fr() + FrStar()
Kane()
Solve(Zero, U')
Input G = 9.81, Q = 0.1, U = 0
Output Q, U'
CODE Algebraic() trunk.c
"""


def _module(tmp_path, name, text):
    from conftest import load_module

    path = tmp_path / f"{name}.al"
    path.write_text(text)
    return load_module(convert(text, str(path)).code, tmp_path, name)


def _python(tmp_path, name, *args):
    return subprocess.run(
        [sys.executable, str(tmp_path / f"{name}.py"), *args],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )


# ------------------------------------------------------------- which job


def test_run_without_job_performs_the_only_dynamics_job(tmp_path):
    module = _module(tmp_path, "decay", ODE_THEN_ALGEBRAIC)
    result = module.run()  # not the Algebraic job that comes last
    assert result.kind == "ODE" and len(result["T"]) == 101
    assert result["X"][-1] == pytest.approx(np.exp(-2.0), rel=1e-6)
    f, y0, names = module.ode_function()
    assert names == ["X"] and f(0.0, np.array(y0))[0] == pytest.approx(-2.0)
    assert module.run(job="decayalg").kind == "ALGEBRAIC"
    assert module.run(job=2).kind == "ALGEBRAIC"  # by its place


def test_run_without_job_refuses_two_dynamics_jobs_and_lists_them(tmp_path):
    text = ODE_THEN_ALGEBRAIC.replace("Y = 2*X\n", "CODE ODE() decay2.c\n")
    module = _module(tmp_path, "decay", text)
    listed = (
        r"decay.al has 3 CODE jobs, 2 of them Dynamics/ODE; choose one with"
        r" job= \(--job\): decay \(CODE Ode decay.c \(line 6\)\), decay2 \(CODE"
        r" Ode decay2.c \(line 7\)\), decayalg \(CODE Algebraic decayalg.c"
        r" \(line 8\)\)"
    )
    with pytest.raises(AutolevRuntimeError, match=listed):
        module.run()
    with pytest.raises(AutolevRuntimeError, match=listed):
        module.ode_function()
    assert module.run(job="decay2.c").stem == "decay2"
    # python decay.py still performs every job, in script order
    done = _python(tmp_path, "decay", "--outdir", "out")
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        "decay.1",
        "decay2.1",
        "decayalg.1",
    ]


def test_ode_function_of_a_script_without_a_dynamics_job(tmp_path):
    module = _module(
        tmp_path, "alg", ODE_THEN_ALGEBRAIC.replace("ODE()", "Algebraic()")
    )
    with pytest.raises(AutolevRuntimeError, match="no CODE Dynamics or ODE job"):
        module.ode_function()


# ------------------------------------------------- a value nobody gave


def test_evaluate_and_run_take_a_specified_quantity_nobody_gave_as_0(tmp_path):
    module = _module(tmp_path, "spec", SPECIFIED)
    with pytest.warns(MissingValueWarning, match="TQ is Specified with no equation"):
        zero = module.evaluate("ZERO", {"U'": 0}, K=3)
    assert zero[0, 0] == pytest.approx(-0.3)  # TQ - K*Q with TQ = 0
    # a derivative nobody gave is an input too (Autolev's .in files list them)
    with pytest.warns(MissingValueWarning, match="U' has no Input value; using 0"):
        assert module.evaluate("ZERO", K=3)[0, 0] == pytest.approx(-0.3)
    with pytest.warns(MissingValueWarning, match="TQ is Specified"):
        result = module.run(K=3)
    assert any("TQ is Specified" in note for note in result.notes)
    assert result.missing == [n for n in result.notes if "TQ" in n]
    # the same value given: no note
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert module.evaluate("ZERO", {"U'": 0}, K=3, TQ=0.3)[0, 0] == pytest.approx(0)


def test_a_constant_nobody_gave_stops_with_its_name_and_line(tmp_path):
    module = _module(tmp_path, "spec", SPECIFIED)
    with pytest.raises(AutolevRuntimeError, match=r"K \(declared on line 5\)"):
        module.evaluate("ZERO", {"U'": 0})
    with pytest.raises(
        AutolevRuntimeError, match=r"no value for K \(declared on line 5\)"
    ):
        module.run()
    with pytest.warns(MissingValueWarning, match="K has no Input value; using 0"):
        zero = module.evaluate("ZERO", {"U'": 0}, zero_missing=True)
    assert zero[0, 0] == 0


@pytest.mark.skipif(CC is None, reason="no C compiler")
def test_the_c_program_notes_a_specified_quantity_it_takes_as_0(tmp_path, capsys):
    (tmp_path / "spec.al").write_text(SPECIFIED.replace("Input M", "Input K = 3, M"))
    assert al2py_main(["code", str(tmp_path / "spec.al"), "-o", str(tmp_path)]) == 0
    subprocess.run(
        [*CC.split(), "-O2", "-std=c99", "-o", "spec", "spec.c", "-lm"],
        cwd=tmp_path,
        check=True,
    )
    done = subprocess.run(["./spec"], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0
    assert done.stderr == (
        "note: TQ is Specified with no equation and no Input; using 0"
        " (as Autolev's programs do)\n"
    )


# -------------------------------------------------- no file written twice


def test_python_module_names_apart_jobs_that_share_a_stem(tmp_path):
    text = ODE_THEN_ALGEBRAIC.replace("decayalg.c", "decay.m").replace(
        "CODE Algebraic", "CODE ODE"
    )
    module = _module(tmp_path, "decay", text)
    assert [j.stem for j in module.al.numerics.jobs] == ["decay", "decay_2"]
    done = _python(tmp_path, "decay", "--outdir", "out")
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        "decay.1",
        "decay_2.1",
    ]
    assert "note: CODE Ode decay.m (line 8) writes decay_2.1, ..." in done.stderr
    help_text = _python(tmp_path, "decay", "--help").stdout
    assert "  decay_2: CODE Ode decay.m (line 8) -> decay_2.1, ..." in help_text


def test_al2py_code_never_writes_a_file_twice(tmp_path, capsys):
    text = ODE_THEN_ALGEBRAIC.replace("decayalg.c", "decay.m").replace(
        "CODE Algebraic", "CODE ODE"
    )
    (tmp_path / "decay.al").write_text(text)
    out = tmp_path / "f"
    assert (
        al2py_main(["code", "--lang", "f", str(tmp_path / "decay.al"), "-o", str(out)])
        == 0
    )
    captured = capsys.readouterr()
    wrote = [w for w in captured.out.split() if w != "Wrote"]
    assert [Path(w).name for w in wrote] == [
        "decay.f",
        "decay.in",
        "decay_2.f",
        "decay_2.in",
    ]
    assert "is written as decay_2.f" in captured.err
    assert "decay_2.in" in (out / "decay_2.f").read_text()
    # in their own languages the two programs share decay.in (same values)
    own = tmp_path / "own"
    assert al2py_main(["code", str(tmp_path / "decay.al"), "-o", str(own)]) == 0
    captured = capsys.readouterr()
    assert [Path(w).name for w in captured.out.split() if w != "Wrote"] == [
        "decay.c",
        "decay.in",
        "decay.m",
    ]
    assert "reads decay.in, written for CODE Ode decay.c (line 6)" in captured.err


# ------------------------------------------------------ NAME=VALUE overrides


@pytest.mark.skipif(FC is None, reason="gfortran is not installed")
def test_the_fortran_program_takes_name_value_overrides(tmp_path, capsys):
    shutil.copy(TUTOR6, tmp_path / "tutor6.al")
    assert (
        al2py_main(
            ["code", "--lang", "f", str(tmp_path / "tutor6.al"), "-o", str(tmp_path)]
        )
        == 0
    )
    subprocess.run(
        [FC, "-O2", "-Wall", "-o", "tutor6", "tutor6.f"], cwd=tmp_path, check=True
    )
    (tmp_path / "tutor6.in").unlink()  # the script's Inputs, then the arguments
    done = subprocess.run(
        ["./tutor6", "QA=30", "tfinal=0.2"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0, done.stderr
    rows = np.loadtxt(tmp_path / "tutor6.1", comments="%", ndmin=2)
    assert rows[0, 2] == pytest.approx(30.0)  # QA starts at 30 deg, not 20
    assert rows[-1, 0] == pytest.approx(0.2)
    bad = subprocess.run(
        ["./tutor6", "QX=1"], cwd=tmp_path, capture_output=True, text=True
    )
    assert bad.returncode == 2 and "error: QX is not an input; inputs: " in bad.stderr
    bad = subprocess.run(
        ["./tutor6", "QA=ab"], cwd=tmp_path, capture_output=True, text=True
    )
    assert bad.returncode == 2 and "ab is not a number" in bad.stderr


def test_the_matlab_program_takes_name_value_overrides(tmp_path, capsys):
    shutil.copy(TUTOR6, tmp_path / "tutor6.al")
    assert (
        al2py_main(
            ["code", "--lang", "m", str(tmp_path / "tutor6.al"), "-o", str(tmp_path)]
        )
        == 0
    )
    text = (tmp_path / "tutor6.m").read_text()
    assert text.startswith("function tutor6(varargin)\n")
    assert "  v = set_args(names, v, varargin);\n" in text
    assert "'QA'" in text and "function v = set_args(names, v, args)" in text
    octave = shutil.which("octave-cli") or shutil.which("octave")
    if octave is None:
        pytest.skip("GNU Octave is not installed: the program is not run")
    (tmp_path / "tutor6.in").unlink()
    done = subprocess.run(
        [
            octave,
            "-q",
            "--no-gui",
            "--norc",
            "--no-history",
            "--eval",
            "tutor6 QA=30 TFINAL=0.2",
        ],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert done.returncode == 0, done.stderr
    rows = np.loadtxt(tmp_path / "tutor6.1", comments="%", ndmin=2)
    assert rows[0, 2] == pytest.approx(30.0)


# ------------------------------------------------------------------- Fr()


def test_fr_without_a_speed_in_any_velocity_names_the_speed(tmp_path):
    text = (
        "Newtonian N\nBodies A\nMotionVariables th'\nConstants G, L\n"
        "Mass A = 1\nInertia A, 1, 1, 1\nW_A_N> = th'*A3>\nV_Ao_N> = 0>\n"
        "Force_Ao> = G*N1>\nTorque_A> = L*A3>\nZero = Fr()\n"
    )
    with pytest.raises(
        AutolevRuntimeError,
        match=r"fr0.al:11: error: Fr\(\): no velocity or angular velocity"
        r" depends on the generalized speed TH",
    ):
        _module(tmp_path, "fr0", text)
    # with the speed itself the row is the torque
    fine = _module(tmp_path, "fr1", text.replace("th'*A3>", "th*A3>"))
    assert fine.evaluate("ZERO", G=1, L=2)[0, 0] == pytest.approx(2.0)


# ---------------------------------------------- division by a missing mass


def test_a_division_by_a_mass_nobody_gave_names_it(tmp_path):
    module = _module(tmp_path, "trunk", TRUNK)
    with pytest.raises(
        AutolevRuntimeError,
        match=r"Output Q, U' \(line 17\): float division by zero; IT \(Variables,"
        r" line 5\) has no value \(no Input, no equation\) and was taken as 0",
    ):
        module.run()
    dynamics = TRUNK.replace("CODE Algebraic() trunk.c", "CODE Dynamics() trunkd.c")
    explicit = _module(tmp_path, "trunkd", dynamics)  # U' = -G*Q/IT
    with pytest.raises(
        AutolevRuntimeError, match=r"not finite .* at t = 0; IT \(Variables, line 5\)"
    ):
        explicit.run()
    implicit = _module(tmp_path, "trunki", dynamics.replace("Solve(Zero, U')\n", ""))
    with pytest.raises(
        AutolevRuntimeError,
        match=r"coefficient matrix of U' in ZERO is singular at t = 0; IT"
        r" \(Variables, line 5\)",
    ):
        implicit.run()
    with pytest.raises(ValueError, match="MT is a function of time"):
        module.kanes_method()


# ------------------------------------------------------------ lint, Save


@pytest.mark.parametrize("rules", [[], ["--select", "E,F,W,I,B,UP,RUF"]])
def test_generated_module_passes_ruff_defaults_and_project_rules(tmp_path, rules):
    code = convert(TUTOR6.read_text(), str(TUTOR6)).code
    (tmp_path / "tutor6.py").write_text(code)
    done = subprocess.run(
        [
            str(RUFF),
            "check",
            "--isolated",
            *rules,
            "--ignore",
            "E501",
            "--output-format",
            "concise",
            "tutor6.py",
        ],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stdout
    project = subprocess.run(
        [
            str(RUFF),
            "check",
            "--config",
            str(ROOT / "pyproject.toml"),
            "--output-format",
            "concise",
            str(tmp_path / "tutor6.py"),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert project.returncode == 0, project.stdout


def test_a_save_file_the_system_refuses_names_its_line(tmp_path):
    long = "a" * 300
    text = f"Variables X'\nX' = 1\nInput X=0, TFINAL=1\nSave {long}.all\n"
    (tmp_path / "longsave.al").write_text(text)
    (tmp_path / "longsave.py").write_text(convert(text, "longsave.al").code)
    done = _python(tmp_path, "longsave", "--outdir", "out")
    assert done.returncode == 2
    assert done.stderr.startswith(
        f"longsave.al:4: error: Save {long}.all: cannot write"
    )
    assert "Traceback" not in done.stderr
