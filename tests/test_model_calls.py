"""The generator's ``al.NAME`` -> ``al.model.NAME`` rewrite reads the code as
Python's tokenizer does (issue 35: one regular expression instead of the
tokenizer, the same module text).

:func:`al2py.generator._model_calls` (one pass of a regular expression over
the text) is compared with :func:`_model_calls_tokenized` (the tokenizer's
reading, token by token: the rewrite's former implementation) on every golden module and on code that hides ``al.NAME`` in
strings and comments of every kind.
"""

from __future__ import annotations

import io
import random
import tokenize
from pathlib import Path

import pytest
from al2py_runtime.model.model import MODEL_COMMANDS, Model

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


def _model_calls_tokenized(lines: list[str]) -> list[str]:
    """:func:`_model_calls` by Python's tokenizer (token by token)."""
    text = "\n".join(lines)
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, SyntaxError):  # pragma: no cover - our own code
        raise AssertionError("generated code does not tokenize") from None
    edits: list[tuple[int, int]] = []  # (row, col) where ``model.`` goes
    for k in range(len(tokens) - 2):
        a, dot, name = tokens[k], tokens[k + 1], tokens[k + 2]
        if (
            a.type == tokenize.NAME
            and a.string == "al"
            and dot.string == "."
            and name.type == tokenize.NAME
            and name.string in MODEL_COMMANDS
            and (k == 0 or tokens[k - 1].string != ".")
        ):
            edits.append(name.start)
    out = text.split("\n")
    for row, col in reversed(edits):
        line = out[row - 1]
        out[row - 1] = line[:col] + "model." + line[col:]
    return out


def module_lines(path: Path) -> list[str]:
    text = path.read_text(encoding="utf-8")
    return text.replace("al.model.", "al.").split("\n")  # calls to rewrite


@pytest.mark.parametrize("path", GOLDEN, ids=lambda p: p.stem)
def test_golden_modules_rewritten_as_by_the_tokenizer(path):
    lines = module_lines(path)
    ours = generator._model_calls(lines)
    assert ours == _model_calls_tokenized(lines)


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
    assert generator._model_calls(lines) == _model_calls_tokenized(lines)


def test_random_mixtures():
    rng = random.Random(35)
    for _ in range(300):
        lines = []
        for _ in range(rng.randint(1, 8)):
            lines += rng.choice(SPELLINGS).split("\n")
        assert generator._model_calls(lines) == _model_calls_tokenized(lines), lines


def test_the_model_commands_are_the_marked_methods():
    """:data:`MODEL_COMMANDS`, written out without sympy for the
    transpiler, lists exactly the :class:`Model` methods marked ``@command``
    or ``@query``."""
    marked = set()
    for name in dir(Model):
        attr = getattr(Model, name)
        func = attr.fget if isinstance(attr, property) else attr
        if getattr(func, "autolev_command", False):
            marked.add(name)
    assert len(marked) > 80 and marked == MODEL_COMMANDS
