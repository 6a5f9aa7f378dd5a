"""Checks at conversion time for input that would otherwise fail only when the
generated module runs (issue 12): every failure found here is a located
``file:line:col: error: ...``, never a traceback later.

* characters a Python module cannot hold (a NUL byte, even in a comment);
* number literals beyond double precision (``1e400``, ``1e-400``);
* unit names in ``Input``, ``Output``, ``UnitSystem`` and CODE sweeps
  (``furlong``), with the nearest known unit suggested;
* unknown commands get "did you mean ...?" and Autolev commands that al2py
  does not translate say "not supported" (:func:`unknown_call_message`).

Also :func:`with_source_line`, which gives an error its source line and caret
wherever the error happened (the main script, a ``RUN`` file or a macro call).
"""

from __future__ import annotations

import difflib
import math
import re
from collections.abc import Callable, Iterable
from pathlib import Path

from . import ir
from .errors import AutolevError, ErrorList, ParseError, SemanticError
from .lines import split_lines

__all__ = [
    "check_text",
    "check_statements",
    "check_orientations",
    "unknown_call_message",
    "with_source_line",
    "too_deep",
    "too_large",
]

# ------------------------------------------------------------------ text

_FORBIDDEN = re.compile(r"\x00")


def check_text(text: str, filename: str) -> None:
    """Refuse a NUL byte: Python cannot load a module holding one, even in a
    comment, and Autolev text has no use for it."""
    m = _FORBIDDEN.search(text)
    if m is None:
        return
    line = text.count("\n", 0, m.start()) + 1
    col = m.start() - (text.rfind("\n", 0, m.start()) + 1) + 1
    lines = split_lines(text)
    line_text = lines[line - 1] if lines else ""
    raise ParseError(
        "a NUL character (\\x00) cannot appear in a script, not even in a comment",
        ir.Span(filename, line, col),
        line_text=line_text.replace("\x00", " "),
    )


# ------------------------------------------------------------ statements


def check_statements(stmts: Iterable[ir.Stmt]) -> None:
    """Numbers and unit names of (macro-expanded) statements."""
    for stmt in _flatten(stmts):
        if isinstance(stmt, ir.UnitSystemStmt):
            for name in stmt.units:
                _check_unit_word(name, stmt.span)
        for node in _nodes(stmt):
            if isinstance(node, ir.Number):
                _check_number(node)
            elif isinstance(node, ir.UnitExpr):
                _check_unit(node)


def _flatten(stmts: Iterable[ir.Stmt]) -> Iterable[ir.Stmt]:
    for s in stmts:
        if isinstance(s, ir.MacroCall):
            yield from _flatten(s.body)
        else:
            yield s


def _nodes(root: ir.Node) -> Iterable[ir.Node]:
    """Every node below ``root`` (iteratively: deep nesting is fine)."""
    stack: list[object] = [root]
    while stack:
        item = stack.pop()
        if isinstance(item, tuple):
            stack.extend(item)
            continue
        if not isinstance(item, ir.Node):
            continue
        if item is not root:
            yield item
        for name, value in ir.content(item):
            if name != "span" and isinstance(value, ir.Node | tuple):
                stack.append(value)


def _check_number(node: ir.Number) -> None:
    text = node.text
    try:
        x = float(text)
    except ValueError:
        return
    if math.isinf(x):
        raise SemanticError(
            f"the number {text} is too large: beyond double precision "
            "(about 1.8E+308), it would become infinity",
            node.span,
        )
    mantissa = re.split(r"[eEdD]", text)[0]
    if x == 0 and any(c in "123456789" for c in mantissa):
        raise SemanticError(
            f"the number {text} is too small: below double precision "
            "(about 4.9E-324), it would become 0",
            node.span,
        )


def _unit_names() -> dict:
    from al2py_runtime.jobs.units import UNIT_NAMES

    return UNIT_NAMES


def _check_unit(node: ir.UnitExpr) -> None:
    for word, _power in node.factors:
        _check_unit_word(word, node.span)
    if node.text:
        from al2py_runtime.jobs.units import UnitError, parse_unit

        try:
            parse_unit(node.text)
        except UnitError as exc:
            raise SemanticError(str(exc), node.span) from None


def _check_unit_word(word: str, span: ir.Span) -> None:
    if re.fullmatch(r"[\d.]+(?:[eE][-+]?\d+)?", word):
        return
    names = _unit_names()
    if word.lower() in names:
        return
    close = difflib.get_close_matches(word.lower(), list(names), n=1, cutoff=0.6)
    hint = f"; did you mean {close[0]}?" if close else ""
    raise SemanticError(f"unknown unit '{word}'{hint}", span)


# ------------------------------------------------------ orientations

#: calls that need the orientation (or angular velocity) between the frames
#: of their arguments' unit vectors (and their frame argument)
_RELATES_FRAMES = frozenset({"DOT", "CROSS", "EXPRESS", "MAG", "UNITVEC", "DT"})
#: commands that relate their first two frames (orientation or angular
#: velocity): after them the two frames may be used together
_RELATING = frozenset({"SIMPROT", "DIRCOS", "ANGVEL", "KINDIFFS"})
_FRAME_DECLS = frozenset({"NEWTONIAN", "FRAMES", "BODIES"})


