"""``al2py code``: the C, Fortran and MATLAB/Octave programs of CODE jobs
read ``STEM.in`` (values from column 60) and write the tables ``run()``
writes; NOSUBS writes the equations only; ``run(job=...)`` picks a job."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest
from al2py_runtime.jobs import backends
from conftest import SHARED
from test_codegen_c import _pendulum_source, _same_tables

from al2py.cli import main as al2py_main

CC = backends.find_compiler()
FC = shutil.which("gfortran")
OCTAVE = shutil.which("octave-cli") or shutil.which("octave")
needs = {
    "c": pytest.mark.skipif(CC is None, reason="no C compiler (cc, gcc, clang or $CC)"),
    "f": pytest.mark.skipif(
        FC is None,
        reason="gfortran is not installed (Debian: apt-get install gfortran)",
    ),
    "m": pytest.mark.skipif(
        OCTAVE is None,
        reason="GNU Octave is not installed (Debian: apt-get install octave)",
    ),
}
LANGS = [pytest.param(lang, marks=needs[lang]) for lang in ("c", "f", "m")]


def _code(script, outdir, capsys, *options) -> list[str]:
    assert al2py_main(["code", *options, str(script), "-o", str(outdir)]) == 0
    return capsys.readouterr().out.split()


def _run(lang, folder, stem, timeout=600) -> subprocess.CompletedProcess:
    """Build (quietly: any warning fails) and run ``stem`` in ``folder``."""
    if lang == "c":
        cmd = [*CC.split(), "-O2", "-std=c99", "-Wall", "-Wextra", "-o", stem]
        build = [*cmd, f"{stem}.c", "-lm"]
    elif lang == "f":
        build = [FC, "-O2", "-Wall", "-o", stem, f"{stem}.f"]
    else:
        build = None
    if build:
        done = subprocess.run(build, cwd=folder, capture_output=True, text=True)
        assert done.returncode == 0 and done.stderr == "", done.stderr
        run = [f"./{stem}"]
    else:
        # --no-history: Octave 7 may fail writing its history file at exit
        run = [OCTAVE, "-q", "--no-gui", "--norc", "--no-history", "--eval", stem]
    done = subprocess.run(
        run, cwd=folder, capture_output=True, text=True, timeout=timeout
    )
    assert done.returncode == 0, done.stdout + done.stderr
    # no warnings; notes of values taken as 0 (docs/jobs.md) are not ones
    noise = [ln for ln in done.stderr.splitlines() if not ln.startswith("note: ")]
    assert noise == [], done.stderr
    return done


def _set_in(path, values: dict) -> None:
    """Change values in a ``.in`` file in place (from column 60)."""
    lines = path.read_text().splitlines()
    for i, line in enumerate(lines):
        name = line[21:41].strip()
        if len(line) >= 60 and line[58] == "|" and name in values:
            lines[i] = line[:59] + f" {values[name]!r}"
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("lang", LANGS)
def test_tutor6_in_each_language_matches_run(lang, tmp_path, capsys, tutorial):
    shutil.copy(SHARED / "tutor6.al", tmp_path / "tutor6.al")
    printed = _code(tmp_path / "tutor6.al", tmp_path, capsys, "--lang", lang)
    suffix = {"c": ".c", "f": ".f", "m": ".m"}[lang]
    assert printed == [
        "Wrote",
        str(tmp_path / f"tutor6{suffix}"),
        "Wrote",
        str(tmp_path / "tutor6.in"),
    ]
    # Tight tolerances through the .in file: both integrators then agree
    # to 1e-8 of each column, whatever their step sizes.
    _set_in(
        tmp_path / "tutor6.in",
        {"ABSERR": 1e-11, "RELERR": 1e-11, "QA": 30.0, "TFINAL": 5.0},
    )
    done = _run(lang, tmp_path, "tutor6")
    assert "Wrote tutor6.1" in done.stdout
    result = tutorial("tutor6").run(ABSERR=1e-11, RELERR=1e-11, QA=30, TFINAL=5)
    assert len(result["T"]) == 26
    _same_tables(result, tmp_path, rtol=1e-7, atol=1e-8)


@pytest.mark.parametrize("lang", LANGS)
def test_eight_link_pendulum_in_each_language_matches_run(
    lang, tmp_path, capsys, convert_and_import
):
    script = tmp_path / "pendulum8.al"
    script.write_text(_pendulum_source(8))
    _code(script, tmp_path, capsys, "--lang", lang)
    # chaotic: over 2 s both integrators stay close
    _set_in(tmp_path / "pendulum8.in", {"TFINAL": 2.0})
    _run(lang, tmp_path, "pendulum8")
    module, _ = convert_and_import(script)
    result = module.run(TFINAL=2)
    assert len(result["T"]) == 21
    _same_tables(result, tmp_path, rtol=1e-5, atol=1e-5)


@needs["c"]
@needs["f"]
def test_the_same_in_file_through_c_and_fortran(tmp_path, capsys):
    script = tmp_path / "pendulum3.al"
    script.write_text(_pendulum_source(3))
    for lang in ("c", "f"):
        _code(script, tmp_path / lang, capsys, "--lang", lang)
    _set_in(tmp_path / "c" / "pendulum3.in", {"TFINAL": 3.0, "PRINTINT": 2})
    shutil.copy(tmp_path / "c" / "pendulum3.in", tmp_path / "f")
    for lang in ("c", "f"):
        _run(lang, tmp_path / lang, "pendulum3")
    a = np.loadtxt(tmp_path / "c" / "pendulum3.1", comments="%")
    b = np.loadtxt(tmp_path / "f" / "pendulum3.1", comments="%")
    assert a.shape[0] == 16  # a row every 2 steps of 0.1 s over 3 s
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12)
    assert a[:, 0] == pytest.approx(np.arange(16) * 0.2)


def test_in_file_layout(tmp_path, capsys):
    shutil.copy(SHARED / "tutor6.al", tmp_path / "tutor6.al")
    _code(tmp_path / "tutor6.al", tmp_path, capsys)
    lines = (tmp_path / "tutor6.in").read_text().splitlines()
    body = lines[6:]
    groups, group = [], []
    for line in body:
        if not line:
            groups.append(group)
            group = []
        elif line[58:59] == "|":
            group.append((line[:21].strip(), line[21:41].strip(), float(line[59:])))
        else:
            break
    assert [len(g) for g in groups] == [9, 5, 6]
    # Autolev's order: each group sorted without case (WhippleDynamics.c
    # reads c, g, IBxx, IBxz, ..., lam, mB, ...)
    assert [g[1] for g in groups[0]] == [
        "C",
        "D",
        "G",
        "K",
        "LA",
        "LB",
        "LO",
        "MP",
        "MQ",
    ]
    assert groups[0][0] == ("Constant", "C", 300.0)
    assert [g[1] for g in groups[1]][1:] == ["QA", "QB", "U1", "U2"]
    assert ("Initial Value", "QA", 20.0) in groups[1]
    assert ("Initial Value", "QB", 60.0) in groups[1]  # as the Input says
    assert [g[1] for g in groups[2]] == [
        "TINITIAL",
        "TFINAL",
        "INTEGSTP",
        "PRINTINT",
        "ABSERR",
        "RELERR",
    ]
    assert groups[2][1][2] == 20.0 and groups[2][3][2] == 1.0


@needs["c"]
def test_help_shows_the_values_used(tmp_path, capsys):
    script = tmp_path / "decay.al"
    script.write_text(
        "Variables X'\nX' = -X\nInput X=1\nOutput T, X\nCODE ODE() decay.c\n"
    )
    _code(script, tmp_path, capsys)
    text = (tmp_path / "decay.in").read_text()
    assert "nan" not in text.lower()
    exe = tmp_path / "decay"
    subprocess.run(
        [*CC.split(), "-std=c99", "-o", str(exe), str(exe) + ".c", "-lm"], check=True
    )
    done = subprocess.run([str(exe), "--help"], capture_output=True, text=True)
    assert "TFINAL = 10\n" in done.stdout and "INTEGSTP = 0.1\n" in done.stdout
    assert "PRINTINT = 1\n" in done.stdout and "nan" not in done.stdout.lower()


def test_every_code_statement_is_written(tmp_path, capsys):
    script = tmp_path / "two.al"
    script.write_text(
        "Variables X'\nConstants A\nX' = -A*X\nInput A=2, X=1, TFINAL=1\n"
        "Output T, X\nCODE ODE() twoc.c\nCODE ODE() twom.m\nCODE ODE() twof.for\n"
        "CODE ODE() twon.c, NOSUBS\n"
    )
    printed = _code(script, tmp_path, capsys)
    names = sorted(p.name for p in tmp_path.iterdir() if p.name != "two.al")
    assert names == [
        "twoc.c",
        "twoc.in",
        "twof.for",
        "twof.in",
        "twom.in",
        "twom.m",
        "twon.c",
    ]
    assert printed.count("Wrote") == 7
    nosubs = (tmp_path / "twon.c").read_text()
    assert "int main" not in nosubs and "int eqns(" in nosubs
    assert "al2py" in nosubs.splitlines()[0] and "two.al" in nosubs.splitlines()[0]


def _oscillator(folder, capsys, target) -> None:
    """X'' = -K X with K = 4, written with NOSUBS into ``target``."""
    script = folder / "osc.al"
    script.write_text(
        "Variables X''\nConstants K\nX'' = -K*X\nInput K=4, X=1, X'=0\n"
        f"Output T, X\nCODE ODE() {target}, NOSUBS\n"
    )
    _code(script, folder, capsys)


@needs["c"]
def test_nosubs_c_equations_link_with_a_driver(tmp_path, capsys):
    _oscillator(tmp_path, capsys, "osc.c")
    (tmp_path / "drive.c").write_text(
        "#include <stdio.h>\n"
        "int eqns(double, const double[], const double[], double[], double[]);\n"
        "int main(void) { double y[2] = {0.5, 0.25}, p[1] = {4.0}, dy[2], ud[1];\n"
        '  eqns(0.0, y, p, dy, ud); printf("%.17g %.17g\\n", dy[0], dy[1]);'
        " return 0; }\n"
    )
    subprocess.run(
        [
            *CC.split(),
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-o",
            "drive",
            "drive.c",
            "osc.c",
            "-lm",
        ],
        cwd=tmp_path,
        check=True,
    )
    out = subprocess.run(["./drive"], cwd=tmp_path, capture_output=True, text=True)
    assert [float(x) for x in out.stdout.split()] == [0.25, -2.0]  # X', X''=-K X


@needs["m"]
def test_nosubs_matlab_function_gives_the_derivatives(tmp_path, capsys):
    _oscillator(tmp_path, capsys, "oscm.m")
    done = subprocess.run(
        [
            OCTAVE,
            "-q",
            "--norc",
            "--no-history",
            "--eval",
            "[dy, out] = oscm(0, [0.5; 0.25], 4); printf('%.17g ', dy, out)",
        ],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.stderr == "", done.stderr
    assert [float(x) for x in done.stdout.split()] == [0.25, -2.0, 0.0, 0.5]


def test_run_and_ode_function_pick_a_job_by_name(tmp_path, convert_and_import):
    script = tmp_path / "jobs.al"
    script.write_text(
        "Variables X'\nConstants A\nX' = -A*X\nInput A=2, X=1, TFINAL=1\n"
        "Output T, X\nCODE ODE() first.c\nCODE ODE() second.c\n"
    )
    module, _ = convert_and_import(script)
    with pytest.raises(Exception, match="2 CODE jobs, 2 of them Dynamics/ODE"):
        module.run()  # two jobs the user may mean: named, not guessed
    assert module.run(job="FIRST").stem == "first"
    f, y0, names = module.ode_function(job="first")
    assert names == ["X"] and f(0.0, np.array(y0))[0] == pytest.approx(-2.0)
    with pytest.raises(
        Exception,
        match=r"no CODE job 'third'; jobs: first \(CODE Ode first.c \(line 6\)\),"
        r" second \(CODE Ode second.c \(line 7\)\)",
    ):
        module.run(job="third")
    done = subprocess.run(
        [
            __import__("sys").executable,
            str(module.__file__),
            "--job",
            "first",
            "--outdir",
            str(tmp_path / "o"),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "o" / "first.1").exists() and not (
        tmp_path / "o" / "second.1"
    ).exists()
    helptext = subprocess.run(
        [__import__("sys").executable, str(module.__file__), "--help"],
        capture_output=True,
        text=True,
        timeout=300,
    ).stdout
    assert "--job STEM" in helptext and "first: CODE Ode first.c" in helptext


# Constants declared out of order, a Specified TQ with neither equation nor
# Input, a Specified FZ with an Input, and a second-order variable.
IN_ORDER = """\
Newtonian N
Bodies A
Constants Kb, a2, A10, A1
Specified TQ, Fz
Variables Y'', Q'
MotionVariables' U'
Mass A = a2
Inertia A, 0, 0, A1
Simprot(N, A, 3, Q)
Q' = U
Y'' = -Kb*Y
Angvel(N, A)
P_NO_AO> = 0>
V_AO_N> = 0>
A_AO_N> = 0>
Torque(N/A, (TQ - A10*U + Fz)*N3>)
Zero = Fr() + FrStar()
Solve(Zero, U')
Input Kb = 2, a2 = 1, A10 = 0.5, A1 = 3, Fz = 0.25, Q = 0.1, Y = 1
Input TFINAL = 2, INTEGSTP = 0.1, ABSERR = 1e-11, RELERR = 1e-11
Output T, Q, U, Y
Code Dynamics() inorder.c
"""


@needs["c"]
def test_in_file_order_and_unspecified_quantities(tmp_path, capsys):
    """Autolev's order (PendulumDynamics.c reads g, i, l, m and omega, theta;
    WhippleDynamics.c c, g, IBxx, ...): each group sorted without case,
    derivatives after names; a Specified without equation or Input is 0 in
    the program ("Quantities to be specified"), not a line of the .in."""
    from al2py import convert

    script = tmp_path / "inorder.al"
    script.write_text(IN_ORDER)
    _code(script, tmp_path, capsys)
    names = [
        line[21:41].strip()
        for line in (tmp_path / "inorder.in").read_text().splitlines()[6:]
        if line[58:59] == "|"
    ]
    # A2 (the mass) does not enter the rotor's equations: not read
    assert names[:8] == ["A1", "A10", "FZ", "KB", "Q", "U", "Y", "Y'"]
    source = (tmp_path / "inorder.c").read_text()
    assert "const double TQ = 0;" in source and '"TQ"' not in source
    done = _run("c", tmp_path, "inorder")
    assert done.stderr == (  # and it says so (docs/jobs.md)
        "note: TQ is Specified with no equation and no Input; using 0"
        " (as Autolev's programs do)\n"
    )
    ours = np.loadtxt(tmp_path / "inorder.1", comments="%")
    code = convert(IN_ORDER, str(script)).code
    from conftest import load_module

    result = load_module(code, tmp_path, "inorder_mod").run()
    theirs = np.column_stack([result[k] for k in ("T", "Q", "U", "Y")])
    np.testing.assert_allclose(ours, theirs, rtol=1e-5, atol=1e-8)


@needs["f"]
def test_long_fortran_routines_in_parts_run_the_same(tmp_path, capsys, monkeypatch):
    """Routines over fortran.PART_LINES lines are written as subroutines
    called in turn (issue 35: gfortran -O2 took 36 s on the bicycle's
    7,700-line outputs routine); the program reads the same .in and writes
    the same bytes, and compiles without a warning."""
    from al2py_runtime.codegen import fortran

    script = tmp_path / "pendulum3.al"
    script.write_text(_pendulum_source(3))
    _code(script, tmp_path / "whole", capsys, "--lang", "f")
    monkeypatch.setattr(fortran, "PART_LINES", 2)
    _code(script, tmp_path / "parts", capsys, "--lang", "f")
    whole = (tmp_path / "whole" / "pendulum3.f").read_text()
    parts = (tmp_path / "parts" / "pendulum3.f").read_text()
    assert "subroutine aleq1" not in whole and "subroutine alout1" not in whole
    for name in ("aleq1", "aleq2", "aleq3", "alout1", "alout2"):
        assert f"      subroutine {name}(" in parts
    # the solve of M ud = f sits in a part, which returns its code
    assert "ierr)\n      if (ierr .ne. 0) return\n      call aleq" in parts
    infile = (tmp_path / "whole" / "pendulum3.in").read_text()
    assert (tmp_path / "parts" / "pendulum3.in").read_text() == infile
    for folder in ("whole", "parts"):
        _set_in(tmp_path / folder / "pendulum3.in", {"TFINAL": 2.0})
        _run("f", tmp_path / folder, "pendulum3")
    tables = sorted(p.name for p in (tmp_path / "whole").glob("pendulum3.[0-9]"))
    assert tables == ["pendulum3.1"]
    assert (
        sorted(p.name for p in (tmp_path / "parts").glob("pendulum3.[0-9]")) == tables
    )
    a = (tmp_path / "whole" / "pendulum3.1").read_bytes()
    assert (
        len(a.splitlines()) > 20
        and a == (tmp_path / "parts" / "pendulum3.1").read_bytes()
    )
