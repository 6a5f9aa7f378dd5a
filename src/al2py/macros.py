"""User-defined commands: Autolev ``.a`` and ``.r`` macro files (tutorial §6.4).

A macro file holds Autolev text with placeholders::

    %POWER.A                     <- comment lines are help text; dropped
    #2#SQ = (#1#)^2              <- #n# is the source text of argument n
    #2#CUBE = (#1#)^3

plus ``#NUM_ARGS#``, ``#Newtonian#`` and ``#DEGREES#``, and a tiny
preprocessor language::

    if( #NUM_ARGS# != 2 )
      { ECHO(\\k\\a"Error: wrong number of arguments"\\p\\n); }
    else
      { #1# + #2# }

:func:`find_macro` locates ``name.a``/``name.r`` files and
:func:`expand_macro` turns a file's text plus argument texts into plain
Autolev text (to be parsed by :mod:`al2py.parser`) and the ECHO messages.
"""

from __future__ import annotations

import dataclasses
import os
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from al2py_runtime.vocabulary import BUILTINS, by_spelling

from . import ir
from .errors import MacroError, ParseError
from .ir import map_expr
from .lines import split_lines

__all__ = ["MacroExpansion", "find_macro", "expand_macro", "check_confined"]


@dataclass(frozen=True, slots=True)
class MacroExpansion:
    """Result of :func:`expand_macro`: Autolev text and ECHO messages."""

    text: str
    echoes: tuple[str, ...] = ()


# ------------------------------------------------------------------ lookup


def find_macro(
    name: str,
    kind: str,
    script_dir: Path,
    autolevpath: str | None = None,
) -> Path | None:
    """Find ``<name>.<kind>`` (``kind`` is ``"a"`` or ``"r"``), ignoring case.

    Looks in *script_dir*, then in each directory of *autolevpath*
    (``os.pathsep``-separated; defaults to ``$AUTOLEVPATH``).
    """
    if kind.lower() not in ("a", "r"):
        raise ValueError(f"macro kind must be 'a' or 'r', not {kind!r}")
    if autolevpath is None:
        autolevpath = os.environ.get("AUTOLEVPATH")
    wanted = f"{name}.{kind}"
    dirs = [Path(script_dir)]
    if autolevpath:
        dirs.extend(Path(d) for d in autolevpath.split(os.pathsep) if d)
    for directory in dirs:
        found = _find_in(directory, wanted)
        if found is not None:
            return found
    return None


def _find_in(directory: Path, wanted: str) -> Path | None:
    exact = directory / wanted
    if exact.is_file():
        return exact
    try:
        entries = sorted(directory.iterdir())
    except OSError:  # missing or unreadable directory
        return None
    lowered = wanted.lower()
    for entry in entries:
        if entry.name.lower() == lowered and entry.is_file():
            return entry
    return None


def check_confined(
    path: Path, given: str, script_dir: Path, autolevpath: str | None, span
) -> None:
    """A ``RUN`` file (or macro) must resolve inside the script's folder tree
    or a folder on ``AUTOLEVPATH`` (``RUN ../../etc/x.al`` is refused), so a
    script cannot pull in files from anywhere on disk."""
    if autolevpath is None:
        autolevpath = os.environ.get("AUTOLEVPATH")
    roots = [Path(script_dir)]
    roots += [Path(d) for d in (autolevpath or "").split(os.pathsep) if d]
    try:
        target = Path(path).resolve()
        if any(target.is_relative_to(root.resolve()) for root in roots):
            return
    except (OSError, RuntimeError):  # a symlink loop
        pass
    raise MacroError(
        f"RUN {given}: the file lies outside the script's folder and "
        "AUTOLEVPATH; copy it beside the script or add its folder to AUTOLEVPATH",
        span,
    )


# --------------------------------------------------------------- expansion

_PLACEHOLDER = re.compile(r"#([A-Za-z0-9_]*)#")
_IF = re.compile(r"(?<![A-Za-z0-9_#])if\s*\(", re.IGNORECASE)
_ELSE = re.compile(r"else(?![A-Za-z0-9_])", re.IGNORECASE)
_ECHO = re.compile(r"(?<![A-Za-z0-9_#])echo\s*\(", re.IGNORECASE)
_COND = re.compile(r"^\s*(.*?)\s*(==|!=|<=|>=|<|>)\s*(.*?)\s*$", re.DOTALL)
_CONTROL = re.compile(r"\\[kapn]", re.IGNORECASE)
_SPECIAL = ("NUM_ARGS", "NEWTONIAN", "DEGREES")


