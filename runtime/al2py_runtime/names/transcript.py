"""Autolev transcripts: numbered input lines interleaved with ``->`` responses.

Autolev numbers every input line and every response line in one sequence::

    (1) Constants A, B
    (2) X = 4*(A+B) - 3*(a-b)
    -> (3) X = A + 7*B

Blank lines are not numbered; a statement continued with ``&`` is one input
line.  Responses are attached to the physical line their statement starts on.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable, Iterator, Sequence

from .settings import Response

__all__ = [
    "echo_lines",
    "echo_records",
    "echoed_source",
    "logical_lines",
    "module_source",
    "transcript_lines",
]


def logical_lines(source: Sequence[str]) -> Iterator[tuple[int, str]]:
    """``(first physical line, text)`` for each non-blank logical line."""
    pending: list[str] = []
    start = 0
    for number, line in enumerate(source, start=1):
        if not pending:
            start = number
            if not line.strip():
                continue
        code = line.split("%", 1)[0].rstrip()
        if code.endswith("&"):
            pending.append(line.rstrip())
            continue
        pending.append(line.rstrip())
        yield start, " ".join(
            p.strip() if i else p.rstrip() for i, p in enumerate(pending)
        )
        pending = []
    if pending:
        yield start, " ".join(p.strip() for p in pending)


def transcript_lines(source: Sequence[str], responses: Iterable[Response]) -> list[str]:
    """The full transcript as text lines."""
    from .printing import format_response

    by_line: dict[int | None, list[Response]] = defaultdict(list)
    for r in responses:
        by_line[r.line].append(r)
    out: list[str] = []
    n = 0
    for start, text in logical_lines(source):
        n += 1
        out.append(f"({n}) {text.strip()}")
        for r in by_line.pop(start, []):
            for line in format_response(r.label, r.value, r.digits):
                n += 1
                out.append(f"-> ({n}) {line}")
    for key in sorted(by_line, key=lambda k: -1 if k is None else k):
        for r in by_line[key]:
            for line in format_response(r.label, r.value, r.digits):
                n += 1
                out.append(f"-> ({n}) {line}")
    return out


# ------------------------------------------------- the source in a module

#: how a generated module holds each line of its ``.al`` file, once, as a
#: comment at column 0: ``# al> TEXT`` (the line, stripped), ``# al+ ...``
#: (the rest of a line too long for one comment), ``# al! 'TEXT'`` (a line
#: with a character a comment cannot hold, as a Python string), and ``#``
#: (a blank line).  The transcript reads its source from these comments.
ECHO, MORE, QUOTED, BLANK = "# al> ", "# al+", "# al! ", "#"
_WIDTH = 88


def echo_lines(line: str) -> list[str]:
    """The comment lines that hold one ``.al`` line in a module.

    >>> echo_lines("Simprot(N, A, 3, QA)   ")
    ['# al> Simprot(N, A, 3, QA)']
    >>> echo_lines("")
    ['#']
    """
    text = line.strip()
    if not text:
        return [BLANK]
    lead = ECHO
    if not all(c.isprintable() or c == "\t" for c in text):
        lead, text = QUOTED, repr(text)
    out: list[str] = []
    while text:
        room = _WIDTH - len(lead)
        piece = _piece(text, room)
        out.append(lead + piece)
        text = text[len(piece) :]
        lead = MORE
    return out


def _piece(text: str, room: int) -> str:
    """The longest start of ``text`` that fits ``room`` columns (a tab as 8),
    ending before a space where it can, and never on whitespace (black
    would strip it)."""
    width = 0
    end = 0
    while end < len(text):
        width += 8 if text[end] == "\t" else 1
        if width > room:
            break
        end += 1
    if end == len(text):
        return text
    for cut in range(end, 0, -1):  # before a space, after a word
        if text[cut].isspace() and not text[cut - 1].isspace():
            return text[:cut]
    cut = end
    while cut > 1 and text[cut - 1].isspace():
        cut -= 1
    return text[: max(cut, 1)]


def echoed_source(module_lines: Sequence[str]) -> list[str]:
    """The ``.al`` lines (stripped) that a generated module echoes, in order:
    what :func:`transcript_lines` numbers.

    >>> echoed_source(["x = 1", "# al> Q' = U", "f(x)", "#", "# al> %  a", "# al+ b"])
    ["Q' = U", '', '%  a b']
    """
    return [text for _, text in echo_records(module_lines)]


def echo_records(module_lines: Sequence[str]) -> list[tuple[int, str]]:
    """``(index in module_lines, .al line)`` of each line a module echoes:
    the ``k``-th record is line ``k`` of the ``.al`` file."""
    import ast
    import io
    import tokenize

    text = "".join(
        line if line.endswith("\n") else line + "\n" for line in module_lines
    )
    out: list[tuple[int, str]] = []
    quoted: list[bool] = []
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type != tokenize.COMMENT or tok.start[1] != 0:
                continue
            comment, index = tok.string.rstrip(), tok.start[0] - 1
            if comment == BLANK:
                out.append((index, ""))
                quoted.append(False)
            elif comment.startswith((ECHO, QUOTED)):
                out.append((index, comment[len(ECHO) :]))
                quoted.append(comment.startswith(QUOTED))
            elif comment.startswith(MORE) and out:
                out[-1] = (out[-1][0], out[-1][1] + comment[len(MORE) :])
    except (tokenize.TokenError, SyntaxError):
        return []
    for k, is_quoted in enumerate(quoted):
        if is_quoted:
            try:
                out[k] = (out[k][0], str(ast.literal_eval(out[k][1])))
            except (ValueError, SyntaxError):
                pass
    return out


def module_source(module_file: str, module_globals: object = None) -> list[str]:
    """:func:`echoed_source` of the module in ``module_file``."""
    import linecache

    return echoed_source(linecache.getlines(module_file, module_globals))
