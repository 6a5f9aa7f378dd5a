"""Autolev script tutor5.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor5`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor5.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor5.py [-h] [options]

Print the Autolev transcript of tutor5.al and perform its numerical CODE job.

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
  H = 200 newton    QA = 30 deg       QB = 60 deg       QC = 30 deg
  ABSERR = 1.0E-07  RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor5: CODE Nonlinear tutor5.m (line 83) -> tutor5.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from sympy import Eq, symbols
    from sympy.physics.mechanics import RigidBody, inertia
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame, Vector

al = Workspace("tutor5.al", __file__)

# al> %      File:  tutor5.al      [Autolev: http://www.autolev.com]
# al> %      Problem:  Four-Bar Linkage -- Equilibrium Configuration
# al> %-----
# al> %      Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian      N
al.model.declare_newtonian(N)
# al> Bodies        A, B, C
A, B, C = ReferenceFrame("A"), ReferenceFrame("B"), ReferenceFrame("C")
Ao, Bo, Co = Point("AO"), Point("BO"), Point("CO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
C_body = RigidBody("C", Co, C, 0, (Dyadic(0), Co))
al.model.declare_bodies(A_body, B_body, C_body)
# al> Points        O, P, Q, R
O_, P, Q, R = Point("O"), Point("P"), Point("Q"), Point("R")
al.model.declare_points(O_, P, Q, R)
# al> %-----
# al> %      Variables, constants, and specified
# al> Variables      U{3}                % Generalized speeds
U1, U2, U3 = dynamicsymbols("U1 U2 U3", real=True)
al.declare_variables(U1, U2, U3, line=10)
# al> Variables      QA', QB', QC'        % Generalized coordinates; derivatives
QA, QB, QC = dynamicsymbols("QA QB QC", real=True)
al.declare_variables(QA, QB, QC, primes=1, line=11)
# al> Constants      G=9.81                % Gravitational acceleration
G = symbols("G", real=True)
al.declare_constants(G, line=12)
al.assign("G", 9.81, line=12)
# al> Constants      LA=1, LB=2, LC=2, LN=1 % Lengths
LA, LB, LC, LN = symbols("LA LB LC LN", real=True)
al.declare_constants(LA, LB, LC, LN, line=13)
al.assign("LA", 1, line=13)
al.assign("LB", 2, line=13)
al.assign("LC", 2, line=13)
al.assign("LN", 1, line=13)
# al> Constants      H                      % Horizontal force on Q
H = symbols("H", real=True)
al.declare_constants(H, line=14)
# al> %-----
# al> %      Mass and inertia
# al> Mass          A=MA=10, B=MB=20, C=MC=20
MA, MB, MC = symbols("MA MB MC", nonnegative=True)
al.declare_constants(MA, MB, MC, line=17)
al.assign("MA", 10, line=17)
A_body.mass = MA
al.assign("MB", 20, line=17)
B_body.mass = MB
al.assign("MC", 20, line=17)
C_body.mass = MC
al.model.given_masses(A_body, B_body, C_body, line=17)
# al> Inertia       A, 0, MA*LA^2/12, MA*LA^2/12
A_body.central_inertia = inertia(A, 0, MA * LA**2 / 12, MA * LA**2 / 12)
al.model.given_inertia(A_body, line=18)
# al> Inertia       B, 0, MB*LB^2/12, MB*LB^2/12
B_body.central_inertia = inertia(B, 0, MB * LB**2 / 12, MB * LB**2 / 12)
al.model.given_inertia(B_body, line=19)
# al> Inertia       C, 0, MC*LC^2/12, MC*LC^2/12
C_body.central_inertia = inertia(C, 0, MC * LC**2 / 12, MC * LC**2 / 12)
al.model.given_inertia(C_body, line=20)
# al> %-----
# al> %      Geometry relating unit vectors
A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=23)
B.orient_axis(N, N.z, QB)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=24)
C.orient_axis(N, N.z, QC)  # al> Simprot(N, C, 3, QC)
al.model.given_orientation(C, N, line=25)
# al> %-----
# al> %      Position vectors
P.set_pos(O_, LA * A.x)  # al> P_O_P> = LA*A1>
al.model.given_pos(P, O_, line=28)
Q.set_pos(P, LB * B.x)  # al> P_P_Q> = LB*B1>
al.model.given_pos(Q, P, line=29)
Q.set_pos(R, LC * C.x)  # al> P_R_Q> = LC*C1>
al.model.given_pos(Q, R, line=30)
R.set_pos(O_, LN * N.y)  # al> P_O_R> = LN*N2>
al.model.given_pos(R, O_, line=31)
Ao.set_pos(O_, 0.5 * P.pos_from(O_))  # al> P_O_Ao> = 0.5*P_O_P>
al.model.given_pos(Ao, O_, line=32)
Bo.set_pos(P, 0.5 * Q.pos_from(P))  # al> P_P_Bo> = 0.5*P_P_Q>
al.model.given_pos(Bo, P, line=33)
Co.set_pos(R, 0.5 * Q.pos_from(R))  # al> P_R_Co> = 0.5*P_R_Q>
al.model.given_pos(Co, R, line=34)
# al> %-----
# al> %      Kinematical differential equations
# al> QA' = U1
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1), line=37))
kd_eqs.append(al.kd(Eq(QB.diff(t), U2), line=38))  # al> QB' = U2
kd_eqs.append(al.kd(Eq(QC.diff(t), U3), line=39))  # al> QC' = U3
# al> %-----
# al> %      Angular velocities
A.set_ang_vel(N, QA.diff(t) * A.z)  # al> W_A_N> = QA'*A3>
al.model.given_ang_vel(A, N, line=42)
B.set_ang_vel(N, QB.diff(t) * B.z)  # al> W_B_N> = QB'*B3>
al.model.given_ang_vel(B, N, line=43)
C.set_ang_vel(N, QC.diff(t) * C.z)  # al> W_C_N> = QC'*C3>
al.model.given_ang_vel(C, N, line=44)
# al> %-----
# al> %      Configuration Constraints
LOOP_vec = al.assign_vector(  # al> LOOP> = P_O_P> + P_P_Q> + P_Q_R> + P_R_O>
    LOOP=P.pos_from(O_) + Q.pos_from(P) + R.pos_from(Q) + O_.pos_from(R), line=47
)
# al> CONFIG[1] = Dot(LOOP>,N1>)
CONFIG = al.assign("CONFIG[1]", al.model.dot(LOOP_vec, N.x), line=48)
# al> CONFIG[2] = Dot(LOOP>,N2>)
CONFIG = al.assign("CONFIG[2]", al.model.dot(LOOP_vec, N.y), line=49)
# al> %-----
# al> %           Velocities
O_.set_vel(N, Vector(0))  # al> V_O_N> = 0>
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
# al> %           Motion constraints
# al> DEPENDENT[1] = Dot(V_R_N>, N1>)
DEPENDENT = al.assign("DEPENDENT[1]", al.model.dot(R.vel(N), N.x), line=61)
# al> DEPENDENT[2] = Dot(V_R_N>, N2>)
DEPENDENT = al.assign("DEPENDENT[2]", al.model.dot(R.vel(N), N.y), line=62)
al.model.constrain("DEPENDENT", [U2, U3], line=63)  # al> Constrain( DEPENDENT[U2,U3] )
# al> %-----
# al> %           Forces
# al> Gravity( G*N1> )
loads = al.model.loads  # sympy Force/Torque loads
al.model.gravity(G * N.x)
al.model.set_force(Q, H * N.y, line=67)  # al> Force_Q> = H*N2>
# al> %-----
# al> %           Equations of motion
Zero = al.assign("ZERO", al.model.fr(), line=70)  # al> Zero = Fr()
Zero = al.assign("ZERO[2]", CONFIG[0], line=71)  # al> Zero[2] = CONFIG[1]
Zero = al.assign("ZERO[3]", CONFIG[1], line=72)  # al> Zero[3] = CONFIG[2]
# al> %-----
# al> %           Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> %           Input constants, variables, etc. for CODE
al.numerics.input({"H": (200, "newton")}, line=78)  # al> Input H=200 newton
# al> Input QA=30 deg, QB=60 deg, QC=30 deg    % Guess
al.numerics.input({"QA": (30, "deg"), "QB": (60, "deg"), "QC": (30, "deg")}, line=79)
# al> Input absErr=1.0E-07, relErr=1.0E-07    % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=80)
# al> %-----
# al> %           MATLAB code generation for numerical solution
# al> CODE Nonlinear( Zero, QA,QB,QC ) tutor5.m
al.numerics.code("NONLINEAR", eqs=Zero, unknowns=[QA, QB, QC], file="tutor5.m", line=83)
# al> %-----
# al> %           Record Autolev responses
al.save("tutor5.all", line=86)  # al> Save tutor5.all

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
    """``python tutor5.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
