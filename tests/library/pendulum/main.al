% File: main.al
% Problem: energy of a double pendulum with particles at the elbow P and tip Q
%-----
RUN frames.al
Constants G, MP, MQ
%-----
% Energies from the ENERGY macro (energy.a beside this file)
ENERGY(MP, P)
ENERGY(MQ, Q)
KE = KE_P + KE_Q
PE = PE_P + PE_Q
%-----
% Where the tip is, symbolically and for one configuration
X = Dot(P_O_Q>, N1>)
Y = Dot(P_O_Q>, N2>)
Reach = Evaluate(X^2 + Y^2, QB=0)
Degrees ON
Tip = Evaluate([X; Y], LA=1, LB=2, QA=30, QB=60)
