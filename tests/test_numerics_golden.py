"""Numerical jobs of the tutorial, run from the generated modules.

Each expected number is the tutorial's, re-derived independently (see the
runtime tests for the hand-built models); tolerances follow the printed digits.
"""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest
from conftest import SHARED


def test_tutor2_sweep(tutorial):
    r = tutorial("tutor2").run()
    phi, distance, gyration = r["PHI"], r["DISTANCE"], r["GYRATION"]
    assert len(phi) == 361
    assert phi[0] == 0 and phi[-1] == 360
    k = int(np.argmin(distance))
    assert phi[k] == 14 and distance[k] == pytest.approx(0.84580, abs=5e-6)
    k = int(np.argmin(gyration))
    assert phi[k] == 340 and gyration[k] == pytest.approx(0.696, abs=5e-4)


def test_tutor3_four_bar_configuration(tutorial):
    r = tutorial("tutor3").run()
    assert float(r["QB"][0]) == pytest.approx(74.4775, abs=5e-5)
    assert float(r["QC"][0]) == pytest.approx(45.5225, abs=5e-5)


@pytest.mark.parametrize(
    "guess, solution",
    [
        ((-30, 30), (-50.1492, 35.1548)),
        ((30, -30), (50.1492, -35.1548)),
        ((20, 60), (0, 0)),
    ],
)
def test_tutor4_equilibria_from_three_guesses(tutorial, guess, solution):
    r = tutorial("tutor4").run(QA=guess[0], QB=guess[1])
    assert float(r["QA"][0]) == pytest.approx(solution[0], abs=5e-5)
    assert float(r["QB"][0]) == pytest.approx(solution[1], abs=5e-5)


def test_tutor5_four_bar_equilibrium(tutorial):
    r = tutorial("tutor5").run()
    got = [float(r[n][0]) for n in ("QA", "QB", "QC")]
    assert got == pytest.approx([19.987, 71.662, 38.325], abs=5e-4)


def test_tutor6_motion(tutorial):
    r = tutorial("tutor6").run()
    t = r["T"]
    # printInt = 1 integration step: a row every integStp = 0.2 s
    assert len(t) == 101 and t[0] == 0 and t[-1] == 20
    assert np.allclose(np.diff(t), 0.2)
    assert np.ptp(r["ECHECK"]) < 1e-3
    # The tutorial's text swaps both signs; its printed equations give these.
    assert float(r["QA"][-1]) == pytest.approx(50.123, abs=5e-4)
    assert float(r["QB"][-1]) == pytest.approx(-35.150, abs=5e-4)


def test_tutor6_script_writes_table_and_plot(tmp_path, convert_and_import):
    from al2py import convert

    code = convert((SHARED / "tutor6.al").read_text(), str(SHARED / "tutor6.al")).code
    (tmp_path / "tutor6.py").write_text(code)
    run = subprocess.run(
        [sys.executable, "tutor6.py", "--plot"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stderr
    table = np.loadtxt(tmp_path / "tutor6.1", comments="%")
    assert table.shape == (101, 5)
    assert table[-1, 2] == pytest.approx(50.123, abs=5e-3)
    assert list(tmp_path.glob("tutor6*.png")), run.stdout


def test_tutor6f_contact_forces_at_start(tutorial):
    r = tutorial("tutor6f").run()
    assert float(r["F1"][0]) == pytest.approx(-252.358, abs=5e-4)
    assert float(r["F2"][0]) == pytest.approx(-269.115, abs=5e-4)


def test_tutor7_constraints_hold_and_energy_is_constant(tutorial):
    r = tutorial("tutor7").run()
    assert np.max(np.abs(r["CONFIG[1]"])) < 1e-5
    assert np.max(np.abs(r["CONFIG[2]"])) < 1e-5
    assert np.ptp(r["ECHECK"]) < 1e-4


def test_tutor8_cart_and_pendulum(tutorial):
    r = tutorial("tutor8").run()
    end = {name: float(r[name][-1]) for name in ("X", "DX", "THETA", "DTHETA", "F")}
    assert float(r["T"][-1]) == 20
    assert end["X"] == pytest.approx(0.0789, abs=5e-5)
    assert end["DX"] == pytest.approx(0.0730, abs=5e-5)
    assert end["THETA"] == pytest.approx(0.0415, abs=5e-5)
    assert end["DTHETA"] == pytest.approx(0.0390, abs=5e-5)
    assert end["F"] == pytest.approx(-0.0776, abs=5e-5)
    assert float(r["F"][0]) == pytest.approx(-84.172, abs=5e-4)


def test_tutor9_angular_momentum_is_constant(tutorial):
    h = tutorial("tutor9").run()["H"]
    assert np.ptp(h) / np.max(np.abs(h)) < 1e-6


def test_odexy(tutorial):
    r = tutorial("odexy").run()
    assert float(r["X"][-1]) == pytest.approx(0.497489, abs=5e-7)
    assert float(r["Y"][-1]) == pytest.approx(-0.491040, abs=5e-7)


def test_katy(tutorial):
    r = tutorial("katy").run()
    assert (float(r["X"][0]), float(r["Y"][0])) == pytest.approx(
        (0.739085, 0.673612), abs=5e-7
    )


def test_becky(tutorial):
    r = tutorial("becky").run()
    assert (float(r["X"][0]), float(r["Y"][0])) == pytest.approx((-4, 4.5), abs=1e-12)
