% File: frames.al
% Problem: kinematics of a two-link planar pendulum (links A and B)
%   O is the fixed pivot, P the elbow, Q the tip; N1> points down.
%-----
Newtonian N
Frames    A, B
Points    O, P, Q
Variables QA', QB'   % Absolute angle of A, relative angle of B
Constants LA, LB     % Link lengths
%-----
Simprot(N, A, 3, QA)
Simprot(A, B, 3, QB)
%-----
P_O_P> = LA*A1>
P_P_Q> = LB*B1>
P_O_Q> = P_O_P> + P_P_Q>
%-----
V_O_N> = 0>
V_P_N> = Dt(P_O_P>, N)
V_Q_N> = Dt(P_O_Q>, N)
