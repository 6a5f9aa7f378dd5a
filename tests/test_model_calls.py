"""The generator's ``al.NAME`` -> ``al.model.NAME`` rewrite reads the code as
Python's tokenizer does (issue 35: one regular expression instead of the
tokenizer, the same module text).

:func:`al2py.generator._model_calls` (one pass of a regular expression over
the text) is compared with :func:`_model_calls_tokenized` (the tokenizer's
reading) on every golden module and on code that hides ``al.NAME`` in
strings and comments of every kind.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from al2py import generator

GOLDEN = sorted((Path(__file__).parent / "golden" / "modules").glob("*.py"))
SPELLINGS = [
    "al.simprot(N, A, 3, Q)",
    "x = al.dot(a, b)",
    "al.setting('al.simprot')",
    'al.setting("al.dot(x)") + al.dot(y)',
    "y = f'{al.dot(a, b)}' + al.dot(c)",
    "z = rb'al.dot' + b'\\'al.dot' + al.dot(d)",
    "s = '''al.dot\n al.simprot''' + al.dot(e)",
    's = """q\\"""\nal.dot(f)""" + al.cross(g)',
    "s = '''q\\''' al.dot(k) ''' + al.dot(m)",
    "# al> al.dot(x)",
    "v = al.dot(a)  # al.dot too",
    "self.al.dot(x)",
    "val.dot(x) + xal.dot(y) + al_.dot(z)",
    "al.model.dot(x)",
    "u = 'it''s' + al.dot(h)",
    "w = 'a\\\\' + al.dot(i) + 'b\\\\'",
    "if al.dot(x) in'al.dot': pass",
    "al.not_a_command(x)",
    "al . dot(x)",
    "(al.dot(x),\n al.cross(y))",
    "t = 'a' 'al.dot' \"al.dot\" + al.dot(j)",
]


def module_lines(path: Path) -> list[str]:
    text = path.read_text(encoding="utf-8")
    return text.replace("al.model.", "al.").split("\n")  # calls to rewrite


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: p.stem)
def test_golden_modules_rewritten_as_by_the_tokenizer(path):
    lines = module_lines(path)
    ours = generator._model_calls(lines)
    assert ours == generator._model_calls_tokenized(lines)


def test_golden_modules_have_calls_to_rewrite():
    rewritten = sum(
        a != b
        for path in GOLDEN
        for a, b in zip(
            generator._model_calls(module_lines(path)), module_lines(path), strict=True
        )
    )
    assert rewritten > 100


@pytest.mark.parametrize("code", SPELLINGS)
def test_strings_and_comments_left_alone(code):
    lines = code.split("\n")
    assert generator._model_calls(lines) == generator._model_calls_tokenized(lines)


def test_random_mixtures():
    rng = random.Random(35)
    for _ in range(300):
        lines = []
        for _ in range(rng.randint(1, 8)):
            lines += rng.choice(SPELLINGS).split("\n")
        assert generator._model_calls(lines) == generator._model_calls_tokenized(
            lines
        ), lines
