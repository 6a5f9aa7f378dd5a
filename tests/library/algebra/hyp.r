%HYP.R
%
%Function: Returns the hypotenuse of a right triangle with legs #1#, #2#.
%
%Syntax:    HYP(x,y)
%
if( #NUM_ARGS# != 2 )
  { ECHO(\k\a"Error: wrong number of arguments to the HYP command"\p\n); }
else
  { ((#1#)^2 + (#2#)^2)^0.5 }
