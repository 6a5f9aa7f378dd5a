"""Autolev script inertia.al converted by al2py 0.2.0: edit the .al file instead.

``import inertia`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python inertia.py``
prints the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python inertia.py [-h] [options]

Print the Autolev transcript of inertia.al and perform its numerical CODE job.

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

This script has no CODE statement: it only prints its transcript.
Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, RELERR.
""")
    raise SystemExit(0)
else:  # imported only here, so that the --help above answers at once
    from al2py_runtime import Workspace
    from sympy import symbols
    from sympy.physics.mechanics import RigidBody
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame, outer

al = Workspace("inertia.al", __file__)

P = Point("P")  # al> Points P
al.model.declare_points(P)
B = ReferenceFrame("B")  # al> Bodies B
Bo = Point("BO")
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
al.model.declare_bodies(B_body)
MB = symbols("MB", nonnegative=True)  # al> Mass B=MB
al.declare_constants(MB, line=3)
B_body.mass = MB
al.model.given_masses(B_body, line=3)
I_, J, L = symbols("I J L", real=True)  # al> Constants I,J,L
al.declare_constants(I_, J, L, line=4)
P.set_pos(Bo, L * B.x)  # al> P_Bo_P> = L*B1>
al.model.given_pos(P, Bo, line=5)
al.model.set_inertia_about(  # al> I_B_P>> = I*B1>*B1> + I*B2>*B2> + J*B3>*B3>
    B, P, outer(I_ * B.x, B.x) + outer(I_ * B.y, B.y) + outer(J * B.z, B.z), line=6
)
# al> I_B_BO>> = Inertia(Bo,B)
al.model.set_inertia_about(B, Bo, al.model.inertia(Bo, B), line=7)

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def main(argv: list[str] | None = None) -> int:
    """``python inertia.py``: print the transcript."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
