# ruff: noqa: E741
"""Tutorial scripts (§5.2-5.9) and transcripts written against the mechanics API.

Each builder is a hand-written equivalent of what the generator emits for a
tutorial ``.al`` file; results are compared mathematically (random numeric
substitution after resolving right-hand sides), never as text.
"""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp
from al2py_runtime import Workspace, t
from sympy.physics.vector import Vector

D = sp.Derivative


def numeric(expr, al=None, values=None, seed=1):
    """Evaluate ``expr`` at reproducible random values of every symbol."""
    if al is not None:
        expr = al.resolve(expr)
    expr = sp.sympify(expr)
    table = dict(values or {})
    derivs = sorted(expr.atoms(sp.Derivative), key=sp.default_sort_key)
    funcs = sorted(expr.atoms(sp.core.function.AppliedUndef), key=sp.default_sort_key)
    for a in derivs + funcs:
        if a not in table:
            r = random.Random(f"{seed}{sp.srepr(a)}")
            table[a] = sp.Float(r.uniform(0.3, 1.7) * r.choice((1, -1)))
    expr = expr.xreplace({d: table[d] for d in derivs}).xreplace(
        {f: table[f] for f in funcs}
    )
    syms = sorted(expr.free_symbols, key=sp.default_sort_key)
    for s in syms:
        if s not in table:
            # name-based so both sides of a comparison agree
            r = random.Random(f"{seed}{s.name}")
            table[s] = sp.Float(r.uniform(0.5, 2.0))
    return complex(expr.xreplace({s: table[s] for s in syms}).evalf())


def same(a, b, al=None, tol=1e-9, seeds=(1, 2, 3)):
    for seed in seeds:
        x, y = numeric(a, al, seed=seed), numeric(b, al, seed=seed)
        if abs(x - y) > tol * max(1.0, abs(x), abs(y)):
            return False
    return True


# ---------------------------------------------------------------- tutor4


def tutor4():
    al = Workspace("tutor4.al")
    N = al.model.newtonian("N")
    A, B = al.model.frames("A", "B")
    P, Q = al.model.particles("P", "Q")
    O = al.model.points("O")
    U1, U2 = al.variables("U1", "U2")
    QA, QB = al.variables("QA'", "QB'")
    G, LA, LB = al.constants("G", "LA", "LB")
    K, LO = al.constants("K", "LO")
    MP, MQ = al.constants("MP+", "MQ+")
    al.model.set_mass(P, MP)
    al.model.set_mass(Q, MQ)
    al.model.simprot(N, A, 3, QA, line=17)
    al.model.simprot(N, B, 3, QB, line=18)
    al.assign("P_O_P>", LA * A.x, line=21)
    al.assign("P_P_Q>", LB * B.x, line=22)
    al.assign("QA'", U1 / LA, line=25)
    al.assign("QB'", U2 / LB, line=26)
    al.assign("W_A_N>", D(QA, t) * A.z, line=29)
    al.assign("W_B_N>", D(QB, t) * B.z, line=30)
    al.assign("V_O_N>", Vector(0), line=33)
    al.model.v2pts(N, A, O, P, line=34)
    al.model.v2pts(N, B, P, Q, line=35)
    al.model.gravity(G * N.x)
    LOQ = al.assign("LOQ", al.model.mag(al["P_O_Q>"]), line=39)
    STRETCH = al.assign("STRETCH", LOQ - LO, line=40)
    UVEC = al.assign("UVEC>", al["P_O_Q>"] / LOQ, line=41)
    al.model.force_between(O, Q, -K * STRETCH * UVEC)
    al.assign("ZERO", al.model.fr(), line=45)
    return al, locals()


def test_tutor4_equilibrium_equations():
    al, v = tutor4()
    LA, LB, QA, QB, K, G = (v[k] for k in ("LA", "LB", "QA", "QB", "K", "G"))
    MP, MQ, LOQ, STRETCH = v["MP"], v["MQ"], v["LOQ"], v["STRETCH"]
    loq = (LA**2 + LB**2 + 2 * LA * LB * sp.cos(QA - QB)) ** sp.Rational(1, 2)
    assert same(al["LOQ"], loq)
    z1 = K * LB * sp.sin(QA - QB) * STRETCH / LOQ - G * (MP + MQ) * sp.sin(QA)
    z2 = -G * MQ * sp.sin(QB) - K * LA * sp.sin(QA - QB) * STRETCH / LOQ
    assert same(al["ZERO[1]"], z1, al)
    assert same(al["ZERO[2]"], z2, al)
    # kept symbolic, as Autolev prints them
    assert al["ZERO[1]"].has(STRETCH) and al["ZERO[1]"].has(LOQ)


def test_tutor4_responses_and_forms():
    al, v = tutor4()
    labels = [r.label for r in al.responses]
    for label in ("N_A", "N_B", "P_O_P>", "V_P_N>", "V_Q_N>", "ZERO"):
        assert label in labels
    N, A, Q, O, U1 = v["N"], v["A"], v["Q"], v["O"], v["U1"]
    # reversal and chaining of positions
    assert al["P_Q_O>"] == -al["P_O_Q>"]
    assert al.model.pos(O, Q) == al["P_O_P>"] + al["P_P_Q>"]
    # V_P_N> = U1*A2> once the kinematical equation is used
    vp = al["V_P_N>"]
    assert same(al.model.dot(vp, A.y), U1, al) and same(al.model.dot(vp, A.x), 0, al)
    # DCM elements and names
    assert al["N_A[1,2]"] == -sp.sin(v["QA"])
    assert al.model.point("O") is O and al.model.frame("a") is A
    assert al["FORCE_Q>"] == al.model.force_on(Q)
    assert al.model.vel(al.model.point("NO"), N) == Vector(0)


# ------------------------------------------------------ tutor5 / tutor7


