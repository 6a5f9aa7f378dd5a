"""Compare a converted module's responses with an Autolev transcript (``.all``).

Comparison is mathematical, never textual: Autolev's printed response is parsed
with al2py's own parser, evaluated into sympy in the module's workspace, and
compared with our value at random points (numbers within the ``Digits`` that
were in force).  A response matches *strictly* when it is equal with every
named quantity left as a symbol, and *after resolving* when it is equal once
right-hand sides are substituted on both sides (Autolev and al2py may keep
different intermediate names).

Vectors and dyadics (``LA*QA'*A2>``, ``A1>*A1>``) are compared through their
components in one frame (the first frame Autolev's response names), so
``LA*A1>`` equals ``LA*COS(QA)*N1> + LA*SIN(QA)*N2>`` when ``A`` is oriented
in ``N``.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import sympy as sp
from al2py_runtime.safety import describe
from al2py_runtime.vocabulary import BUILTINS, Style, unit_vector
from sympy.physics.vector import Dyadic, Vector

from . import ir
from .errors import AutolevError
from .lines import split_lines
from .parser import parse

__all__ = [
    "TranscriptEntry",
    "parse_transcript",
    "transcript_verdict",
    "ResponseCheck",
    "check_responses",
    "evaluate_text",
    "compare",
]

_INPUT = re.compile(r"^\s*\((\d+)\)\s?(.*)$")
_RESPONSE = re.compile(r"^\s*->\s*\((\d+)\)\s*(.*)$")


@dataclass(frozen=True)
class TranscriptEntry:
    """One numbered line of a transcript."""

    number: int
    is_response: bool
    text: str
    line: int = 0  # 1-based line in the transcript file (0: unknown)

    @property
    def label(self) -> str:
        """``"M5[1,1]"`` for ``M5[1,1] = D/(A*D-B*C)`` (upper case, no spaces)."""
        return re.sub(r"\s+", "", self.text.split("=", 1)[0]).upper()

    @property
    def value_text(self) -> str:
        return self.text.split("=", 1)[1].strip() if "=" in self.text else ""


def parse_transcript(text: str) -> list[TranscriptEntry]:
    """Entries of an ``.all`` file, in order.

    Unnumbered lines are ignored, except that a response whose text is
    visibly unfinished (an open bracket, or a trailing operator) continues on
    the following unnumbered lines, as Autolev wraps long responses."""
    out: list[TranscriptEntry] = []
    for lineno, line in enumerate(split_lines(text), start=1):
        m = _RESPONSE.match(line)
        if m:
            out.append(
                TranscriptEntry(int(m.group(1)), True, m.group(2).strip(), lineno)
            )
            continue
        m = _INPUT.match(line)
        if m:
            out.append(
                TranscriptEntry(int(m.group(1)), False, m.group(2).rstrip(), lineno)
            )
            continue
        last = out[-1] if out else None
        if last is not None and last.is_response and line.strip():
            if _unfinished(last.text):
                joined = f"{last.text} {line.strip()}"
                out[-1] = TranscriptEntry(last.number, True, joined, last.line)
    return out


#: share of characters that did not decode (or NULs) beyond which a
#: transcript is not text at all
_UNREADABLE_SHARE = 0.01


def transcript_verdict(
    text: str,
    entries: Sequence[TranscriptEntry],
    ws: object,
    source: Sequence[str] = (),
) -> tuple[str, list[str]]:
    """Whether a transcript can serve as the reference: ``(error, notes)``.

    ``error`` (else '') says why nothing can be compared: the file is empty,
    is not text, holds no numbered line, or holds no response although the
    script gives some.  A check with such a transcript must fail, never
    pass with 0 of 0 responses.  ``notes`` say what a passing check did not
    cover: a transcript cut off in the middle of a line, numbers out of
    order, or one that ends before the script does (the responses of the
    lines after its end are not compared).  ``source`` is the script's lines
    (the lines a module echoes: ``al2py_runtime.safety.module_source``)."""
    if not text.strip():
        return "the transcript is empty", []
    bad = text.count("\ufffd") + text.count("\x00")
    if bad > _UNREADABLE_SHARE * len(text):
        return (
            f"the transcript is not text ({bad} of its {len(text)} characters "
            "are not UTF-8 or are NUL): it is damaged or not an Autolev transcript"
        ), []
    if not entries:
        return (
            "the transcript has no numbered line ('(1) ...' or '-> (2) ...'): "
            "it is damaged or not an Autolev transcript"
        ), []
    ours = list(getattr(ws, "responses", ()))
    if not any(e.is_response for e in entries) and ours:
        return (
            "the transcript has no response ('-> (n) NAME = ...') to compare, "
            f"though the script gives {len(ours)}"
        ), []
    notes = []
    if not text.endswith(("\n", "\r")):
        notes.append(
            "the transcript ends in the middle of a line (no line break after "
            "its last line): it may be cut off"
        )
    for before, after in zip(entries, entries[1:], strict=False):
        if after.number <= before.number:
            notes.append(
                f"the transcript's numbers go back at its line {after.line} "
                f"(({before.number}) then ({after.number})): it may be damaged"
            )
            break
    unread = [
        n
        for n, line in enumerate(split_lines(text), start=1)
        if line.lstrip().startswith("->") and not _RESPONSE.match(line)
    ]
    if unread:
        notes.append(
            f"{len(unread)} response line{'s' if len(unread) != 1 else ''} of the "
            f"transcript (the first at its line {unread[0]}) without a readable "
            "'(n)' number: not compared"
        )
    early = _ends_early(entries, ours, source)
    if early:
        notes.append(early)
    return "", notes


def _squeezed(text: str) -> str:
    return re.sub(r"\s+", "", text).upper()


def _ends_early(
    entries: Sequence[TranscriptEntry], ours: Sequence[object], source: Sequence[str]
) -> str:
    """A note if the transcript's input lines stop before script lines that
    give responses (else '')."""
    from al2py_runtime.names.transcript import logical_lines

    inputs = [e for e in entries if not e.is_response]
    logical = list(logical_lines(source))
    if not inputs or len(inputs) >= len(logical):
        return ""
    last = inputs[-1]
    # the script line the transcript ends on: the one with its text nearest
    # to its position by count, else the position by count
    k = len(inputs) - 1
    same = [
        i
        for i, (_, txt) in enumerate(logical)
        if _squeezed(txt) == _squeezed(last.text)
    ]
    if same:
        k = min(same, key=lambda i: (abs(i - (len(inputs) - 1)), i))
    end = logical[k][0]
    later = [r for r in ours if getattr(r, "line", None) and r.line > end]  # type: ignore[attr-defined]
    if not later:
        return ""
    first = min(r.line for r in later)  # type: ignore[attr-defined]
    return (
        f"the transcript ends early: its last line ({last.number}) is line {end} "
        f"of the script, so the {len(later)} response{'s' if len(later) != 1 else ''}"
        f" from line {first} on are not compared"
    )


def _unfinished(text: str) -> bool:
    """True if a response's text cannot end here (wrapped onto the next line)."""
    depth = 0
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
    stripped = text.rstrip()
    return depth > 0 or stripped.endswith(("+", "-", "*", "/", "^", ",", ";", "="))


