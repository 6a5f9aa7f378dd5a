"""Autolev script tutor7a.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor7a`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor7a.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor7a.py [-h] [options]

Print the Autolev transcript of tutor7a.al and perform its numerical CODE job.

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
  QA = 30 deg           QB = 74.47751219 deg  QC = 45.52248781 deg
  TINITIAL = 0          TFINAL = 10           INTEGSTP = 0.1
  PRINTINT = 1          ABSERR = 1.0E-07      RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor7a: CODE Dynamics tutor7a.for (line 108) -> tutor7a.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from sympy import Eq, Matrix, symbols
    from sympy.physics.mechanics import RigidBody, inertia
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame, Vector

al = Workspace("tutor7a.al", __file__)

# al> %      File:  tutor7a.al (tutor7.al modified to find FC1, FC2, FA1)      [Autolev:
# al+ http://www.autolev.com]
# al> %      Problem:  Four-Bar Linkage -- Motion and Contact Forces
# al> %-----
# al> %      Default Settings
# al> AutoZ      ON              % Program introduces Zees automatically
al.settings.set("Autoz", "ON")
al.settings.set("Digits", 7)  # al> Digits     7              % Significant digits
# al> %-----
# al> %      Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian  N
al.model.declare_newtonian(N)
# al> Bodies     A, B, C
A, B, C = ReferenceFrame("A"), ReferenceFrame("B"), ReferenceFrame("C")
Ao, Bo, Co = Point("AO"), Point("BO"), Point("CO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
C_body = RigidBody("C", Co, C, 0, (Dyadic(0), Co))
al.model.declare_bodies(A_body, B_body, C_body)
# al> Points     O, P, Q, R
O_, P, Q, R = Point("O"), Point("P"), Point("Q"), Point("R")
al.model.declare_points(O_, P, Q, R)
# al> %-----
# al> %      Variables, constants, and specified
# al> Variables  U{4}'          % Generalized speeds; derivatives
U1, U2, U3, U4 = dynamicsymbols("U1 U2 U3 U4", real=True)
al.declare_variables(U1, U2, U3, U4, primes=1, line=14)
# al> Variables  QA', QB', QC' % Generalized coordinates; derivatives
QA, QB, QC = dynamicsymbols("QA QB QC", real=True)
al.declare_variables(QA, QB, QC, primes=1, line=15)
# al> Variables  FA{2}, FC{2}  % Contact forces
FA1, FA2, FC1, FC2 = dynamicsymbols("FA1 FA2 FC1 FC2", real=True)
al.declare_variables(FA1, FA2, FC1, FC2, line=16)
G = symbols("G", real=True)  # al> Constants  G=9.81        % Gravitational acceleration
al.declare_constants(G, line=17)
al.assign("G", 9.81, line=17)
# al> Constants  LA=1, LB=2, LC=2, LN=1 % Lengths
LA, LB, LC, LN = symbols("LA LB LC LN", real=True)
al.declare_constants(LA, LB, LC, LN, line=18)
al.assign("LA", 1, line=18)
al.assign("LB", 2, line=18)
al.assign("LC", 2, line=18)
al.assign("LN", 1, line=18)
# al> ZEE_NOT = [FA1, FA2, FC1, FC2]
ZEE_NOT = al.assign("ZEE_NOT", Matrix([[FA1, FA2, FC1, FC2]]), line=19)
# al> %-----
# al> %      Mass and inertia
# al> Mass       A=MA=10, B=MB=20, C=MC=20
MA, MB, MC = symbols("MA MB MC", nonnegative=True)
al.declare_constants(MA, MB, MC, line=22)
al.assign("MA", 10, line=22)
A_body.mass = MA
al.assign("MB", 20, line=22)
B_body.mass = MB
al.assign("MC", 20, line=22)
C_body.mass = MC
al.model.given_masses(A_body, B_body, C_body, line=22)
# al> Inertia    A, 0, MA*LA^2/12, MA*LA^2/12
A_body.central_inertia = inertia(A, 0, MA * LA**2 / 12, MA * LA**2 / 12)
al.model.given_inertia(A_body, line=23)
# al> Inertia    B, 0, MB*LB^2/12, MB*LB^2/12
B_body.central_inertia = inertia(B, 0, MB * LB**2 / 12, MB * LB**2 / 12)
al.model.given_inertia(B_body, line=24)
# al> Inertia    C, 0, MC*LC^2/12, MC*LC^2/12
C_body.central_inertia = inertia(C, 0, MC * LC**2 / 12, MC * LC**2 / 12)
al.model.given_inertia(C_body, line=25)
# al> %-----
# al> %      Geometry relating unit vectors
A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=28)
B.orient_axis(N, N.z, QB)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=29)
C.orient_axis(N, N.z, QC)  # al> Simprot(N, C, 3, QC)
al.model.given_orientation(C, N, line=30)
# al> %-----
# al> %      Position vectors
P.set_pos(O_, LA * A.x)  # al> P_O_P> = LA*A1>
al.model.given_pos(P, O_, line=33)
Q.set_pos(P, LB * B.x)  # al> P_P_Q> = LB*B1>
al.model.given_pos(Q, P, line=34)
Q.set_pos(R, LC * C.x)  # al> P_R_Q> = LC*C1>
al.model.given_pos(Q, R, line=35)
R.set_pos(O_, LN * N.y)  # al> P_O_R> = LN*N2>
al.model.given_pos(R, O_, line=36)
Ao.set_pos(O_, 0.5 * P.pos_from(O_))  # al> P_O_Ao> = 0.5*P_O_P>
al.model.given_pos(Ao, O_, line=37)
Bo.set_pos(P, 0.5 * Q.pos_from(P))  # al> P_P_Bo> = 0.5*P_P_Q>
al.model.given_pos(Bo, P, line=38)
Co.set_pos(R, 0.5 * Q.pos_from(R))  # al> P_R_Co> = 0.5*P_R_Q>
al.model.given_pos(Co, R, line=39)
# al> %-----
# al> %      Kinematical differential equations
# al> QA' = U1
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1), line=42))
kd_eqs.append(al.kd(Eq(QB.diff(t), U2), line=43))  # al> QB' = U2
kd_eqs.append(al.kd(Eq(QC.diff(t), U3), line=44))  # al> QC' = U3
# al> %-----
# al> %      Angular velocities
A.set_ang_vel(N, QA.diff(t) * A.z)  # al> W_A_N> = QA'*A3>
al.model.given_ang_vel(A, N, line=47)
B.set_ang_vel(N, QB.diff(t) * B.z)  # al> W_B_N> = QB'*B3>
al.model.given_ang_vel(B, N, line=48)
C.set_ang_vel(N, QC.diff(t) * C.z)  # al> W_C_N> = QC'*C3>
al.model.given_ang_vel(C, N, line=49)
# al> %-----
# al> %      Velocities
O_.set_vel(N, U4 * N.x)  # al> V_O_N> = U4*N1>
al.model.given_vel(O_, N, line=52)
Ao.v2pt_theory(O_, N, A)  # al> V2pts(N, A, O, Ao)
al.model.formed_vel(Ao, N, line=53)
P.v2pt_theory(O_, N, A)  # al> V2pts(N, A, O, P)
al.model.formed_vel(P, N, line=54)
Bo.v2pt_theory(P, N, B)  # al> V2pts(N, B, P, Bo)
al.model.formed_vel(Bo, N, line=55)
Q.v2pt_theory(P, N, B)  # al> V2pts(N, B, P, Q)
al.model.formed_vel(Q, N, line=56)
al.model.v2pts(N, C, Q, Co, line=57)  # al> V2pts(N, C, Q, Co)
R.v2pt_theory(Q, N, C)  # al> V2pts(N, C, Q, R)
al.model.formed_vel(R, N, line=58)
# al> %-----
# al> %      Motion constraints
# al> AUXILIARY[1] = Dot(V_R_N>, N1>)           % Dot(V_R_N>, N1>) = 0
AUXILIARY = al.assign("AUXILIARY[1]", al.model.dot(R.vel(N), N.x), line=61)
# al> AUXILIARY[2] = Dot(V_R_N>, N2>)           % Dot(V_R_N>, N2>) = 0
AUXILIARY = al.assign("AUXILIARY[2]", al.model.dot(R.vel(N), N.y), line=62)
# al> AUXILIARY[3] = Dot(V_O_N>, N1>)         % Dot(V_O_N>, N1>) = 0
AUXILIARY = al.assign("AUXILIARY[3]", al.model.dot(O_.vel(N), N.x), line=63)
# al> Constrain( AUXILIARY[U2,U3,U4] )       % Solve for U2,U3,U4
al.model.constrain("AUXILIARY", [U2, U3, U4], line=64)
# al> %-----
# al> %           Angular accelerations
A.set_ang_acc(N, al.dt(A.ang_vel_in(N), N))  # al> ALF_A_N> = DT(W_A_N>, N)
al.model.given_ang_acc(A, N, line=67)
B.set_ang_acc(N, al.dt(B.ang_vel_in(N), N))  # al> ALF_B_N> = DT(W_B_N>, N)
al.model.given_ang_acc(B, N, line=68)
C.set_ang_acc(N, al.dt(C.ang_vel_in(N), N))  # al> ALF_C_N> = DT(W_C_N>, N)
al.model.given_ang_acc(C, N, line=69)
# al> %-----
# al> %           Accelerations of particles and mass centers of bodies
O_.set_acc(N, Vector(0))  # al> A_O_N> = 0>
al.model.given_acc(O_, N, line=72)
al.model.a2pts(N, A, O_, Ao, line=73)  # al> A2pts(N, A, O, Ao)
al.model.a2pts(N, A, O_, P, line=74)  # al> A2pts(N, A, O, P)
al.model.a2pts(N, B, P, Bo, line=75)  # al> A2pts(N, B, P, Bo)
al.model.a2pts(N, B, P, Q, line=76)  # al> A2pts(N, B, P, Q)
al.model.a2pts(N, C, Q, Co, line=77)  # al> A2pts(N, C, Q, Co)
# al> %-----
# al> %           Forces
# al> Gravity( G*N1> )
loads = al.model.loads  # sympy Force/Torque loads
al.model.gravity(G * N.x)
# al> Force_O> = FA1*N1> + FA2*N2>
al.model.set_force(O_, FA1 * N.x + FA2 * N.y, line=81)
# al> Force_R> = FC1*N1> + FC2*N2>
al.model.set_force(R, FC1 * N.x + FC2 * N.y, line=82)
# al> %-----
# al> %           Equations of motion
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.model.fr() + al.model.frstar(), line=85)
Zero = al.model.kane(FC1, FC2, FA1, line=86)  # al> Kane( FC1, FC2, FA1 )
# al> %-----
# al> %           Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> %           Input constants, variables, etc. for CODE
# al> Input  QA=30 deg, QB=74.47751219 deg, QC=45.52248781 deg % Initial values
al.numerics.input(
    {"QA": (30, "deg"), "QB": (74.47751219, "deg"), "QC": (45.52248781, "deg")}, line=92
)
# al> Input  tInitial=0, tFinal=10 % Begin/end times
al.numerics.input({"TINITIAL": 0, "TFINAL": 10}, line=93)
# al> Input  integStp=0.1, printInt=1 % Integration/print step
al.numerics.input({"INTEGSTP": 0.1, "PRINTINT": 1}, line=94)
# al> Input  absErr=1.0E-07, relErr=1.0E-07 % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=95)
# al> %-----
# al> %           Quantities to be output from CODE
LOOP_vec = al.assign_vector(  # al> LOOP> = P_O_P> + P_P_Q> + P_Q_R> + P_R_O>
    LOOP=P.pos_from(O_) + Q.pos_from(P) + R.pos_from(Q) + O_.pos_from(R), line=98
)
# al> CONFIG[1] = Dot(LOOP>,N1>) % Should always equal 0
CONFIG = al.assign("CONFIG[1]", al.model.dot(LOOP_vec, N.x), line=99)
# al> CONFIG[2] = Dot(LOOP>,N2>) % Should always equal 0
CONFIG = al.assign("CONFIG[2]", al.model.dot(LOOP_vec, N.y), line=100)
# al> ECHECK = NICHECK() % Checking function
ECHECK = al.assign("ECHECK", al.model.nicheck(), line=101)
al.numerics.output(  # al> Output T, QA deg, QB deg, QC deg
    [("T", t, None), ("QA", QA, "deg"), ("QB", QB, "deg"), ("QC", QC, "deg")], line=102
)
al.numerics.output(  # al> Output T, CONFIG[1], CONFIG[2], ECHECK
    [
        ("T", t, None),
        ("CONFIG[1]", CONFIG[0], None),
        ("CONFIG[2]", CONFIG[1], None),
        ("ECHECK", ECHECK, None),
    ],
    line=103,
)
al.numerics.output(  # al> Output T, FC1 newtons, FC2 newtons
    [("T", t, None), ("FC1", FC1, "newtons"), ("FC2", FC2, "newtons")], line=104
)
# al> Output T, FA1 newtons
al.numerics.output([("T", t, None), ("FA1", FA1, "newtons")], line=105)
# al> %-----
# al> %           Fortran code generation for numerical solution
# al> CODE Dynamics() tutor7a.for
al.numerics.code("DYNAMICS", file="tutor7a.for", line=108)
# al> %-----
# al> %           Record Autolev responses
al.save("tutor7a.all", line=111)  # al> Save tutor7a.all

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


@al.numerics.document_run  # its Inputs become keyword parameters
def run(values=None, /, **overrides):
    """Perform the CODE job; keyword arguments override Inputs (in their
    units): ``run(QA=30)``, ``result["QA"]``; ``job=`` picks a job."""
    return al.numerics.run(values, **overrides)


def ode_function(values=None, /, **overrides):
    """``(f, y0, names)`` for ``scipy.integrate.solve_ivp(f, (t0, t1), y0)``."""
    return al.numerics.ode_function(values, **overrides)


def kanes_method():
    """``sympy.physics.mechanics.KanesMethod`` of this script's model."""
    return al.model.kanes_method()


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity (or of the CODE job) over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def linearize(values=None, /, *, job=None, symbolic=False, **overrides):
    """The CODE job's ``x' = A x + B r`` about a point: ``lin.A``, ``lin.B``."""
    return al.numerics.linearize(values, job=job, symbolic=symbolic, **overrides)


def main(argv: list[str] | None = None) -> int:
    """``python tutor7a.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
