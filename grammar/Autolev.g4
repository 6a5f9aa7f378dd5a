// Grammar of the Autolev language (Kane & Levinson), as used by al2py.
//
// One logical statement per line; newlines are significant.  `&` at the end
// of a line continues a statement; `%` starts a comment.  Comments are kept on
// channel 2 so the visitor can attach them to statements.  The lexer never
// fails: unknown characters become ERRCHAR tokens and an unterminated string
// becomes UNTERMINATED_STRING, so the parser reports every error, in order.
//
// Keywords are case-insensitive and may be used as ordinary names (see the
// `ident` rule); a keyword only starts a declaration/command when it is the
// first word of a statement with the right shape.

grammar Autolev;

options { caseInsensitive = true; }

// ------------------------------------------------------------------ parser

// A statement ends at a newline or a `;` (several statements may share a
// line: `x = 1; y = 2`).  The parser runs once per statement, so an error in
// one statement never hides the next.
statement
    : stmt? (NEWLINE | SEMI | EOF)
    ;

stmt
    : assignment
    | exprStmt
    | declaration
    | inputStmt
    | outputStmt
    | unitSystemStmt
    | codeStmt
    | fileCommand
    | setting
    ;

assignment
    : lvalue op=(EQ | COLONEQ | PLUSEQ | MINUSEQ | TIMESEQ | DIVEQ | POWEQ) expr
    ;

lvalue
    : ident LBRACK exprList RBRACK      # elementTarget
    | ident PRIME*                      # nameTarget
    ;

exprStmt
    : expr
    ;

// -- declarations ---------------------------------------------------------

declaration
    : declKeyword PRIME? firstDeclItem (COMMA declItem)*
    ;

declKeyword
    : CONSTANTS
    | VARIABLES
    | SPECIFIED
    | IMAGINARY
    | NEWTONIAN
    | FRAMES
    | BODIES
    | PARTICLES
    | POINTS
    | MASS
    | INERTIA
    ;

// The first item must start with a name (or a number: `Points 0`) so that
// `Mass(A)` and `Inertia(O)` stay expression statements.
firstDeclItem
    : declHead declTail
    ;

declHead
    : ident indexBraces suffix=ident? PRIME*   // U{3}', RRF{2}O
    | ident LPAREN basis=ident RPAREN          // Inertia C(B), ...: B's basis
    | ident PRIME*
    | NUMBER
    ;

declItem
    : expr declTail
    ;

declTail
    : sign? (EQ expr sign?)*
    ;

sign
    : PLUS
    | MINUS
    ;

// -- input / output / units -------------------------------------------------

inputStmt
    : INPUT inputItem (COMMA inputItem)*
    ;

inputItem
    : inputTarget EQ expr unit?
    ;

inputTarget
    : ident LBRACK exprList RBRACK      # inputElement
    | ident indexBraces PRIME*          # inputIndexed
    | ident PRIME*                      # inputName
    ;

outputStmt
    : OUTPUT outputItem (COMMA outputItem)*
    ;

outputItem
    : expr unit?
    ;

unitSystemStmt
    : UNITSYSTEM ident (COMMA ident)*
    ;

unit
    : unitFactor (unitOp unitFactor)*
    ;

unitOp
    : TIMES
    | DIV
    ;

// `KG.M^2`: a dot multiplies unit words (read as one FILENAME token).
unitFactor
    : (ident | FILENAME) (CARET MINUS? NUMBER)?
    ;

// -- commands ---------------------------------------------------------------

codeStmt
    : CODE ident LPAREN argList? RPAREN sweep? (fileName (COMMA ident)*)?
    ;

sweep
    : LBRACK ident unit? EQ expr COMMA expr COMMA expr RBRACK
    ;

fileCommand
    : (SAVE | RUN) fileName
    ;

// A path is read from its pieces (`../lib/kin.al` is `.` `.` `/` `lib` `/`
// `kin.al`; `sub\x.al` holds a backslash, an ERRCHAR): a FILENAME token
// holding `/` or `-` would make the lexer look ahead across every `A-B-C`
// or `----A` of an expression (quadratic time).  The parser checks that the
// pieces touch and which characters they are.
fileName
    : filePiece* (FILENAME | ident)
    ;

filePiece
    : FILENAME
    | ident
    | NUMBER
    | DIV
    | MINUS
    | ERRCHAR
    ;

// `Digits 7`, `Overwrite All`, and word commands with a list:
// `Encode A, B'`, `Units T=S, TINITIAL=S`, `Units [A, B]=M, [C]=KG` (a group
// of names given one unit).
setting
    : ID settingArg (COMMA settingArg)*
    ;

settingArg
    : ident (LBRACK exprList RBRACK)? PRIME* (EQ settingWord)?   # settingName
    | LBRACK ident (COMMA ident)* RBRACK EQ settingWord          # settingGroup
    | sign? NUMBER                                             # settingNumber
    ;