def check_orientations(stmts: Iterable[ir.Stmt]) -> None:
    """A frame used before it is oriented: ``Dot(A1>, N1>)`` (also ``Cross``,
    ``Express``, ``Mag``, ``Dt``) with unit vectors of two frames that no
    earlier ``Simprot``, ``Dircos``, ``N_A = ...`` or ``W_A_N> = ...``
    relates, directly or through other frames.  Only what is visible in the
    text is checked (unit vectors written out, not vectors held in names);
    the module reports the rest when it runs."""
    root: dict[str, str] = {}

    def find(name: str) -> str:
        while root[name] != name:
            root[name] = root[root[name]]
            name = root[name]
        return name

    def join(a: str | None, b: str | None) -> None:
        if a in root and b in root:
            root[find(a)] = find(b)  # type: ignore[arg-type]

    errors: list[AutolevError] = []
    for stmt in _flatten(stmts):
        if isinstance(stmt, ir.Declaration) and stmt.keyword in _FRAME_DECLS:
            for item in stmt.items:
                if isinstance(item.target, ir.Name):
                    root.setdefault(item.target.key, item.target.key)
            continue
        calls = [n for n in _nodes(stmt) if isinstance(n, ir.Call)]
        for call in calls:
            if call.key in _RELATES_FRAMES:
                err = _unrelated(call, root, find)
                if err is not None:
                    errors.append(err)
        for call in calls:
            if call.key in _RELATING and len(call.args) >= 2:
                join(_frame_arg(call.args[0], root), _frame_arg(call.args[1], root))
        if isinstance(stmt, ir.Assign):
            target = stmt.target
            if isinstance(target, ir.Element):  # N_A[1,1] = ...
                target = target.base
            pair = (
                _frame_pair(target.key, root) if isinstance(target, ir.Name) else None
            )
            if pair:
                join(*pair)
    if errors:
        raise errors[0] if len(errors) == 1 else ErrorList(errors)


def _frame_arg(expr: ir.Expr, frames: dict[str, str]) -> str | None:
    return expr.key if isinstance(expr, ir.Name) and expr.key in frames else None


def _frame_pair(key: str, frames: dict[str, str]) -> tuple[str, str] | None:
    """The two frames of ``N_A`` (direction cosines) or ``W_A_N>`` (angular
    velocity), if ``key`` is one of those forms of declared frames."""
    parts = key.rstrip(">").split("_")
    if key.endswith(">") and len(parts) == 3 and parts[0] in ("W", "ALF"):
        parts = parts[1:]
    elif key.endswith(">") or len(parts) != 2:
        return None
    a, b = parts
    return (a, b) if a in frames and b in frames else None


def _unrelated(
    call: ir.Call, frames: dict[str, str], find: Callable[[str], str]
) -> AutolevError | None:
    """The error for ``call`` if it names frames that nothing relates."""
    from al2py_runtime.vocabulary import unit_vector

    seen: list[str] = []
    for node in _nodes(call):
        name = None
        if isinstance(node, ir.Name):
            unit = unit_vector(node.key)
            if unit and unit[0] in frames:
                name = unit[0]
            elif node.key in frames and call.key in ("EXPRESS", "DT"):
                name = node.key
        if name and name not in seen:
            seen.append(name)
    for i, a in enumerate(seen):
        for b in seen[i + 1 :]:
            if find(a) != find(b):
                return SemanticError(
                    f"frame {b} is not oriented relative to frame {a}: "
                    f"{call.func}() needs their orientation; orient one in the "
                    f"other first (for example Simprot({a}, {b}, 3, angle), "
                    f"Dircos(...) or {a}_{b} = ...)",
                    call.span,
                )
    return None


# ------------------------------------------------------ matrix shapes


def matrix_sum_error(
    expr: ir.BinOp,
    shape_of_name: Callable[[ir.Name], tuple[int, int] | None],
    is_scalar: Callable[[ir.Expr], bool],
) -> str | None:
    """For ``M + a*[1, 2, 3]`` whose operand shapes are known statically and
    differ: the error message (else None)."""
    a = static_shape(expr.left, shape_of_name, is_scalar)
    b = static_shape(expr.right, shape_of_name, is_scalar)
    if a is None or b is None or a == b:
        return None
    verb = "add" if expr.op == "+" else "subtract"
    return (
        f"cannot {verb} a {a[0]}x{a[1]} matrix and a {b[0]}x{b[1]} matrix "
        "(their sizes differ)"
    )


