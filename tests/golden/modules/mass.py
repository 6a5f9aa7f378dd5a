"""Autolev script mass.al, converted to Python.

Converted from mass.al by al2py 0.1.0; edit the .al file and
convert again rather than editing this module.

``import mass`` runs the symbolic part silently; ``AUTOLEV`` maps
Autolev names (``"ZERO[1]"``, ``"X'"``) to their current values.
``python mass.py`` prints the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write(
        "usage: python mass.py [-h] [--set NAME=VALUE] [--job STEM] [--tfinal T"
        "FINAL]\n"
        "                      [--outdir OUTDIR] [--plot]\n"
        "                      [--backend {auto,c,llvm,lambdify}] [--zero-missi"
        "ng]\n"
        "                      [--emit-code DIR] [--no-run] [--max-seconds S]\n"
        "                      [--max-evals N]\n"
        "\n"
        "Print the Autolev transcript of mass.al and perform its numerical CODE"
        " job.\n"
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
        "This script has no CODE statement: it only prints its transcript.\n"
        "Integration parameters: TINITIAL, TFINAL, INTEGSTP, PRINTINT, ABSERR, "
        "RELERR.\n"
    )
    raise SystemExit(0)

from al2py_runtime import Workspace  # noqa: E402

al = Workspace("mass.al")

# al> Bodies      A,B
A, B = al.bodies("A", "B")
A_body, B_body = al.rigid_body(A), al.rigid_body(B)
# al> Particles   C
C = al.particles("C")
C_particle = al.particle(C)
# al> Mass        A=12.5, B=MB, C=MC=10
MB, MC = al.constants("MB+", "MC+", line=3)
al.set_mass(A, 12.5)
al.set_mass(B, MB)
al.assign("MC", 10, line=3)
al.set_mass(C, MC)
# al> Mass_A = Mass(A)           % Returns the mass of A
Mass_A = al.assign("MASS_A", al.mass_of(A), line=4)
# al> Mass_AB = Mass(A,B)       % Returns Mass(A) + Mass(B)
Mass_AB = al.assign("MASS_AB", al.mass_of(A, B), line=5)
# al> TOTAL = Mass()           % Returns Mass(A) + Mass(B) + Mass(C)
TOTAL = al.assign("TOTAL", al.mass_of(), line=6)

AUTOLEV = al.names()

# The Autolev source, echoed in the transcript.
AL_SOURCE = (
    "Bodies      A,B",
    "Particles   C",
    "Mass        A=12.5, B=MB, C=MC=10",
    "Mass_A = Mass(A)           % Returns the mass of A",
    "Mass_AB = Mass(A,B)       % Returns Mass(A) + Mass(B)",
    "TOTAL = Mass()           % Returns Mass(A) + Mass(B) + Mass(C)",
)


def evaluate(name, values=None, /, **given):
    """The named Autolev quantity as a number (a numpy array for a matrix).

    Input values (in their own units), the values given here and every named
    intermediate are substituted: ``evaluate("ZERO", QA=30)``.
    """
    return al.numerics.evaluate_name(name, values, **given)


def main(argv: list[str] | None = None) -> int:
    """``python mass.py``: print the transcript."""
    return al.main(AL_SOURCE, argv)


if __name__ == "__main__":
    raise SystemExit(main())
