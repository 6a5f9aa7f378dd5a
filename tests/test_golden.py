"""Golden tests: every response of Autolev's transcripts, checked mathematically."""

from __future__ import annotations

import subprocess
import sys

import pytest
import sympy as sp
from conftest import GOLDEN

from al2py.checking import check_responses, parse_transcript

CASES = sorted(p.stem for p in GOLDEN.glob("*.all"))


def _report(checks) -> str:
    lines = []
    for c in checks:
        if not c.ok:
            lines.append(
                f"  ({c.entry.number}) {c.entry.label}\n"
                f"      Autolev: {c.entry.value_text}\n"
                f"      al2py:   {c.ours}\n"
                f"      {c.how}"
            )
    return "\n".join(lines)


@pytest.mark.parametrize("case", CASES)
def test_every_response_matches(case, convert_and_import):
    module, _ = convert_and_import(GOLDEN / f"{case}.al")
    entries = parse_transcript((GOLDEN / f"{case}.all").read_text())
    checks = check_responses(entries, module.al)
    assert checks, f"{case}.all has no responses"
    assert len(checks) == sum(e.is_response for e in entries)
    bad = [c for c in checks if not c.ok]
    assert not bad, f"{len(bad)} of {len(checks)} responses differ:\n" + _report(checks)


@pytest.mark.parametrize(
    "case, label, top",
    [
        ("factoring_on", "X", sp.Mul),
        ("factoring_on", "Y", sp.Mul),
        ("factoring_off", "X", sp.Add),
        ("factoring_off", "Y", sp.Add),
    ],
)
def test_factoring_setting_shapes_the_result(case, label, top, convert_and_import):
    module, _ = convert_and_import(GOLDEN / f"{case}.al")
    assert isinstance(module.AUTOLEV[label], top)


@pytest.mark.parametrize("case", ["autorhs_on", "autorhs_off", "autorhs_all"])
def test_autorhs_keeps_or_substitutes_names(case, convert_and_import):
    """Strict: names Autolev kept (``C*SIN(C)``) must still be symbols."""
    module, _ = convert_and_import(GOLDEN / f"{case}.al")
    entries = parse_transcript((GOLDEN / f"{case}.all").read_text())
    checks = check_responses(entries, module.al)
    assert [c.how for c in checks] == ["strict"] * len(checks), _report(checks)


def test_tutor1_highlights(convert_and_import):
    module, _ = convert_and_import(GOLDEN / "tutor1.al")
    A = module.AUTOLEV
    assert float(A["F"]) == pytest.approx(0.8775825, abs=5e-8)
    roots = [complex(r) for r in A["ROOT1"]]
    assert roots[0] == pytest.approx(-1.650629, abs=1e-6)
    assert sorted(r.imag for r in roots[1:]) == pytest.approx(
        [-1.546869, 1.546869], abs=1e-6
    )
    vec = sp.Matrix(A["EIGVEC"]).evalf()
    expected = sp.Matrix([[-0.8245648, 0.5657675], [-0.4159736, -0.9093767]])
    assert (vec - expected).norm() < 1e-6
    a, b, c, d = sp.symbols("A B C D", real=True)
    assert A["M8"].shape == (3, 2)
    assert sp.simplify(A["M8"] - sp.Matrix([[c, d], [a, b], [c, d]])) == sp.zeros(3, 2)
    assert A["ZERO[2]"] == A["ZERO"][1]
    assert A["M0[2,2]"] == d


def test_tutor1_transcript_printed_by_python_module(tmp_path, convert_and_import):
    """``python tutor1.py`` prints tutor1.all, response by response."""
    module, code = convert_and_import(GOLDEN / "tutor1.al")
    script = tmp_path / "tutor1_run.py"
    script.write_text(code)
    run = subprocess.run(
        [sys.executable, str(script)],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    ours = parse_transcript(run.stdout)
    expected = parse_transcript((GOLDEN / "tutor1.all").read_text())
    # Input lines: same text under the same numbers.
    ours_inputs = [
        (e.number, e.text.split("%")[0].split()) for e in ours if not e.is_response
    ]
    want_inputs = [
        (e.number, e.text.split("%")[0].split()) for e in expected if not e.is_response
    ]
    assert ours_inputs[: len(want_inputs)] == want_inputs
    # Responses: our printed text, read back, equals Autolev's printed text.
    from al2py.checking import compare, evaluate_text

    ours_by_label = {}
    for e in ours:
        if e.is_response:
            ours_by_label.setdefault(e.label, e.value_text)
    failures = []
    for e in expected:
        if not e.is_response:
            continue
        base = e.label.split("[")[0]
        text = ours_by_label.get(e.label) or ours_by_label.get(base)
        assert text is not None, f"no response {e.label} in:\n{run.stdout}"
        got = evaluate_text(text, module.al)
        if e.label not in ours_by_label:  # we printed the whole matrix
            idx = [int(i) - 1 for i in e.label[len(base) + 1 : -1].split(",")]
            got = got[idx[0]] if len(idx) == 1 else got[idx[0], idx[1]]
        want = evaluate_text(e.value_text, module.al)
        reason = compare(want, got, 7)
        if reason is not None:
            failures.append(
                f"{e.label}: Autolev {e.value_text} | ours {text} | {reason}"
            )
    assert not failures, "\n".join(failures)
