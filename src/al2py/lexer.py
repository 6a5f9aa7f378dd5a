"""The tokens of ``grammar/Autolev.g4``'s lexer rules, for ANTLR's parser.

ANTLR's generated Python lexer simulates the rules' automaton character by
character: about 30 microseconds a token in a fresh process (Moore's
Whipple bicycle, 7,000 tokens: 0.23 s, a quarter of its conversion, and
the longest step before ``al2py code`` can derive).  The rules are few and
regular, so :class:`Lexer` reads the same tokens with Python's regular
expressions and hands them to ANTLR's ``CommonTokenStream`` and parser as
ANTLR's own ``CommonToken`` objects: the same type, channel, start, stop,
line and column (``tests/test_lexer.py`` holds the two lexers to each
other, token for token, on every script the tests have and on random text).

ANTLR's rule is the one followed here: at each place the longest match of
any rule, and of rules matching as much, the first in the grammar (a
keyword before a name: ``inputs`` is INPUT, ``inputsx`` an ID).  The
grammar is ``caseInsensitive``: its letters are ``[a-zA-Z]`` (Python's
``re.IGNORECASE`` would add four non-ASCII letters, so the classes are
written out).  ``ERRCHAR`` matches any character no other rule takes, so
the lexer never fails; the parser reports such a token.
"""

from __future__ import annotations

import re

from antlr4 import InputStream, Token
from antlr4.CommonTokenFactory import CommonTokenFactory
from antlr4.Token import CommonToken

from ._antlr.AutolevParser import AutolevParser as _P

__all__ = ["Lexer"]

#: the keywords, lowercase, by their token type (each rule's alternatives)
_KEYWORDS: dict[str, int] = {
    "constant": _P.CONSTANTS,
    "constants": _P.CONSTANTS,
    "variable": _P.VARIABLES,
    "variables": _P.VARIABLES,
    "motionvariable": _P.VARIABLES,
    "motionvariables": _P.VARIABLES,
    "specified": _P.SPECIFIED,
    "imaginary": _P.IMAGINARY,
    "newtonian": _P.NEWTONIAN,
    "frame": _P.FRAMES,
    "frames": _P.FRAMES,
    "body": _P.BODIES,
    "bodies": _P.BODIES,
    "particle": _P.PARTICLES,
    "particles": _P.PARTICLES,
    "point": _P.POINTS,
    "points": _P.POINTS,
    "mass": _P.MASS,
    "inertia": _P.INERTIA,
    "input": _P.INPUT,
    "inputs": _P.INPUT,
    "output": _P.OUTPUT,
    "outputs": _P.OUTPUT,
    "unitsystem": _P.UNITSYSTEM,
    "code": _P.CODE,
    "save": _P.SAVE,
    "run": _P.RUN,
}

#: ID: LETTER (LETTER | DIGIT | '_')* ('>' ('>' '>'?)?)?  (the name, then
#: its arrows)
_ID = re.compile(r"[a-zA-Z][a-zA-Z0-9_]*")
_ARROWS = re.compile(r">(?:>>?)?")
#: FILENAME: (LETTER | DIGIT | [_.~])* '.' LETTER (LETTER | DIGIT | '_')*
#: (greedy, it ends after the last '.' that a letter follows: the longest)
_FILENAME = re.compile(r"[a-zA-Z0-9_.~]*\.[a-zA-Z][a-zA-Z0-9_]*")
#: the characters a FILENAME is made of
_FILE_RUN = re.compile(r"[a-zA-Z0-9_.~]*")
#: NUMBER: DIGIT+ ('.' DIGIT*)? EXPONENT? | '.' DIGIT+ EXPONENT?
_NUMBER = re.compile(
    r"[0-9]+(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?|\.[0-9]+(?:[eE][+-]?[0-9]+)?"
)
#: ZEROVEC: '0' '>' '>'? '>'?
_ZEROVEC = re.compile(r"0>>?>?")
#: STRING: '"' ~["\r\n]* '"' and UNTERMINATED_STRING: '"' ~["\r\n]*
_STRING = re.compile(r'"[^"\r\n]*"?')
#: COMMENT: '%' ~[\r\n]* (channel 2)
_COMMENT = re.compile(r"%[^\r\n]*")
#: WS: [ \t\f\u000B]+ (skipped)
_WS = re.compile(r"[ \t\f\v]+")

