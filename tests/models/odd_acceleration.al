% A particle whose stated acceleration is not the derivative of its
% velocity: FrStar() must use the script's A_P_N>, as Autolev did.
Newtonian N
Particles P
Variables Q', U1'
Constants M, K
Mass P=M
Q' = U1
P_No_P> = Q*N1>
V_P_N> = U1*N1>
A_P_N> = 2*U1'*N1>
Force_P> = -K*Q*N1>
Zero = Fr() + FrStar()
Kane()
