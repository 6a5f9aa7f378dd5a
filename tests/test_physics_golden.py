"""Golden physics tests: tutor2-tutor9 converted, imported, compared with the
results the tutorial prints (mathematically, at random points).

Expected values are Autolev text, read with al2py's own parser in the module's
names.  Where a printed result has a typo it is corrected here and the
correction is noted.
"""

from __future__ import annotations

import pytest
import sympy as sp

from al2py.checking import compare, evaluate_text

# (script, Autolev name, printed value, Digits of the printed value)
PRINTED = [
    ("tutor2", "DISTANCE", "(0.94444 - 0.22222*COS(PHI) - 0.055556*SIN(PHI))^0.5", 5),
    ("tutor2", "LAMBDA", "[5; 13; 14]", 7),
    ("tutor2", "MTOTAL", "36", 7),
    ("tutor3", "CONFIG[1]", "LA*COS(QA) + LB*COS(QB) - LC*COS(QC)", 7),
    ("tutor3", "CONFIG[2]", "LA*SIN(QA) + LB*SIN(QB) - LC*SIN(QC) - LN", 7),
    ("tutor4", "LOQ", "(LA^2 + LB^2 + 2*LA*LB*COS(QA-QB))^0.5", 7),
    ("tutor4", "ZERO[1]", "K*LB*SIN(QA-QB)*STRETCH/LOQ - G*(MP+MQ)*SIN(QA)", 7),
    ("tutor4", "ZERO[2]", "-G*MQ*SIN(QB) - K*LA*SIN(QA-QB)*STRETCH/LOQ", 7),
    (
        "tutor5",
        "ZERO[1]",
        "H*(COS(QA)-COS(QB)*SIN(QA-QC)/SIN(QB-QC)) + 98.1*(3*SIN(QB)*SIN(QA-QC)"
        "-SIN(QC)*SIN(QA-QB))/SIN(QB-QC) - 441.45*SIN(QA)",
        5,
    ),
    ("tutor5", "ZERO[2]", "COS(QA) + 2*COS(QB) - 2*COS(QC)", 7),
    ("tutor5", "ZERO[3]", "SIN(QA) + 2*SIN(QB) - 2*SIN(QC) - 1", 7),
    ("tutor6", "STRETCH'", "SIN(QA-QB)*(LA*U2-LB*U1)/LOQ", 7),
    (
        "tutor6",
        "ZERO[1]",
        "FP + SIN(QA-QB)*(LB^2*(K*STRETCH+C*STRETCH')/LOQ-MQ*U2^2)/LB "
        "- G*(MP+MQ)*SIN(QA) - (MP+MQ)*U1' - MQ*COS(QA-QB)*U2'",
        7,
    ),
    (
        "tutor6",
        "ZERO[2]",
        "MQ*SIN(QA-QB)*U1^2/LA - G*MQ*SIN(QB) - MQ*U2' - MQ*COS(QA-QB)*U1' "
        "- LA*(K*STRETCH+C*STRETCH')*SIN(QA-QB)/LOQ",
        7,
    ),
    (
        "tutor6f",
        "F1",
        "FP*SIN(QA) - G*(MP+MQ) - MP*COS(QA)*U1^2/LA - MQ*SIN(QB)*U2' "
        "- (MP+MQ)*SIN(QA)*U1' - MQ*(COS(QA)*U1^2/LA+COS(QB)*U2^2/LB)",
        7,
    ),
    (
        "tutor6f",
        "F2",
        "MQ*COS(QB)*U2' + (MP+MQ)*COS(QA)*U1' - FP*COS(QA) - MP*SIN(QA)*U1^2/LA "
        "- MQ*(SIN(QA)*U1^2/LA+SIN(QB)*U2^2/LB)",
        7,
    ),
    # tutor8 prints ZERO from Kane(); the script then evaluates it with
    # L=1, MA=10, MB=1, G=9.81.  The printed ZERO[1] has U2'^2 for U2^2.
    (
        "tutor8",
        "ZERO[1]",
        "F + 0.5*COS(THETA)*U2' - 0.5*SIN(THETA)*U2^2 - 11*U1'",
        7,
    ),
    (
        "tutor8",
        "ZERO[2]",
        "4.905*SIN(THETA) + 0.5*COS(THETA)*U1' - 0.25*(4/12+1)*U2'",
        7,
    ),
    ("tutor8", "CHECK", "[0; 0]", 7),
    (
        "tutor8",
        "A",
        "[0, 0, 1, 0; 0, 0, 0, 1; 4/41*K1, 0.717805+4/41*K2, 4/41*K3, 4/41*K4;"
        " 6/41*K1, 15.7917+6/41*K2, 6/41*K3, 6/41*K4]",
        6,
    ),
    ("tutor8", "ROOTS1", "[-3.97388; 0; 0; 3.97388]", 6),
    ("tutor9", "ZERO[1]", "-U2*(J*OMEGA-(I2-I3)*U3) - I1*U1'", 7),
    ("tutor9", "ZERO[2]", "U1*(J*OMEGA-(I1-I3)*U3) - I2*U2'", 7),
    ("tutor9", "ZERO[3]", "(I1-I2)*U1*U2 - I3*U3'", 7),
    ("tutor9", "CHECK", "[0; 0; 0]", 7),
    (
        "tutor9",
        "AM",
        "[0, -(J*OMEGA-(I2-I3)*NU3)/I1, 0; (J*OMEGA-(I1-I3)*NU3)/I2, 0, 0; 0, 0, 0]",
        7,
    ),
    ("tutor9", "DET", "0.001096997*(9.824469+OMEGA)*(49.12235+OMEGA) + LAMBDA^2", 7),
]


def _resolved(ws, value):
    m = value if isinstance(value, sp.MatrixBase) else sp.Matrix([[value]])
    return ws.resolve(sp.Matrix(m))


@pytest.mark.parametrize("script, name, printed, digits", PRINTED)
def test_printed_result(tutorial, script, name, printed, digits):
    module = tutorial(script)
    ws = module.al
    ours = module.AUTOLEV[name]
    expected = evaluate_text(printed, ws)
    reason = compare(_resolved(ws, expected), _resolved(ws, ours), digits)
    assert reason is None, f"{script} {name}: {reason}\n  ours: {ours}"


def test_tutor2_angle(tutorial):
    angle = float(tutorial("tutor2").AUTOLEV["ANGLE"])
    assert min(abs(angle - 65.90516), abs(angle - 114.09484)) < 1e-4


def test_tutor8_roots2_are_the_eigenvalues_of_a(tutorial):
    module = tutorial("tutor8")
    a = module.AUTOLEV["A"]
    gains = dict(zip(sp.symbols("K1:5", real=True), (1, -244, 5.4, -59), strict=True))
    numeric = sp.Matrix(a).xreplace(gains).evalf()
    key = lambda z: (round(z.real, 6), round(z.imag, 6))  # noqa: E731
    want = sorted((complex(v) for v in numeric.eigenvals(multiple=True)), key=key)
    got = sorted((complex(v) for v in module.AUTOLEV["ROOTS2"]), key=key)
    assert got == pytest.approx(want, abs=1e-5)
    assert all(v.real < 0 for v in got)


@pytest.mark.parametrize("script", ["tutor7", "tutor7c", "tutor7a"])
def test_tutor7_zero_has_one_equation_per_independent_speed(tutorial, script):
    zero = tutorial(script).AUTOLEV["ZERO"]
    assert zero.shape == (1, 1)