#: the tokens of one or two characters: the longer first
_PAIRS = {
    ":=": _P.COLONEQ,
    "+=": _P.PLUSEQ,
    "-=": _P.MINUSEQ,
    "*=": _P.TIMESEQ,
    "/=": _P.DIVEQ,
    "^=": _P.POWEQ,
    "\r\n": _P.NEWLINE,
}
_SINGLES = {
    "=": _P.EQ,
    "+": _P.PLUS,
    "-": _P.MINUS,
    "*": _P.TIMES,
    "/": _P.DIV,
    "^": _P.CARET,
    "'": _P.PRIME,
    "(": _P.LPAREN,
    ")": _P.RPAREN,
    "[": _P.LBRACK,
    "]": _P.RBRACK,
    "{": _P.LBRACE,
    "}": _P.RBRACE,
    ",": _P.COMMA,
    ";": _P.SEMI,
    ":": _P.COLON,
    "&": _P.AMP,
    "\n": _P.NEWLINE,
    "\r": _P.NEWLINE,
}
_LETTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")
_DIGITS = frozenset("0123456789")
_COMMENT_CHANNEL = 2


class Lexer:
    """An ANTLR token source over ``input`` (what ``CommonTokenStream``
    reads): :meth:`nextToken` gives the next token, then ``EOF`` for ever.
    """

    def __init__(self, input: InputStream) -> None:
        self._input = input
        self._text = str(input)
        self._pos = 0
        #: the line (1-based) and column of the last token's start
        self.line = 1
        self.column = 0
        self._line_start = 0  # where that line starts in the text
        #: what ANTLR's parser makes a missing token with
        self._factory = CommonTokenFactory.DEFAULT
        self._source = (self, input)

    def getSourceName(self) -> str:
        return self._input.getSourceName()

    def nextToken(self) -> Token:
        text, pos, n = self._text, self._pos, len(self._text)
        while pos < n:
            c = text[pos]
            if c == " " or c == "\t" or c == "\f" or c == "\v":
                pos = _WS.match(text, pos).end()
                continue
            kind, end, channel = self._match(text, pos, c)
            self._pos = end
            return self._token(kind, channel, pos, end)
        self._pos = pos
        return self._token(Token.EOF, Token.DEFAULT_CHANNEL, n, n)

    def _token(self, kind: int, channel: int, start: int, end: int) -> Token:
        # ANTLR's line and column of the token's first character (a newline
        # ends the line it is on), which CommonToken reads from its source
        text = self._text
        newlines = text.count("\n", self._line_start, start)
        if newlines:
            self.line += newlines
            self._line_start = text.rfind("\n", 0, start) + 1
        self.column = start - self._line_start
        return CommonToken(self._source, kind, channel, start, end - 1)

    @staticmethod
    def _match(text: str, pos: int, c: str) -> tuple[int, int, int]:
        """The type, end and channel of the token at ``pos`` (its first
        character ``c``): the longest match, of equals the first rule."""
        if c in _LETTERS or c in _DIGITS or c == "." or c == "_" or c == "~":
            kind, end = _longest(text, pos, c)
            return kind, end, 0
        pair = _PAIRS.get(text[pos : pos + 2])
        if pair is not None:
            return pair, pos + 2, 0
        single = _SINGLES.get(c)
        if single is not None:
            return single, pos + 1, 0
        if c == '"':
            end = _STRING.match(text, pos).end()
            closed = end - pos > 1 and text[end - 1] == '"'
            return (_P.STRING if closed else _P.UNTERMINATED_STRING), end, 0
        if c == "%":
            return _P.COMMENT, _COMMENT.match(text, pos).end(), _COMMENT_CHANNEL
        return _P.ERRCHAR, pos + 1, 0


def _longest(text: str, pos: int, c: str) -> tuple[int, int]:
    """The type and end of the longest of the rules that a letter, digit,
    ``.``, ``_`` or ``~`` can start (in the grammar's order: the keywords,
    ZEROVEC, UNITDYADIC, NUMBER, ID, FILENAME; ERRCHAR last)."""
    kind, end = _P.ERRCHAR, pos  # (no match yet)
    if c in _LETTERS:
        word_end = _ID.match(text, pos).end()
        arrows = _ARROWS.match(text, word_end)
        id_end = arrows.end() if arrows else word_end
        keyword = _KEYWORDS.get(text[pos:word_end].lower())
        kind, end = (_P.ID, id_end) if keyword is None else (keyword, word_end)
        if end < id_end:  # the arrows make the name longer
            kind, end = _P.ID, id_end
    elif c in _DIGITS or c == ".":
        if c == "0":
            zero = _ZEROVEC.match(text, pos)
            if zero:
                kind, end = _P.ZEROVEC, zero.end()
        elif c == "1" and text.startswith(">>", pos + 1):
            kind, end = _P.UNITDYADIC, pos + 3
        number = _NUMBER.match(text, pos)
        if number and number.end() > end:
            kind, end = _P.NUMBER, number.end()
    run = _FILE_RUN.match(text, pos).end()
    if text.find(".", pos, run) >= 0:
        name = _FILENAME.match(text, pos)
        if name and name.end() > end:
            kind, end = _P.FILENAME, name.end()
    return (kind, end) if end > pos else (_P.ERRCHAR, pos + 1)