def fourbar(mode):
    """tutor5 (mode "static"), tutor7 ("dependent"), tutor7c ("aux2"),
    tutor7a ("aux3")."""
    al = Workspace("tutor7.al")
    N = al.model.newtonian("N")
    A, B, C = al.model.bodies("A", "B", "C")
    O, P, Q, R = al.model.points("O", "P", "Q", "R")
    n_speeds = 4 if mode == "aux3" else 3
    us = al.variables(*[f"U{i}'" for i in range(1, n_speeds + 1)])
    U1, U2, U3 = us[:3]
    QA, QB, QC = al.variables("QA'", "QB'", "QC'")
    FA1, FA2, FC1, FC2 = al.variables("FA1", "FA2", "FC1", "FC2")
    G = al.constants("G")
    al.assign("G", 9.81)
    LA, LB, LC, LN = al.constants("LA", "LB", "LC", "LN")
    for name, val in (("LA", 1), ("LB", 2), ("LC", 2), ("LN", 1)):
        al.assign(name, val)
    if mode == "static":
        H = al.constants("H")
    MA, MB, MC = al.constants("MA+", "MB+", "MC+")
    for body, m, val, length in ((A, MA, 10, LA), (B, MB, 20, LB), (C, MC, 20, LC)):
        al.model.set_mass(body, m)
        al.assign(str(m), val)
        al.model.set_inertia(body, 0, m * length**2 / 12, m * length**2 / 12)
    al.model.simprot(N, A, 3, QA)
    al.model.simprot(N, B, 3, QB)
    al.model.simprot(N, C, 3, QC)
    al.assign("P_O_P>", LA * A.x)
    al.assign("P_P_Q>", LB * B.x)
    al.assign("P_R_Q>", LC * C.x)
    al.assign("P_O_R>", LN * N.y)
    al.assign("P_O_AO>", 0.5 * al["P_O_P>"])
    al.assign("P_P_BO>", 0.5 * al["P_P_Q>"])
    al.assign("P_R_CO>", 0.5 * al["P_R_Q>"])
    al.assign("QA'", U1)
    al.assign("QB'", U2)
    al.assign("QC'", U3)
    al.assign("W_A_N>", D(QA, t) * A.z)
    al.assign("W_B_N>", D(QB, t) * B.z)
    al.assign("W_C_N>", D(QC, t) * C.z)
    loop = al.assign("LOOP>", al["P_O_P>"] + al["P_P_Q>"] + al["P_Q_R>"] + al["P_R_O>"])
    al.assign("CONFIG[1]", al.model.dot(loop, N.x))
    al.assign("CONFIG[2]", al.model.dot(loop, N.y))
    if mode == "aux3":
        al.assign("V_O_N>", us[3] * N.x)
    else:
        al.assign("V_O_N>", 0)
    AO, BO, CO = al.model.point("AO"), al.model.point("BO"), al.model.point("CO")
    al.model.v2pts(N, A, O, AO)
    al.model.v2pts(N, A, O, P)
    al.model.v2pts(N, B, P, BO)
    al.model.v2pts(N, B, P, Q)
    al.model.v2pts(N, C, Q, CO)
    al.model.v2pts(N, C, Q, R)
    which = "DEPENDENT" if mode in ("static", "dependent") else "AUXILIARY"
    al.assign(f"{which}[1]", al.model.dot(al["V_R_N>"], N.x))
    al.assign(f"{which}[2]", al.model.dot(al["V_R_N>"], N.y))
    if mode == "aux3":
        al.assign("AUXILIARY[3]", al.model.dot(al["V_O_N>"], N.x))
        al.model.constrain(which, [U2, U3, us[3]], line=70)
    else:
        al.model.constrain(which, [U2, U3], line=70)
    if mode == "static":
        al.model.gravity(G * N.x)
        al.assign("FORCE_Q>", H * N.y)
        al.assign("ZERO", al.model.fr())
        al.assign("ZERO[2]", al["CONFIG[1]"])
        al.assign("ZERO[3]", al["CONFIG[2]"])
        return al, locals()
    al.assign("ALF_A_N>", al.dt(al["W_A_N>"], N))
    al.assign("ALF_B_N>", al.dt(al["W_B_N>"], N))
    al.assign("ALF_C_N>", al.dt(al["W_C_N>"], N))
    al.assign("A_O_N>", 0)
    al.model.a2pts(N, A, O, AO)
    al.model.a2pts(N, A, O, P)
    al.model.a2pts(N, B, P, BO)
    al.model.a2pts(N, B, P, Q)
    al.model.a2pts(N, C, Q, CO)
    al.model.gravity(G * N.x)
    al.assign("FORCE_O>", FA1 * N.x + FA2 * N.y)
    if mode != "dependent":
        al.assign("FORCE_R>", FC1 * N.x + FC2 * N.y)
    al.assign("ZERO", al.model.fr() + al.model.frstar())
    if mode == "dependent":
        al.model.kane(line=90)
    elif mode == "aux2":
        al.model.kane(FC1, FC2, line=90)
    else:
        al.model.kane(FC1, FC2, FA1, line=90)
    return al, locals()


def test_tutor5_static_four_bar():
    al, v = fourbar("static")
    QA, QB, QC, H = v["QA"], v["QB"], v["QC"], v["H"]
    s, c = sp.sin, sp.cos
    z1 = (
        H * (c(QA) - c(QB) * s(QA - QC) / s(QB - QC))
        + sp.Float(98.1) * (3 * s(QB) * s(QA - QC) - s(QC) * s(QA - QB)) / s(QB - QC)
        - sp.Float(441.45) * s(QA)
    )
    assert same(al["ZERO[1]"], z1, al)
    assert same(al["ZERO[2]"], c(QA) + 2 * c(QB) - 2 * c(QC), al)
    assert same(al["ZERO[3]"], s(QA) + 2 * s(QB) - 2 * s(QC) - 1, al)


def test_tutor3_configuration_constraints():
    al = Workspace("tutor3.al")
    A, B, C, N = al.model.frames("A", "B", "C", "N")
    O, P, Q, R = al.model.points("O", "P", "Q", "R")
    QA, QB, QC = al.variables("QA", "QB", "QC")
    LA, LB, LC, LN = al.constants("LA", "LB", "LC", "LN")
    al.model.simprot(N, A, 3, QA)
    al.model.simprot(N, B, 3, QB)
    al.model.simprot(N, C, 3, QC)
    al.assign("P_O_P>", LA * A.x)
    al.assign("P_P_Q>", LB * B.x)
    al.assign("P_R_Q>", LC * C.x)
    al.assign("P_O_R>", LN * N.y)
    loop = al.assign("LOOP>", al["P_O_P>"] + al["P_P_Q>"] + al["P_Q_R>"] + al["P_R_O>"])
    c1 = al.assign("CONFIG[1]", al.model.dot(loop, N.x))
    c2 = al.assign("CONFIG[2]", al.model.dot(loop, N.y))
    s, c = sp.sin, sp.cos
    assert sp.simplify(c1[0] - (LA * c(QA) + LB * c(QB) - LC * c(QC))) == 0
    assert sp.simplify(c2[1] - (LA * s(QA) + LB * s(QB) - LC * s(QC) - LN)) == 0


def test_constrain_transcript():
    al = Workspace("constrain.al")
    N = al.model.newtonian("N")
    A, B, C = al.model.bodies("A", "B", "C")
    al.model.points("P")
    U1, U2, U3 = al.variables("U1", "U2", "U3")
    QA, QB, QC = al.variables("QA", "QB", "QC")
    LA, LB, LC = al.constants("LA", "LB", "LC")
    VX, VY = al.specified("VX", "VY")
    al.model.simprot(N, A, 3, QA, line=9)
    al.model.simprot(N, B, 3, QB, line=11)
    al.model.simprot(N, C, 3, QC, line=13)
    al.assign("V_P_N>", LA * U1 * A.y + LB * U2 * B.y + LC * U3 * C.y, line=15)
    al.assign("DEPENDENT[1]", al.model.dot(al["V_P_N>"], N.x) - VX, line=17)
    al.assign("DEPENDENT[2]", al.model.dot(al["V_P_N>"], N.y) - VY, line=19)
    al.model.constrain("DEPENDENT", [U2, U3], line=21)
    s, c = sp.sin, sp.cos
    got = {r.label: r for r in al.responses}
    assert got["N_A"].value == sp.Matrix(
        [[c(QA), -s(QA), 0], [s(QA), c(QA), 0], [0, 0, 1]]
    )
    assert got["N_A"].line == 9
    u2 = -(VX * c(QC) + VY * s(QC) + LA * s(QA - QC) * U1) / (LB * s(QB - QC))
    u3 = (VX * c(QB) + VY * s(QB) + LA * s(QA - QB) * U1) / (LC * s(QB - QC))
    assert got["U2"].line == 21 and got["U3"].line == 21
    assert sp.simplify(got["U2"].value - u2) == 0
    assert sp.simplify(got["U3"].value - u3) == 0
    assert [r.label for r in al.responses][-2:] == ["U2", "U3"]  # U' not declared


