POWER(3,A)
Constants A,B
POWER(A+B,ED)
