"""Autolev script constrain.al converted by al2py 0.2.0: edit the .al file
instead.

``import constrain`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python
constrain.py`` prints the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python constrain.py [-h] [options]

Print the Autolev transcript of constrain.al and perform its numerical CODE
job.

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
    from al2py_runtime import Workspace, dynamicsymbols
    from sympy import symbols
    from sympy.physics.mechanics import RigidBody
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame

al = Workspace("constrain.al", __file__)

# al> % Problem: Triple pendulum whose tip has a specified motion
# al> Newtonian      N                % Newtonian reference frame
N = ReferenceFrame("N")
al.model.declare_newtonian(N)
# al> Bodies         A, B, C          % Links of pendulum
A, B, C = ReferenceFrame("A"), ReferenceFrame("B"), ReferenceFrame("C")
Ao, Bo, Co = Point("AO"), Point("BO"), Point("CO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
C_body = RigidBody("C", Co, C, 0, (Dyadic(0), Co))
al.model.declare_bodies(A_body, B_body, C_body)
P = Point("P")  # al> Points         P                % Distal end of C
al.model.declare_points(P)
# al> Variables      U{3}            % Generalized speeds
U1, U2, U3 = dynamicsymbols("U1 U2 U3", real=True)
al.declare_variables(U1, U2, U3, line=5)
# al> Variables      Qa, Qb, Qc       % Angles for A, B, C
Qa, Qb, Qc = dynamicsymbols("QA QB QC", real=True)
al.declare_variables(Qa, Qb, Qc, line=6)
# al> Constants      LA, LB, LC       % Lengths of A, B, C
LA, LB, LC = symbols("LA LB LC", real=True)
al.declare_constants(LA, LB, LC, line=7)
# al> Specified      Vx, Vy           % Specified motion of P
Vx, Vy = dynamicsymbols("VX VY", real=True)
al.declare_specified(Vx, Vy, line=8)
A.orient_axis(N, N.z, Qa)  # al> Simprot(N, A, 3, QA)
al.model.given_orientation(A, N, line=9)
B.orient_axis(N, N.z, Qb)  # al> Simprot(N, B, 3, QB)
al.model.given_orientation(B, N, line=10)
C.orient_axis(N, N.z, Qc)  # al> Simprot(N, C, 3, QC)
al.model.given_orientation(C, N, line=11)
# al> V_P_N> = LA*U1*A2> + LB*U2*B2> + LC*U3*C2>
P.set_vel(N, LA * U1 * A.y + LB * U2 * B.y + LC * U3 * C.y)
al.model.given_vel(P, N, line=12)
# al> DEPENDENT[1] = DOT(V_P_N>,N1>) - Vx
DEPENDENT = al.assign("DEPENDENT[1]", al.model.dot(P.vel(N), N.x) - Vx, line=13)
# al> DEPENDENT[2] = DOT(V_P_N>,N2>) - Vy
DEPENDENT = al.assign("DEPENDENT[2]", al.model.dot(P.vel(N), N.y) - Vy, line=14)
al.model.constrain("DEPENDENT", [U2, U3], line=15)  # al> Constrain( DEPENDENT[U2,U3] )

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def main(argv: list[str] | None = None) -> int:
    """``python constrain.py``: print the transcript."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
