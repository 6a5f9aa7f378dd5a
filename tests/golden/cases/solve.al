Variables X, Y
Zero[1] = -37 + 3*X + 4*Y
Zero[2] = 2 + 4*X - 2*Y
SOLVE( Zero, X,Y )
