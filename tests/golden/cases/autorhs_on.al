AUTORHS ON
Constants B
A = 7
C = A + B
D = C*SIN(C)