# ------------------------------------------------------------- evaluation


_Z_NAME = re.compile(r"^Z\d+$")
_T = sp.Symbol("t")  # dynamicsymbols._t


def _declared(ws: object, name: str) -> bool:
    try:
        return ws.kind(name) is not None  # type: ignore[attr-defined]
    except (KeyError, AttributeError):
        return False


class _Evaluator:
    """Evaluates an expression IR in a workspace (names -> its symbols/values)."""

    def __init__(self, ws: object, zs: dict[str, object] | None = None) -> None:
        self.ws = ws
        self.zs = zs or {}

    def __call__(self, node: ir.Expr) -> object:
        return getattr(self, type(node).__name__)(node)

    def Number(self, node: ir.Number) -> object:  # noqa: N802 - dispatch on node type
        return sp.Rational(node.text.lower())

    def Name(self, node: ir.Name) -> object:  # noqa: N802
        key = node.key
        ws = self.ws
        if key == "I" and node.primes == 0 and not _declared(ws, "I"):
            return sp.I
        if key == "0>":
            return Vector(0)
        if key in self.zs:  # one of the transcript's own AutoZ intermediates
            value = self.zs[key]
            for _ in range(node.primes):
                value = sp.diff(value, _T)
            return value
        unit = unit_vector(key)
        if unit and node.primes == 0:
            try:
                frame = ws.model.frame(unit[0])  # type: ignore[attr-defined]
            except (KeyError, AttributeError):
                pass
            else:
                return (frame.x, frame.y, frame.z)[unit[1] - 1]
        try:
            kind = ws.kind(key)  # type: ignore[attr-defined]
            if kind in (None, "value"):
                return ws.value(node.autolev)  # type: ignore[attr-defined]
            return ws.symbol(node.autolev)  # type: ignore[attr-defined]
        except KeyError:
            return sp.Symbol(node.autolev)

    def Element(self, node: ir.Element) -> object:  # noqa: N802
        base = self(node.base)
        idx = [int(self(i)) - 1 for i in node.indices]
        if isinstance(base, sp.MatrixBase):
            return base[idx[0]] if len(idx) == 1 else base[idx[0], idx[1]]
        raise ValueError(f"{node.base.name} is not a matrix")

    def UnaryOp(self, node: ir.UnaryOp) -> object:  # noqa: N802
        v = self(node.operand)
        return -v if node.op == "-" else v

    def BinOp(self, node: ir.BinOp) -> object:  # noqa: N802
        a, b = self(node.left), self(node.right)
        if node.op == "+":
            return a + b
        if node.op == "-":
            return a - b
        if node.op == "*":
            if isinstance(a, Vector) and isinstance(b, Vector):
                return a | b  # Autolev writes the dyadic A1>A2> as A1>*A2>
            return a * b
        if node.op == "/":
            return a / b
        return a**b

    def Call(self, node: ir.Call) -> object:  # noqa: N802
        row = BUILTINS.get(node.key)
        if (
            row is None
            or row.style is not Style.FUNC
            or row.arity_error(len(node.args))
        ):
            raise ValueError(f"cannot evaluate {node.func}(...) in a response")
        return row.implementation(*(self(a) for a in node.args))

    def MatrixLit(self, node: ir.MatrixLit) -> object:  # noqa: N802
        rows = [[self(e) for e in row] for row in node.rows]
        if any(isinstance(e, sp.MatrixBase) for row in rows for e in row):
            return sp.BlockMatrix(rows).as_explicit()
        return sp.Matrix(rows)


