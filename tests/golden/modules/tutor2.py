"""Autolev script tutor2.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor2`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor2.py``
prints the transcript Autolev would print and runs the CODE job (``--help``
lists its options); ``run()`` runs it from Python.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor2.py [-h] [options]

Print the Autolev transcript of tutor2.al and perform its numerical CODE job.

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

Jobs (--job STEM runs one; default: all, in script order):
  tutor2: CODE Algebraic tutor2.c (line 56) -> tutor2.1, ...
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace, dynamicsymbols
    from al2py_runtime.functions import acos_deg
    from sympy import symbols
    from sympy.physics.mechanics import RigidBody, inertia
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame

al = Workspace("tutor2.al", __file__)

# al> % File: tutor2.al [Autolev: http://www.autolev.com]
# al> % Problem: Mass and inertia calculations
# al> %-----
# al> Degrees ON % Online calculations of PHI in degrees
al.settings.set("Degrees", "ON")
# al> %-----
# al> % Physical declarations: bodies, points
# al> Bodies A, B, C % Right, middle, top plate
A, B, C = ReferenceFrame("A"), ReferenceFrame("B"), ReferenceFrame("C")
Ao, Bo, Co = Point("AO"), Point("BO"), Point("CO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
C_body = RigidBody("C", Co, C, 0, (Dyadic(0), Co))
al.model.declare_bodies(A_body, B_body, C_body)
O_, P = Point("O"), Point("P")  # al> Points O, P % Points on L
al.model.declare_points(O_, P)
CM = Point("CM")  # al> Points CM % Center of mass of system
al.model.declare_points(CM)
# al> %-----
# al> % Mathematical declarations: variables, constants
# al> Variables PHI % Angle between plates A and B
PHI = dynamicsymbols("PHI", real=True)
al.declare_variables(PHI, line=12)
W = symbols("W", real=True)  # al> Constants W=1 % Width of plate
al.declare_constants(W, line=13)
al.assign("W", 1, line=13)
# al> %-----
# al> % Mass and inertia
M = symbols("M", nonnegative=True)  # al> Mass A=M=12, B=M, C=M
al.declare_constants(M, line=16)
al.assign("M", 12, line=16)
A_body.mass = M
B_body.mass = M
C_body.mass = M
al.model.given_masses(A_body, B_body, C_body, line=16)
# al> Inertia A, M*W^2/12, M*W^2/12, M*W^2/6
A_body.central_inertia = inertia(A, M * W**2 / 12, M * W**2 / 12, M * W**2 / 6)
al.model.given_inertia(A_body, line=17)
# al> Inertia B, M*W^2/12, M*W^2/12, M*W^2/6
B_body.central_inertia = inertia(B, M * W**2 / 12, M * W**2 / 12, M * W**2 / 6)
al.model.given_inertia(B_body, line=18)
# al> Inertia C, M*W^2/12, M*W^2/6, M*W^2/12
C_body.central_inertia = inertia(C, M * W**2 / 12, M * W**2 / 6, M * W**2 / 12)
al.model.given_inertia(C_body, line=19)
# al> %-----
# al> % Geometry relating unit vectors
B.orient_axis(A, -A.y, PHI)  # al> Simprot(A, B, -2, PHI)
al.model.given_orientation(B, A, line=22)
# al> A_C = Diagmat(3,1) % 3x3 identity matrix
al.model.set_dcm(A, C, al.diagmat(3, 1), line=23)
# al> %-----
# al> % Position vectors (Ao, Bo, Co are mass centers)
Ao.set_pos(O_, -0.5 * W * A.x + 0.5 * W * A.y)  # al> P_O_Ao> = -0.5*W*A1> + 0.5*W*A2>
al.model.given_pos(Ao, O_, line=26)
# al> P_O_Bo> = -W*A1> + 0.5*W*A2> + 0.5*W*B1>
Bo.set_pos(O_, -W * A.x + 0.5 * W * A.y + 0.5 * W * B.x)
al.model.given_pos(Bo, O_, line=27)
# al> P_O_Co> = W*A2> - 0.5*W*C1> - 0.5*W*C3>
Co.set_pos(O_, W * A.y - 0.5 * W * C.x - 0.5 * W * C.z)
al.model.given_pos(Co, O_, line=28)
P.set_pos(O_, W * A.y - W * C.z)  # al> P_O_P> = W*A2> - W*C3>
al.model.given_pos(P, O_, line=29)
# al> %-----
# al> % Center of mass of system
CM.set_pos(O_, al.model.cm(O_))  # al> P_O_CM> = CM(O)
al.model.given_pos(CM, O_, line=32)
# al> Distance = Mag( P_O_CM> )
Distance = al.assign("DISTANCE", al.model.mag(CM.pos_from(O_)), line=33)
# al> %-----
# al> % Inertia dyadics of system about CM and O
# al> I_SYSTEM_CM>> = Inertia(CM, A, B, C) % Central inertia dyadic
I_SYSTEM_CM_dyad = al.assign_dyadic(I_SYSTEM_CM=al.model.inertia(CM, A, B, C), line=36)
# al> I_SYSTEM_CM = Represent( I_SYSTEM_CM>>, A) % Central inertia matrix
I_SYSTEM_CM = al.assign("I_SYSTEM_CM", al.model.represent(I_SYSTEM_CM_dyad, A), line=37)
# al> Eig( Evaluate(I_SYSTEM_CM, PHI=90), LAMBDA, EIGENVECS )
LAMBDA, EIGENVECS = al.assign_all(
    ("LAMBDA", "EIGENVECS"),
    al.eig_vectors(al.evaluate(I_SYSTEM_CM, {PHI: 90})),
    line=38,
)
# al> EVEC = Rows(EIGENVECS, 1) % Extract eigenvector
EVEC = al.assign("EVEC", al.rows(EIGENVECS, 1), line=39)
# al> EVEC> = Represent( EVEC, A ) % Corresponding unit vector
EVEC_vec = al.assign_vector(EVEC=al.model.represent(EVEC, A), line=40)
# al> ANGLE = acos( DOT(EVEC>,A2>) ) % Angle between EVEC>, A2>
ANGLE = al.assign("ANGLE", acos_deg(al.model.dot(EVEC_vec, A.y)), line=41)
# al> %-----
# al> % Moment of inertia of system about line joining O and P
# al> I_SYSTEM_O>> = Inertia(O) % Inertia dyadic about point O
I_SYSTEM_O_dyad = al.assign_dyadic(I_SYSTEM_O=al.model.inertia(O_), line=44)
# al> Express(I_SYSTEM_O>>, A) % Express in terms of A1>, A2>, A3>
I_SYSTEM_O_dyad = al.update_dyadic(
    I_SYSTEM_O=al.model.express(I_SYSTEM_O_dyad, A), line=45
)
# al> L> = Unitvec( P_O_P> ) % Unit vector parallel to line L
L_vec = al.assign_vector(L=al.model.unitvec(P.pos_from(O_)), line=46)
# al> IL = Dot(L>, DOT(I_SYSTEM_O>>, L>)) % Moment of inertia about L
IL = al.assign("IL", al.model.dot(L_vec, al.model.dot(I_SYSTEM_O_dyad, L_vec)), line=47)
# al> MTOTAL = Mass() % Mass of system
MTOTAL = al.assign("MTOTAL", al.model.mass_of(), line=48)
# al> GYRATION = (IL / MTOTAL)^0.5 % Radius of gyration about L
GYRATION = al.assign("GYRATION", (IL / MTOTAL) ** 0.5, line=49)
# al> %-----
# al> % Output and units for use in program created by CODE command
al.numerics.unit_system("kg", "meter", "sec")  # al> UnitSystem kg, meter, sec
al.numerics.output(  # al> Output PHI degrees, DISTANCE meters, GYRATION meters
    [
        ("PHI", PHI, "degrees"),
        ("DISTANCE", Distance, "meters"),
        ("GYRATION", GYRATION, "meters"),
    ],
    line=53,
)
# al> %-----
# al> % C code generation for numerical solution
# al> CODE Algebraic() [PHI deg=0,360,1] tutor2.c
al.numerics.code("ALGEBRAIC", sweep=(PHI, "deg", 0, 360, 1), file="tutor2.c", line=56)
# al> %-----
# al> % Record Autolev responses
al.save("tutor2.all", line=59)  # al> Save tutor2.all

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
    """``python tutor2.py``: print the transcript, then run the CODE job."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