def test_tutor7_variants_agree():
    """tutor7 (dependent speeds), tutor7c and tutor7a (auxiliary speeds) give
    the same equation of motion; 7c and 7a the same reaction at R."""
    al, v = fourbar("dependent")
    al_c, vc = fourbar("aux2")
    al_a, va = fourbar("aux3")
    for w in (al, al_c, al_a):
        z = w["ZERO"]
        assert z.shape == (1, 1)  # one equation per independent speed
        assert not z[0].has(v["U2"], v["U3"], D(v["U2"], t))
        assert sp.diff(z[0], D(v["U1"], t)) != 0
    assert same(al["ZERO[1]"], al_c["ZERO[1]"])
    assert same(al["ZERO[1]"], al_a["ZERO[1]"])
    assert same(al_c.rhs(vc["FC1"]), al_a.rhs(va["FC1"]))
    assert same(al_c.rhs(vc["FC2"]), al_a.rhs(va["FC2"]))
    assert not al_a.rhs(va["FA1"]).has(va["FC1"])
    labels = [r.label for r in al_a.responses]
    assert {"FC1", "FC2", "FA1", "ZERO", "U2", "U3", "U4", "U2'"} <= set(labels)


def test_tutor7_against_sympy_kanes_method():
    from sympy.physics.mechanics import KanesMethod, RigidBody, inertia

    al, v = fourbar("dependent")
    N, A, B, C = v["N"], v["A"], v["B"], v["C"]
    QA, QB, QC, U1, U2, U3 = (v[k] for k in ("QA", "QB", "QC", "U1", "U2", "U3"))
    R = v["R"]
    bodies = []
    for frame, m, length in ((A, 10, 1), (B, 20, 2), (C, 20, 2)):
        cm = al.model.point(frame.name + "O")
        cm.set_vel(N, al.model.actual_value(al.model.vel(cm, N), [U1, U2, U3]))
        i = inertia(
            frame, 0, sp.Rational(m * length**2, 12), sp.Rational(m * length**2, 12)
        )
        frame.set_ang_vel(
            N, al.model.actual_value(al.model.ang_vel(frame, N), [U1, U2, U3])
        )
        bodies.append(RigidBody(frame.name, cm, frame, m, (i, cm)))
    g = sp.Rational(981, 100)
    loads = [(b.masscenter, b.mass * g * N.x) for b in bodies]
    vr = al.model.actual_value(al.model.vel(R, N), [U1, U2, U3])
    km = KanesMethod(
        N,
        q_ind=[QA, QB, QC],
        u_ind=[U1],
        u_dependent=[U2, U3],
        kd_eqs=[D(QA, t) - U1, D(QB, t) - U2, D(QC, t) - U3],
        velocity_constraints=[vr.dot(N.x), vr.dot(N.y)],
    )
    fr, frstar = km.kanes_equations(bodies, loads)
    ref = al.model._speed_subs((fr + frstar)[0])
    assert same(al["ZERO[1]"], ref)


# ------------------------------------------------------ tutor6 / tutor6f


def tutor6(contact_forces=False):
    al = Workspace("tutor6.al")
    N = al.model.newtonian("N")
    A, B = al.model.frames("A", "B")
    P, Q = al.model.particles("P", "Q")
    O = al.model.points("O")
    us = al.variables(*[f"U{i}'" for i in range(1, 5 if contact_forces else 3)])
    U1, U2 = us[:2]
    QA, QB = al.variables("QA'", "QB'")
    F1, F2 = al.variables("F1", "F2")
    G, LA, LB = al.constants("G", "LA", "LB")
    K, LO = al.constants("K", "LO")
    C, DD = al.constants("C", "D")
    STRETCH = al.specified("STRETCH'")
    FP = al.specified("FP")
    al.assign("FP", -DD * D(QA, t))
    MP, MQ = al.constants("MP+", "MQ+")
    al.model.set_mass(P, MP)
    al.model.set_mass(Q, MQ)
    al.model.simprot(N, A, 3, QA)
    al.model.simprot(N, B, 3, QB)
    al.assign("P_O_P>", LA * A.x)
    al.assign("P_P_Q>", LB * B.x)
    al.assign("QA'", U1 / LA)
    al.assign("QB'", U2 / LB)
    al.assign("W_A_N>", D(QA, t) * A.z)
    al.assign("W_B_N>", D(QB, t) * B.z)
    if contact_forces:
        al.assign("V_O_N>", us[2] * N.x + us[3] * N.y)
    else:
        al.assign("V_O_N>", Vector(0))
    al.model.v2pts(N, A, O, P)
    al.model.v2pts(N, B, P, Q)
    if contact_forces:
        al.assign("AUXILIARY[1]", al.model.dot(al["V_O_N>"], N.x))
        al.assign("AUXILIARY[2]", al.model.dot(al["V_O_N>"], N.y))
        al.model.constrain("AUXILIARY", [us[2], us[3]])
    al.model.gravity(G * N.x)
    al.assign("FORCE_P>", al["FORCE_P>"] + FP * A.y)
    LOQ = al.assign("LOQ", al.model.mag(al["P_O_Q>"]))
    al.assign("STRETCH", LOQ - LO)
    UVEC = al.assign("UVEC>", al["P_O_Q>"] / LOQ)
    al.assign("STRETCH'", al.model.dot(al["V_Q_N>"], UVEC))
    al.model.force_between(O, Q, (-K * STRETCH - C * D(STRETCH, t)) * UVEC)
    al.assign("FORCE_O>", al["FORCE_O>"] + F1 * N.x + F2 * N.y)
    al.assign("ZERO", al.model.fr() + al.model.frstar(), line=62)
    zero_before_kane = al["ZERO"]
    if contact_forces:
        al.model.kane(F1, F2, line=64)
    else:
        al.model.kane(line=64)
    return al, locals()


def test_tutor6_equations_of_motion():
    al, v = tutor6()
    LA, LB, QA, QB, U1, U2 = (v[k] for k in ("LA", "LB", "QA", "QB", "U1", "U2"))
    K, C, G, MP, MQ, FP = (v[k] for k in ("K", "C", "G", "MP", "MQ", "FP"))
    LOQ, STRETCH = v["LOQ"], v["STRETCH"]
    s, c = sp.sin, sp.cos
    loq = sp.sqrt(LA**2 + LB**2 + 2 * LA * LB * c(QA - QB))
    assert same(al["LOQ"], loq)
    sdot = s(QA - QB) * (LA * U2 - LB * U1) / LOQ
    assert same(al["STRETCH'"], sdot, al)
    ks = K * STRETCH + C * D(STRETCH, t)
    z1 = (
        FP
        + s(QA - QB) * (LB**2 * ks / LOQ - MQ * U2**2) / LB
        - G * (MP + MQ) * s(QA)
        - (MP + MQ) * D(U1, t)
        - MQ * c(QA - QB) * D(U2, t)
    )
    z2 = (
        MQ * s(QA - QB) * U1**2 / LA
        - G * MQ * s(QB)
        - MQ * D(U2, t)
        - MQ * c(QA - QB) * D(U1, t)
        - LA * ks * s(QA - QB) / LOQ
    )
    before = v["zero_before_kane"]
    assert same(before[0], z1, al) and same(before[1], z2, al)
    assert same(al["ZERO[1]"], z1, al) and same(al["ZERO[2]"], z2, al)
    # after Kane: linear in U1', U2' and free of QA', QB'
    for row in al["ZERO"]:
        assert not row.has(D(QA, t), D(QB, t))
        for u in (U1, U2):
            assert not sp.diff(row, D(u, t)).has(D(U1, t), D(U2, t))