def expand_macro(
    text: str,
    args: list[str],
    *,
    newtonian: str | None,
    degrees: bool,
    path: str,
) -> MacroExpansion:
    """Expand the macro file *text* called with argument source texts *args*.

    Comment lines are dropped, ``if``/``else`` is evaluated, ``ECHO`` output
    of the taken branches is collected, and placeholders are substituted.
    Raises :class:`MacroError` (naming *path*) for malformed macros.
    """
    expander = _MacroText(text, list(args), newtonian, degrees, path)
    return expander.run()


class _MacroText:
    """Recursive-descent interpreter for the macro preprocessor language."""

    def __init__(
        self,
        text: str,
        args: list[str],
        newtonian: str | None,
        degrees: bool,
        path: str,
    ) -> None:
        kept = [ln for ln in split_lines(text) if not ln.lstrip().startswith("%")]
        self.src = "\n".join(kept)
        self.args = args
        self.newtonian = newtonian
        self.degrees = degrees
        self.path = path
        self.pos = 0
        self.echoes: list[str] = []

    def run(self) -> MacroExpansion:
        self._check_placeholders()
        out = self._body(top=True)
        lines = (ln.strip() for ln in split_lines(out))
        return MacroExpansion("\n".join(ln for ln in lines if ln), tuple(self.echoes))

    def _error(self, message: str) -> MacroError:
        line = self.src.count("\n", 0, self.pos) + 1
        return MacroError(f"macro file {self.path}, line {line}: {message}")

    def _check_placeholders(self) -> None:
        """Reject unknown ``#WORD#`` and stray ``#`` anywhere in the file."""
        rest = _PLACEHOLDER.sub(self._check_one, self.src)
        if "#" in rest:
            self.pos = self.src.find("#")
            raise self._error("stray '#' (placeholders look like #1# or #NUM_ARGS#)")

    def _check_one(self, match: re.Match[str]) -> str:
        word = match.group(1)
        if not (word.isdigit() or word.upper() in _SPECIAL):
            self.pos = match.start()
            raise self._error(f"unknown placeholder #{word}#")
        return ""

    # -- substitution -----------------------------------------------------

    def _substitute(self, text: str) -> str:
        return _PLACEHOLDER.sub(self._replacement, text)

    def _replacement(self, match: re.Match[str]) -> str:
        word = match.group(1).upper()
        if word.isdigit():
            index = int(word)
            if not 1 <= index <= len(self.args):
                given = len(self.args)
                noun = "argument was" if given == 1 else "arguments were"
                raise self._error(
                    f"#{word}# refers to argument {index} but {given} {noun} given"
                )
            return self.args[index - 1]
        if word == "NUM_ARGS":
            return str(len(self.args))
        if word == "DEGREES":
            return "ON" if self.degrees else "OFF"
        if self.newtonian is None:
            raise self._error("#Newtonian# used but no Newtonian frame is declared")
        return self.newtonian

    # -- structure ----------------------------------------------------------

    def _body(self, *, top: bool, emit: bool = True) -> str:
        """Text up to the ``}`` closing the current block (or end of file)."""
        out: list[str] = []
        start = self.pos
        depth = 0
        src = self.src
        while self.pos < len(src):
            ch = src[self.pos]
            if ch == '"':
                self._skip_string()
                continue
            if ch == "{":
                depth += 1
            elif ch == "}":
                if depth == 0:
                    if top:
                        raise self._error("'}' without a matching '{'")
                    break
                depth -= 1
            elif self._at_word(_IF):
                out.append(self._plain(src[start : self.pos], emit))
                out.append(self._if(emit))
                start = self.pos
                continue
            elif self._at_word(_ELSE):
                raise self._error("'else' without a matching 'if'")
            self.pos += 1
        if not top and self.pos >= len(src):
            raise self._error("missing '}' at end of file")
        out.append(self._plain(src[start : self.pos], emit))
        return "".join(out)

    def _at_word(self, pattern: re.Pattern[str]) -> bool:
        if pattern is _ELSE and self.pos > 0:
            prev = self.src[self.pos - 1]
            if prev.isalnum() or prev in "_#":
                return False
        return pattern.match(self.src, self.pos) is not None

    def _skip_string(self) -> None:
        end = self.src.find('"', self.pos + 1)
        if end < 0:
            raise self._error("unterminated string")
        self.pos = end + 1

    def _skip_space(self) -> None:
        while self.pos < len(self.src) and self.src[self.pos].isspace():
            self.pos += 1

    def _if(self, emit: bool) -> str:
        """``if(cond) {block} [else if ... | else {block}]``; pos is at ``if``."""
        match = _IF.match(self.src, self.pos)
        self.pos = match.end()
        cond_text = self._until_close_paren()
        taken = emit and self._condition(cond_text)
        result = self._block(taken)
        done = taken
        while True:
            before_else = self.pos
            self._skip_space()
            if not _ELSE.match(self.src, self.pos):
                self.pos = before_else  # keep the line break after the block
                break
            self.pos += len("else")
            self._skip_space()
            match = _IF.match(self.src, self.pos)
            if match is not None:
                self.pos = match.end()
                cond_text = self._until_close_paren()
                branch = emit and not done and self._condition(cond_text)
                text = self._block(branch)
            else:
                branch = emit and not done
                text = self._block(branch)
                if branch:
                    result = text
                break
            if branch:
                result, done = text, True
        return result

    def _until_close_paren(self) -> str:
        start = self.pos
        depth = 0
        while self.pos < len(self.src):
            ch = self.src[self.pos]
            if ch == '"':
                self._skip_string()
                continue
            if ch == "\n":
                break
            if ch == "(":
                depth += 1
            elif ch == ")":
                if depth == 0:
                    text = self.src[start : self.pos]
                    self.pos += 1
                    return text
                depth -= 1
            self.pos += 1
        self.pos = start
        raise self._error("missing ')' after 'if' condition")

    def _block(self, emit: bool) -> str:
        self._skip_space()
        if self.pos >= len(self.src) or self.src[self.pos] != "{":
            raise self._error("expected '{' to start an if/else block")
        self.pos += 1
        text = self._body(top=False, emit=emit)
        self.pos += 1  # the closing '}'
        return text if emit else ""

    def _condition(self, text: str) -> bool:
        match = _COND.match(self._substitute(text))
        if match is None:
            raise self._error(f"malformed if condition {text.strip()!r}")
        left, op, right = match.groups()
        left, right = _operand(left), _operand(right)
        if not left and not right:
            raise self._error(f"malformed if condition {text.strip()!r}")
        lhs: int | str
        rhs: int | str
        if _is_int(left) and _is_int(right):
            lhs, rhs = int(left), int(right)
        else:
            lhs, rhs = left.upper(), right.upper()
        return {
            "==": lhs == rhs,
            "!=": lhs != rhs,
            "<": lhs < rhs,
            ">": lhs > rhs,
            "<=": lhs <= rhs,
            ">=": lhs >= rhs,
        }[op]

    # -- plain text and ECHO ------------------------------------------------

    def _plain(self, text: str, emit: bool) -> str:
        """Substitute placeholders and run ECHO commands in taken text."""
        if not emit:
            return ""
        out: list[str] = []
        pos = 0
        while True:
            match = _ECHO.search(text, pos)
            if match is None or _inside_string(text, match.start()):
                if match is not None:
                    out.append(text[pos : match.end()])
                    pos = match.end()
                    continue
                out.append(text[pos:])
                break
            out.append(text[pos : match.start()])
            end = _close_paren(text, match.end())
            if end < 0:
                raise self._error("missing ')' after ECHO(")
            self.echoes.append(self._echo_text(text[match.end() : end]))
            pos = end + 1
            while pos < len(text) and text[pos] in " \t":
                pos += 1
            if pos < len(text) and text[pos] == ";":
                pos += 1
        return self._substitute("".join(out))

    def _echo_text(self, inner: str) -> str:
        pieces = re.findall(r'"([^"]*)"', inner)
        outside = re.sub(r'"[^"]*"', "", inner)
        if not pieces:
            pieces = [outside]
        message = self._substitute("".join(pieces))
        return _CONTROL.sub("", message).strip()


