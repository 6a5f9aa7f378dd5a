"""More constructs that real research scripts use (issue 19, items 1-6, 9).

Each test is a small script of our own with an expected value; the choices
are recorded in docs/semantics.md.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from conftest import load_module

from al2py import convert
from al2py.errors import AutolevError


def run(src: str, tmp_path: Path, name: str = "snip"):
    path = tmp_path / f"{name}.al"
    path.write_text(src)
    result = convert(src, str(path))
    return load_module(result.code, tmp_path, f"{name}_mod"), result.code


# ------------------------------------------------- 1. Units on any name


def test_units_of_assigned_scalars_in_the_output_header(tmp_path):
    src = (
        "Newtonian N\nPoints O, P1\nVariables x'\nConstants k\nx' = -k*x\n"
        "P_O_P1> = 2*x*N1>\nPOP1X = DOT(P_O_P1>, N1>)\nVX = 3*x'\n"
        "Units T=S, POP1X=CM, VX=M/S\n"
        "Input k=1, x=1, tFinal=1, integStp=0.5\nOutput T, POP1X, VX\n"
        "CODE ODE() u.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    units = [c.unit for c in result.tables[0].columns]
    assert units == ["S", "CM", "M/S"]
    x = np.exp(-result["T"])
    assert np.allclose(result["POP1X"], 200 * x, rtol=1e-5)  # metres -> cm
    assert np.allclose(result["VX"], -3 * x, rtol=1e-5)
    written = result.write(tmp_path)[0].read_text().splitlines()
    assert "(CM)" in written[3] and "(M/S)" in written[3]
    # frames and points have no units
    with pytest.raises(AutolevError) as info:
        run("Newtonian N\nUnits N=M\n", tmp_path)
    assert "not a newtonian" in info.value.message


# ------------------------------- 2. Inputs computed from the script's values


def test_inputs_computed_from_assigned_scalars_and_matrices(tmp_path):
    src = (
        "Constants e1, e4, posa1, posa2, k\nVariables x'\nx' = -k*x\n"
        "QQ1 = PI/4\nInput e1 = 3\n"
        "V = REPLACE([1+e1, 2*e1], E1=INPUT(E1))\nW = [e1; 5]\n"
        "Input E4 = COS(QQ1/2)\nInput POSA1 = V[2], POSA2 = W[1] + 1\n"
        "Input k = 1, x=1, tFinal=1, integStp=0.5\nOutput T, x\nCODE ODE() c.c\n"
    )
    mod, _ = run(src, tmp_path)
    assert mod.evaluate("E4") == pytest.approx(0.9238795325)  # Autolev's .m value
    assert mod.evaluate("POSA1") == pytest.approx(6.0)
    assert mod.evaluate("POSA2") == pytest.approx(4.0)
    # the Input value of e1 given to run() flows into W (evaluated at the job)
    assert mod.evaluate("POSA2", E1=10) == pytest.approx(11.0)


def test_computed_input_with_a_missing_value_names_it(tmp_path):
    src = (
        "Constants e1, posa1, k\nVariables x'\nx' = -k*x\nV = [1+e1, 2]\n"
        "Input POSA1 = V[1]\nInput k = 1, x=1, tFinal=1, integStp=0.5\n"
        "Output T, x\nCODE ODE() c.c\n"
    )
    mod, _ = run(src, tmp_path)
    with pytest.raises(Exception) as info:
        mod.run()
    assert "POSA1" in str(info.value) and "E1 has no Input value" in str(info.value)


# -------------------------------------- 3. Output of matrices and vectors


def test_output_of_matrices_and_vectors(tmp_path):
    src = (
        "Newtonian N\nConstants k, c\nVariables x'\nx' = -k*x\n"
        "A = [1, 2*x, 3; 4, 5, 6*x; 7, 8, x^2]\nb = [x; 2*x]\n"
        "G> = x*N1> + 2*N2> - c*N3>\n"
        "Input k = 1, c=3, x=1, tFinal=1, integStp=0.5\n"
        "Output T, A, b, G>\nCODE ODE() m.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    names = result.tables[0].names
    assert names == ["T"] + [f"A[{i},{j}]" for i in (1, 2, 3) for j in (1, 2, 3)] + [
        "B[1]",
        "B[2]",
        "G>[1]",
        "G>[2]",
        "G>[3]",
    ]
    x = np.exp(-result["T"])
    assert np.allclose(result["A[2,3]"], 6 * x, rtol=1e-5)
    a = result["A"]
    assert a.shape == (3, 3, 3)
    assert np.allclose(a[:, 2, 2], x**2, rtol=1e-5)
    assert np.allclose(result["B"][:, 1, 0], 2 * x, rtol=1e-5)
    assert np.allclose(
        result["G>"][:, :, 0], np.column_stack([x, 2 + 0 * x, -3 + 0 * x])
    )
    # the file holds the same columns, in the same order
    header = result.write(tmp_path)[0].read_text().splitlines()[2].split()
    assert header[1:] == names
    # every column is a key of the result (what to_pandas() builds on)
    assert [k for k, _ in result.items()][: len(names)] == names


def test_output_of_a_vector_needs_a_newtonian_frame(tmp_path):
    src = "Frames A\nConstants c\nG> = c*A1>\nOutput G>\n"
    with pytest.raises(AutolevError) as info:
        run(src, tmp_path)
    assert "Newtonian frame" in info.value.message


# ------------------------------------------ 4. matrices of vectors


def test_matrix_whose_entries_are_vectors(tmp_path, capsys):
    src = (
        "Newtonian N\nPoints O, CA\nVariables u2, u3\nConstants c\n"
        "V_CA_N> = u2*N1> + 3*c*u3*N2> + u2*N3>\n"
        "VCA = [COEF(V_CA_N>, U2), COEF(V_CA_N>, U3)]\n"
        "D1 = DOT(VCA[1], N1>)\nD2 = DOT(VCA[2], N2>)\nD3 = DOT(VCA[1,1], N3>)\n"
    )
    mod, _ = run(src, tmp_path)
    assert mod.AUTOLEV["D1"] == 1
    assert mod.AUTOLEV["D2"] == 3 * mod.c
    assert mod.AUTOLEV["D3"] == 1
    mod.main(["--no-run"])
    assert "VCA = [N1> + N3>, 3*C*N2>]" in capsys.readouterr().out


# ------------------------------------ 5. Replace on vectors and dyadics


def test_replace_on_vectors_and_dyadics(tmp_path):
    src = (
        "Newtonian N\nVariables w1, w2, q'\nConstants k\nW1 = 3*q'\n"
        "W_DA_N> = w1*N1> + w2*N2>\n"
        "W_DA_N> := REPLACE(W_DA_N>, W1=RHS(W1))\n"
        "X> = REPLACE(W_DA_N>, Q'=k)\nDY>> = REPLACE(w2*N1>*N2>, w2=k)\n"
    )
    mod, _ = run(src, tmp_path)
    N = mod.N
    x = mod.AUTOLEV["X>"]
    assert sp.simplify(x.dot(N.x) - 3 * mod.k) == 0
    assert x.dot(N.y) == mod.w2
    w = mod.AUTOLEV["W_DA_N>"]
    assert w.dot(N.x) == 3 * mod.q.diff()
    assert (N.x & mod.AUTOLEV["DY>>"] & N.y) == mod.k


# ------------------------------------ 6. Rows and Cols with ranges and lists


def test_rows_and_cols_with_ranges_and_lists(tmp_path):
    src = (
        "Constants a\n"
        "B = [1,2,3,4,5; 6,7,8,9,10; 11,12,13,14,15; 16,17,18,19,20]\n"
        "R = ROWS(B, 3:4)\nC = COLS(B, 2:5)\nR2 = ROWS(B, [1, 3])\n"
        "C2 = COLS(B, 2, 4)\nC3 = COLS(B, 1, 3:4)\n"
    )
    mod, _ = run(src, tmp_path)
    b = np.arange(1, 21).reshape(4, 5)
    assert np.array_equal(np.array(mod.AUTOLEV["R"]), b[2:4])
    assert np.array_equal(np.array(mod.AUTOLEV["C"]), b[:, 1:5])
    assert np.array_equal(np.array(mod.AUTOLEV["R2"]), b[[0, 2]])
    assert np.array_equal(np.array(mod.AUTOLEV["C2"]), b[:, [1, 3]])
    assert np.array_equal(np.array(mod.AUTOLEV["C3"]), b[:, [0, 2, 3]])


def test_shapes_of_the_matrices_that_feed_rows(tmp_path):
    src = (
        "Variables u{5}\nConstants a{4}\n"
        "F = [a1*u1 + u3; a2*u2 + 2*u4; u3 + a3*u5 + u4; u4 + a4*u1 + u5]\n"
        "B1 = COEF(F, [U4, U5])\nB2 = D(F, [U4, U5])\n"
        "B4 = EXCLUDE(F, [U4, U5])\nB5 = INCLUDE(F, [U4, U5])\n"
        "R = INV(ROWS(B2, 3:4))\n"
    )
    mod, _ = run(src, tmp_path)
    a3, a4 = mod.a3, mod.a4
    u = [mod.u1, mod.u2, mod.u3, mod.u4, mod.u5]
    want = sp.Matrix([[0, 0], [2, 0], [1, a3], [1, 1]])
    assert mod.AUTOLEV["B1"] == want and mod.AUTOLEV["B2"] == want
    f = mod.AUTOLEV["F"]
    excluded = mod.AUTOLEV["B4"]
    assert excluded.shape == (4, 1)
    assert excluded == sp.Matrix([mod.a1 * u[0] + u[2], mod.a2 * u[1], u[2], a4 * u[0]])
    assert sp.expand(mod.AUTOLEV["B5"] + excluded - f) == sp.zeros(4, 1)
    assert sp.simplify(mod.AUTOLEV["R"] * sp.Matrix([[1, a3], [1, 1]])) == sp.eye(2)


# ---------------------------------------------- 9. a missing macro file


def test_missing_macro_file_says_where_it_looked(tmp_path, monkeypatch):
    monkeypatch.delenv("AUTOLEVPATH", raising=False)
    with pytest.raises(AutolevError) as info:
        run("Newtonian N\nPoints RHeel\ncontact(RHeel)\n", tmp_path)
    message = info.value.message
    assert info.value.span.line == 3
    assert "no macro file contact.a or contact.r" in message
    assert str(tmp_path) in message and "AUTOLEVPATH is not set" in message
    lib = tmp_path / "lib"
    monkeypatch.setenv("AUTOLEVPATH", str(lib))
    with pytest.raises(AutolevError) as info:
        run("Newtonian N\nPoints RHeel\ncontact(RHeel)\n", tmp_path)
    assert f"on AUTOLEVPATH ({lib})" in info.value.message
    # with the macro file on AUTOLEVPATH, the call expands
    lib.mkdir()
    (lib / "contact.a").write_text("KC = 7\n")
    mod, _ = run("Newtonian N\nPoints RHeel\ncontact(RHeel)\n", tmp_path)
    assert mod.AUTOLEV["KC"] == 7
