"""Autolev script tutor3.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor3`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor3.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor3.py [-h] [options]

Print the Autolev transcript of tutor3.al and perform its numerical CODE job.

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
  LA = 1 m          LB = 2 m          LC = 2 m          LN = 1 m
  QA = 30 deg       QB = 60 deg       QC = 20 deg       ABSERR = 1.0E-07
  RELERR = 1.0E-07
Jobs (--job STEM runs one; default: all, in script order):
  tutor3: CODE Nonlinear tutor3.for (line 35) -> tutor3.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols
    from sympy import symbols
    from sympy.physics.vector import Point, ReferenceFrame

al = Workspace("tutor3.al", __file__)

# al> %      File:  tutor3.al      [Autolev: http://www.autolev.com]
# al> %      Problem:  Solving a set of nonlinear equations (4-bar linkage)
# al> %-----
# al> %      Physical declarations:  Frames and Points
A, B, C, N = (  # al> Frames      A, B, C, N
    ReferenceFrame("A"),
    ReferenceFrame("B"),
    ReferenceFrame("C"),
    ReferenceFrame("N"),
)
al.model.declare_frames(A, B, C, N)
# al> Points      O, P, Q, R
O_, P, Q, R = Point("O"), Point("P"), Point("Q"), Point("R")
al.model.declare_points(O_, P, Q, R)
# al> %-----
# al> %      Mathematical declarations:  variables, constants
# al> Variables   QA, QB, QC      % Configuration variables
QA, QB, QC = dynamicsymbols("QA QB QC", real=True)
al.declare_variables(QA, QB, QC, line=9)
# al> Constants   LA, LB, LC, LN  % Lengths
LA, LB, LC, LN = symbols("LA LB LC LN", real=True)
al.declare_constants(LA, LB, LC, LN, line=10)
# al> %-----
# al> %      Geometry relating unit vectors
A.orient_axis(N, N.z, QA)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=13)
B.orient_axis(N, N.z, QB)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=14)
C.orient_axis(N, N.z, QC)  # al> Simprot(N, C, 3, QC)
al.model.given_orientation(C, N, line=15)
# al> %-----
# al> %      Position vectors
P.set_pos(O_, LA * A.x)  # al> P_O_P> = LA*A1>
al.model.given_pos(P, O_, line=18)
Q.set_pos(P, LB * B.x)  # al> P_P_Q> = LB*B1>
al.model.given_pos(Q, P, line=19)
Q.set_pos(R, LC * C.x)  # al> P_R_Q> = LC*C1>
al.model.given_pos(Q, R, line=20)
R.set_pos(O_, LN * N.y)  # al> P_O_R> = LN*N2>
al.model.given_pos(R, O_, line=21)
# al> %-----
# al> %      Configuration constraints
LOOP_vec = al.assign_vector(  # al> LOOP> = P_O_P> + P_P_Q> + P_Q_R> + P_R_O>
    LOOP=P.pos_from(O_) + Q.pos_from(P) + R.pos_from(Q) + O_.pos_from(R), line=24
)
# al> CONFIG[1] = Dot(LOOP>,N1>)
CONFIG = al.assign("CONFIG[1]", al.model.dot(LOOP_vec, N.x), line=25)
# al> CONFIG[2] = Dot(LOOP>,N2>)
CONFIG = al.assign("CONFIG[2]", al.model.dot(LOOP_vec, N.y), line=26)
# al> %-----
# al> %      Input constants, variables, etc. for Fortran code
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg, meter, sec
al.numerics.input(  # al> Input LA=1 m, LB=2 m, LC=2 m, LN=1 m, QA=30 deg
    {"LA": (1, "m"), "LB": (2, "m"), "LC": (2, "m"), "LN": (1, "m"), "QA": (30, "deg")},
    line=30,
)
# al> Input QB=60 deg, QC=20 deg      % Guess
al.numerics.input({"QB": (60, "deg"), "QC": (20, "deg")}, line=31)
# al> Input absErr=1.0E-07, relErr=1.0E-07 % Error tolerances
al.numerics.input({"ABSERR": 1.0e-07, "RELERR": 1.0e-07}, line=32)
# al> %-----
# al> %      Fortran code generation for numerical solution
# al> CODE Nonlinear(CONFIG,QB,QC) tutor3.for
al.numerics.code("NONLINEAR", eqs=CONFIG, unknowns=[QB, QC], file="tutor3.for", line=35)
# al> %-----
# al> %      Comment:  Nonlinear equations may have more than one solution.
# al> %               The solution depends on a guess.  If a guess does not
# al> %               provide a satisfactory answer, try another guess.
# al> %-----
# al> %      Record Autolev responses
al.save("tutor3.all", line=42)  # al> Save tutor3.all

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


@al.numerics.document_run  # its Inputs become keyword parameters
def run(values=None, /, **overrides):
    """Perform the CODE job; keyword arguments override Inputs (in their
    units): ``run(QA=30)``, ``result["QA"]``; ``job=`` picks a job."""
    return al.numerics.run(values, **overrides)


def ode_function(values=None, /, **overrides):
    """``(f, y0, names)`` for ``scipy.integrate.solve_ivp(f, (t0, t1), y0)``."""
    return al.numerics.ode_function(values, **overrides)


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
    """``python tutor3.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
