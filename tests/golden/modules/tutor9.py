"""Autolev script tutor9.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor9`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor9.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor9.py [-h] [options]

Print the Autolev transcript of tutor9.al and perform its numerical CODE job.

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
  TINITIAL = 0      TFINAL = 20       INTEGSTP = 0.1    PRINTINT = 1
  ABSERR = 1.0E-07  RELERR = 1.0E-07  J = 0.07634       I1 = 1.25
  I2 = 4.25         I3 = 5            OMEGA = -20.0     U1 = 0
  U2 = 0.02         U3 = 1
Jobs (--job STEM runs one; default: all, in script order):
  tutor9: CODE Dynamics tutor9.for (line 54) -> tutor9.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from al2py_runtime.functions import acos
    from sympy import Matrix, symbols
    from sympy.physics.mechanics import RigidBody, inertia
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame, Vector

al = Workspace("tutor9.al", __file__)

# al> %      File:  tutor9.al      [Autolev: http://www.autolev.com]
# al> %      Problem:  Spin stability of gyrostat
# al> %-----
# al> %      Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian      N              % Newtonian reference frame
al.model.declare_newtonian(N)
A = ReferenceFrame("A")  # al> Bodies         A              % Carrier
Ao = Point("AO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
al.model.declare_bodies(A_body)
B = ReferenceFrame("B")  # al> Frames         B              % Rotor
al.model.declare_frames(B)
# al> %-----
# al> %      Variables, constants, and specified
# al> Variables      U{3}'         % Generalized speeds; derivatives
U1, U2, U3 = dynamicsymbols("U1 U2 U3", real=True)
al.declare_variables(U1, U2, U3, primes=1, line=10)
# al> Constants      OMEGA         % Angular speed of B in A
OMEGA = symbols("OMEGA", real=True)
al.declare_constants(OMEGA, line=11)
# al> Constants      J              % Moment of inertia of B about spin axis
J = symbols("J", real=True)
al.declare_constants(J, line=12)
# al> %-----
# al> %      Mass and inertia
# al> Mass           A=M           % Attribute mass of G to A
M = symbols("M", nonnegative=True)
al.declare_constants(M, line=15)
A_body.mass = M
al.model.given_masses(A_body, line=15)
# al> Inertia        A, I1, I2, I3 % Attribute inertia of G to A
I1, I2, I3 = symbols("I1 I2 I3", nonnegative=True)
al.declare_constants(I1, I2, I3, line=16)
A_body.central_inertia = inertia(A, I1, I2, I3)
al.model.given_inertia(A_body, line=16)
# al> %-----
# al> %      Angular velocities
# al> W_A_N> = U1*A1> + U2*A2> + U3*A3>
A.set_ang_vel(N, U1 * A.x + U2 * A.y + U3 * A.z)
al.model.given_ang_vel(A, N, line=19)
B.set_ang_vel(A, OMEGA * A.z)  # al> W_B_A> = OMEGA*A3>
al.model.given_ang_vel(B, A, line=20)
# al> %-----
# al> %      Angular accelerations
A.set_ang_acc(N, al.dt(A.ang_vel_in(N), N))  # al> ALF_A_N> = DT(W_A_N>, N)
al.model.given_ang_acc(A, N, line=23)
B.set_ang_acc(A, al.dt(B.ang_vel_in(A), A))  # al> ALF_B_A> = DT(W_B_A>, A)
al.model.given_ang_acc(B, A, line=24)
# al> %-----
# al> %      Acceleration of mass center of G is 0>
Ao.set_acc(N, Vector(0))  # al> A_Ao_N> = 0>
al.model.given_acc(Ao, N, line=27)
# al> %-----
# al> %      Equations of motion
Zero = al.assign(  # al> Zero = Fr() + FrStar() + Gyrostat(FrStar,CYLINDER,A,B,J)
    "ZERO",
    al.model.fr()
    + al.model.frstar()
    + al.model.gyrostat("FRSTAR", "CYLINDER", A, B, J),
    line=30,
)
Zero = al.model.kane(line=31)  # al> Kane()
# al> %-----
# al> %      Angular momentum of gyrostat
# al> H> = Momentum(ANGULAR, Ao) + Gyrostat(ANGMOM,CYLINDER,A,B,J)
H_vec = al.assign_vector(
    H=al.model.momentum("ANGULAR", Ao)
    + al.model.gyrostat("ANGMOM", "CYLINDER", A, B, J),
    line=34,
)
H = al.assign("H", al.model.mag(H_vec), line=35)  # al> H = Mag(H>)
# al> %-----
# al> %      Angle between angular momentum vector and A3>
# al> PHI = acos( Dot( UNITVEC(H>), A3> ) )
PHI = al.assign("PHI", acos(al.model.dot(al.model.unitvec(H_vec), A.z)), line=38)
# al> %-----
# al> %      Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> %      Input constants, variables, etc. for CODE
# al> Input      tInitial=0,      tFinal=20          % Begin/end times
al.numerics.input({"TINITIAL": 0, "TFINAL": 20}, line=44)
# al> Input      integStp=0.1,    printInt=1          % Integration/print step
al.numerics.input({"INTEGSTP": 0.1, "PRINTINT": 1}, line=45)
# al> Input      absErr=1.0E-07,  relErr=1.0E-07       % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=46)
# al> Input      J=0.07634, I1=1.25, I2=4.25, I3=5
al.numerics.input({"J": 0.07634, "I1": 1.25, "I2": 4.25, "I3": 5}, line=47)
# al> Input  OMEGA=-20.0, U1=0, U2=0.02, U3=1
al.numerics.input({"OMEGA": -20.0, "U1": 0, "U2": 0.02, "U3": 1}, line=48)
# al> %-----
# al> %      Quantities to be output from CODE
# al> Output T, PHI degs, H
al.numerics.output([("T", t, None), ("PHI", PHI, "degs"), ("H", H, None)], line=51)
# al> %-----
# al> %      Fortran code generation for numerical solution
# al> CODE Dynamics() tutor9.for
al.numerics.code("DYNAMICS", file="tutor9.for", line=54)
# al> %*****
# al> %      STABILITY ANALYSIS
# al> %*****
# al> %      Linearization: Perturbation vars + nominal solution parameters
# al> Variables  dU{3}'          % Perturbations of U1, U2, U3
dU1, dU2, dU3 = dynamicsymbols("DU1 DU2 DU3", real=True)
al.declare_variables(dU1, dU2, dU3, primes=1, line=59)
# al> Constants  nU3             % Nominal solution for U3
nU3 = symbols("NU3", real=True)
al.declare_constants(nU3, line=60)
# al> %-----
# al> %      Check nominal solution
# al> CHECK = Evaluate(Zero, U1=0, U1'=0, U2=0, U2'=0, U3=nU3, U3'=0)
CHECK = al.assign(
    "CHECK",
    al.evaluate(
        Zero, {U1: 0, U1.diff(t): 0, U2: 0, U2.diff(t): 0, U3: nU3, U3.diff(t): 0}
    ),
    line=63,
)
# al> %-----
# al> %      Linearize equations of motion about nominal solution
# al> PETURB = Taylor(Zero, 1, U1=0:dU1, U1'=0:dU1', U2=0:dU2, U2'=0:dU2', &
PETURB = al.assign(  # al> U3=nU3:dU3, U3'=0:dU3')
    "PETURB",
    al.taylor(
        Zero,
        1,
        [
            (U1, 0, dU1),
            (U1.diff(t), 0, dU1.diff(t)),
            (U2, 0, dU2),
            (U2.diff(t), 0, dU2.diff(t)),
            (U3, nU3, dU3),
            (U3.diff(t), 0, dU3.diff(t)),
        ],
    ),
    line=66,
)
# al> Solve( PETURB,  dU{1:3}' )
al.solve(PETURB, [dU1.diff(t), dU2.diff(t), dU3.diff(t)], line=68)
# al> %-----
# al> %      Form, x, x', and the A matrix in the equation x'=A*x
Xm = al.assign("XM", Matrix([[dU1, dU2, dU3]]), line=71)  # al> Xm = [ dU1,  dU2,  dU3 ]
# al> Xp = [ dU1'; dU2'; dU3' ]
Xp = al.assign("XP", Matrix([dU1.diff(t), dU2.diff(t), dU3.diff(t)]), line=72)
Am = al.assign("AM", al.d(Xp, Xm), line=73)  # al> Am = D( Xp, Xm )
# al> %-----
# al> %      To find eigenvalues of Am symbolically, find the roots of the
# al> %      equation found by setting the determinant of LAMBDA*I-A = 0
LAMBDA = dynamicsymbols("LAMBDA", real=True)  # al> Variables LAMBDA
al.declare_variables(LAMBDA, line=77)
# al> DET = Det( LAMBDA*DIAGMAT(3,1) - Am )
DET = al.assign("DET", al.det(LAMBDA * al.diagmat(3, 1) - Am), line=78)
# al> %-----
# al> %      Inspection of DET shows that LAMBDA=0 is a root
DET = al.assign("DET", al.val(DET) / (LAMBDA), line=81)  # al> DET /= LAMBDA
# al> %-----
# al> %      With J=0.07634, I1=1.25, I2=4.25, I3=5, nU3=1,
# al> %      determine the values of OMEGA which result in LAMBDA > 0
DET = al.assign(  # al> DET := Evaluate(DET, J=0.07634, I1=1.25, I2=4.25, I3=5, nU3=1)
    "DET", al.evaluate(DET, {J: 0.07634, I1: 1.25, I2: 4.25, I3: 5, nU3: 1}), line=85
)
# al> %-----
# al> %      Record Autolev responses
al.save("tutor9.all", line=88)  # al> Save tutor9.all

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
    """``python tutor9.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
