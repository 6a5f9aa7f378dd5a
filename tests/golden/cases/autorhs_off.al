AUTORHS OFF
Constants B
A = 7
C = A + B
D = C*SIN(C)
