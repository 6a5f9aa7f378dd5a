Points P
Bodies B
Mass B=MB
Constants I,J,L
P_Bo_P> = L*B1>
I_B_P>> = I*B1>*B1> + I*B2>*B2> + J*B3>*B3>
I_B_BO>> = Inertia(Bo,B)