def test_tutor6f_contact_forces():
    al, v = tutor6(contact_forces=True)
    LA, LB, QA, QB, U1, U2 = (v[k] for k in ("LA", "LB", "QA", "QB", "U1", "U2"))
    G, MP, MQ, FP = (v[k] for k in ("G", "MP", "MQ", "FP"))
    s, c = sp.sin, sp.cos
    d1, d2 = D(U1, t), D(U2, t)
    f1 = (
        FP * s(QA)
        - G * (MP + MQ)
        - MP * c(QA) * U1**2 / LA
        - MQ * s(QB) * d2
        - (MP + MQ) * s(QA) * d1
        - MQ * (c(QA) * U1**2 / LA + c(QB) * U2**2 / LB)
    )
    f2 = (
        MQ * c(QB) * d2
        + (MP + MQ) * c(QA) * d1
        - FP * c(QA)
        - MP * s(QA) * U1**2 / LA
        - MQ * (s(QA) * U1**2 / LA + s(QB) * U2**2 / LB)
    )
    assert same(al.rhs(v["F1"]), f1, al)
    assert same(al.rhs(v["F2"]), f2, al)
    # the remaining equations are tutor6's
    ref, _ = tutor6()
    assert al["ZERO"].shape == (2, 1)
    assert same(al["ZERO[1]"], ref["ZERO[1]"], al)
    assert same(al["ZERO[2]"], ref["ZERO[2]"], al)
    assert al.rhs(v["us"][2]) == 0 and al["U4'"] == 0


# ---------------------------------------------------------------- tutor8


def tutor8():
    al = Workspace("tutor8.al")
    al.settings.set("Digits", 2)
    N = al.model.newtonian("N")
    A, B = al.model.bodies("A", "B")
    O = al.model.points("O")
    U1, U2 = al.variables("U1'", "U2'")
    X, THETA = al.variables("X'", "THETA'")
    L = al.constants("L")
    G = al.constants("G")
    K1, K2, K3, K4 = al.constants("K1", "K2", "K3", "K4")
    F = al.specified("F")
    al.assign("F", K1 * X + K2 * THETA + K3 * U1 + K4 * U2)
    MA, MB = al.constants("MA+", "MB+")
    al.model.set_mass(A, MA)
    al.model.set_mass(B, MB)
    IB = al.constants("IB")
    al.assign("IB", MB * L**2 / 12)
    al.model.set_inertia(B, IB, 0, IB)
    al.model.simprot(N, B, 3, THETA)
    AO, BO = al.model.point("AO"), al.model.point("BO")
    al.assign("P_O_AO>", X * N.x)
    al.assign("P_AO_BO>", 0.5 * L * B.y)
    al.assign("X'", U1)
    al.assign("THETA'", U2)
    al.assign("W_A_N>", Vector(0))
    al.assign("W_B_N>", D(THETA, t) * B.z)
    al.assign("V_AO_N>", al.dt(al["P_O_AO>"], N))
    al.model.v2pts(N, B, AO, BO)
    al.model.gravity(-G * N.y)
    al.assign("FORCE_AO>", al["FORCE_AO>"] + F * N.x)
    al.assign("ZERO", al.model.fr() + al.model.frstar())
    al.model.kane(line=49)
    kane_zero = al["ZERO"]
    al.assign("ZERO", al.evaluate(al["ZERO"], {L: 1, MA: 10, MB: 1, G: 9.81}))
    dU1, dU2 = al.variables("dU1'", "dU2'")
    dX, dTHETA = al.variables("dX'", "dTHETA'")
    nominal = {X: 0, THETA: 0, U1: 0, U2: 0, D(U1, t): 0, D(U2, t): 0}
    al.assign("CHECK", al.evaluate(al["ZERO"], nominal))
    pts = [(X, 0, dX), (THETA, 0, dTHETA), (U1, 0, dU1), (U2, 0, dU2)]
    al.assign("DX'", al.taylor(al["X'"], 1, pts))
    al.assign("DTHETA'", al.taylor(al["THETA'"], 1, pts))
    pts += [(D(U1, t), 0, D(dU1, t)), (D(U2, t), 0, D(dU2, t))]
    al.assign("PERTURB", al.taylor(al["ZERO"], 1, pts))
    al.solve(al["PERTURB"], [D(dU1, t), D(dU2, t)])
    xm = al.assign("XM", sp.Matrix([[dX, dTHETA, dU1, dU2]]))
    xp = al.assign("XP", sp.Matrix([D(x, t) for x in (dX, dTHETA, dU1, dU2)]))
    al.assign("A", al.d(xp, xm))
    al.assign("ROOTS1", al.eig(al.evaluate(al["A"], {K1: 0, K2: 0, K3: 0, K4: 0})))
    return al, locals()


def test_tutor8_cart_pendulum():
    al, v = tutor8()
    L, MA, MB, G, IB, F = (v[k] for k in ("L", "MA", "MB", "G", "IB", "F"))
    THETA, U1, U2 = v["THETA"], v["U1"], v["U2"]
    K1, K2, K3, K4 = v["K1"], v["K2"], v["K3"], v["K4"]
    s, c = sp.sin, sp.cos
    half = sp.Rational(1, 2)
    # the printed ZERO[1] has U2'^2 where U2^2 is meant
    z1 = (
        F
        + half * L * MB * c(THETA) * D(U2, t)
        - half * L * MB * s(THETA) * U2**2
        - (MA + MB) * D(U1, t)
    )
    z2 = (
        half * G * L * MB * s(THETA)
        + half * L * MB * c(THETA) * D(U1, t)
        - sp.Rational(1, 4) * (4 * IB + MB * L**2) * D(U2, t)
    )
    zk = v["kane_zero"]
    assert same(zk[0], z1, al) and same(zk[1], z2, al)
    assert al["CHECK"] == sp.Matrix([0, 0])
    a = al["A"]
    assert a[:2, :] == sp.Matrix([[0, 0, 1, 0], [0, 0, 0, 1]])
    g = sp.Rational(981, 100)
    expected = sp.Matrix(
        [
            [
                sp.Rational(4, 41) * K1,
                sp.Rational(4, 41) * K2 + 3 * g / 41,
                sp.Rational(4, 41) * K3,
                sp.Rational(4, 41) * K4,
            ],
            [
                sp.Rational(6, 41) * K1,
                sp.Rational(6, 41) * K2 + 66 * g / 41,
                sp.Rational(6, 41) * K3,
                sp.Rational(6, 41) * K4,
            ],
        ]
    )
    assert (a[2:, :] - expected).applyfunc(sp.simplify) == sp.zeros(2, 4)
    assert abs(float(a[2, 1].subs(K2, 0)) - 0.717805) < 1e-6
    assert abs(float(a[3, 1].subs(K2, 0)) - 15.7917) < 1e-4
    roots = sorted(complex(r).real for r in al["ROOTS1"])
    assert roots == pytest.approx([-3.97388, 0, 0, 3.97388], abs=1e-5)


# ---------------------------------------------------------------- tutor9


