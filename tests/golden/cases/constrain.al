% Problem: Triple pendulum whose tip has a specified motion
Newtonian      N                % Newtonian reference frame
Bodies         A, B, C          % Links of pendulum
Points         P                % Distal end of C
Variables      U{3}            % Generalized speeds
Variables      Qa, Qb, Qc       % Angles for A, B, C
Constants      LA, LB, LC       % Lengths of A, B, C
Specified      Vx, Vy           % Specified motion of P
Simprot(N, A, 3, QA)
Simprot(N, B, 3, QB)
Simprot(N, C, 3, QC)
V_P_N> = LA*U1*A2> + LB*U2*B2> + LC*U3*C2>
DEPENDENT[1] = DOT(V_P_N>,N1>) - Vx
DEPENDENT[2] = DOT(V_P_N>,N2>) - Vy
Constrain( DEPENDENT[U2,U3] )
