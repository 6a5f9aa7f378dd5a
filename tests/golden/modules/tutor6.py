"""Autolev script tutor6.al, converted to Python.

Converted from tutor6.al by al2py 0.1.0; edit the .al file and
convert again rather than editing this module.

``import tutor6`` runs the symbolic part silently; ``AUTOLEV`` maps
Autolev names (``"ZERO[1]"``, ``"X'"``) to their current values.
``python tutor6.py`` prints the transcript Autolev would print
and runs the CODE job (``--help`` lists its options); ``run()`` runs it from
Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write(
        "usage: python tutor6.py [-h] [--set NAME=VALUE] [--job STEM] [--tfinal"
        " TFINAL]\n"
        "                        [--outdir OUTDIR] [--plot]\n"
        "                        [--backend {auto,c,llvm,lambdify}] [--zero-mis"
        "sing]\n"
        "                        [--emit-code DIR] [--no-run] [--max-seconds S]"
        "\n"
        "                        [--max-evals N]\n"
        "\n"
        "Print the Autolev transcript of tutor6.al and perform its numerical CO"
        "DE job.\n"
        "\n"
        "options:\n"
        "  -h, --help            show this help message and exit\n"
        "  --set NAME=VALUE      change an Input value (repeatable); VALUE is i"
        "n the\n"
        "                        Input's unit\n"
        "  --job STEM            perform (or with --emit-code, write) only the "
        "CODE job\n"
        "                        whose file is STEM (see the list below)\n"
        "  --tfinal TFINAL       final time (sets TFINAL; Dynamics/ODE jobs)\n"
        "  --outdir OUTDIR       directory for every file the script writes: Sa"
        "ve files,\n"
        "                        output tables and plots, under their base name"
        "s\n"
        "                        (default: .)\n"
        "  --plot                also write STEM.n.png plots\n"
        "  --backend {auto,c,llvm,lambdify}\n"
        "                        how Dynamics/ODE equations are evaluated (defa"
        "ult:\n"
        "                        $AL2PY_BACKEND or auto, the fastest available)"
        "\n"
        "  --zero-missing        use 0 for constants that no Input gives (by de"
        "fault the\n"
        "                        job stops and names them; or AL2PY_ZERO_MISSIN"
        "G=1)\n"
        "  --emit-code DIR       write the program (C, MATLAB or Fortran, as CO"
        "DE names\n"
        "                        it) and STEM.in of each CODE job into DIR (as "
        "'al2py\n"
        "                        code' does) instead of running\n"
        "  --no-run              only print the transcript; perform no CODE job"
        " and\n"
        "                        write no file\n"
        "  --max-seconds S       time budget of one integration (default 120; o"
        "r\n"
        "                        AL2PY_MAX_SECONDS)\n"
        "  --max-evals N         right-hand-side evaluations allowed in one int"
        "egration\n"
        "                        (default 5e+06; or AL2PY_MAX_EVALS)\n"
        "\n"
        "Input values (change with --set NAME=VALUE, in these units):\n"
        "  G = 9.81 m/sec^2\n"
        "  LA = 1 m\n"
        "  LB = 2 m\n"
        "  LO = 1 m\n"
        "  K = 200 n/m\n"
        "  C = 300 n*sec/m\n"
        "  D = 300 n*sec/m\n"
        "  MP = 10 kg\n"
        "  MQ = 20 kg\n"
        "  QA = 20 deg\n"
        "  QB = 60 deg\n"
        "  U1 = 0 rad/sec\n"
        "  U2 = 0 rad/sec\n"
        "  TINITIAL = 0\n"
        "  TFINAL = 20\n"
        "  INTEGSTP = 0.2\n"
        "  PRINTINT = 1\n"
        "  ABSERR = 1.0E-07\n"
        "  RELERR = 1.0E-07\n"
        "Jobs (--job STEM runs one; default: all, in script order):\n"
        "  tutor6: CODE Dynamics tutor6.c (line 87) -> tutor6.1, ...\n"
        "Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, "
        "RELERR.\n"
    )
    raise SystemExit(0)

from al2py_runtime import Workspace, t  # noqa: E402
from al2py_runtime.functions import sin  # noqa: E402
from sympy import Eq  # noqa: E402
from sympy.physics.vector import Vector  # noqa: E402

al = Workspace("tutor6.al")

# File:  tutor6.al      [Autolev: http://www.autolev.com]
# Problem:  Spring-Damper-Restrained Double Pendulum --
# Motion and Contact Forces
# -----
# Newtonian, bodies, frames, particles, points
# al> Newtonian      N
N = al.newtonian("N")
# al> Frames         A, B
A, B = al.frames("A", "B")
# al> Particles      P, Q
P, Q = al.particles("P", "Q")
P_particle, Q_particle = al.particle(P), al.particle(Q)
# al> Points         O
O_ = al.points("O")
# -----
# Variables, constants, and specified
# al> Variables      U{2}'          % Generalized Speeds; derivatives
U1, U2 = al.variables("U1'", "U2'", line=12)
# al> Variables      QA', QB'       % Generalized coordinates; derivatives
QA, QB = al.variables("QA'", "QB'", line=13)
# al> Variables      F1, F2         % Contact forces
F1, F2 = al.variables("F1", "F2", line=14)
# al> Constants      G, LA, LB      % Gravitational acceleration, lengths of A, B
G, LA, LB = al.constants("G", "LA", "LB", line=15)
# al> Constants      K, LO          % Spring constant, natural length of spring
K, LO = al.constants("K", "LO", line=16)
# al> Constants      C, D           % Damping constants
C, D = al.constants("C", "D", line=17)
# al> Specified      STRETCH'       % Elongation of spring joining O and Q
STRETCH = al.specified("STRETCH'", line=18)
# al> Specified      FP = -D*QA'    % Force on P
FP = al.specified("FP", line=19)
al.assign("FP", -D * QA.diff(t), line=19)
# -----
# Mass and inertia
# al> Mass           P=MP, Q=MQ
MP, MQ = al.constants("MP+", "MQ+", line=22)
al.set_mass(P, MP)
al.set_mass(Q, MQ)
# -----
# Geometry relating unit vectors
# al> Simprot(N, A, 3, QA)
# sympy: A.orient_axis(N, N.z, QA)
al.simprot(N, A, 3, QA, line=25)
# al> Simprot(N, B, 3, QB)
# sympy: B.orient_axis(N, N.z, QB)
al.simprot(N, B, 3, QB, line=26)
# -----
# Position vectors
# al> P_O_P> = LA*A1>
al.set_pos(P, O_, LA * A.x, line=29)
# al> P_P_Q> = LB*B1>
al.set_pos(Q, P, LB * B.x, line=30)
# -----
# Kinematical differential equations
# al> QA' = U1/LA
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=33))
# al> QB' = U2/LB
kd_eqs.append(al.kd(Eq(QB.diff(t), U2 / LB), line=34))
# -----
# Angular velocities
# al> W_A_N> = QA'*A3>
al.set_ang_vel(A, N, QA.diff(t) * A.z, line=37)
# al> W_B_N> = QB'*B3>
al.set_ang_vel(B, N, QB.diff(t) * B.z, line=38)
# -----
# Velocities
# V_O_N> = U3*N1> + U4*N2>          % Brings into evidence F1, F2
# al> V_O_N> = 0>
al.set_vel(O_, N, Vector(0), line=42)
# al> V2pts(N, A, O, P)
# sympy: P.v2pt_theory(O_, N, A)
al.v2pts(N, A, O_, P, line=43)
# al> V2pts(N, B, P, Q)
# sympy: Q.v2pt_theory(P, N, B)
al.v2pts(N, B, P, Q, line=44)
# -----
# Motion constraints
# AUXILIARY[1] = Dot(V_O_N>, N1>)    % Dot(V_O_N>,N1>) = 0
# AUXILIARY[2] = Dot(V_O_N>, N2>)          % Dot(V_O_N>,N2>) = 0
# Constrain( AUXILIARY[U3,U4] )          % Solves for U3,U4
# -----
# Forces
# al> Gravity( G*N1> )
al.gravity(G * N.x)
# al> Force_P> += Fp*A2>
al.set_force(P, al.force_on(P) + (FP * A.y), line=53)
# al> LOQ = Mag(P_O_Q>)                        % Distance from O to Q
LOQ = al.assign("LOQ", al.mag(al.pos(O_, Q)), line=54)
# al> STRETCH = LOQ - LO                       % Stretch of spring
al.assign("STRETCH", LOQ - LO, line=55)
# al> UVEC> = P_O_Q> / LOQ                     % Unit vector directed from O to Q
UVEC_vec = al.assign("UVEC>", al.pos(O_, Q) / LOQ, line=56)
# al> STRETCH' = Dot(V_Q_N>,UVEC>)            % Time rate of change of stretch
al.assign("STRETCH'", al.dot(al.vel(Q, N), UVEC_vec), line=57)
# al> Force(O/Q, (-K*STRETCH-C*STRETCH')*UVEC> )
al.force_between(O_, Q, (-K * STRETCH - C * STRETCH.diff(t)) * UVEC_vec)
# al> Force_O> += F1*N1> + F2*N2>
al.set_force(O_, al.force_on(O_) + (F1 * N.x + F2 * N.y), line=59)
# -----
# Equations of motion
# al> Zero = Fr() + FrStar()
Zero = al.assign("ZERO", al.fr() + al.frstar(), line=62)
# al> Factor(Zero, G, SIN(QA-QB) )             % Simplify slightly
Zero = al.update("ZERO", al.factor(Zero, G, sin(QA - QB)), line=63)
# al> Kane()
Zero = al.kane(line=64)
# Kane(F1,F2)                            % Solve for F1, F2
# -----
# Units system for CODE input/output conversions
# al> UnitSystem kg,meter,sec
al.numerics.unit_system("kg", "meter", "sec")
# -----
# Input constants, variables, etc. for CODE
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
# -----
# Quantities to be output from CODE
# al> ECHECK = NiCheck()                      % Checking function
ECHECK = al.assign("ECHECK", al.nicheck(), line=82)
# al> Output T, STRETCH m, QA deg, QB deg, ECHECK joules
al.numerics.output(
    [
        ("T", t, None),
        ("STRETCH", STRETCH, "m"),
        ("QA", QA, "deg"),
        ("QB", QB, "deg"),
        ("ECHECK", ECHECK, "joules"),
    ],
    line=83,
)
# Output T, F1 newtons, F2 newtons
# -----
# C code generation for numerical solution
# al> CODE Dynamics() tutor6.c
al.numerics.code("DYNAMICS", file="tutor6.c", line=87)
# -----
# Record Autolev responses
# al> Save tutor6.all
al.save("tutor6.all")

AUTOLEV = al.names()

# The Autolev source, echoed in the transcript.
AL_SOURCE = (
    "%      File:  tutor6.al      [Autolev: http://www.autolev.com]",
    "%      Problem:  Spring-Damper-Restrained Double Pendulum --",
    "%              Motion and Contact Forces",
    "%-----",
    "%      Newtonian, bodies, frames, particles, points",
    "Newtonian      N",
    "Frames         A, B",
    "Particles      P, Q",
    "Points         O",
    "%-----",
    "%      Variables, constants, and specified",
    "Variables      U{2}'          % Generalized Speeds; derivatives",
    "Variables      QA', QB'       % Generalized coordinates; derivatives",
    "Variables      F1, F2         % Contact forces",
    "Constants      G, LA, LB      % Gravitational acceleration, lengths of A, B",
    "Constants      K, LO          % Spring constant, natural length of spring",
    "Constants      C, D           % Damping constants",
    "Specified      STRETCH'       % Elongation of spring joining O and Q",
    "Specified      FP = -D*QA'    % Force on P",
    "%-----",
    "%      Mass and inertia",
    "Mass           P=MP, Q=MQ",
    "%-----",
    "%      Geometry relating unit vectors",
    "Simprot(N, A, 3, QA)",
    "Simprot(N, B, 3, QB)",
    "%-----",
    "%      Position vectors",
    "P_O_P> = LA*A1>",
    "P_P_Q> = LB*B1>",
    "%-----",
    "%      Kinematical differential equations",
    "QA' = U1/LA",
    "QB' = U2/LB",
    "%-----",
    "%      Angular velocities",
    "W_A_N> = QA'*A3>",
    "W_B_N> = QB'*B3>",
    "%-----",
    "%      Velocities",
    "% V_O_N> = U3*N1> + U4*N2>          % Brings into evidence F1, F2",
    "V_O_N> = 0>",
    "V2pts(N, A, O, P)",
    "V2pts(N, B, P, Q)",
    "%-----",
    "%      Motion constraints",
    "% AUXILIARY[1] = Dot(V_O_N>, N1>)    % Dot(V_O_N>,N1>) = 0",
    "% AUXILIARY[2] = Dot(V_O_N>, N2>)          % Dot(V_O_N>,N2>) = 0",
    "% Constrain( AUXILIARY[U3,U4] )          % Solves for U3,U4",
    "%-----",
    "%      Forces",
    "Gravity( G*N1> )",
    "Force_P> += Fp*A2>",
    "LOQ = Mag(P_O_Q>)                        % Distance from O to Q",
    "STRETCH = LOQ - LO                       % Stretch of spring",
    "UVEC> = P_O_Q> / LOQ                     % Unit vector directed from O to Q",
    "STRETCH' = Dot(V_Q_N>,UVEC>)            % Time rate of change of stretch",
    "Force(O/Q, (-K*STRETCH-C*STRETCH')*UVEC> )",
    "Force_O> += F1*N1> + F2*N2>",
    "%-----",
    "%      Equations of motion",
    "Zero = Fr() + FrStar()",
    "Factor(Zero, G, SIN(QA-QB) )             % Simplify slightly",
    "Kane()",
    "% Kane(F1,F2)                            % Solve for F1, F2",
    "%-----",
    "%      Units system for CODE input/output conversions",
    "UnitSystem kg,meter,sec",
    "%-----",
    "%      Input constants, variables, etc. for CODE",
    "Input G=9.81 m/sec^2, LA=1 m, LB=2 m",
    "Input LO=1 m, K=200 n/m",
    "Input C=300 n*sec/m, D=300 n*sec/m",
    "Input MP=10 kg, MQ=20 kg",
    "Input QA=20 deg, QB=60 deg               % Initial values",
    "Input U1=0 rad/sec, U2=0 rad/sec        % Initial values",
    "Input tInitial=0, tFinal=20             % Begin/end times",
    "Input integStp=0.2, printInt=1         % Integration/print step",
    "Input absErr=1.0E-07, relErr=1.0E-07  % Error tolerances",
    "%-----",
    "%      Quantities to be output from CODE",
    "ECHECK = NiCheck()                      % Checking function",
    "Output T, STRETCH m, QA deg, QB deg, ECHECK joules",
    "% Output T, F1 newtons, F2 newtons",
    "%-----",
    "%      C code generation for numerical solution",
    "CODE Dynamics() tutor6.c",
    "%-----",
    "%      Record Autolev responses",
    "Save tutor6.all",
)


def run(values=None, /, **overrides):
    """Perform this script's CODE job; keyword arguments override Inputs.

    Values are in the Input's own units (``run(QA=30)`` with ``QA`` in deg).
    ``result["NAME"]`` is a numpy array with one value per output row.
    """
    return al.numerics.run(values, **overrides)


al.numerics.document_run(run)  # its Inputs become keyword parameters (tab completion)


def ode_function(values=None, /, **overrides):
    """``(f, y0, names)`` for ``scipy.integrate.solve_ivp(f, (t0, t1), y0)``:
    the CODE job's equations of motion in internal units (SI, radians);
    keyword arguments override Inputs as for ``run()``, which integrates
    the same function."""
    return al.numerics.ode_function(values, **overrides)


def kanes_method():
    """``sympy.physics.mechanics.KanesMethod`` of this script's model, with
    ``mass_matrix_full`` and ``forcing_full`` formed."""
    return al.kanes_method()


def evaluate(name, values=None, /, **given):
    """The named Autolev quantity as a number (a numpy array for a matrix).

    Input values (in their own units), the values given here and every named
    intermediate are substituted: ``evaluate("ZERO", QA=30)``.
    """
    return al.numerics.evaluate_name(name, values, **given)


def main(argv: list[str] | None = None) -> int:
    """``python tutor6.py``: print the transcript, then run the CODE job."""
    return al.main(AL_SOURCE, argv)


if __name__ == "__main__":
    raise SystemExit(main())
