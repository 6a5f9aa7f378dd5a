% File: whipple_benchmark.al
% Problem: the Whipple bicycle of the benchmark by Meijaard, Papadopoulos,
%   Ruina and Schwab, Proc. R. Soc. A 463 (2007): rear wheel R, rear frame
%   with rider B, front frame and fork H, front wheel F; knife-edge wheels
%   rolling without slip on level ground.  Written for al2py's tests from the
%   paper's description.  Axes as in the paper: 1 forward, 2 right, 3 down.
%-----
AutoZ ON                           % intermediates, as Autolev's Z's
Newtonian N
Frames    Y, L, E            % heading, lean (roll), steer axis
Bodies    R, B, H, F
Points    P, S               % rear contact point, a point on the steer axis
%-----
% Q1, Q2: rear contact point; Q3 yaw; Q4 roll; Q5 rear frame pitch;
% Q6 rear wheel angle; Q7 steer angle; Q8 front wheel angle.
Variables Q{8}'
Variables U{8}'
Constants W, C, LAM, G             % wheelbase, trail, steer axis tilt, gravity
Constants RR, RF                   % wheel radii
Constants XB, ZB, XH, ZH           % mass centres in the reference configuration
Constants IRXX, IRYY, IFXX, IFYY
Constants IBXX, IBYY, IBZZ, IBXZ
Constants IHXX, IHYY, IHZZ, IHXZ
%-----
Mass    R=MR, B=MB, H=MH, F=MF
Inertia R, IRXX, IRYY, IRXX
Inertia B, IBXX, IBYY, IBZZ, 0, 0, IBXZ
Inertia H, IHXX, IHYY, IHZZ, 0, 0, IHXZ
Inertia F, IFXX, IFYY, IFXX
%-----
Simprot(N, Y, 3, Q3)
Simprot(Y, L, 1, Q4)
Simprot(L, B, 2, Q5)
Simprot(B, R, 2, Q6)
Simprot(B, E, 2, LAM)
% H's axes are parallel to B's when the steer angle is zero.
Dircos(E, H, BODY321, Q7, -LAM, 0)
Simprot(H, F, 2, Q8)
%-----
Q1' = U1
Q2' = U2
Q3' = U3
Q4' = U4
Q5' = U5
Q6' = U6
Q7' = U7
Q8' = U8
%-----
W_Y_N> = U3*N3>
W_L_N> = W_Y_N> + U4*Y1>
W_B_N> = W_L_N> + U5*L2>
W_R_N> = W_B_N> + U6*B2>
W_E_N> = W_B_N>
W_H_N> = W_B_N> + U7*E3>
W_F_N> = W_H_N> + U8*H2>
%-----
P_P_Ro> = -RR*L3>
P_Ro_Bo> = XB*B1> + (ZB + RR)*B3>
% The steer axis meets the ground at distance W + C ahead of P.
P_Ro_S> = (W + C)*B1> + RR*B3>
P_S_Ho> = (XH - W - C)*H1> + ZH*H3>
P_S_Fo> = -C*H1> - RF*H3>
DOWN> = Cross(H2>, Cross(N3>, H2>))
P_Fo_Q> = RF*UnitVec(DOWN>)
%-----
V_P_N> = U1*N1> + U2*N2>
V2pts(N, L, P, Ro)
V2pts(N, B, Ro, Bo)
V2pts(N, B, Ro, S)
V2pts(N, H, S, Ho)
V2pts(N, H, S, Fo)
%-----
% Rolling without slip: the wheels' material points at the contacts are at rest.
SLIPR> = V_Ro_N> + Cross(W_R_N>, -P_P_Ro>)
SLIPF> = V_Fo_N> + Cross(W_F_N>, P_Fo_Q>)
DEPENDENT[1] = Dot(SLIPR>, N1>)
DEPENDENT[2] = Dot(SLIPR>, N2>)
DEPENDENT[3] = Dot(SLIPF>, N1>)
DEPENDENT[4] = Dot(SLIPF>, N2>)
DEPENDENT[5] = Dot(SLIPF>, N3>)
Constrain(DEPENDENT[U1, U2, U3, U5, U8])
%-----
Gravity(G*N3>)
Zero = Fr() + FrStar()
Kane()
% Linearized equations about the upright reference configuration: the
% accelerations of the independent speeds and their Jacobian by the lean
% and steer angles and rates (the forward speed is U6 = -v/RR).
Solve(Zero, U4', U6', U7')
XD = [U4'; U7']
XS = [Q4; Q7; U4; U7]
AL = D(XD, XS)
%-----
% Benchmark parameters, Table 1 of the paper.
Input W=1.02, C=0.08, LAM=0.314159265358979, G=9.81
Input RR=0.3, RF=0.35, MR=2, MB=85, MH=4, MF=3
Input XB=0.3, ZB=-0.9, XH=0.9, ZH=-0.7
Input IRXX=0.0603, IRYY=0.12, IFXX=0.1405, IFYY=0.28
Input IBXX=9.2, IBYY=11, IBZZ=2.8, IBXZ=2.4
Input IHXX=0.05892, IHYY=0.06, IHZZ=0.00708, IHXZ=-0.00756
