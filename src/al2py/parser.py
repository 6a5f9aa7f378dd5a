"""Parse Autolev source text into the typed IR of :mod:`al2py.ir`.

The heavy lifting is done by the ANTLR parser generated from
``grammar/Autolev.g4`` (committed under :mod:`al2py._antlr`).  This module
adds three things on top of it:

* an error listener that turns the *first* lexical or syntax error into a
  :class:`~al2py.errors.ParseError` with a plain-English message and an exact
  ``line:col`` (ANTLR never prints anything);
* :class:`_IRBuilder`, a visitor with one small method per grammar rule that
  builds IR nodes with accurate :class:`~al2py.ir.Span` s;
* comment handling: comment-only lines become :class:`~al2py.ir.Comment`
  statements, trailing comments go into ``Stmt.comment``.

>>> script = parse("Constants A, B=3  % two constants")
>>> script.statements[0].keyword, script.statements[0].comment
('CONSTANTS', 'two constants')
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass

from al2py_runtime.vocabulary import LIST_COMMANDS
from antlr4 import CommonTokenStream, InputStream, Token
from antlr4.atn.ATNState import ATNState
from antlr4.atn.PredictionMode import PredictionMode
from antlr4.error.ErrorListener import ErrorListener
from antlr4.error.Errors import InputMismatchException, ParseCancellationException
from antlr4.error.ErrorStrategy import BailErrorStrategy, DefaultErrorStrategy
from antlr4.tree.Tree import TerminalNode

from . import ir
from ._antlr.AutolevParser import AutolevParser
from ._antlr.AutolevVisitor import AutolevVisitor
from .errors import AutolevError, InternalError, ParseError, ParseErrorList
from .lexer import Lexer
from .lines import split_lines

__all__ = ["parse", "parse_partial", "span_text", "join_continuations"]

_P = AutolevParser
_COMMENT_CHANNEL = 2

_DECL_KEYWORDS = {
    _P.CONSTANTS: "CONSTANTS",
    _P.VARIABLES: "VARIABLES",
    _P.SPECIFIED: "SPECIFIED",
    _P.IMAGINARY: "IMAGINARY",
    _P.NEWTONIAN: "NEWTONIAN",
    _P.FRAMES: "FRAMES",
    _P.BODIES: "BODIES",
    _P.PARTICLES: "PARTICLES",
    _P.POINTS: "POINTS",
    _P.MASS: "MASS",
    _P.INERTIA: "INERTIA",
}

_SEPARATORS = frozenset({_P.NEWLINE, _P.SEMI, Token.EOF})
_OPENERS = {_P.LPAREN: ")", _P.LBRACK: "]", _P.LBRACE: "}"}
_CLOSERS = {_P.RPAREN: ")", _P.RBRACK: "]", _P.RBRACE: "}"}
_NEEDS_OPERAND = frozenset(
    {
        _P.PLUS,
        _P.MINUS,
        _P.TIMES,
        _P.DIV,
        _P.CARET,
        _P.EQ,
        _P.COLONEQ,
        _P.PLUSEQ,
        _P.MINUSEQ,
        _P.TIMESEQ,
        _P.DIVEQ,
        _P.POWEQ,
        _P.COMMA,
        _P.SEMI,
        _P.COLON,
    }
)


#: sums with more terms than this are built as balanced trees (issue 12)
_LONG_SUM = 64

#: the most names one index range (``X{3,4}``) may make, and all the index
#: ranges of one file together: far beyond real scripts (tens), and small
#: enough that conversion stops with a located message before memory runs
#: out (``Variables X{100000000}`` grew past 5 GB)
MAX_INDEXED_NAMES = 10_000
MAX_INDEXED_NAMES_PER_FILE = 100_000


# ------------------------------------------------------------------ public API


def parse(text: str, filename: str = "<input>") -> ir.Script:
    """Parse Autolev source *text* into an :class:`ir.Script`.

    Raises :class:`ParseError` (an :class:`ErrorList` when there are several)
    with every syntax error in the file: after an error the parser goes on at
    the next statement.  Any other exception would be a bug and is reported
    as :class:`InternalError`.
    """
    script, errors = parse_partial(text, filename)
    if errors:
        raise errors[0] if len(errors) == 1 else ParseErrorList(errors)
    return script


def parse_partial(
    text: str, filename: str = "<input>"
) -> tuple[ir.Script, list[AutolevError]]:
    """The statements that parsed, and the syntax errors of the others."""
    lines = tuple(split_lines(text))
    try:
        return _parse(lines, filename)
    except AutolevError as exc:
        return ir.Script(ir.Span(filename, 1, 1), (), lines=lines), [exc]
    except RecursionError:
        # Too deep for ANTLR's recursive descent: point at the deepest bracket.
        from .static_checks import deepest_nesting

        span = deepest_nesting(filename, lines)
        err = ParseError(
            "expression nested too deeply",
            span,
            line_text=lines[span.line - 1] if lines else "",
        )
        return ir.Script(ir.Span(filename, 1, 1), (), lines=lines), [err]
    except Exception as exc:  # a bug in al2py, not in the input
        raise InternalError(f"parser failed on {filename}: {exc!r}") from exc


def span_text(lines: Sequence[str], span: ir.Span) -> str:
    """The exact source text covered by *span* (lines joined with ``\\n``)."""
    first, last = span.line, span.end_line or span.line
    if first < 1 or last < first or first > len(lines):
        return ""
    end_col = span.end_col if span.end_line else span.col
    if first == last:
        return lines[first - 1][span.col - 1 : end_col - 1]
    parts = [lines[first - 1][span.col - 1 :]]
    parts.extend(lines[first : min(last - 1, len(lines))])
    if last <= len(lines):
        parts.append(lines[last - 1][: end_col - 1])
    return "\n".join(parts)


# ------------------------------------------------------------------- plumbing


def _parse(
    lines: tuple[str, ...], filename: str
) -> tuple[ir.Script, list[AutolevError]]:
    logical = join_continuations(lines)
    # (every character is a token, ERRCHAR at worst: the lexer reports
    # nothing, the parser reports what it cannot use)
    stream = CommonTokenStream(Lexer(InputStream(logical.text)))
    listener = _ErrorListener(filename, lines, stream)
    stream.fill()
    logical.relocate(stream.tokens)
    parser = AutolevParser(stream)
    parser.removeErrorListeners()
    parser.addErrorListener(listener)
    careful = _ErrorStrategy()
    parsed: list[tuple[AutolevParser.StatementContext | None, Token]] = []
    for first, last in _statement_ranges(stream.tokens):
        ctx = _quick_statement(parser, stream, first, last)
        if ctx is not None:
            parsed.append((ctx, stream.tokens[last]))
            continue
        errors_before = listener.count
        stream.seek(first)
        parser._errHandler = careful
        parser._interp.predictionMode = PredictionMode.LL
        # A statement that ended in error recovery must not keep the parser in
        # recovery mode, where ANTLR reports no further errors.
        careful.reset(parser)
        ctx = parser.statement()
        if listener.count == errors_before and stream.index >= last:
            parsed.append((ctx, stream.tokens[last]))
        else:
            parsed.append((None, stream.tokens[last]))
    builder = _IRBuilder(filename, logical, lines, stream)
    script = builder.build(parsed)
    return script, listener.errors() + builder.errors


class _Bail(BailErrorStrategy):
    """The first stage of the two-stage parse: any syntax error stops the
    statement's parse at once, unreported and without recovery."""

    def reportError(self, recognizer, e):
        pass


