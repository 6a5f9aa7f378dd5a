"""Issue 19, item 10: ``al2py check`` on real transcripts (own small scripts
and transcripts): AutoZ intermediates, failed CODE jobs, constrained random
points, and ``-j 2`` reporting exactly what ``-j 1`` does."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from al2py import batch
from al2py.checking import compare

ZS_AL = """Newtonian N
Frames A, B
Variables Q{2}'
Constants L
AutoZ ON
Simprot(N, A, 3, Q1)
Simprot(A, B, 3, Q2)
P> = L*B1>
X = Dot(P>, N1>)
Y = Dot(P>, N2>)
"""

# What Autolev prints with AutoZ ON: its own Z numbering, each Z defined
# before its first use (al2py numbers its intermediates differently).
ZS_ALL = """(1) Newtonian N
(2) Frames A, B
(3) Variables Q{2}'
(4) Constants L
(5) AutoZ ON
(6) Simprot(N, A, 3, Q1)
-> (7) Z1 = COS(Q1)
-> (8) Z2 = SIN(Q1)
-> (9) N_A = [Z1, -Z2, 0; Z2, Z1, 0; 0, 0, 1]
(10) Simprot(A, B, 3, Q2)
-> (11) Z3 = COS(Q2)
-> (12) Z4 = SIN(Q2)
-> (13) A_B = [Z3, -Z4, 0; Z4, Z3, 0; 0, 0, 1]
(14) P> = L*B1>
-> (15) P> = L*B1>
(16) X = Dot(P>, N1>)
-> (17) Z5 = Z1*Z3 - Z2*Z4
-> (18) X = L*Z5
(19) Y = Dot(P>, N2>)
-> (20) Y = L*(Z2*Z3+Z1*Z4)
"""


def write(folder: Path, name: str, al: str, transcript: str | None) -> Path:
    path = folder / f"{name}.al"
    path.write_text(al)
    if transcript is not None:
        (folder / f"{name}.all").write_text(transcript)
    return path


def test_autoz_transcript_is_compared_through_its_own_z(tmp_path):
    result = batch.check_file(write(tmp_path, "zs", ZS_AL, ZS_ALL), timeout=120)
    assert result.status == batch.PASSED, batch.format_file_report(result)
    # N_A, A_B, P>, X, Y compared; Z1..Z5 not compared, counted apart
    assert (result.matched, result.total, result.not_compared) == (5, 5, 5)
    report = batch.format_report([result])
    assert "5 compared, 5 matching, 5 not compared" in report
    assert "5 Z not compared" in batch.progress_line(1, 1, result)


def test_a_wrong_z_fails_the_responses_that_use_it(tmp_path):
    wrong = ZS_ALL.replace("Z4 = SIN(Q2)", "Z4 = COS(Q2)")
    result = batch.check_file(write(tmp_path, "zs", ZS_AL, wrong), timeout=120)
    assert result.status == batch.FAILED
    assert (result.matched, result.total, result.not_compared) == (2, 5, 5)
    assert sorted(f.label for f in result.failures) == ["A_B", "X", "Y"]


FAILING_JOB_AL = """Variables X''
Constants M, K
Zero[1] = M*X'' + K*X
E = K*X^2/2
Input M = 0, K = 1, X = 1, X' = 0, tFinal = 1
Output X
CODE Dynamics() failing.c
"""

FAILING_JOB_ALL = """(1) Variables X''
(2) Constants M, K
(3) Zero[1] = M*X'' + K*X
-> (4) ZERO[1] = K*X + M*X''
(5) E = K*X^2/2
-> (6) E = 0.5*K*X^2
(7) Input M = 0, K = 1, X = 1, X' = 0, tFinal = 1
(8) Output X
(9) CODE Dynamics() failing.c
"""


def test_failed_code_job_still_compares_the_responses(tmp_path):
    wrong = FAILING_JOB_ALL.replace("0.5*K*X^2", "0.5*K*X^3")
    path = write(tmp_path, "failing", FAILING_JOB_AL, wrong)
    result = batch.check_file(path, timeout=120)
    assert result.status == batch.ERRORED
    assert "failing.al:7: error: CODE Dynamics failing.c" in result.message
    assert "singular" in result.message
    assert (result.matched, result.total) == (1, 2)
    report = batch.format_file_report(result)
    assert "failing.al: errored" in report
    assert "1 of 2 responses differ from" in report
    assert "(6) E: differs" in report


EULER_AL = """Newtonian N
Bodies B
Variables E{4}'
Dircos(N, B, EULER, E1, E2, E3, E4)
C11 = N_B[1,1]
"""

# The same direction cosine written without using the unit norm: equal only
# where E1^2 + E2^2 + E3^2 + E4^2 = 1.
EULER_ALL = """(1) Newtonian N
(2) Bodies B
(3) Variables E{4}'
(4) Dircos(N, B, EULER, E1, E2, E3, E4)
(5) C11 = N_B[1,1]
-> (6) C11 = E1^2 - E2^2 - E3^2 + E4^2
"""


def test_random_points_keep_euler_parameters_on_the_unit_sphere(tmp_path):
    result = batch.check_file(write(tmp_path, "eu", EULER_AL, EULER_ALL), timeout=120)
    assert result.status == batch.PASSED, batch.format_file_report(result)
    assert (result.matched, result.total) == (1, 1)
    # without the constraint the two forms differ at random points
    import sympy as sp

    e = [sp.Function(f"E{i}")(sp.Symbol("t")) for i in range(1, 5)]
    old = e[0] ** 2 - e[1] ** 2 - e[2] ** 2 + e[3] ** 2
    new = 1 - 2 * e[1] ** 2 - 2 * e[2] ** 2
    assert compare(old, new) is not None
    assert compare(old, new, unit_norms=[e]) is None
    wrong = 1 - 2 * e[1] ** 2 - 3 * e[2] ** 2
    assert compare(old, wrong, unit_norms=[e]) is not None


def _without_timings(text: str) -> str:
    lines = []
    for line in text.splitlines():
        cells = [c for c in line.split() if not re.fullmatch(r"\d+(\.\d+)?s,?", c)]
        lines.append(" ".join(cells))
    return "\n".join(lines)


@pytest.mark.slow
def test_two_jobs_report_exactly_what_one_job_does(tmp_path):
    write(tmp_path, "zs", ZS_AL, ZS_ALL)
    write(tmp_path, "zbad", ZS_AL, ZS_ALL.replace("Z4 = SIN(Q2)", "Z4 = COS(Q2)"))
    write(tmp_path, "failing", FAILING_JOB_AL, FAILING_JOB_ALL)
    write(tmp_path, "eu", EULER_AL, EULER_ALL)
    write(tmp_path, "plain", "Constants A\nE = A + 1\n", None)
    outputs = []
    for jobs in ("1", "2"):
        run = subprocess.run(
            [sys.executable, "-m", "al2py", "check", ".", "-j", jobs, "-q"],
            capture_output=True,
            text=True,
            cwd=tmp_path,
            timeout=600,
        )
        assert run.returncode == 2, run.stdout + run.stderr
        outputs.append(_without_timings(run.stdout))
    assert outputs[0] == outputs[1]
    assert "5 files: 3 passed, 1 failed, 1 errored" in outputs[0]
    assert "responses: 13 compared, 10 matching, 10 not compared" in outputs[0]
