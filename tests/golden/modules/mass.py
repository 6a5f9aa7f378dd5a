"""Autolev script mass.al converted by al2py 0.2.0: edit the .al file instead.

``import mass`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev names
(``"ZERO[1]"``, ``"X'"``) to their current values.  ``python mass.py`` prints
the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python mass.py [-h] [options]

Print the Autolev transcript of mass.al and perform its numerical CODE job.

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
    from sympy.physics.mechanics import Particle, RigidBody
    from sympy.physics.vector import Dyadic, Point, ReferenceFrame

al = Workspace("mass.al", __file__)

A, B = ReferenceFrame("A"), ReferenceFrame("B")  # al> Bodies      A,B
Ao, Bo = Point("AO"), Point("BO")
A_body = RigidBody("A", Ao, A, 0, (Dyadic(0), Ao))
B_body = RigidBody("B", Bo, B, 0, (Dyadic(0), Bo))
al.model.declare_bodies(A_body, B_body)
C = Point("C")  # al> Particles   C
C_particle = Particle("C", C, 0)
al.model.declare_particles(C_particle)
MB, MC = symbols("MB MC", nonnegative=True)  # al> Mass        A=12.5, B=MB, C=MC=10
al.declare_constants(MB, MC, line=3)
A_body.mass = 12.5
B_body.mass = MB
al.assign("MC", 10, line=3)
C_particle.mass = MC
al.model.given_masses(A_body, B_body, C_particle, line=3)
# al> Mass_A = Mass(A)           % Returns the mass of A
Mass_A = al.assign("MASS_A", al.model.mass_of(A), line=4)
# al> Mass_AB = Mass(A,B)       % Returns Mass(A) + Mass(B)
Mass_AB = al.assign("MASS_AB", al.model.mass_of(A, B), line=5)
# al> TOTAL = Mass()           % Returns Mass(A) + Mass(B) + Mass(C)
TOTAL = al.assign("TOTAL", al.model.mass_of(), line=6)

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def main(argv: list[str] | None = None) -> int:
    """``python mass.py``: print the transcript."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