def tutor9():
    al = Workspace("tutor9.al")
    N = al.model.newtonian("N")
    A = al.model.bodies("A")
    B = al.model.frames("B")
    U1, U2, U3 = al.variables("U1'", "U2'", "U3'")
    OMEGA = al.constants("OMEGA")
    J = al.constants("J")
    M = al.constants("M+")
    al.model.set_mass(A, M)
    I1, I2, I3 = al.constants("I1+", "I2+", "I3+")
    al.model.set_inertia(A, I1, I2, I3)
    al.assign("W_A_N>", U1 * A.x + U2 * A.y + U3 * A.z)
    al.assign("W_B_A>", OMEGA * A.z)
    al.assign("ALF_A_N>", al.dt(al["W_A_N>"], N))
    al.assign("ALF_B_A>", al.dt(al["W_B_A>"], A))
    AO = al.model.point("AO")
    al.assign("A_AO_N>", Vector(0))
    al.assign(
        "ZERO",
        al.model.fr()
        + al.model.frstar()
        + al.model.gyrostat("FRSTAR", "CYLINDER", A, B, J),
    )
    al.model.kane(line=31)
    h = al.assign(
        "H>",
        al.model.momentum("ANGULAR", AO)
        + al.model.gyrostat("ANGMOM", "CYLINDER", A, B, J),
    )
    al.assign("H", al.model.mag(h))
    al.assign("PHI", sp.acos(al.model.dot(al.model.unitvec(h), A.z)))
    dU1, dU2, dU3 = al.variables("dU1'", "dU2'", "dU3'")
    nU3 = al.constants("nU3")
    nominal = {U1: 0, D(U1, t): 0, U2: 0, D(U2, t): 0, U3: nU3, D(U3, t): 0}
    al.assign("CHECK", al.evaluate(al["ZERO"], nominal))
    pts = [
        (U1, 0, dU1),
        (D(U1, t), 0, D(dU1, t)),
        (U2, 0, dU2),
        (D(U2, t), 0, D(dU2, t)),
        (U3, nU3, dU3),
        (D(U3, t), 0, D(dU3, t)),
    ]
    al.assign("PETURB", al.taylor(al["ZERO"], 1, pts))
    al.solve(al["PETURB"], [D(dU1, t), D(dU2, t), D(dU3, t)])
    xm = al.assign("XM", sp.Matrix([[dU1, dU2, dU3]]))
    xp = al.assign("XP", sp.Matrix([D(dU1, t), D(dU2, t), D(dU3, t)]))
    am = al.assign("AM", al.d(xp, xm))
    LAMBDA = al.variables("LAMBDA")
    det = al.assign("DET", al.det(LAMBDA * sp.eye(3) - am))
    al.assign("DET", det / LAMBDA)
    al.assign(
        "DET",
        al.evaluate(al["DET"], {J: 0.07634, I1: 1.25, I2: 4.25, I3: 5, nU3: 1}),
    )
    return al, locals()


def test_tutor9_gyrostat():
    al, v = tutor9()
    U1, U2, U3, J, OMEGA = (v[k] for k in ("U1", "U2", "U3", "J", "OMEGA"))
    I1, I2, I3, LAMBDA = (v[k] for k in ("I1", "I2", "I3", "LAMBDA"))
    z = al["ZERO"]
    assert sp.expand(z[0] - (-U2 * (J * OMEGA - (I2 - I3) * U3) - I1 * D(U1, t))) == 0
    assert sp.expand(z[1] - (U1 * (J * OMEGA - (I1 - I3) * U3) - I2 * D(U2, t))) == 0
    assert sp.expand(z[2] - ((I1 - I2) * U1 * U2 - I3 * D(U3, t))) == 0
    assert al["CHECK"] == sp.zeros(3, 1)
    expected = 0.001096997 * (9.824469 + OMEGA) * (49.12235 + OMEGA) + LAMBDA**2
    got = sp.expand(al["DET"])
    diff = sp.Poly(sp.expand(got - expected), OMEGA, LAMBDA)
    assert all(abs(float(c)) < 1e-6 for c in diff.coeffs())
    # angular momentum of the gyrostat
    h = al["H>"]
    A = v["A"]
    assert sp.expand(al.model.dot(h, A.z) - (I3 * U3 + J * OMEGA)) == 0
    assert sp.expand(al.model.dot(h, A.x) - I1 * U1) == 0


# ------------------------------------------------- tutor2 and transcripts


def tutor2():
    al = Workspace("tutor2.al")
    al.settings.set("Degrees", "ON")
    A, B, C = al.model.bodies("A", "B", "C")
    O, P = al.model.points("O", "P")
    CM = al.model.points("CM")
    PHI = al.variables("PHI")
    W = al.constants("W")
    al.assign("W", 1)
    M = al.constants("M+")
    al.assign("M", 12)
    for body in (A, B, C):
        al.model.set_mass(body, M)
    al.model.set_inertia(A, M * W**2 / 12, M * W**2 / 12, M * W**2 / 6)
    al.model.set_inertia(B, M * W**2 / 12, M * W**2 / 12, M * W**2 / 6)
    al.model.set_inertia(C, M * W**2 / 12, M * W**2 / 6, M * W**2 / 12)
    al.model.simprot(A, B, -2, PHI)
    al.assign("A_C", sp.eye(3))
    al.assign("P_O_AO>", -0.5 * W * A.x + 0.5 * W * A.y)
    al.assign("P_O_BO>", -W * A.x + 0.5 * W * A.y + 0.5 * W * B.x)
    al.assign("P_O_CO>", W * A.y - 0.5 * W * C.x - 0.5 * W * C.z)
    al.assign("P_O_P>", W * A.y - W * C.z)
    al.assign("P_O_CM>", al.model.cm(O))
    al.assign("DISTANCE", al.model.mag(al["P_O_CM>"]))
    al.assign("I_SYSTEM_CM>>", al.model.inertia(CM, A, B, C))
    al.assign("I_SYSTEM_CM", al.model.represent(al["I_SYSTEM_CM>>"], A))
    lam, vecs = al.eig_vectors(al.evaluate(al["I_SYSTEM_CM"], {PHI: 90}))
    al.assign("LAMBDA", lam)
    al.assign("EIGENVECS", vecs)
    al.assign("I_SYSTEM_O>>", al.model.inertia(O))
    al.assign("L>", al.model.unitvec(al["P_O_P>"]))
    il = al.assign(
        "IL", al.model.dot(al["L>"], al.model.dot(al["I_SYSTEM_O>>"], al["L>"]))
    )
    mt = al.assign("MTOTAL", al.model.mass_of())
    al.assign("GYRATION", (il / mt) ** 0.5)
    return al, locals()


def test_tutor2_mass_center_and_inertia():
    al, v = tutor2()
    PHI = v["PHI"]
    for deg in (0, 14, 90, 200, 340):
        phi = math.radians(deg)
        expected = (0.94444 - 0.22222 * math.cos(phi) - 0.055556 * math.sin(phi)) ** 0.5
        got = float(al["DISTANCE"].subs(PHI, phi))
        assert got == pytest.approx(expected, abs=2e-5)
    lam = sorted(float(x) for x in al["LAMBDA"])
    assert lam == pytest.approx([5, 13, 14])
    vecs = al["EIGENVECS"]
    lams = [float(x) for x in al["LAMBDA"]]
    row = vecs.row(lams.index(min(lams)))
    evec = al.model.represent(row, v["A"])
    cosang = float(al.model.dot(evec, v["A"].y)) / float(al.model.mag(evec))
    angle = math.degrees(math.acos(cosang))
    assert min(abs(angle - 65.90516), abs(angle - 114.09484)) < 1e-4
    assert al["MTOTAL"] == 36
    # radius of gyration about OP: minimum 0.696 m near PHI = 340 degrees
    gyr = [
        float(al.resolve(al["GYRATION"]).subs(PHI, math.radians(d))) for d in range(361)
    ]
    assert min(range(361), key=gyr.__getitem__) == 340
    assert min(gyr) == pytest.approx(0.696, abs=1e-3)


