"""Autolev script tutor6f.al, converted to Python.

Converted from tutor6f.al by al2py 0.2.0; edit the .al file and
convert again rather than editing this module.

``import tutor6f`` runs the symbolic part silently; ``AUTOLEV`` maps
Autolev names (``"ZERO[1]"``, ``"X'"``) to their current values.
``python tutor6f.py`` prints the transcript Autolev would print
and runs the CODE job (``--help`` lists its options); ``run()`` runs it from
Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor6f.py [-h] [--set NAME=VALUE] [--job STEM] [--tfinal TFINAL]
                         [--outdir OUTDIR] [--plot] [--animate]
                         [--backend {auto,c,llvm,lambdify}] [--zero-missing]
                         [--emit-code DIR] [--no-run] [--max-seconds S]
                         [--max-evals N]

Print the Autolev transcript of tutor6f.al and perform its numerical CODE job.

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
  G = 9.81 m/sec^2
  LA = 1 m
  LB = 2 m
  LO = 1 m
  K = 200 n/m
  C = 300 n*sec/m
  D = 300 n*sec/m
  MP = 10 kg
  MQ = 20 kg
  QA = 20 deg
  QB = 60 deg
  U1 = 0 rad/sec
  U2 = 0 rad/sec
  TINITIAL = 0
  TFINAL = 20
  INTEGSTP = 0.2
  PRINTINT = 1
  ABSERR = 1.0E-07
  RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor6f: CODE Dynamics tutor6f.c (line 85) -> tutor6f.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from al2py_runtime.functions import sin
    from sympy import Eq, symbols
    from sympy.physics.mechanics import Force, Particle
    from sympy.physics.mechanics.loads import gravity
    from sympy.physics.vector import Point, ReferenceFrame

al = Workspace("tutor6f.al", __file__)

# al> %      File:  tutor6f.al (tutor6.al modified to find F1, F2)      [Autolev:
# al+ http://www.autolev.com]
# al> %      Problem:  Spring-Damper-Restrained Double Pendulum --
# al> %              Motion and Contact Forces
# al> %-----
# al> %      Newtonian, bodies, frames, particles, points
# al> Newtonian      N
N = ReferenceFrame("N")
al.model.declare_newtonian(N)
# al> Frames         A, B
A, B = ReferenceFrame("A"), ReferenceFrame("B")
al.model.declare_frames(A, B)
# al> Particles      P, Q
P, Q = Point("P"), Point("Q")
P_particle, Q_particle = Particle("P", P, 0), Particle("Q", Q, 0)
al.model.declare_particles(P_particle, Q_particle)
# al> Points         O
O_ = Point("O")
al.model.declare_points(O_)
# al> %-----
# al> %      Variables, constants, and specified
# al> Variables      U{4}'          % Generalized Speeds; derivatives
U1, U2, U3, U4 = dynamicsymbols("U1 U2 U3 U4", real=True)
al.declare_variables(U1, U2, U3, U4, primes=1, line=12)
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
# al> Specified      FP = -D*QA'    % Force on P
FP = dynamicsymbols("FP", real=True)
al.declare_specified(FP, line=19)
al.assign("FP", -D * QA.diff(t), line=19)
# al> %-----
# al> %      Mass and inertia
# al> Mass           P=MP, Q=MQ
MP, MQ = symbols("MP MQ", nonnegative=True)
al.declare_constants(MP, MQ, line=22)
P_particle.mass = MP
Q_particle.mass = MQ
al.model.given_masses(P_particle, Q_particle, line=22)
# al> %-----
# al> %      Geometry relating unit vectors
# al> Simprot(N, A, 3, QA)
A.orient_axis(N, N.z, QA)
al.model.given_orientation(A, N, line=25)
# al> Simprot(N, B, 3, QB)
B.orient_axis(N, N.z, QB)
al.model.given_orientation(B, N, line=26)
# al> %-----
# al> %      Position vectors
# al> P_O_P> = LA*A1>
P.set_pos(O_, LA * A.x)
al.model.given_pos(P, O_, line=29)
# al> P_P_Q> = LB*B1>
Q.set_pos(P, LB * B.x)
al.model.given_pos(Q, P, line=30)
# al> %-----
# al> %      Kinematical differential equations
# al> QA' = U1/LA
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=33))
# al> QB' = U2/LB
kd_eqs.append(al.kd(Eq(QB.diff(t), U2 / LB), line=34))
# al> %-----
# al> %      Angular velocities
# al> W_A_N> = QA'*A3>
A.set_ang_vel(N, QA.diff(t) * A.z)
al.model.given_ang_vel(A, N, line=37)
# al> W_B_N> = QB'*B3>
B.set_ang_vel(N, QB.diff(t) * B.z)
al.model.given_ang_vel(B, N, line=38)
# al> %-----
# al> %      Velocities
# al> V_O_N> = U3*N1> + U4*N2>          % Brings into evidence F1, F2
O_.set_vel(N, U3 * N.x + U4 * N.y)
al.model.given_vel(O_, N, line=41)
# al> V2pts(N, A, O, P)
P.v2pt_theory(O_, N, A)
al.model.formed_vel(P, N, line=42)
# al> V2pts(N, B, P, Q)
Q.v2pt_theory(P, N, B)
al.model.formed_vel(Q, N, line=43)
# al> %-----
# al> %      Motion constraints
# al> AUXILIARY[1] = Dot(V_O_N>, N1>)    % Dot(V_O_N>,N1>) = 0
AUXILIARY = al.assign("AUXILIARY[1]", al.model.dot(O_.vel(N), N.x), line=46)
# al> AUXILIARY[2] = Dot(V_O_N>, N2>)          % Dot(V_O_N>,N2>) = 0
AUXILIARY = al.assign("AUXILIARY[2]", al.model.dot(O_.vel(N), N.y), line=47)
# al> Constrain( AUXILIARY[U3,U4] )          % Solves for U3,U4
al.model.constrain("AUXILIARY", [U3, U4], line=48)
# al> %-----
# al> %      Forces
# al> Gravity( G*N1> )
loads = al.model.loads  # sympy Force/Torque loads
loads += gravity(G * N.x, P_particle, Q_particle)
al.model.given_gravity(G * N.x)
# al> Force_P> += Fp*A2>
loads.append(Force(P, FP * A.y))
al.model.given_force(P, line=52)
# al> LOQ = Mag(P_O_Q>)                        % Distance from O to Q
LOQ = al.assign("LOQ", al.model.mag(al.model.pos(O_, Q)), line=53)
# al> STRETCH = LOQ - LO                       % Stretch of spring
al.assign("STRETCH", LOQ - LO, line=54)
# al> UVEC> = P_O_Q> / LOQ                     % Unit vector directed from O to Q
UVEC_vec = al.assign_vector(UVEC=al.model.pos(O_, Q) / LOQ, line=55)
# al> STRETCH' = Dot(V_Q_N>,UVEC>)            % Time rate of change of stretch
al.assign("STRETCH'", al.model.dot(Q.vel(N), UVEC_vec), line=56)
# al> Force(O/Q, (-K*STRETCH-C*STRETCH')*UVEC> )
loads += [
    Force(O_, -((-K * STRETCH - C * STRETCH.diff(t)) * UVEC_vec)),
    Force(Q, (-K * STRETCH - C * STRETCH.diff(t)) * UVEC_vec),
]
# al> Force_O> += F1*N1> + F2*N2>
loads.append(Force(O_, F1 * N.x + F2 * N.y))
al.model.given_force(O_, line=58)
# al> %-----
# al> %      Equations of motion
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.model.fr() + al.model.frstar(), line=61)
# al> Factor(Zero, G, SIN(QA-QB) )             % Simplify slightly
Zero = al.update("ZERO", al.factor(Zero, G, sin(QA - QB)), line=62)
# al> Kane(F1,F2)                              % Solve for F1, F2
Zero = al.model.kane(F1, F2, line=63)
# al> %-----
# al> %      Units system for CODE input/output conversions
# al> UnitSystem kg,meter,sec
al.numerics.unit_system("kg", "meter", "sec")
# al> %-----
# al> %      Input constants, variables, etc. for CODE
# al> Input G=9.81 m/sec^2, LA=1 m, LB=2 m
al.numerics.input({"G": (9.81, "m/sec^2"), "LA": (1, "m"), "LB": (2, "m")}, line=69)
# al> Input LO=1 m, K=200 n/m
al.numerics.input({"LO": (1, "m"), "K": (200, "n/m")}, line=70)
# al> Input C=300 n*sec/m, D=300 n*sec/m
al.numerics.input({"C": (300, "n*sec/m"), "D": (300, "n*sec/m")}, line=71)
# al> Input MP=10 kg, MQ=20 kg
al.numerics.input({"MP": (10, "kg"), "MQ": (20, "kg")}, line=72)
# al> Input QA=20 deg, QB=60 deg               % Initial values
al.numerics.input({"QA": (20, "deg"), "QB": (60, "deg")}, line=73)
# al> Input U1=0 rad/sec, U2=0 rad/sec        % Initial values
al.numerics.input({"U1": (0, "rad/sec"), "U2": (0, "rad/sec")}, line=74)
# al> Input tInitial=0, tFinal=20             % Begin/end times
al.numerics.input({"TINITIAL": 0, "TFINAL": 20}, line=75)
# al> Input integStp=0.2, printInt=1         % Integration/print step
al.numerics.input({"INTEGSTP": 0.2, "PRINTINT": 1}, line=76)
# al> Input absErr=1.0E-07, relErr=1.0E-07  % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=77)
# al> %-----
# al> %      Quantities to be output from CODE
# al> ECHECK = NiCheck()                      % Checking function
ECHECK = al.assign("ECHECK", al.model.nicheck(), line=80)
# al> Output T, STRETCH m, QA deg, QB deg, ECHECK joules
al.numerics.output(
    [
        ("T", t, None),
        ("STRETCH", STRETCH, "m"),
        ("QA", QA, "deg"),
        ("QB", QB, "deg"),
        ("ECHECK", ECHECK, "joules"),
    ],
    line=81,
)
# al> Output T, F1 newtons, F2 newtons
al.numerics.output(
    [("T", t, None), ("F1", F1, "newtons"), ("F2", F2, "newtons")], line=82
)
# al> %-----
# al> %      C code generation for numerical solution
# al> CODE Dynamics() tutor6f.c
al.numerics.code("DYNAMICS", file="tutor6f.c", line=85)
# al> %-----
# al> %      Record Autolev responses
# al> Save tutor6f.all
al.save("tutor6f.all", line=88)

AUTOLEV = al.names()


def run(values=None, /, **overrides):
    """Perform this script's CODE job; keyword arguments override Inputs.

    Without ``job=`` it is the only job, else the only Dynamics/ODE job,
    else an error listing the jobs (``job="NAME"`` or ``job=2`` picks one).

    Values are in the Input's own units (``run(QA=30)`` with ``QA`` in deg).
    ``result["NAME"]`` is a numpy array with one value per output row.
    """
    return al.numerics.run(values, **overrides)


al.numerics.document_run(run)  # its Inputs become keyword parameters (tab completion)


def ode_function(values=None, /, **overrides):
    """``(f, y0, names)`` for ``scipy.integrate.solve_ivp(f, (t0, t1), y0)``:
    the only CODE Dynamics/ODE job's equations of motion (else ``job=``
    names one) in internal units (SI, radians);
    keyword arguments override Inputs as for ``run()``, which integrates
    the same function."""
    return al.numerics.ode_function(values, **overrides)


def kanes_method():
    """``sympy.physics.mechanics.KanesMethod`` of this script's model, with
    ``mass_matrix_full`` and ``forcing_full`` formed."""
    return al.model.kanes_method()


def evaluate(name, values=None, /, **given):
    """The named Autolev quantity as a number (a numpy array for a matrix).

    Input values (in their own units), the values given here and every named
    intermediate are substituted: ``evaluate("ZERO", QA=30)``.  The quantity
    is compiled on the first call; later calls take microseconds.  Values may
    be numpy arrays: the result has their shape in front
    (``evaluate("AMAT", U6=speeds)``: one matrix per speed).  A Specified
    quantity nobody gave is 0, as in ``run()``; a constant nobody gave stops,
    unless ``zero_missing=True``.
    """
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, *, executor=None, job=None, **given):
    """A ``Sweep`` of the named quantity (or, without a name, of the CODE
    job, ``job=`` as for ``run()``) over the grid that its 1-D array values span.

    ``sweep("AMAT", U6=-speeds / 0.3)``: ``.values`` (one matrix per speed),
    ``.eigenvalues()`` (branches followed across the grid), ``.to_pandas()``,
    ``.plot()``.  Several arrays give their product; scalars are fixed.
    ``executor``: any ``concurrent.futures.Executor`` (a process pool,
    Dask's ``client.get_executor()``) or ``"dask"``; the results are the
    serial ones.
    """
    return al.numerics.sweep(
        name,
        values,
        executor=executor,
        job=job,
        origin=(__name__, globals().get("__file__")),
        **given,
    )


def linearize(values=None, /, *, job=None, symbolic=False, **overrides):
    """The CODE job's equations of motion linearized, ``x' = A x + B r``,
    about the point its Inputs and ``overrides`` give (as for ``run()``).

    ``lin = linearize(U6=-5 / 0.3)``: ``lin.A``, ``lin.B`` (SI units,
    radians), ``lin.states``, ``lin.inputs`` (the Specified quantities with
    no equation), ``lin.eigenvalues()``; ``A, B = linearize()`` unpacks.
    ``symbolic=True`` keeps the constants as symbols (sympy matrices).
    """
    return al.numerics.linearize(values, job=job, symbolic=symbolic, **overrides)


def main(argv: list[str] | None = None) -> int:
    """``python tutor6f.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
