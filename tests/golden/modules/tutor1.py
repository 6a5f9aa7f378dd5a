"""Autolev script tutor1.al converted by al2py 0.2.0: edit the .al file instead.

``import tutor1`` runs the symbolic part silently; ``AUTOLEV`` maps Autolev
names (``"ZERO[1]"``, ``"X'"``) to their current values.  ``python tutor1.py``
prints the transcript Autolev would print.
"""

import sys

if __name__ == "__main__" and {"-h", "--help"} & set(sys.argv[1:]):
    # answered here, before sympy loads and the model is derived
    sys.stdout.write("""\
usage: python tutor1.py [-h] [options]

Print the Autolev transcript of tutor1.al and perform its numerical CODE job.

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
    from al2py_runtime.functions import cos
    from sympy import Matrix, pi, symbols

al = Workspace("tutor1.al", __file__)

# al> % File: tutorial [Autolev: http://www.autolev.com]
# al> % Problem: Examples of mathematical functions
# al> %-----
# al> % Mathematical declarations: variables, constants
X, Y = dynamicsymbols("X Y", real=True)  # al> Variables X', Y'
al.declare_variables(X, Y, primes=1, line=5)
A, B, C, D = symbols("A B C D", real=True)  # al> Constants A,B,C,D
al.declare_constants(A, B, C, D, line=6)
# al> %-----
# al> % Create an expression and then rearrange (simplify) it
# al> E = (X+2*Y)^2 + 3*(7+X)*(X+Y) % Create an expression
E = al.assign("E", (X + 2 * Y) ** 2 + 3 * (7 + X) * (X + Y), line=9)
# al> Expand( E, 1:2 ) % Clear parentheses
E = al.update("E", al.expand(E, (1, 2)), line=10)
E = al.update("E", al.factor(E, X), line=11)  # al> Factor( E, X ) % Factor on X
# al> %-----
# al> % Mathematical commands
# al> Dy = D( E, Y ) % Partial derivative wrt. Y
Dy = al.assign("DY", al.d(E, Y), line=14)
Dt = al.assign("DT", al.dt(E), line=15)  # al> Dt = Dt( E ) % Total derivative wrt. t
# al> TY = Taylor( X*COS(Y), 0:7, X=0,Y=0) % Multi-variable Taylor series
TY = al.assign("TY", al.taylor(X * cos(Y), (0, 7), [(X, 0), (Y, 0)]), line=16)
# al> F = Evaluate(TY, X=1, Y=0.5) % Symbolic/numerical evaluation
F = al.assign("F", al.evaluate(TY, {X: 1, Y: 0.5}), line=17)
# al> POLY = Polynomial( [A,B,C], X ) % Creates A*X^2 +B*X +C
POLY = al.assign("POLY", al.polynomial(Matrix([[A, B, C]]), X), line=18)
# al> ROOT1 = Roots( [1; 2; 3; 4] ) % Roots of X^3+2*X^2+3*X+4 = 0
ROOT1 = al.assign("ROOT1", al.roots(Matrix([1, 2, 3, 4])), line=19)
# al> ROOT2 = Roots( POLY, X, 2 ) % Some symbolic roots
ROOT2 = al.assign("ROOT2", al.roots(POLY, X, 2), line=20)
# al> %-----
# al> % Creating row or column matrices
# al> RowMatrix = [1, 2, 3, 4] % Create a 1x4 matrix
RowMatrix = al.assign("ROWMATRIX", Matrix([[1, 2, 3, 4]]), line=23)
# al> ColMatrix = [1; 2; 3; 4] % Create a 4x1 matrix
ColMatrix = al.assign("COLMATRIX", Matrix([1, 2, 3, 4]), line=24)
# al> Zero[1] = A*X + B*Y - 1 % Assign elements of column matrix
Zero = al.assign("ZERO[1]", A * X + B * Y - 1, line=25)
Zero = al.assign("ZERO[2]", C * X + D * Y - pi, line=26)  # al> Zero[2] = C*X + D*Y - Pi
# al> %-----
# al> % Solve a set of linear equations
al.solve(Zero, [X, Y], line=29)  # al> Solve( Zero, X, Y )
# al> %-----
# al> % Creating rectangular matrices
# al> M0 = [A, B; C, 0] % Create a 2x2 matrix
M0 = al.assign("M0", Matrix([[A, B], [C, 0]]), line=32)
# al> M0[2,2] := D % Assign element of rectangular matrix
M0 = al.assign("M0[2,2]", D, line=33)
# al> M1 = [M0, [1,2;3,4] ] % Elements of matrices can be matrices
M1 = al.assign("M1", al.block([[M0, Matrix([[1, 2], [3, 4]])]]), line=34)
# al> %-----
# al> % Matrix commands
M2 = al.assign("M2", M0 + M0, line=37)  # al> M2 = M0 + M0 % Matrix addition
M3 = al.assign("M3", M0 * M0, line=38)  # al> M3 = M0 * M0 % Matrix multiplication
# al> M4 = Transpose(M0) % Matrix transposition
M4 = al.assign("M4", al.transpose(M0), line=39)
M5 = al.assign("M5", al.inv(M0), line=40)  # al> M5 = Inv(M0) % Matrix inversion
# al> M6 = Diagmat(3,1) % Makes 3x3 matrix with 1 along diagonal
M6 = al.assign("M6", al.diagmat(3, 1), line=41)
# al> M7 = Cols( M0, 1 ) % Returns column 1 of M0
M7 = al.assign("M7", al.cols(M0, 1), line=42)
# al> M8 = Rows( M0, 2, 1:2) % Returns rows 2 and rows 1 through 2 of M0
M8 = al.assign("M8", al.rows(M0, 2, (1, 2)), line=43)
# al> N1 = Rows( M0 ) % Returns the number of rows in M0
N1 = al.assign("N1", al.rows(M0), line=44)
# al> N2 = Det( M0 ) % Determinant of a matrix
N2 = al.assign("N2", al.det(M0), line=45)
# al> M9 = Evaluate( M0, A=1, B=2, C=3, D=4 )
M9 = al.assign("M9", al.evaluate(M0, {A: 1, B: 2, C: 3, D: 4}), line=46)
# al> LAMBDA = Eig( M9 ) % Eigenvalues
LAMBDA = al.assign("LAMBDA", al.eig(M9), line=47)
# al> Eig( M9, EigValue, EigVec) % Eigenvalues/eigenvectors
EigValue, EigVec = al.assign_all(("EIGVALUE", "EIGVEC"), al.eig_vectors(M9), line=48)
# al> %-----
# al> % Record Autolev responses

AUTOLEV = al.names()  # the functions below call the runtime's, whose help tells more


def evaluate(name, values=None, /, **given):
    """The named quantity as a number: ``evaluate("ZERO", QA=30)``."""
    return al.numerics.evaluate_name(name, values, **given)


def sweep(name=None, values=None, /, **given):
    """A ``Sweep`` of the named quantity over a grid of values."""
    return al.numerics.sweep(name, values, origin=(__name__, __file__), **given)


def main(argv: list[str] | None = None) -> int:
    """``python tutor1.py``: print the transcript."""
    return al.main(__file__, argv)  # the transcript echoes the # al> lines


if __name__ == "__main__":
    raise SystemExit(main())