def evaluate_text(text: str, ws: object, zs: dict[str, object] | None = None) -> object:
    """Evaluate Autolev expression ``text`` with names taken from ``ws``
    (and the transcript's AutoZ intermediates ``zs``, name -> value)."""
    script = parse(f"CHECKED_VALUE_ = {text}\n", "<response>")
    stmts = [s for s in script.statements if isinstance(s, ir.Assign)]
    if len(stmts) != 1:
        raise ValueError(f"not one expression: {text!r}")
    return _Evaluator(ws, zs)(stmts[0].value)


# ------------------------------------------------------------- comparison


def _leaves(expr: sp.Basic) -> list[sp.Basic]:
    """Things to replace by random numbers: derivatives first, then functions
    of time, then symbols."""
    derivs = sorted(expr.atoms(sp.Derivative), key=sp.default_sort_key, reverse=True)
    funcs = sorted(expr.atoms(sp.core.function.AppliedUndef), key=sp.default_sort_key)
    syms = sorted(expr.free_symbols, key=sp.default_sort_key)
    return [*derivs, *funcs, *syms]


def _frames_of(value: object) -> list[object]:
    """The reference frames a vector or dyadic is written in, in order."""
    if isinstance(value, Vector):
        return [frame for _, frame in value.args]
    if isinstance(value, Dyadic):
        return [frame for _, v1, v2 in value.args for frame in _frames_of(v1 + v2)]
    return []


def _as_matrix(value: object, frame: object = None) -> sp.Matrix:
    """A value as a matrix: vectors as 3x1 and dyadics as 3x3 components in
    ``frame`` (by default the first frame the value is written in)."""
    if isinstance(value, Vector | Dyadic):
        frames = _frames_of(value)
        if frame is None and frames:
            frame = frames[0]
        if frame is None:  # the zero vector or dyadic
            return sp.zeros(3, 1) if isinstance(value, Vector) else sp.zeros(3, 3)
        return sp.Matrix(value.to_matrix(frame))
    if isinstance(value, sp.MatrixBase):
        return sp.Matrix(value)
    return sp.Matrix([[sp.sympify(value)]])