def static_shape(
    expr: ir.Expr,
    shape_of_name: Callable[[ir.Name], tuple[int, int] | None],
    is_scalar: Callable[[ir.Expr], bool],
    depth: int = 0,
) -> tuple[int, int] | None:
    """The (rows, cols) of a matrix expression when known without running it."""
    if depth > 50:
        return None
    if isinstance(expr, ir.MatrixLit):
        if any(isinstance(e, ir.MatrixLit) for row in expr.rows for e in row):
            return None
        widths = {len(row) for row in expr.rows}
        return (len(expr.rows), widths.pop()) if len(widths) == 1 else None
    if isinstance(expr, ir.Name):
        return shape_of_name(expr)
    if isinstance(expr, ir.UnaryOp):
        return static_shape(expr.operand, shape_of_name, is_scalar, depth + 1)
    if isinstance(expr, ir.BinOp):
        left = lambda: static_shape(  # noqa: E731
            expr.left, shape_of_name, is_scalar, depth + 1
        )
        right = lambda: static_shape(  # noqa: E731
            expr.right, shape_of_name, is_scalar, depth + 1
        )
        if expr.op in "+-":
            return left() or right()
        if expr.op == "/" and is_scalar(expr.right):
            return left()
        if expr.op == "*":
            if is_scalar(expr.left):
                return right()
            if is_scalar(expr.right):
                return left()
            a, b = left(), right()
            if a and b and a[1] == b[0]:
                return (a[0], b[1])
    return None


# ------------------------------------------------------ unknown commands

#: Autolev commands of the tutorial that al2py does not translate
UNSUPPORTED_COMMANDS = {
    "CLEAR": "a script cannot restart its own workspace",
    "HELP": "it is interactive",
    "LIST": "it is interactive",
    "MEMORY": "it is interactive",
    "WHAT": "it is interactive",
    "DEFAULTS": "it is interactive",
    "STEPPING": "it only changes screen spacing",
    "SIMPLIFY": "it only places scratch files",
    "OPTION": "CODE options of generated C/Fortran do not apply to Python",
}


def unknown_call_message(name: str) -> str:
    """The error for a call of ``name``, which is neither a builtin nor a
    macro found on disk."""
    key = name.upper()
    if key in UNSUPPORTED_COMMANDS:
        return (
            f"the Autolev command '{name}' is not supported by al2py "
            f"({UNSUPPORTED_COMMANDS[key]})"
        )
    from al2py_runtime.vocabulary import BUILTINS

    pool = {b.lower(): b for b in BUILTINS}
    close = difflib.get_close_matches(name.lower(), list(pool), n=1, cutoff=0.6)
    hint = f" (did you mean {pool[close[0]].title()}?)" if close else ""
    return f"unknown function or command '{name}'{hint}"


# ------------------------------------------------------------ locations


def too_deep(filename: str, text: str) -> ParseError:
    """The located error for input nested too deeply to convert."""
    lines = split_lines(text)
    span = deepest_nesting(filename, lines)
    return ParseError(
        "this expression is nested too deeply to convert",
        span,
        line_text=lines[span.line - 1] if lines else "",
    )


def deepest_nesting(filename: str, lines: Iterable[str]) -> ir.Span:
    """Where the brackets of ``lines`` nest deepest, or where the longest
    run of operators starts (``----A``, ``A^A^A``), whichever is deeper: the
    place to blame when an expression is nested too deeply to convert."""
    depth = best = 0
    where = (1, 1)
    for number, line in enumerate(lines, start=1):
        code = line.split("%", 1)[0]
        for col, char in enumerate(code, start=1):
            if char in "([{":
                depth += 1
                if depth > best:
                    best, where = depth, (number, col)
            elif char in ")]}":
                depth = max(0, depth - 1)
        operators = sum(code.count(c) for c in "-+*/^")
        if operators > best:
            first = min((code.find(c) for c in "-+*/^" if c in code), default=0)
            best, where = operators, (number, first + 1)
    return ir.Span(filename, *where)


def too_large(filename: str, text: str) -> ParseError:
    """The located error for input that exhausted memory while converting:
    blamed on its longest line (the statement most likely to be at fault)."""
    lines = split_lines(text)
    if not lines:
        return ParseError("out of memory converting this file", ir.Span(filename, 1, 1))
    number = max(range(len(lines)), key=lambda i: (len(lines[i]), -i)) + 1
    return ParseError(
        "out of memory converting this file (its longest statement is here)",
        ir.Span(filename, number, 1),
        line_text=lines[number - 1],
    )


def with_source_line(
    exc: AutolevError, filename: str, lines: Iterable[str] | None = None
) -> AutolevError:
    """Give ``exc`` the text of its line (for the caret), reading a ``RUN``
    file or macro from disk when the error is located there."""
    if exc.line_text or exc.span is None:
        return exc
    line = exc.span.line
    text_lines: list[str] | None = None
    if exc.span.file == filename and lines is not None:
        text_lines = list(lines)
    else:
        try:
            path = Path(exc.span.file)
            if path.is_file() and path.stat().st_size < 50_000_000:
                text_lines = split_lines(
                    path.read_text(encoding="utf-8", errors="replace")
                )
        except (OSError, ValueError):
            text_lines = None
    if text_lines and 0 < line <= len(text_lines):
        exc.line_text = text_lines[line - 1]
    return exc
