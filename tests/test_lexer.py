"""``al2py.lexer.Lexer`` reads the tokens ANTLR's generated lexer reads
(``grammar/Autolev.g4``'s lexer rules): the same type, channel, start,
stop, text, line, column and index, token for token, on every script the
tests have (and the tutorial's, when it is beside the project) and on
random text made of the characters and words where the rules meet
(keywords and names, numbers, file names, arrows, strings, comments, the
newlines, and the four non-ASCII letters that case-insensitive ``[a-z]``
could be taken to hold)"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from antlr4 import CommonTokenStream, InputStream, Token

from al2py import lexer as lexer_module
from al2py._antlr.AutolevLexer import AutolevLexer
from al2py.lexer import Lexer

ROOT = Path(__file__).resolve().parents[1]
SHARED = ROOT.parent / "shared"

ALPHABET = [
    *"aAzZkKsSiIeE019_.~>+- \t\f\v\r\n\"%&:=*/^'()[]{},;!#\\@$",
    *["\u0130", "\u0131", "\u017f", "\u212a", "é", "ß", "\U0001f600"],
]
WORDS = [
    "constants", "Variables", "motionvariable", "MotionVariables", "body",
    "bodies", "inputs", "output", "code", "Run", "1>>", "0>", "0>>>", "1.e5",
    ".5e-3", "12.", "tutor2.all", "a.b.c", "x>>", "1.e", "..", "~/x.al",
    "UNITSYSTEM", "frames>", "point_", '"a b"', '"open', "% note", "\r\n",
]  # fmt: skip


def _tokens(text: str, make) -> list[tuple]:
    out = []
    for token in _stream(text, make).tokens:
        out.append(
            (
                token.type,
                token.channel,
                token.start,
                token.stop,
                token.text,
                token.line,
                token.column,
                token.tokenIndex,
            )
        )
    assert out[-1][0] == Token.EOF
    return out


def _stream(text: str, make) -> CommonTokenStream:
    stream = CommonTokenStream(make(InputStream(text)))
    stream.fill()
    return stream


def _scripts() -> list[Path]:
    found = sorted((ROOT / "examples").glob("*.al"))
    found += sorted((ROOT / "tests").rglob("*.al"))
    found += sorted((SHARED / "tutorial").glob("*.al"))  # when beside us
    return found


def _random_texts(n: int, seed: int) -> list[str]:
    rng = random.Random(seed)
    texts = []
    for _ in range(n):
        parts = [
            rng.choice(ALPHABET) if rng.random() < 0.7 else rng.choice(WORDS)
            for _ in range(rng.randint(0, 25))
        ]
        texts.append("".join(parts))
    return texts


def _differences(texts: list[str]) -> list[str]:
    return [t for t in texts if _tokens(t, Lexer) != _tokens(t, AutolevLexer)]


def test_every_script_lexes_as_antlr_lexes_it():
    scripts = _scripts()
    assert len(scripts) > 20
    texts = [p.read_text(encoding="utf-8", errors="replace") for p in scripts]
    assert _differences(texts) == []


def test_random_text_lexes_as_antlr_lexes_it():
    assert _differences(_random_texts(3000, seed=5)) == []


@pytest.mark.parametrize(
    "broken",
    [
        {"_KEYWORDS": {}},  # keywords read as names
        {"_ARROWS": lexer_module.re.compile(r">")},  # one arrow only
        {"_COMMENT_CHANNEL": 0},  # comments on the parser's channel
    ],
)
def test_the_comparison_finds_a_wrong_lexer(broken, monkeypatch):
    for name, value in broken.items():
        monkeypatch.setattr(lexer_module, name, value)
    assert _differences(_random_texts(400, seed=6))
