%      A planar pendulum: a rigid rod A pinned at a base point P1 that is
%      held at rest.  U1, U2 move P1 (auxiliary: they bring the pin force
%      RX, RY into evidence); U3 is A's angular speed and U4 the speed of
%      A's mass center along A2> (dependent: the rod is rigid, U4 = L*U3).
%      Constrain comes before the velocity of P1, formed by differentiation.
%      (Our own model for issue 23, build point 4.)
Newtonian  N
Bodies     A
Points     P1
Variables  Q{3}', U{4}'
Variables  RX, RY
Constants  G, L, M, IZ
Mass       A = M
Inertia    A, 0, 0, IZ
Simprot(N, A, 3, Q3)
Q1' = U1
Q2' = U2
Q3' = U3
W_A_N> = U3*A3>
P_P1_AO> = L*A1>
AUXILIARY[1] = U1
AUXILIARY[2] = U2
DEPENDENT[1] = U4 - L*U3
Constrain(AUXILIARY[U1, U2], DEPENDENT[U4])
P_NO_P1> = Q1*N1> + Q2*N2>
V_P1_N> = Dt(P_NO_P1>, N)
V_AO_N> = V_P1_N> + U4*A2>
A_AO_N> = Dt(V_AO_N>, N)
ALF_A_N> = Dt(W_A_N>, N)
Gravity(-G*N2>)
Force_P1> = RX*N1> + RY*N2>
Zero = Fr() + FrStar()
Kane(RX, RY)
Input  G=9.81, L=0.8, M=1.5, IZ=0.1
Input  Q3=-60 deg, U3=1.0
Input  tFinal=3, integStp=0.02
Input  absErr=1.0E-10, relErr=1.0E-10
Output T, Q3, U3, RX, RY
CODE Dynamics() aux_planar_pendulum.m
