"""The transpiler's shortcuts give what the long ways give (issue 35).

* The two-stage parse (ANTLR's SLL prediction without error recovery first,
  full LL with the reporting error strategy only for a statement where that
  fails) builds the same IR and reports the same errors as the LL parse alone,
  on every example and on broken copies of them.
* ``attach_echoes`` finds the rows that can take an echo from the syntax tree
  and tokenizes only the statements it cannot read there: the rows are those
  the tokenizer finds in the whole module.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
import sympy
from conftest import SHARED as TUTORIAL

from al2py import parser
from al2py.generator import _single_rows, _tokenized_single_rows, attach_echoes
from al2py.parser import parse_partial

ROOT = Path(__file__).resolve().parent.parent
SYMPY_EXAMPLES = Path(sympy.__file__).parent / "parsing" / "autolev" / "test-examples"
SCRIPTS = sorted(
    [
        *(ROOT / "examples").glob("*.al"),
        *(ROOT / "tests" / "golden" / "cases").glob("*.al"),
        *(ROOT / "tests" / "models").glob("*.al"),
        *SYMPY_EXAMPLES.rglob("*.al"),
        *TUTORIAL.glob("*.al"),
    ]
)
MODULES = sorted((ROOT / "tests" / "golden" / "modules").glob("*.py"))


def _parsed(text: str, quick: bool, monkeypatch) -> tuple[str, list[tuple]]:
    """The IR (as its repr) and the errors of ``text``, parsed with the
    two-stage parse or (``quick`` false) with full LL alone."""
    with monkeypatch.context() as m:
        if not quick:
            m.setattr(parser, "_quick_statement", lambda *args: None)
        script, errors = parse_partial(text, "f.al")
    return repr(script), [(str(e), repr(e.span)) for e in errors]


def _broken(text: str, seed: int) -> str:
    """``text`` with three characters removed, replaced or inserted."""
    rnd = random.Random(seed)
    lines = text.split("\n")
    for _ in range(3):
        i = rnd.randrange(len(lines))
        if not lines[i]:
            continue
        j = rnd.randrange(len(lines[i]))
        op = rnd.randrange(3)
        ch = rnd.choice("()[]{},;=+*-/^'\":&x1 .%$@")
        lines[i] = lines[i][:j] + (ch if op else "") + lines[i][j + (op != 1) :]
    return "\n".join(lines)


def test_there_are_scripts():
    assert len(SCRIPTS) >= 40


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: p.name)
def test_two_stage_parse_is_the_ll_parse(path, monkeypatch):
    text = path.read_text(encoding="utf-8", errors="replace")
    assert _parsed(text, True, monkeypatch) == _parsed(text, False, monkeypatch)
    for seed in range(3):
        broken = _broken(text, seed)
        quick = _parsed(broken, True, monkeypatch)
        assert quick == _parsed(broken, False, monkeypatch)


BAD = [
    ":= } =\nCode [ % note\nx = 1\n",
    "Constants a, b\nx = a +\ny = (b\nz = b)\nw = [a, b; a]\n",
    "Variables q'\nq' = q + * 2\nq'' = 1 &\n",
    "Frames A\nA_B = [1 2]\n@ x = 3\nSimprot(N, A, 3\n",
    "x = 1;; y = 2; z = \n%% done\n",
]


@pytest.mark.parametrize("text", BAD)
def test_two_stage_parse_reports_the_same_errors(text, monkeypatch):
    quick = _parsed(text, True, monkeypatch)
    assert quick[1], "every case has errors"
    assert quick == _parsed(text, False, monkeypatch)


def test_the_first_stage_reports_nothing():
    """A statement the first stage cannot parse leaves no error behind: the
    second stage reports it (once, where LL with recovery finds it)."""
    lines = ("x = [1, 2", "y = 3")
    logical = parser.join_continuations(lines)
    stream = parser.CommonTokenStream(
        parser.Lexer(parser.InputStream(logical.text))
    )
    stream.fill()
    listener = parser._ErrorListener("f.al", lines, stream)
    ll = parser.AutolevParser(stream)
    ll.removeErrorListeners()
    ll.addErrorListener(listener)
    ranges = list(parser._statement_ranges(stream.tokens))
    assert parser._quick_statement(ll, stream, *ranges[0]) is None
    assert listener.count == 0
    assert parser._quick_statement(ll, stream, *ranges[1]) is not None


def test_the_first_stage_parses_most_statements(monkeypatch):
    """The quick stage is used (this fails if it always fell back)."""
    calls: list[bool] = []
    quick = parser._quick_statement

    def counted(*args):
        ctx = quick(*args)
        calls.append(ctx is not None)
        return ctx

    monkeypatch.setattr(parser, "_quick_statement", counted)
    parse_partial((ROOT / "examples" / "tutor6.al").read_text(), "tutor6.al")
    assert len(calls) > 50 and all(calls)


TRICKY = '''\
"""Doc."""

# al> A
import os  # a comment
# al> B
x = f(
    1,
)
# al> C
@decorator
def g():
    return 1
# al> D
if x: y = 1
# al> E
else: y = 2
# al> F
a = 1; b = (
    2
)
# al> G
s = "#(" + \\
    "x"
# al> H
t = """
# al> I
"""
# al> J
class K: pass
# al> K
for i in x:
    pass
# al> L
u = [  # c
    1]
# al> M
v = {
}
# al> N
w = "é"
# al> O
try:
    pass
except E:
    pass
# al> P
z = (1 +
     2)
# al> Q
r = 1
c = (
# al> R
    1); d = 2
e = 1; \\
f = (
# al> S
    2)
# al> T
g = 3; h = 4
# al> U
i = 1  # ; \\
# al> V
j = 2
'''


def _unformatted(name: str) -> str:
    from al2py import convert

    path = ROOT / "examples" / name
    return convert(path.read_text(), str(path), formatted=False).code


@pytest.mark.parametrize(
    "path",
    [*MODULES, "TRICKY", "tutor1.al", "tutor6.al"],
    ids=lambda p: getattr(p, "name", p),
)
def test_single_rows_are_the_tokenizers(path):
    if path == "TRICKY":
        code = TRICKY
    elif isinstance(path, str):
        code = _unformatted(path)
    else:
        code = path.read_text()
    for text in (code, code.replace("  # al>", "\n# al>")):
        rows = set(range(1, text.count("\n") + 2))
        assert _single_rows(text, text.split("\n"), rows) == _tokenized_single_rows(
            text, 1
        )


def test_tricky_echoes():
    """The echoes that move in TRICKY (as the whole module's tokens say)."""
    moved = attach_echoes(TRICKY)
    for kept in "AGHIKLOPRSU":
        assert f"\n# al> {kept}\n" in moved
    for taken in "BCDEFJMNQTV":
        assert f"  # al> {taken}\n" in moved
    assert "\nimport os  # a comment\n" in moved
    assert "\n@decorator  # al> C\ndef g():\n" in moved
    assert "\nelse: y = 2  # al> E\n" in moved
    assert '\nw = "é"  # al> N\n' in moved


def test_unparsable_code_is_tokenized_whole():
    code = "# al> A\nx = (((\n# al> B\ny = 1\n"  # not Python
    with pytest.raises(Exception, match="tokenize"):
        attach_echoes(code)
    code = "# al> A\nx = 1 +\n# al> B\ny = 1\n"  # tokenizes, does not parse
    assert attach_echoes(code) == "x = 1 +  # al> A\ny = 1  # al> B\n"


def test_collector_paused_while_converting(monkeypatch):
    """The cycle collector is off during a conversion and on again after it,
    also when the conversion fails; one that was off stays off."""
    import gc

    from al2py import transpile
    from al2py.errors import AutolevError

    seen: list[bool] = []
    parse = transpile.parse_partial

    def watched(*args, **kwargs):
        seen.append(gc.isenabled())
        return parse(*args, **kwargs)

    monkeypatch.setattr(transpile, "parse_partial", watched)
    assert gc.isenabled()
    transpile.convert("Constants a\nx = a + 1\n", "ok.al")
    with pytest.raises(AutolevError):
        transpile.convert("x = (\n", "bad.al")
    assert seen == [False, False] and gc.isenabled()
    gc.disable()
    try:
        transpile.convert("Constants a\n", "off.al")
        assert not gc.isenabled()
    finally:
        gc.enable()
