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
        4,1,51,490,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,1,0,3,0,88,8,0,1,0,1,0,1,1,1,1,1,1,
        1,1,1,1,1,1,1,1,1,1,1,1,3,1,101,8,1,1,2,1,2,1,2,1,2,1,3,1,3,1,3,
        1,3,1,3,1,3,1,3,5,3,114,8,3,10,3,12,3,117,9,3,3,3,119,8,3,1,4,1,
        4,1,5,1,5,3,5,125,8,5,1,5,1,5,1,5,5,5,130,8,5,10,5,12,5,133,9,5,
        1,6,1,6,1,7,1,7,1,7,1,8,1,8,1,8,3,8,143,8,8,1,8,5,8,146,8,8,10,8,
        12,8,149,9,8,1,8,1,8,1,8,1,8,1,8,1,8,1,8,5,8,158,8,8,10,8,12,8,161,
        9,8,1,8,3,8,164,8,8,1,9,1,9,1,9,1,10,3,10,170,8,10,1,10,1,10,1,10,
        3,10,175,8,10,5,10,177,8,10,10,10,12,10,180,9,10,1,11,1,11,1,12,
        1,12,1,12,1,12,5,12,188,8,12,10,12,12,12,191,9,12,1,13,1,13,1,13,
        1,13,3,13,197,8,13,1,14,1,14,1,14,1,14,1,14,1,14,1,14,1,14,5,14,
        207,8,14,10,14,12,14,210,9,14,1,14,1,14,5,14,214,8,14,10,14,12,14,
        217,9,14,3,14,219,8,14,1,15,1,15,1,15,1,15,5,15,225,8,15,10,15,12,
        15,228,9,15,1,16,1,16,3,16,232,8,16,1,17,1,17,1,17,1,17,5,17,238,
        8,17,10,17,12,17,241,9,17,1,18,1,18,1,18,1,18,5,18,247,8,18,10,18,
        12,18,250,9,18,1,19,1,19,1,20,1,20,3,20,256,8,20,1,20,1,20,3,20,
        260,8,20,1,20,3,20,263,8,20,1,21,1,21,1,21,1,21,3,21,269,8,21,1,
        21,1,21,3,21,273,8,21,1,21,1,21,1,21,5,21,278,8,21,10,21,12,21,281,
        9,21,3,21,283,8,21,1,22,1,22,1,22,3,22,288,8,22,1,22,1,22,1,22,1,
        22,1,22,1,22,1,22,1,22,1,23,1,23,1,23,1,24,1,24,3,24,303,8,24,1,
        25,1,25,1,25,1,25,5,25,309,8,25,10,25,12,25,312,9,25,1,26,1,26,1,
        26,1,26,1,26,3,26,319,8,26,1,26,5,26,322,8,26,10,26,12,26,325,9,
        26,1,26,1,26,3,26,329,8,26,1,26,1,26,1,26,1,26,5,26,335,8,26,10,
        26,12,26,338,9,26,1,26,1,26,1,26,1,26,1,26,3,26,345,8,26,1,26,3,
        26,348,8,26,1,27,1,27,3,27,352,8,27,1,28,1,28,1,29,1,29,1,29,1,29,
        5,29,360,8,29,10,29,12,29,363,9,29,1,30,1,30,1,31,1,31,1,31,1,31,
        5,31,371,8,31,10,31,12,31,374,9,31,1,32,1,32,1,33,1,33,1,33,1,33,
        3,33,382,8,33,1,34,1,34,1,34,3,34,387,8,34,1,35,1,35,1,35,1,35,1,
        35,1,35,3,35,395,8,35,1,35,1,35,1,35,1,35,1,35,1,35,1,35,1,35,1,
        35,1,35,3,35,407,8,35,1,35,5,35,410,8,35,10,35,12,35,413,9,35,1,
        35,1,35,5,35,417,8,35,10,35,12,35,420,9,35,1,35,1,35,1,35,1,35,5,
        35,426,8,35,10,35,12,35,429,9,35,1,35,1,35,1,35,1,35,1,35,1,35,3,
        35,437,8,35,1,36,1,36,1,36,5,36,442,8,36,10,36,12,36,445,9,36,1,
        37,1,37,1,37,5,37,450,8,37,10,37,12,37,453,9,37,1,38,1,38,1,38,5,
        38,458,8,38,10,38,12,38,461,9,38,1,39,1,39,1,39,3,39,466,8,39,1,
        39,1,39,3,39,470,8,39,1,40,1,40,1,40,1,40,5,40,476,8,40,10,40,12,
        40,479,9,40,1,40,1,40,1,41,1,41,1,41,3,41,486,8,41,1,42,1,42,1,42,
        0,0,43,0,2,4,6,8,10,12,14,16,18,20,22,24,26,28,30,32,34,36,38,40,
        42,44,46,48,50,52,54,56,58,60,62,64,66,68,70,72,74,76,78,80,82,84,
        0,8,2,1,45,45,49,49,1,0,25,31,1,0,1,11,1,0,32,33,1,0,34,35,1,0,16,
        17,1,0,18,19,2,0,1,17,21,21,520,0,87,1,0,0,0,2,100,1,0,0,0,4,102,
        1,0,0,0,6,118,1,0,0,0,8,120,1,0,0,0,10,122,1,0,0,0,12,134,1,0,0,
        0,14,136,1,0,0,0,16,163,1,0,0,0,18,165,1,0,0,0,20,169,1,0,0,0,22,
        181,1,0,0,0,24,183,1,0,0,0,26,192,1,0,0,0,28,218,1,0,0,0,30,220,
        1,0,0,0,32,229,1,0,0,0,34,233,1,0,0,0,36,242,1,0,0,0,38,251,1,0,
        0,0,40,255,1,0,0,0,42,264,1,0,0,0,44,284,1,0,0,0,46,297,1,0,0,0,
        48,302,1,0,0,0,50,304,1,0,0,0,52,347,1,0,0,0,54,351,1,0,0,0,56,353,
        1,0,0,0,58,355,1,0,0,0,60,364,1,0,0,0,62,366,1,0,0,0,64,375,1,0,
        0,0,66,381,1,0,0,0,68,383,1,0,0,0,70,436,1,0,0,0,72,438,1,0,0,0,
        74,446,1,0,0,0,76,454,1,0,0,0,78,462,1,0,0,0,80,471,1,0,0,0,82,482,
        1,0,0,0,84,487,1,0,0,0,86,88,3,2,1,0,87,86,1,0,0,0,87,88,1,0,0,0,
        88,89,1,0,0,0,89,90,7,0,0,0,90,1,1,0,0,0,91,101,3,4,2,0,92,101,3,
        8,4,0,93,101,3,10,5,0,94,101,3,24,12,0,95,101,3,30,15,0,96,101,3,
        34,17,0,97,101,3,42,21,0,98,101,3,46,23,0,99,101,3,50,25,0,100,91,
        1,0,0,0,100,92,1,0,0,0,100,93,1,0,0,0,100,94,1,0,0,0,100,95,1,0,
        0,0,100,96,1,0,0,0,100,97,1,0,0,0,100,98,1,0,0,0,100,99,1,0,0,0,
        101,3,1,0,0,0,102,103,3,6,3,0,103,104,7,1,0,0,104,105,3,56,28,0,
        105,5,1,0,0,0,106,107,3,84,42,0,107,108,5,40,0,0,108,109,3,74,37,
        0,109,110,5,41,0,0,110,119,1,0,0,0,111,115,3,84,42,0,112,114,5,37,
        0,0,113,112,1,0,0,0,114,117,1,0,0,0,115,113,1,0,0,0,115,116,1,0,
        0,0,116,119,1,0,0,0,117,115,1,0,0,0,118,106,1,0,0,0,118,111,1,0,
        0,0,119,7,1,0,0,0,120,121,3,56,28,0,121,9,1,0,0,0,122,124,3,12,6,
        0,123,125,5,37,0,0,124,123,1,0,0,0,124,125,1,0,0,0,125,126,1,0,0,
        0,126,131,3,14,7,0,127,128,5,44,0,0,128,130,3,18,9,0,129,127,1,0,
        0,0,130,133,1,0,0,0,131,129,1,0,0,0,131,132,1,0,0,0,132,11,1,0,0,
        0,133,131,1,0,0,0,134,135,7,2,0,0,135,13,1,0,0,0,136,137,3,16,8,
        0,137,138,3,20,10,0,138,15,1,0,0,0,139,140,3,84,42,0,140,142,3,80,
        40,0,141,143,3,84,42,0,142,141,1,0,0,0,142,143,1,0,0,0,143,147,1,
        0,0,0,144,146,5,37,0,0,145,144,1,0,0,0,146,149,1,0,0,0,147,145,1,
        0,0,0,147,148,1,0,0,0,148,164,1,0,0,0,149,147,1,0,0,0,150,151,3,
        84,42,0,151,152,5,38,0,0,152,153,3,84,42,0,153,154,5,39,0,0,154,
        164,1,0,0,0,155,159,3,84,42,0,156,158,5,37,0,0,157,156,1,0,0,0,158,
        161,1,0,0,0,159,157,1,0,0,0,159,160,1,0,0,0,160,164,1,0,0,0,161,
        159,1,0,0,0,162,164,5,20,0,0,163,139,1,0,0,0,163,150,1,0,0,0,163,
        155,1,0,0,0,163,162,1,0,0,0,164,17,1,0,0,0,165,166,3,56,28,0,166,
        167,3,20,10,0,167,19,1,0,0,0,168,170,3,22,11,0,169,168,1,0,0,0,169,
        170,1,0,0,0,170,178,1,0,0,0,171,172,5,31,0,0,172,174,3,56,28,0,173,
        175,3,22,11,0,174,173,1,0,0,0,174,175,1,0,0,0,175,177,1,0,0,0,176,
        171,1,0,0,0,177,180,1,0,0,0,178,176,1,0,0,0,178,179,1,0,0,0,179,
        21,1,0,0,0,180,178,1,0,0,0,181,182,7,3,0,0,182,23,1,0,0,0,183,184,
        5,12,0,0,184,189,3,26,13,0,185,186,5,44,0,0,186,188,3,26,13,0,187,
        185,1,0,0,0,188,191,1,0,0,0,189,187,1,0,0,0,189,190,1,0,0,0,190,
        25,1,0,0,0,191,189,1,0,0,0,192,193,3,28,14,0,193,194,5,31,0,0,194,
        196,3,56,28,0,195,197,3,36,18,0,196,195,1,0,0,0,196,197,1,0,0,0,
        197,27,1,0,0,0,198,199,3,84,42,0,199,200,5,40,0,0,200,201,3,74,37,
        0,201,202,5,41,0,0,202,219,1,0,0,0,203,204,3,84,42,0,204,208,3,80,
        40,0,205,207,5,37,0,0,206,205,1,0,0,0,207,210,1,0,0,0,208,206,1,
        0,0,0,208,209,1,0,0,0,209,219,1,0,0,0,210,208,1,0,0,0,211,215,3,
        84,42,0,212,214,5,37,0,0,213,212,1,0,0,0,214,217,1,0,0,0,215,213,
        1,0,0,0,215,216,1,0,0,0,216,219,1,0,0,0,217,215,1,0,0,0,218,198,
        1,0,0,0,218,203,1,0,0,0,218,211,1,0,0,0,219,29,1,0,0,0,220,221,5,
        13,0,0,221,226,3,32,16,0,222,223,5,44,0,0,223,225,3,32,16,0,224,
        222,1,0,0,0,225,228,1,0,0,0,226,224,1,0,0,0,226,227,1,0,0,0,227,
        31,1,0,0,0,228,226,1,0,0,0,229,231,3,56,28,0,230,232,3,36,18,0,231,
        230,1,0,0,0,231,232,1,0,0,0,232,33,1,0,0,0,233,234,5,14,0,0,234,
        239,3,84,42,0,235,236,5,44,0,0,236,238,3,84,42,0,237,235,1,0,0,0,
        238,241,1,0,0,0,239,237,1,0,0,0,239,240,1,0,0,0,240,35,1,0,0,0,241,
        239,1,0,0,0,242,248,3,40,20,0,243,244,3,38,19,0,244,245,3,40,20,
        0,245,247,1,0,0,0,246,243,1,0,0,0,247,250,1,0,0,0,248,246,1,0,0,
        0,248,249,1,0,0,0,249,37,1,0,0,0,250,248,1,0,0,0,251,252,7,4,0,0,
        252,39,1,0,0,0,253,256,3,84,42,0,254,256,5,22,0,0,255,253,1,0,0,
        0,255,254,1,0,0,0,256,262,1,0,0,0,257,259,5,36,0,0,258,260,5,33,
        0,0,259,258,1,0,0,0,259,260,1,0,0,0,260,261,1,0,0,0,261,263,5,20,
        0,0,262,257,1,0,0,0,262,263,1,0,0,0,263,41,1,0,0,0,264,265,5,15,
        0,0,265,266,3,84,42,0,266,268,5,38,0,0,267,269,3,76,38,0,268,267,
        1,0,0,0,268,269,1,0,0,0,269,270,1,0,0,0,270,272,5,39,0,0,271,273,
        3,44,22,0,272,271,1,0,0,0,272,273,1,0,0,0,273,282,1,0,0,0,274,279,
        3,48,24,0,275,276,5,44,0,0,276,278,3,84,42,0,277,275,1,0,0,0,278,
        281,1,0,0,0,279,277,1,0,0,0,279,280,1,0,0,0,280,283,1,0,0,0,281,
        279,1,0,0,0,282,274,1,0,0,0,282,283,1,0,0,0,283,43,1,0,0,0,284,285,
        5,40,0,0,285,287,3,84,42,0,286,288,3,36,18,0,287,286,1,0,0,0,287,
        288,1,0,0,0,288,289,1,0,0,0,289,290,5,31,0,0,290,291,3,56,28,0,291,
        292,5,44,0,0,292,293,3,56,28,0,293,294,5,44,0,0,294,295,3,56,28,
        0,295,296,5,41,0,0,296,45,1,0,0,0,297,298,7,5,0,0,298,299,3,48,24,
        0,299,47,1,0,0,0,300,303,5,22,0,0,301,303,3,84,42,0,302,300,1,0,
        0,0,302,301,1,0,0,0,303,49,1,0,0,0,304,305,5,21,0,0,305,310,3,52,
        26,0,306,307,5,44,0,0,307,309,3,52,26,0,308,306,1,0,0,0,309,312,
        1,0,0,0,310,308,1,0,0,0,310,311,1,0,0,0,311,51,1,0,0,0,312,310,1,
        0,0,0,313,318,3,84,42,0,314,315,5,40,0,0,315,316,3,74,37,0,316,317,
        5,41,0,0,317,319,1,0,0,0,318,314,1,0,0,0,318,319,1,0,0,0,319,323,
        1,0,0,0,320,322,5,37,0,0,321,320,1,0,0,0,322,325,1,0,0,0,323,321,
        1,0,0,0,323,324,1,0,0,0,324,328,1,0,0,0,325,323,1,0,0,0,326,327,
        5,31,0,0,327,329,3,54,27,0,328,326,1,0,0,0,328,329,1,0,0,0,329,348,
        1,0,0,0,330,331,5,40,0,0,331,336,3,84,42,0,332,333,5,44,0,0,333,
        335,3,84,42,0,334,332,1,0,0,0,335,338,1,0,0,0,336,334,1,0,0,0,336,
        337,1,0,0,0,337,339,1,0,0,0,338,336,1,0,0,0,339,340,5,41,0,0,340,
        341,5,31,0,0,341,342,3,54,27,0,342,348,1,0,0,0,343,345,3,22,11,0,
        344,343,1,0,0,0,344,345,1,0,0,0,345,346,1,0,0,0,346,348,5,20,0,0,
        347,313,1,0,0,0,347,330,1,0,0,0,347,344,1,0,0,0,348,53,1,0,0,0,349,
        352,3,36,18,0,350,352,5,20,0,0,351,349,1,0,0,0,351,350,1,0,0,0,352,
        55,1,0,0,0,353,354,3,58,29,0,354,57,1,0,0,0,355,361,3,62,31,0,356,
        357,3,60,30,0,357,358,3,62,31,0,358,360,1,0,0,0,359,356,1,0,0,0,
        360,363,1,0,0,0,361,359,1,0,0,0,361,362,1,0,0,0,362,59,1,0,0,0,363,
        361,1,0,0,0,364,365,7,3,0,0,365,61,1,0,0,0,366,372,3,66,33,0,367,
        368,3,64,32,0,368,369,3,66,33,0,369,371,1,0,0,0,370,367,1,0,0,0,
        371,374,1,0,0,0,372,370,1,0,0,0,372,373,1,0,0,0,373,63,1,0,0,0,374,
        372,1,0,0,0,375,376,7,4,0,0,376,65,1,0,0,0,377,378,3,60,30,0,378,
        379,3,66,33,0,379,382,1,0,0,0,380,382,3,68,34,0,381,377,1,0,0,0,
        381,380,1,0,0,0,382,67,1,0,0,0,383,386,3,70,35,0,384,385,5,36,0,
        0,385,387,3,66,33,0,386,384,1,0,0,0,386,387,1,0,0,0,387,69,1,0,0,
        0,388,437,5,20,0,0,389,437,5,23,0,0,390,437,7,6,0,0,391,392,3,84,
        42,0,392,394,5,38,0,0,393,395,3,76,38,0,394,393,1,0,0,0,394,395,
        1,0,0,0,395,396,1,0,0,0,396,397,5,39,0,0,397,437,1,0,0,0,398,399,
        3,84,42,0,399,400,5,40,0,0,400,401,3,74,37,0,401,402,5,41,0,0,402,
        437,1,0,0,0,403,404,3,84,42,0,404,406,3,80,40,0,405,407,3,84,42,
        0,406,405,1,0,0,0,406,407,1,0,0,0,407,411,1,0,0,0,408,410,5,37,0,
        0,409,408,1,0,0,0,410,413,1,0,0,0,411,409,1,0,0,0,411,412,1,0,0,
        0,412,437,1,0,0,0,413,411,1,0,0,0,414,418,3,84,42,0,415,417,5,37,
        0,0,416,415,1,0,0,0,417,420,1,0,0,0,418,416,1,0,0,0,418,419,1,0,
        0,0,419,437,1,0,0,0,420,418,1,0,0,0,421,422,5,40,0,0,422,427,3,72,
        36,0,423,424,5,45,0,0,424,426,3,72,36,0,425,423,1,0,0,0,426,429,
        1,0,0,0,427,425,1,0,0,0,427,428,1,0,0,0,428,430,1,0,0,0,429,427,
        1,0,0,0,430,431,5,41,0,0,431,437,1,0,0,0,432,433,5,38,0,0,433,434,
        3,56,28,0,434,435,5,39,0,0,435,437,1,0,0,0,436,388,1,0,0,0,436,389,
        1,0,0,0,436,390,1,0,0,0,436,391,1,0,0,0,436,398,1,0,0,0,436,403,
        1,0,0,0,436,414,1,0,0,0,436,421,1,0,0,0,436,432,1,0,0,0,437,71,1,
        0,0,0,438,443,3,56,28,0,439,440,5,44,0,0,440,442,3,56,28,0,441,439,
        1,0,0,0,442,445,1,0,0,0,443,441,1,0,0,0,443,444,1,0,0,0,444,73,1,
        0,0,0,445,443,1,0,0,0,446,451,3,56,28,0,447,448,5,44,0,0,448,450,
        3,56,28,0,449,447,1,0,0,0,450,453,1,0,0,0,451,449,1,0,0,0,451,452,
        1,0,0,0,452,75,1,0,0,0,453,451,1,0,0,0,454,459,3,78,39,0,455,456,
        5,44,0,0,456,458,3,78,39,0,457,455,1,0,0,0,458,461,1,0,0,0,459,457,
        1,0,0,0,459,460,1,0,0,0,460,77,1,0,0,0,461,459,1,0,0,0,462,465,3,
        56,28,0,463,464,5,31,0,0,464,466,3,56,28,0,465,463,1,0,0,0,465,466,
        1,0,0,0,466,469,1,0,0,0,467,468,5,46,0,0,468,470,3,56,28,0,469,467,
        1,0,0,0,469,470,1,0,0,0,470,79,1,0,0,0,471,472,5,42,0,0,472,477,
        3,82,41,0,473,474,5,44,0,0,474,476,3,82,41,0,475,473,1,0,0,0,476,
        479,1,0,0,0,477,475,1,0,0,0,477,478,1,0,0,0,478,480,1,0,0,0,479,
        477,1,0,0,0,480,481,5,43,0,0,481,81,1,0,0,0,482,485,5,20,0,0,483,
        484,5,46,0,0,484,486,5,20,0,0,485,483,1,0,0,0,485,486,1,0,0,0,486,
        83,1,0,0,0,487,488,7,7,0,0,488,85,1,0,0,0,56,87,100,115,118,124,
        131,142,147,159,163,169,174,178,189,196,208,215,218,226,231,239,
        248,255,259,262,268,272,279,282,287,302,310,318,323,328,336,344,
        347,351,361,372,381,386,394,406,411,418,427,436,443,451,459,465,
        469,477,485
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
                     "','", "';'", "':'", "'&'" ]

    symbolicNames = [ "<INVALID>", "CONSTANTS", "VARIABLES", "SPECIFIED", 
                      "IMAGINARY", "NEWTONIAN", "FRAMES", "BODIES", "PARTICLES", 
                      "POINTS", "MASS", "INERTIA", "INPUT", "OUTPUT", "UNITSYSTEM", 
                      "CODE", "SAVE", "RUN", "ZEROVEC", "UNITDYADIC", "NUMBER", 
                      "ID", "FILENAME", "STRING", "UNTERMINATED_STRING", 
                      "COLONEQ", "PLUSEQ", "MINUSEQ", "TIMESEQ", "DIVEQ", 
                      "POWEQ", "EQ", "PLUS", "MINUS", "TIMES", "DIV", "CARET", 
                      "PRIME", "LPAREN", "RPAREN", "LBRACK", "RBRACK", "LBRACE", 
                      "RBRACE", "COMMA", "SEMI", "COLON", "AMP", "COMMENT", 
                      "NEWLINE", "WS", "ERRCHAR" ]

    RULE_statement = 0
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
    RULE_settingArg = 26
    RULE_settingWord = 27
    RULE_expr = 28
    RULE_additive = 29
    RULE_addOp = 30
    RULE_multiplicative = 31
    RULE_mulOp = 32
    RULE_unary = 33
    RULE_power = 34
    RULE_atom = 35
    RULE_matrixRow = 36
    RULE_exprList = 37
    RULE_argList = 38
    RULE_arg = 39
    RULE_indexBraces = 40
    RULE_indexRange = 41
    RULE_ident = 42

    ruleNames =  [ "statement", "stmt", "assignment", "lvalue", "exprStmt", 
                   "declaration", "declKeyword", "firstDeclItem", "declHead", 
                   "declItem", "declTail", "sign", "inputStmt", "inputItem", 
                   "inputTarget", "outputStmt", "outputItem", "unitSystemStmt", 
                   "unit", "unitOp", "unitFactor", "codeStmt", "sweep", 
                   "fileCommand", "fileName", "setting", "settingArg", "settingWord", 
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
    AMP=47
    COMMENT=48
    NEWLINE=49
    WS=50
    ERRCHAR=51

    def __init__(self, input:TokenStream, output:TextIO = sys.stdout):
        super().__init__(input, output)
        self.checkVersion("4.13.2")
        self._interp = ParserATNSimulator(self, self.atn, self.decisionsToDFA, self.sharedContextCache)
        self._predicates = None




    class StatementContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def NEWLINE(self):
            return self.getToken(AutolevParser.NEWLINE, 0)

        def SEMI(self):
            return self.getToken(AutolevParser.SEMI, 0)

        def EOF(self):
            return self.getToken(AutolevParser.EOF, 0)

        def stmt(self):
            return self.getTypedRuleContext(AutolevParser.StmtContext,0)


        def getRuleIndex(self):
            return AutolevParser.RULE_statement

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitStatement" ):
                return visitor.visitStatement(self)
            else:
                return visitor.visitChildren(self)




    def statement(self):

        localctx = AutolevParser.StatementContext(self, self._ctx, self.state)
        self.enterRule(localctx, 0, self.RULE_statement)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 87
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 86
                self.stmt()


            self.state = 89
            _la = self._input.LA(1)
            if not(((((_la - -1)) & ~0x3f) == 0 and ((1 << (_la - -1)) & 1196268651020289) != 0)):
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
            self.state = 100
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,1,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 91
                self.assignment()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 92
                self.exprStmt()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 93
                self.declaration()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 94
                self.inputStmt()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 95
                self.outputStmt()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 96
                self.unitSystemStmt()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 97
                self.codeStmt()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 98
                self.fileCommand()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 99
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
            self.state = 102
            self.lvalue()
            self.state = 103
            localctx.op = self._input.LT(1)
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 4261412864) != 0)):
                localctx.op = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 104
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
            self.state = 118
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,3,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.ElementTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 106
                self.ident()
                self.state = 107
                self.match(AutolevParser.LBRACK)
                self.state = 108
                self.exprList()
                self.state = 109
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.NameTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 111
                self.ident()
                self.state = 115
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 112
                    self.match(AutolevParser.PRIME)
                    self.state = 117
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
            self.state = 120
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
            self.state = 122
            self.declKeyword()
            self.state = 124
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==37:
                self.state = 123
                self.match(AutolevParser.PRIME)


            self.state = 126
            self.firstDeclItem()
            self.state = 131
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 127
                self.match(AutolevParser.COMMA)
                self.state = 128
                self.declItem()
                self.state = 133
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
            self.state = 134
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
            self.state = 136
            self.declHead()
            self.state = 137
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
            self.suffix = None # IdentContext
            self.basis = None # IdentContext

        def ident(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IdentContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IdentContext,i)


        def indexBraces(self):
            return self.getTypedRuleContext(AutolevParser.IndexBracesContext,0)


        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)

        def LPAREN(self):
            return self.getToken(AutolevParser.LPAREN, 0)

        def RPAREN(self):
            return self.getToken(AutolevParser.RPAREN, 0)

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
            self.state = 163
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,9,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 139
                self.ident()
                self.state = 140
                self.indexBraces()
                self.state = 142
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0):
                    self.state = 141
                    localctx.suffix = self.ident()


                self.state = 147
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 144
                    self.match(AutolevParser.PRIME)
                    self.state = 149
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 150
                self.ident()
                self.state = 151
                self.match(AutolevParser.LPAREN)
                self.state = 152
                localctx.basis = self.ident()
                self.state = 153
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 155
                self.ident()
                self.state = 159
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 156
                    self.match(AutolevParser.PRIME)
                    self.state = 161
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 162
                self.match(AutolevParser.NUMBER)
                pass


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
            self.state = 165
            self.expr()
            self.state = 166
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
            self.state = 169
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==32 or _la==33:
                self.state = 168
                self.sign()


            self.state = 178
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==31:
                self.state = 171
                self.match(AutolevParser.EQ)
                self.state = 172
                self.expr()
                self.state = 174
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==32 or _la==33:
                    self.state = 173
                    self.sign()


                self.state = 180
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
            self.state = 181
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
            self.state = 183
            self.match(AutolevParser.INPUT)
            self.state = 184
            self.inputItem()
            self.state = 189
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 185
                self.match(AutolevParser.COMMA)
                self.state = 186
                self.inputItem()
                self.state = 191
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
            self.state = 192
            self.inputTarget()
            self.state = 193
            self.match(AutolevParser.EQ)
            self.state = 194
            self.expr()
            self.state = 196
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 195
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
            self.state = 218
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,17,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.InputElementContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 198
                self.ident()
                self.state = 199
                self.match(AutolevParser.LBRACK)
                self.state = 200
                self.exprList()
                self.state = 201
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.InputIndexedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 203
                self.ident()
                self.state = 204
                self.indexBraces()
                self.state = 208
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 205
                    self.match(AutolevParser.PRIME)
                    self.state = 210
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 3:
                localctx = AutolevParser.InputNameContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 211
                self.ident()
                self.state = 215
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 212
                    self.match(AutolevParser.PRIME)
                    self.state = 217
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
            self.state = 220
            self.match(AutolevParser.OUTPUT)
            self.state = 221
            self.outputItem()
            self.state = 226
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 222
                self.match(AutolevParser.COMMA)
                self.state = 223
                self.outputItem()
                self.state = 228
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
            self.state = 229
            self.expr()
            self.state = 231
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 230
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
            self.state = 233
            self.match(AutolevParser.UNITSYSTEM)
            self.state = 234
            self.ident()
            self.state = 239
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 235
                self.match(AutolevParser.COMMA)
                self.state = 236
                self.ident()
                self.state = 241
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
            self.state = 242
            self.unitFactor()
            self.state = 248
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 243
                self.unitOp()
                self.state = 244
                self.unitFactor()
                self.state = 250
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
            self.state = 251
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


        def FILENAME(self):
            return self.getToken(AutolevParser.FILENAME, 0)

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
            self.state = 255
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.state = 253
                self.ident()
                pass
            elif token in [22]:
                self.state = 254
                self.match(AutolevParser.FILENAME)
                pass
            else:
                raise NoViableAltException(self)

            self.state = 262
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 257
                self.match(AutolevParser.CARET)
                self.state = 259
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==33:
                    self.state = 258
                    self.match(AutolevParser.MINUS)


                self.state = 261
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

        def ident(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IdentContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IdentContext,i)


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


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

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
            self.state = 264
            self.match(AutolevParser.CODE)
            self.state = 265
            self.ident()
            self.state = 266
            self.match(AutolevParser.LPAREN)
            self.state = 268
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 267
                self.argList()


            self.state = 270
            self.match(AutolevParser.RPAREN)
            self.state = 272
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 271
                self.sweep()


            self.state = 282
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 274
                self.fileName()
                self.state = 279
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==44:
                    self.state = 275
                    self.match(AutolevParser.COMMA)
                    self.state = 276
                    self.ident()
                    self.state = 281
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)



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
            self.state = 284
            self.match(AutolevParser.LBRACK)
            self.state = 285
            self.ident()
            self.state = 287
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 286
                self.unit()


            self.state = 289
            self.match(AutolevParser.EQ)
            self.state = 290
            self.expr()
            self.state = 291
            self.match(AutolevParser.COMMA)
            self.state = 292
            self.expr()
            self.state = 293
            self.match(AutolevParser.COMMA)
            self.state = 294
            self.expr()
            self.state = 295
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
            self.state = 297
            _la = self._input.LA(1)
            if not(_la==16 or _la==17):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 298
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
            self.state = 302
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [22]:
                self.enterOuterAlt(localctx, 1)
                self.state = 300
                self.match(AutolevParser.FILENAME)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.enterOuterAlt(localctx, 2)
                self.state = 301
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

        def settingArg(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.SettingArgContext)
            else:
                return self.getTypedRuleContext(AutolevParser.SettingArgContext,i)


        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

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
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 304
            self.match(AutolevParser.ID)
            self.state = 305
            self.settingArg()
            self.state = 310
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 306
                self.match(AutolevParser.COMMA)
                self.state = 307
                self.settingArg()
                self.state = 312
                self._errHandler.sync(self)
                _la = self._input.LA(1)

        except RecognitionException as re:
            localctx.exception = re
            self._errHandler.reportError(self, re)
            self._errHandler.recover(self, re)
        finally:
            self.exitRule()
        return localctx


    class SettingArgContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser


        def getRuleIndex(self):
            return AutolevParser.RULE_settingArg

     
        def copyFrom(self, ctx:ParserRuleContext):
            super().copyFrom(ctx)



    class SettingGroupContext(SettingArgContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.SettingArgContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def LBRACK(self):
            return self.getToken(AutolevParser.LBRACK, 0)
        def ident(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IdentContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IdentContext,i)

        def RBRACK(self):
            return self.getToken(AutolevParser.RBRACK, 0)
        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)
        def settingWord(self):
            return self.getTypedRuleContext(AutolevParser.SettingWordContext,0)

        def COMMA(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.COMMA)
            else:
                return self.getToken(AutolevParser.COMMA, i)

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingGroup" ):
                return visitor.visitSettingGroup(self)
            else:
                return visitor.visitChildren(self)


    class SettingNumberContext(SettingArgContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.SettingArgContext
            super().__init__(parser)
            self.copyFrom(ctx)

        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)
        def sign(self):
            return self.getTypedRuleContext(AutolevParser.SignContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingNumber" ):
                return visitor.visitSettingNumber(self)
            else:
                return visitor.visitChildren(self)


    class SettingNameContext(SettingArgContext):

        def __init__(self, parser, ctx:ParserRuleContext): # actually a AutolevParser.SettingArgContext
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
        def PRIME(self, i:int=None):
            if i is None:
                return self.getTokens(AutolevParser.PRIME)
            else:
                return self.getToken(AutolevParser.PRIME, i)
        def EQ(self):
            return self.getToken(AutolevParser.EQ, 0)
        def settingWord(self):
            return self.getTypedRuleContext(AutolevParser.SettingWordContext,0)


        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingName" ):
                return visitor.visitSettingName(self)
            else:
                return visitor.visitChildren(self)



    def settingArg(self):

        localctx = AutolevParser.SettingArgContext(self, self._ctx, self.state)
        self.enterRule(localctx, 52, self.RULE_settingArg)
        self._la = 0 # Token type
        try:
            self.state = 347
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                localctx = AutolevParser.SettingNameContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 313
                self.ident()
                self.state = 318
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==40:
                    self.state = 314
                    self.match(AutolevParser.LBRACK)
                    self.state = 315
                    self.exprList()
                    self.state = 316
                    self.match(AutolevParser.RBRACK)


                self.state = 323
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 320
                    self.match(AutolevParser.PRIME)
                    self.state = 325
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 328
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==31:
                    self.state = 326
                    self.match(AutolevParser.EQ)
                    self.state = 327
                    self.settingWord()


                pass
            elif token in [40]:
                localctx = AutolevParser.SettingGroupContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 330
                self.match(AutolevParser.LBRACK)
                self.state = 331
                self.ident()
                self.state = 336
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==44:
                    self.state = 332
                    self.match(AutolevParser.COMMA)
                    self.state = 333
                    self.ident()
                    self.state = 338
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 339
                self.match(AutolevParser.RBRACK)
                self.state = 340
                self.match(AutolevParser.EQ)
                self.state = 341
                self.settingWord()
                pass
            elif token in [20, 32, 33]:
                localctx = AutolevParser.SettingNumberContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 344
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==32 or _la==33:
                    self.state = 343
                    self.sign()


                self.state = 346
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


    class SettingWordContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def unit(self):
            return self.getTypedRuleContext(AutolevParser.UnitContext,0)


        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_settingWord

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitSettingWord" ):
                return visitor.visitSettingWord(self)
            else:
                return visitor.visitChildren(self)




    def settingWord(self):

        localctx = AutolevParser.SettingWordContext(self, self._ctx, self.state)
        self.enterRule(localctx, 54, self.RULE_settingWord)
        try:
            self.state = 351
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21, 22]:
                self.enterOuterAlt(localctx, 1)
                self.state = 349
                self.unit()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 350
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
        self.enterRule(localctx, 56, self.RULE_expr)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 353
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
        self.enterRule(localctx, 58, self.RULE_additive)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 355
            self.multiplicative()
            self.state = 361
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,39,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 356
                    self.addOp()
                    self.state = 357
                    self.multiplicative() 
                self.state = 363
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,39,self._ctx)

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
        self.enterRule(localctx, 60, self.RULE_addOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 364
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
        self.enterRule(localctx, 62, self.RULE_multiplicative)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 366
            self.unary()
            self.state = 372
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 367
                self.mulOp()
                self.state = 368
                self.unary()
                self.state = 374
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
        self.enterRule(localctx, 64, self.RULE_mulOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 375
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
        self.enterRule(localctx, 66, self.RULE_unary)
        try:
            self.state = 381
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [32, 33]:
                localctx = AutolevParser.SignedContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 377
                self.addOp()
                self.state = 378
                self.unary()
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 23, 38, 40]:
                localctx = AutolevParser.UnsignedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 380
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
        self.enterRule(localctx, 68, self.RULE_power)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 383
            self.atom()
            self.state = 386
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 384
                self.match(AutolevParser.CARET)
                self.state = 385
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
            self.suffix = None # IdentContext
            self.copyFrom(ctx)

        def ident(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.IdentContext)
            else:
                return self.getTypedRuleContext(AutolevParser.IdentContext,i)

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
        self.enterRule(localctx, 70, self.RULE_atom)
        self._la = 0 # Token type
        try:
            self.state = 436
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,48,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.NumberContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 388
                self.match(AutolevParser.NUMBER)
                pass

            elif la_ == 2:
                localctx = AutolevParser.StringContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 389
                self.match(AutolevParser.STRING)
                pass

            elif la_ == 3:
                localctx = AutolevParser.SpecialContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 390
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
                self.state = 391
                self.ident()
                self.state = 392
                self.match(AutolevParser.LPAREN)
                self.state = 394
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                    self.state = 393
                    self.argList()


                self.state = 396
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 5:
                localctx = AutolevParser.ElementContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 398
                self.ident()
                self.state = 399
                self.match(AutolevParser.LBRACK)
                self.state = 400
                self.exprList()
                self.state = 401
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 6:
                localctx = AutolevParser.IndexedNamesContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 403
                self.ident()
                self.state = 404
                self.indexBraces()
                self.state = 406
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,44,self._ctx)
                if la_ == 1:
                    self.state = 405
                    localctx.suffix = self.ident()


                self.state = 411
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 408
                    self.match(AutolevParser.PRIME)
                    self.state = 413
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 7:
                localctx = AutolevParser.NameContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 414
                self.ident()
                self.state = 418
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 415
                    self.match(AutolevParser.PRIME)
                    self.state = 420
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 8:
                localctx = AutolevParser.MatrixContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 421
                self.match(AutolevParser.LBRACK)
                self.state = 422
                self.matrixRow()
                self.state = 427
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==45:
                    self.state = 423
                    self.match(AutolevParser.SEMI)
                    self.state = 424
                    self.matrixRow()
                    self.state = 429
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 430
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 9:
                localctx = AutolevParser.ParensContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 432
                self.match(AutolevParser.LPAREN)
                self.state = 433
                self.expr()
                self.state = 434
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
        self.enterRule(localctx, 72, self.RULE_matrixRow)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 438
            self.expr()
            self.state = 443
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 439
                self.match(AutolevParser.COMMA)
                self.state = 440
                self.expr()
                self.state = 445
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
        self.enterRule(localctx, 74, self.RULE_exprList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 446
            self.expr()
            self.state = 451
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 447
                self.match(AutolevParser.COMMA)
                self.state = 448
                self.expr()
                self.state = 453
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
        self.enterRule(localctx, 76, self.RULE_argList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 454
            self.arg()
            self.state = 459
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 455
                self.match(AutolevParser.COMMA)
                self.state = 456
                self.arg()
                self.state = 461
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
        self.enterRule(localctx, 78, self.RULE_arg)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 462
            self.expr()
            self.state = 465
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==31:
                self.state = 463
                self.match(AutolevParser.EQ)
                self.state = 464
                self.expr()


            self.state = 469
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 467
                self.match(AutolevParser.COLON)
                self.state = 468
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
        self.enterRule(localctx, 80, self.RULE_indexBraces)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 471
            self.match(AutolevParser.LBRACE)
            self.state = 472
            self.indexRange()
            self.state = 477
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 473
                self.match(AutolevParser.COMMA)
                self.state = 474
                self.indexRange()
                self.state = 479
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 480
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
        self.enterRule(localctx, 82, self.RULE_indexRange)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 482
            self.match(AutolevParser.NUMBER)
            self.state = 485
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 483
                self.match(AutolevParser.COLON)
                self.state = 484
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
        self.enterRule(localctx, 84, self.RULE_ident)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 487
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





