"""``al2py check``: convert, import and compare whole libraries with transcripts."""

from __future__ import annotations

import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from conftest import ROOT, SHARED

from al2py import batch, cli
from al2py.checking import check_responses, compare, parse_transcript

LIBRARY = ROOT / "tests" / "library"
BAD_SCRIPT = "Constants A\nE = A + Q\n"  # Q is undeclared


def al2py(*args: str, cwd: Path, timeout: float = 600):
    """Run the real ``al2py`` command; return the CompletedProcess."""
    return subprocess.run(
        [sys.executable, "-m", "al2py", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=timeout,
    )


def copy_library(tmp_path: Path) -> Path:
    lib = tmp_path / "library"
    shutil.copytree(LIBRARY, lib)
    return lib


def mutate(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path}"
    path.write_text(text.replace(old, new, 1))


def parse_junit(path: Path) -> ET.Element:
    """The single ``testsuite`` of a JUnit file, with the standard attributes."""
    root = ET.parse(path).getroot()
    suites = [root] if root.tag == "testsuite" else root.findall("testsuite")
    assert root.tag in ("testsuites", "testsuite")
    assert len(suites) == 1
    suite = suites[0]
    for attr in ("name", "tests", "failures", "errors", "skipped", "time"):
        assert attr in suite.attrib, attr
    cases = suite.findall("testcase")
    assert int(suite.get("tests")) == len(cases)
    for case in cases:
        for attr in ("classname", "name", "time"):
            assert attr in case.attrib, attr
        float(case.get("time"))
    assert int(suite.get("failures")) == sum(
        c.find("failure") is not None for c in cases
    )
    assert int(suite.get("errors")) == sum(c.find("error") is not None for c in cases)
    return suite


def row(stdout: str, name: str) -> list[str]:
    """The table row for the file whose path ends with ``name``."""
    for line in stdout.splitlines():
        cells = line.split()
        if len(cells) == 4 and cells[3].endswith(name):
            return cells
    raise AssertionError(f"no row for {name} in:\n{stdout}")


# ------------------------------------------------------------ the library


def test_library_passes_with_junit_and_jobs(tmp_path):
    junit = tmp_path / "out" / "results.xml"
    junit.parent.mkdir()
    run = al2py("check", ".", "-j", "2", "--junit", str(junit), cwd=LIBRARY)
    assert run.returncode == 0, run.stdout + run.stderr
    assert row(run.stdout, "pendulum/main.al")[:2] == ["passed", "18/18"]
    assert row(run.stdout, "algebra/linear.al")[:2] == ["passed", "9/9"]
    # RUN-only kinematics file without a transcript: converts and imports
    assert row(run.stdout, "pendulum/frames.al")[:2] == ["passed", "none"]
    assert "3 files: 3 passed, 0 failed, 0 errored" in run.stdout
    # progress on stderr, one line per file
    progress = [ln for ln in run.stderr.splitlines() if ln.startswith("[")]
    assert sorted(ln.split()[0] for ln in progress) == ["[1/3]", "[2/3]", "[3/3]"]
    assert "Traceback" not in run.stderr
    suite = parse_junit(junit)
    assert suite.get("failures") == "0" and suite.get("errors") == "0"
    names = {(c.get("classname"), c.get("name")) for c in suite.findall("testcase")}
    assert names == {
        ("pendulum", "main.al"),
        ("pendulum", "frames.al"),
        ("algebra", "linear.al"),
    }


def test_mutated_library_transcript_reports_each_response(tmp_path):
    lib = copy_library(tmp_path)
    mutate(
        lib / "pendulum" / "main.all",
        "TIP = [0.8660254; 2.5]",
        "TIP = [0.8660254; 2.6]",
    )
    mutate(
        lib / "pendulum" / "main.all", "V_P_N> = LA*QA'*A2>\n", "V_P_N> = LA*QB'*A2>\n"
    )
    junit = tmp_path / "j.xml"
    run = al2py("check", "pendulum/main.al", "--junit", str(junit), cwd=lib)
    assert run.returncode == 2, run.stdout + run.stderr
    assert row(run.stdout, "main.al")[:2] == ["failed", "16/18"]
    out = run.stdout
    assert "pendulum/main.al: 2 of 18 responses differ from pendulum/main.all" in out
    assert (
        "pendulum/main.all:56: (56) TIP: differs at [2]: expected 2.6, got 2.5" in out
    )
    assert "  - Autolev: TIP = [0.8660254; 2.6]" in out
    assert "  + al2py:   TIP = [0.8660254; 2.5]" in out
    # a vector response, compared by components
    assert "pendulum/main.all:30: (30) V_P_N>: differs at [2]" in out
    assert "  - Autolev: V_P_N> = LA*QB'*A2>" in out
    suite = parse_junit(junit)
    (case,) = suite.findall("testcase")
    failure = case.find("failure")
    assert failure.get("message") == "2 of 18 responses differ"
    assert "(56) TIP" in failure.text


# ------------------------------------------------------------ the tutorial


@pytest.mark.skipif(not SHARED.is_dir(), reason="no tutorial files")
def test_tutorial_folder_passes(tmp_path):
    junit = tmp_path / "tutorial.xml"
    run = al2py("check", str(SHARED), "-j", "2", "--junit", str(junit), cwd=tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    # tutor1 is the script with its transcript beside it
    assert row(run.stdout, "tutor1.al")[:2] == ["passed", "36/36"]
    n = len(list(SHARED.glob("*.al")))
    assert f"{n} files: {n} passed, 0 failed, 0 errored" in run.stdout
    # transcripts with no script beside them are mentioned, not checked
    assert "note: transcripts without a script are not checked" in run.stderr
    suite = parse_junit(junit)
    assert int(suite.get("tests")) == n


def test_mutated_tutor1_transcript_fails(tmp_path):
    for name in ("tutor1.al", "tutor1.all"):
        shutil.copy(ROOT / "tests" / "golden" / "cases" / name, tmp_path / name)
    mutate(tmp_path / "tutor1.all", "-> (24) F = 0.8775825", "-> (24) F = 0.8775835")
    run = al2py("check", "tutor1.al", cwd=tmp_path)
    assert run.returncode == 2
    assert row(run.stdout, "tutor1.al")[:2] == ["failed", "35/36"]
    line = next(
        i
        for i, text in enumerate((tmp_path / "tutor1.all").read_text().splitlines(), 1)
        if text.startswith("-> (24)")
    )
    want = f"tutor1.all:{line}: (24) F: differs: expected 0.8775835, got 0.877582"
    assert want in run.stdout
    assert "  - Autolev: F = 0.8775835" in run.stdout
    assert "  + al2py:   F = 0.8775825" in run.stdout


# ------------------------------------------------------- errors and options


def test_bad_file_is_reported_and_others_still_checked(tmp_path):
    lib = copy_library(tmp_path)
    (lib / "algebra" / "bad.al").write_text(BAD_SCRIPT)
    run = al2py("check", ".", "--exclude", "pendulum/*", cwd=lib)
    assert run.returncode == 2
    assert row(run.stdout, "algebra/bad.al")[:2] == ["errored", "none"]
    assert row(run.stdout, "algebra/linear.al")[:2] == ["passed", "9/9"]
    assert "algebra/bad.al:2:9: error: undeclared name 'Q'" in run.stdout
    assert "2 files: 1 passed, 0 failed, 1 errored" in run.stdout
    assert "Traceback" not in run.stdout + run.stderr


def test_timeout_gives_an_error_not_a_hang(tmp_path):
    (tmp_path / "x.al").write_text("Constants A\nE = A + 1\n")
    run = al2py("check", "x.al", "--timeout", "0.05", cwd=tmp_path)
    assert run.returncode == 2
    assert row(run.stdout, "x.al")[0] == "errored"
    assert "x.al: error: timed out after 0.05 s" in run.stdout


def test_file_without_transcript_passes_if_it_imports(tmp_path, capsys):
    (tmp_path / "x.al").write_text("Constants A\nE = A + 1\n")
    status = cli.main(["check", str(tmp_path), "-q"])
    out, err = capsys.readouterr()
    assert status == 0, out + err
    assert err == ""
    assert row(out, "x.al")[:2] == ["passed", "none"]


def test_worker_that_dies_is_an_error(tmp_path, monkeypatch):
    (tmp_path / "x.al").write_text("Constants A\n")
    monkeypatch.setattr(
        batch, "_WORKER", "import sys; print('boom', file=sys.stderr); sys.exit(7)"
    )
    result = batch.check_file(tmp_path / "x.al", timeout=60)
    assert result.status == batch.ERRORED
    assert "the checking process died (exit status 7)" in result.message
    assert "boom" in result.message


def test_no_scripts_and_missing_paths_are_usage_errors(tmp_path, capsys):
    assert cli.main(["check", str(tmp_path)]) == 2
    assert "no .al scripts found" in capsys.readouterr().err
    assert cli.main(["check", str(tmp_path / "nothere")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("al2py: error: no such file or folder:")
    with pytest.raises(SystemExit) as exc:
        cli.main(["check", "-j", "0", str(tmp_path)])
    assert exc.value.code == 2
    assert "must be at least 1" in capsys.readouterr().err


def test_help_lists_subcommands(capsys):
    with pytest.raises(SystemExit):
        cli.main(["--help"])
    out = capsys.readouterr().out
    assert "al2py check" in out and "al2py convert" in out
    with pytest.raises(SystemExit) as exc:
        cli.main(["check", "--help"])
    assert exc.value.code == 0
    out = capsys.readouterr().out
    for option in ("--timeout", "--junit", "-j", "--exclude"):
        assert option in out


def test_a_script_named_check_converts_as_dot_slash_check(
    tmp_path, monkeypatch, capsys
):
    (tmp_path / "check").write_text("Constants A\nE = A + 1\n")
    monkeypatch.chdir(tmp_path)
    assert cli.main(["./check", "-o", "check.py"]) == 0
    assert "AUTOLEV" in (tmp_path / "check.py").read_text()


# --------------------------------------------------------- the comparison


def test_transcript_lines_and_wrapped_responses():
    text = (
        "(1) Constants A, B\n"
        "(2) X = (A+B)^2\n"
        "-> (3) X = A^2 + 2*A*B +\n"
        "       B^2\n"
        "some message Autolev printed\n"
        "-> (4) Y = A\n"
        "not a continuation\n"
    )
    entries = parse_transcript(text)
    assert [(e.number, e.line, e.is_response) for e in entries] == [
        (1, 1, False),
        (2, 2, False),
        (3, 3, True),
        (4, 6, True),
    ]
    assert entries[2].value_text == "A^2 + 2*A*B + B^2"
    assert entries[3].value_text == "A"


@pytest.fixture(scope="module")
def pendulum(tmp_path_factory):
    from conftest import load_module

    from al2py import convert

    path = LIBRARY / "pendulum" / "main.al"
    result = convert(path.read_text(), str(path))
    return load_module(result.code, tmp_path_factory.mktemp("pendulum"), "main")


def one(module, text: str):
    (check,) = check_responses(parse_transcript(f"-> (1) {text}\n"), module.al)
    return check


def test_vectors_compare_by_components_across_frames(pendulum):
    assert one(pendulum, "P_O_P> = LA*COS(QA)*N1> + LA*SIN(QA)*N2>").ok
    assert one(pendulum, "P_O_P> = LA*A1>").ok
    bad = one(pendulum, "P_O_P> = LA*A2>")
    assert not bad.ok and bad.how.startswith("differs at [")
    assert one(pendulum, "V_O_N> = 0>").ok
    assert not one(pendulum, "V_P_N> = 0>").ok


def test_dyadics_are_outer_products(pendulum):
    from sympy.physics.vector import outer

    a = pendulum.A
    assert compare(outer(a.x, a.x), outer(a.x, a.x)) is None
    assert compare(outer(a.x, a.x), outer(a.x, a.y)) is not None


def test_unreadable_or_missing_responses_fail_without_crashing(pendulum):
    assert one(pendulum, "NOSUCH = 1").how == "no such response from the module"
    bad = one(pendulum, "X = FROB(LA)")
    assert not bad.ok and "cannot read Autolev's response" in bad.how
