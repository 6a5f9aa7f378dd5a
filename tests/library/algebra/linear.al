% File: linear.al
% Problem: a 2x2 linear system, its matrix, and a hypotenuse macro
Variables X, Y
Constants A, B
Zero[1] = 3*X + 4*Y - A
Zero[2] = 4*X - 2*Y + B
Solve(Zero, X, Y)
M = [3, 4; 4, -2]
DetM = Det(M)
MI = Inv(M)
H = HYP(3, 4)
HAB = HYP(A, B)
