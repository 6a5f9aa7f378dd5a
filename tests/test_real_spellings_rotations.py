"""Issue 19, items 7 and 8: spellings and reserved names Autolev accepted, and
direction cosines written as Autolev writes them (own small scripts)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from conftest import load_module

from al2py import convert
from al2py.errors import AutolevError


def module(tmp_path, text: str, name: str = "m"):
    return load_module(convert(text, f"{name}.al").code, tmp_path, name)


def at_random(expr, seed: int = 3) -> float:
    """``expr`` at a random point (derivatives, then functions of time)."""
    expr = sp.sympify(expr)
    rng = random.Random(seed)
    table = {}
    for a in sorted(expr.atoms(sp.Derivative), key=sp.default_sort_key):
        table[a] = rng.uniform(-1, 1)
    expr = expr.xreplace(table)
    funcs = sorted(expr.atoms(sp.core.function.AppliedUndef), key=sp.default_sort_key)
    expr = expr.xreplace({f: rng.uniform(-1, 1) for f in funcs})
    syms = sorted(expr.free_symbols, key=sp.default_sort_key)
    return float(expr.xreplace({s: rng.uniform(-1, 1) for s in syms}))


# ------------------------------------------------- item 8: Euler parameters

EULER = """Newtonian N
Bodies B
Variables E{4}'
Dircos(N, B, EULER, E1, E2, E3, E4)
C11 = N_B[1,1]
DC11 = D(C11, E1)
Angvel(N, B, EULER, E1, E2, E3, E4)
"""


def test_euler_direction_cosines_are_autolevs(tmp_path):
    m = module(tmp_path, EULER)
    e1, e2, e3, e4 = (m.AUTOLEV[f"E{i}"] for i in range(1, 5))
    # As Autolev 4.1's generated programs write them: unit norm used on the
    # diagonal (1 - 2*E2^2 - 2*E3^2), E4 only off the diagonal.
    want = sp.Matrix(
        [
            [
                1 - 2 * e2**2 - 2 * e3**2,
                2 * e1 * e2 - 2 * e3 * e4,
                2 * e1 * e3 + 2 * e2 * e4,
            ],
            [
                2 * e1 * e2 + 2 * e3 * e4,
                1 - 2 * e1**2 - 2 * e3**2,
                2 * e2 * e3 - 2 * e1 * e4,
            ],
            [
                2 * e1 * e3 - 2 * e2 * e4,
                2 * e1 * e4 + 2 * e2 * e3,
                1 - 2 * e1**2 - 2 * e2**2,
            ],
        ]
    )
    got = m.AUTOLEV["N_B"]
    assert all(sp.expand(x - y) == 0 for x, y in zip(got, want, strict=True))
    # the derivative is that of Autolev's form: D(1 - 2*E2^2 - 2*E3^2, E1) = 0
    assert m.AUTOLEV["DC11"] == 0
    # a 90 degree turn about N3>: E3 = sin(45), E4 = cos(45)
    s = sp.sqrt(2) / 2
    turned = got.subs({e1: 0, e2: 0, e3: s, e4: s})
    assert turned == sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])


def test_euler_angular_velocity_inverts_the_kinematical_equations(tmp_path):
    m = module(tmp_path, EULER)
    e = [m.AUTOLEV[f"E{i}"] for i in range(1, 5)]
    t = sp.Symbol("t")
    de = [sp.diff(x, t) for x in e]
    w = m.AUTOLEV["W_B_N>"].to_matrix(m.B)
    # w = 2*(e4*e' - e4'*e - e x e'), first measure number written out
    w1 = 2 * (e[3] * de[0] - de[3] * e[0] - (e[1] * de[2] - e[2] * de[1]))
    assert sp.expand(w[0] - w1) == 0
    assert at_random(w[0]) == pytest.approx(at_random(w1))


# -------------------------------------------- item 7: spellings and names

SPEEDS = """Newtonian N
Bodies A
Constants G, L, K
Variables U{3}', Q{3}'
Specified FB
Q1' = U1
Q2' = U2
Q3' = U3
Simprot(N, A, 3, Q1)
W_A_N> = U1*A3>
V_AO_N> = U2*N1> + U3*N2>
Mass A = 2
Inertia A, 1, 1, 3
Gravity(-G*N2>)
Force_AO> += FB*A1>
Torque_A> += -K*Q1*A3>
Dependent[1] = U3 - L*U1
Constrain(Dependent[U3])
Zero = Fr() + FrStar()
B = -Exclude(Zero, [U_Independent'; G; FB])
Gin = Include(Zero, [G; FB])
Ui = U_INDEPENDENT
Ud = U_Dependent'
P2 = U_PARTIALS[2]
"""


def test_reserved_speed_matrices_and_exclude_of_a_list(tmp_path):
    m = module(tmp_path, SPEEDS)
    a = m.AUTOLEV
    t = sp.Symbol("t")
    u1, u2, u3, q1 = m.U1, m.U2, m.U3, m.Q1
    g, fb, k = m.G, m.FB, m.K
    # U3 is dependent: U_INDEPENDENT = [U1; U2], U_DEPENDENT' = [U3']
    assert list(a["UI"]) == [u1, u2]
    assert list(a["UD"]) == [sp.diff(u3, t)]
    assert a["P2"] == u2
    # Zero[1] = -K*Q1 - L*(2*G - FB*sin(Q1)) - (3 + 2*L^2)*U1': only the
    # spring term has none of U1', U2', G, FB.
    assert sp.expand(a["B"][0] - k * q1) == 0
    assert a["B"][1] == 0
    # Include with a list: the terms with G or FB, nothing else
    gin = sp.expand(a["GIN"][0])
    assert gin.has(g) and gin.has(fb)
    assert not gin.has(k) and not gin.has(sp.diff(u1, t))


def test_reserved_speed_matrices_cannot_be_assigned():
    with pytest.raises(AutolevError, match="reserved"):
        convert("Variables U{2}'\nU_INDEPENDENT = [U1]\n", "x.al")


def test_longer_spellings_of_builtins_are_the_builtin(tmp_path):
    m = module(
        tmp_path,
        "M = [2, 1; 1, 1]\nMI = inverse(M)\nMT = Transposed(M)\nC = Cosine(0)\n",
    )
    assert m.AUTOLEV["MI"] == sp.Matrix([[1, -1], [-1, 2]])
    assert m.AUTOLEV["MT"] == sp.Matrix([[2, 1], [1, 1]])
    assert m.AUTOLEV["C"] == 1


def test_a_macro_file_wins_over_a_longer_spelling(tmp_path):
    (tmp_path / "inverse.r").write_text("2*#1#\n")
    text = "Constants A\nX = inverse(A)\n"
    code = convert(text, str(tmp_path / "s.al"), script_dir=tmp_path).code
    m = load_module(code, tmp_path, "s")
    assert m.AUTOLEV["X"] == 2 * sp.Symbol("A", real=True)


def test_abbreviations_and_short_stems_stay_errors():
    for text in ("M = [1]\nX = Trans(M)\n", "Constants A\nX = Dtx(A)\n"):
        with pytest.raises(AutolevError, match="unknown function"):
            convert(text, "x.al")


def test_an_empty_speed_class_is_a_located_error(tmp_path):
    from al2py_runtime import AutolevRuntimeError

    with pytest.raises(AutolevRuntimeError, match="U_DEPENDENT is empty") as err:
        module(tmp_path, "Variables U{2}'\nX = U_DEPENDENT\n", "e")
    assert err.value.line == 2
