"""The runtime's structure, checked statically from its source (``ast``).

What is checked, and how far a static check can see:

* **No import cycle** among ``al2py_runtime``'s modules.  Every ``import``
  counts, also one inside a function (a deferred import is still a
  dependency).  Importing ``a.b.c`` first runs the packages ``a`` and
  ``a.b``; that implicit step is not an edge (else every package would be
  in a cycle with its own ``__init__``), but an explicit
  ``from .. import name`` of a package is.
* **No ``__getattr__`` forwarding**: no class or module defines
  ``__getattr__`` or ``__getattribute__``, except the package itself
  (``al2py_runtime/__init__.py``), whose module ``__getattr__`` imports its
  exported names on first use (PEP 562, as sympy and scipy do), so that
  the transpiler reads the runtime's tables without importing sympy.
* **No cross-object private access**: ``obj._name`` only where ``obj`` is
  ``self``, ``cls`` or ``super()``, and no ``from .mod import _name``.
  A static check cannot know an object's type, so the few private names of
  *other libraries* the runtime must use are listed in :data:`FOREIGN` with
  their owner; the test also proves that no runtime module defines a name
  of that list, so none of our own objects can hide behind it.
* **No private name shared across modules through ``self``**: ``self._x``
  only in the module that defines ``_x`` (a ``def``, a class or an
  assignment).  This is what keeps the parts of
  :class:`~al2py_runtime.model.model.Model` (one mixin per module of
  ``model/``) honest: a part that needs another's method calls a public one.
* **No one-line forwarder**: no method's whole body hands its own
  parameters, unchanged, to the method of the same name of one of its
  attributes (``def run(self, v): return self.numerics.run(v)``).  A generated module
  calls the part that does the work (``al.numerics.run``,
  ``al.settings.set``; see :func:`test_a_run_parameter_goes_straight_to_the_job`).
* **The model parts' interface is explicit**: a method that one module of
  ``model/`` defines and another calls on ``self`` is public, has a docstring
  and a return annotation.
* **A module's calls resolve to methods written in their class** (issue 33):
  every ``al.NAME``, ``al.model.NAME``, ``al.numerics.NAME`` and
  ``al.settings.NAME`` call of the golden modules is a function defined in
  the body of ``Workspace``, ``Model`` (or one of its parts), ``Numerics``
  or ``Settings``, as an editor's go-to-definition or ``mypy`` finds it; no
  class gains a method at import (no ``setattr`` on a class, no
  ``Class.attr = ...`` outside its body), and no caller's frame is read
  (``sys._getframe``).
"""

from __future__ import annotations

import ast
import math
from pathlib import Path

import al2py_runtime
import pytest

ROOT = Path(al2py_runtime.__file__).parent
PACKAGE = ROOT.name

