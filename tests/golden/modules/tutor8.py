"""Autolev script tutor8.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor8`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor8.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor8.py [-h] [options]

Print the Autolev transcript of tutor8.al and perform its numerical CODE job.

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
  K1 = 1            K2 = -244         K3 = 5.4          K4 = -59
  X = 1 m           THETA = 20 deg    U1 = 0 m/sec      U2 = 0 rad/sec
  DX = 1 m          DTHETA = 20 deg   DU1 = 0 m/sec     DU2 = 0 rad/sec
  TINITIAL = 0      TFINAL = 20       INTEGSTP = 0.1    PRINTINT = 1
  ABSERR = 1.0E-08  RELERR = 1.0E-08
Jobs (--job STEM runs one; default: all, in script order):
  tutor8: CODE Dynamics tutor8.c (line 99) -> tutor8.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from sympy import Eq, Matrix, symbols
    from sympy.physics.mechanics import Force, RigidBody, inertia
    from sympy.physics.mechanics.loads import gravity
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame, Vector

al = Workspace("tutor8.al", __file__)

# al> % File: tutor8.al [Autolev: http://www.autolev.com]
# al> % Problem: Dynamics of a Cart Carrying an Inverted Pendulum
# al> %-----
# al> % Default Settings
al.settings.set("Digits", 2)  # al> Digits      2          % Significant digits
# al> %-----
# al> % Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian   N          % Newtonian reference frame
al.model.declare_newtonian(N)
# al> Bodies      A, B       % Cart, inverted pendulum
A, B = ReferenceFrame("A"), ReferenceFrame("B")
Ao, Bo = Point("AO"), Point("BO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
al.model.declare_bodies(A_body, B_body)
O_ = Point("O")  # al> Points      O          % Point fixed in N
al.model.declare_points(O_)
# al> %-----
# al> % Variables, constants, and specified
# al> Variables   U{2}'      % Generalized speeds; derivatives
U1, U2 = dynamicsymbols("U1 U2", real=True)
al.declare_variables(U1, U2, primes=1, line=13)
# al> Variables   X', THETA' % Generalized coordinates; derivatives
X, THETA = dynamicsymbols("X THETA", real=True)
al.declare_variables(X, THETA, primes=1, line=14)
L = symbols("L", real=True)  # al> Constants   L          % Length of rod
al.declare_constants(L, line=15)
G = symbols("G", real=True)  # al> Constants   G          % Gravitational acceleration
al.declare_constants(G, line=16)
# al> Constants   K{4}       % Control gains
K1, K2, K3, K4 = symbols("K1 K2 K3 K4", real=True)
al.declare_constants(K1, K2, K3, K4, line=17)
# al> Specified   F = K1*X + K2*THETA + K3*U1 + K4*U2
F = dynamicsymbols("F", real=True)
al.declare_specified(F, line=18)
al.assign("F", K1 * X + K2 * THETA + K3 * U1 + K4 * U2, line=18)
# al> %-----
# al> % Mass and inertia
MA, MB = symbols("MA MB", nonnegative=True)  # al> Mass        A=MA, B=MB
al.declare_constants(MA, MB, line=21)
A_body.mass = MA
B_body.mass = MB
al.model.given_masses(A_body, B_body, line=21)
IB = symbols("IB", nonnegative=True)  # al> Inertia     B, IB=MB*L^2/12, 0, IB
al.declare_constants(IB, line=22)
al.assign("IB", MB * L**2 / 12, line=22)
B_body.central_inertia = inertia(B, IB, 0, IB)
al.model.given_inertia(B_body, line=22)
# al> %-----
# al> % Geometry relating unit vectors
B.orient_axis(N, N.z, THETA)  # al> Simprot(N, B, 3, THETA)
al.model.given_orientation(B, N, line=25)
# al> %-----
# al> % Position vectors
Ao.set_pos(O_, X * N.x)  # al> P_O_Ao> = X*N1>
al.model.given_pos(Ao, O_, line=28)
Bo.set_pos(Ao, 0.5 * L * B.y)  # al> P_Ao_Bo> = 0.5*L*B2>
al.model.given_pos(Bo, Ao, line=29)
# al> %-----
# al> % Kinematical differential equations
# al> X' = U1
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(X.diff(t), U1), line=32))
kd_eqs.append(al.kd(Eq(THETA.diff(t), U2), line=33))  # al> THETA' = U2
# al> %-----
# al> % Angular velocities
A.set_ang_vel(N, Vector(0))  # al> W_A_N> = 0>
al.model.given_ang_vel(A, N, line=36)
B.set_ang_vel(N, THETA.diff(t) * B.z)  # al> W_B_N> = THETA'*B3>
al.model.given_ang_vel(B, N, line=37)
# al> %-----
# al> % Velocities
Ao.set_vel(N, al.dt(Ao.pos_from(O_), N))  # al> V_Ao_N> = DT(P_O_Ao>, N)
al.model.given_vel(Ao, N, line=40)
Bo.v2pt_theory(Ao, N, B)  # al> V2pts(N, B, Ao, Bo)
al.model.formed_vel(Bo, N, line=41)
# al> %-----
# al> % Forces
# al> Gravity( -G*N2> )
loads = al.model.loads  # sympy Force/Torque loads
loads += gravity(-G * N.y, A_body, B_body)
al.model.given_gravity(-G * N.y)
loads.append(Force(Ao, F * N.x))  # al> Force_Ao> += F*N1>
al.model.given_force(Ao, line=45)
# al> %-----
# al> % Equations of motion
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.model.fr() + al.model.frstar(), line=48)
Zero = al.model.kane(line=49)  # al> Kane()
# al> Zero := Evaluate( Zero, L=1, MA=10, MB=1, G=9.81 )
Zero = al.assign("ZERO", al.evaluate(Zero, {L: 1, MA: 10, MB: 1, G: 9.81}), line=50)
# al> %*****
# al> % CONTROL SYSTEM / STABILITY ANALYSIS
# al> %*****
# al> % Linearization: Perturbation variables
# al> Variables   dU{2}'      % Perturbations of U1,U2,U1',U2'
dU1, dU2 = dynamicsymbols("DU1 DU2", real=True)
al.declare_variables(dU1, dU2, primes=1, line=55)
# al> Variables    dX', dTHETA'    % Perturbations of X,X', THETA,THETA'
dX, dTHETA = dynamicsymbols("DX DTHETA", real=True)
al.declare_variables(dX, dTHETA, primes=1, line=56)
# al> %-----
# al> %          Check whether X=THETA=U1=U2=U1'=U2'=0 is a solution
CHECK = al.assign(  # al> CHECK = Evaluate(Zero, X=0, THETA=0, U1=0, U2=0, U1'=0, U2'=0)
    "CHECK",
    al.evaluate(Zero, {X: 0, THETA: 0, U1: 0, U2: 0, U1.diff(t): 0, U2.diff(t): 0}),
    line=59,
)
# al> %-----
# al> %          Linearize kinematical equations about nominal solution
# al> dX'        = Taylor(X',      1, X=0:dX, THETA=0:dTHETA, U1=0:dU1, U2=0:dU2)
kd_eqs.append(
    al.kd(
        Eq(
            dX.diff(t),
            al.taylor(
                X.diff(t),
                1,
                [(X, 0, dX), (THETA, 0, dTHETA), (U1, 0, dU1), (U2, 0, dU2)],
            ),
        ),
        line=62,
    )
)
# al> dTHETA'    = Taylor(THETA', 1, X=0:dX, THETA=0:dTHETA, U1=0:dU1, U2=0:dU2)
kd_eqs.append(
    al.kd(
        Eq(
            dTHETA.diff(t),
            al.taylor(
                THETA.diff(t),
                1,
                [(X, 0, dX), (THETA, 0, dTHETA), (U1, 0, dU1), (U2, 0, dU2)],
            ),
        ),
        line=63,
    )
)
# al> %-----
# al> %          Linearize equations of motion about nominal solution
# al> PERTURB = Taylor(Zero, 1, X=0:dX, THETA=0:dTHETA, U1=0:dU1, U2=0:dU2, &
PERTURB = al.assign(  # al> U1'=0:dU1', U2'=0:dU2')
    "PERTURB",
    al.taylor(
        Zero,
        1,
        [
            (X, 0, dX),
            (THETA, 0, dTHETA),
            (U1, 0, dU1),
            (U2, 0, dU2),
            (U1.diff(t), 0, dU1.diff(t)),
            (U2.diff(t), 0, dU2.diff(t)),
        ],
    ),
    line=66,
)
al.solve(PERTURB, [dU1.diff(t), dU2.diff(t)], line=68)  # al> Solve( PERTURB, dU{1:2}' )
# al> %-----
# al> %          Form matrix of perturbations and its time-derivative
# al> Xm = [ dX , dTHETA , dU1 , dU2 ]    % Matrix of perturbations
Xm = al.assign("XM", Matrix([[dX, dTHETA, dU1, dU2]]), line=71)
Xp = al.assign(  # al> Xp = [ dX'; dTHETA'; dU1'; dU2' ]  % Time derivative of Xm
    "XP", Matrix([dX.diff(t), dTHETA.diff(t), dU1.diff(t), dU2.diff(t)]), line=72
)
# al> %-----
# al> %          Form matrix A such that Xm' = A * Xm
A_val = al.assign("A", al.d(Xp, Xm), line=75)  # al> A = D( Xp, Xm )
# al> %-----
# al> %          Stability when F=0
ROOTS1 = al.assign(  # al> ROOTS1 = Eig( evaluate(A, K1=0, K2=0, K3=0, K4=0) )
    "ROOTS1", al.eig(al.evaluate(A_val, {K1: 0, K2: 0, K3: 0, K4: 0})), line=78
)
# al> %-----
# al> %          Stability when F = X - 244*THETA + 5.4*U1 - 59*U2
ROOTS2 = al.assign(  # al> ROOTS2 = Eig( evaluate(A, K1=1, K2=-244, K3=5.4, K4=-59) )
    "ROOTS2", al.eig(al.evaluate(A_val, {K1: 1, K2: -244, K3: 5.4, K4: -59})), line=81
)
# al> %-----
# al> %          Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> %          Input constants, variables, etc. for CODE
# al> Input K1=1, K2=-244, K3=5.4, K4=-59
al.numerics.input({"K1": 1, "K2": -244, "K3": 5.4, "K4": -59}, line=87)
al.numerics.input(  # al> Input X=1 m, THETA=20 deg, U1=0 m/sec, U2=0 rad/sec
    {"X": (1, "m"), "THETA": (20, "deg"), "U1": (0, "m/sec"), "U2": (0, "rad/sec")},
    line=88,
)
al.numerics.input(  # al> Input dX=1 m, dTHETA=20 deg, dU1=0 m/sec, dU2=0 rad/sec
    {"DX": (1, "m"), "DTHETA": (20, "deg"), "DU1": (0, "m/sec"), "DU2": (0, "rad/sec")},
    line=89,
)
# al> Input tInitial=0, tFinal=20          % Begin/end times
al.numerics.input({"TINITIAL": 0, "TFINAL": 20}, line=90)
# al> Input integStp=0.1, printInt=1      % Integration/print step
al.numerics.input({"INTEGSTP": 0.1, "PRINTINT": 1}, line=91)
# al> Input absErr=1.0E-08, relErr=1.0E-08 % Error tolerances
al.numerics.input({"ABSERR": 1.0e-08, "RELERR": 1.0e-08}, line=92)
# al> %-----
# al> %          Quantities to be output from CODE
# al> Output T, X meters, dX meters, THETA deg, dTHETA deg, F newtons
al.numerics.output(
    [
        ("T", t, None),
        ("X", X, "meters"),
        ("DX", dX, "meters"),
        ("THETA", THETA, "deg"),
        ("DTHETA", dTHETA, "deg"),
        ("F", F, "newtons"),
    ],
    line=95,
)
# al> %-----
# al> %          C code generation for numerical solution
# al> Digits 5          % Significant digits in output files
al.settings.set("Digits", 5)
al.numerics.code("DYNAMICS", file="tutor8.c", line=99)  # al> CODE Dynamics() tutor8.c
# al> %-----
# al> %          Record Autolev responses
al.save("tutor8.all", line=102)  # al> Save tutor8.all

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
    """``python tutor8.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
