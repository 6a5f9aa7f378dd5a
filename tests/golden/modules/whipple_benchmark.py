"""Autolev script whipple_benchmark.al converted by al2py 0.2.0: edit the .al file
instead.

``import whipple_benchmark`` runs the symbolic part silently; ``AUTOLEV`` maps
Autolev names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python
whipple_benchmark.py`` prints the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python whipple_benchmark.py [-h] [options]

Print the Autolev transcript of whipple_benchmark.al and perform its numerical
CODE job.

options:
  -h, --help            show this help message and exit
  --set NAME=VALUE      change an Input value (repeatable); VALUE is in the
                        Input's unit
  --job STEM            perform (or with --emit-code, write) only the CODE job
                        whose file is STEM (see the list below)
  --tfinal TFINAL       final time (sets TFINAL; Dynamics/ODE jobs)
  --outdir OUTDIR       directory for every file the script writes: Save files,
                        output tables and plots, under their base names
                        (default: .)
  --plot                also write STEM.n.png plots
  --animate             also write STEM.html, an animation of the model that
                        plays in a browser (Dynamics/ODE jobs; what the
                        script's Animate names, else every body)
  --backend {auto,c,llvm,lambdify}
                        how Dynamics/ODE equations are evaluated (default:
                        $AL2PY_BACKEND or auto, the fastest available)
  --zero-missing        use 0 for constants that no Input gives (by default the
                        job stops and names them; or AL2PY_ZERO_MISSING=1)
  --emit-code DIR       write the program (C, MATLAB or Fortran, as CODE names
                        it) and STEM.in of each CODE job into DIR (as 'al2py
                        code' does) instead of running
  --no-run              only print the transcript; perform no CODE job and
                        write no file
  --max-seconds S       time budget of one integration (default 120; or
                        AL2PY_MAX_SECONDS)
  --max-evals N         right-hand-side evaluations allowed in one integration
                        (default 5e+06; or AL2PY_MAX_EVALS)

Input values (change with --set NAME=VALUE, in these units):
  W = 1.02                 C = 0.08                 LAM = 0.314159265358979
  G = 9.81                 RR = 0.3                 RF = 0.35
  MR = 2                   MB = 85                  MH = 4
  MF = 3                   XB = 0.3                 ZB = -0.9
  XH = 0.9                 ZH = -0.7                IRXX = 0.0603
  IRYY = 0.12              IFXX = 0.1405            IFYY = 0.28
  IBXX = 9.2               IBYY = 11                IBZZ = 2.8
  IBXZ = 2.4               IHXX = 0.05892           IHYY = 0.06
  IHZZ = 0.00708           IHXZ = -0.00756
This script has no CODE statement: it only prints its transcript.
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from sympy import Eq, Matrix, symbols
    from sympy.physics.mechanics import RigidBody, inertia
    from sympy.physics.mechanics.loads import gravity
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame

al = Workspace("whipple_benchmark.al", __file__)

# al> % File: whipple_benchmark.al
# al> % Problem: the Whipple bicycle of the benchmark by Meijaard, Papadopoulos,
# al> %   Ruina and Schwab, Proc. R. Soc. A 463 (2007): rear wheel R, rear frame
# al> %   with rider B, front frame and fork H, front wheel F; knife-edge wheels
# al> %   rolling without slip on level ground.  Written for al2py's tests from the
# al> %   paper's description.  Axes as in the paper: 1 forward, 2 right, 3 down.
# al> %-----
# al> AutoZ ON                           % intermediates, as Autolev's Z's
al.settings.set("Autoz", "ON")
N = ReferenceFrame("N")  # al> Newtonian N
al.model.declare_newtonian(N)
# al> Frames    Y, L, E            % heading, lean (roll), steer axis
Y, L, E = ReferenceFrame("Y"), ReferenceFrame("L"), ReferenceFrame("E")
al.model.declare_frames(Y, L, E)
R, B, H, F = (  # al> Bodies    R, B, H, F
    ReferenceFrame("R"),
    ReferenceFrame("B"),
    ReferenceFrame("H"),
    ReferenceFrame("F"),
)
Ro, Bo, Ho, Fo = Point("RO"), Point("BO"), Point("HO"), Point("FO")
R_body = RigidBody("R", Ro, R, 0, (Dyadic(0), Ro))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
H_body = RigidBody("H", Ho, H, 0, (Dyadic(0), Ho))
F_body = RigidBody("F", Fo, F, 0, (Dyadic(0), Fo))
al.model.declare_bodies(R_body, B_body, H_body, F_body)
# al> Points    P, S               % rear contact point, a point on the steer axis
P, S = Point("P"), Point("S")
al.model.declare_points(P, S)
# al> %-----
# al> % Q1, Q2: rear contact point; Q3 yaw; Q4 roll; Q5 rear frame pitch;
# al> % Q6 rear wheel angle; Q7 steer angle; Q8 front wheel angle.
# al> Variables Q{8}'
Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8 = dynamicsymbols("Q1 Q2 Q3 Q4 Q5 Q6 Q7 Q8", real=True)
al.declare_variables(Q1, Q2, Q3, Q4, Q5, Q6, Q7, Q8, primes=1, line=16)
# al> Variables U{8}'
U1, U2, U3, U4, U5, U6, U7, U8 = dynamicsymbols("U1 U2 U3 U4 U5 U6 U7 U8", real=True)
al.declare_variables(U1, U2, U3, U4, U5, U6, U7, U8, primes=1, line=17)
# al> Constants W, C, LAM, G             % wheelbase, trail, steer axis tilt, gravity
W, C, LAM, G = symbols("W C LAM G", real=True)
al.declare_constants(W, C, LAM, G, line=18)
# al> Constants RR, RF                   % wheel radii
RR, RF = symbols("RR RF", real=True)
al.declare_constants(RR, RF, line=19)
# al> Constants XB, ZB, XH, ZH           % mass centres in the reference configuration
XB, ZB, XH, ZH = symbols("XB ZB XH ZH", real=True)
al.declare_constants(XB, ZB, XH, ZH, line=20)
# al> Constants IRXX, IRYY, IFXX, IFYY
IRXX, IRYY, IFXX, IFYY = symbols("IRXX IRYY IFXX IFYY", real=True)
al.declare_constants(IRXX, IRYY, IFXX, IFYY, line=21)
# al> Constants IBXX, IBYY, IBZZ, IBXZ
IBXX, IBYY, IBZZ, IBXZ = symbols("IBXX IBYY IBZZ IBXZ", real=True)
al.declare_constants(IBXX, IBYY, IBZZ, IBXZ, line=22)
# al> Constants IHXX, IHYY, IHZZ, IHXZ
IHXX, IHYY, IHZZ, IHXZ = symbols("IHXX IHYY IHZZ IHXZ", real=True)
al.declare_constants(IHXX, IHYY, IHZZ, IHXZ, line=23)
# al> %-----
# al> Mass    R=MR, B=MB, H=MH, F=MF
MR, MB, MH, MF = symbols("MR MB MH MF", nonnegative=True)
al.declare_constants(MR, MB, MH, MF, line=25)
R_body.mass = MR
B_body.mass = MB
H_body.mass = MH
F_body.mass = MF
al.model.given_masses(R_body, B_body, H_body, F_body, line=25)
R_body.central_inertia = inertia(R, IRXX, IRYY, IRXX)  # al> Inertia R, IRXX, IRYY, IRXX
al.model.given_inertia(R_body, line=26)
# al> Inertia B, IBXX, IBYY, IBZZ, 0, 0, IBXZ
B_body.central_inertia = inertia(B, IBXX, IBYY, IBZZ, 0, 0, IBXZ)
al.model.given_inertia(B_body, line=27)
# al> Inertia H, IHXX, IHYY, IHZZ, 0, 0, IHXZ
H_body.central_inertia = inertia(H, IHXX, IHYY, IHZZ, 0, 0, IHXZ)
al.model.given_inertia(H_body, line=28)
F_body.central_inertia = inertia(F, IFXX, IFYY, IFXX)  # al> Inertia F, IFXX, IFYY, IFXX
al.model.given_inertia(F_body, line=29)
# al> %-----
Y.orient_axis(N, N.z, Q3)  # al> Simprot(N, Y, 3, Q3)
al.model.given_orientation(Y, N, line=31)
L.orient_axis(Y, Y.x, Q4)  # al> Simprot(Y, L, 1, Q4)
al.model.given_orientation(L, Y, line=32)
B.orient_axis(L, L.y, Q5)  # al> Simprot(L, B, 2, Q5)
al.model.given_orientation(B, L, line=33)
R.orient_axis(B, B.y, Q6)  # al> Simprot(B, R, 2, Q6)
al.model.given_orientation(R, B, line=34)
E.orient_axis(B, B.y, LAM)  # al> Simprot(B, E, 2, LAM)
al.model.given_orientation(E, B, line=35)
# al> % H's axes are parallel to B's when the steer angle is zero.
H.orient_body_fixed(E, (Q7, -LAM, 0), "321")  # al> Dircos(E, H, BODY321, Q7, -LAM, 0)
al.model.given_orientation(H, E, line=37)
F.orient_axis(H, H.y, Q8)  # al> Simprot(H, F, 2, Q8)
al.model.given_orientation(F, H, line=38)
# al> %-----
# al> Q1' = U1
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(Q1.diff(t), U1), line=40))
kd_eqs.append(al.kd(Eq(Q2.diff(t), U2), line=41))  # al> Q2' = U2
kd_eqs.append(al.kd(Eq(Q3.diff(t), U3), line=42))  # al> Q3' = U3
kd_eqs.append(al.kd(Eq(Q4.diff(t), U4), line=43))  # al> Q4' = U4
kd_eqs.append(al.kd(Eq(Q5.diff(t), U5), line=44))  # al> Q5' = U5
kd_eqs.append(al.kd(Eq(Q6.diff(t), U6), line=45))  # al> Q6' = U6
kd_eqs.append(al.kd(Eq(Q7.diff(t), U7), line=46))  # al> Q7' = U7
kd_eqs.append(al.kd(Eq(Q8.diff(t), U8), line=47))  # al> Q8' = U8
# al> %-----
Y.set_ang_vel(N, U3 * N.z)  # al> W_Y_N> = U3*N3>
al.model.given_ang_vel(Y, N, line=49)
L.set_ang_vel(N, Y.ang_vel_in(N) + U4 * Y.x)  # al> W_L_N> = W_Y_N> + U4*Y1>
al.model.given_ang_vel(L, N, line=50)
B.set_ang_vel(N, L.ang_vel_in(N) + U5 * L.y)  # al> W_B_N> = W_L_N> + U5*L2>
al.model.given_ang_vel(B, N, line=51)
R.set_ang_vel(N, B.ang_vel_in(N) + U6 * B.y)  # al> W_R_N> = W_B_N> + U6*B2>
al.model.given_ang_vel(R, N, line=52)
E.set_ang_vel(N, B.ang_vel_in(N))  # al> W_E_N> = W_B_N>
al.model.given_ang_vel(E, N, line=53)
H.set_ang_vel(N, B.ang_vel_in(N) + U7 * E.z)  # al> W_H_N> = W_B_N> + U7*E3>
al.model.given_ang_vel(H, N, line=54)
F.set_ang_vel(N, H.ang_vel_in(N) + U8 * H.y)  # al> W_F_N> = W_H_N> + U8*H2>
al.model.given_ang_vel(F, N, line=55)
# al> %-----
Ro.set_pos(P, -RR * L.z)  # al> P_P_Ro> = -RR*L3>
al.model.given_pos(Ro, P, line=57)
Bo.set_pos(Ro, XB * B.x + (ZB + RR) * B.z)  # al> P_Ro_Bo> = XB*B1> + (ZB + RR)*B3>
al.model.given_pos(Bo, Ro, line=58)
# al> % The steer axis meets the ground at distance W + C ahead of P.
S.set_pos(Ro, (W + C) * B.x + RR * B.z)  # al> P_Ro_S> = (W + C)*B1> + RR*B3>
al.model.given_pos(S, Ro, line=60)
Ho.set_pos(S, (XH - W - C) * H.x + ZH * H.z)  # al> P_S_Ho> = (XH - W - C)*H1> + ZH*H3>
al.model.given_pos(Ho, S, line=61)
Fo.set_pos(S, -C * H.x - RF * H.z)  # al> P_S_Fo> = -C*H1> - RF*H3>
al.model.given_pos(Fo, S, line=62)
# al> DOWN> = Cross(H2>, Cross(N3>, H2>))
DOWN_vec = al.assign_vector(DOWN=al.model.cross(H.y, al.model.cross(N.z, H.y)), line=63)
# al> P_Fo_Q> = RF*UnitVec(DOWN>)
P_Fo_Q_vec = al.assign_vector(P_FO_Q=RF * al.model.unitvec(DOWN_vec), line=64)
# al> %-----
P.set_vel(N, U1 * N.x + U2 * N.y)  # al> V_P_N> = U1*N1> + U2*N2>
al.model.given_vel(P, N, line=66)
Ro.v2pt_theory(P, N, L)  # al> V2pts(N, L, P, Ro)
al.model.formed_vel(Ro, N, line=67)
Bo.v2pt_theory(Ro, N, B)  # al> V2pts(N, B, Ro, Bo)
al.model.formed_vel(Bo, N, line=68)
S.v2pt_theory(Ro, N, B)  # al> V2pts(N, B, Ro, S)
al.model.formed_vel(S, N, line=69)
Ho.v2pt_theory(S, N, H)  # al> V2pts(N, H, S, Ho)
al.model.formed_vel(Ho, N, line=70)
Fo.v2pt_theory(S, N, H)  # al> V2pts(N, H, S, Fo)
al.model.formed_vel(Fo, N, line=71)
# al> %-----
# al> % Rolling without slip: the wheels' material points at the contacts are at rest.
SLIPR_vec = al.assign_vector(  # al> SLIPR> = V_Ro_N> + Cross(W_R_N>, -P_P_Ro>)
    SLIPR=Ro.vel(N) + al.model.cross(R.ang_vel_in(N), -Ro.pos_from(P)), line=74
)
SLIPF_vec = al.assign_vector(  # al> SLIPF> = V_Fo_N> + Cross(W_F_N>, P_Fo_Q>)
    SLIPF=Fo.vel(N) + al.model.cross(F.ang_vel_in(N), P_Fo_Q_vec), line=75
)
# al> DEPENDENT[1] = Dot(SLIPR>, N1>)
DEPENDENT = al.assign("DEPENDENT[1]", al.model.dot(SLIPR_vec, N.x), line=76)
# al> DEPENDENT[2] = Dot(SLIPR>, N2>)
DEPENDENT = al.assign("DEPENDENT[2]", al.model.dot(SLIPR_vec, N.y), line=77)
# al> DEPENDENT[3] = Dot(SLIPF>, N1>)
DEPENDENT = al.assign("DEPENDENT[3]", al.model.dot(SLIPF_vec, N.x), line=78)
# al> DEPENDENT[4] = Dot(SLIPF>, N2>)
DEPENDENT = al.assign("DEPENDENT[4]", al.model.dot(SLIPF_vec, N.y), line=79)
# al> DEPENDENT[5] = Dot(SLIPF>, N3>)
DEPENDENT = al.assign("DEPENDENT[5]", al.model.dot(SLIPF_vec, N.z), line=80)
# al> Constrain(DEPENDENT[U1, U2, U3, U5, U8])
al.model.constrain("DEPENDENT", [U1, U2, U3, U5, U8], line=81)
# al> %-----
# al> Gravity(G*N3>)
loads = al.model.loads  # sympy Force/Torque loads
loads += gravity(G * N.z, R_body, B_body, H_body, F_body)
al.model.given_gravity(G * N.z)
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.model.fr() + al.model.frstar(), line=84)
Zero = al.model.kane(line=85)  # al> Kane()
# al> % Linearized equations about the upright reference configuration: the
# al> % accelerations of the independent speeds and their Jacobian by the lean
# al> % and steer angles and rates (the forward speed is U6 = -v/RR).
# al> Solve(Zero, U4', U6', U7')
al.solve(Zero, [U4.diff(t), U6.diff(t), U7.diff(t)], line=89)
XD = al.assign("XD", Matrix([U4.diff(t), U7.diff(t)]), line=90)  # al> XD = [U4'; U7']
XS = al.assign("XS", Matrix([Q4, Q7, U4, U7]), line=91)  # al> XS = [Q4; Q7; U4; U7]
AL = al.assign("AL", al.d(XD, XS), line=92)  # al> AL = D(XD, XS)
# al> %-----
# al> % Benchmark parameters, Table 1 of the paper.
# al> Input W=1.02, C=0.08, LAM=0.314159265358979, G=9.81
al.numerics.input({"W": 1.02, "C": 0.08, "LAM": 0.314159265358979, "G": 9.81}, line=95)
# al> Input RR=0.3, RF=0.35, MR=2, MB=85, MH=4, MF=3
al.numerics.input({"RR": 0.3, "RF": 0.35, "MR": 2, "MB": 85, "MH": 4, "MF": 3}, line=96)
# al> Input XB=0.3, ZB=-0.9, XH=0.9, ZH=-0.7
al.numerics.input({"XB": 0.3, "ZB": -0.9, "XH": 0.9, "ZH": -0.7}, line=97)
# al> Input IRXX=0.0603, IRYY=0.12, IFXX=0.1405, IFYY=0.28
al.numerics.input({"IRXX": 0.0603, "IRYY": 0.12, "IFXX": 0.1405, "IFYY": 0.28}, line=98)
# al> Input IBXX=9.2, IBYY=11, IBZZ=2.8, IBXZ=2.4
al.numerics.input({"IBXX": 9.2, "IBYY": 11, "IBZZ": 2.8, "IBXZ": 2.4}, line=99)
al.numerics.input(  # al> Input IHXX=0.05892, IHYY=0.06, IHZZ=0.00708, IHXZ=-0.00756
    {"IHXX": 0.05892, "IHYY": 0.06, "IHZZ": 0.00708, "IHXZ": -0.00756}, line=100
)

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


def kanes_method():
    """``sympy.physics.mechanics.KanesMethod`` of this script's model."""
    return al.model.kanes_method()


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def main(argv: list[str] | None = None) -> int:
    """``python whipple_benchmark.py``: print the transcript."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
