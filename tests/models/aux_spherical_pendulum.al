%      A spherical pendulum: a rigid rod A hanging from a base point P1.
%      P1 is held at rest; its speeds U1, U2, U3 are auxiliary: they bring
%      the force RX, RY, RZ that P1 exerts on A into evidence.  Constrain
%      comes before the velocities, which are formed by differentiation.
%      (Our own model for issue 23, build point 4.)
Newtonian  N
Frames     B
Bodies     A
Points     P1
Variables  Q{5}', U{5}'
Variables  RX, RY, RZ
Constants  G, L, M, IA, IC
Mass       A = M
Inertia    A, IA, IA, IC
Simprot(N, B, 1, Q4)
Simprot(B, A, 2, Q5)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
W_B_N> = U4*B1>
W_A_B> = U5*A2>
W_A_N> = W_B_N> + W_A_B>
AUXILIARY[1] = U1
AUXILIARY[2] = U2
AUXILIARY[3] = U3
Constrain(AUXILIARY[U1, U2, U3])
P_NO_P1> = Q1*N1> + Q2*N2> + Q3*N3>
P_NO_AO> = P_NO_P1> - L*A3>
V_P1_N> = Dt(P_NO_P1>, N)
V_AO_N> = Dt(P_NO_AO>, N)
A_AO_N> = Dt(V_AO_N>, N)
ALF_A_N> = Dt(W_A_N>, N)
Gravity(-G*N3>)
Force_P1> += RX*N1> + RY*N2> + RZ*N3>
Zero = Fr() + FrStar()
Kane(RX, RY, RZ)
Input  G=9.81, L=1.2, M=2, IA=0.3, IC=0.05
Input  Q4=30 deg, Q5=20 deg, U4=0.5, U5=-0.3
Input  tFinal=2, integStp=0.02
Input  absErr=1.0E-10, relErr=1.0E-10
Output T, Q4, Q5, U4, U5, RX, RY, RZ
CODE Dynamics() aux_spherical_pendulum.m