def _as_matrices(expected: object, ours: object) -> tuple[sp.Matrix, sp.Matrix]:
    """Both values as matrices; vectors and dyadics in one common frame."""
    frames = _frames_of(expected) + _frames_of(ours)
    frame = frames[0] if frames else None
    a, b = _as_matrix(expected, frame), _as_matrix(ours, frame)
    # 0 and 0> (or 0>>) are the same response
    if a.shape != b.shape:
        if a.shape == (1, 1) and a[0] == 0:
            a = sp.zeros(*b.shape)
        elif b.shape == (1, 1) and b[0] == 0:
            b = sp.zeros(*a.shape)
    return a, b


def _on_unit_spheres(
    values: dict[sp.Basic, sp.Basic], groups: Sequence[Sequence[object]], rng
) -> None:
    """Move the random point onto each group's unit sphere (Euler parameters:
    ``E1^2 + E2^2 + E3^2 + E4^2 = 1``), with first derivatives tangent to it,
    so that expressions equal only under that constraint compare equal."""
    for group in groups:
        qs = [sp.sympify(q) for q in group]
        if not any(q in values or sp.Derivative(q, _T) in values for q in qs):
            continue
        head = [sp.Float(rng.uniform(-0.5, 0.5), 30) for _ in qs[:-1]]
        last = sp.sqrt(1 - sum(x**2 for x in head)).evalf(30)
        rates = [sp.Float(rng.uniform(-1, 1), 30) for _ in qs[:-1]]
        for q, x, r in zip(qs, head, rates, strict=False):
            values[q], values[sp.Derivative(q, _T)] = x, r
        values[qs[-1]] = last
        values[sp.Derivative(qs[-1], _T)] = (
            -sum(x * r for x, r in zip(head, rates, strict=True)) / last
        )


def compare(
    expected: object,
    ours: object,
    digits: int = 7,
    *,
    trials: int = 3,
    seed: int = 1,
    unit_norms: Sequence[Sequence[object]] = (),
) -> str | None:
    """None if equal (within ``digits``) at random points, else a reason.

    ``unit_norms`` lists groups of quantities the script keeps at unit norm
    (Euler parameters); the points respect them."""
    a, b = _as_matrices(expected, ours)
    if a.shape != b.shape:
        if a.shape == b.T.shape and 1 in a.shape:
            b = b.T
        else:
            return (
                f"shape {b.shape[0]}x{b.shape[1]} instead of {a.shape[0]}x{a.shape[1]}"
            )
    rtol = 5 * 10.0 ** (1 - digits)
    rng = random.Random(seed)
    for _ in range(trials):
        values: dict[sp.Basic, sp.Basic] = {}
        for m in (a, b):
            for e in m:
                for leaf in _leaves(sp.sympify(e)):
                    if leaf not in values:
                        values[leaf] = sp.Float(rng.uniform(0.5, 1.5), 30)
        _on_unit_spheres(values, unit_norms, rng)
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            x, y = sp.sympify(x), sp.sympify(y)
            xv = complex(x.xreplace(values).evalf(30))
            yv = complex(y.xreplace(values).evalf(30))
            if x.is_number and y.is_number:
                # A printed number: equal to within one unit in its last digit.
                tol = _last_digit(max(abs(xv.real), abs(xv.imag)), digits)
            else:
                tol = rtol * max(abs(xv), abs(yv), 1.0)
            if abs(xv.real - yv.real) > tol or abs(xv.imag - yv.imag) > tol:
                where = ""
                if len(a) > 1:
                    r, c = divmod(i, a.shape[1])
                    k = f"{r + 1},{c + 1}" if 1 not in a.shape else f"{i + 1}"
                    where = f" at [{k}]"
                at = "" if x.is_number and y.is_number else " at a random point"
                return f"differs{where}: expected {_num(xv)}, got {_num(yv)}{at}"
    return None


def _num(z: complex) -> str:
    """``0.80169343`` for a real number, ``1.5-2i`` for a complex one."""
    if z.imag == 0:
        return f"{z.real:.8g}"
    sign = "+" if z.imag >= 0 else "-"
    return f"{z.real:.8g}{sign}{abs(z.imag):.8g}i"


def _last_digit(magnitude: float, digits: int) -> float:
    """One unit in the last of ``digits`` significant digits of ``magnitude``."""
    if magnitude == 0:
        return 10.0 ** (-digits)
    return 10.0 ** (math.floor(math.log10(magnitude)) - digits + 1)


# ----------------------------------------------------------------- checks