def test_mass_transcript():
    al = Workspace("mass.al")
    A, B = al.model.bodies("A", "B")
    C = al.model.particles("C")
    MB = al.constants("MB+")
    MC = al.constants("MC+")
    al.model.set_mass(A, 12.5)
    al.model.set_mass(B, MB)
    al.assign("MC", 10, line=4)
    al.model.set_mass(C, MC)
    assert al.assign("MASS_A", al.model.mass_of(A), line=6) is not None
    assert sp.nsimplify(al["MASS_A"]) == sp.Rational(25, 2)
    al.assign("MASS_AB", al.model.mass_of(A, B), line=8)
    al.assign("TOTAL", al.model.mass_of(), line=10)
    assert sp.expand(al.resolve(al["MASS_AB"]) - (sp.Rational(25, 2) + MB)) == 0
    assert sp.expand(al.resolve(al["TOTAL"]) - (sp.Rational(45, 2) + MB)) == 0
    got = {r.label: r for r in al.responses}
    assert got["MASS_AB"].line == 8 and got["TOTAL"].line == 10


def test_inertia_transcript():
    al = Workspace("inertia.al")
    P = al.model.points("P")
    B = al.model.bodies("B")
    MB = al.constants("MB+")
    al.model.set_mass(B, MB)
    I, J, L = al.constants("I", "J", "L")
    al.assign("P_BO_P>", L * B.x, line=5)
    ib = al.assign(
        "I_B_P>>", I * (B.x | B.x) + I * (B.y | B.y) + J * (B.z | B.z), line=7
    )
    assert al.model.inertia_dyadic(B, P) == ib
    got = al.assign("I_B_BO>>", al.model.inertia(al.model.point("BO"), B), line=9)
    expected = (
        I * (B.x | B.x) + (I - MB * L**2) * (B.y | B.y) + (J - MB * L**2) * (B.z | B.z)
    )
    assert (got - expected).to_matrix(B).applyfunc(sp.expand) == sp.zeros(3, 3)
    labels = [(r.line, r.label) for r in al.responses]
    assert labels == [(5, "P_BO_P>"), (7, "I_B_P>>"), (9, "I_B_BO>>")]
    # the transfer theorem back to P gives the given dyadic
    back = al.model.inertia(P, B) - ib
    assert back.to_matrix(B).applyfunc(sp.expand) == sp.zeros(3, 3)


def test_inertia_about_a_point():
    """``Inertia A, about=O``: the dyadic is about O; the central one follows."""
    al = Workspace()
    al.model.newtonian("N")
    A = al.model.bodies("A")
    O = al.model.points("O")
    m, length = al.constants("M", "L")
    al.model.set_mass(A, m)
    al.assign("P_O_AO>", length / 2 * A.x)
    al.model.set_inertia(A, 0, m * length**2 / 3, m * length**2 / 3, about=O)
    central = al.model.central_inertia(A).to_matrix(A)
    assert central.applyfunc(sp.expand) == sp.diag(
        0, m * length**2 / 12, m * length**2 / 12
    )
    assert al["I_A_O>>"].to_matrix(A)[1, 1] == m * length**2 / 3


# ---------------------------------------------------- rotation commands


def test_dircos_body_and_space_match_sympy():
    al = Workspace()
    A, B, C = al.model.frames("A", "B", "C")
    Q1, Q2, Q3 = al.variables("Q1", "Q2", "Q3")
    m = al.model.dircos(A, B, "BODY123", Q1, Q2, Q3, line=3)
    assert m[0, 2] == sp.sin(Q2)
    assert al.responses[-1].label == "A_B" and al.responses[-1].line == 3
    for kind, method in (
        ("BODY313", "orient_body_fixed"),
        ("SPACE231", "orient_space_fixed"),
    ):
        al.model.dircos(A, C, kind, Q1, Q2, Q3)
        from sympy.physics.vector import ReferenceFrame

        ref_a, ref_c = ReferenceFrame("RA"), ReferenceFrame("RC")
        getattr(ref_c, method)(ref_a, (Q1, Q2, Q3), kind[-3:])
        for x, y in zip(al.model.dcm(A, C), ref_a.dcm(ref_c), strict=True):
            assert same(x, y)
    # Simprot with a negative axis is a rotation by -angle
    al.model.simprot(A, B, -2, Q1)
    assert al["A_B[1,3]"] == -sp.sin(Q1)


@pytest.mark.parametrize(
    "kind, n", [("BODY123", 3), ("SPACE321", 3), ("EULER", 4), ("RODRIGUES", 3)]
)
def test_kindiffs_reproduce_the_angular_velocity(kind, n):
    from al2py_runtime.model import kinematics as kin

    al = Workspace()
    N = al.model.newtonian("N")
    B = al.model.bodies("B")
    us = al.variables("U1", "U2", "U3")
    qs = al.variables(*[f"Q{i}'" for i in range(1, n + 1)])
    al.model.dircos(N, B, kind, *qs)
    w = al.model.angvel(N, B, kind, *qs)
    assert al.responses[-1].label == "W_B_N>"
    al.assign("W_B_N>", us[0] * B.x + us[1] * B.y + us[2] * B.z)
    al.model.kindiffs(N, B, kind, *qs, line=9)
    assert [r.label for r in al.responses[-n:]] == [f"Q{i}'" for i in range(1, n + 1)]
    # the orientation's angular velocity with the q' substituted is the U's
    values = {}
    if kind == "EULER":
        e = [0.3, -0.5, 0.2]
        e.append(math.sqrt(1 - sum(x * x for x in e)))
        values = dict(zip(qs, e, strict=True))
    wq = kin.angvel_from_dcm(kin.rotation_dcm(kind, list(qs)))
    for k, u in enumerate(us):
        assert (
            same(wq[k], u, al)
            if not values
            else abs(
                numeric(al.resolve(wq[k]), values=values) - numeric(u, values=values)
            )
            < 1e-9
        )
    if kind == "EULER":
        # Angvel uses 2*(e4*e' - e4'*e - e x e'), equal to the direction
        # cosines' angular velocity only on the unit sphere.
        wq = kin.euler_parameter_angvel(list(qs))
    assert same(al.model.dot(w, B.z), wq[2])


# ------------------------------------------------------ kinematics misc


def slider():
    """A particle P sliding along A1> of a frame A spinning about N3>."""
    al = Workspace()
    N = al.model.newtonian("N")
    A = al.model.frames("A")
    O = al.model.points("O")
    P = al.model.particles("P")
    U1, U2 = al.variables("U1'", "U2'")
    QA, X = al.variables("QA'", "X'")
    MP, G = al.constants("MP+", "G")
    al.model.set_mass(P, MP)
    al.model.simprot(N, A, 3, QA)
    al.assign("QA'", U1)
    al.assign("X'", U2)
    al.assign("P_O_P>", X * A.x)
    al.assign("V_O_N>", 0)
    al.assign("A_O_N>", 0)
    return al, locals()


def test_one_point_formulas_match_differentiation():
    al, v = slider()
    N, A, O, P = v["N"], v["A"], v["O"], v["P"]
    derived_v, derived_a = al.model.vel(P, N), al.model.acc(P, N)
    vp = al.model.v1pt(N, A, O, P, line=4)
    ap = al.model.a1pt(N, A, O, P, line=5)
    assert [r.label for r in al.responses[-2:]] == ["V_P_N>", "A_P_N>"]
    for got, ref in ((vp, derived_v), (ap, derived_a)):
        assert (al.model.actual_value(got - ref)).to_matrix(N).applyfunc(
            sp.simplify
        ) == sp.zeros(3, 1)
    # partials and remainder
    pv = al.model.partials(al["V_P_N>"])
    assert len(pv) == 2
    assert al.model.actual_value(pv[1] - A.x) == Vector(0)
    assert al.model.remainder(al["V_P_N>"]) == Vector(0)


