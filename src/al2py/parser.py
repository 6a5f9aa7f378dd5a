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
from collections.abc import Sequence

from antlr4 import CommonTokenStream, InputStream, Token
from antlr4.error.ErrorListener import ErrorListener
from antlr4.error.Errors import InputMismatchException
from antlr4.tree.Tree import TerminalNode

from . import ir
from ._antlr.AutolevLexer import AutolevLexer
from ._antlr.AutolevParser import AutolevParser
from ._antlr.AutolevVisitor import AutolevVisitor
from .errors import AutolevError, InternalError, ParseError

__all__ = ["parse", "span_text"]

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


# ------------------------------------------------------------------ public API


def parse(text: str, filename: str = "<input>") -> ir.Script:
    """Parse Autolev source *text* into an :class:`ir.Script`.

    Raises :class:`ParseError` for the first syntax error.  Any other
    exception would be a bug and is reported as :class:`InternalError`.
    """
    lines = tuple(text.splitlines())
    # Join with plain newlines so ANTLR's line numbers agree with `lines`.
    source = "\n".join(lines)
    try:
        return _parse(source, filename, lines)
    except AutolevError:
        raise
    except RecursionError:
        from .static_checks import deepest_nesting

        span = deepest_nesting(filename, lines)
        raise ParseError(
            "expression nested too deeply",
            span,
            line_text=lines[span.line - 1] if lines else "",
        ) from None
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


def _parse(source: str, filename: str, lines: tuple[str, ...]) -> ir.Script:
    lexer = AutolevLexer(InputStream(source))
    stream = CommonTokenStream(lexer)
    listener = _ErrorListener(filename, lines, stream)
    lexer.removeErrorListeners()
    lexer.addErrorListener(listener)
    stream.fill()
    parser = AutolevParser(stream)
    parser.removeErrorListeners()
    parser.addErrorListener(listener)
    tree = parser.script()
    builder = _IRBuilder(filename, source, lines, stream)
    return builder.visitScript(tree)


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


class _ErrorListener(ErrorListener):
    """Raise :class:`ParseError` for the first error ANTLR reports."""

    def __init__(
        self, filename: str, lines: tuple[str, ...], stream: CommonTokenStream
    ) -> None:
        self.filename = filename
        self.lines = lines
        self.stream = stream

    def syntaxError(self, recognizer, offendingSymbol, line, column, msg, e):
        if not isinstance(offendingSymbol, Token):  # lexer error (no token)
            self._raise("unexpected character", line, column + 1)
        tok = offendingSymbol
        message = self._message(recognizer, tok, e)
        if tok.type == Token.EOF:
            line, col = self._end_of_input(tok)
        else:
            line, col = tok.line, tok.column + 1
        self._raise(message, line, col)

    def _raise(self, message: str, line: int, col: int) -> None:
        text = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        span = ir.Span(self.filename, line, col, line, col + 1)
        raise ParseError(message, span, line_text=text)

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
        return f"unexpected {_describe(tok)}" + self._hint(recognizer, e)

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


# ----------------------------------------------------------------- IR builder


class _IRBuilder(AutolevVisitor):
    """Build IR nodes from the ANTLR parse tree, one method per rule."""

    def __init__(
        self,
        filename: str,
        source: str,
        lines: tuple[str, ...],
        stream: CommonTokenStream,
    ) -> None:
        self.filename = filename
        self.source = source
        self.lines = lines
        self.tokens = stream.tokens

    # -- spans and text -----------------------------------------------------

    def _span(self, start: Token, stop: Token | None = None) -> ir.Span:
        end_line, end_col = _token_end(stop if stop is not None else start)
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

    def visitScript(self, ctx: AutolevParser.ScriptContext) -> ir.Script:
        statements: list[ir.Stmt] = []
        pending: AutolevParser.StmtContext | None = None
        for child in ctx.children or ():
            if isinstance(child, AutolevParser.StmtContext):
                pending = child
                continue
            end = child.symbol  # NEWLINE or EOF
            if pending is not None:
                statements.append(self._statement(pending, end))
                pending = None
            else:
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
        comment = self._trailing_comment(ctx.start.tokenIndex, end.tokenIndex)
        if comment is not None:
            node = dataclasses.replace(node, comment=comment)
        return node

    def _trailing_comment(self, first: int, end: int) -> str | None:
        parts: list[str] = []
        found = False
        for tok in self.tokens[first:end]:
            if tok.type == _P.COMMENT:
                found = True
                parts.append(tok.text[1:].strip())
            elif tok.type == _P.CONTINUATION and "%" in tok.text:
                found = True
                parts.append(tok.text[tok.text.index("%") + 1 :].strip())
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

    def visitAssignment(self, ctx: AutolevParser.AssignmentContext) -> ir.Assign:
        target = self.visit(ctx.lvalue())
        value = self.visit(ctx.expr())
        return ir.Assign(self._ctx_span(ctx), target, ctx.op.text, value)

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
        stem = ctx.ident().getText()
        primes = len(ctx.PRIME())
        if ctx.indexBraces() is not None:
            ranges = self.visit(ctx.indexBraces())
            return ir.IndexedNames(span, stem, ranges, primes)
        return ir.Name(span, stem, primes)

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
                word, power = self.visit(child)
                factors.append((word, -power if divide else power))
        return ir.UnitExpr(self._ctx_span(ctx), tuple(factors), self._text(ctx))

    def visitUnitFactor(self, ctx: AutolevParser.UnitFactorContext):
        word = ctx.ident().getText()
        number = ctx.NUMBER()
        if number is None:
            return word, 1
        if not number.getText().isdigit():
            raise self._error("unit exponents must be integers", number.symbol)
        power = int(number.getText())
        return word, -power if ctx.MINUS() is not None else power

    def visitCodeStmt(self, ctx: AutolevParser.CodeStmtContext) -> ir.CodeStmt:
        args = self.visit(ctx.argList()) if ctx.argList() is not None else ()
        sweep = self.visit(ctx.sweep()) if ctx.sweep() is not None else None
        name = ctx.fileName()
        return ir.CodeStmt(
            self._ctx_span(ctx),
            ctx.ident().getText().upper(),
            args,
            sweep,
            name.getText() if name is not None else None,
        )

    def visitSweep(self, ctx: AutolevParser.SweepContext) -> ir.Sweep:
        unit = self.visit(ctx.unit()) if ctx.unit() is not None else None
        start, stop, step = (self.visit(e) for e in ctx.expr())
        return ir.Sweep(
            self._ctx_span(ctx), self._name(ctx.ident()), unit, start, stop, step
        )

    def visitFileCommand(self, ctx: AutolevParser.FileCommandContext):
        command = ctx.getChild(0).getText().upper()
        return ir.FileCommand(self._ctx_span(ctx), command, ctx.fileName().getText())

    def visitSetting(self, ctx: AutolevParser.SettingContext) -> ir.Setting:
        return ir.Setting(
            self._ctx_span(ctx),
            ctx.ID().getText().upper(),
            ctx.settingValue().getText(),
        )

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
        return ir.IndexedNames(
            self._ctx_span(ctx), ctx.ident().getText(), ranges, len(ctx.PRIME())
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
        return tuple(self.visit(r) for r in ctx.indexRange())

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
