"""Constructs that real research scripts use beyond the tutorial.

Each test is a small script of our own that uses one construct the way the
public research scripts do, with an expected value (never only "it
converts").  The choices are recorded in docs/semantics.md.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from conftest import load_module
from sympy.physics.mechanics import dynamicsymbols

from al2py import convert
from al2py.errors import AutolevError

T = dynamicsymbols._t


def run(src: str, tmp_path: Path, name: str = "snip"):
    path = tmp_path / f"{name}.al"
    path.write_text(src)
    result = convert(src, str(path))
    return load_module(result.code, tmp_path, f"{name}_mod"), result.code


def same(got, want) -> bool:
    got, want = sp.Matrix(got), sp.Matrix(want)
    if got.shape != want.shape:
        return False
    return all(
        sp.simplify(sp.expand(g - w)) == 0 for g, w in zip(got, want, strict=True)
    )


def at_random(expr, subs_objs, seed: int = 1) -> complex:
    rng = np.random.default_rng(seed)
    return complex(sp.N(expr.xreplace({o: rng.uniform(0.2, 1.3) for o in subs_objs})))


# ----------------------------------------------------------- settings


def test_overwrite_all_and_interactive_settings(tmp_path):
    mod, code = run(
        "Overwrite All\nPause 0\nBeepsound Off\nAutoz On\nAutoz Off\n"
        "Constants a\nPause\nb = 2*a\n",
        tmp_path,
    )
    assert mod.al.settings.overwrite == "ALL"
    assert mod.al.settings.autoz is False
    assert mod.AUTOLEV["B"] == 2 * mod.a
    assert "# Pause: Autolev waits for a key press" in code


def test_unknown_setting_word_is_a_located_error(tmp_path):
    with pytest.raises(AutolevError) as info:
        run("Overwrite Sometimes\n", tmp_path)
    assert info.value.span.line == 1
    assert "OVERWRITE takes ON, OFF, ALL" in info.value.message


# --------------------------------------------------- statement separators


def test_semicolons_end_statements(tmp_path):
    mod, code = run("Constants a;\nb = a + 1; c = 2*b;\nd = [1; 2];\n", tmp_path)
    assert mod.AUTOLEV["B"] == mod.a + 1
    assert mod.AUTOLEV["C"] == 2 * mod.b
    assert mod.AUTOLEV["D"] == sp.Matrix([1, 2])
    # the line is echoed once, and numbered once in the transcript
    assert code.count("# al> b = a + 1; c = 2*b;") == 1


def test_semicolon_statement_still_responds(tmp_path, capsys):
    mod, _ = run("Constants a\nb = a + 1;\n", tmp_path)
    mod.main(["--no-run"])
    out = capsys.readouterr().out
    assert "-> (3) B = 1 + A" in out


def test_continuation_may_split_a_name(tmp_path):
    mod, _ = run("Variables theta\nx = sin(THET&\n   A)*2 + &\n   1\n", tmp_path)
    assert same([mod.AUTOLEV["X"]], [2 * sp.sin(mod.theta) + 1])


# ------------------------------------------------ names shared by objects


def test_body_and_constant_with_the_same_letters(tmp_path):
    src = (
        "Newtonian N\nBodies B, C\nConstants c, lam\nVariables q5\n"
        "Simprot(N, B, 3, lam)\nSimprot(B, C, 2, q5)\n"
        "trail = c*cos(lam)\n"
        "P_BO_CO> = c*B1>\n"
        "w> = C1>\n"
    )
    mod, code = run(src, tmp_path)
    c_const = mod.AUTOLEV["TRAIL"] / sp.cos(mod.lam)
    assert isinstance(c_const, sp.Symbol) and c_const.name == "C"
    # Simprot(B, C, 2, q5) rotates body C about B2>
    c1_in_b = mod.AUTOLEV["W>"].to_matrix(mod.B)
    assert same(c1_in_b, [sp.cos(mod.q5), 0, -sp.sin(mod.q5)])


def test_gravity_on_listed_bodies_only(tmp_path):
    src = (
        "Newtonian N\nParticles P, Q\nVariables x', y', u{2}'\nConstants g, mp, mq\n"
        "Mass P=mp, Q=mq\nx' = u1\ny' = u2\n"
        "P_NO_P> = x*N1>\nP_NO_Q> = y*N1>\n"
        "V_P_N> = u1*N1>\nV_Q_N> = u2*N1>\n"
        "Gravity(g*N1>, P)\n"
        "F = Fr()\n"
    )
    mod, _ = run(src, tmp_path)
    assert same(mod.AUTOLEV["F"], [mod.g * mod.mp, 0])


def test_gravity_names_must_be_bodies(tmp_path):
    with pytest.raises(AutolevError) as info:
        run("Newtonian N\nConstants g\nPoints O\nGravity(g*N1>, O)\n", tmp_path)
    assert info.value.span.line == 4 and "bodies or particles" in info.value.message


def test_ke_and_momentum_of_a_subset(tmp_path):
    src = (
        "Newtonian N\nParticles P, Q\nVariables u{2}'\nConstants mp, mq\n"
        "Mass P=mp, Q=mq\nV_P_N> = u1*N1>\nV_Q_N> = u2*N2>\n"
        "kp = KE(P)\nkall = KE()\nlp> = Momentum(LINEAR, Q)\n"
    )
    mod, _ = run(src, tmp_path)
    assert same([mod.AUTOLEV["KP"]], [mod.mp * mod.u1**2 / 2])
    assert same(
        [mod.AUTOLEV["KALL"]], [mod.mp * mod.u1**2 / 2 + mod.mq * mod.u2**2 / 2]
    )
    assert same(mod.AUTOLEV["LP>"].to_matrix(mod.N), [0, mod.mq * mod.u2, 0])


def test_reserved_looking_names_are_ordinary(tmp_path):
    mod, _ = run("Constants I, J\nk = I + J\nI2 = [1, 0; 0, 1]\n", tmp_path)
    assert str(mod.AUTOLEV["K"]) == "I + J"
    mod, _ = run("I = [1, 0; 0, 1]\nM = 2*I\n", tmp_path, "eye")
    assert mod.AUTOLEV["M"] == 2 * sp.eye(2)


def test_inertia_in_another_frames_basis(tmp_path):
    src = (
        "Newtonian N\nFrames B\nBodies C\nConstants I, J\nVariables q\n"
        "Simprot(N, B, 3, 0)\nSimprot(B, C, 2, q)\n"
        "Inertia C(B), I, J, I, 0, 0, 0\n"
        "M = Matrix(B, I_C_CO>>)\n"
    )
    mod, _ = run(src, tmp_path)
    got = mod.AUTOLEV["M"]
    by_name = {s.name: s for s in got.free_symbols}
    i_, j_ = by_name["I"], by_name["J"]
    assert same(got, sp.diag(i_, j_, i_))  # in B's basis, whatever q is


def test_indexed_names_with_a_suffix(tmp_path):
    mod, _ = run("Newtonian N\nPoints rrf{2}o\nP_RRF1O_RRF2O> = N1>\n", tmp_path)
    assert mod.AUTOLEV["P_RRF1O_RRF2O>"].to_matrix(mod.N) == sp.Matrix([1, 0, 0])
    assert {"RRF1O", "RRF2O"} <= set(mod.AUTOLEV.keys())


# ------------------------------------------------------- DCMs as values


def test_direction_cosines_as_values(tmp_path):
    src = (
        "Newtonian N\nFrames A\nVariables q\nSimprot(N, A, 3, q)\n"
        "c11 = N_A[1,1]\nc21 = N_A[2,1]\nR = N_A\n"
    )
    mod, _ = run(src, tmp_path)
    assert same(
        [mod.AUTOLEV["C11"], mod.AUTOLEV["C21"]], [sp.cos(mod.q), sp.sin(mod.q)]
    )
    assert same(mod.AUTOLEV["R"], mod.N.dcm(mod.A))


# ----------------------------------------------------------- commands


def test_constrain_with_auxiliary_and_dependent_in_one_call(tmp_path):
    body = (
        "Newtonian N\nParticles P\nVariables u{3}'\nConstants m, k\nMass P=m\n"
        "V_P_N> = u1*N1> + u2*N2> + u3*N3>\n"
        "Force_P> = -k*u1*N1> - k*u2*N2>\n"
        "Dependent[1] = u2 - 2*u1\nAuxiliary[1] = u3\n"
    )
    one, _ = run(
        body + "Constrain(Auxiliary[u3], Dependent[u2])\nZero = Fr() + FrStar()\n",
        tmp_path,
        "one",
    )
    two, _ = run(
        body
        + "Constrain(Auxiliary[u3])\nConstrain(Dependent[u2])\nZero = Fr() + FrStar()\n",
        tmp_path,
        "two",
    )
    z1, z2 = one.AUTOLEV["ZERO"], two.AUTOLEV["ZERO"]
    assert z1.shape == z2.shape == (2, 1)
    assert str(z1) == str(z2)
    # the independent speed u1 (u2 = 2*u1): -5*k*u1 - 5*m*u1'
    u1 = one.u1
    want = -5 * one.k * u1 - 5 * one.m * u1.diff(T)
    assert sp.simplify(z1[0].subs(one.u2, 2 * u1) - want) == 0


def test_code_options_after_the_file_name(tmp_path):
    src = (
        "Variables x'\nConstants a\nx' = -a*x\nInput a=2, x=1, tFinal=1, integStp=0.1\n"
        "Output T, x\nCODE ODE() f.c, NOSUBS\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    assert np.allclose(result["X"], np.exp(-2 * result["T"]), atol=1e-6)


def test_unknown_code_option_is_reported(tmp_path):
    with pytest.raises(AutolevError) as info:
        run("Variables x'\nx' = -x\nCODE ODE() f.c, FAST\n", tmp_path)
    assert "CODE option FAST is not supported" in info.value.message


def test_solve_for_a_matrix_of_unknowns(tmp_path):
    src = (
        "Variables q{2}''\nConstants a, b\n"
        "Zero = [q1'' + q2'' - a; q1'' - q2'' - b]\n"
        "qdd = [q1''; q2'']\n"
        "Solve(Zero, qdd)\n"
    )
    mod, _ = run(src, tmp_path)
    assert same(
        [mod.AUTOLEV["Q1''"], mod.AUTOLEV["Q2''"]],
        [(mod.a + mod.b) / 2, (mod.a - mod.b) / 2],
    )


# ------------------------------------------------------- numerical jobs


def test_input_as_an_expression_of_other_inputs(tmp_path):
    src = (
        "Constants qq1, e4, k\nVariables x'\nx' = -k*x\n"
        "Input qq1 = 60 deg, e4 = cos(qq1/2)*2, k = e4\n"
        "Input x=1, tFinal=1, integStp=0.5\nOutput T, x\nCODE ODE() f.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    k = 2 * np.cos(np.pi / 6)
    assert np.allclose(result["X"], np.exp(-k * result["T"]), atol=1e-6)
    assert mod.evaluate("E4") == pytest.approx(k)


def test_units_statement_sets_default_units(tmp_path):
    src = (
        "Variables x'\nx' = 1\nUnits T=S, X=cm\n"
        "Input x=0, tFinal=1, integStp=0.5\nOutput T, x\nCODE ODE() f.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    assert result.tables[0].columns[1].unit == "cm"
    # x is in cm: x(1 s) = 1 cm/s * ... the equation is in internal units (m)
    assert result["X"][-1] == pytest.approx(100.0)


def test_printint_counts_integration_steps(tmp_path):
    src = (
        "Variables x'\nx' = 1\nInput x=0, tFinal=2, integStp=0.1, printInt=5\n"
        "Output T, x\nCODE ODE() f.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    assert np.allclose(result["T"], [0, 0.5, 1.0, 1.5, 2.0])


def test_unspecified_specified_is_zero_with_a_note(tmp_path):
    src = (
        "Newtonian N\nParticles P\nVariables x', u1'\nConstants m, k\nSpecified f''\n"
        "Mass P=m\nx' = u1\nP_NO_P> = x*N1>\nV_P_N> = u1*N1>\n"
        "Force_P> = (-k*x + f'')*N1>\nZero = Fr() + FrStar()\nKane()\n"
        "Input m=1, k=4, x=1, u1=0, tFinal=1, integStp=0.1\nOutput T, x\n"
        "CODE Dynamics() s.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    assert np.allclose(result["X"], np.cos(2 * result["T"]), atol=1e-5)
    assert any("F''" in note and "using 0" in note for note in result.notes)


def test_encode_computes_quantities_at_every_row(tmp_path):
    src = (
        "Newtonian N\nBodies A\nConstants g, l, m, i\nVariables q', u1'\n"
        "Mass A=m\nInertia A, 0, 0, i\nSimprot(N, A, 3, q)\nq' = u1\n"
        "W_A_N> = u1*A3>\nP_NO_AO> = l/2*A1>\nV_AO_N> = Dt(P_NO_AO>, N)\n"
        "Gravity(g*N1>)\nZero = Fr() + FrStar()\nKane()\n"
        "k = m*l^2/8*u1^2\naMat = [q, u1; k, 2*k]\n"
        "Input g=9.81, l=2, m=4, i=0.5, q=30 deg, u1=0, tFinal=1, integStp=0.1\n"
        "Output T, q deg\nEncode q', k, aMat\nCode Dynamics() enc.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    assert result.files() == ["enc.1"]  # encoded quantities are not written
    u1 = result["Q'"]
    assert np.allclose(result["K"], 4 * 4 / 8 * u1**2)
    amat = result["AMAT"]
    assert amat.shape == (11, 2, 2)
    assert np.allclose(amat[:, 1, 1], 2 * result["K"])
    assert np.allclose(np.degrees(amat[:, 0, 0]), result["Q"])
    # evaluate() substitutes the Inputs and the values given
    assert mod.evaluate("K", U1=2) == pytest.approx(8.0)
    assert mod.evaluate("ZERO", {"U1'": 1})[0, 0] == pytest.approx(-24.12)


# ------------------------------------------------------------ errors


def test_every_syntax_error_is_reported_once(tmp_path):
    src = "Constants a\nx = (a +\ny = a a\nz = 1\nw = a)\n"
    with pytest.raises(AutolevError) as info:
        run(src, tmp_path)
    errors = info.value.errors  # type: ignore[attr-defined]
    assert [(e.span.line, e.span.col) for e in errors] == [(2, 9), (3, 7), (5, 6)]


def test_autoz_name_from_a_session_gets_a_hint(tmp_path):
    with pytest.raises(AutolevError) as info:
        run("Variables u\nx = Z12*u\n", tmp_path)
    assert "AutoZ" in info.value.message and info.value.span.col == 5


def test_a_dot_multiplies_unit_words(tmp_path):
    """``Units P=KG.M/S`` and ``Input I=2 KG.M^2``: research scripts write a
    product of units with a dot (the lexer reads ``KG.M`` as one word)."""
    src = (
        "Constants I\nVariables x'\nx' = I\nP = I*x\nUnits T=S, P=KG.M/S, X=G.CM\n"
        "Input I=2 KG.M^2, x=0, tFinal=1, integStp=0.5\nOutput T, x, P\n"
        "CODE ODE() f.c\n"
    )
    mod, _ = run(src, tmp_path)
    result = mod.run()
    table = result.tables[0]
    assert [c.unit for c in table.columns[1:]] == ["G.CM", "KG.M/S"]
    # x' = 2 (internal units, kg*m): x(1) = 2 kg*m = 2e5 g*cm; P = I*x = 4
    assert result["X"][-1] == pytest.approx(2e5)
    assert result["P"][-1] == pytest.approx(4.0)


def test_input_function_of_a_computed_input(tmp_path):
    """``Input(X)`` where X's Input is an expression of other Inputs: the
    value the job computes (it was a library error)."""
    src = (
        "Constants a, b, c\nVariables q'\nq' = -a*q\n"
        "Input a = 2, b = cos(a/2)*3, c = 90 deg\nInput q = 1\n"
        "x = Input(b) + Input(a)\ny = Input(c) + Input(c, UnitSystem)\n"
        "Output T, q\nCODE ODE() f.c\n"
    )
    mod, _ = run(src, tmp_path)
    assert float(mod.AUTOLEV["X"]) == pytest.approx(3 * np.cos(1) + 2)
    assert float(mod.AUTOLEV["Y"]) == pytest.approx(90 + np.pi / 2)


def test_input_function_of_a_constant_given_a_value(tmp_path):
    """``Input(A)`` of a constant assigned a value (``A = PI/2``) rather than
    given an Input is that value, from the Inputs it uses; a constant with
    neither stays an error naming it."""
    src = (
        "Constants L, A, B, C\nA = pi/2\nInput L = 2\nB = 3*L + A\n"
        "X = Input(A) + 1\nY = Input(B)\n"
    )
    mod, _ = run(src, tmp_path)
    assert float(mod.AUTOLEV["X"]) == pytest.approx(np.pi / 2 + 1)
    assert float(mod.AUTOLEV["Y"]) == pytest.approx(6 + np.pi / 2)
    with pytest.raises(Exception, match="C has no Input value"):
        run(src + "Z = Input(C)\n", tmp_path, "snip_c")


def test_kane_with_forces_after_constrain_of_declared_auxiliary_speeds(tmp_path):
    """``MotionVariables' U', UA'`` with ``Constrain(AUXILIARY[UA])``: UA
    keeps its Fr row although Constrain gave UA' a value too; ``Kane(TEN)``
    solves that row for the rod's tension and rewrites ZERO, and the
    script's ``Zero`` follows (``Solve(Zero, U')`` sees one row)."""
    src = (
        "Newtonian N\nBodies A\nParticles P\nVariables Q', TEN\n"
        "MotionVariables' U', UA'\nConstants m, g, l\nMass A = 0, P = m\n"
        "Inertia A, 0, 0, 0\nSimprot(N, A, 3, Q)\nQ' = U\nW_A_N> = U*A3>\n"
        "P_AO_P> = l*A1>\nV_P_N> = U*l*A2> + UA*A1>\nA_P_N> = Dt(V_P_N>, N)\n"
        "Gravity(-g*N2>)\nForce_P> += -TEN*A1>\nAUXILIARY[1] = UA\n"
        "Constrain(AUXILIARY[UA])\nZero = Fr() + FrStar()\nKane(TEN)\n"
        "Solve(Zero, U')\n"
    )
    mod, code = run(src, tmp_path)
    assert "Zero = al.model.kane(" in code
    q, u, m, g, length = (mod.al.symbol(n) for n in ("Q", "U", "M", "G", "L"))
    point = {q: 0.7, u: 1.3, m: 2.0, g: 9.81, length: 0.8}
    tension = mod.AUTOLEV["TEN"].xreplace(point)
    want = 2.0 * 0.8 * 1.3**2 - 2.0 * 9.81 * np.sin(0.7)
    assert float(tension) == pytest.approx(want)
    assert mod.AUTOLEV["ZERO"].shape == (1, 1)
    acc = mod.AUTOLEV["U'"].xreplace(point)
    assert float(acc) == pytest.approx(-9.81 * np.cos(0.7) / 0.8)


@pytest.mark.parametrize(
    "units",
    [
        "UNITS [a, b]= METRES, [c]=KG, x=CM",
        "UNITS [a, b] = M",
        "Units [a] = M, [b] = M",
        "Units [a, b] = M/S^2*S^2",
    ],
)
def test_units_for_a_bracketed_group_of_names(tmp_path, units):
    """``Units [A, B] = M`` gives each name of the group the unit (one group
    alone reads like an assignment to ``UNITS[A, B]``)."""
    src = (
        "Constants a, b, c\nVariables x'\nx' = a + b\n"
        f"{units}\nInput a=2, b=1, c=1, x=0, tFinal=1, integStp=0.5\n"
        "Output T, x\nCODE ODE() f.c\n"
    )
    mod, code = run(src, tmp_path)
    assert '"A": "' in code and '"B": "' in code
    result = mod.run()
    # x' = a + b = 3 m/s: x(1) = 3 m (300 in CM, when x has that unit)
    want = 300.0 if "CM" in units else 3.0
    assert result["X"][-1] == pytest.approx(want)


def test_a_bracketed_group_belongs_to_units():
    from al2py.errors import AutolevError

    with pytest.raises(AutolevError, match="belongs to Units"):
        convert("Constants a, b\nEncode [a] = M, [b] = M\n", "g.al")


def test_assigned_u_variables_are_not_the_speeds(tmp_path):
    """``Variables U{2}`` assigned expressions (``U1 = Dot(W_A_N>, A3>)``)
    name quantities; the generalized speed is the motion variable W."""
    src = (
        "Newtonian N\nBodies A\nVariables Q', U{2}\nMotionVariables' W'\n"
        "Constants m, g, l, k\nMass A = m\nInertia A, 0, 0, k\n"
        "Simprot(N, A, 3, Q)\nW_A_N> = W*N3>\nU1 = Dot(W_A_N>, A3>)\n"
        "U2 = 2*U1\nQ' = W\nP_NO_AO> = l*A1>\nV_AO_N> = Dt(P_NO_AO>, N)\n"
        "A_AO_N> = Dt(V_AO_N>, N)\nGravity(-g*N2>)\nZero = Fr() + FrStar()\n"
    )
    mod, _ = run(src, tmp_path)
    zero = mod.AUTOLEV["ZERO"]
    assert zero.shape == (1, 1)
    t = sp.Symbol("t")
    q, w, m, g, length, k = (mod.al.symbol(n) for n in ("Q", "W", "M", "G", "L", "K"))
    expected = -(m * length**2 + k) * sp.Derivative(w, t) - m * g * length * sp.cos(q)
    diff = (zero[0] - expected).subs(sp.Derivative(w, t), 0.7)
    values = {q: 0.3, w: 1.1, m: 2.0, g: 9.8, length: 0.5, k: 0.2}
    assert abs(float(diff.subs(values))) < 1e-12


def test_small_solve_of_large_equations_uses_elimination():
    """With AutoZ OFF a 2-unknown Solve over large equations eliminates with
    intermediates instead of Cramer's rule and factor_terms (which ran for
    minutes on a rolling disc's written-out equations); small ones keep the
    closed form Autolev printed."""
    from al2py_runtime import Workspace, algebra

    al = Workspace("big.al")
    q = sp.symbols("q1:400")
    big = sp.Add(
        *[
            sp.sin(a) * sp.cos(b) * c
            for a, b, c in zip(q[:-2], q[1:-1], q[2:], strict=True)
        ]
    )
    assert al.solver_book(2, sp.Matrix([big, 2 * big])) is al.book
    assert al.solver_book(2, sp.Matrix([q[0] + q[1], q[1]])) is None
    small = 2 * q[0] + 2 * q[1]
    assert algebra._factor_small(small) == sp.factor_terms(small) != small
    assert algebra._factor_small(2 * big) == 2 * big