def test_nicheck_is_constant_along_motion():
    al, v = slider()
    N, A, P = v["N"], v["A"], v["P"]
    U1, U2, X, MP, G = v["U1"], v["U2"], v["X"], v["MP"], v["G"]
    TQ = al.specified("TQ")
    al.model.gravity(-G * N.y)
    al.model.torque_between(N, A, TQ * A.z)
    al.model.add_force(P, -MP * X * A.x)  # a spring towards O
    al.assign("ZERO", al.model.fr() + al.model.frstar())
    al.model.kane()
    sol = sp.solve(list(al["ZERO"]), [D(U1, t), D(U2, t)], dict=True)[0]
    echeck = al.assign("ECHECK", al.model.nicheck())
    rate = al.dt(echeck)
    rate = al.resolve(rate).xreplace(sol)
    assert sp.simplify(rate) == 0 or same(rate, 0, al)
    work = al.symbol("NICHECK_WORK")
    assert al.kind("NICHECK_WORK") == "variable"
    assert sp.Derivative(work, t) in al.table.rhs


def test_vector_helpers_and_derivatives():
    al, v = slider()
    N, A, QA, X, U1 = v["N"], v["A"], v["QA"], v["X"], v["U1"]
    r = al["P_O_P>"]
    assert al.model.represent(r, N) == sp.Matrix([[X * sp.cos(QA), X * sp.sin(QA), 0]])
    assert al.model.represent(sp.Matrix([[1, 2, 3]]), A) == A.x + 2 * A.y + 3 * A.z
    assert al.model.matrix(A, 2 * (A.x | A.y))[0, 1] == 2
    assert al.model.vector(A, 1, 2, 3) == al.model.vector(A, sp.Matrix([1, 2, 3]))
    assert al.model.dyadic(A, 1, 2, 3).to_matrix(A) == sp.diag(1, 2, 3)
    assert al.model.trace(al.model.dyadic(A, 1, 2, 3)) == 6
    assert al.model.trace(sp.eye(2)) == 2
    assert al.model.express(r, N) == X * sp.cos(QA) * N.x + X * sp.sin(QA) * N.y
    assert al.model.dot(A.x, N.x) == sp.cos(QA)
    assert al.model.dot(2 * (A.x | A.x), A.x) == 2 * A.x
    assert al.model.dot(A.x, 2 * (A.x | A.x)) == 2 * A.x
    assert al.model.dot(0, A.x) == 0 and al.model.dot(3, 4) == 12
    assert al.model.cross(A.x, A.y) == A.z and al.model.cross(0, A.x) == Vector(0)
    assert al.model.mag(3 * A.x + 4 * A.y) == 5 and al.model.mag(-2) == 2
    assert al.model.magsq(r) == X**2
    assert al.model.unitvec(3 * A.x) == A.x
    assert al.model.unit_dyadic() & N.x == N.x
    assert al["1>>"] & N.y == N.y and al["0>"] == Vector(0)
    # D(v>, q, N) and Dt(v>, N) (hooks reached through Workspace.d/dt)
    assert al.d(r, QA, N) == X * A.y
    assert al.d(r, QA, A) == Vector(0)
    vel = al.dt(r, N)
    assert al.model.actual_value(vel - al.model.vel(v["P"], N)) == Vector(0)
    assert al.dt(r, A) == v["U2"] * A.x
    # Dt of a formed quantity sees through right-hand sides
    al.assign("W_A_N>", D(QA, t) * A.z)
    assert al.dt(al["W_A_N>"], N) == D(U1, t) * A.z


def test_momentum_and_energy():
    al, v = slider()
    N, A, MP, X, U1, U2 = (v[k] for k in ("N", "A", "MP", "X", "U1", "U2"))
    O = v["O"]
    assert sp.expand(al.model.ke() - MP * (U2**2 + X**2 * U1**2) / 2) == 0
    lin = al.model.momentum("LINEAR")
    assert al.model.actual_value(lin - MP * (U2 * A.x + X * U1 * A.y)) == Vector(0)
    ang = al.model.momentum("ANGULAR", O)
    assert sp.expand(al.model.dot(ang, N.z) - MP * X**2 * U1) == 0
    gen = al.model.momentum("GENERALIZED")
    assert sp.expand(gen[0] - MP * X**2 * U1) == 0 and sp.expand(gen[1] - MP * U2) == 0
    # tstar of a spinning body
    B = al.model.bodies("B")
    al.model.set_inertia(B, 1, 2, 3)
    al.assign("W_B_N>", U1 * B.z)
    assert al.model.tstar(B, N) == -3 * D(U1, t) * B.z


def test_errors_and_non_forms():
    al, v = slider()
    N, P = v["N"], v["P"]
    with pytest.raises(KeyError):
        al["V_Q_N>"]  # Q is not a point: not a form, not defined
    Q = al.model.points("Q")
    with pytest.raises(KeyError, match="P_O_Q"):
        al["P_O_Q>"]
    with pytest.raises(ValueError, match="V_Q_N"):
        al.model.vel(Q, N)
    # user vectors and dyadics with form-like names are plain values
    al.assign("I_SYSTEM_O>>", al.model.unit_dyadic())
    assert al["I_SYSTEM_O>>"] == al.model.unit_dyadic()
    al.assign("UVEC>", N.x)
    assert al["UVEC>"] == N.x
    with pytest.raises(ValueError):
        al.model.set_mass(Q, 1)
    with pytest.raises(ValueError):
        al.model.mass_of(al.model.bodies("E"))
    al.assign("FORCE_P>", N.x)
    al.assign("FORCE_P>", al["FORCE_P>"] + N.y)
    assert al.model.force_on(P) == N.x + N.y


# ------------------------------------------- SymPy's examples: runtime rules


def test_simprot_about_a_vector_rotates_about_it():
    al = Workspace()
    N = al.model.newtonian("N")
    A, B = al.model.frames("A", "B")
    X = al.variables("X")
    al.model.simprot(N, A, N.x + N.y, X, line=1)
    B.orient_axis(N, (N.x + N.y).normalize(), X)
    assert sp.simplify(A.dcm(N) - B.dcm(N)) == sp.zeros(3, 3)
    w = (A.ang_vel_in(N) - B.ang_vel_in(N)).to_matrix(N)
    assert sp.simplify(w) == sp.zeros(3, 1)
    # a numeric angle about a unit vector: the 1-axis
    m = al.model.simprot(N, A, N.x, sp.pi / 2, line=2)
    assert m == sp.Matrix([[1, 0, 0], [0, 0, -1], [0, 1, 0]])
    with pytest.raises(ValueError, match="zero"):
        al.model.simprot(N, A, Vector(0), X, line=3)


def test_partials_one_speed_is_one_vector_several_a_tuple():
    al = Workspace()
    A = al.model.frames("A")
    P = al.model.particles("P")
    U1, U2 = al.variables("U1", "U2")
    al.assign("V_P_A>", U1 * A.x + 3 * U2 * A.y, line=1)
    v = al.model.vel(P, A)
    assert al.model.partials(v, U1) == A.x
    assert al.model.partials(v, U1, U2) == (A.x, 3 * A.y)