def _quick_statement(
    parser: AutolevParser, stream: CommonTokenStream, first: int, last: int
) -> AutolevParser.StatementContext | None:
    """The statement of tokens ``first`` .. ``last`` parsed the quick way
    (ANTLR's SLL prediction, no error recovery), or None when that fails:
    then the statement is parsed again with full LL prediction and the error
    strategy that reports its errors (ANTLR's two-stage parse; when SLL
    succeeds, LL would build the same tree)."""
    stream.seek(first)
    parser._errHandler = _BAIL
    parser._interp.predictionMode = PredictionMode.SLL
    try:
        ctx = parser.statement()
    except ParseCancellationException:
        return None
    return ctx if stream.index >= last else None


_BAIL = _Bail()


def _statement_ranges(tokens: list[Token]) -> Iterator[tuple[int, int]]:
    """(first, last) token indexes of each statement, ``last`` its separator.

    A newline always ends a statement; a ``;`` ends one outside brackets
    (inside, it separates matrix rows).
    """
    first = 0
    depth = 0
    for k, tok in enumerate(tokens):
        if tok.type in _OPENERS:
            depth += 1
        elif tok.type in _CLOSERS:
            depth = max(depth - 1, 0)
        elif tok.type in (_P.NEWLINE, Token.EOF) or (tok.type == _P.SEMI and not depth):
            yield first, k
            first, depth = k + 1, 0
            if tok.type == Token.EOF:
                return


#: characters that are no token of the language but may appear in a file
#: name (``..\\lib\\kin.al``, ``~/x.al``)
_FILE_CHARACTERS = frozenset({"\\", "~", "."})

#: a unit written with dots (``KG.M``, ``M/KG.S``), which the lexer reads as
#: one file-name token
_DOTTED_UNIT = re.compile(r"[A-Za-z_]\w*([./][A-Za-z_]\w*)+")


@dataclass
class LogicalText:
    """Source text with ``&`` continuations joined, and where each char came from.

    ``origin[k]`` is the 1-based (line, column) in the physical file of
    character ``k`` of :attr:`text`.
    """

    text: str
    origin: list[tuple[int, int]]

    def relocate(self, tokens: list[Token]) -> None:
        """Give every token its physical line and column (ANTLR's are logical)."""
        last = self.origin[-1] if self.origin else (1, 0)
        end = (last[0], last[1] + 1)
        for tok in tokens:
            k = tok.start if tok.start >= 0 else len(self.text)
            line, col = self.origin[k] if k < len(self.origin) else end
            tok.line, tok.column = line, col - 1


def join_continuations(lines: tuple[str, ...]) -> LogicalText:
    """Join each line whose code ends in ``&`` with the next one.

    The ``&`` and the next line's leading blanks disappear, so a continuation
    may split a name (``THET&`` + ``   A`` is ``THETA``), as in Autolev's own
    wrapped output.  Comments of the joined lines move to the end of the
    logical line.  An ``&`` on the last line stays, and is reported.
    """
    text: list[str] = []
    origin: list[tuple[int, int]] = []
    i = 0
    while i < len(lines):
        comments: list[tuple[str, int, int]] = []
        first = True
        while True:
            line = lines[i]
            code_end = _code_end(line)
            code = line[:code_end]
            stripped = code.rstrip()
            start = 0 if first else len(code) - len(code.lstrip())
            more = stripped.endswith("&") and i + 1 < len(lines)
            if more:
                piece_end = len(stripped) - 1
                if code_end < len(line):
                    comments.append((line[code_end:], i + 1, code_end + 1))
            else:
                piece_end = len(line) if not comments else code_end
                if comments and code_end < len(line):
                    comments.append((line[code_end:], i + 1, code_end + 1))
            for col in range(start, piece_end):
                text.append(line[col])
                origin.append((i + 1, col + 1))
            first = False
            i += 1
            if not more:
                break
        if comments:
            joined = " ".join(c[0].lstrip("%").strip() for c in comments)
            lead = "%%" if comments[0][0].startswith("%%") else "%"
            _, line_no, col = comments[0]
            if text and not text[-1].isspace():
                text.append(" ")
                origin.append((line_no, col))
            for ch in lead + " " + joined:
                text.append(ch)
                origin.append((line_no, col))
        end_line = i  # the last physical line of this logical line
        text.append("\n")
        origin.append((end_line, len(lines[end_line - 1]) + 1))
    if text:
        text.pop()  # no newline after the last line
        origin.pop()
    return LogicalText("".join(text), origin)


