% File: rolling_disc.al
% A thin disc rolling without slip on level ground (al2py's own test
% model): heading Q3, lean Q4, spin Q5; the contact point's velocity is
% zero, so the ground-plane speeds U1, U2 are dependent.
Newtonian N
Frames A, B
Bodies D
Points CP
Variables Q{5}'
Variables U{5}'
Constants R, G, M
Mass D = M
Inertia D, M*R^2/4, M*R^2/2, M*R^2/4
Simprot(N, A, 3, Q3)
Simprot(A, B, 1, Q4)
Simprot(B, D, 2, Q5)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
W_A_N> = U3*N3>
W_B_A> = U4*A1>
W_D_B> = U5*B2>
P_N_DO> = Q1*N1> + Q2*N2> + R*B3>
V_DO_N> = Dt(P_N_DO>, N)
P_DO_CP> = -R*B3>
V2pts(N, D, DO, CP)
DEPENDENT[1] = Dot(V_CP_N>, N1>)
DEPENDENT[2] = Dot(V_CP_N>, N2>)
Constrain(DEPENDENT[U1, U2])
Gravity(-G*N3>)
Zero = Fr() + FrStar()
Kane()
Input R=0.3, G=9.81, M=2
Input Q1=0, Q2=0, Q3=0, Q4=0.2, Q5=0, U3=0.5, U4=0, U5=6
Input tFinal=1, integStp=0.05
Output T, Q3, Q4, U3, U4, U5
Code Dynamics() rolling_disc.c
