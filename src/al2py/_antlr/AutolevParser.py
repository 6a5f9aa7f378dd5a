# Generated from Autolev.g4 by ANTLR 4.13.2
# encoding: utf-8
from antlr4 import *
from io import StringIO
import sys
if sys.version_info[1] > 5:
	from typing import TextIO
else:
	from typing.io import TextIO

def serializedATN():
    return [
        4,1,52,429,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,1,0,3,0,86,8,0,1,0,5,0,89,8,0,10,0,12,0,92,9,
        0,1,0,3,0,95,8,0,1,0,1,0,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,3,1,
        108,8,1,1,2,1,2,1,2,1,2,1,3,1,3,1,3,1,3,1,3,1,3,1,3,5,3,121,8,3,
        10,3,12,3,124,9,3,3,3,126,8,3,1,4,1,4,1,5,1,5,3,5,132,8,5,1,5,1,
        5,1,5,5,5,137,8,5,10,5,12,5,140,9,5,1,6,1,6,1,7,1,7,1,7,1,8,1,8,
        3,8,149,8,8,1,8,5,8,152,8,8,10,8,12,8,155,9,8,1,8,3,8,158,8,8,1,
        9,1,9,1,9,1,10,3,10,164,8,10,1,10,1,10,1,10,3,10,169,8,10,5,10,171,
        8,10,10,10,12,10,174,9,10,1,11,1,11,1,12,1,12,1,12,1,12,5,12,182,
        8,12,10,12,12,12,185,9,12,1,13,1,13,1,13,1,13,3,13,191,8,13,1,14,
        1,14,1,14,1,14,1,14,1,14,1,14,1,14,5,14,201,8,14,10,14,12,14,204,
        9,14,1,14,1,14,5,14,208,8,14,10,14,12,14,211,9,14,3,14,213,8,14,
        1,15,1,15,1,15,1,15,5,15,219,8,15,10,15,12,15,222,9,15,1,16,1,16,
        3,16,226,8,16,1,17,1,17,1,17,1,17,5,17,232,8,17,10,17,12,17,235,
        9,17,1,18,1,18,1,18,1,18,5,18,241,8,18,10,18,12,18,244,9,18,1,19,
        1,19,1,20,1,20,1,20,3,20,251,8,20,1,20,3,20,254,8,20,1,21,1,21,1,
        21,1,21,3,21,260,8,21,1,21,1,21,3,21,264,8,21,1,21,3,21,267,8,21,
        1,22,1,22,1,22,3,22,272,8,22,1,22,1,22,1,22,1,22,1,22,1,22,1,22,
        1,22,1,23,1,23,1,23,1,24,1,24,3,24,287,8,24,1,25,1,25,1,25,1,26,
        1,26,3,26,294,8,26,1,27,1,27,1,28,1,28,1,28,1,28,5,28,302,8,28,10,
        28,12,28,305,9,28,1,29,1,29,1,30,1,30,1,30,1,30,5,30,313,8,30,10,
        30,12,30,316,9,30,1,31,1,31,1,32,1,32,1,32,1,32,3,32,324,8,32,1,
        33,1,33,1,33,3,33,329,8,33,1,34,1,34,1,34,1,34,1,34,1,34,3,34,337,
        8,34,1,34,1,34,1,34,1,34,1,34,1,34,1,34,1,34,1,34,1,34,5,34,349,
        8,34,10,34,12,34,352,9,34,1,34,1,34,5,34,356,8,34,10,34,12,34,359,
        9,34,1,34,1,34,1,34,1,34,5,34,365,8,34,10,34,12,34,368,9,34,1,34,
        1,34,1,34,1,34,1,34,1,34,3,34,376,8,34,1,35,1,35,1,35,5,35,381,8,
        35,10,35,12,35,384,9,35,1,36,1,36,1,36,5,36,389,8,36,10,36,12,36,
        392,9,36,1,37,1,37,1,37,5,37,397,8,37,10,37,12,37,400,9,37,1,38,
        1,38,1,38,3,38,405,8,38,1,38,1,38,3,38,409,8,38,1,39,1,39,1,39,1,
        39,5,39,415,8,39,10,39,12,39,418,9,39,1,39,1,39,1,40,1,40,1,40,3,
        40,425,8,40,1,41,1,41,1,41,0,0,42,0,2,4,6,8,10,12,14,16,18,20,22,
        24,26,28,30,32,34,36,38,40,42,44,46,48,50,52,54,56,58,60,62,64,66,
        68,70,72,74,76,78,80,82,0,7,1,0,25,31,1,0,1,11,1,0,32,33,1,0,34,
        35,1,0,16,17,1,0,18,19,2,0,1,17,21,21,448,0,90,1,0,0,0,2,107,1,0,
        0,0,4,109,1,0,0,0,6,125,1,0,0,0,8,127,1,0,0,0,10,129,1,0,0,0,12,
        141,1,0,0,0,14,143,1,0,0,0,16,157,1,0,0,0,18,159,1,0,0,0,20,163,
        1,0,0,0,22,175,1,0,0,0,24,177,1,0,0,0,26,186,1,0,0,0,28,212,1,0,
        0,0,30,214,1,0,0,0,32,223,1,0,0,0,34,227,1,0,0,0,36,236,1,0,0,0,
        38,245,1,0,0,0,40,247,1,0,0,0,42,255,1,0,0,0,44,268,1,0,0,0,46,281,
        1,0,0,0,48,286,1,0,0,0,50,288,1,0,0,0,52,293,1,0,0,0,54,295,1,0,
        0,0,56,297,1,0,0,0,58,306,1,0,0,0,60,308,1,0,0,0,62,317,1,0,0,0,
        64,323,1,0,0,0,66,325,1,0,0,0,68,375,1,0,0,0,70,377,1,0,0,0,72,385,
        1,0,0,0,74,393,1,0,0,0,76,401,1,0,0,0,78,410,1,0,0,0,80,421,1,0,
        0,0,82,426,1,0,0,0,84,86,3,2,1,0,85,84,1,0,0,0,85,86,1,0,0,0,86,
        87,1,0,0,0,87,89,5,50,0,0,88,85,1,0,0,0,89,92,1,0,0,0,90,88,1,0,
        0,0,90,91,1,0,0,0,91,94,1,0,0,0,92,90,1,0,0,0,93,95,3,2,1,0,94,93,
        1,0,0,0,94,95,1,0,0,0,95,96,1,0,0,0,96,97,5,0,0,1,97,1,1,0,0,0,98,
        108,3,4,2,0,99,108,3,8,4,0,100,108,3,10,5,0,101,108,3,24,12,0,102,
        108,3,30,15,0,103,108,3,34,17,0,104,108,3,42,21,0,105,108,3,46,23,
        0,106,108,3,50,25,0,107,98,1,0,0,0,107,99,1,0,0,0,107,100,1,0,0,
        0,107,101,1,0,0,0,107,102,1,0,0,0,107,103,1,0,0,0,107,104,1,0,0,
        0,107,105,1,0,0,0,107,106,1,0,0,0,108,3,1,0,0,0,109,110,3,6,3,0,
        110,111,7,0,0,0,111,112,3,54,27,0,112,5,1,0,0,0,113,114,3,82,41,
        0,114,115,5,40,0,0,115,116,3,72,36,0,116,117,5,41,0,0,117,126,1,
        0,0,0,118,122,3,82,41,0,119,121,5,37,0,0,120,119,1,0,0,0,121,124,
        1,0,0,0,122,120,1,0,0,0,122,123,1,0,0,0,123,126,1,0,0,0,124,122,
        1,0,0,0,125,113,1,0,0,0,125,118,1,0,0,0,126,7,1,0,0,0,127,128,3,
        54,27,0,128,9,1,0,0,0,129,131,3,12,6,0,130,132,5,37,0,0,131,130,
        1,0,0,0,131,132,1,0,0,0,132,133,1,0,0,0,133,138,3,14,7,0,134,135,
        5,44,0,0,135,137,3,18,9,0,136,134,1,0,0,0,137,140,1,0,0,0,138,136,
        1,0,0,0,138,139,1,0,0,0,139,11,1,0,0,0,140,138,1,0,0,0,141,142,7,
        1,0,0,142,13,1,0,0,0,143,144,3,16,8,0,144,145,3,20,10,0,145,15,1,
        0,0,0,146,148,3,82,41,0,147,149,3,78,39,0,148,147,1,0,0,0,148,149,
        1,0,0,0,149,153,1,0,0,0,150,152,5,37,0,0,151,150,1,0,0,0,152,155,
        1,0,0,0,153,151,1,0,0,0,153,154,1,0,0,0,154,158,1,0,0,0,155,153,
        1,0,0,0,156,158,5,20,0,0,157,146,1,0,0,0,157,156,1,0,0,0,158,17,
        1,0,0,0,159,160,3,54,27,0,160,161,3,20,10,0,161,19,1,0,0,0,162,164,
        3,22,11,0,163,162,1,0,0,0,163,164,1,0,0,0,164,172,1,0,0,0,165,166,
        5,31,0,0,166,168,3,54,27,0,167,169,3,22,11,0,168,167,1,0,0,0,168,
        169,1,0,0,0,169,171,1,0,0,0,170,165,1,0,0,0,171,174,1,0,0,0,172,
        170,1,0,0,0,172,173,1,0,0,0,173,21,1,0,0,0,174,172,1,0,0,0,175,176,
        7,2,0,0,176,23,1,0,0,0,177,178,5,12,0,0,178,183,3,26,13,0,179,180,
        5,44,0,0,180,182,3,26,13,0,181,179,1,0,0,0,182,185,1,0,0,0,183,181,
        1,0,0,0,183,184,1,0,0,0,184,25,1,0,0,0,185,183,1,0,0,0,186,187,3,
        28,14,0,187,188,5,31,0,0,188,190,3,54,27,0,189,191,3,36,18,0,190,
        189,1,0,0,0,190,191,1,0,0,0,191,27,1,0,0,0,192,193,3,82,41,0,193,
        194,5,40,0,0,194,195,3,72,36,0,195,196,5,41,0,0,196,213,1,0,0,0,
        197,198,3,82,41,0,198,202,3,78,39,0,199,201,5,37,0,0,200,199,1,0,
        0,0,201,204,1,0,0,0,202,200,1,0,0,0,202,203,1,0,0,0,203,213,1,0,
        0,0,204,202,1,0,0,0,205,209,3,82,41,0,206,208,5,37,0,0,207,206,1,
        0,0,0,208,211,1,0,0,0,209,207,1,0,0,0,209,210,1,0,0,0,210,213,1,
        0,0,0,211,209,1,0,0,0,212,192,1,0,0,0,212,197,1,0,0,0,212,205,1,
        0,0,0,213,29,1,0,0,0,214,215,5,13,0,0,215,220,3,32,16,0,216,217,
        5,44,0,0,217,219,3,32,16,0,218,216,1,0,0,0,219,222,1,0,0,0,220,218,
        1,0,0,0,220,221,1,0,0,0,221,31,1,0,0,0,222,220,1,0,0,0,223,225,3,
        54,27,0,224,226,3,36,18,0,225,224,1,0,0,0,225,226,1,0,0,0,226,33,
        1,0,0,0,227,228,5,14,0,0,228,233,3,82,41,0,229,230,5,44,0,0,230,
        232,3,82,41,0,231,229,1,0,0,0,232,235,1,0,0,0,233,231,1,0,0,0,233,
        234,1,0,0,0,234,35,1,0,0,0,235,233,1,0,0,0,236,242,3,40,20,0,237,
        238,3,38,19,0,238,239,3,40,20,0,239,241,1,0,0,0,240,237,1,0,0,0,
        241,244,1,0,0,0,242,240,1,0,0,0,242,243,1,0,0,0,243,37,1,0,0,0,244,
        242,1,0,0,0,245,246,7,3,0,0,246,39,1,0,0,0,247,253,3,82,41,0,248,
        250,5,36,0,0,249,251,5,33,0,0,250,249,1,0,0,0,250,251,1,0,0,0,251,
        252,1,0,0,0,252,254,5,20,0,0,253,248,1,0,0,0,253,254,1,0,0,0,254,
        41,1,0,0,0,255,256,5,15,0,0,256,257,3,82,41,0,257,259,5,38,0,0,258,
        260,3,74,37,0,259,258,1,0,0,0,259,260,1,0,0,0,260,261,1,0,0,0,261,
        263,5,39,0,0,262,264,3,44,22,0,263,262,1,0,0,0,263,264,1,0,0,0,264,
        266,1,0,0,0,265,267,3,48,24,0,266,265,1,0,0,0,266,267,1,0,0,0,267,
        43,1,0,0,0,268,269,5,40,0,0,269,271,3,82,41,0,270,272,3,36,18,0,
        271,270,1,0,0,0,271,272,1,0,0,0,272,273,1,0,0,0,273,274,5,31,0,0,
        274,275,3,54,27,0,275,276,5,44,0,0,276,277,3,54,27,0,277,278,5,44,
        0,0,278,279,3,54,27,0,279,280,5,41,0,0,280,45,1,0,0,0,281,282,7,
        4,0,0,282,283,3,48,24,0,283,47,1,0,0,0,284,287,5,22,0,0,285,287,
        3,82,41,0,286,284,1,0,0,0,286,285,1,0,0,0,287,49,1,0,0,0,288,289,
        5,21,0,0,289,290,3,52,26,0,290,51,1,0,0,0,291,294,3,82,41,0,292,
        294,5,20,0,0,293,291,1,0,0,0,293,292,1,0,0,0,294,53,1,0,0,0,295,
        296,3,56,28,0,296,55,1,0,0,0,297,303,3,60,30,0,298,299,3,58,29,0,
        299,300,3,60,30,0,300,302,1,0,0,0,301,298,1,0,0,0,302,305,1,0,0,
        0,303,301,1,0,0,0,303,304,1,0,0,0,304,57,1,0,0,0,305,303,1,0,0,0,
        306,307,7,2,0,0,307,59,1,0,0,0,308,314,3,64,32,0,309,310,3,62,31,
        0,310,311,3,64,32,0,311,313,1,0,0,0,312,309,1,0,0,0,313,316,1,0,
        0,0,314,312,1,0,0,0,314,315,1,0,0,0,315,61,1,0,0,0,316,314,1,0,0,
        0,317,318,7,3,0,0,318,63,1,0,0,0,319,320,3,58,29,0,320,321,3,64,
        32,0,321,324,1,0,0,0,322,324,3,66,33,0,323,319,1,0,0,0,323,322,1,
        0,0,0,324,65,1,0,0,0,325,328,3,68,34,0,326,327,5,36,0,0,327,329,
        3,64,32,0,328,326,1,0,0,0,328,329,1,0,0,0,329,67,1,0,0,0,330,376,
        5,20,0,0,331,376,5,23,0,0,332,376,7,5,0,0,333,334,3,82,41,0,334,
        336,5,38,0,0,335,337,3,74,37,0,336,335,1,0,0,0,336,337,1,0,0,0,337,
        338,1,0,0,0,338,339,5,39,0,0,339,376,1,0,0,0,340,341,3,82,41,0,341,
        342,5,40,0,0,342,343,3,72,36,0,343,344,5,41,0,0,344,376,1,0,0,0,
        345,346,3,82,41,0,346,350,3,78,39,0,347,349,5,37,0,0,348,347,1,0,
        0,0,349,352,1,0,0,0,350,348,1,0,0,0,350,351,1,0,0,0,351,376,1,0,
        0,0,352,350,1,0,0,0,353,357,3,82,41,0,354,356,5,37,0,0,355,354,1,
        0,0,0,356,359,1,0,0,0,357,355,1,0,0,0,357,358,1,0,0,0,358,376,1,
        0,0,0,359,357,1,0,0,0,360,361,5,40,0,0,361,366,3,70,35,0,362,363,
        5,45,0,0,363,365,3,70,35,0,364,362,1,0,0,0,365,368,1,0,0,0,366,364,
        1,0,0,0,366,367,1,0,0,0,367,369,1,0,0,0,368,366,1,0,0,0,369,370,
        5,41,0,0,370,376,1,0,0,0,371,372,5,38,0,0,372,373,3,54,27,0,373,
        374,5,39,0,0,374,376,1,0,0,0,375,330,1,0,0,0,375,331,1,0,0,0,375,
        332,1,0,0,0,375,333,1,0,0,0,375,340,1,0,0,0,375,345,1,0,0,0,375,
        353,1,0,0,0,375,360,1,0,0,0,375,371,1,0,0,0,376,69,1,0,0,0,377,382,
        3,54,27,0,378,379,5,44,0,0,379,381,3,54,27,0,380,378,1,0,0,0,381,
        384,1,0,0,0,382,380,1,0,0,0,382,383,1,0,0,0,383,71,1,0,0,0,384,382,
        1,0,0,0,385,390,3,54,27,0,386,387,5,44,0,0,387,389,3,54,27,0,388,
        386,1,0,0,0,389,392,1,0,0,0,390,388,1,0,0,0,390,391,1,0,0,0,391,
        73,1,0,0,0,392,390,1,0,0,0,393,398,3,76,38,0,394,395,5,44,0,0,395,
        397,3,76,38,0,396,394,1,0,0,0,397,400,1,0,0,0,398,396,1,0,0,0,398,
        399,1,0,0,0,399,75,1,0,0,0,400,398,1,0,0,0,401,404,3,54,27,0,402,
        403,5,31,0,0,403,405,3,54,27,0,404,402,1,0,0,0,404,405,1,0,0,0,405,
        408,1,0,0,0,406,407,5,46,0,0,407,409,3,54,27,0,408,406,1,0,0,0,408,
        409,1,0,0,0,409,77,1,0,0,0,410,411,5,42,0,0,411,416,3,80,40,0,412,
        413,5,44,0,0,413,415,3,80,40,0,414,412,1,0,0,0,415,418,1,0,0,0,416,
        414,1,0,0,0,416,417,1,0,0,0,417,419,1,0,0,0,418,416,1,0,0,0,419,
        420,5,43,0,0,420,79,1,0,0,0,421,424,5,20,0,0,422,423,5,46,0,0,423,
        425,5,20,0,0,424,422,1,0,0,0,424,425,1,0,0,0,425,81,1,0,0,0,426,
        427,7,6,0,0,427,83,1,0,0,0,47,85,90,94,107,122,125,131,138,148,153,
        157,163,168,172,183,190,202,209,212,220,225,233,242,250,253,259,
        263,266,271,286,293,303,314,323,328,336,350,357,366,375,382,390,
        398,404,408,416,424
    ]