// `Units VX=M/S`: a unit word may be a product or quotient of units.
settingWord
    : unit
    | NUMBER
    ;

// -- expressions ------------------------------------------------------------
// Precedence, low to high: binary + -, * /, unary + -, ^ (right-assoc).

expr
    : additive
    ;

additive
    : multiplicative (addOp multiplicative)*
    ;

addOp
    : PLUS
    | MINUS
    ;

multiplicative
    : unary (mulOp unary)*
    ;

mulOp
    : TIMES
    | DIV
    ;

unary
    : addOp unary                       # signed
    | power                             # unsigned
    ;

power
    : atom (CARET unary)?
    ;

atom
    : NUMBER                                    # number
    | STRING                                    # string
    | (ZEROVEC | UNITDYADIC)                    # special
    | ident LPAREN argList? RPAREN              # call
    | ident LBRACK exprList RBRACK              # element
    | ident indexBraces suffix=ident? PRIME*    # indexedNames
    | ident PRIME*                              # name
    | LBRACK matrixRow (SEMI matrixRow)* RBRACK # matrix
    | LPAREN expr RPAREN                        # parens
    ;

matrixRow
    : expr (COMMA expr)*
    ;

exprList
    : expr (COMMA expr)*
    ;

argList
    : arg (COMMA arg)*
    ;

// `X`, `1:2`, `X=1`, `U1'=0:dU1'`
arg
    : expr (EQ expr)? (COLON expr)?
    ;

indexBraces
    : LBRACE indexRange (COMMA indexRange)* RBRACE
    ;

indexRange
    : NUMBER (COLON NUMBER)?
    ;

ident
    : ID
    | CONSTANTS
    | VARIABLES
    | SPECIFIED
    | IMAGINARY
    | NEWTONIAN
    | FRAMES
    | BODIES
    | PARTICLES
    | POINTS
    | MASS
    | INERTIA
    | INPUT
    | OUTPUT
    | UNITSYSTEM
    | CODE
    | SAVE
    | RUN
    ;

// ------------------------------------------------------------------- lexer

CONSTANTS  : 'constant' 's'? ;
VARIABLES  : 'variable' 's'? | 'motionvariable' 's'? ;
SPECIFIED  : 'specified' ;
IMAGINARY  : 'imaginary' ;
NEWTONIAN  : 'newtonian' ;
FRAMES     : 'frame' 's'? ;
BODIES     : 'body' | 'bodies' ;
PARTICLES  : 'particle' 's'? ;
POINTS     : 'point' 's'? ;
MASS       : 'mass' ;
INERTIA    : 'inertia' ;
INPUT      : 'input' 's'? ;
OUTPUT     : 'output' 's'? ;
UNITSYSTEM : 'unitsystem' ;
CODE       : 'code' ;
SAVE       : 'save' ;
RUN        : 'run' ;

ZEROVEC    : '0' '>' '>'? '>'? ;
UNITDYADIC : '1>>' ;

NUMBER
    : DIGIT+ ('.' DIGIT*)? EXPONENT?
    | '.' DIGIT+ EXPONENT?
    ;

ID         : LETTER (LETTER | DIGIT | '_')* ('>' ('>' '>'?)?)? ;

// A file name has an extension: `tutor2.all`, `tutor3.for`, `my_file.al`;
// paths (`../lib/kin.al`, `my-file.al`) are put together by the parser's
// fileName rule.
FILENAME   : (LETTER | DIGIT | [_.~])* '.' LETTER (LETTER | DIGIT | '_')* ;

STRING     : '"' ~["\r\n]* '"' ;
UNTERMINATED_STRING : '"' ~["\r\n]* ;

COLONEQ    : ':=' ;
PLUSEQ     : '+=' ;
MINUSEQ    : '-=' ;
TIMESEQ    : '*=' ;
DIVEQ      : '/=' ;
POWEQ      : '^=' ;
EQ         : '=' ;
PLUS       : '+' ;
MINUS      : '-' ;
TIMES      : '*' ;
DIV        : '/' ;
CARET      : '^' ;
PRIME      : '\'' ;
LPAREN     : '(' ;
RPAREN     : ')' ;
LBRACK     : '[' ;
RBRACK     : ']' ;
LBRACE     : '{' ;
RBRACE     : '}' ;
COMMA      : ',' ;
SEMI       : ';' ;
COLON      : ':' ;

// `&` as the last non-blank character of a line (before any comment) joins
// the next line to this one; the parser does the joining before lexing, so
// a continuation may split a name (`THET&` / `   A`).  An `&` left in the
// text is an error.
AMP        : '&' ;

COMMENT    : '%' ~[\r\n]* -> channel(2) ;
NEWLINE    : '\r'? '\n' | '\r' ;
WS         : [ \t\f\u000B]+ -> skip ;

ERRCHAR    : . ;

fragment LETTER   : [a-z] ;
fragment DIGIT    : [0-9] ;
fragment EXPONENT : 'e' [+-]? DIGIT+ ;