#: private names of sympy and the standard library that the runtime uses
FOREIGN = {
    "_t": "sympy: dynamicsymbols._t, mechanics' time symbol (documented usage)",
    "_dcm_dict": "sympy ReferenceFrame: the frames' direction cosine graph",
    "_dcm_cache": "sympy ReferenceFrame: cached direction cosines",
    "_dict_list": "sympy ReferenceFrame: the frames' angular velocity graphs",
    "_ang_vel_dict": "sympy ReferenceFrame: the angular velocities given to it"
    " (the edges kinematics.ang_vel_in walks, as sympy's ang_vel_in sums them)",
    "_dcm": "sympy ReferenceFrame: sets direction cosines (orient_explicit"
    " without differentiating them for an angular velocity set at once)",
    "_var_dict": "sympy ReferenceFrame: cached variable maps (reset on a new"
    " orientation, as sympy's orient_* do)",
    "_pos_dict": "sympy Point: the positions given to it (set_pos), the edges"
    " of Autolev's position chains (model/points.py; docs/semantics.md,"
    ' "Kinematics stored on the sympy objects")',
    "_vel_dict": "sympy Point: its velocities; a V2pts deferred by Autolev's"
    " rule withdraws a given one (sympy has no unset)",
    "_print": "sympy printers' dispatch (the printer extension protocol)",
    "_print_level": "sympy Printer: how deep _print calls are (a Float alone is"
    " printed with its zeros at depth 1; codegen/printers.py ProgramPrinter"
    " remembers only parts printed deeper)",
    "_module_format": "sympy code printers: a qualified function name",
    "_mpf_": "mpmath's raw value of a sympy Float",
    "_current_frames": "sys._current_frames: the statement a long import derives",
    "_exit": "os._exit",
    "_assume_defined": "sympy.core.assumptions: the names of sympy's facts"
    " (intermediates answer them from one table, autoz.py)",
    "_from_args": "sympy AssocOp: a sum or product from arguments already in"
    " sympy's canonical form (autoz.product_with and autoz.minus, tested equal"
    " to sympy's constructors)",
    "_parse_order": "sympy Expr: the term order of as_ordered_terms"
    " (autoz.minus_first decides a sum's sign as could_extract_minus_sign)",
    "_hashable_content": "sympy Basic: what Basic.compare orders by"
    " (autoz._compare, tested equal to Basic.compare)",
    "_args_sortkey": "sympy.core.basic: the key sympy's sums and products sort"
    " their arguments by (codegen/program.py renamed_evaluated builds a renamed"
    " node in sympy's order, tested equal to xreplace)",
    "_constructor_postprocessor_mapping": "sympy Basic: the classes whose"
    " constructors post-process (jobs/run.py renamed builds plain nodes only"
    " where none applies)",
    "_get_statement": "sympy code printers: a statement's text with its"
    " terminator (codegen/printers.py prints a plain assignment directly)",
    "_format_code": "sympy code printers: a statement's lines indented (and"
    " wrapped: Fortran) as doprint formats them (codegen/printers.py prints a"
    " plain assignment directly)",
    "_eval_subs": "sympy Basic: a class's own rule for subs (model/kinematics.py"
    " _collect substitutes by xreplace only where every node's rule is sympy's"
    " generic rebuild, tested equal to sympy's collect)",
    "_keep_coeff": "sympy.core.mul: a coefficient times a term, undistributed, as"
    " sympy's printers' _print_Mul forms a product's magnitude (codegen/octave.py,"
    " codegen/fortran.py, jobs/backends.py print the same text faster)",
    "_kwargs": "sympy UndefinedFunction: the assumptions its __eq__ compares"
    " (names.variables.TimeFunction, equal to dynamicsymbols' functions)",
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


def everywhere(check) -> list[str]:
    """``path:line: what`` for each finding of ``check`` in every module."""
    return [
        f"{MODULES[m].relative_to(ROOT)}:{line}: {what}"
        for m, tree in TREES.items()
        for line, what in check(tree)
    ]


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
    lazy_exports = TREES[PACKAGE].body  # the package's module __getattr__
    found = [
        f"{MODULES[m].relative_to(ROOT)}:{node.lineno}"
        for m, tree in TREES.items()
        for node in ast.walk(tree)
        if isinstance(node, ast.FunctionDef)
        and node.name in ("__getattr__", "__getattribute__")
        and not (m == PACKAGE and node in lazy_exports)
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
                and not (a.name in FOREIGN and _foreign_module(node))
            ]
    return found


def _foreign_module(node: ast.ImportFrom) -> bool:
    """An absolute import from another library (not the runtime)."""
    return not node.level and not (node.module or "").startswith(PACKAGE)


def test_the_checker_finds_private_access():
    tree = ast.parse(
        "self._a\ncls._b\nsuper()._c\nws._names\nself.ws._rhs\nfrom .x import _y\n"
    )
    assert sorted(line for line, _ in private_access(tree)) == [4, 5, 6]


def test_no_cross_object_private_access():
    assert everywhere(private_access) == []


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


def _defined(tree: ast.AST) -> set[str]:
    """Names a module defines: functions, classes, assigned names and
    attributes (``self._x = ...``) and parameters."""
    out = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
            out.add(node.name)
        elif isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            out.add(node.id)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            out.add(node.attr)
    return out


def foreign_self_private(tree: ast.AST) -> list[tuple[int, str]]:
    """``self._x``/``cls._x`` where this module defines no ``_x``: a private
    name of another module (a sibling mixin's or a base class's)."""
    own = _defined(tree)
    return [
        (node.lineno, ast.unparse(node))
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute)
        and _private(node.attr)
        and _own(node.value)
        and node.attr not in own
        and node.attr not in FOREIGN
    ]


def test_the_checker_finds_a_siblings_private_name():
    mine = ast.parse("class A:\n    def _a(self):\n        self._b = self._a()\n")
    assert foreign_self_private(mine) == []
    theirs = ast.parse("class B:\n    def f(self):\n        return self._a(self._b)\n")
    assert [line for line, _ in foreign_self_private(theirs)] == [3, 3]


def test_no_private_name_used_outside_its_module():
    assert everywhere(foreign_self_private) == []


MODEL = f"{PACKAGE}.model."


def model_interface() -> dict[tuple[str, str], list[str]]:
    """``(defining module, method) -> [calling modules]`` for the methods of
    one ``model/`` module's classes called on ``self`` in another."""
    methods: dict[str, tuple[str, ast.FunctionDef]] = {}
    for m, tree in TREES.items():
        if m.startswith(MODEL):
            for cls in tree.body:
                if isinstance(cls, ast.ClassDef):
                    for f in cls.body:
                        if isinstance(f, ast.FunctionDef):
                            methods.setdefault(f.name, (m, f))
    used: dict[tuple[str, str], list[str]] = {}
    for m, tree in TREES.items():
        if not m.startswith(MODEL):
            continue
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id == "self"
                and node.attr in methods
                and methods[node.attr][0] != m
            ):
                users = used.setdefault((methods[node.attr][0], node.attr), [])
                if m not in users:
                    users.append(m)
    return used


def test_the_model_parts_call_each_other():
    """The interface check sees real calls (else it would prove nothing)."""
    used = model_interface()
    assert f"{MODEL}equations" in used[(f"{MODEL}speeds", "fr_speeds")]
    assert f"{MODEL}objects" in used[(f"{MODEL}points", "add_position")]


def test_the_model_parts_interface_is_public_documented_and_typed():
    bad = []
    for (m, name), users in sorted(model_interface().items()):
        f = next(
            f
            for cls in TREES[m].body
            if isinstance(cls, ast.ClassDef)
            for f in cls.body
            if isinstance(f, ast.FunctionDef) and f.name == name
        )
        missing = [
            what
            for what, ok in (
                ("public", not _private(name)),
                ("docstring", ast.get_docstring(f) is not None),
                ("return annotation", f.returns is not None),
            )
            if not ok
        ]
        if missing:
            bad.append(f"{m}.{name} (used by {', '.join(users)}): {missing}")
    assert bad == []


def _parameters(f: ast.FunctionDef) -> list[str]:
    a = f.args
    return [p.arg for p in [*a.posonlyargs, *a.args, *a.kwonlyargs]][1:] + [
        p.arg for p in (a.vararg, a.kwarg) if p is not None
    ]


def _passed(call: ast.Call) -> list[str] | None:
    out = []
    for a in [*call.args, *(k.value for k in call.keywords)]:
        if isinstance(a, ast.Starred):
            a = a.value
        if not isinstance(a, ast.Name):
            return None
        out.append(a.id)
    return out


def forwarders(tree: ast.AST) -> list[tuple[int, str]]:
    """Methods whose whole body is ``self.part.<same name>(<its parameters>)``."""
    found = []
    for cls in ast.walk(tree):
        if not isinstance(cls, ast.ClassDef):
            continue
        for f in cls.body:
            if not isinstance(f, ast.FunctionDef):
                continue
            body = f.body[1:] if ast.get_docstring(f) is not None else f.body
            if len(body) != 1 or not isinstance(body[0], ast.Return | ast.Expr):
                continue
            call = body[0].value
            if (
                isinstance(call, ast.Call)
                and isinstance(call.func, ast.Attribute)
                and isinstance(call.func.value, ast.Attribute)
                and _own(call.func.value.value)
                and call.func.attr.lstrip("_") == f.name.lstrip("_")
                and _passed(call) == _parameters(f)
            ):
                found.append((f.lineno, f"{cls.name}.{f.name}"))
    return found


def test_the_checker_finds_a_forwarder():
    tree = ast.parse(
        "class W:\n"
        "    def run(self, values=None, /, **more):\n"
        "        'Run.'\n"
        "        return self.numerics.run(values, **more)\n"
        "    def set(self, name, value):\n"
        "        self.settings.set(name, value.upper())\n"
        "    def save(self, name):\n"
        "        self.saves.append(name)\n"
    )
    assert forwarders(tree) == [(2, "W.run")]


def test_no_one_line_forwarder():
    assert everywhere(forwarders) == []


PATH_SCRIPT = """\
Variables X'
Constants A
X' = -A*X
Input A = 2, X = 1, TFINAL = 1, INTEGSTP = 0.5
Output T, X
CODE ODE() decay.c
"""


def test_a_run_parameter_goes_straight_to_the_job(tmp_path, monkeypatch):
    """The path of ``run(job=..., backend=..., A=3)`` and of ``Input``
    values, from the generated module to where they are used:

    * ``Input A = 2`` is ``al.numerics.input({"A": 2}, line=N)``:
      :meth:`Numerics.input` stores an ``InputValue``, and ``CODE``
      (``al.numerics.code``) snapshots the Inputs into its ``Job``;
    * the module's ``run(values, **overrides)`` is
      ``al.numerics.run(values, **overrides)``: :meth:`Numerics.run` picks
      the ``Job`` (``job=``) and merges the overrides, then
      :func:`~al2py_runtime.jobs.run.run_job` converts Inputs and overrides
      to internal units (``input_values``) and hands ``backend`` to the
      dynamics (``ode_system`` -> ``backends.choose``/``compile_dynamics``).

    No workspace method sits between: the module's ``al`` holds the parts."""
    from al2py_runtime.jobs import run as runner

    from al2py import convert

    code = convert(PATH_SCRIPT, "decay.al").code
    assert "al.numerics.input({" in code
    assert "return al.numerics.run(values, **overrides)" in code
    path = tmp_path / "decay_path.py"
    path.write_text(code, encoding="utf-8")
    namespace: dict = {"__name__": "decay_path", "__file__": str(path)}
    exec(compile(code, str(path), "exec"), namespace)

    seen = []
    real = runner.run_job

    def spy(job, overrides, **kw):
        seen.append((job.inputs["A"].value, dict(overrides), kw))
        return real(job, overrides, **kw)

    monkeypatch.setattr(runner, "run_job", spy)
    result = namespace["run"](A=3, backend="lambdify", job="decay")
    ((given, overrides, kw),) = seen
    assert given == 2 and overrides == {"A": 3}
    assert kw == {"backend": "lambdify", "zero_missing": None}
    assert result["X"][-1] == pytest.approx(math.exp(-3), rel=1e-4)


def test_the_layout_names_every_runtime_module():
    """The layout table (docs/layout.md) names each folder and module of the
    runtime (with the one concept it owns)."""
    import re

    layout = (ROOT.parents[1] / "docs" / "layout.md").read_text(encoding="utf-8")
    words = set(re.findall(r"\w+", layout))
    missing = [
        str(path.relative_to(ROOT))
        for path in sorted(ROOT.rglob("*.py"))
        if path.name != "__init__.py" and path.stem not in words
    ] + [
        f"{d.name}/"
        for d in sorted(ROOT.iterdir())
        if d.is_dir() and (d / "__init__.py").exists() and f"{d.name}/" not in layout
    ]
    assert missing == []


# ------------------------------------------------- the module's API (issue 33)

GOLDEN_MODULES = ROOT.parent.parent / "tests" / "golden" / "modules"


def _owners() -> dict[str, type]:
    from al2py_runtime.jobs.numerics import Numerics
    from al2py_runtime.model.model import Model
    from al2py_runtime.names.settings import Settings
    from al2py_runtime.workspace import Workspace

    return {"al": Workspace, "model": Model, "numerics": Numerics, "settings": Settings}


def written_in_class(cls: type, name: str) -> bool:
    """``cls.name`` is a function written in the body of ``cls`` or of one of
    its bases (its source is there), not one attached later."""
    import inspect

    for base in cls.__mro__:
        func = base.__dict__.get(name)
        if func is None:
            continue
        func = inspect.unwrap(getattr(func, "fget", func))
        if not inspect.isfunction(func):
            return False
        return func.__qualname__ == f"{base.__name__}.{name}"
    return False


def module_calls(tree: ast.AST) -> set[tuple[str, str]]:
    """``(owner, method)`` of every ``al.m(...)``, ``al.model.m(...)``,
    ``al.numerics.m(...)`` and ``al.settings.m(...)`` call in a module."""
    out = set()
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute)):
            continue
        target = node.func.value
        if isinstance(target, ast.Name) and target.id == "al":
            out.add(("al", node.func.attr))
        elif (
            isinstance(target, ast.Attribute)
            and isinstance(target.value, ast.Name)
            and target.value.id == "al"
        ):
            out.add((target.attr, node.func.attr))
    return out


def test_the_checker_finds_an_attached_method():
    from al2py_runtime.workspace import Workspace

    class Late:
        pass

    Late.offered = lambda self: None  # type: ignore[attr-defined]
    assert not written_in_class(Late, "offered")
    assert written_in_class(Workspace, "assign")
    assert not written_in_class(Workspace, "simprot")  # a Model command


def test_every_module_call_is_written_in_its_class():
    owners = _owners()
    modules = sorted(GOLDEN_MODULES.glob("*.py"))
    assert len(modules) > 20
    unresolved = []
    for path in modules:
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for owner, name in sorted(module_calls(tree)):
            if owner not in owners or not written_in_class(owners[owner], name):
                unresolved.append(f"{path.name}: al.{owner}.{name}")
    assert unresolved == []


def class_patches(tree: ast.AST) -> list[tuple[int, str]]:
    """``setattr(Class, ...)`` and ``Class.attr = ...`` outside a class body
    (a capitalized name taken for a class)."""
    out = []
    for node in ast.walk(tree):
        if (
            isinstance(node, ast.Call)
            and isinstance(node.func, ast.Name)
            and node.func.id == "setattr"
            and node.args
            and isinstance(node.args[0], ast.Name)
            and node.args[0].id[:1].isupper()
        ):
            out.append((node.lineno, f"setattr({node.args[0].id}, ...)"))
        if isinstance(node, ast.Assign):
            for target in node.targets:
                if (
                    isinstance(target, ast.Attribute)
                    and isinstance(target.value, ast.Name)
                    and target.value.id[:1].isupper()
                ):
                    out.append((node.lineno, f"{target.value.id}.{target.attr} = ..."))
    return out


def test_the_checker_finds_a_class_patch():
    tree = ast.parse("setattr(Workspace, 'simprot', f)\nModel.x = property(g)\n")
    assert sorted(what for _, what in class_patches(tree)) == [
        "Model.x = ...",
        "setattr(Workspace, ...)",
    ]


def test_no_class_gains_a_method_at_import():
    assert everywhere(class_patches) == []


def test_no_caller_frame_is_read():
    def frames(tree: ast.AST) -> list[tuple[int, str]]:
        return [
            (node.lineno, node.attr)
            for node in ast.walk(tree)
            if isinstance(node, ast.Attribute) and node.attr == "_getframe"
        ]

    assert everywhere(frames) == []


# ------------------------------- narrow, typed collaborators (issue 33)


def _class_defs() -> dict[str, tuple[str, ast.ClassDef]]:
    """Every class of the runtime by name: ``name -> (module, node)``."""
    out: dict[str, tuple[str, ast.ClassDef]] = {}
    for m, tree in TREES.items():
        for node in ast.walk(tree):
            if isinstance(node, ast.ClassDef):
                out.setdefault(node.name, (m, node))
    return out


def _is_protocol(cls: ast.ClassDef) -> bool:
    return any(isinstance(b, ast.Name) and b.id == "Protocol" for b in cls.bases)


def _init_of(cls: ast.ClassDef) -> ast.FunctionDef | None:
    return next(
        (
            f
            for f in cls.body
            if isinstance(f, ast.FunctionDef) and f.name == "__init__"
        ),
        None,
    )


def _init_params(cls: ast.ClassDef) -> list[tuple[str, ast.expr | None]]:
    """``(name, annotation)`` of what constructing ``cls`` takes: its
    ``__init__``'s parameters, or a dataclass's fields."""
    init = _init_of(cls)
    if init is None:
        return [
            (n.target.id, n.annotation)
            for n in cls.body
            if isinstance(n, ast.AnnAssign) and isinstance(n.target, ast.Name)
        ]
    return [(a.arg, a.annotation) for a in init.args.args[1:] + init.args.kwonlyargs]


def handed_self(tree: ast.AST, classes: dict) -> list[tuple[int, str]]:
    """``(line, what)`` for each object a class's ``__init__`` makes with
    ``self`` as an argument (a part given its owner) whose receiving
    parameter is not annotated with a ``Protocol``: an owner handed to a
    part must reach it as a narrow, typed collaborator, never as ``Any``."""
    found = []
    for owner in ast.walk(tree):
        if not isinstance(owner, ast.ClassDef) or _init_of(owner) is None:
            continue
        for call in ast.walk(_init_of(owner)):
            if not (isinstance(call, ast.Call) and isinstance(call.func, ast.Name)):
                continue
            if call.func.id not in classes:
                continue
            params = _init_params(classes[call.func.id][1])
            by_name = {name: ann for name, ann in params}
            given = [
                params[i]
                for i, a in enumerate(call.args)
                if isinstance(a, ast.Name) and a.id == "self" and i < len(params)
            ] + [
                (k.arg, by_name.get(k.arg))
                for k in call.keywords
                if isinstance(k.value, ast.Name) and k.value.id == "self"
            ]
            for param, ann in given:
                name = (
                    ann.id
                    if isinstance(ann, ast.Name)
                    else ast.unparse(ann or ast.Constant(None))
                )
                if not (name in classes and _is_protocol(classes[name][1])):
                    found.append(
                        (
                            call.lineno,
                            f"{owner.name} gives itself to {call.func.id}({param}: {name})",
                        )
                    )
    return found


def test_the_checker_finds_an_owner_handed_as_any():
    tree = ast.parse(
        "from typing import Any, Protocol\n"
        "class Names(Protocol):\n    def val(self, x: Any) -> Any: ...\n"
        "class Part:\n    def __init__(self, ws: Any) -> None:\n        self.ws = ws\n"
        "class Good:\n    def __init__(self, ws: Names) -> None:\n        self.ws = ws\n"
        "class Owner:\n    def __init__(self) -> None:\n"
        "        self.part = Part(self)\n        self.good = Good(ws=self)\n"
    )
    classes = {n.name: ("m", n) for n in ast.walk(tree) if isinstance(n, ast.ClassDef)}
    assert handed_self(tree, classes) == [(12, "Owner gives itself to Part(ws: Any)")]


def test_no_part_holds_an_untyped_reference_to_its_owner():
    """The workspace's parts (``al.model``, ``al.numerics``...) receive it
    only through a ``Protocol`` that lists what they call (issue 33): no
    ``ws: Any`` back-reference."""
    classes = _class_defs()
    found = [
        f"{MODULES[m].relative_to(ROOT)}:{line}: {what}"
        for m, tree in TREES.items()
        for line, what in handed_self(tree, classes)
    ]
    assert found == []
    # the check sees the parts the workspace makes
    tree = TREES[f"{PACKAGE}.workspace"]
    made = {
        c.func.id
        for c in ast.walk(tree)
        if isinstance(c, ast.Call)
        and isinstance(c.func, ast.Name)
        and any(isinstance(a, ast.Name) and a.id == "self" for a in c.args)
    }
    assert {"Model", "Numerics"} <= made


def _members(cls: ast.ClassDef) -> set[str]:
    """Names a class body defines: methods, annotated and assigned names."""
    out = set()
    for node in cls.body:
        if isinstance(node, ast.FunctionDef):
            out.add(node.name)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            out.add(node.target.id)
        elif isinstance(node, ast.Assign):
            out.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return out


def _uses(tree: ast.AST, holder: str, attr: str) -> list[tuple[int, str]]:
    """``(line, name)`` of each ``holder.attr.name`` (``self.script.val``)."""
    return [
        (node.lineno, node.attr)
        for node in ast.walk(tree)
        if isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Attribute)
        and node.value.attr == attr
        and isinstance(node.value.value, ast.Name)
        and node.value.value.id == holder
    ]


def test_the_model_parts_use_only_what_they_are_given():
    """Every ``self.x`` of a part of ``Model`` is declared in a part (a
    method, or an annotation of :class:`ModelPart`, set by ``Model``'s
    constructor), and every call on ``self.script`` (``model.script``) is a
    member of :class:`ScriptNames`: a reader, or ``mypy``, sees what each
    part uses of the script."""
    classes = _class_defs()
    parts = [
        (m, cls)
        for m, tree in TREES.items()
        if m.startswith(MODEL)
        for cls in tree.body
        if isinstance(cls, ast.ClassDef)
        and (
            cls.name in ("Model", "ModelPart")
            or any(isinstance(b, ast.Name) and b.id == "ModelPart" for b in cls.bases)
        )
    ]
    assert len(parts) >= 9  # ModelPart, Model and its seven parts
    declared = set().union(*(_members(cls) for _m, cls in parts))
    bad = [
        f"{MODULES[m].relative_to(ROOT)}:{node.lineno}: self.{node.attr}"
        for m, cls in parts
        for node in ast.walk(cls)
        if isinstance(node, ast.Attribute)
        and isinstance(node.value, ast.Name)
        and node.value.id == "self"
        and node.attr not in declared
    ]
    assert bad == []
    allowed = _members(classes["ScriptNames"][1])
    calls = [
        (m, line, name)
        for m, tree in TREES.items()
        if m.startswith(MODEL)
        for holder in ("self", "model")
        for line, name in _uses(tree, holder, "script")
    ]
    assert len(calls) > 40
    assert [c for c in calls if c[2] not in allowed] == []
    allowed = _members(classes["ScriptValues"][1])
    calls = _uses(TREES[f"{PACKAGE}.jobs.numerics"], "self", "_script")
    assert calls and [c for c in calls if c[1] not in allowed] == []


def test_the_workspace_is_what_its_parts_call():
    """The workspace has each member of the protocols its parts receive,
    with the same parameters (the protocols describe it, not a wish)."""
    import inspect

    from al2py_runtime.jobs.numerics import ScriptValues
    from al2py_runtime.model.script import ScriptNames
    from al2py_runtime.workspace import Workspace

    def shape(func) -> list[tuple[str, object]]:
        params = inspect.signature(inspect.unwrap(func)).parameters.values()
        return [(p.name, p.kind) for p in params]

    for protocol in (ScriptNames, ScriptValues):
        for name, member in vars(protocol).items():
            if name.startswith("_"):
                continue
            mine = inspect.getattr_static(Workspace, name)
            if isinstance(member, property):
                assert isinstance(mine, property), name
            else:
                assert shape(mine) == shape(member), name


def test_positions_and_velocities_are_stored_once():
    """Positions and velocities live in sympy's ``Point`` only (issue 33):
    the model's registry holds no position or velocity vector, and sympy's
    own ``pos_from``/``vel`` give Autolev's values; masses are the sympy
    ``RigidBody``/``Particle``'s."""
    import dataclasses

    import sympy as sp
    from al2py_runtime import Workspace
    from sympy.physics.vector import Vector

    al = Workspace("once.al")
    n = al.model.newtonian("N")
    a = al.model.bodies("A")
    o, p, q = al.model.points("O", "P", "Q")
    qa, u = al.variables("QA'", "U'")
    length = al.constants("L")
    al.model.simprot(n, a, 3, qa)
    al.assign("QA'", u)
    al.assign("P_O_P>", length * a.x)
    al.assign("P_P_Q>", length * a.y)
    al.assign("V_O_N>", 0)
    al.model.v2pts(n, a, o, p)
    al.assign("A_O_N>", 0)
    al.model.a2pts(n, a, o, p)
    al.assign("ALF_A_N>", al.dt(al["W_A_N>"], n))
    al.model.set_mass(a, 2)
    al.assign("FORCE_P>", length * n.x)
    al.model.gravity(-length * n.y)
    assert q.pos_from(o) == al["P_O_Q>"] == length * (a.x + a.y)
    assert p.vel(n) == al["V_P_N>"]
    assert sp.simplify(al["V_P_N>"].dot(a.y) - length * u) == 0
    # Autolev's rule forms V_Q_N> when used (not stored)
    assert al["V_Q_N>"] != Vector(0)

    def vectors(x) -> bool:
        if isinstance(x, Vector):
            return True
        if isinstance(x, dict):
            return any(vectors(k) or vectors(v) for k, v in x.items())
        if isinstance(x, list | tuple | set):
            return any(vectors(e) for e in x)
        return False

    registry = al.model.registry
    holding = {
        f.name
        for f in dataclasses.fields(registry)
        if vectors(getattr(registry, f.name))
    }
    # accelerations Autolev forms (not sympy's: see ModelState), and loads
    assert holding == {"acc", "angacc", "angacc_given", "loads", "gravity"}

    # masses are the sympy bodies' own (Autolev's record keeps no copy)
    from al2py_runtime.model.state import BodyRecord

    assert "mass" not in {f.name for f in dataclasses.fields(BodyRecord)}
    ball = al.model.particles("BALL")
    assert al.model.mass_of() == 2  # BALL's mass is not declared: zero
    al.model.set_mass(ball, length)
    assert al.model.particle(ball).mass == length
    assert al.model.rigid_body(a).mass == 2
    assert al.model.mass_of(a, ball) == 2 + length