def _operand(text: str) -> str:
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] == '"':
        return text[1:-1].strip()
    return text


def _is_int(text: str) -> bool:
    return re.fullmatch(r"[+-]?\d+", text) is not None


def _inside_string(text: str, index: int) -> bool:
    return text.count('"', 0, index) % 2 == 1


def _close_paren(text: str, start: int) -> int:
    """Index of the ``)`` closing a ``(`` just before *start* (or -1)."""
    depth = 0
    pos = start
    while pos < len(text):
        ch = text[pos]
        if ch == '"':
            end = text.find('"', pos + 1)
            if end < 0:
                return -1
            pos = end + 1
            continue
        if ch == "(":
            depth += 1
        elif ch == ")":
            if depth == 0:
                return pos
            depth -= 1
        pos += 1
    return -1


# ------------------------------------------------------------ macro expansion


@dataclass
class Expander:
    """Expands ``.a`` macros, ``.r`` macros and ``RUN`` files in a script's
    statements: the one expander of the pipeline (parse -> expand -> analyse
    -> generate)."""

    parse: Callable[[str, str], ir.Script]
    script_dir: Path
    autolevpath: str | None
    lines: tuple[str, ...]
    newtonian: str | None = None
    degrees: bool = False
    depth: int = 0
    run_stack: tuple[str, ...] = field(default_factory=tuple)

    def statements(self, stmts: tuple[ir.Stmt, ...]) -> Iterator[ir.Stmt]:
        for stmt in stmts:
            yield from self.statement(stmt)

    def statement(self, stmt: ir.Stmt) -> Iterator[ir.Stmt]:
        if (
            isinstance(stmt, ir.Declaration)
            and stmt.keyword == "NEWTONIAN"
            and stmt.items
        ):
            target = stmt.items[0].target
            if isinstance(target, ir.Name):
                self.newtonian = target.name
        if isinstance(stmt, ir.Setting) and stmt.name == "DEGREES":
            self.degrees = (stmt.value or "").upper() == "ON"
        if isinstance(stmt, ir.FileCommand) and stmt.command == "RUN":
            yield self.run(stmt)
            return
        if isinstance(stmt, ir.ExprStmt) and isinstance(stmt.expr, ir.Call):
            call = stmt.expr
            if call.key not in BUILTINS:
                path = self._find(call.func, "a")
                if path is not None:
                    yield self.macro_statement(stmt, call, path)
                    return
                if self._find(call.func, "r") is None:
                    self._missing_macro(call)
        yield self.expand_results(stmt)

    def _missing_macro(self, call: ir.Call) -> None:
        """``contact(RHeel)`` as a statement, with no ``contact.a``: say
        where the macro file was looked for."""
        from .static_checks import UNSUPPORTED_COMMANDS

        if call.key in UNSUPPORTED_COMMANDS:
            return
        name = call.func
        dirs = [d for d in (self.autolevpath or "").split(os.pathsep) if d]
        where = f"the script's folder ({self.script_dir})" + (
            f" or on AUTOLEVPATH ({os.pathsep.join(dirs)})"
            if dirs
            else "; AUTOLEVPATH is not set"
        )
        raise MacroError(
            f"unknown command '{name}': no macro file {name}.a or {name}.r "
            f"was found in {where}",
            call.span,
        )

    def _find(self, name: str, kind: str) -> Path | None:
        return find_macro(name, kind, self.script_dir, self.autolevpath)

    def _arg_texts(self, call: ir.Call) -> list[str]:
        from .parser import span_text

        return [span_text(self.lines, a.span) for a in call.args]

    def _expand_text(self, path: Path, call: ir.Call) -> str:
        if self.depth > 20:
            raise MacroError(f"macro {call.func} calls itself too deeply", call.span)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError as exc:
            raise MacroError(
                f"cannot read macro file {path}: {exc.strerror}", call.span
            ) from None
        try:
            expansion = expand_macro(
                text,
                self._arg_texts(call),
                newtonian=self.newtonian,
                degrees=self.degrees,
                path=str(path),
            )
        except MacroError as exc:
            raise MacroError(exc.message, call.span) from None
        if expansion.echoes:
            raise MacroError(f"{path.name}: " + " ".join(expansion.echoes), call.span)
        return expansion.text

    def _parse_nested(self, text: str, path: Path, call_span: ir.Span) -> ir.Script:
        try:
            return self.parse(text, str(path))
        except ParseError as exc:
            where = f"line {exc.span.line}" if exc.span else "text"
            raise MacroError(
                f"in {path.name} ({where} of the expansion): {exc.message}", call_span
            ) from None

    def _child(self, lines: tuple[str, ...]) -> Expander:
        """An expander for a macro's text, one level deeper."""
        return Expander(
            self.parse,
            self.script_dir,
            self.autolevpath,
            lines,
            self.newtonian,
            self.degrees,
            self.depth + 1,
            self.run_stack,
        )

    def macro_statement(
        self, stmt: ir.ExprStmt, call: ir.Call, path: Path
    ) -> ir.MacroCall:
        text = self._expand_text(path, call)
        script = self._parse_nested(text, path, call.span)
        inner = self._child(script.lines)
        body = tuple(
            _respan_stmt(s, call.span) for s in inner.statements(script.statements)
        )
        return ir.MacroCall(stmt.span, call.func, str(path), body, comment=stmt.comment)

    def run(self, stmt: ir.FileCommand) -> ir.MacroCall:
        path = _resolve(stmt.filename, self.script_dir, self.autolevpath)
        if path is None:
            raise MacroError(f"RUN: cannot find {stmt.filename}", stmt.span)
        check_confined(
            path, stmt.filename, self.script_dir, self.autolevpath, stmt.span
        )
        key = str(path.resolve())
        if key in self.run_stack:
            raise MacroError(f"RUN {stmt.filename} runs itself", stmt.span)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError as exc:
            raise MacroError(f"cannot read {path}: {exc.strerror}", stmt.span) from None
        script = self.parse(text, str(path))
        inner = Expander(
            self.parse,
            path.parent,
            self.autolevpath,
            script.lines,
            self.newtonian,
            self.degrees,
            self.depth + 1,
            (*self.run_stack, key),
        )
        body = tuple(inner.statements(script.statements))
        self.newtonian, self.degrees = inner.newtonian, inner.degrees
        return ir.MacroCall(stmt.span, "RUN", str(path), body, comment=stmt.comment)

    def expand_results(self, stmt: ir.Stmt) -> ir.Stmt:
        """Replace calls of ``.r`` macros inside the statement's expressions."""
        changes = {}
        for name, value in ir.content(stmt):
            if isinstance(value, ir.Expr):
                new = map_expr(value, self._result_macro)
                if new is not value:
                    changes[name] = new
        return dataclasses.replace(stmt, **changes) if changes else stmt

    def _result_macro(self, node: ir.Expr) -> ir.Expr | None:
        if not isinstance(node, ir.Call) or node.key in BUILTINS:
            return None
        path = self._find(node.func, "r")
        if path is None:
            return _spelled(node)
        text = self._expand_text(path, node).strip()
        script = self._parse_nested(f"MACRO_RESULT_ = {text}", path, node.span)
        stmts = [s for s in script.statements if not isinstance(s, ir.Comment)]
        if len(stmts) != 1 or not isinstance(stmts[0], ir.Assign):
            raise MacroError(
                f"{path.name} does not expand to one expression", node.span
            )
        value = _respan_expr(stmts[0].value, node.span)
        inner = self._child(script.lines)
        return map_expr(value, inner._result_macro)


