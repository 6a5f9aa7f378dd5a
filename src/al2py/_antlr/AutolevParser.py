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
        4,1,51,506,2,0,7,0,2,1,7,1,2,2,7,2,2,3,7,3,2,4,7,4,2,5,7,5,2,6,7,
        6,2,7,7,7,2,8,7,8,2,9,7,9,2,10,7,10,2,11,7,11,2,12,7,12,2,13,7,13,
        2,14,7,14,2,15,7,15,2,16,7,16,2,17,7,17,2,18,7,18,2,19,7,19,2,20,
        7,20,2,21,7,21,2,22,7,22,2,23,7,23,2,24,7,24,2,25,7,25,2,26,7,26,
        2,27,7,27,2,28,7,28,2,29,7,29,2,30,7,30,2,31,7,31,2,32,7,32,2,33,
        7,33,2,34,7,34,2,35,7,35,2,36,7,36,2,37,7,37,2,38,7,38,2,39,7,39,
        2,40,7,40,2,41,7,41,2,42,7,42,2,43,7,43,1,0,3,0,90,8,0,1,0,1,0,1,
        1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,3,1,103,8,1,1,2,1,2,1,2,1,2,1,
        3,1,3,1,3,1,3,1,3,1,3,1,3,5,3,116,8,3,10,3,12,3,119,9,3,3,3,121,
        8,3,1,4,1,4,1,5,1,5,3,5,127,8,5,1,5,1,5,1,5,5,5,132,8,5,10,5,12,
        5,135,9,5,1,6,1,6,1,7,1,7,1,7,1,8,1,8,1,8,3,8,145,8,8,1,8,5,8,148,
        8,8,10,8,12,8,151,9,8,1,8,1,8,1,8,1,8,1,8,1,8,1,8,5,8,160,8,8,10,
        8,12,8,163,9,8,1,8,3,8,166,8,8,1,9,1,9,1,9,1,10,3,10,172,8,10,1,
        10,1,10,1,10,3,10,177,8,10,5,10,179,8,10,10,10,12,10,182,9,10,1,
        11,1,11,1,12,1,12,1,12,1,12,5,12,190,8,12,10,12,12,12,193,9,12,1,
        13,1,13,1,13,1,13,3,13,199,8,13,1,14,1,14,1,14,1,14,1,14,1,14,1,
        14,1,14,5,14,209,8,14,10,14,12,14,212,9,14,1,14,1,14,5,14,216,8,
        14,10,14,12,14,219,9,14,3,14,221,8,14,1,15,1,15,1,15,1,15,5,15,227,
        8,15,10,15,12,15,230,9,15,1,16,1,16,3,16,234,8,16,1,17,1,17,1,17,
        1,17,5,17,240,8,17,10,17,12,17,243,9,17,1,18,1,18,1,18,1,18,5,18,
        249,8,18,10,18,12,18,252,9,18,1,19,1,19,1,20,1,20,3,20,258,8,20,
        1,20,1,20,3,20,262,8,20,1,20,3,20,265,8,20,1,21,1,21,1,21,1,21,3,
        21,271,8,21,1,21,1,21,3,21,275,8,21,1,21,1,21,1,21,5,21,280,8,21,
        10,21,12,21,283,9,21,3,21,285,8,21,1,22,1,22,1,22,3,22,290,8,22,
        1,22,1,22,1,22,1,22,1,22,1,22,1,22,1,22,1,23,1,23,1,23,1,24,5,24,
        304,8,24,10,24,12,24,307,9,24,1,24,1,24,3,24,311,8,24,1,25,1,25,
        1,25,1,25,1,25,1,25,3,25,319,8,25,1,26,1,26,1,26,1,26,5,26,325,8,
        26,10,26,12,26,328,9,26,1,27,1,27,1,27,1,27,1,27,3,27,335,8,27,1,
        27,5,27,338,8,27,10,27,12,27,341,9,27,1,27,1,27,3,27,345,8,27,1,
        27,1,27,1,27,1,27,5,27,351,8,27,10,27,12,27,354,9,27,1,27,1,27,1,
        27,1,27,1,27,3,27,361,8,27,1,27,3,27,364,8,27,1,28,1,28,3,28,368,
        8,28,1,29,1,29,1,30,1,30,1,30,1,30,5,30,376,8,30,10,30,12,30,379,
        9,30,1,31,1,31,1,32,1,32,1,32,1,32,5,32,387,8,32,10,32,12,32,390,
        9,32,1,33,1,33,1,34,1,34,1,34,1,34,3,34,398,8,34,1,35,1,35,1,35,
        3,35,403,8,35,1,36,1,36,1,36,1,36,1,36,1,36,3,36,411,8,36,1,36,1,
        36,1,36,1,36,1,36,1,36,1,36,1,36,1,36,1,36,3,36,423,8,36,1,36,5,
        36,426,8,36,10,36,12,36,429,9,36,1,36,1,36,5,36,433,8,36,10,36,12,
        36,436,9,36,1,36,1,36,1,36,1,36,5,36,442,8,36,10,36,12,36,445,9,
        36,1,36,1,36,1,36,1,36,1,36,1,36,3,36,453,8,36,1,37,1,37,1,37,5,
        37,458,8,37,10,37,12,37,461,9,37,1,38,1,38,1,38,5,38,466,8,38,10,
        38,12,38,469,9,38,1,39,1,39,1,39,5,39,474,8,39,10,39,12,39,477,9,
        39,1,40,1,40,1,40,3,40,482,8,40,1,40,1,40,3,40,486,8,40,1,41,1,41,
        1,41,1,41,5,41,492,8,41,10,41,12,41,495,9,41,1,41,1,41,1,42,1,42,
        1,42,3,42,502,8,42,1,43,1,43,1,43,0,0,44,0,2,4,6,8,10,12,14,16,18,
        20,22,24,26,28,30,32,34,36,38,40,42,44,46,48,50,52,54,56,58,60,62,
        64,66,68,70,72,74,76,78,80,82,84,86,0,8,2,1,45,45,49,49,1,0,25,31,
        1,0,1,11,1,0,32,33,1,0,34,35,1,0,16,17,1,0,18,19,2,0,1,17,21,21,
        541,0,89,1,0,0,0,2,102,1,0,0,0,4,104,1,0,0,0,6,120,1,0,0,0,8,122,
        1,0,0,0,10,124,1,0,0,0,12,136,1,0,0,0,14,138,1,0,0,0,16,165,1,0,
        0,0,18,167,1,0,0,0,20,171,1,0,0,0,22,183,1,0,0,0,24,185,1,0,0,0,
        26,194,1,0,0,0,28,220,1,0,0,0,30,222,1,0,0,0,32,231,1,0,0,0,34,235,
        1,0,0,0,36,244,1,0,0,0,38,253,1,0,0,0,40,257,1,0,0,0,42,266,1,0,
        0,0,44,286,1,0,0,0,46,299,1,0,0,0,48,305,1,0,0,0,50,318,1,0,0,0,
        52,320,1,0,0,0,54,363,1,0,0,0,56,367,1,0,0,0,58,369,1,0,0,0,60,371,
        1,0,0,0,62,380,1,0,0,0,64,382,1,0,0,0,66,391,1,0,0,0,68,397,1,0,
        0,0,70,399,1,0,0,0,72,452,1,0,0,0,74,454,1,0,0,0,76,462,1,0,0,0,
        78,470,1,0,0,0,80,478,1,0,0,0,82,487,1,0,0,0,84,498,1,0,0,0,86,503,
        1,0,0,0,88,90,3,2,1,0,89,88,1,0,0,0,89,90,1,0,0,0,90,91,1,0,0,0,
        91,92,7,0,0,0,92,1,1,0,0,0,93,103,3,4,2,0,94,103,3,8,4,0,95,103,
        3,10,5,0,96,103,3,24,12,0,97,103,3,30,15,0,98,103,3,34,17,0,99,103,
        3,42,21,0,100,103,3,46,23,0,101,103,3,52,26,0,102,93,1,0,0,0,102,
        94,1,0,0,0,102,95,1,0,0,0,102,96,1,0,0,0,102,97,1,0,0,0,102,98,1,
        0,0,0,102,99,1,0,0,0,102,100,1,0,0,0,102,101,1,0,0,0,103,3,1,0,0,
        0,104,105,3,6,3,0,105,106,7,1,0,0,106,107,3,58,29,0,107,5,1,0,0,
        0,108,109,3,86,43,0,109,110,5,40,0,0,110,111,3,76,38,0,111,112,5,
        41,0,0,112,121,1,0,0,0,113,117,3,86,43,0,114,116,5,37,0,0,115,114,
        1,0,0,0,116,119,1,0,0,0,117,115,1,0,0,0,117,118,1,0,0,0,118,121,
        1,0,0,0,119,117,1,0,0,0,120,108,1,0,0,0,120,113,1,0,0,0,121,7,1,
        0,0,0,122,123,3,58,29,0,123,9,1,0,0,0,124,126,3,12,6,0,125,127,5,
        37,0,0,126,125,1,0,0,0,126,127,1,0,0,0,127,128,1,0,0,0,128,133,3,
        14,7,0,129,130,5,44,0,0,130,132,3,18,9,0,131,129,1,0,0,0,132,135,
        1,0,0,0,133,131,1,0,0,0,133,134,1,0,0,0,134,11,1,0,0,0,135,133,1,
        0,0,0,136,137,7,2,0,0,137,13,1,0,0,0,138,139,3,16,8,0,139,140,3,
        20,10,0,140,15,1,0,0,0,141,142,3,86,43,0,142,144,3,82,41,0,143,145,
        3,86,43,0,144,143,1,0,0,0,144,145,1,0,0,0,145,149,1,0,0,0,146,148,
        5,37,0,0,147,146,1,0,0,0,148,151,1,0,0,0,149,147,1,0,0,0,149,150,
        1,0,0,0,150,166,1,0,0,0,151,149,1,0,0,0,152,153,3,86,43,0,153,154,
        5,38,0,0,154,155,3,86,43,0,155,156,5,39,0,0,156,166,1,0,0,0,157,
        161,3,86,43,0,158,160,5,37,0,0,159,158,1,0,0,0,160,163,1,0,0,0,161,
        159,1,0,0,0,161,162,1,0,0,0,162,166,1,0,0,0,163,161,1,0,0,0,164,
        166,5,20,0,0,165,141,1,0,0,0,165,152,1,0,0,0,165,157,1,0,0,0,165,
        164,1,0,0,0,166,17,1,0,0,0,167,168,3,58,29,0,168,169,3,20,10,0,169,
        19,1,0,0,0,170,172,3,22,11,0,171,170,1,0,0,0,171,172,1,0,0,0,172,
        180,1,0,0,0,173,174,5,31,0,0,174,176,3,58,29,0,175,177,3,22,11,0,
        176,175,1,0,0,0,176,177,1,0,0,0,177,179,1,0,0,0,178,173,1,0,0,0,
        179,182,1,0,0,0,180,178,1,0,0,0,180,181,1,0,0,0,181,21,1,0,0,0,182,
        180,1,0,0,0,183,184,7,3,0,0,184,23,1,0,0,0,185,186,5,12,0,0,186,
        191,3,26,13,0,187,188,5,44,0,0,188,190,3,26,13,0,189,187,1,0,0,0,
        190,193,1,0,0,0,191,189,1,0,0,0,191,192,1,0,0,0,192,25,1,0,0,0,193,
        191,1,0,0,0,194,195,3,28,14,0,195,196,5,31,0,0,196,198,3,58,29,0,
        197,199,3,36,18,0,198,197,1,0,0,0,198,199,1,0,0,0,199,27,1,0,0,0,
        200,201,3,86,43,0,201,202,5,40,0,0,202,203,3,76,38,0,203,204,5,41,
        0,0,204,221,1,0,0,0,205,206,3,86,43,0,206,210,3,82,41,0,207,209,
        5,37,0,0,208,207,1,0,0,0,209,212,1,0,0,0,210,208,1,0,0,0,210,211,
        1,0,0,0,211,221,1,0,0,0,212,210,1,0,0,0,213,217,3,86,43,0,214,216,
        5,37,0,0,215,214,1,0,0,0,216,219,1,0,0,0,217,215,1,0,0,0,217,218,
        1,0,0,0,218,221,1,0,0,0,219,217,1,0,0,0,220,200,1,0,0,0,220,205,
        1,0,0,0,220,213,1,0,0,0,221,29,1,0,0,0,222,223,5,13,0,0,223,228,
        3,32,16,0,224,225,5,44,0,0,225,227,3,32,16,0,226,224,1,0,0,0,227,
        230,1,0,0,0,228,226,1,0,0,0,228,229,1,0,0,0,229,31,1,0,0,0,230,228,
        1,0,0,0,231,233,3,58,29,0,232,234,3,36,18,0,233,232,1,0,0,0,233,
        234,1,0,0,0,234,33,1,0,0,0,235,236,5,14,0,0,236,241,3,86,43,0,237,
        238,5,44,0,0,238,240,3,86,43,0,239,237,1,0,0,0,240,243,1,0,0,0,241,
        239,1,0,0,0,241,242,1,0,0,0,242,35,1,0,0,0,243,241,1,0,0,0,244,250,
        3,40,20,0,245,246,3,38,19,0,246,247,3,40,20,0,247,249,1,0,0,0,248,
        245,1,0,0,0,249,252,1,0,0,0,250,248,1,0,0,0,250,251,1,0,0,0,251,
        37,1,0,0,0,252,250,1,0,0,0,253,254,7,4,0,0,254,39,1,0,0,0,255,258,
        3,86,43,0,256,258,5,22,0,0,257,255,1,0,0,0,257,256,1,0,0,0,258,264,
        1,0,0,0,259,261,5,36,0,0,260,262,5,33,0,0,261,260,1,0,0,0,261,262,
        1,0,0,0,262,263,1,0,0,0,263,265,5,20,0,0,264,259,1,0,0,0,264,265,
        1,0,0,0,265,41,1,0,0,0,266,267,5,15,0,0,267,268,3,86,43,0,268,270,
        5,38,0,0,269,271,3,78,39,0,270,269,1,0,0,0,270,271,1,0,0,0,271,272,
        1,0,0,0,272,274,5,39,0,0,273,275,3,44,22,0,274,273,1,0,0,0,274,275,
        1,0,0,0,275,284,1,0,0,0,276,281,3,48,24,0,277,278,5,44,0,0,278,280,
        3,86,43,0,279,277,1,0,0,0,280,283,1,0,0,0,281,279,1,0,0,0,281,282,
        1,0,0,0,282,285,1,0,0,0,283,281,1,0,0,0,284,276,1,0,0,0,284,285,
        1,0,0,0,285,43,1,0,0,0,286,287,5,40,0,0,287,289,3,86,43,0,288,290,
        3,36,18,0,289,288,1,0,0,0,289,290,1,0,0,0,290,291,1,0,0,0,291,292,
        5,31,0,0,292,293,3,58,29,0,293,294,5,44,0,0,294,295,3,58,29,0,295,
        296,5,44,0,0,296,297,3,58,29,0,297,298,5,41,0,0,298,45,1,0,0,0,299,
        300,7,5,0,0,300,301,3,48,24,0,301,47,1,0,0,0,302,304,3,50,25,0,303,
        302,1,0,0,0,304,307,1,0,0,0,305,303,1,0,0,0,305,306,1,0,0,0,306,
        310,1,0,0,0,307,305,1,0,0,0,308,311,5,22,0,0,309,311,3,86,43,0,310,
        308,1,0,0,0,310,309,1,0,0,0,311,49,1,0,0,0,312,319,5,22,0,0,313,
        319,3,86,43,0,314,319,5,20,0,0,315,319,5,35,0,0,316,319,5,33,0,0,
        317,319,5,51,0,0,318,312,1,0,0,0,318,313,1,0,0,0,318,314,1,0,0,0,
        318,315,1,0,0,0,318,316,1,0,0,0,318,317,1,0,0,0,319,51,1,0,0,0,320,
        321,5,21,0,0,321,326,3,54,27,0,322,323,5,44,0,0,323,325,3,54,27,
        0,324,322,1,0,0,0,325,328,1,0,0,0,326,324,1,0,0,0,326,327,1,0,0,
        0,327,53,1,0,0,0,328,326,1,0,0,0,329,334,3,86,43,0,330,331,5,40,
        0,0,331,332,3,76,38,0,332,333,5,41,0,0,333,335,1,0,0,0,334,330,1,
        0,0,0,334,335,1,0,0,0,335,339,1,0,0,0,336,338,5,37,0,0,337,336,1,
        0,0,0,338,341,1,0,0,0,339,337,1,0,0,0,339,340,1,0,0,0,340,344,1,
        0,0,0,341,339,1,0,0,0,342,343,5,31,0,0,343,345,3,56,28,0,344,342,
        1,0,0,0,344,345,1,0,0,0,345,364,1,0,0,0,346,347,5,40,0,0,347,352,
        3,86,43,0,348,349,5,44,0,0,349,351,3,86,43,0,350,348,1,0,0,0,351,
        354,1,0,0,0,352,350,1,0,0,0,352,353,1,0,0,0,353,355,1,0,0,0,354,
        352,1,0,0,0,355,356,5,41,0,0,356,357,5,31,0,0,357,358,3,56,28,0,
        358,364,1,0,0,0,359,361,3,22,11,0,360,359,1,0,0,0,360,361,1,0,0,
        0,361,362,1,0,0,0,362,364,5,20,0,0,363,329,1,0,0,0,363,346,1,0,0,
        0,363,360,1,0,0,0,364,55,1,0,0,0,365,368,3,36,18,0,366,368,5,20,
        0,0,367,365,1,0,0,0,367,366,1,0,0,0,368,57,1,0,0,0,369,370,3,60,
        30,0,370,59,1,0,0,0,371,377,3,64,32,0,372,373,3,62,31,0,373,374,
        3,64,32,0,374,376,1,0,0,0,375,372,1,0,0,0,376,379,1,0,0,0,377,375,
        1,0,0,0,377,378,1,0,0,0,378,61,1,0,0,0,379,377,1,0,0,0,380,381,7,
        3,0,0,381,63,1,0,0,0,382,388,3,68,34,0,383,384,3,66,33,0,384,385,
        3,68,34,0,385,387,1,0,0,0,386,383,1,0,0,0,387,390,1,0,0,0,388,386,
        1,0,0,0,388,389,1,0,0,0,389,65,1,0,0,0,390,388,1,0,0,0,391,392,7,
        4,0,0,392,67,1,0,0,0,393,394,3,62,31,0,394,395,3,68,34,0,395,398,
        1,0,0,0,396,398,3,70,35,0,397,393,1,0,0,0,397,396,1,0,0,0,398,69,
        1,0,0,0,399,402,3,72,36,0,400,401,5,36,0,0,401,403,3,68,34,0,402,
        400,1,0,0,0,402,403,1,0,0,0,403,71,1,0,0,0,404,453,5,20,0,0,405,
        453,5,23,0,0,406,453,7,6,0,0,407,408,3,86,43,0,408,410,5,38,0,0,
        409,411,3,78,39,0,410,409,1,0,0,0,410,411,1,0,0,0,411,412,1,0,0,
        0,412,413,5,39,0,0,413,453,1,0,0,0,414,415,3,86,43,0,415,416,5,40,
        0,0,416,417,3,76,38,0,417,418,5,41,0,0,418,453,1,0,0,0,419,420,3,
        86,43,0,420,422,3,82,41,0,421,423,3,86,43,0,422,421,1,0,0,0,422,
        423,1,0,0,0,423,427,1,0,0,0,424,426,5,37,0,0,425,424,1,0,0,0,426,
        429,1,0,0,0,427,425,1,0,0,0,427,428,1,0,0,0,428,453,1,0,0,0,429,
        427,1,0,0,0,430,434,3,86,43,0,431,433,5,37,0,0,432,431,1,0,0,0,433,
        436,1,0,0,0,434,432,1,0,0,0,434,435,1,0,0,0,435,453,1,0,0,0,436,
        434,1,0,0,0,437,438,5,40,0,0,438,443,3,74,37,0,439,440,5,45,0,0,
        440,442,3,74,37,0,441,439,1,0,0,0,442,445,1,0,0,0,443,441,1,0,0,
        0,443,444,1,0,0,0,444,446,1,0,0,0,445,443,1,0,0,0,446,447,5,41,0,
        0,447,453,1,0,0,0,448,449,5,38,0,0,449,450,3,58,29,0,450,451,5,39,
        0,0,451,453,1,0,0,0,452,404,1,0,0,0,452,405,1,0,0,0,452,406,1,0,
        0,0,452,407,1,0,0,0,452,414,1,0,0,0,452,419,1,0,0,0,452,430,1,0,
        0,0,452,437,1,0,0,0,452,448,1,0,0,0,453,73,1,0,0,0,454,459,3,58,
        29,0,455,456,5,44,0,0,456,458,3,58,29,0,457,455,1,0,0,0,458,461,
        1,0,0,0,459,457,1,0,0,0,459,460,1,0,0,0,460,75,1,0,0,0,461,459,1,
        0,0,0,462,467,3,58,29,0,463,464,5,44,0,0,464,466,3,58,29,0,465,463,
        1,0,0,0,466,469,1,0,0,0,467,465,1,0,0,0,467,468,1,0,0,0,468,77,1,
        0,0,0,469,467,1,0,0,0,470,475,3,80,40,0,471,472,5,44,0,0,472,474,
        3,80,40,0,473,471,1,0,0,0,474,477,1,0,0,0,475,473,1,0,0,0,475,476,
        1,0,0,0,476,79,1,0,0,0,477,475,1,0,0,0,478,481,3,58,29,0,479,480,
        5,31,0,0,480,482,3,58,29,0,481,479,1,0,0,0,481,482,1,0,0,0,482,485,
        1,0,0,0,483,484,5,46,0,0,484,486,3,58,29,0,485,483,1,0,0,0,485,486,
        1,0,0,0,486,81,1,0,0,0,487,488,5,42,0,0,488,493,3,84,42,0,489,490,
        5,44,0,0,490,492,3,84,42,0,491,489,1,0,0,0,492,495,1,0,0,0,493,491,
        1,0,0,0,493,494,1,0,0,0,494,496,1,0,0,0,495,493,1,0,0,0,496,497,
        5,43,0,0,497,83,1,0,0,0,498,501,5,20,0,0,499,500,5,46,0,0,500,502,
        5,20,0,0,501,499,1,0,0,0,501,502,1,0,0,0,502,85,1,0,0,0,503,504,
        7,7,0,0,504,87,1,0,0,0,58,89,102,117,120,126,133,144,149,161,165,
        171,176,180,191,198,210,217,220,228,233,241,250,257,261,264,270,
        274,281,284,289,305,310,318,326,334,339,344,352,360,363,367,377,
        388,397,402,410,422,427,434,443,452,459,467,475,481,485,493,501
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
    RULE_filePiece = 25
    RULE_setting = 26
    RULE_settingArg = 27
    RULE_settingWord = 28
    RULE_expr = 29
    RULE_additive = 30
    RULE_addOp = 31
    RULE_multiplicative = 32
    RULE_mulOp = 33
    RULE_unary = 34
    RULE_power = 35
    RULE_atom = 36
    RULE_matrixRow = 37
    RULE_exprList = 38
    RULE_argList = 39
    RULE_arg = 40
    RULE_indexBraces = 41
    RULE_indexRange = 42
    RULE_ident = 43

    ruleNames =  [ "statement", "stmt", "assignment", "lvalue", "exprStmt", 
                   "declaration", "declKeyword", "firstDeclItem", "declHead", 
                   "declItem", "declTail", "sign", "inputStmt", "inputItem", 
                   "inputTarget", "outputStmt", "outputItem", "unitSystemStmt", 
                   "unit", "unitOp", "unitFactor", "codeStmt", "sweep", 
                   "fileCommand", "fileName", "filePiece", "setting", "settingArg", 
                   "settingWord", "expr", "additive", "addOp", "multiplicative", 
                   "mulOp", "unary", "power", "atom", "matrixRow", "exprList", 
                   "argList", "arg", "indexBraces", "indexRange", "ident" ]

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
            self.state = 89
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 88
                self.stmt()


            self.state = 91
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
            self.state = 102
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,1,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 93
                self.assignment()
                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 94
                self.exprStmt()
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 95
                self.declaration()
                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 96
                self.inputStmt()
                pass

            elif la_ == 5:
                self.enterOuterAlt(localctx, 5)
                self.state = 97
                self.outputStmt()
                pass

            elif la_ == 6:
                self.enterOuterAlt(localctx, 6)
                self.state = 98
                self.unitSystemStmt()
                pass

            elif la_ == 7:
                self.enterOuterAlt(localctx, 7)
                self.state = 99
                self.codeStmt()
                pass

            elif la_ == 8:
                self.enterOuterAlt(localctx, 8)
                self.state = 100
                self.fileCommand()
                pass

            elif la_ == 9:
                self.enterOuterAlt(localctx, 9)
                self.state = 101
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
            self.state = 104
            self.lvalue()
            self.state = 105
            localctx.op = self._input.LT(1)
            _la = self._input.LA(1)
            if not((((_la) & ~0x3f) == 0 and ((1 << _la) & 4261412864) != 0)):
                localctx.op = self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 106
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
            self.state = 120
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,3,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.ElementTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 108
                self.ident()
                self.state = 109
                self.match(AutolevParser.LBRACK)
                self.state = 110
                self.exprList()
                self.state = 111
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.NameTargetContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 113
                self.ident()
                self.state = 117
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 114
                    self.match(AutolevParser.PRIME)
                    self.state = 119
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
            self.state = 122
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
            self.state = 124
            self.declKeyword()
            self.state = 126
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==37:
                self.state = 125
                self.match(AutolevParser.PRIME)


            self.state = 128
            self.firstDeclItem()
            self.state = 133
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 129
                self.match(AutolevParser.COMMA)
                self.state = 130
                self.declItem()
                self.state = 135
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
            self.state = 136
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
            self.state = 138
            self.declHead()
            self.state = 139
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
            self.state = 165
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,9,self._ctx)
            if la_ == 1:
                self.enterOuterAlt(localctx, 1)
                self.state = 141
                self.ident()
                self.state = 142
                self.indexBraces()
                self.state = 144
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2359294) != 0):
                    self.state = 143
                    localctx.suffix = self.ident()


                self.state = 149
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 146
                    self.match(AutolevParser.PRIME)
                    self.state = 151
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 2:
                self.enterOuterAlt(localctx, 2)
                self.state = 152
                self.ident()
                self.state = 153
                self.match(AutolevParser.LPAREN)
                self.state = 154
                localctx.basis = self.ident()
                self.state = 155
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 3:
                self.enterOuterAlt(localctx, 3)
                self.state = 157
                self.ident()
                self.state = 161
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 158
                    self.match(AutolevParser.PRIME)
                    self.state = 163
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 4:
                self.enterOuterAlt(localctx, 4)
                self.state = 164
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
            self.state = 167
            self.expr()
            self.state = 168
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
            self.state = 171
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==32 or _la==33:
                self.state = 170
                self.sign()


            self.state = 180
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==31:
                self.state = 173
                self.match(AutolevParser.EQ)
                self.state = 174
                self.expr()
                self.state = 176
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==32 or _la==33:
                    self.state = 175
                    self.sign()


                self.state = 182
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
            self.state = 183
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
            self.state = 185
            self.match(AutolevParser.INPUT)
            self.state = 186
            self.inputItem()
            self.state = 191
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 187
                self.match(AutolevParser.COMMA)
                self.state = 188
                self.inputItem()
                self.state = 193
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
            self.state = 194
            self.inputTarget()
            self.state = 195
            self.match(AutolevParser.EQ)
            self.state = 196
            self.expr()
            self.state = 198
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 197
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
            self.state = 220
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,17,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.InputElementContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 200
                self.ident()
                self.state = 201
                self.match(AutolevParser.LBRACK)
                self.state = 202
                self.exprList()
                self.state = 203
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 2:
                localctx = AutolevParser.InputIndexedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 205
                self.ident()
                self.state = 206
                self.indexBraces()
                self.state = 210
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 207
                    self.match(AutolevParser.PRIME)
                    self.state = 212
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 3:
                localctx = AutolevParser.InputNameContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 213
                self.ident()
                self.state = 217
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 214
                    self.match(AutolevParser.PRIME)
                    self.state = 219
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
            self.state = 222
            self.match(AutolevParser.OUTPUT)
            self.state = 223
            self.outputItem()
            self.state = 228
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 224
                self.match(AutolevParser.COMMA)
                self.state = 225
                self.outputItem()
                self.state = 230
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
            self.state = 231
            self.expr()
            self.state = 233
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 232
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
            self.state = 235
            self.match(AutolevParser.UNITSYSTEM)
            self.state = 236
            self.ident()
            self.state = 241
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 237
                self.match(AutolevParser.COMMA)
                self.state = 238
                self.ident()
                self.state = 243
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
            self.state = 244
            self.unitFactor()
            self.state = 250
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 245
                self.unitOp()
                self.state = 246
                self.unitFactor()
                self.state = 252
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
            self.state = 253
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
            self.state = 257
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.state = 255
                self.ident()
                pass
            elif token in [22]:
                self.state = 256
                self.match(AutolevParser.FILENAME)
                pass
            else:
                raise NoViableAltException(self)

            self.state = 264
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 259
                self.match(AutolevParser.CARET)
                self.state = 261
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==33:
                    self.state = 260
                    self.match(AutolevParser.MINUS)


                self.state = 263
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
            self.state = 266
            self.match(AutolevParser.CODE)
            self.state = 267
            self.ident()
            self.state = 268
            self.match(AutolevParser.LPAREN)
            self.state = 270
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                self.state = 269
                self.argList()


            self.state = 272
            self.match(AutolevParser.RPAREN)
            self.state = 274
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==40:
                self.state = 273
                self.sweep()


            self.state = 284
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 2251842770960382) != 0):
                self.state = 276
                self.fileName()
                self.state = 281
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==44:
                    self.state = 277
                    self.match(AutolevParser.COMMA)
                    self.state = 278
                    self.ident()
                    self.state = 283
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
            self.state = 286
            self.match(AutolevParser.LBRACK)
            self.state = 287
            self.ident()
            self.state = 289
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if (((_la) & ~0x3f) == 0 and ((1 << _la) & 6553598) != 0):
                self.state = 288
                self.unit()


            self.state = 291
            self.match(AutolevParser.EQ)
            self.state = 292
            self.expr()
            self.state = 293
            self.match(AutolevParser.COMMA)
            self.state = 294
            self.expr()
            self.state = 295
            self.match(AutolevParser.COMMA)
            self.state = 296
            self.expr()
            self.state = 297
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
            self.state = 299
            _la = self._input.LA(1)
            if not(_la==16 or _la==17):
                self._errHandler.recoverInline(self)
            else:
                self._errHandler.reportMatch(self)
                self.consume()
            self.state = 300
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


        def filePiece(self, i:int=None):
            if i is None:
                return self.getTypedRuleContexts(AutolevParser.FilePieceContext)
            else:
                return self.getTypedRuleContext(AutolevParser.FilePieceContext,i)


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
            self.enterOuterAlt(localctx, 1)
            self.state = 305
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,30,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 302
                    self.filePiece() 
                self.state = 307
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,30,self._ctx)

            self.state = 310
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [22]:
                self.state = 308
                self.match(AutolevParser.FILENAME)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.state = 309
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


    class FilePieceContext(ParserRuleContext):
        __slots__ = 'parser'

        def __init__(self, parser, parent:ParserRuleContext=None, invokingState:int=-1):
            super().__init__(parent, invokingState)
            self.parser = parser

        def FILENAME(self):
            return self.getToken(AutolevParser.FILENAME, 0)

        def ident(self):
            return self.getTypedRuleContext(AutolevParser.IdentContext,0)


        def NUMBER(self):
            return self.getToken(AutolevParser.NUMBER, 0)

        def DIV(self):
            return self.getToken(AutolevParser.DIV, 0)

        def MINUS(self):
            return self.getToken(AutolevParser.MINUS, 0)

        def ERRCHAR(self):
            return self.getToken(AutolevParser.ERRCHAR, 0)

        def getRuleIndex(self):
            return AutolevParser.RULE_filePiece

        def accept(self, visitor:ParseTreeVisitor):
            if hasattr( visitor, "visitFilePiece" ):
                return visitor.visitFilePiece(self)
            else:
                return visitor.visitChildren(self)




    def filePiece(self):

        localctx = AutolevParser.FilePieceContext(self, self._ctx, self.state)
        self.enterRule(localctx, 50, self.RULE_filePiece)
        try:
            self.state = 318
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [22]:
                self.enterOuterAlt(localctx, 1)
                self.state = 312
                self.match(AutolevParser.FILENAME)
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                self.enterOuterAlt(localctx, 2)
                self.state = 313
                self.ident()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 3)
                self.state = 314
                self.match(AutolevParser.NUMBER)
                pass
            elif token in [35]:
                self.enterOuterAlt(localctx, 4)
                self.state = 315
                self.match(AutolevParser.DIV)
                pass
            elif token in [33]:
                self.enterOuterAlt(localctx, 5)
                self.state = 316
                self.match(AutolevParser.MINUS)
                pass
            elif token in [51]:
                self.enterOuterAlt(localctx, 6)
                self.state = 317
                self.match(AutolevParser.ERRCHAR)
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
        self.enterRule(localctx, 52, self.RULE_setting)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 320
            self.match(AutolevParser.ID)
            self.state = 321
            self.settingArg()
            self.state = 326
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 322
                self.match(AutolevParser.COMMA)
                self.state = 323
                self.settingArg()
                self.state = 328
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
        self.enterRule(localctx, 54, self.RULE_settingArg)
        self._la = 0 # Token type
        try:
            self.state = 363
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21]:
                localctx = AutolevParser.SettingNameContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 329
                self.ident()
                self.state = 334
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==40:
                    self.state = 330
                    self.match(AutolevParser.LBRACK)
                    self.state = 331
                    self.exprList()
                    self.state = 332
                    self.match(AutolevParser.RBRACK)


                self.state = 339
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 336
                    self.match(AutolevParser.PRIME)
                    self.state = 341
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 344
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==31:
                    self.state = 342
                    self.match(AutolevParser.EQ)
                    self.state = 343
                    self.settingWord()


                pass
            elif token in [40]:
                localctx = AutolevParser.SettingGroupContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 346
                self.match(AutolevParser.LBRACK)
                self.state = 347
                self.ident()
                self.state = 352
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==44:
                    self.state = 348
                    self.match(AutolevParser.COMMA)
                    self.state = 349
                    self.ident()
                    self.state = 354
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 355
                self.match(AutolevParser.RBRACK)
                self.state = 356
                self.match(AutolevParser.EQ)
                self.state = 357
                self.settingWord()
                pass
            elif token in [20, 32, 33]:
                localctx = AutolevParser.SettingNumberContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 360
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if _la==32 or _la==33:
                    self.state = 359
                    self.sign()


                self.state = 362
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
        self.enterRule(localctx, 56, self.RULE_settingWord)
        try:
            self.state = 367
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 21, 22]:
                self.enterOuterAlt(localctx, 1)
                self.state = 365
                self.unit()
                pass
            elif token in [20]:
                self.enterOuterAlt(localctx, 2)
                self.state = 366
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
        self.enterRule(localctx, 58, self.RULE_expr)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 369
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
        self.enterRule(localctx, 60, self.RULE_additive)
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 371
            self.multiplicative()
            self.state = 377
            self._errHandler.sync(self)
            _alt = self._interp.adaptivePredict(self._input,41,self._ctx)
            while _alt!=2 and _alt!=ATN.INVALID_ALT_NUMBER:
                if _alt==1:
                    self.state = 372
                    self.addOp()
                    self.state = 373
                    self.multiplicative() 
                self.state = 379
                self._errHandler.sync(self)
                _alt = self._interp.adaptivePredict(self._input,41,self._ctx)

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
        self.enterRule(localctx, 62, self.RULE_addOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 380
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
        self.enterRule(localctx, 64, self.RULE_multiplicative)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 382
            self.unary()
            self.state = 388
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==34 or _la==35:
                self.state = 383
                self.mulOp()
                self.state = 384
                self.unary()
                self.state = 390
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
        self.enterRule(localctx, 66, self.RULE_mulOp)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 391
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
        self.enterRule(localctx, 68, self.RULE_unary)
        try:
            self.state = 397
            self._errHandler.sync(self)
            token = self._input.LA(1)
            if token in [32, 33]:
                localctx = AutolevParser.SignedContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 393
                self.addOp()
                self.state = 394
                self.unary()
                pass
            elif token in [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 23, 38, 40]:
                localctx = AutolevParser.UnsignedContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 396
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
        self.enterRule(localctx, 70, self.RULE_power)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 399
            self.atom()
            self.state = 402
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==36:
                self.state = 400
                self.match(AutolevParser.CARET)
                self.state = 401
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
        self.enterRule(localctx, 72, self.RULE_atom)
        self._la = 0 # Token type
        try:
            self.state = 452
            self._errHandler.sync(self)
            la_ = self._interp.adaptivePredict(self._input,50,self._ctx)
            if la_ == 1:
                localctx = AutolevParser.NumberContext(self, localctx)
                self.enterOuterAlt(localctx, 1)
                self.state = 404
                self.match(AutolevParser.NUMBER)
                pass

            elif la_ == 2:
                localctx = AutolevParser.StringContext(self, localctx)
                self.enterOuterAlt(localctx, 2)
                self.state = 405
                self.match(AutolevParser.STRING)
                pass

            elif la_ == 3:
                localctx = AutolevParser.SpecialContext(self, localctx)
                self.enterOuterAlt(localctx, 3)
                self.state = 406
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
                self.state = 407
                self.ident()
                self.state = 408
                self.match(AutolevParser.LPAREN)
                self.state = 410
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                if (((_la) & ~0x3f) == 0 and ((1 << _la) & 1387287019518) != 0):
                    self.state = 409
                    self.argList()


                self.state = 412
                self.match(AutolevParser.RPAREN)
                pass

            elif la_ == 5:
                localctx = AutolevParser.ElementContext(self, localctx)
                self.enterOuterAlt(localctx, 5)
                self.state = 414
                self.ident()
                self.state = 415
                self.match(AutolevParser.LBRACK)
                self.state = 416
                self.exprList()
                self.state = 417
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 6:
                localctx = AutolevParser.IndexedNamesContext(self, localctx)
                self.enterOuterAlt(localctx, 6)
                self.state = 419
                self.ident()
                self.state = 420
                self.indexBraces()
                self.state = 422
                self._errHandler.sync(self)
                la_ = self._interp.adaptivePredict(self._input,46,self._ctx)
                if la_ == 1:
                    self.state = 421
                    localctx.suffix = self.ident()


                self.state = 427
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 424
                    self.match(AutolevParser.PRIME)
                    self.state = 429
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 7:
                localctx = AutolevParser.NameContext(self, localctx)
                self.enterOuterAlt(localctx, 7)
                self.state = 430
                self.ident()
                self.state = 434
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==37:
                    self.state = 431
                    self.match(AutolevParser.PRIME)
                    self.state = 436
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                pass

            elif la_ == 8:
                localctx = AutolevParser.MatrixContext(self, localctx)
                self.enterOuterAlt(localctx, 8)
                self.state = 437
                self.match(AutolevParser.LBRACK)
                self.state = 438
                self.matrixRow()
                self.state = 443
                self._errHandler.sync(self)
                _la = self._input.LA(1)
                while _la==45:
                    self.state = 439
                    self.match(AutolevParser.SEMI)
                    self.state = 440
                    self.matrixRow()
                    self.state = 445
                    self._errHandler.sync(self)
                    _la = self._input.LA(1)

                self.state = 446
                self.match(AutolevParser.RBRACK)
                pass

            elif la_ == 9:
                localctx = AutolevParser.ParensContext(self, localctx)
                self.enterOuterAlt(localctx, 9)
                self.state = 448
                self.match(AutolevParser.LPAREN)
                self.state = 449
                self.expr()
                self.state = 450
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
        self.enterRule(localctx, 74, self.RULE_matrixRow)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 454
            self.expr()
            self.state = 459
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 455
                self.match(AutolevParser.COMMA)
                self.state = 456
                self.expr()
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
        self.enterRule(localctx, 76, self.RULE_exprList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 462
            self.expr()
            self.state = 467
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 463
                self.match(AutolevParser.COMMA)
                self.state = 464
                self.expr()
                self.state = 469
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
        self.enterRule(localctx, 78, self.RULE_argList)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 470
            self.arg()
            self.state = 475
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 471
                self.match(AutolevParser.COMMA)
                self.state = 472
                self.arg()
                self.state = 477
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
        self.enterRule(localctx, 80, self.RULE_arg)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 478
            self.expr()
            self.state = 481
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==31:
                self.state = 479
                self.match(AutolevParser.EQ)
                self.state = 480
                self.expr()


            self.state = 485
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 483
                self.match(AutolevParser.COLON)
                self.state = 484
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
        self.enterRule(localctx, 82, self.RULE_indexBraces)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 487
            self.match(AutolevParser.LBRACE)
            self.state = 488
            self.indexRange()
            self.state = 493
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            while _la==44:
                self.state = 489
                self.match(AutolevParser.COMMA)
                self.state = 490
                self.indexRange()
                self.state = 495
                self._errHandler.sync(self)
                _la = self._input.LA(1)

            self.state = 496
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
        self.enterRule(localctx, 84, self.RULE_indexRange)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 498
            self.match(AutolevParser.NUMBER)
            self.state = 501
            self._errHandler.sync(self)
            _la = self._input.LA(1)
            if _la==46:
                self.state = 499
                self.match(AutolevParser.COLON)
                self.state = 500
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
        self.enterRule(localctx, 86, self.RULE_ident)
        self._la = 0 # Token type
        try:
            self.enterOuterAlt(localctx, 1)
            self.state = 503
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





