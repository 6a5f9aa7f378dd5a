"""Autolev script tutor4.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor4`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor4.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor4.py [-h] [options]

Print the Autolev transcript of tutor4.al and perform its numerical CODE job.

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
  K = 200 n/m       MP = 10 kg        MQ = 20 kg        QA = -30 deg
  QB = 30 deg       ABSERR = 1.0E-07  RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor4: CODE Nonlinear tutor4.c (line 58) -> tutor4.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols, t
    from sympy import Eq, symbols
    from sympy.physics.mechanics import Force, Particle
    from sympy.physics.mechanics.loads import gravity
    from sympy.physics.vector import Point, ReferenceFrame, Vector

al = Workspace("tutor4.al", __file__)

# al> % File: tutor4.al [Autolev: http://www.autolev.com]
# al> % Problem: Spring-Restrained Double Pendulum -- Equilibrium Configuration
# al> %-----
# al> % Newtonian, bodies, frames, particles, points
N = ReferenceFrame("N")  # al> Newtonian N
al.model.declare_newtonian(N)
A, B = ReferenceFrame("A"), ReferenceFrame("B")  # al> Frames A, B
al.model.declare_frames(A, B)
P, Q = Point("P"), Point("Q")  # al> Particles P, Q
P_particle, Q_particle = Particle("P", P, 0), Particle("Q", Q, 0)
al.model.declare_particles(P_particle, Q_particle)
O_ = Point("O")  # al> Points O
al.model.declare_points(O_)
# al> %-----
# al> % Mathematical declarations: variables, constants, mass
U1, U2 = dynamicsymbols("U1 U2", real=True)  # al> Variables U{2} % Generalized speeds
al.declare_variables(U1, U2, line=11)
# al> Variables QA', QB' % Generalized coordinates; derivatives
QA, QB = dynamicsymbols("QA QB", real=True)
al.declare_variables(QA, QB, primes=1, line=12)
# al> Constants G, LA, LB % Gravitational acceleration, lengths of A, B
G, LA, LB = symbols("G LA LB", real=True)
al.declare_constants(G, LA, LB, line=13)
# al> Constants K, LO % Spring constant, natural length of spring
K, LO = symbols("K LO", real=True)
al.declare_constants(K, LO, line=14)
MP, MQ = symbols("MP MQ", nonnegative=True)  # al> Mass P=MP, Q=MQ
al.declare_constants(MP, MQ, line=15)
P_particle.mass = MP
Q_particle.mass = MQ
al.model.given_masses(P_particle, Q_particle, line=15)
# al> %-----
# al> % Geometry relating unit vectors
A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=18)
B.orient_axis(N, N.z, QB)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=19)
# al> %-----
# al> % Position vectors
P.set_pos(O_, LA * A.x)  # al> P_O_P> = LA*A1>
al.model.given_pos(P, O_, line=22)
Q.set_pos(P, LB * B.x)  # al> P_P_Q> = LB*B1>
al.model.given_pos(Q, P, line=23)
# al> %-----
# al> % Kinematical differential equations
# al> QA' = U1/LA
kd_eqs = []  # kinematical differential equations, Eq(q', rhs)
kd_eqs.append(al.kd(Eq(QA.diff(t), U1 / LA), line=26))
kd_eqs.append(al.kd(Eq(QB.diff(t), U2 / LB), line=27))  # al> QB' = U2/LB
# al> %-----
# al> % Angular velocities
A.set_ang_vel(N, QA.diff(t) * A.z)  # al> W_A_N> = QA'*A3>
al.model.given_ang_vel(A, N, line=30)
B.set_ang_vel(N, QB.diff(t) * B.z)  # al> W_B_N> = QB'*B3>
al.model.given_ang_vel(B, N, line=31)
# al> %-----
# al> % Velocities
O_.set_vel(N, Vector(0))  # al> V_O_N> = 0>
al.model.given_vel(O_, N, line=34)
P.v2pt_theory(O_, N, A)  # al> V2pts(N, A, O, P)
al.model.formed_vel(P, N, line=35)
Q.v2pt_theory(P, N, B)  # al> V2pts(N, B, P, Q)
al.model.formed_vel(Q, N, line=36)
# al> %-----
# al> % Forces
# al> Gravity( G*N1> )
loads = al.model.loads  # sympy Force/Torque loads
loads += gravity(G * N.x, P_particle, Q_particle)
al.model.given_gravity(G * N.x)
# al> LOQ = MAG(P_O_Q>) % Distance from O to Q
LOQ = al.assign("LOQ", al.model.mag(al.model.pos(O_, Q)), line=40)
# al> STRETCH = LOQ - LO % Stretch of spring
STRETCH = al.assign("STRETCH", LOQ - LO, line=41)
# al> UVEC> = P_O_Q> / LOQ % Unit vector from O to Q
UVEC_vec = al.assign_vector(UVEC=al.model.pos(O_, Q) / LOQ, line=42)
# al> Force(O/Q, -K*STRETCH*UVEC> ) % Spring force
loads += [Force(O_, -(-K * STRETCH * UVEC_vec)), Force(Q, -K * STRETCH * UVEC_vec)]
# al> %-----
# al> % Equations of motion
Zero = al.assign("ZERO", al.model.fr(), line=46)  # al> Zero = Fr()
# al> Factor(Zero, G) % Simplify slightly
Zero = al.update("ZERO", al.factor(Zero, G), line=47)
# al> %-----
# al> % Units system for CODE input/output conversions
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg,meter,sec
# al> %-----
# al> % Input constants, variables, etc. for CODE
# al> Input G=9.81 m/sec^2, LA=1 m, LB=2 m, LO=1 m, K=200 n/m, MP=10 kg, MQ=20 kg
al.numerics.input(
    {
        "G": (9.81, "m/sec^2"),
        "LA": (1, "m"),
        "LB": (2, "m"),
        "LO": (1, "m"),
        "K": (200, "n/m"),
        "MP": (10, "kg"),
        "MQ": (20, "kg"),
    },
    line=53,
)
# al> Input QA=-30 deg, QB=30 deg % Guess
al.numerics.input({"QA": (-30, "deg"), "QB": (30, "deg")}, line=54)
# al> Input absErr=1.0E-07, relErr=1.0E-07 % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=55)
# al> %-----
# al> % C code generation for numerical solution
# al> CODE Nonlinear(Zero,QA,QB) tutor4.c
al.numerics.code("NONLINEAR", eqs=Zero, unknowns=[QA, QB], file="tutor4.c", line=58)
# al> %-----
# al> % Record Autolev responses
al.save("tutor4.all", line=61)  # al> Save tutor4.all

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
    """``python tutor4.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