def _code_end(line: str) -> int:
    """Index of the ``%`` that starts the comment of ``line`` (or its length)."""
    in_string = False
    for k, ch in enumerate(line):
        if ch == '"':
            in_string = not in_string
        elif ch == "%" and not in_string:
            return k
    return len(line)


def _token_end(tok: Token) -> tuple[int, int]:
    """1-based (line, col) of the position just after *tok*."""
    text = tok.text or ""
    if "\n" in text:
        return tok.line + text.count("\n"), len(text) - text.rindex("\n")
    return tok.line, tok.column + len(text) + 1


def _describe(tok: Token) -> str:
    if tok.type == Token.EOF:
        return "end of input"
    if tok.type == _P.NEWLINE:
        return "end of line"
    text = tok.text
    if len(text) > 20:
        text = text[:17] + "..."
    return repr(text)


class _ErrorStrategy(DefaultErrorStrategy):
    """ANTLR's default error strategy, whose ``sync`` (at every loop and
    choice of the grammar, most of a parse's checks) first asks whether the
    next token is one the state expects: here a set per state answers, not
    ANTLR's list of ranges.  Every other case is ANTLR's own ``sync``."""

    def __init__(self) -> None:
        super().__init__()
        #: the tokens each ATN state expects next (within its rule)
        self.expected: dict[int, frozenset[int]] = {}

    def sync(self, recognizer: AutolevParser) -> None:
        if self.inErrorRecoveryMode(recognizer):
            return
        state = recognizer.state
        expected = self.expected.get(state)
        if expected is None:
            s = recognizer._interp.atn.states[state]
            ranges = recognizer.atn.nextTokens(s).intervals or ()
            expected = self.expected[state] = frozenset(t for r in ranges for t in r)
        if recognizer.getTokenStream().LA(1) in expected:
            # as ANTLR's sync does when the token is expected
            self.nextTokensContext = None
            self.nextTokenState = ATNState.INVALID_STATE_NUMBER
            return
        super().sync(recognizer)


class _ErrorListener(ErrorListener):
    """Collect the errors ANTLR reports: the first one of each statement.

    ANTLR's default strategy recovers after an error; later complaints about
    the same statement are consequences of the first, so they are dropped.
    """

    def __init__(
        self, filename: str, lines: tuple[str, ...], stream: CommonTokenStream
    ) -> None:
        self.filename = filename
        self.lines = lines
        self.stream = stream
        self._found: list[tuple[int, ParseError]] = []  # (token index, error)

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):
        if not isinstance(offendingSymbol, Token):  # lexer error (no token)
            self._add(-1, "unexpected character", line, column + 1)
            return
        tok = self._dangling(offendingSymbol)
        message = self._message(recognizer, tok, e)
        if tok.type == Token.EOF:
            line, col = self._end_of_input(tok)
        else:
            line, col = tok.line, tok.column + 1
        self._add(tok.tokenIndex, message, line, col)

    def _add(self, index: int, message: str, line: int, col: int) -> None:
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        span = ir.Span(self.filename, line, col, line, col + 1)
        self._found.append((index, ParseError(message, span, line_text=text)))

    def _statement_of(self, index: int) -> int:
        """Token index of the separator that ends the statement holding ``index``."""
        tokens = self.stream.tokens
        k = max(index, 0)
        while k < len(tokens) and tokens[k].type not in _SEPARATORS:
            k += 1
        return k

    def _dangling(self, tok: Token) -> Token:
        """The end of the line, when ``tok`` is an operator left without operand.

        ``X = A +`` is missing an operand at the end of the line, which is
        where the error is reported (not at the ``+``).
        """
        if tok.type not in _NEEDS_OPERAND or tok.type in (_P.COMMA, _P.SEMI):
            return tok
        tokens = self.stream.tokens
        k = tok.tokenIndex + 1
        while k < len(tokens) and tokens[k].channel != Token.DEFAULT_CHANNEL:
            k += 1
        if k < len(tokens) and tokens[k].type in (_P.NEWLINE, Token.EOF):
            return tokens[k]
        return tok

    @property
    def count(self) -> int:
        return len(self._found)

    def errors(self) -> list[AutolevError]:
        """The first error of each statement."""
        seen: set[int] = set()
        out: list[AutolevError] = []
        for index, err in sorted(self._found, key=lambda f: f[0]):
            end = self._statement_of(index)
            if end not in seen:
                seen.add(end)
                out.append(self._stray_character(index, end) or err)
        return out

    def _stray_character(self, index: int, end: int) -> ParseError | None:
        """An error at the first character that is no token of the
        language in the statement ending at ``end`` (``Y = X + $ + X``): the
        parser's complaint about that statement is a consequence of it."""
        tokens = self.stream.tokens
        k = min(max(index, 0), len(tokens) - 1)
        while k > 0 and tokens[k - 1].type not in _SEPARATORS:
            k -= 1
        for tok in tokens[k:end]:
            if tok.type == _P.ERRCHAR:
                text = (
                    self.lines[tok.line - 1] if 0 < tok.line <= len(self.lines) else ""
                )
                span = ir.Span(
                    self.filename, tok.line, tok.column + 1, tok.line, tok.column + 2
                )
                return ParseError(
                    f"unexpected character {tok.text!r}", span, line_text=text
                )
        return None

    def _end_of_input(self, eof: Token) -> tuple[int, int]:
        if not self.lines:
            return 1, 1
        return len(self.lines), len(self.lines[-1]) + 1

    def _message(self, recognizer, tok: Token, e) -> str:
        ttype = tok.type
        if ttype == _P.UNTERMINATED_STRING:
            return "unterminated string"
        if ttype == _P.ERRCHAR:
            return f"unexpected character {tok.text!r}"
        if ttype == _P.AMP:
            following = self.stream.tokens[tok.tokenIndex + 1 :]
            if all(t.type == Token.EOF or t.channel != 0 for t in following):
                return "unexpected end of input after '&'"
            return "'&' (line continuation) must be the last character on a line"
        unclosed = self._unclosed(tok)
        if ttype in (Token.EOF, _P.NEWLINE):
            if unclosed is not None and not self._after_operator(tok):
                return f"missing {unclosed!r}"
            return f"unexpected {_describe(tok)}"
        if ttype in _CLOSERS:
            if unclosed is not None and unclosed != _CLOSERS[ttype]:
                return f"unexpected {tok.text!r}; missing {unclosed!r}"
            return f"unexpected {tok.text!r}"
        if self._new_statement_starts(recognizer, tok):
            return (
                f"unexpected {_describe(tok)}: the statement before it is complete "
                "and a new one starts here (one statement per line: a line break "
                "or ';' is missing)"
            )
        return f"unexpected {_describe(tok)}" + self._hint(recognizer, e)

    def _new_statement_starts(self, recognizer, tok: Token) -> bool:
        """True if a statement could end before *tok* and the rest is one.

        Two statements run together on a line (``V> = R*A1>W> = 2*V>``): the
        statement is complete before ``W>``, and ``W> = 2*V>`` parses as an
        assignment, declaration or command of its own (a bare expression
        does not count: ``x = a b`` gets the plain message).
        """
        if not isinstance(recognizer, AutolevParser) or tok.start < 0:
            return False
        try:
            expected = recognizer.getExpectedTokens()
        except Exception:  # ANTLR cannot tell in this state
            return False
        if not expected.__contains__(_P.NEWLINE):
            return False
        tokens = self.stream.tokens
        k = tok.tokenIndex
        while k < len(tokens) and tokens[k].type not in (_P.NEWLINE, Token.EOF):
            k += 1
        stream = tok.getInputStream()
        end = tokens[k].start if k < len(tokens) and tokens[k].start >= 0 else None
        stop = (end if end is not None else stream.size) - 1
        rest = stream.getText(tok.start, stop)
        parser = AutolevParser(CommonTokenStream(Lexer(InputStream(rest))))
        parser.removeErrorListeners()
        counter = _CountingListener()
        parser.addErrorListener(counter)
        try:
            ctx = parser.statement()
        except Exception:  # only a hint: never let the trial parse fail
            return False
        if counter.count or ctx.stmt() is None:
            return False
        return ctx.stmt().exprStmt() is None

    def _after_operator(self, tok: Token) -> bool:
        """True if the default-channel token before *tok* needs an operand."""
        index = tok.tokenIndex - 1
        tokens = self.stream.tokens
        while index >= 0 and tokens[index].channel != Token.DEFAULT_CHANNEL:
            index -= 1
        return index >= 0 and tokens[index].type in _NEEDS_OPERAND

    def _unclosed(self, tok: Token) -> str | None:
        """Closer of the innermost bracket still open before *tok* on its line."""
        tokens = self.stream.tokens
        start = tok.tokenIndex
        while start > 0 and tokens[start - 1].type != _P.NEWLINE:
            start -= 1
        stack: list[str] = []
        for t in tokens[start : tok.tokenIndex]:
            if t.type in _OPENERS:
                stack.append(_OPENERS[t.type])
            elif t.type in _CLOSERS and stack:
                stack.pop()
        return stack[-1] if stack else None

    @staticmethod
    def _hint(recognizer, e) -> str:
        if not isinstance(recognizer, AutolevParser):
            return ""
        if e is not None and not isinstance(e, InputMismatchException):
            return ""
        expected = recognizer.getExpectedTokens()
        names = [
            recognizer.literalNames[t]
            for t in expected
            if 0 < t < len(recognizer.literalNames)
            and recognizer.literalNames[t] != "<INVALID>"
        ]
        if len(names) == 1 and len(list(expected)) == 1:
            return f"; expected {names[0]}"
        return ""