def test_unit_dyadic_is_the_identity_in_any_frame():
    al = Workspace()
    A = al.model.frames("A")  # no Newtonian frame, no orientation
    one = al.model.express(al.model.unit_dyadic(), A)
    assert one.to_matrix(A) == sp.eye(3)
    al2 = Workspace()
    N = al2.model.newtonian("N")
    B = al2.model.frames("B")  # not oriented relative to N
    assert al2.model.express(al2.model.unit_dyadic(), B).to_matrix(B) == sp.eye(3)
    # a dyadic that is not 1>> still needs the orientation
    with pytest.raises(ValueError):
        al2.model.express(2 * (N.x | N.x) + (N.y | N.y) + (N.z | N.z), B)


def test_dot_with_a_matrix_of_vectors_is_a_matrix():
    al = Workspace()
    A = al.model.frames("A")
    v1 = 2 * A.x - 3 * A.y
    v2 = A.x + A.y
    m = al.model.dot(v1, al.model.vector_matrix([[v2], [2 * v2]]))
    assert m == sp.Matrix([[-1], [-2]])


def test_angvel_with_two_frames_shows_the_angular_velocity():
    al = Workspace()
    N = al.model.newtonian("N")
    A = al.model.frames("A")
    C3 = al.constants("C3")
    al.assign("W_A_N>", C3 * A.z, line=1)
    assert al.model.angvel(A, N, line=2) == -C3 * A.z  # W_N_A>
    assert al.responses[-1].label == "W_N_A>"


def test_v2pts_waits_for_the_other_point():
    al = Workspace()
    N = al.model.newtonian("N")
    A = al.model.frames("A")
    O, P = al.model.points("O", "P")
    C1, C3 = al.constants("C1", "C3")
    al.assign("W_A_N>", C3 * A.z, line=1)
    al.model.v2pts(N, A, O, P, line=2)  # P_O_P> and V_O_N> are not known yet
    with pytest.raises(ValueError, match="V2pts"):
        al.model.vel(P, N)
    al.assign("P_O_P>", C1 * A.x, line=3)
    al.assign("V_O_N>", Vector(0), line=4)
    assert al.model.vel(P, N) == C1 * C3 * A.y


def test_quantity_may_share_its_name_with_a_frame():
    al = Workspace()
    A = al.model.frames("A")
    x = al.assign("A", 3, line=1)
    assert al["A"] == 3 and x == sp.Symbol("A", real=True)
    assert al.model.frame("A") is A


def test_particle_inertia_about_a_point():
    al = Workspace()
    A = al.model.frames("A")
    P1 = al.model.particles("P1")
    O = al.model.points("O")
    C1, M1 = al.constants("C1", "M1")
    al.model.set_mass(P1, M1)
    al.assign("P_P1_O>", C1 * A.x, line=1)
    i = al["I_P1_O>>"].to_matrix(A)
    assert i == sp.diag(0, M1 * C1**2, M1 * C1**2)
    assert al.model.inertia_dyadic(P1, O).to_matrix(A) == i


def _motion_pendulum(with_kin_eq: bool):
    """A pendulum with MotionVariables' and no U variables."""
    al = Workspace()
    N = al.model.newtonian("N")
    A = al.model.frames("A")
    P = al.model.particles("P")
    L, M, G = al.constants("L", "M", "G")
    if with_kin_eq:  # MotionVariables' Q', W'  with  Q' = W
        Q, W = al.model.motion_variables("Q'", "W'")
        al.assign("Q'", W, line=1)
    else:  # MotionVariables' Q''
        Q = al.model.motion_variables("Q''")
        W = D(Q, t)
    al.model.simprot(N, A, 3, Q, line=2)
    al.assign("W_A_N>", D(Q, t) * A.z, line=3)
    al.assign("P_NO_P>", L * A.x, line=4)
    al.model.set_mass(P, M)
    al.model.gravity(G * N.x)
    al.assign("ZERO", al.model.fr() + al.model.frstar(), line=5)
    al.model.kane(line=6)
    return al, Q, W


def test_speeds_from_motion_variables():
    al, Q, W = _motion_pendulum(with_kin_eq=False)
    assert al.model.generalized_speeds() == [D(Q, t)]
    zero = al["ZERO"]
    L, M, G = (sp.Symbol(n, real=True) for n in ("L", "M", "G"))
    expected = -M * L**2 * D(Q, (t, 2)) - M * G * L * sp.sin(Q)
    assert sp.simplify(zero[0] - expected) == 0
    al2, Q2, W2 = _motion_pendulum(with_kin_eq=True)
    assert al2.model.generalized_speeds() == [
        W2
    ]  # Q' = W: W is the speed, Q a coordinate
    expected2 = expected.subs(Q, Q2).subs(D(Q2, (t, 2)), D(W2, t))
    assert sp.simplify(al2.resolve(al2["ZERO"][0]) - expected2) == 0


def test_motion_variable_named_for_a_rate_is_not_a_speed():
    al = Workspace()
    TH, OM = al.model.motion_variables("TH''", "OM'")
    al.assign("OM", D(TH, t), line=1)
    assert al.model.generalized_speeds() == [D(TH, t)]
    # declared U variables take precedence
    U1 = al.variables("U1")
    assert al.model.generalized_speeds() == [U1]


def test_loads_are_one_list_of_sympy_loads():
    """Issue 33: Gravity, Force(O/Q, v>) and a module's
    ``loads.append(Force(P, v))`` all land in ``al.model.loads``, the one
    list that ``Force_P>``, Fr() and ``kanes_method()`` read."""
    from sympy.physics.mechanics import Force

    al, v = tutor4()
    N, P, Q, O, G, MP = (v[k] for k in ("N", "P", "Q", "O", "G", "MP"))
    loads = al.model.loads
    assert all(isinstance(load, Force) for load in loads)
    assert [load.point for load in loads] == [P, Q, O, Q]
    assert loads[0].force == MP * G * N.x
    F = al.constants("F")
    loads.append(Force(P, F * N.y))
    al.model.given_force(P, line=50)  # Force_P> += F*N2>: one load on P
    assert [load.point for load in loads] == [P, Q, O, Q]
    assert al.model.force_on(P) == MP * G * N.x + F * N.y
    fr = al.model.fr()
    assert any(entry.has(F) for entry in fr)
    forcing = al.model.kanes_method().forcing
    assert any(entry.has(F) for entry in forcing)


def test_declared_sympy_objects_are_autolevs_names():
    """Issue 33: ``N = ReferenceFrame("N")``, ``O = Point("O")``,
    ``symbols("G", real=True)`` declared by the runtime are the names' objects;
    a constant without Autolev's assumptions is refused, not taken silently."""
    from sympy.physics.mechanics import Particle
    from sympy.physics.vector import Point, ReferenceFrame

    al = Workspace("decl.al")
    N = ReferenceFrame("N")
    al.model.declare_newtonian(N)
    P = Point("P")
    P_particle = Particle("P", P, 0)
    al.model.declare_particles(P_particle)
    G = sp.Symbol("G", real=True)
    al.declare_constants(G, line=3)
    assert al.model.frame("N") is N and al.model.point("P") is P
    assert al.model.point("NO") is not None
    assert al.model.particle(P) is P_particle
    assert al.kind("G") == "constant" and al.table.entries["G"].obj is G
    with pytest.raises(Exception, match="real"):
        al.declare_constants(sp.Symbol("H"), line=4)
