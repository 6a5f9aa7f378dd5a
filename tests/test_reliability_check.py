"""Issue 12: ``al2py check`` cannot pass wrongly (items 9, 10, 11) and errors
carry their source line and caret (item 8)."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

from al2py import batch, cli

FAILING_JOB = """\
Variables X'
X' = log(X)
Input X = -1, tFinal = 1
Output T, X
CODE ODE() dom.c
"""

GOOD_JOB = """\
Variables X'
X' = -X
Input X = 1, tFinal = 1
Output T, X
CODE ODE() good.c
"""


def run_check(*args: str, cwd: Path):
    return subprocess.run(
        [sys.executable, "-m", "al2py", "check", *args],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=600,
    )


# ------------------------------------------ item 10: CODE jobs are run


def test_check_runs_code_jobs_and_fails_a_failing_one(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "dom.al").write_text(FAILING_JOB)
    (lib / "good.al").write_text(GOOD_JOB)
    run = run_check("lib", cwd=tmp_path)
    assert run.returncode == 2
    assert "errored  none" in run.stdout
    (located,) = {
        line.strip()
        for line in run.stdout.splitlines()
        if "error: CODE Ode dom.c" in line
    }
    assert located.startswith("lib/dom.al:5: error: CODE Ode dom.c (line 5) failed: ")
    assert located.endswith("at t = 0")
    assert "1 passed, 0 failed, 1 errored" in run.stdout
    assert "[1/2]" in run.stderr or "[2/2]" in run.stderr
    assert (
        "passed (no transcript to compare: converted, imported and ran its CODE job)"
        in (run.stderr)
    )
    # --no-run skips the jobs (and says less)
    skipped = run_check("lib", "--no-run", cwd=tmp_path)
    assert skipped.returncode == 0, skipped.stdout
    assert (
        "2 passed with no transcript, so nothing was compared: lib/dom.al, lib/good.al"
        in (skipped.stdout)
    )


# --------------------------------------- item 11: plain words, ETA, files


def test_progress_lines_and_table_say_what_was_compared():
    bare = batch.FileResult("a.al", batch.PASSED, seconds=1.0, jobs_run=1)
    compared = batch.FileResult(
        "b.al", batch.PASSED, matched=3, total=3, transcript="b.all", seconds=2.0
    )
    assert batch.progress_line(1, 4, bare, eta=30.0) == (
        "[1/4] a.al ... passed (no transcript to compare: converted, imported and "
        "ran its CODE job) 1.0s, ETA 30s"
    )
    assert batch.progress_line(4, 4, compared, eta=None) == (
        "[4/4] b.al ... passed (3/3 responses) 2.0s"
    )
    table = batch.format_table([bare, compared]).splitlines()
    assert table[1].split()[:2] == ["passed", "none"]
    assert table[2].split()[:2] == ["passed", "3/3"]
    assert "1 passed with no transcript, so nothing was compared: a.al" in (
        batch.summary_line([bare, compared]).splitlines()
    )
    assert batch.eta_seconds(2, 10, 20.0) == 80.0
    assert batch.eta_seconds(10, 10, 20.0) is None
    assert batch.heartbeat_line([("m/x.al", 75.0)]) == "still checking: m/x.al (1m15s)"


def test_heartbeat_names_the_file_being_checked(tmp_path):
    slow = tmp_path / "slow.al"
    slow.write_text(GOOD_JOB.replace("tFinal = 1", "tFinal = 2"))
    beats: list = []
    results = batch.check_files(
        batch.find_scripts([slow]),
        heartbeat=beats.append,
        heartbeat_every=0.2,
    )
    assert results[0].status == batch.PASSED, results[0].message
    assert beats and beats[0][0][0].endswith("slow.al") and beats[0][0][1] > 0


# ---------------------------------------- item 9: JUnit XML stays valid


def test_junit_xml_escapes_characters_xml_forbids(tmp_path):
    bad = batch.FileResult(
        "ctl.al",
        batch.ERRORED,
        message="ctl.al:1:5: error: bad\x01 input\x1b[31m\n    E = \x0c\x00",
    )
    text = batch.junit_xml([bad], 1.0)
    root = ET.fromstring(text.encode())  # parses: no forbidden character left
    error = root.find("./testsuite/testcase/error")
    assert error is not None
    assert error.get("message") == "ctl.al:1:5: error: bad\\x01 input\\x1b[31m"
    assert "\\x00" in error.text and "\x0c" not in error.text


def test_junit_from_check_with_control_characters_parses(tmp_path):
    (tmp_path / "ctl.al").write_bytes(b"Constants A\nB = A +\x01 1\n")
    run = run_check("ctl.al", "--junit", "r.xml", "-q", cwd=tmp_path)
    assert run.returncode == 2
    root = ET.parse(tmp_path / "r.xml").getroot()
    assert root.find("./testsuite/testcase/error") is not None


# ------------------------------------------------- item 8: error locations


def test_run_cycle_errors_show_the_line_and_caret(tmp_path, capsys):
    (tmp_path / "a.al").write_text("Constants A\nRUN b.al\n")
    (tmp_path / "b.al").write_text("Constants B\n  RUN a.al\n")
    status = cli.main([str(tmp_path / "a.al")])
    err = capsys.readouterr().err.splitlines()
    assert status == 2
    assert err[0].endswith("runs itself"), err
    assert err[1].strip().startswith("RUN ")
    assert err[2].index("^") == err[1].index("RUN")  # the caret under RUN
    column = int(err[0].split(":")[2])
    assert err[2].index("^") == 4 + column - 1


def test_macro_errors_show_the_line_and_caret(tmp_path, capsys):
    (tmp_path / "twice.a").write_text("#2# = 2*(#1#\n")  # unbalanced parenthesis
    (tmp_path / "m.al").write_text("Constants A\nTwice(A, B)\n")
    status = cli.main([str(tmp_path / "m.al")])
    err = capsys.readouterr().err.splitlines()
    assert status == 2
    assert ":2:1: error: " in err[0]
    assert err[1] == "    Twice(A, B)"
    assert err[2] == "    ^"


def test_deep_nesting_error_points_at_the_deepest_bracket(tmp_path):
    depth = 3000
    text = "Constants A\nB = " + "(" * depth + "A" + ")" * depth + "\n"
    (tmp_path / "deep.al").write_text(text)
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "deep.al"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=600,
    )
    assert run.returncode == 2
    first, source, caret = run.stderr.splitlines()[:3]
    col = len("B = ") + depth
    assert first.startswith(f"deep.al:2:{col}: error: ")
    assert "nested too deeply" in first
    # the 6000-character line is shown cut around the column
    assert source.startswith("    ...") and len(source) < 140
    at = caret.index("^")
    assert source[at : at + 2] == "(A"


def _depth(node) -> int:
    import dataclasses

    from al2py import ir

    best, stack = 0, [(node, 1)]
    while stack:
        item, d = stack.pop()
        best = max(best, d)
        for f in dataclasses.fields(item):
            value = getattr(item, f.name)
            if isinstance(value, ir.Expr):
                stack.append((value, d + 1))
    return best


def test_long_flat_sums_are_shallow_trees():
    """A 4000-term sum is a balanced tree (depth ~ log2 n), so no pass
    recurses 4000 deep and Python can compile the generated code."""
    from al2py.analysis import walk_expr
    from al2py.parser import parse

    n = 4000
    text = "Constants A\nB = " + "+".join(["A"] * n) + " - 1\n"
    value = parse(text, "s.al").statements[1].value
    assert _depth(value) <= 14
    names = [e for e in walk_expr(value) if type(e).__name__ == "Name"]
    assert len(names) == n


def test_long_flat_sum_converts_and_runs(tmp_path):
    n = 4000  # Python itself cannot compile a chain of more than ~3000 '+'
    text = "Constants A\nB = " + "+".join(["1"] * n) + " - A\nC = B/2\n"
    (tmp_path / "flat.al").write_text(text)
    conv = subprocess.run(
        [sys.executable, "-m", "al2py", "flat.al", "-o", "flat.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=600,
    )
    assert conv.returncode == 0, conv.stderr
    run = subprocess.run(
        [sys.executable, "flat.py"], capture_output=True, text=True, cwd=tmp_path
    )
    assert run.returncode == 0, run.stderr
    responses = [line for line in run.stdout.splitlines() if line.startswith("->")]
    assert responses == ["-> (3) B = 4000 - A", "-> (5) C = 0.5*B"]


def test_check_reports_a_run_time_failure_at_its_line(tmp_path):
    lib = tmp_path / "lib"
    lib.mkdir()
    (lib / "mag.al").write_text("Newtonian N\nPoints P, Q\nD = Mag(P_P_Q>)\n")
    run = run_check("lib", "-q", cwd=tmp_path)
    assert run.returncode == 2
    assert "  lib/mag.al:3: error: P_P_Q> is not defined\n      D = Mag(P_P_Q>)" in (
        run.stdout
    )
    assert "Traceback" not in run.stdout + run.stderr
