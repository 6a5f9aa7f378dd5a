% File: twin_disc.al
% Two thin discs rolling without slip on level ground (al2py's own test
% model for large linear solves): heading Q3/Q8, lean Q4/Q9, spin
% Q5/Q10.  The discs turn alike (equal angular velocities), their centres
% keep their distance and their midpoint moves along N1>: nine velocity
% constraints, so nine of the ten speeds depend on the spin rate U5.
Newtonian N
Frames EA, FA, EB, FB
Bodies DA, DB
Points CA, CB
Variables Q{10}'
Variables U{10}'
Constants R, G, M
Mass DA = M, DB = M
Inertia DA, M*R^2/4, M*R^2/2, M*R^2/4
Inertia DB, M*R^2/4, M*R^2/2, M*R^2/4
Simprot(N, EA, 3, Q3)
Simprot(EA, FA, 1, Q4)
Simprot(FA, DA, 2, Q5)
Simprot(N, EB, 3, Q8)
Simprot(EB, FB, 1, Q9)
Simprot(FB, DB, 2, Q10)
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
Q6' = U6
Q7' = U7
Q8' = U8
Q9' = U9
Q10' = U10
W_EA_N> = U3*N3>
W_FA_EA> = U4*EA1>
W_DA_FA> = U5*FA2>
W_EB_N> = U8*N3>
W_FB_EB> = U9*EB1>
W_DB_FB> = U10*FB2>
P_N_DAO> = Q1*N1> + Q2*N2> + R*FA3>
P_N_DBO> = Q6*N1> + Q7*N2> + R*FB3>
V_DAO_N> = Dt(P_N_DAO>, N)
V_DBO_N> = Dt(P_N_DBO>, N)
P_DAO_CA> = -R*FA3>
P_DBO_CB> = -R*FB3>
V2pts(N, DA, DAO, CA)
V2pts(N, DB, DBO, CB)
DEPENDENT[1] = Dot(V_CA_N>, N1>)
DEPENDENT[2] = Dot(V_CA_N>, N2>)
DEPENDENT[3] = Dot(V_CB_N>, N1>)
DEPENDENT[4] = Dot(V_CB_N>, N2>)
DEPENDENT[5] = Dot(W_DB_N> - W_DA_N>, N1>)
DEPENDENT[6] = Dot(W_DB_N> - W_DA_N>, N2>)
DEPENDENT[7] = Dot(W_DB_N> - W_DA_N>, N3>)
DEPENDENT[8] = Dot(V_DBO_N> - V_DAO_N>, P_N_DBO> - P_N_DAO>)
DEPENDENT[9] = Dot(V_DAO_N> + V_DBO_N>, N2>)
Constrain(DEPENDENT[U1, U2, U3, U4, U6, U7, U8, U9, U10])
Gravity(-G*N3>)
Zero = Fr() + FrStar()
Kane()