def _spelled(call: ir.Call) -> ir.Call | None:
    """``inverse(M)`` as ``Inv(M)``: a longer spelling of a built-in that
    no macro file defines (:func:`al2py_runtime.vocabulary.by_spelling`)."""
    builtin = by_spelling(call.func)
    if builtin is None or builtin.name == call.key:
        return None
    return dataclasses.replace(call, func=builtin.name.title())


def _resolve(filename: str, script_dir: Path, autolevpath: str | None) -> Path | None:
    # Autolev ran on Windows: ``RUN sub\x.al`` names sub/x.al
    # (BioMAC's gait10dof18musc_NoDer.al).
    if os.sep == "/" and "\\" in filename:
        filename = filename.replace("\\", "/")
    candidates = [script_dir / filename]
    for d in (autolevpath or "").split(os.pathsep):
        if d:
            candidates.append(Path(d) / filename)
    for c in candidates:
        if c.is_file():
            return c
    return None


def _respan_expr(expr: ir.Expr, span: ir.Span) -> ir.Expr:
    return map_expr(expr, lambda n: dataclasses.replace(n, span=span))


def _respan_stmt(stmt: ir.Stmt, span: ir.Span) -> ir.Stmt:
    changes: dict[str, object] = {"span": span}
    for name, value in ir.content(stmt):
        if isinstance(value, ir.Expr):
            changes[name] = _respan_expr(value, span)
    return dataclasses.replace(stmt, **changes)


def expand(
    script: ir.Script,
    parse: Callable[[str, str], ir.Script],
    *,
    script_dir: Path,
    autolevpath: str | None = None,
) -> tuple[ir.Stmt, ...]:
    """Statements of ``script`` with ``.a`` macros, ``.r`` macros and ``RUN``
    files expanded (as :class:`ir.MacroCall` nodes or inline expressions)."""
    if autolevpath is None:
        autolevpath = os.environ.get("AUTOLEVPATH")
    expander = Expander(parse, script_dir, autolevpath, script.lines)
    return tuple(expander.statements(script.statements))


def flatten(stmts: tuple[ir.Stmt, ...]) -> Iterator[ir.Stmt]:
    """Statements with macro bodies inlined (for pre-passes)."""
    for s in stmts:
        if isinstance(s, ir.MacroCall):
            yield from flatten(s.body)
        else:
            yield s
