FACTORING ON
Constants A,B,C
X = A*B + A*C + A^2
Y = A/C + B/C