@dataclass(frozen=True)
class ResponseCheck:
    """The verdict for one expected response."""

    entry: TranscriptEntry
    ok: bool
    how: str  # "strict", "resolved", or the reason for failure
    ours: str = ""
    #: False for a response that is not compared: the definition of one of
    #: Autolev's AutoZ intermediates (``Z12 = ...``), whose numbering al2py
    #: does not reproduce; it is expanded into the responses that use it.
    compared: bool = True


def _our_value(
    label: str, responses: Sequence[object], start: int
) -> tuple[object, int, int]:
    """Find our response for ``label`` at or after ``start``.

    Returns (value, digits, where the next search starts).  A matrix response
    also answers element labels (``M5[1,1]``), so it stays current."""
    m = re.match(r"^(.*?)(?:\[(\d+)(?:,(\d+))?\])?$", label)
    assert m is not None
    base = m.group(1)
    idx = [int(g) for g in m.groups()[1:] if g]
    for k in range(start, len(responses)):
        r = responses[k]
        rl = r.label.upper().replace(" ", "")  # type: ignore[attr-defined]
        if rl == label:
            return r.value, r.digits, k + 1  # type: ignore[attr-defined]
        if idx and rl == base and isinstance(r.value, sp.MatrixBase):  # type: ignore[attr-defined]
            v = r.value  # type: ignore[attr-defined]
            try:
                if len(idx) == 1:
                    return v[idx[0] - 1], r.digits, k  # type: ignore[attr-defined]
                return v[idx[0] - 1, idx[1] - 1], r.digits, k  # type: ignore[attr-defined]
            except IndexError:
                continue
    raise LookupError(label)


def check_responses(
    entries: Iterable[TranscriptEntry],
    ws: object,
    responses: Sequence[object] | None = None,
) -> list[ResponseCheck]:
    """Check every response of a transcript against a workspace's responses."""
    if responses is None:
        responses = ws.responses  # type: ignore[attr-defined]
    out = []
    cursor = 0
    zs: dict[str, object] = {}
    for entry in entries:
        if not entry.is_response:
            continue
        if _Z_NAME.match(entry.label) and not _declared(ws, entry.label):
            out.append(_z_definition(entry, ws, zs))
            continue
        try:
            ours, digits, k = _our_value(entry.label, responses, cursor)
        except LookupError:
            out.append(ResponseCheck(entry, False, "no such response from the module"))
            continue
        cursor = k
        out.append(_check_one(entry, ours, digits, ws, zs))
    return out


def _z_definition(
    entry: TranscriptEntry, ws: object, zs: dict[str, object]
) -> ResponseCheck:
    """Record ``Z12 = ...`` (earlier intermediates expanded) for the
    responses that use it; the line itself is not compared."""
    try:
        zs[entry.label] = evaluate_text(entry.value_text, ws, zs)
    except Exception as exc:  # noqa: BLE001 - a verdict, never a crash
        text = getattr(exc, "message", None) or str(exc)
        return ResponseCheck(
            entry, False, f"cannot read Autolev's intermediate: {text}", compared=False
        )
    return ResponseCheck(
        entry, True, "AutoZ intermediate, not compared", compared=False
    )


def _check_one(
    entry: TranscriptEntry,
    ours: object,
    digits: int,
    ws: object,
    zs: dict[str, object] | None = None,
) -> ResponseCheck:
    from al2py_runtime.names.printing import autolev_str

    try:
        shown = autolev_str(ours, digits)
    except Exception:  # noqa: BLE001 - only for the report
        shown = str(ours)
    try:
        expected = evaluate_text(entry.value_text, ws, zs)
    except AutolevError as exc:
        return ResponseCheck(
            entry, False, f"cannot read Autolev's response: {exc.message}", shown
        )
    except Exception as exc:  # noqa: BLE001 - a verdict, never a crash
        return ResponseCheck(
            entry, False, f"cannot read Autolev's response: {exc}", shown
        )
    norms = list(getattr(ws, "unit_norms", ()))
    try:
        reason = compare(expected, ours, digits, unit_norms=norms)
        if reason is None:
            return ResponseCheck(entry, True, "strict", shown)
        resolve = ws.resolve  # type: ignore[attr-defined]
        a, b = _as_matrices(expected, ours)
        if compare(resolve(a), resolve(b), digits, unit_norms=norms) is None:
            return ResponseCheck(entry, True, "resolved", shown)
    except Exception as exc:  # noqa: BLE001 - a verdict, never a crash
        return ResponseCheck(entry, False, f"cannot compare: {describe(exc)}", shown)
    return ResponseCheck(entry, False, reason, shown)
