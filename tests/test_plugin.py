"""The pytest plugin: ``pytest --al2py models/`` checks every ``.al`` script."""

from __future__ import annotations

import shutil
import xml.etree.ElementTree as ET

import pytest
from conftest import ROOT

pytest_plugins = ["pytester"]

LIBRARY = ROOT / "tests" / "library"


@pytest.fixture
def library(pytester):
    """The fixture library, copied into the pytester folder as ``models/``."""
    shutil.copytree(LIBRARY, pytester.path / "models")
    return pytester.path / "models"


@pytest.fixture
def algebra(pytester):
    """Only the small algebra part of the library (faster)."""
    shutil.copytree(LIBRARY / "algebra", pytester.path / "models")
    return pytester.path / "models"


def test_off_by_default(pytester, algebra):
    result = pytester.runpytest("models")
    assert result.ret == pytest.ExitCode.NO_TESTS_COLLECTED
    result.assert_outcomes()


def test_option_collects_and_checks_the_library(pytester, library):
    junit = pytester.path / "junit.xml"
    result = pytester.runpytest("--al2py", "-v", "models", f"--junitxml={junit}")
    result.assert_outcomes(passed=3)
    result.stdout.fnmatch_lines(
        [
            "*models/algebra/linear.al::linear PASSED*",
            "*models/pendulum/frames.al::frames PASSED*",
            "*models/pendulum/main.al::main PASSED*",
        ]
    )
    suite = ET.parse(junit).getroot().find("testsuite")
    assert suite.get("tests") == "3"
    cases = {c.get("name"): c for c in suite.iter("testcase")}
    assert set(cases) == {"linear", "frames", "main"}
    props = {p.get("name"): p.get("value") for p in cases["main"].iter("property")}
    assert props == {"al2py_status": "passed", "al2py_responses": "18/18"}


def test_ini_setting_enables_it(pytester, algebra):
    pytester.makeini("[pytest]\nal2py = true\n")
    result = pytester.runpytest("models")
    result.assert_outcomes(passed=1)


def test_ini_false_and_no_option_stays_off(pytester, algebra):
    pytester.makeini("[pytest]\nal2py = false\n")
    result = pytester.runpytest("models")
    assert result.ret == pytest.ExitCode.NO_TESTS_COLLECTED


def test_failing_transcript_shows_the_report(pytester, algebra):
    path = algebra / "linear.all"
    path.write_text(path.read_text().replace("-> (19) H = 5", "-> (19) H = 6"))
    (algebra / "bad.al").write_text("Constants A\nE = A + Q\n")
    result = pytester.runpytest("--al2py", "models")
    result.assert_outcomes(failed=2)
    result.stdout.fnmatch_lines(
        [
            "*models/linear.al: 1 of 9 responses differ from models/linear.all",
            "*models/linear.all:19: (19) H: differs: expected 6, got 5",
            "*- Autolev: H = 6",
            "*+ al2py:   H = 5",
        ]
    )
    result.stdout.fnmatch_lines(["*models/bad.al:2:9: error: undeclared name 'Q'"])
    assert "Traceback" not in result.stdout.str()


def test_timeout_option(pytester, algebra):
    result = pytester.runpytest("--al2py", "--al2py-timeout=0.05", "models")
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*timed out after 0.05 s*"])
