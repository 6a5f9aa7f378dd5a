Bodies      A,B
Particles   C
Mass        A=12.5, B=MB, C=MC=10
Mass_A = Mass(A)           % Returns the mass of A
Mass_AB = Mass(A,B)       % Returns Mass(A) + Mass(B)
TOTAL = Mass()           % Returns Mass(A) + Mass(B) + Mass(C)