class AutolevParser ( Parser ):

    grammarFileName = "Autolev.g4"

    atn = ATNDeserializer().deserialize(serializedATN())

    decisionsToDFA = [ DFA(ds, i) for i, ds in enumerate(atn.decisionToState) ]

    sharedContextCache = PredictionContextCache()

    literalNames = [ "<INVALID>", "<INVALID>", "<INVALID>", "'specified'", 
                     "'imaginary'", "'newtonian'", "<INVALID>", "<INVALID>", 
                     "<INVALID>", "<INVALID>", "'mass'", "'inertia'", "<INVALID>", 
                     "<INVALID>", "'unitsystem'", "'code'", "'save'", "'run'", 
                     "<INVALID>", "'1>>'", "<INVALID>", "<INVALID>", "<INVALID>", 
                     "<INVALID>", "<INVALID>", "':='", "'+='", "'-='", "'*='", 
                     "'/='", "'^='", "'='", "'+'", "'-'", "'*'", "'/'", 
                     "'^'", "'''", "'('", "')'", "'['", "']'", "'{'", "'}'", 
                     "','", "';'", "':'", "<INVALID>", "'&'" ]

    symbolicNames = [ "<INVALID>", "CONSTANTS", "VARIABLES", "SPECIFIED", 
                      "IMAGINARY", "NEWTONIAN", "FRAMES", "BODIES", "PARTICLES", 
                      "POINTS", "MASS", "INERTIA", "INPUT", "OUTPUT", "UNITSYSTEM", 
                      "CODE", "SAVE", "RUN", "ZEROVEC", "UNITDYADIC", "NUMBER", 
                      "ID", "FILENAME", "STRING", "UNTERMINATED_STRING", 
                      "COLONEQ", "PLUSEQ", "MINUSEQ", "TIMESEQ", "DIVEQ", 
                      "POWEQ", "EQ", "PLUS", "MINUS", "TIMES", "DIV", "CARET", 
                      "PRIME", "LPAREN", "RPAREN", "LBRACK", "RBRACK", "LBRACE", 
                      "RBRACE", "COMMA", "SEMI", "COLON", "CONTINUATION", 
                      "AMP", "COMMENT", "NEWLINE", "WS", "ERRCHAR" ]

    RULE_script = 0
    RULE_stmt = 1
    RULE_assignment = 2
    RULE_lvalue = 3
    RULE_exprStmt = 4
    RULE_declaration = 5
    RULE_declKeyword = 6
    RULE_firstDeclItem = 7
    RULE_declHead = 8
    RULE_declItem = 9
    RULE_declTail = 10
    RULE_sign = 11
    RULE_inputStmt = 12
    RULE_inputItem = 13
    RULE_inputTarget = 14
    RULE_outputStmt = 15
    RULE_outputItem = 16
    RULE_unitSystemStmt = 17
    RULE_unit = 18
    RULE_unitOp = 19
    RULE_unitFactor = 20
    RULE_codeStmt = 21
    RULE_sweep = 22
    RULE_fileCommand = 23
    RULE_fileName = 24
    RULE_setting = 25
    RULE_settingValue = 26
    RULE_expr = 27
    RULE_additive = 28
    RULE_addOp = 29
    RULE_multiplicative = 30
    RULE_mulOp = 31
    RULE_unary = 32
    RULE_power = 33
    RULE_atom = 34
    RULE_matrixRow = 35
    RULE_exprList = 36
    RULE_argList = 37
    RULE_arg = 38
    RULE_indexBraces = 39
    RULE_indexRange = 40
    RULE_ident = 41

    ruleNames =  [ "script", "stmt", "assignment", "lvalue", "exprStmt", 
                   "declaration", "declKeyword", "firstDeclItem", "declHead", 
                   "declItem", "declTail", "sign", "inputStmt", "inputItem", 
                   "inputTarget", "outputStmt", "outputItem", "unitSystemStmt", 
                   "unit", "unitOp", "unitFactor", "codeStmt", "sweep", 
                   "fileCommand", "fileName", "setting", "settingValue", 
                   "expr", "additive", "addOp", "multiplicative", "mulOp", 
                   "unary", "power", "atom", "matrixRow", "exprList", "argList", 
                   "arg", "indexBraces", "indexRange", "ident" ]

    EOF = Token.EOF
    CONSTANTS=1
    VARIABLES=2
    SPECIFIED=3
    IMAGINARY=4
    NEWTONIAN=5
    FRAMES=6
    BODIES=7
    PARTICLES=8
    POINTS=9
    MASS=10
    INERTIA=11
    INPUT=12
    OUTPUT=13
    UNITSYSTEM=14
    CODE=15
    SAVE=16
    RUN=17
    ZEROVEC=18
    UNITDYADIC=19
    NUMBER=20
    ID=21
    FILENAME=22
    STRING=23
    UNTERMINATED_STRING=24
    COLONEQ=25
    PLUSEQ=26
    MINUSEQ=27
    TIMESEQ=28
    DIVEQ=29
    POWEQ=30
    EQ=31
    PLUS=32
    MINUS=33
    TIMES=34
    DIV=35
    CARET=36
    PRIME=37
    LPAREN=38
    RPAREN=39
    LBRACK=40
    RBRACK=41
    LBRACE=42
    RBRACE=43
    COMMA=44
    SEMI=45
    COLON=46
    CONTINUATION=47
    AMP=48
    COMMENT=49
    NEWLINE=50
    WS=51
    ERRCHAR=52

    def __init__(self, input:TokenStream, output:TextIO = sys.stdout):
        super().__init__(input, output)
        self.checkVersion("4.13.2")
        self._interp = ParserATNSimulator(self, self.atn, self.decisionsToDFA, self.sharedContextCache)
        self._predicates = None




    class ScriptContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def EOF(self):
            return self.getToken(AutolevParser.EOF, 0)

        def NEWLINE(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.NEWLINE)
            else:
                return self.getToken(AutolevParser.NEWLINE, i)

        def stmt(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.StmtContext)
            else:
                return self.getTypedRuleContext(AutolevParser.StmtContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_script

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitScript" ):
                return visitor.visitScript(self)
            else:
                return visitor.visitChildren(self)




    def script(self):

        localctx = AutolevParser.ScriptContext(self, self._ctx, self.state)
        self.enterRule(localctx, 0, self.RULE_script)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 90
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,1,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 85
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)
                    if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                        self.state = 84
                        self.stmt()


                    self.state = 87
                    self.match(AutolevParser.NEWLINE) 
                self.state = 92
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,1,self._ctx)

            self.state = 94
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 93
                self.stmt()


            self.state = 96
            self.match(AutolevParser.EOF)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class StmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def assignment(self):
            return self.getTypedRuleContext(AutolevParser.AssignmentContext,0)


        def exprStmt(self):
            return self.getTypedRuleContext(AutolevParser.ExprStmtContext,0)


        def declaration(self):
            return self.getTypedRuleContext(AutolevParser.DeclarationContext,0)


        def inputStmt(self):
            return self.getTypedRuleContext(AutolevParser.InputStmtContext,0)


        def outputStmt(self):
            return self.getTypedRuleContext(AutolevParser.OutputStmtContext,0)


        def unitSystemStmt(self):
            return self.getTypedRuleContext(AutolevParser.UnitSystemStmtContext,0)


        def codeStmt(self):
            return self.getTypedRuleContext(AutolevParser.CodeStmtContext,0)


        def fileCommand(self):
            return self.getTypedRuleContext(AutolevParser.FileCommandContext,0)


        def setting(self):
            return self.getTypedRuleContext(AutolevParser.SettingContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_stmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStmt" ):
                return visitor.visitStmt(self)
            else:
                return visitor.visitChildren(self)




    def stmt(self):

        localctx = AutolevParser.StmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 2, self.RULE_stmt)
        try:
            self.state = 107
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,3,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 98
                self.assignment()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 99
                self.exprStmt()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 100
                self.declaration()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 101
                self.inputStmt()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 102
                self.outputStmt()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 103
                self.unitSystemStmt()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 104
                self.codeStmt()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 105
                self.fileCommand()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 106
                self.setting()
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AssignmentContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser
            self.op = None # Token

        def lvalue(self):
            return self.getTypedRuleContext(AutolevParser.LvalueContext,0)


        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)

        def COLONEQ(self):
            return self.getToken(AutolevParser.COLONEQ, 0)

        def PLUSEQ(self):
            return self.getToken(AutolevParser.PLUSEQ, 0)

        def MINUSEQ(self):
            return self.getToken(AutolevParser.MINUSEQ, 0)

        def TIMESEQ(self):
            return self.getToken(AutolevParser.TIMESEQ, 0)

        def DIVEQ(self):
            return self.getToken(AutolevParser.DIVEQ, 0)

        def POWEQ(self):
            return self.getToken(AutolevParser.POWEQ, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_assignment

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAssignment" ):
                return visitor.visitAssignment(self)
            else:
                return visitor.visitChildren(self)




    def assignment(self):

        localctx = AutolevParser.AssignmentContext(self, self._ctx, self.state)
        self.enterRule(localctx, 4, self.RULE_assignment)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 109
            self.lvalue()
            self.state = 110
            localctx.op = self._input.LT(1)
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 4261412864) != 0)):
                localctx.op = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 111
            self.expr()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class LvalueContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_lvalue

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class ElementTargetContext(LvalueContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.LvalueContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def exprList(self):
            return self.getTypedRuleContext(AutolevParser.ExprListContext,0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitElementTarget" ):
                return visitor.visitElementTarget(self)
            else:
                return visitor.visitChildren(self)


    class NameTargetContext(LvalueContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.LvalueContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNameTarget" ):
                return visitor.visitNameTarget(self)
            else:
                return visitor.visitChildren(self)



    def lvalue(self):

        localctx = AutolevParser.LvalueContext(self, self._ctx, self.state)
        self.enterRule(localctx, 6, self.RULE_lvalue)
        self._la = 0 # Token type
        try:
            self.state = 125
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,5,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.ElementTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 113
                self.ident()
                self.state = 114
                self.match(AutolevParser.LBRACK)
                self.state = 115
                self.exprList()
                self.state = 116
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.NameTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 118
                self.ident()
                self.state = 122
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 119
                    self.match(AutolevParser.PRIME)
                    self.state = 124
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExprStmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_exprStmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExprStmt" ):
                return visitor.visitExprStmt(self)
            else:
                return visitor.visitChildren(self)




    def exprStmt(self):

        localctx = AutolevParser.ExprStmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 8, self.RULE_exprStmt)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 127
            self.expr()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclarationContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def declKeyword(self):
            return self.getTypedRuleContext(AutolevParser.DeclKeywordContext,0)


        def firstDeclItem(self):
            return self.getTypedRuleContext(AutolevParser.FirstDeclItemContext,0)


        def PRIME(self):
            return self.getToken(AutolevParser.PRIME, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def declItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.DeclItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.DeclItemContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_declaration

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclaration" ):
                return visitor.visitDeclaration(self)
            else:
                return visitor.visitChildren(self)




    def declaration(self):

        localctx = AutolevParser.DeclarationContext(self, self._ctx, self.state)
        self.enterRule(localctx, 10, self.RULE_declaration)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 129
            self.declKeyword()
            self.state = 131
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==37:
                self.state = 130
                self.match(AutolevParser.PRIME)


            self.state = 133
            self.firstDeclItem()
            self.state = 138
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 134
                self.match(AutolevParser.COMMA)
                self.state = 135
                self.declItem()
                self.state = 140
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclKeywordContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def CONSTANTS(self):
            return self.getToken(AutolevParser.CONSTANTS, 0)

        def VARIABLES(self):
            return self.getToken(AutolevParser.VARIABLES, 0)

        def SPECIFIED(self):
            return self.getToken(AutolevParser.SPECIFIED, 0)

        def IMAGINARY(self):
            return self.getToken(AutolevParser.IMAGINARY, 0)

        def NEWTONIAN(self):
            return self.getToken(AutolevParser.NEWTONIAN, 0)

        def FRAMES(self):
            return self.getToken(AutolevParser.FRAMES, 0)

        def BODIES(self):
            return self.getToken(AutolevParser.BODIES, 0)

        def PARTICLES(self):
            return self.getToken(AutolevParser.PARTICLES, 0)

        def POINTS(self):
            return self.getToken(AutolevParser.POINTS, 0)

        def MASS(self):
            return self.getToken(AutolevParser.MASS, 0)

        def INERTIA(self):
            return self.getToken(AutolevParser.INERTIA, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_declKeyword

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclKeyword" ):
                return visitor.visitDeclKeyword(self)
            else:
                return visitor.visitChildren(self)




    def declKeyword(self):

        localctx = AutolevParser.DeclKeywordContext(self, self._ctx, self.state)
        self.enterRule(localctx, 12, self.RULE_declKeyword)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 141
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 4094) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FirstDeclItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def declHead(self):
            return self.getTypedRuleContext(AutolevParser.DeclHeadContext,0)


        def declTail(self):
            return self.getTypedRuleContext(AutolevParser.DeclTailContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_firstDeclItem

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFirstDeclItem" ):
                return visitor.visitFirstDeclItem(self)
            else:
                return visitor.visitChildren(self)




    def firstDeclItem(self):

        localctx = AutolevParser.FirstDeclItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 14, self.RULE_firstDeclItem)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 143
            self.declHead()
            self.state = 144
            self.declTail()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclHeadContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def indexBraces(self):
            return self.getTypedRuleContext(AutolevParser.IndexBracesContext,0)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_declHead

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclHead" ):
                return visitor.visitDeclHead(self)
            else:
                return visitor.visitChildren(self)




    def declHead(self):

        localctx = AutolevParser.DeclHeadContext(self, self._ctx, self.state)
        self.enterRule(localctx, 16, self.RULE_declHead)
        self._la = 0 # Token type
        try:
            self.state = 157
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.enterOuterAlt(localctx, 1)
                self.state = 146
                self.ident()
                self.state = 148
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==42:
                    self.state = 147
                    self.indexBraces()


                self.state = 153
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 150
                    self.match(AutolevParser.PRIME)
                    self.state = 155
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 156
                self.match(AutolevParser.NUMBER)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def declTail(self):
            return self.getTypedRuleContext(AutolevParser.DeclTailContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_declItem

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclItem" ):
                return visitor.visitDeclItem(self)
            else:
                return visitor.visitChildren(self)




    def declItem(self):

        localctx = AutolevParser.DeclItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 18, self.RULE_declItem)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 159
            self.expr()
            self.state = 160
            self.declTail()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class DeclTailContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def sign(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.SignContext)
            else:
                return self.getTypedRuleContext(AutolevParser.SignContext,i)


        def EQ(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.EQ)
            else:
                return self.getToken(AutolevParser.EQ, i)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_declTail

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitDeclTail" ):
                return visitor.visitDeclTail(self)
            else:
                return visitor.visitChildren(self)




    def declTail(self):

        localctx = AutolevParser.DeclTailContext(self, self._ctx, self.state)
        self.enterRule(localctx, 20, self.RULE_declTail)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 163
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==32 or _la==33:
                self.state = 162
                self.sign()


            self.state = 172
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==31:
                self.state = 165
                self.match(AutolevParser.EQ)
                self.state = 166
                self.expr()
                self.state = 168
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==32 or _la==33:
                    self.state = 167
                    self.sign()


                self.state = 174
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SignContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def PLUS(self):
            return self.getToken(AutolevParser.PLUS, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_sign

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSign" ):
                return visitor.visitSign(self)
            else:
                return visitor.visitChildren(self)




    def sign(self):

        localctx = AutolevParser.SignContext(self, self._ctx, self.state)
        self.enterRule(localctx, 22, self.RULE_sign)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 175
            _la = self._input.LA(1)
            if not(_la==32 or _la==33):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InputStmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def INPUT(self):
            return self.getToken(AutolevParser.INPUT, 0)

        def inputItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.InputItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.InputItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_inputStmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputStmt" ):
                return visitor.visitInputStmt(self)
            else:
                return visitor.visitChildren(self)




    def inputStmt(self):

        localctx = AutolevParser.InputStmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 24, self.RULE_inputStmt)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 177
            self.match(AutolevParser.INPUT)
            self.state = 178
            self.inputItem()
            self.state = 183
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 179
                self.match(AutolevParser.COMMA)
                self.state = 180
                self.inputItem()
                self.state = 185
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InputItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def inputTarget(self):
            return self.getTypedRuleContext(AutolevParser.InputTargetContext,0)


        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_inputItem

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputItem" ):
                return visitor.visitInputItem(self)
            else:
                return visitor.visitChildren(self)




    def inputItem(self):

        localctx = AutolevParser.InputItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 26, self.RULE_inputItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 186
            self.inputTarget()
            self.state = 187
            self.match(AutolevParser.EQ)
            self.state = 188
            self.expr()
            self.state = 190
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0):
                self.state = 189
                self.unit()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class InputTargetContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_inputTarget

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class InputIndexedContext(InputTargetContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.InputTargetContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def indexBraces(self):
            return self.getTypedRuleContext(AutolevParser.IndexBracesContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputIndexed" ):
                return visitor.visitInputIndexed(self)
            else:
                return visitor.visitChildren(self)


    class InputNameContext(InputTargetContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.InputTargetContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputName" ):
                return visitor.visitInputName(self)
            else:
                return visitor.visitChildren(self)


    class InputElementContext(InputTargetContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.InputTargetContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def exprList(self):
            return self.getTypedRuleContext(AutolevParser.ExprListContext,0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitInputElement" ):
                return visitor.visitInputElement(self)
            else:
                return visitor.visitChildren(self)



    def inputTarget(self):

        localctx = AutolevParser.InputTargetContext(self, self._ctx, self.state)
        self.enterRule(localctx, 28, self.RULE_inputTarget)
        self._la = 0 # Token type
        try:
            self.state = 212
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,18,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.InputElementContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 192
                self.ident()
                self.state = 193
                self.match(AutolevParser.LBRACK)
                self.state = 194
                self.exprList()
                self.state = 195
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.InputIndexedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 197
                self.ident()
                self.state = 198
                self.indexBraces()
                self.state = 202
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 199
                    self.match(AutolevParser.PRIME)
                    self.state = 204
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 3:
                localctx = AutolevParser.InputNameContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 205
                self.ident()
                self.state = 209
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 206
                    self.match(AutolevParser.PRIME)
                    self.state = 211
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class OutputStmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def OUTPUT(self):
            return self.getToken(AutolevParser.OUTPUT, 0)

        def outputItem(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.OutputItemContext)
            else:
                return self.getTypedRuleContext(AutolevParser.OutputItemContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_outputStmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOutputStmt" ):
                return visitor.visitOutputStmt(self)
            else:
                return visitor.visitChildren(self)




    def outputStmt(self):

        localctx = AutolevParser.OutputStmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 30, self.RULE_outputStmt)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 214
            self.match(AutolevParser.OUTPUT)
            self.state = 215
            self.outputItem()
            self.state = 220
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 216
                self.match(AutolevParser.COMMA)
                self.state = 217
                self.outputItem()
                self.state = 222
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class OutputItemContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)


        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_outputItem

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitOutputItem" ):
                return visitor.visitOutputItem(self)
            else:
                return visitor.visitChildren(self)




    def outputItem(self):

        localctx = AutolevParser.OutputItemContext(self, self._ctx, self.state)
        self.enterRule(localctx, 32, self.RULE_outputItem)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 223
            self.expr()
            self.state = 225
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0):
                self.state = 224
                self.unit()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitSystemStmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def UNITSYSTEM(self):
            return self.getToken(AutolevParser.UNITSYSTEM, 0)

        def ident(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IdentContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IdentContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitSystemStmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitSystemStmt" ):
                return visitor.visitUnitSystemStmt(self)
            else:
                return visitor.visitChildren(self)




    def unitSystemStmt(self):

        localctx = AutolevParser.UnitSystemStmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 34, self.RULE_unitSystemStmt)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 227
            self.match(AutolevParser.UNITSYSTEM)
            self.state = 228
            self.ident()
            self.state = 233
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 229
                self.match(AutolevParser.COMMA)
                self.state = 230
                self.ident()
                self.state = 235
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def unitFactor(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.UnitFactorContext)
            else:
                return self.getTypedRuleContext(AutolevParser.UnitFactorContext,i)


        def unitOp(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.UnitOpContext)
            else:
                return self.getTypedRuleContext(AutolevParser.UnitOpContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_unit

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnit" ):
                return visitor.visitUnit(self)
            else:
                return visitor.visitChildren(self)




    def unit(self):

        localctx = AutolevParser.UnitContext(self, self._ctx, self.state)
        self.enterRule(localctx, 36, self.RULE_unit)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 236
            self.unitFactor()
            self.state = 242
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 237
                self.unitOp()
                self.state = 238
                self.unitFactor()
                self.state = 244
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitOpContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def TIMES(self):
            return self.getToken(AutolevParser.TIMES, 0)

        def DIV(self):
            return self.getToken(AutolevParser.DIV, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitOp

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitOp" ):
                return visitor.visitUnitOp(self)
            else:
                return visitor.visitChildren(self)




    def unitOp(self):

        localctx = AutolevParser.UnitOpContext(self, self._ctx, self.state)
        self.enterRule(localctx, 38, self.RULE_unitOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 245
            _la = self._input.LA(1)
            if not(_la==34 or _la==35):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnitFactorContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def CARET(self):
            return self.getToken(AutolevParser.CARET, 0)

        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_unitFactor

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnitFactor" ):
                return visitor.visitUnitFactor(self)
            else:
                return visitor.visitChildren(self)




    def unitFactor(self):

        localctx = AutolevParser.UnitFactorContext(self, self._ctx, self.state)
        self.enterRule(localctx, 40, self.RULE_unitFactor)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 247
            self.ident()
            self.state = 253
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 248
                self.match(AutolevParser.CARET)
                self.state = 250
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==33:
                    self.state = 249
                    self.match(AutolevParser.MINUS)


                self.state = 252
                self.match(AutolevParser.NUMBER)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class CodeStmtContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def CODE(self):
            return self.getToken(AutolevParser.CODE, 0)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

        def argList(self):
            return self.getTypedRuleContext(AutolevParser.ArgListContext,0)


        def sweep(self):
            return self.getTypedRuleContext(AutolevParser.SweepContext,0)


        def fileName(self):
            return self.getTypedRuleContext(AutolevParser.FileNameContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_codeStmt

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCodeStmt" ):
                return visitor.visitCodeStmt(self)
            else:
                return visitor.visitChildren(self)




    def codeStmt(self):

        localctx = AutolevParser.CodeStmtContext(self, self._ctx, self.state)
        self.enterRule(localctx, 42, self.RULE_codeStmt)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 255
            self.match(AutolevParser.CODE)
            self.state = 256
            self.ident()
            self.state = 257
            self.match(AutolevParser.LPAREN)
            self.state = 259
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 258
                self.argList()


            self.state = 261
            self.match(AutolevParser.RPAREN)
            self.state = 263
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 262
                self.sweep()


            self.state = 266
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 265
                self.fileName()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SweepContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_sweep

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSweep" ):
                return visitor.visitSweep(self)
            else:
                return visitor.visitChildren(self)




    def sweep(self):

        localctx = AutolevParser.SweepContext(self, self._ctx, self.state)
        self.enterRule(localctx, 44, self.RULE_sweep)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 268
            self.match(AutolevParser.LBRACK)
            self.state = 269
            self.ident()
            self.state = 271
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0):
                self.state = 270
                self.unit()


            self.state = 273
            self.match(AutolevParser.EQ)
            self.state = 274
            self.expr()
            self.state = 275
            self.match(AutolevParser.COMMA)
            self.state = 276
            self.expr()
            self.state = 277
            self.match(AutolevParser.COMMA)
            self.state = 278
            self.expr()
            self.state = 279
            self.match(AutolevParser.RBRACK)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FileCommandContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def fileName(self):
            return self.getTypedRuleContext(AutolevParser.FileNameContext,0)


        def SAVE(self):
            return self.getToken(AutolevParser.SAVE, 0)

        def RUN(self):
            return self.getToken(AutolevParser.RUN, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_fileCommand

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFileCommand" ):
                return visitor.visitFileCommand(self)
            else:
                return visitor.visitChildren(self)




    def fileCommand(self):

        localctx = AutolevParser.FileCommandContext(self, self._ctx, self.state)
        self.enterRule(localctx, 46, self.RULE_fileCommand)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 281
            _la = self._input.LA(1)
            if not(_la==16 or _la==17):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 282
            self.fileName()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class FileNameContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def FILENAME(self):
            return self.getToken(AutolevParser.FILENAME, 0)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_fileName

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFileName" ):
                return visitor.visitFileName(self)
            else:
                return visitor.visitChildren(self)




    def fileName(self):

        localctx = AutolevParser.FileNameContext(self, self._ctx, self.state)
        self.enterRule(localctx, 48, self.RULE_fileName)
        try:
            self.state = 286
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [22]:
                self.enterOuterAlt(localctx, 1)
                self.state = 284
                self.match(AutolevParser.FILENAME)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.enterOuterAlt(localctx, 2)
                self.state = 285
                self.ident()
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ID(self):
            return self.getToken(AutolevParser.ID, 0)

        def settingValue(self):
            return self.getTypedRuleContext(AutolevParser.SettingValueContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_setting

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSetting" ):
                return visitor.visitSetting(self)
            else:
                return visitor.visitChildren(self)




    def setting(self):

        localctx = AutolevParser.SettingContext(self, self._ctx, self.state)
        self.enterRule(localctx, 50, self.RULE_setting)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 288
            self.match(AutolevParser.ID)
            self.state = 289
            self.settingValue()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingValueContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_settingValue

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingValue" ):
                return visitor.visitSettingValue(self)
            else:
                return visitor.visitChildren(self)




    def settingValue(self):

        localctx = AutolevParser.SettingValueContext(self, self._ctx, self.state)
        self.enterRule(localctx, 52, self.RULE_settingValue)
        try:
            self.state = 293
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.enterOuterAlt(localctx, 1)
                self.state = 291
                self.ident()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 292
                self.match(AutolevParser.NUMBER)
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExprContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def additive(self):
            return self.getTypedRuleContext(AutolevParser.AdditiveContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_expr

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExpr" ):
                return visitor.visitExpr(self)
            else:
                return visitor.visitChildren(self)




    def expr(self):

        localctx = AutolevParser.ExprContext(self, self._ctx, self.state)
        self.enterRule(localctx, 54, self.RULE_expr)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 295
            self.additive()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AdditiveContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def multiplicative(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.MultiplicativeContext)
            else:
                return self.getTypedRuleContext(AutolevParser.MultiplicativeContext,i)


        def addOp(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.AddOpContext)
            else:
                return self.getTypedRuleContext(AutolevParser.AddOpContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_additive

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAdditive" ):
                return visitor.visitAdditive(self)
            else:
                return visitor.visitChildren(self)




    def additive(self):

        localctx = AutolevParser.AdditiveContext(self, self._ctx, self.state)
        self.enterRule(localctx, 56, self.RULE_additive)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 297
            self.multiplicative()
            self.state = 303
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,31,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 298
                    self.addOp()
                    self.state = 299
                    self.multiplicative() 
                self.state = 305
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,31,self._ctx)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AddOpContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def PLUS(self):
            return self.getToken(AutolevParser.PLUS, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_addOp

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitAddOp" ):
                return visitor.visitAddOp(self)
            else:
                return visitor.visitChildren(self)




    def addOp(self):

        localctx = AutolevParser.AddOpContext(self, self._ctx, self.state)
        self.enterRule(localctx, 58, self.RULE_addOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 306
            _la = self._input.LA(1)
            if not(_la==32 or _la==33):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MultiplicativeContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def unary(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.UnaryContext)
            else:
                return self.getTypedRuleContext(AutolevParser.UnaryContext,i)


        def mulOp(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.MulOpContext)
            else:
                return self.getTypedRuleContext(AutolevParser.MulOpContext,i)


        def getRuleIndex(self):
            return AutolevParser.RULE_multiplicative

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMultiplicative" ):
                return visitor.visitMultiplicative(self)
            else:
                return visitor.visitChildren(self)




    def multiplicative(self):

        localctx = AutolevParser.MultiplicativeContext(self, self._ctx, self.state)
        self.enterRule(localctx, 60, self.RULE_multiplicative)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 308
            self.unary()
            self.state = 314
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 309
                self.mulOp()
                self.state = 310
                self.unary()
                self.state = 316
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MulOpContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def TIMES(self):
            return self.getToken(AutolevParser.TIMES, 0)

        def DIV(self):
            return self.getToken(AutolevParser.DIV, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_mulOp

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMulOp" ):
                return visitor.visitMulOp(self)
            else:
                return visitor.visitChildren(self)




    def mulOp(self):

        localctx = AutolevParser.MulOpContext(self, self._ctx, self.state)
        self.enterRule(localctx, 62, self.RULE_mulOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 317
            _la = self._input.LA(1)
            if not(_la==34 or _la==35):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class UnaryContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_unary

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class SignedContext(UnaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.UnaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def addOp(self):
            return self.getTypedRuleContext(AutolevParser.AddOpContext,0)

        def unary(self):
            return self.getTypedRuleContext(AutolevParser.UnaryContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSigned" ):
                return visitor.visitSigned(self)
            else:
                return visitor.visitChildren(self)


    class UnsignedContext(UnaryContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.UnaryContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def power(self):
            return self.getTypedRuleContext(AutolevParser.PowerContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitUnsigned" ):
                return visitor.visitUnsigned(self)
            else:
                return visitor.visitChildren(self)



    def unary(self):

        localctx = AutolevParser.UnaryContext(self, self._ctx, self.state)
        self.enterRule(localctx, 64, self.RULE_unary)
        try:
            self.state = 323
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [32, 33]:
                localctx = AutolevParser.SignedContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 319
                self.addOp()
                self.state = 320
                self.unary()
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 23, 38, 40]:
                localctx = AutolevParser.UnsignedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 322
                self.power()
                pass
            else:
                raise NoViableAltException(self)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class PowerContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def atom(self):
            return self.getTypedRuleContext(AutolevParser.AtomContext,0)


        def CARET(self):
            return self.getToken(AutolevParser.CARET, 0)

        def unary(self):
            return self.getTypedRuleContext(AutolevParser.UnaryContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_power

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitPower" ):
                return visitor.visitPower(self)
            else:
                return visitor.visitChildren(self)




    def power(self):

        localctx = AutolevParser.PowerContext(self, self._ctx, self.state)
        self.enterRule(localctx, 66, self.RULE_power)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 325
            self.atom()
            self.state = 328
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 326
                self.match(AutolevParser.CARET)
                self.state = 327
                self.unary()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class AtomContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_atom

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class SpecialContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ZEROVEC(self):
            return self.getToken(AutolevParser.ZEROVEC, 0)
        def UNITDYADIC(self):
            return self.getToken(AutolevParser.UNITDYADIC, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSpecial" ):
                return visitor.visitSpecial(self)
            else:
                return visitor.visitChildren(self)


    class CallContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)
        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)
        def argList(self):
            return self.getTypedRuleContext(AutolevParser.ArgListContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitCall" ):
                return visitor.visitCall(self)
            else:
                return visitor.visitChildren(self)


    class NumberContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitNumber" ):
                return visitor.visitNumber(self)
            else:
                return visitor.visitChildren(self)


    class ParensContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)
        def expr(self):
            return self.getTypedRuleContext(AutolevParser.ExprContext,0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitParens" ):
                return visitor.visitParens(self)
            else:
                return visitor.visitChildren(self)


    class StringContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def STRING(self):
            return self.getToken(AutolevParser.STRING, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitString" ):
                return visitor.visitString(self)
            else:
                return visitor.visitChildren(self)


    class IndexedNamesContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def indexBraces(self):
            return self.getTypedRuleContext(AutolevParser.IndexBracesContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexedNames" ):
                return visitor.visitIndexedNames(self)
            else:
                return visitor.visitChildren(self)


    class NameContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitName" ):
                return visitor.visitName(self)
            else:
                return visitor.visitChildren(self)


    class MatrixContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def matrixRow(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.MatrixRowContext)
            else:
                return self.getTypedRuleContext(AutolevParser.MatrixRowContext,i)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)
        def SEMI(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.SEMI)
            else:
                return self.getToken(AutolevParser.SEMI, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMatrix" ):
                return visitor.visitMatrix(self)
            else:
                return visitor.visitChildren(self)


    class ElementContext(AtomContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.AtomContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def exprList(self):
            return self.getTypedRuleContext(AutolevParser.ExprListContext,0)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitElement" ):
                return visitor.visitElement(self)
            else:
                return visitor.visitChildren(self)



    def atom(self):

        localctx = AutolevParser.AtomContext(self, self._ctx, self.state)
        self.enterRule(localctx, 68, self.RULE_atom)
        self._la = 0 # Token type
        try:
            self.state = 375
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,39,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.NumberContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 330
                self.match(AutolevParser.NUMBER)
                pass

            elif la_ == 2:
                localctx = AutolevParser.StringContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 331
                self.match(AutolevParser.STRING)
                pass

            elif la_ == 3:
                localctx = AutolevParser.SpecialContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 332
                _la = self._input.LA(1)
                if not(_la==18 or _la==19):
                    self._errHandler.recoverInline(self)
                else:
                    self._errHandler.reportMatch(self)
                    self.consume()
                pass

            elif la_ == 4:
                localctx = AutolevParser.CallContext(self, localctx)
                self.enterOuterAlt(localctx, 4)
                self.state = 333
                self.ident()
                self.state = 334
                self.match(AutolevParser.LPAREN)
                self.state = 336
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                    self.state = 335
                    self.argList()


                self.state = 338
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 5:
                localctx = AutolevParser.ElementContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 340
                self.ident()
                self.state = 341
                self.match(AutolevParser.LBRACK)
                self.state = 342
                self.exprList()
                self.state = 343
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 6:
                localctx = AutolevParser.IndexedNamesContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 345
                self.ident()
                self.state = 346
                self.indexBraces()
                self.state = 350
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 347
                    self.match(AutolevParser.PRIME)
                    self.state = 352
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 7:
                localctx = AutolevParser.NameContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 353
                self.ident()
                self.state = 357
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 354
                    self.match(AutolevParser.PRIME)
                    self.state = 359
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 8:
                localctx = AutolevParser.MatrixContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 360
                self.match(AutolevParser.LBRACK)
                self.state = 361
                self.matrixRow()
                self.state = 366
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==45:
                    self.state = 362
                    self.match(AutolevParser.SEMI)
                    self.state = 363
                    self.matrixRow()
                    self.state = 368
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 369
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 9:
                localctx = AutolevParser.ParensContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 371
                self.match(AutolevParser.LPAREN)
                self.state = 372
                self.expr()
                self.state = 373
                self.match(AutolevParser.RPAREN)
                pass


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class MatrixRowContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_matrixRow

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitMatrixRow" ):
                return visitor.visitMatrixRow(self)
            else:
                return visitor.visitChildren(self)




    def matrixRow(self):

        localctx = AutolevParser.MatrixRowContext(self, self._ctx, self.state)
        self.enterRule(localctx, 70, self.RULE_matrixRow)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 377
            self.expr()
            self.state = 382
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 378
                self.match(AutolevParser.COMMA)
                self.state = 379
                self.expr()
                self.state = 384
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ExprListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_exprList

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitExprList" ):
                return visitor.visitExprList(self)
            else:
                return visitor.visitChildren(self)




    def exprList(self):

        localctx = AutolevParser.ExprListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 72, self.RULE_exprList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 385
            self.expr()
            self.state = 390
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 386
                self.match(AutolevParser.COMMA)
                self.state = 387
                self.expr()
                self.state = 392
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgListContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def arg(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ArgContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ArgContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_argList

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArgList" ):
                return visitor.visitArgList(self)
            else:
                return visitor.visitChildren(self)




    def argList(self):

        localctx = AutolevParser.ArgListContext(self, self._ctx, self.state)
        self.enterRule(localctx, 74, self.RULE_argList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 393
            self.arg()
            self.state = 398
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 394
                self.match(AutolevParser.COMMA)
                self.state = 395
                self.arg()
                self.state = 400
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class ArgContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def expr(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.ExprContext)
            else:
                return self.getTypedRuleContext(AutolevParser.ExprContext,i)


        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)

        def COLON(self):
            return self.getToken(AutolevParser.COLON, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_arg

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitArg" ):
                return visitor.visitArg(self)
            else:
                return visitor.visitChildren(self)




    def arg(self):

        localctx = AutolevParser.ArgContext(self, self._ctx, self.state)
        self.enterRule(localctx, 76, self.RULE_arg)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 401
            self.expr()
            self.state = 404
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==31:
                self.state = 402
                self.match(AutolevParser.EQ)
                self.state = 403
                self.expr()


            self.state = 408
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 406
                self.match(AutolevParser.COLON)
                self.state = 407
                self.expr()


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IndexBracesContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def LBRACE(self):
            return self.getToken(AutolevParser.LBRACE, 0)

        def indexRange(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IndexRangeContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IndexRangeContext,i)


        def RBRACE(self):
            return self.getToken(AutolevParser.RBRACE, 0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def getRuleIndex(self):
            return AutolevParser.RULE_indexBraces

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexBraces" ):
                return visitor.visitIndexBraces(self)
            else:
                return visitor.visitChildren(self)




    def indexBraces(self):

        localctx = AutolevParser.IndexBracesContext(self, self._ctx, self.state)
        self.enterRule(localctx, 78, self.RULE_indexBraces)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 410
            self.match(AutolevParser.LBRACE)
            self.state = 411
            self.indexRange()
            self.state = 416
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 412
                self.match(AutolevParser.COMMA)
                self.state = 413
                self.indexRange()
                self.state = 418
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 419
            self.match(AutolevParser.RBRACE)
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IndexRangeContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def NUMBER(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.NUMBER)
            else:
                return self.getToken(AutolevParser.NUMBER, i)

        def COLON(self):
            return self.getToken(AutolevParser.COLON, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_indexRange

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIndexRange" ):
                return visitor.visitIndexRange(self)
            else:
                return visitor.visitChildren(self)




    def indexRange(self):

        localctx = AutolevParser.IndexRangeContext(self, self._ctx, self.state)
        self.enterRule(localctx, 80, self.RULE_indexRange)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 421
            self.match(AutolevParser.NUMBER)
            self.state = 424
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 422
                self.match(AutolevParser.COLON)
                self.state = 423
                self.match(AutolevParser.NUMBER)


        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class IdentContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def ID(self):
            return self.getToken(AutolevParser.ID, 0)

        def CONSTANTS(self):
            return self.getToken(AutolevParser.CONSTANTS, 0)

        def VARIABLES(self):
            return self.getToken(AutolevParser.VARIABLES, 0)

        def SPECIFIED(self):
            return self.getToken(AutolevParser.SPECIFIED, 0)

        def IMAGINARY(self):
            return self.getToken(AutolevParser.IMAGINARY, 0)

        def NEWTONIAN(self):
            return self.getToken(AutolevParser.NEWTONIAN, 0)

        def FRAMES(self):
            return self.getToken(AutolevParser.FRAMES, 0)

        def BODIES(self):
            return self.getToken(AutolevParser.BODIES, 0)

        def PARTICLES(self):
            return self.getToken(AutolevParser.PARTICLES, 0)

        def POINTS(self):
            return self.getToken(AutolevParser.POINTS, 0)

        def MASS(self):
            return self.getToken(AutolevParser.MASS, 0)

        def INERTIA(self):
            return self.getToken(AutolevParser.INERTIA, 0)

        def INPUT(self):
            return self.getToken(AutolevParser.INPUT, 0)

        def OUTPUT(self):
            return self.getToken(AutolevParser.OUTPUT, 0)

        def UNITSYSTEM(self):
            return self.getToken(AutolevParser.UNITSYSTEM, 0)

        def CODE(self):
            return self.getToken(AutolevParser.CODE, 0)

        def SAVE(self):
            return self.getToken(AutolevParser.SAVE, 0)

        def RUN(self):
            return self.getToken(AutolevParser.RUN, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_ident

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitIdent" ):
                return visitor.visitIdent(self)
            else:
                return visitor.visitChildren(self)




    def ident(self):

        localctx = AutolevParser.IdentContext(self, self._ctx, self.state)
        self.enterRule(localctx, 82, self.RULE_ident)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 426
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0)):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx





