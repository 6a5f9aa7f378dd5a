"""The runtime's structure, checked statically from its source (``ast``).

What is checked, and how far a static check can see:

* **No import cycle** among ``al2py_runtime``'s modules.  Every ``import``
  counts, also one inside a function (a deferred import is still a
  dependency).  Importing ``a.b.c`` first runs the packages ``a`` and
  ``a.b``; that implicit step is not an edge (else every package would be
  in a cycle with its own ``__init__``), but an explicit
  ``from .. import name`` of a package is.
* **No ``__getattr__`` forwarding**: no class or module defines
  ``__getattr__`` or ``__getattribute__``.
* **No cross-object private access**: ``obj._name`` only where ``obj`` is
  ``self``, ``cls`` or ``super()``, and no ``from .mod import _name``.
  A static check cannot know an object's type, so the few private names of
  *other libraries* the runtime must use are listed in :data:`FOREIGN` with
  their owner; the test also proves that no runtime module defines a name
  of that list, so none of our own objects can hide behind it.
"""

from __future__ import annotations

import ast
from pathlib import Path

import al2py_runtime

ROOT = Path(al2py_runtime.__file__).parent
PACKAGE = ROOT.name

#: private names of sympy and the standard library that the runtime uses
FOREIGN = {
    "_t": "sympy: dynamicsymbols._t, mechanics' time symbol (documented usage)",
    "_dcm_dict": "sympy ReferenceFrame: the frames' direction cosine graph",
    "_dcm_cache": "sympy ReferenceFrame: cached direction cosines",
    "_dict_list": "sympy ReferenceFrame: the frames' angular velocity graphs",
    "_print": "sympy printers' dispatch (the printer extension protocol)",
    "_module_format": "sympy code printers: a qualified function name",
    "_mpf_": "mpmath's raw value of a sympy Float",
    "_getframe": "sys._getframe: the generated module's line",
    "_current_frames": "sys._current_frames: the statement a long import derives",
    "_exit": "os._exit",
}


def _modules() -> dict[str, Path]:
    out = {}
    for path in sorted(ROOT.rglob("*.py")):
        parts = list(path.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


MODULES = _modules()
TREES = {
    name: ast.parse(path.read_text(encoding="utf-8")) for name, path in MODULES.items()
}


def _imported(module: str, node: ast.Import | ast.ImportFrom) -> list[str]:
    """The runtime modules that an import statement names."""
    if isinstance(node, ast.Import):
        return [a.name for a in node.names if a.name in MODULES]
    if node.level:
        path = module.split(".")
        if not MODULES[module].name == "__init__.py":
            path.pop()
        path = path[: len(path) - node.level + 1]
        target = ".".join(path + ([node.module] if node.module else []))
    else:
        target = node.module or ""
    out = []
    for alias in node.names:
        sub = f"{target}.{alias.name}"
        if sub in MODULES:
            out.append(sub)
        elif target in MODULES:
            out.append(target)
    return out


def import_graph() -> dict[str, set[str]]:
    graph: dict[str, set[str]] = {}
    for module, tree in TREES.items():
        deps = graph.setdefault(module, set())
        for node in ast.walk(tree):
            if isinstance(node, ast.Import | ast.ImportFrom):
                deps.update(d for d in _imported(module, node) if d != module)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_the_checker_finds_a_cycle():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_the_import_graph_sees_relative_and_deferred_imports():
    graph = import_graph()
    assert f"{PACKAGE}.workspace" in graph[PACKAGE]
    assert f"{PACKAGE}.jobs.records" in graph[f"{PACKAGE}.jobs.budget"]  # deferred
    assert (
        f"{PACKAGE}.jobs.backends" in graph[f"{PACKAGE}.codegen"]
    )  # from ..jobs import


def test_no_import_cycle():
    assert cycles(import_graph()) == []


def test_no_getattr_forwarding():
    found = [
        f"{MODULES[m].relative_to(ROOT)}:{node.lineno}"
        for m, tree in TREES.items()
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef)
        and node.name in ("__getattr__", "__getattribute__")
    ]
    assert found == []


def _own(node: ast.expr) -> bool:
    if isinstance(node, ast.Name):
        return node.id in ("self", "cls")
    return (
        isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id == "super"
    )


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def private_access(tree: ast.AST) -> list[tuple[int, str]]:
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute) and _private(node.attr):
            if not _own(node.value) and node.attr not in FOREIGN:
                found.append((node.lineno, ast.unparse(node)))
        elif isinstance(node, ast.ImportFrom):
            found += [
                (node.lineno, f"from {node.module} import {a.name}")
                for a in node.names
                if _private(a.name)
            ]
    return found


def test_the_checker_finds_private_access():
    tree = ast.parse(
        "self._a\ncls._b\nsuper()._c\nws._names\nself.ws._rhs\nfrom .x import _y\n"
    )
    assert sorted(line for line, _ in private_access(tree)) == [4, 5, 6]


def test_no_cross_object_private_access():
    found = [
        f"{MODULES[m].relative_to(ROOT)}:{line}: {text}"
        for m, tree in TREES.items()
        for line, text in private_access(tree)
    ]
    assert found == []


def test_foreign_private_names_are_not_ours():
    """No runtime module defines a name of :data:`FOREIGN`, so allowing it
    cannot hide an access to one of the runtime's own private attributes."""
    defined = set()
    for tree in TREES.values():
        for node in ast.walk(tree):
            if isinstance(node, ast.FunctionDef | ast.ClassDef):
                defined.add(node.name)
            elif isinstance(node, ast.Name | ast.Attribute) and isinstance(
                node.ctx, ast.Store
            ):
                defined.add(node.id if isinstance(node, ast.Name) else node.attr)
            elif isinstance(node, ast.arg):
                defined.add(node.arg)
    assert defined & set(FOREIGN) == set()
