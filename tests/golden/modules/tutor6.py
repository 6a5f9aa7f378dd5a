"""Autolev script tutor6.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor6`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor6.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor6.py [-h] [options]

Print the Autolev transcript of tutor6.al and perform its numerical CODE job.

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
  G = 9.81 m/sec^2  LA = 1 m          LB = 2 m          LO = 1 m
  K = 200 n/m       C = 300 n*sec/m   D = 300 n*sec/m   MP = 10 kg
  MQ = 20 kg        QA = 20 deg       QB = 60 deg       U1 = 0 rad/sec
  U2 = 0 rad/sec    TINITIAL = 0      TFINAL = 20       INTEGSTP = 0.2
  PRINTINT = 1      ABSERR = 1.0E-07  RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor6: CODE Dynamics tutor6.c (line 87) -> tutor6.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from al2py_runtime.functions import sin
    from sympy import Eq, symbols
    from sympy.physics.mechanics import Force, Particle
    from sympy.physics.mechanics.loads import gravity
    from sympy.physics.vector import Point, ReferenceFrame, Vector

al = Workspace("tutor6.al", __file__)

# al> %      File:  tutor6.al      [Autolev: http://www.autolev.com]
# al> %      Problem:  Spring-Damper-Restrained Double Pendulum --
# al> %              Motion and Contact Forces
# al> %-----
# al> %      Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian      N
al.model.declare_newtonian(N)
A, B = ReferenceFrame("A"), ReferenceFrame("B")  # al> Frames         A, B
al.model.declare_frames(A, B)
P, Q = Point("P"), Point("Q")  # al> Particles      P, Q
P_particle, Q_particle = Particle("P", P, 0), Particle("Q", Q, 0)
al.model.declare_particles(P_particle, Q_particle)
O_ = Point("O")  # al> Points         O
al.model.declare_points(O_)
# al> %-----
# al> %      Variables, constants, and specified
# al> Variables      U{2}'          % Generalized Speeds; derivatives
U1, U2 = dynamicsymbols("U1 U2", real=True)
al.declare_variables(U1, U2, primes=1, line=12)
# al> Variables      QA', QB'       % Generalized coordinates; derivatives
QA, QB = dynamicsymbols("QA QB", real=True)
al.declare_variables(QA, QB, primes=1, line=13)
# al> Variables      F1, F2         % Contact forces
F1, F2 = dynamicsymbols("F1 F2", real=True)
al.declare_variables(F1, F2, line=14)
# al> Constants      G, LA, LB      % Gravitational acceleration, lengths of A, B
G, LA, LB = symbols("G LA LB", real=True)
al.declare_constants(G, LA, LB, line=15)
# al> Constants      K, LO          % Spring constant, natural length of spring
K, LO = symbols("K LO", real=True)
al.declare_constants(K, LO, line=16)
# al> Constants      C, D           % Damping constants
C, D = symbols("C D", real=True)
al.declare_constants(C, D, line=17)
# al> Specified      STRETCH'       % Elongation of spring joining O and Q
STRETCH = dynamicsymbols("STRETCH", real=True)
al.declare_specified(STRETCH, primes=1, line=18)
FP = dynamicsymbols("FP", real=True)  # al> Specified      FP = -D*QA'    % Force on P
al.declare_specified(FP, line=19)
al.assign("FP", -D * QA.diff(t), line=19)
# al> %-----
# al> %      Mass and inertia
MP, MQ = symbols("MP MQ", nonnegative=True)  # al> Mass           P=MP, Q=MQ
al.declare_constants(MP, MQ, line=22)
P_particle.mass = MP
Q_particle.mass = MQ
al.model.given_masses(P_particle, Q_particle, line=22)
# al> %-----
# al> %      Geometry relating unit vectors
A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=25)
B.orient_axis(N, N.z, QB)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=26)
# al> %-----
# al> %      Position vectors
P.set_pos(O_, LA * A.x)  # al> P_O_P> = LA*A1>
al.model.given_pos(P, O_, line=29)
Q.set_pos(P, LB * B.x)  # al> P_P_Q> = LB*B1>
al.model.given_pos(Q, P, line=30)
# al> %-----
# al> %      Kinematical differential equations
# al> QA' = U1/LA
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=33))
kd_eqs.append(al.kd(Eq(QB.diff(t), U2 / LB), line=34))  # al> QB' = U2/LB
# al> %-----
# al> %      Angular velocities
A.set_ang_vel(N, QA.diff(t) * A.z)  # al> W_A_N> = QA'*A3>
al.model.given_ang_vel(A, N, line=37)
B.set_ang_vel(N, QB.diff(t) * B.z)  # al> W_B_N> = QB'*B3>
al.model.given_ang_vel(B, N, line=38)
# al> %-----
# al> %      Velocities
# al> % V_O_N> = U3*N1> + U4*N2>          % Brings into evidence F1, F2
O_.set_vel(N, Vector(0))  # al> V_O_N> = 0>
al.model.given_vel(O_, N, line=42)
P.v2pt_theory(O_, N, A)  # al> V2pts(N, A, O, P)
al.model.formed_vel(P, N, line=43)
Q.v2pt_theory(P, N, B)  # al> V2pts(N, B, P, Q)
al.model.formed_vel(Q, N, line=44)
# al> %-----
# al> %      Motion constraints
# al> % AUXILIARY[1] = Dot(V_O_N>, N1>)    % Dot(V_O_N>,N1>) = 0
# al> % AUXILIARY[2] = Dot(V_O_N>, N2>)          % Dot(V_O_N>,N2>) = 0
# al> % Constrain( AUXILIARY[U3,U4] )          % Solves for U3,U4
# al> %-----
# al> %      Forces
# al> Gravity( G*N1> )
loads = al.model.loads  # sympy Force/Torque loads
loads += gravity(G * N.x, P_particle, Q_particle)
al.model.given_gravity(G * N.x)
loads.append(Force(P, FP * A.y))  # al> Force_P> += Fp*A2>
al.model.given_force(P, line=53)
# al> LOQ = Mag(P_O_Q>)                        % Distance from O to Q
LOQ = al.assign("LOQ", al.model.mag(al.model.pos(O_, Q)), line=54)
# al> STRETCH = LOQ - LO                       % Stretch of spring
al.assign("STRETCH", LOQ - LO, line=55)
# al> UVEC> = P_O_Q> / LOQ                     % Unit vector directed from O to Q
UVEC_vec = al.assign_vector(UVEC=al.model.pos(O_, Q) / LOQ, line=56)
# al> STRETCH' = Dot(V_Q_N>,UVEC>)            % Time rate of change of stretch
al.assign("STRETCH'", al.model.dot(Q.vel(N), UVEC_vec), line=57)
loads += [  # al> Force(O/Q, (-K*STRETCH-C*STRETCH')*UVEC> )
    Force(O_, -((-K * STRETCH - C * STRETCH.diff(t)) * UVEC_vec)),
    Force(Q, (-K * STRETCH - C * STRETCH.diff(t)) * UVEC_vec),
]
loads.append(Force(O_, F1 * N.x + F2 * N.y))  # al> Force_O> += F1*N1> + F2*N2>
al.model.given_force(O_, line=59)
# al> %-----
# al> %      Equations of motion
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.model.fr() + al.model.frstar(), line=62)
# al> Factor(Zero, G, SIN(QA-QB) )             % Simplify slightly
Zero = al.update("ZERO", al.factor(Zero, G, sin(QA - QB)), line=63)
Zero = al.model.kane(line=64)  # al> Kane()
# al> % Kane(F1,F2)                            % Solve for F1, F2
# al> %-----
# al> %      Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> %      Input constants, variables, etc. for CODE
# al> Input G=9.81 m/sec^2, LA=1 m, LB=2 m
al.numerics.input({"G": (9.81, "m/sec^2"), "LA": (1, "m"), "LB": (2, "m")}, line=71)
# al> Input LO=1 m, K=200 n/m
al.numerics.input({"LO": (1, "m"), "K": (200, "n/m")}, line=72)
# al> Input C=300 n*sec/m, D=300 n*sec/m
al.numerics.input({"C": (300, "n*sec/m"), "D": (300, "n*sec/m")}, line=73)
# al> Input MP=10 kg, MQ=20 kg
al.numerics.input({"MP": (10, "kg"), "MQ": (20, "kg")}, line=74)
# al> Input QA=20 deg, QB=60 deg               % Initial values
al.numerics.input({"QA": (20, "deg"), "QB": (60, "deg")}, line=75)
# al> Input U1=0 rad/sec, U2=0 rad/sec        % Initial values
al.numerics.input({"U1": (0, "rad/sec"), "U2": (0, "rad/sec")}, line=76)
# al> Input tInitial=0, tFinal=20             % Begin/end times
al.numerics.input({"TINITIAL": 0, "TFINAL": 20}, line=77)
# al> Input integStp=0.2, printInt=1         % Integration/print step
al.numerics.input({"INTEGSTP": 0.2, "PRINTINT": 1}, line=78)
# al> Input absErr=1.0E-07, relErr=1.0E-07  % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=79)
# al> %-----
# al> %      Quantities to be output from CODE
# al> ECHECK = NiCheck()                      % Checking function
ECHECK = al.assign("ECHECK", al.model.nicheck(), line=82)
al.numerics.output(  # al> Output T, STRETCH m, QA deg, QB deg, ECHECK joules
    [
        ("T", t, None),
        ("STRETCH", STRETCH, "m"),
        ("QA", QA, "deg"),
        ("QB", QB, "deg"),
        ("ECHECK", ECHECK, "joules"),
    ],
    line=83,
)
# al> % Output T, F1 newtons, F2 newtons
# al> %-----
# al> %      C code generation for numerical solution
al.numerics.code("DYNAMICS", file="tutor6.c", line=87)  # al> CODE Dynamics() tutor6.c
# al> %-----
# al> %      Record Autolev responses
al.save("tutor6.all", line=90)  # al> Save tutor6.all

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
    """``python tutor6.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
