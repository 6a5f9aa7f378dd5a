"""``CODE Algebraic`` and ``CODE Nonlinear`` programs in C, Fortran and
MATLAB/Octave: they read ``STEM.in`` and write the tables ``run()`` writes
(tutor2's range, tutor4's and tutor5's equilibria, the tutorial's katy)."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import SHARED
from test_codegen_c import _same_tables
from test_codegen_targets import CC, LANGS, _code, _run, _set_in, needs

ROOT = Path(__file__).resolve().parent.parent

SUFFIX = {"c": ".c", "f": ".f", "m": ".m"}


def _program(name, lang, folder, capsys) -> None:
    shutil.copy(SHARED / f"{name}.al", folder / f"{name}.al")
    printed = _code(folder / f"{name}.al", folder, capsys, "--lang", lang)
    assert printed == [
        "Wrote",
        str(folder / f"{name}{SUFFIX[lang]}"),
        "Wrote",
        str(folder / f"{name}.in"),
    ]


@pytest.mark.parametrize("lang", LANGS)
def test_tutor2_algebraic_range_matches_run(lang, tmp_path, capsys, tutorial):
    _program("tutor2", lang, tmp_path, capsys)
    text = (tmp_path / "tutor2.in").read_text()
    assert "Range Step           PHI                  deg             | 1.0" in text
    done = _run(lang, tmp_path, "tutor2")
    assert "Wrote tutor2.1" in done.stdout
    result = tutorial("tutor2").run()
    assert len(result["PHI"]) == 361
    _same_tables(result, tmp_path, rtol=1e-9, atol=1e-12)
    table = np.loadtxt(tmp_path / "tutor2.1", comments="%")
    assert table[[0, -1], 0] == pytest.approx([0, 360])  # degrees, as Output says


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", ["tutor4", "tutor5"])
def test_nonlinear_equilibria_match_run(name, lang, tmp_path, capsys, tutorial):
    _program(name, lang, tmp_path, capsys)
    _run(lang, tmp_path, name)
    result = tutorial(name).run()
    _same_tables(result, tmp_path, rtol=1e-9, atol=1e-9)
    if name == "tutor4":  # the tutorial's answer
        row = np.loadtxt(tmp_path / "tutor4.1", comments="%")
        assert row == pytest.approx([-50.1492, 35.1548], abs=1e-4)


@needs["c"]
@needs["f"]
def test_the_same_in_file_through_c_and_fortran(tmp_path, capsys, tutorial):
    """katy with other constants and guesses, edited in katy.in."""
    for lang in ("c", "f"):
        (tmp_path / lang).mkdir()
        shutil.copy(SHARED / "katy.al", tmp_path / lang / "katy.al")
        _code(tmp_path / lang / "katy.al", tmp_path / lang, capsys, "--lang", lang)
    values = {"A": 2.0, "R": 3.0, "X": -1.0, "Y": -1.0}
    _set_in(tmp_path / "c" / "katy.in", values)
    shutil.copy(tmp_path / "c" / "katy.in", tmp_path / "f" / "katy.in")
    for lang in ("c", "f"):
        _run(lang, tmp_path / lang, "katy")
    a = np.loadtxt(tmp_path / "c" / "katy.1", comments="%")
    b = np.loadtxt(tmp_path / "f" / "katy.1", comments="%")
    np.testing.assert_allclose(a, b, rtol=1e-12)
    x, y = a
    assert x**2 + y**2 == pytest.approx(3.0) and y == pytest.approx(2 * np.sin(x))
    result = tutorial("katy").run(values)
    assert a == pytest.approx([result["X"][0], result["Y"][0]], rel=1e-6)


@needs["c"]
def test_no_solution_names_the_code_line(tmp_path, capsys):
    shutil.copy(SHARED / "katy.al", tmp_path / "katy.al")
    _code(tmp_path / "katy.al", tmp_path, capsys, "--lang", "c")
    _set_in(tmp_path / "katy.in", {"R": -1.0})  # x^2 + y^2 = -1: no root
    exe = tmp_path / "katy"
    cmd = [*CC.split(), "-std=c99", "-o", str(exe), str(exe) + ".c", "-lm"]
    subprocess.run(cmd, check=True)
    done = subprocess.run([str(exe)], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 2
    assert done.stderr.startswith(
        "error: CODE Nonlinear katy.m (line 10): no solution found from the"
        " guesses in katy.in: |EQN[1]| = "
    ), done.stderr
    assert not (tmp_path / "katy.1").exists()


@needs["c"]
def test_singular_algebraic_equations_stop_with_the_code_line(tmp_path, capsys):
    shutil.copy(SHARED / "becky.al", tmp_path / "becky.al")
    _code(tmp_path / "becky.al", tmp_path, capsys, "--lang", "c")
    exe = tmp_path / "becky"
    cmd = [*CC.split(), "-std=c99", "-o", str(exe), str(exe) + ".c", "-lm"]
    subprocess.run(cmd, check=True)
    done = subprocess.run([str(exe)], cwd=tmp_path, capture_output=True, text=True)
    assert done.returncode == 0
    assert np.loadtxt(tmp_path / "becky.1", comments="%") == pytest.approx([-4, 4.5])
    done = subprocess.run(
        [str(exe), "A21=2", "A22=4"], cwd=tmp_path, capture_output=True, text=True
    )
    assert done.returncode == 2
    assert done.stderr == (
        "error: CODE Algebraic becky.for (line 9): the equations are singular"
        " (no unique solution)\n"
    )


def test_every_code_statement_of_a_script_is_written(tmp_path, capsys):
    script = tmp_path / "all.al"
    script.write_text(
        "Variables X, Y, Z'\nConstants A, B\nE[1] = X + Y - A\nE[2] = X - Y - B\n"
        "N[1] = X^2 - A\nZ' = -A*Z\nInput A=4, B=2, X=1, Y=0, Z=1, TFINAL=1\n"
        "CODE Algebraic(E, X, Y) alg.c\nCODE Algebraic(E, X, Y) algm.m, NOSUBS\n"
        "CODE Nonlinear(N, X) non.m\nCODE Nonlinear(N, X) nonf.for\n"
        "Output T, Z\nCODE ODE() ode.c\n"
    )
    from al2py.cli import main as al2py_main

    assert al2py_main(["code", str(script), "-o", str(tmp_path)]) == 0
    printed = capsys.readouterr()
    assert "not" not in printed.err and printed.err == ""
    names = sorted(p.name for p in tmp_path.iterdir() if p.name != "all.al")
    expected = "alg.c alg.in algm.m non.in non.m nonf.for nonf.in ode.c ode.in"
    assert names == expected.split()  # NOSUBS: no algm.in
    assert printed.out.count("Wrote") == 9
    for name in ("alg.c", "non.m", "nonf.for", "algm.m"):
        head = " ".join((tmp_path / name).read_text().splitlines()[:3])
        assert "generated by al2py" in head and "all.al" in head, head
    assert "function" in (tmp_path / "algm.m").read_text().splitlines()[0]


@needs["c"]
def test_nosubs_nonlinear_c_gives_residuals_and_newton_step(tmp_path, capsys):
    script = tmp_path / "circle.al"
    script.write_text(
        "Variables X, Y\nConstants A\nE[1] = X^2 + Y^2 - A\nE[2] = Y - X\n"
        "Input A=2, X=2, Y=1\nCODE Nonlinear(E, X, Y) circle.c, NOSUBS\n"
    )
    _code(script, tmp_path, capsys)
    assert not (tmp_path / "circle.in").exists()
    (tmp_path / "drive.c").write_text(
        "#include <stdio.h>\n"
        "int eqns(double, const double[], const double[], double[], double[]);\n"
        "int main(void) { double y[2] = {2.0, 1.0}, p[1] = {2.0}, f[2], dx[2];\n"
        "  int code = eqns(0.0, y, p, f, dx);\n"
        '  printf("%d %.17g %.17g %.17g %.17g\\n", code, f[0], f[1], dx[0], dx[1]);'
        " return 0; }\n"
    )
    build = [*CC.split(), "-std=c99", "-Wall", "-Wextra", "-o", "drive"]
    done = subprocess.run(
        [*build, "drive.c", "circle.c", "-lm"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
    )
    assert done.returncode == 0 and done.stderr == "", done.stderr
    out = subprocess.run(["./drive"], cwd=tmp_path, capture_output=True, text=True)
    code, *values = out.stdout.split()
    f = np.array([3.0, -1.0])  # 4 + 1 - 2, 1 - 2
    jac = np.array([[4.0, 2.0], [-1.0, 1.0]])
    assert code == "0"
    assert [float(v) for v in values] == pytest.approx([*f, *np.linalg.solve(jac, -f)])


# Variables declared before the constants and named so that sorting all
# names together would mix them: Autolev's Algebraic programs read the
# constants, then the variables, then their derivatives (BioMAC's
# gait2d_osim_NoDer_raw.c: par__..., G1 .. G6, q1 .., q1p ..).  The CODE
# file is named with a Windows path, as BioMAC's gait10dof18musc scripts do.
ALG_ORDER = """\
MotionVariables' Q{2}''
Variables G{2}
Constants ZK, Bk, a1
E1 = ZK*Q1'' + Bk*Q2' + a1*G1 - Q1
E2 = G2*Q2 + A1
Encode E1, E2
Code Algebraic() sub\\alg_raw.c
"""


@needs["c"]
def test_algebraic_in_order_constants_then_variables(tmp_path, capsys):
    script = tmp_path / "alg.al"
    script.write_text(ALG_ORDER)
    assert _code(script, tmp_path, capsys) == [
        "Wrote",
        str(tmp_path / "alg_raw.c"),
        "Wrote",
        str(tmp_path / "alg_raw.in"),
    ]
    lines = (tmp_path / "alg_raw.in").read_text().splitlines()[6:]
    names = [line[21:41].strip() for line in lines if line[58:59] == "|"]
    assert names == ["A1", "BK", "ZK", "G1", "G2", "Q1", "Q2", "Q2'", "Q1''"]
    numbers = [0.5, 2.0, 3.0, 7.0, 11.0, 13.0, 17.0, 19.0, 23.0]
    values = dict(zip(names, numbers, strict=True))
    _set_in(tmp_path / "alg_raw.in", values)
    # the harness the judge uses prints outputs() at full precision
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import autolev_programs as judge

    own = judge.OurProgram(tmp_path / "alg_raw.c", None)
    got = own.call_outputs()
    assert list(got) == ["E1", "E2"]
    assert got["E1"][0] == 3.0 * 23.0 + 2.0 * 19.0 + 0.5 * 7.0 - 13.0
    assert got["E2"][0] == 11.0 * 17.0 + 0.5