class _CountingListener(ErrorListener):
    """Counts syntax errors (a trial parse that must not report them)."""

    def __init__(self) -> None:
        self.count = 0

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):
        self.count += 1


# ----------------------------------------------------------------- IR builder


class _IRBuilder(AutolevVisitor):
    """Build IR nodes from the ANTLR parse tree, one method per rule."""

    def __init__(
        self,
        filename: str,
        logical: LogicalText,
        lines: tuple[str, ...],
        stream: CommonTokenStream,
    ) -> None:
        self.filename = filename
        self.logical = logical
        self.source = logical.text
        self.lines = lines
        self.tokens = stream.tokens
        #: Errors found while building statements (one per statement).
        self.errors: list[AutolevError] = []
        #: names made by the index ranges so far (MAX_INDEXED_NAMES_PER_FILE)
        self._indexed_names = 0

    # -- spans and text -----------------------------------------------------

    def _span(self, start: Token, stop: Token | None = None) -> ir.Span:
        last = stop if stop is not None else start
        if 0 <= last.stop < len(self.logical.origin):
            end_line, end_col = self.logical.origin[last.stop]
            end_col += 1
        else:
            end_line, end_col = _token_end(last)
        return ir.Span(self.filename, start.line, start.column + 1, end_line, end_col)

    def _ctx_span(self, ctx) -> ir.Span:
        return self._span(ctx.start, ctx.stop)

    def _join(self, first: ir.Span, last: ir.Span) -> ir.Span:
        return ir.Span(
            self.filename, first.line, first.col, last.end_line, last.end_col
        )

    def _text(self, ctx) -> str:
        return self.source[ctx.start.start : ctx.stop.stop + 1]

    def _error(self, message: str, tok: Token) -> ParseError:
        span = self._span(tok)
        line_text = self.lines[tok.line - 1] if tok.line <= len(self.lines) else ""
        return ParseError(message, span, line_text=line_text)

    # -- script, comments ---------------------------------------------------

    def build(
        self, parsed: list[tuple[AutolevParser.StatementContext | None, Token]]
    ) -> ir.Script:
        """The script of the statements that parsed (``None``: a syntax error)."""
        statements: list[ir.Stmt] = []
        ended_by_semi = False  # the line's last statement ended in ';'
        for ctx, end in parsed:
            semi, ended_by_semi = ended_by_semi, end.type == _P.SEMI
            if ctx is None:
                continue
            stmt = ctx.stmt()
            if stmt is not None:
                try:
                    statements.append(self._statement(stmt, end))
                except AutolevError as exc:
                    self.errors.append(exc)
            elif end.type != _P.SEMI and not semi:
                comment = self._comment_line(end)
                if comment is not None:
                    statements.append(comment)
        span = ir.Span(
            self.filename,
            1,
            1,
            max(len(self.lines), 1),
            len(self.lines[-1]) + 1 if self.lines else 1,
        )
        return ir.Script(span, tuple(statements), lines=self.lines)

    def _statement(self, ctx: AutolevParser.StmtContext, end: Token) -> ir.Stmt:
        node = self.visit(ctx)
        if not isinstance(node, ir.Stmt):  # never drop a statement silently
            raise self._error("cannot read this statement", ctx.start)
        comment = self._trailing_comment(ctx.start.tokenIndex, end.tokenIndex)
        if comment is None and end.type == _P.SEMI:
            comment = self._comment_after(end.tokenIndex)
        if comment is not None:
            node = dataclasses.replace(node, comment=comment)
        return node

    def _comment_after(self, index: int) -> str | None:
        """The comment ending a line whose last statement ends in ``;``."""
        for tok in self.tokens[index + 1 :]:
            if tok.type == _P.COMMENT:
                return tok.text[1:].strip()
            if tok.channel == Token.DEFAULT_CHANNEL:
                return None
        return None

    def _trailing_comment(self, first: int, end: int) -> str | None:
        parts: list[str] = []
        found = False
        for tok in self.tokens[first:end]:
            if tok.type == _P.COMMENT:
                found = True
                parts.append(tok.text[1:].strip())
        if not found:
            return None
        return " ".join(p for p in parts if p)

    def _comment_line(self, end: Token) -> ir.Comment | None:
        first = end.tokenIndex
        while first > 0 and self.tokens[first - 1].channel != Token.DEFAULT_CHANNEL:
            first -= 1
        for tok in self.tokens[first : end.tokenIndex]:
            if tok.type == _P.COMMENT:
                text = tok.text
                code = text.startswith("%%")
                body = text[2:] if code else text[1:]
                return ir.Comment(self._span(tok), body.strip(), code_comment=code)
        return None

    # -- statements -----------------------------------------------------------

    def visitStmt(self, ctx: AutolevParser.StmtContext) -> ir.Stmt:
        return self.visit(ctx.getChild(0))

    def visitAssignment(self, ctx: AutolevParser.AssignmentContext) -> ir.Stmt:
        target = self.visit(ctx.lvalue())
        value = self.visit(ctx.expr())
        group = self._units_group(ctx, target, value)
        if group is not None:
            return group
        return ir.Assign(self._ctx_span(ctx), target, ctx.op.text, value)

    def _units_group(
        self, ctx: AutolevParser.AssignmentContext, target: ir.Expr, value: ir.Expr
    ) -> ir.Stmt | None:
        """``Units [A, B] = M`` reads like an assignment to an element of a
        matrix ``UNITS``; it is the Units command with a group of names (the
        grammar's ``settingGroup``, which a line of more than one group
        reaches directly).  None for any other assignment."""
        if not (
            isinstance(target, ir.Element)
            and target.base.name.upper() == "UNITS"
            and ctx.op.text == "="
        ):
            return None
        names = target.indices
        if not all(isinstance(n, ir.Name) and not n.primes for n in names):
            return None
        factors = _unit_factors(value)
        if factors is None:
            raise self._error("Units [A, B] = ... takes a unit here", ctx.expr().start)
        text = self._text(ctx.expr())
        span = self._ctx_span(ctx.expr())
        items = tuple(
            ir.Equation(
                n.span,
                ir.Name(n.span, n.name, 0),
                (
                    ir.Name(span, text)
                    if isinstance(value, ir.Name)
                    else ir.UnitExpr(span, factors, text)
                ),
            )
            for n in names
        )
        return ir.ListCommand(self._ctx_span(ctx), "UNITS", items)

    def visitElementTarget(self, ctx: AutolevParser.ElementTargetContext):
        base = self._name(ctx.ident())
        return ir.Element(self._ctx_span(ctx), base, self.visit(ctx.exprList()))

    def visitNameTarget(self, ctx: AutolevParser.NameTargetContext) -> ir.Name:
        return ir.Name(self._ctx_span(ctx), ctx.ident().getText(), len(ctx.PRIME()))

    def visitExprStmt(self, ctx: AutolevParser.ExprStmtContext) -> ir.ExprStmt:
        return ir.ExprStmt(self._ctx_span(ctx), self.visit(ctx.expr()))

    def visitDeclaration(self, ctx: AutolevParser.DeclarationContext):
        keyword = _DECL_KEYWORDS[ctx.declKeyword().start.type]
        items = [self.visit(ctx.firstDeclItem())]
        items.extend(self.visit(item) for item in ctx.declItem())
        motion = ctx.declKeyword().getText().upper().startswith("MOTION")
        return ir.Declaration(self._ctx_span(ctx), keyword, tuple(items), motion)

    def visitFirstDeclItem(self, ctx: AutolevParser.FirstDeclItemContext):
        return self._decl_item(ctx, self.visit(ctx.declHead()), ctx.declTail())

    def visitDeclItem(self, ctx: AutolevParser.DeclItemContext) -> ir.DeclItem:
        return self._decl_item(ctx, self.visit(ctx.expr()), ctx.declTail())

    def _decl_item(self, ctx, target: ir.Expr, tail) -> ir.DeclItem:
        sign: str | None = None
        values: list[ir.Expr] = []
        value_signs: list[str | None] = []
        for child in tail.children or ():
            if isinstance(child, AutolevParser.SignContext):
                if values:
                    value_signs[-1] = child.getText()
                else:
                    sign = child.getText()
            elif isinstance(child, AutolevParser.ExprContext):
                values.append(self.visit(child))
                value_signs.append(None)
        if not any(value_signs):
            value_signs = []
        return ir.DeclItem(
            self._ctx_span(ctx), target, tuple(values), sign, tuple(value_signs)
        )

    def visitDeclHead(self, ctx: AutolevParser.DeclHeadContext) -> ir.Expr:
        span = self._ctx_span(ctx)
        if ctx.NUMBER() is not None:
            return ir.Number(span, ctx.getText())
        stem = ctx.ident(0).getText()
        primes = len(ctx.PRIME())
        if ctx.indexBraces() is not None:
            ranges = self.visit(ctx.indexBraces())
            suffix = self._suffix(ctx.indexBraces(), ctx.suffix)
            return ir.IndexedNames(span, stem, ranges, primes, suffix)
        if ctx.basis is not None:
            # ``Inertia C(B), ...``: C's inertia in B's basis.
            basis = self._name(ctx.basis)
            return ir.Call(span, stem, (basis,))
        return ir.Name(span, stem, primes)

    def _suffix(self, braces, suffix) -> str:
        """The name part after ``{...}`` (``RRF{2}O``); it must touch the brace."""
        if suffix is None:
            return ""
        if suffix.start.start != braces.stop.stop + 1:
            raise self._error(
                "write the suffix right after the braces, as in RRF{2}O",
                suffix.start,
            )
        return suffix.getText()

    def visitInputStmt(self, ctx: AutolevParser.InputStmtContext) -> ir.InputStmt:
        items = tuple(self.visit(item) for item in ctx.inputItem())
        return ir.InputStmt(self._ctx_span(ctx), items)

    def visitInputItem(self, ctx: AutolevParser.InputItemContext) -> ir.InputItem:
        unit = self.visit(ctx.unit()) if ctx.unit() is not None else None
        return ir.InputItem(
            self._ctx_span(ctx),
            self.visit(ctx.inputTarget()),
            self.visit(ctx.expr()),
            unit,
        )

    def visitInputElement(self, ctx: AutolevParser.InputElementContext):
        base = self._name(ctx.ident())
        return ir.Element(self._ctx_span(ctx), base, self.visit(ctx.exprList()))

    def visitInputIndexed(self, ctx: AutolevParser.InputIndexedContext):
        ranges = self.visit(ctx.indexBraces())
        return ir.IndexedNames(
            self._ctx_span(ctx), ctx.ident().getText(), ranges, len(ctx.PRIME())
        )

    def visitInputName(self, ctx: AutolevParser.InputNameContext) -> ir.Name:
        return ir.Name(self._ctx_span(ctx), ctx.ident().getText(), len(ctx.PRIME()))

    def visitOutputStmt(self, ctx: AutolevParser.OutputStmtContext):
        items = tuple(self.visit(item) for item in ctx.outputItem())
        return ir.OutputStmt(self._ctx_span(ctx), items)

    def visitOutputItem(self, ctx: AutolevParser.OutputItemContext):
        unit = self.visit(ctx.unit()) if ctx.unit() is not None else None
        return ir.OutputItem(self._ctx_span(ctx), self.visit(ctx.expr()), unit)

    def visitUnitSystemStmt(self, ctx: AutolevParser.UnitSystemStmtContext):
        units = tuple(ident.getText() for ident in ctx.ident())
        return ir.UnitSystemStmt(self._ctx_span(ctx), units)

    def visitUnit(self, ctx: AutolevParser.UnitContext) -> ir.UnitExpr:
        factors = []
        divide = False
        for child in ctx.children:
            if isinstance(child, AutolevParser.UnitOpContext):
                divide = child.DIV() is not None
            else:
                parts = self.visit(child)
                # ``A/B.C`` is ``A/B*C``: the dot multiplies, left to right
                word, power = parts[0]
                factors.append((word, -power if divide else power))
                factors.extend(parts[1:])
        return ir.UnitExpr(self._ctx_span(ctx), tuple(factors), self._text(ctx))

    def visitUnitFactor(
        self, ctx: AutolevParser.UnitFactorContext
    ) -> list[tuple[str, int]]:
        """``M^2`` -> [("M", 2)]; ``KG.M^2`` (a dot multiplies) ->
        [("KG", 1), ("M", 2)], ``M/KG.S`` -> [("M", 1), ("KG", -1), ("S", 1)]
        (the lexer reads a dotted word as one token): the power is the last
        word's."""
        if ctx.ident() is not None:
            parts = [(ctx.ident().getText(), 1)]
        else:
            token = ctx.FILENAME().symbol
            if not _DOTTED_UNIT.fullmatch(token.text):
                raise self._error(f"cannot read unit '{token.text}'", token)
            parts = [
                (word, -1 if op == "/" else 1)
                for op, word in re.findall(r"([./]?)([A-Za-z_]\w*)", token.text)
            ]
        number = ctx.NUMBER()
        if number is not None:
            if not number.getText().isdigit():
                raise self._error("unit exponents must be integers", number.symbol)
            power = int(number.getText())
            power = -power if ctx.MINUS() is not None else power
            word, sign = parts[-1]
            parts[-1] = (word, sign * power)
        return parts

    def visitCodeStmt(self, ctx: AutolevParser.CodeStmtContext) -> ir.CodeStmt:
        args = self.visit(ctx.argList()) if ctx.argList() is not None else ()
        sweep = self.visit(ctx.sweep()) if ctx.sweep() is not None else None
        name = ctx.fileName()
        words = ctx.ident()
        return ir.CodeStmt(
            self._ctx_span(ctx),
            words[0].getText().upper(),
            args,
            sweep,
            self._file_name(name) if name is not None else None,
            tuple(w.getText().upper() for w in words[1:]),
        )

    def visitSweep(self, ctx: AutolevParser.SweepContext) -> ir.Sweep:
        unit = self.visit(ctx.unit()) if ctx.unit() is not None else None
        start, stop, step = (self.visit(e) for e in ctx.expr())
        return ir.Sweep(
            self._ctx_span(ctx), self._name(ctx.ident()), unit, start, stop, step
        )

    def visitFileCommand(self, ctx: AutolevParser.FileCommandContext):
        command = ctx.getChild(0).getText().upper()
        return ir.FileCommand(
            self._ctx_span(ctx), command, self._file_name(ctx.fileName())
        )

    def _file_name(self, ctx: AutolevParser.FileNameContext) -> str:
        """The file name of ``Save``, ``Run`` or ``Code``, put together from
        its pieces (``../lib/kin.al``), which must touch."""
        pieces = self.tokens[ctx.start.tokenIndex : ctx.stop.tokenIndex + 1]
        for before, tok in zip(pieces, pieces[1:], strict=False):
            if tok.start != before.stop + 1:
                raise self._error("a file name cannot hold a blank", tok)
        for tok in pieces:
            if tok.type == _P.ERRCHAR and tok.text not in _FILE_CHARACTERS:
                raise self._error(f"unexpected character {tok.text!r}", tok)
        return "".join(tok.text for tok in pieces)

    def visitSetting(self, ctx: AutolevParser.SettingContext) -> ir.Stmt:
        name = ctx.ID().getText().upper()
        args = ctx.settingArg()
        plain = len(args) == 1 and (
            isinstance(args[0], AutolevParser.SettingNumberContext)
            or (
                args[0].exprList() is None
                and not args[0].PRIME()
                and args[0].settingWord() is None
            )
        )
        if plain and name not in LIST_COMMANDS:
            return ir.Setting(self._ctx_span(ctx), name, args[0].getText())
        items: list[ir.Expr] = []
        for a in args:
            if isinstance(a, AutolevParser.SettingGroupContext):
                if name != "UNITS":
                    raise self._error(
                        "a bracketed group of names ([A, B] = M) belongs to Units",
                        a.start,
                    )
                items.extend(self._setting_group(a))
            else:
                items.append(self.visit(a))
        return ir.ListCommand(self._ctx_span(ctx), name, tuple(items))

    def _setting_group(self, ctx: AutolevParser.SettingGroupContext) -> list[ir.Expr]:
        """``[A, B] = M`` of ``Units``: ``A = M, B = M``, each name with its
        own span and its own node of the unit (nodes are never shared)."""
        return [
            ir.Equation(
                self._ctx_span(ident),
                ir.Name(self._ctx_span(ident), ident.getText(), 0),
                self._setting_value(ctx.settingWord()),
            )
            for ident in ctx.ident()
        ]

    def visitSettingName(self, ctx: AutolevParser.SettingNameContext) -> ir.Expr:
        span = self._ctx_span(ctx)
        name = ir.Name(
            self._ctx_span(ctx.ident()), ctx.ident().getText(), len(ctx.PRIME())
        )
        if ctx.exprList() is not None:
            base = dataclasses.replace(name, primes=0)
            name = ir.Element(span, base, self.visit(ctx.exprList()))
        word = ctx.settingWord()
        if word is None:
            return name
        return ir.Equation(span, name, self._setting_value(word))

    def _setting_value(self, word: AutolevParser.SettingWordContext) -> ir.Expr:
        """The value after ``=`` in a setting: a number, a unit word, or a
        product or quotient of units."""
        value_span = self._ctx_span(word)
        unit = word.unit()
        value: ir.Expr
        if unit is None:
            value = ir.Number(value_span, word.getText())
        elif (
            len(unit.unitFactor()) == 1
            and unit.unitFactor(0).NUMBER() is None
            and unit.unitFactor(0).ident() is not None
        ):
            value = ir.Name(value_span, word.getText())
        else:  # ``Units VX=M/S``
            value = self.visit(unit)
        return value

    def visitSettingNumber(self, ctx: AutolevParser.SettingNumberContext) -> ir.Expr:
        return ir.Number(self._ctx_span(ctx), ctx.getText())

    # -- expressions ------------------------------------------------------------

    def visitExpr(self, ctx: AutolevParser.ExprContext) -> ir.Expr:
        return self.visit(ctx.additive())

    def _fold(self, ctx) -> ir.Expr:
        """Left-associative chain ``operand (op operand)*``."""
        children = ctx.children
        if len(children) > 2 * _LONG_SUM and children[1].getText() in "+-":
            return self._balanced_sum(children)
        result = self.visit(children[0])
        for i in range(1, len(children), 2):
            right = self.visit(children[i + 1])
            span = self._join(result.span, right.span)
            result = ir.BinOp(span, children[i].getText(), result, right)
        return result

    def _balanced_sum(self, children) -> ir.Expr:
        """A long sum ``a + b - c + ...`` as a balanced tree of ``+`` with
        ``-c`` negated: depth log2(n) instead of n, so later passes (and
        Python's compiler) need no deep recursion and time stays linear."""
        nodes = [self.visit(children[0])]
        for i in range(1, len(children), 2):
            term = self.visit(children[i + 1])
            if children[i].getText() == "-":
                term = ir.UnaryOp(term.span, "-", term)
            nodes.append(term)
        while len(nodes) > 1:
            paired = [
                ir.BinOp(self._join(a.span, b.span), "+", a, b)
                for a, b in zip(nodes[::2], nodes[1::2], strict=False)
            ]
            nodes = paired + ([nodes[-1]] if len(nodes) % 2 else [])
        return nodes[0]

    def visitAdditive(self, ctx: AutolevParser.AdditiveContext) -> ir.Expr:
        return self._fold(ctx)

    def visitMultiplicative(self, ctx: AutolevParser.MultiplicativeContext):
        return self._fold(ctx)

    def visitSigned(self, ctx: AutolevParser.SignedContext) -> ir.UnaryOp:
        operand = self.visit(ctx.unary())
        return ir.UnaryOp(self._ctx_span(ctx), ctx.addOp().getText(), operand)

    def visitUnsigned(self, ctx: AutolevParser.UnsignedContext) -> ir.Expr:
        return self.visit(ctx.power())

    def visitPower(self, ctx: AutolevParser.PowerContext) -> ir.Expr:
        base = self.visit(ctx.atom())
        if ctx.CARET() is None:
            return base
        exponent = self.visit(ctx.unary())
        return ir.BinOp(self._ctx_span(ctx), "^", base, exponent)

    def visitNumber(self, ctx: AutolevParser.NumberContext) -> ir.Number:
        return ir.Number(self._ctx_span(ctx), ctx.getText())

    def visitString(self, ctx: AutolevParser.StringContext) -> ir.String:
        return ir.String(self._ctx_span(ctx), ctx.getText()[1:-1])

    def visitSpecial(self, ctx: AutolevParser.SpecialContext) -> ir.Name:
        return ir.Name(self._ctx_span(ctx), ctx.getText())

    def visitCall(self, ctx: AutolevParser.CallContext) -> ir.Call:
        args = self.visit(ctx.argList()) if ctx.argList() is not None else ()
        return ir.Call(self._ctx_span(ctx), ctx.ident().getText(), args)

    def visitElement(self, ctx: AutolevParser.ElementContext) -> ir.Element:
        base = self._name(ctx.ident())
        return ir.Element(self._ctx_span(ctx), base, self.visit(ctx.exprList()))

    def visitIndexedNames(self, ctx: AutolevParser.IndexedNamesContext):
        ranges = self.visit(ctx.indexBraces())
        suffix = self._suffix(ctx.indexBraces(), ctx.suffix)
        return ir.IndexedNames(
            self._ctx_span(ctx),
            ctx.ident(0).getText(),
            ranges,
            len(ctx.PRIME()),
            suffix,
        )

    def visitName(self, ctx: AutolevParser.NameContext) -> ir.Name:
        return ir.Name(self._ctx_span(ctx), ctx.ident().getText(), len(ctx.PRIME()))

    def visitMatrix(self, ctx: AutolevParser.MatrixContext) -> ir.MatrixLit:
        rows = tuple(self.visit(row) for row in ctx.matrixRow())
        return ir.MatrixLit(self._ctx_span(ctx), rows)

    def visitParens(self, ctx: AutolevParser.ParensContext) -> ir.Expr:
        # The node keeps its own type but its span includes the parentheses,
        # so that span_text() of an enclosing node is always well formed.
        inner = self.visit(ctx.expr())
        return dataclasses.replace(inner, span=self._ctx_span(ctx))

    def visitMatrixRow(self, ctx: AutolevParser.MatrixRowContext):
        return tuple(self.visit(e) for e in ctx.expr())

    def visitExprList(self, ctx: AutolevParser.ExprListContext):
        return tuple(self.visit(e) for e in ctx.expr())

    def visitArgList(self, ctx: AutolevParser.ArgListContext):
        return tuple(self.visit(a) for a in ctx.arg())

    def visitArg(self, ctx: AutolevParser.ArgContext) -> ir.Expr:
        exprs = [self.visit(e) for e in ctx.expr()]
        if ctx.COLON() is not None:
            lo, hi = exprs[-2], exprs[-1]
            exprs[-2:] = [ir.Range(self._join(lo.span, hi.span), lo, hi)]
        if ctx.EQ() is not None:
            return ir.Equation(self._ctx_span(ctx), exprs[0], exprs[1])
        return exprs[0]

    def visitIndexBraces(self, ctx: AutolevParser.IndexBracesContext):
        ranges = tuple(self.visit(r) for r in ctx.indexRange())
        count = 1
        for lo, hi in ranges:
            count *= hi - lo + 1
        self._indexed_names += count
        if count > MAX_INDEXED_NAMES:
            raise self._error(
                f"the index range {ctx.getText()} makes {count} names; al2py allows at most "
                f"{MAX_INDEXED_NAMES} in one index range",
                ctx.start,
            )
        if self._indexed_names > MAX_INDEXED_NAMES_PER_FILE:
            raise self._error(
                f"the index range {ctx.getText()} brings the names of this file's index ranges "
                f"beyond {MAX_INDEXED_NAMES_PER_FILE}, al2py's limit",
                ctx.start,
            )
        return ranges

    def visitIndexRange(self, ctx: AutolevParser.IndexRangeContext):
        bounds = []
        for number in ctx.NUMBER():
            if not number.getText().isdigit():
                raise self._error("index bounds must be integers", number.symbol)
            bounds.append(int(number.getText()))
        lo, hi = bounds if len(bounds) == 2 else (1, bounds[0])
        if lo > hi:
            raise self._error(f"empty index range {lo}:{hi}", ctx.start)
        return lo, hi

    def _name(self, ident: AutolevParser.IdentContext) -> ir.Name:
        return ir.Name(self._ctx_span(ident), ident.getText())

    def visitTerminal(self, node: TerminalNode):  # pragma: no cover - safety net
        raise InternalError(f"unexpected terminal {node.getText()!r}")


def _unit_factors(e: ir.Expr) -> tuple[tuple[str, int], ...] | None:
    """The (word, power) factors of a unit read as an expression (``M``,
    ``M/S^2``, ``KG*M``), None if ``e`` is not one."""
    if isinstance(e, ir.Name) and not e.primes:
        return ((e.name, 1),)
    if isinstance(e, ir.BinOp) and e.op == "^":
        base = _unit_factors(e.left)
        if (
            base is not None
            and len(base) == 1
            and isinstance(e.right, ir.Number)
            and e.right.text.isdigit()
        ):
            return ((base[0][0], base[0][1] * int(e.right.text)),)
        return None
    if isinstance(e, ir.BinOp) and e.op in ("*", "/"):
        left, right = _unit_factors(e.left), _unit_factors(e.right)
        if left is None or right is None:
            return None
        sign = -1 if e.op == "/" else 1
        return left + tuple((w, sign * p) for w, p in right)
    return None
