"""Every runnable example in the runtime's docstrings runs (``make test``).

The public API must have examples: the package itself (the ``Workspace`` a
generated module uses), the vocabulary and the model API (Kane export)."""

from __future__ import annotations

import doctest
import importlib
import pkgutil

import al2py_runtime
import pytest

MODULES = sorted(
    m.name for m in pkgutil.walk_packages(al2py_runtime.__path__, "al2py_runtime.")
)
#: modules whose docstrings must show runnable examples
PUBLIC = [
    "al2py_runtime",
    "al2py_runtime.workspace",
    "al2py_runtime.vocabulary",
    "al2py_runtime.vocabulary.builtins",
    "al2py_runtime.vocabulary.forms",
    "al2py_runtime.vocabulary.kinds",
    "al2py_runtime.model",
    "al2py_runtime.jobs.numerics",
    "al2py_runtime.names.table",
    "al2py_runtime.functions",
    "al2py_runtime.algebra",
    "al2py_runtime.matrices",
    "al2py_runtime.intermediates.autoz",
]


@pytest.mark.parametrize("name", ["al2py_runtime", *MODULES])
def test_examples_run(name):
    result = doctest.testmod(
        importlib.import_module(name), optionflags=doctest.ELLIPSIS, report=False
    )
    assert result.failed == 0
    if name in PUBLIC:
        assert result.attempted > 0, f"{name} has no runnable example"


def test_the_public_modules_exist():
    assert set(PUBLIC) - {"al2py_runtime"} <= set(MODULES)
