% File: whipple_linear.al
% Problem: the Whipple bicycle of the benchmark by Meijaard, Papadopoulos,
%   Ruina and Schwab, Proc. R. Soc. A 463 (2007), driven by a roll, a steer
%   and a rear wheel torque, with its linearized state matrices formed in
%   the script by D(), as research scripts form theirs.  The geometry is
%   that of whipple_benchmark.al.  Written for al2py's tests from the
%   paper's description.  Axes as in the paper: 1 forward, 2 right, 3 down.
%-----
AutoZ ON
Newtonian N
Frames    Y, L, E            % heading, lean (roll), steer axis
Bodies    R, B, H, F         % rear wheel, rear frame, fork, front wheel
Points    P, S               % rear contact point, a point on the steer axis
%-----
% Q1, Q2: rear contact point; Q3 yaw; Q4 roll; Q5 rear frame pitch;
% Q6 rear wheel angle; Q7 steer angle; Q8 front wheel angle.
Variables Q{8}'
MotionVariables' U{8}'
Constants W, C, LAM, G             % wheelbase, trail, steer axis tilt, gravity
Constants RR, RF                   % wheel radii
Constants XB, ZB, XH, ZH           % mass centres in the reference configuration
Constants IRXX, IRYY, IFXX, IFYY
Constants IBXX, IBYY, IBZZ, IBXZ
Constants IHXX, IHYY, IHZZ, IHXZ
Specified TPHI, TDELTA, TTHETAR    % roll, steer and rear wheel torques
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
Torque(Y/L, TPHI*Y1>)              % the rider leans the frame
Torque(B/H, TDELTA*E3>)            % the rider steers
Torque(B/R, TTHETAR*B2>)           % pedalling
Zero = Fr() + FrStar()
Solve(Zero, U4', U6', U7')
%-----
% The linearized equations: the state is every coordinate and the
% independent speeds; the inputs are the roll and steer torques.  Upright
% at forward speed v, the state is zero but for U6 = -v/RR.
XDOT = [Q1'; Q2'; Q3'; Q4'; Q5'; Q6'; Q7'; Q8'; U4'; U6'; U7']
X = [Q1; Q2; Q3; Q4; Q5; Q6; Q7; Q8; U4; U6; U7]
AMAT = D(XDOT, X)
BMAT = D(XDOT, [TPHI; TDELTA])
%-----
UnitSystem kg, meter, sec
% Benchmark parameters, Table 1 of the paper.
Input W=1.02 m, C=0.08 m, LAM=0.314159265358979 rad, G=9.81 m/sec^2
Input RR=0.3 m, RF=0.35 m, MR=2 kg, MB=85 kg, MH=4 kg, MF=3 kg
Input XB=0.3 m, ZB=-0.9 m, XH=0.9 m, ZH=-0.7 m
Input IRXX=0.0603 kg*m^2, IRYY=0.12 kg*m^2, IFXX=0.1405 kg*m^2, IFYY=0.28 kg*m^2
Input IBXX=9.2 kg*m^2, IBYY=11 kg*m^2, IBZZ=2.8 kg*m^2, IBXZ=2.4 kg*m^2
Input IHXX=0.05892 kg*m^2, IHYY=0.06 kg*m^2, IHZZ=0.00708 kg*m^2
Input IHXZ=-0.00756 kg*m^2
% Upright at 5 m/s (the forward speed is -U6*RR).
Input Q1=0 m, Q2=0 m, Q3=0 rad, Q4=0 rad, Q5=0 rad, Q6=0 rad, Q7=0 rad, Q8=0 rad
Input U4=0 rad/sec, U6=-16.6666666666667 rad/sec, U7=0 rad/sec
Input tFinal=2, integStp=0.01
Output T, Q4 rad, Q7 rad, U4 rad/sec, U6 rad/sec, U7 rad/sec
CODE Dynamics() whipple_linear.c
