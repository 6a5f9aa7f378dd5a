"""The golden modules write sympy mechanics where Autolev and sympy mean the
same thing (issue 33).

Each statement of a kept module (``tests/golden/modules/*.py``) is the code
below its ``# al>`` echo.  The statements that sympy mechanics can say --
declarations, ``Simprot``/``Dircos``, assignments to ``P_``/``V_``/``A_``/
``W_``/``ALF_`` forms of declared objects, ``V2pts``/``V1pt``/``A2pts``/
``A1pt``, ``Mass``/``Inertia``, ``Force``/``Torque``/``Gravity`` and the
``Force_P>``/``Torque_B>`` forms -- count as sympy code when their code makes
a sympy call or assignment and calls the runtime only to record it
(``al...given_*``, ``declare_*``, ``formed_*``).  ``python
tests/test_module_sympy.py`` prints each module's share and the statements
that are not sympy code.
"""

from __future__ import annotations

import ast
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
MODULES = ROOT / "tests" / "golden" / "modules"

#: the runtime calls that only record what a sympy call did
RECORDING = re.compile(r"(given_|declare_|formed_)\w*$")
_DECLARES = ("NEWTONIAN", "FRAMES", "BODIES", "POINTS", "PARTICLES")
_KEYWORDS = re.compile(
    r"(NEWTONIAN|FRAMES|BODIES|POINTS|PARTICLES|VARIABLES|CONSTANTS|SPECIFIED"
    r"|MASS|INERTIA)\s"
    r"|(SIMPROT|DIRCOS|V2PTS|V1PT|A2PTS|A1PT|GRAVITY|FORCE|TORQUE)\s*\(",
    re.IGNORECASE,
)
_FORM = re.compile(
    r"(?:(P|V|A|W|ALF)_([A-Z0-9]+)_([A-Z0-9]+)|(FORCE|TORQUE)_([A-Z0-9]+))>"
    r"\s*[-+]?:?=",
    re.IGNORECASE,
)


def statements(text: str) -> list[tuple[str, str]]:
    """``(Autolev statement, its Python code)`` in the module's order: the
    code from one ``# al>`` echo of a statement (a line of its own above the
    code, or the end of the code's first line) to the next echo."""
    body = text.split("al = Workspace(", 1)[1].split("\nAUTOLEV = ", 1)[0]
    out: list[tuple[str, list[str]]] = []
    for line in body.splitlines()[1:]:
        code, mark, source = line.partition("# al>")
        source = source.strip()
        if mark and (not source or source.startswith("%")):
            continue  # a comment of the script
        if mark:
            out.append((source.split("%", 1)[0].strip(), []))
        if out and code.strip() and not code.lstrip().startswith("#"):
            out[-1][1].append(code.rstrip())
    return [(src, "\n".join(code)) for src, code in out]


def declared_objects(stmts: list[tuple[str, str]]) -> set[str]:
    """Names of the frames, bodies, points and particles the script declares
    (and the bodies' mass centers ``BO``)."""
    names: set[str] = set()
    for src, _ in stmts:
        word, _, rest = src.partition(" ")
        if word.upper() in _DECLARES:
            for name in re.findall(r"[A-Za-z]\w*", rest):
                names.add(name.upper())
                if word.upper() in ("BODIES", "NEWTONIAN", "FRAMES"):
                    names.add(name.upper() + "O")
    return names


def in_scope(src: str, objects: set[str]) -> bool:
    """Whether sympy mechanics can say the statement ``src``."""
    if _KEYWORDS.match(src):
        return True
    m = _FORM.match(src)
    if m is None:
        return False
    parts = m.group(2, 3) if m.group(1) else (m.group(5),)
    return all(p.upper() in objects for p in parts)


def _al_calls(tree: ast.AST) -> list[str]:
    """The method names of the ``al.…(...)`` calls in ``tree``."""
    out = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
            root = node.func.value
            while isinstance(root, ast.Attribute):
                root = root.value
            if isinstance(root, ast.Name) and root.id == "al":
                out.append(node.func.attr)
    return out


def is_sympy(code: str) -> bool:
    """Code that makes a sympy call or assignment and calls the runtime only
    to record it."""
    if not code.strip():
        return False  # only a comment
    tree = ast.parse(code)
    if any(not RECORDING.match(name) for name in _al_calls(tree)):
        return False
    for stmt in tree.body:
        if isinstance(stmt, ast.Expr) and _al_calls(stmt):
            continue  # a recording call
        return True  # an assignment or a call of sympy's
    return False


def share(path: Path) -> tuple[int, int, list[str]]:
    """``(sympy statements, statements sympy can say, the others)``."""
    stmts = statements(path.read_text(encoding="utf-8"))
    objects = declared_objects(stmts)
    scoped = [(src, code) for src, code in stmts if in_scope(src, objects)]
    others = [src for src, code in scoped if not is_sympy(code)]
    return len(scoped) - len(others), len(scoped), others


@pytest.mark.parametrize("stem", ["tutor6", "whipple_benchmark"])
def test_most_mechanics_statements_are_sympy_code(stem: str) -> None:
    good, total, others = share(MODULES / f"{stem}.py")
    assert total >= 20, f"{stem}: only {total} mechanics statements found"
    assert good / total >= 0.9, (
        f"{stem}: {good} of {total} mechanics statements are sympy code;"
        f" not: {others}"
    )


@pytest.mark.parametrize("stem", ["tutor6", "whipple_benchmark"])
def test_no_mechanics_statement_is_only_a_comment(stem: str) -> None:
    stmts = statements((MODULES / f"{stem}.py").read_text(encoding="utf-8"))
    objects = declared_objects(stmts)
    empty = [src for src, code in stmts if in_scope(src, objects) and not code]
    assert not empty


def test_the_classifier_tells_sympy_from_runtime() -> None:
    """The classifier's own cases (so that its share can fail)."""
    assert is_sympy("A.orient_axis(N, N.z, QA)\nal.model.given_orientation(A, N)")
    assert is_sympy("U1 = dynamicsymbols('U1')\nal.declare_variables(U1, line=3)")
    assert not is_sympy('U1 = al.variables("U1\'", line=3)')
    assert not is_sympy("al.model.v2pts(N, A, O_, P, line=43)")
    assert not is_sympy("A.set_ang_vel(N, al.model.ang_vel(B, N))")
    assert not is_sympy("")
    objects = {"N", "A", "O", "P"}
    assert in_scope("V2pts(N, A, O, P)", objects)
    assert in_scope("P_O_P> = LA*A1>", objects)
    assert in_scope("Force_P> += F*A2>", objects)
    assert not in_scope("P_O_Q> = RF*A1>", objects)  # Q: not a point
    assert not in_scope("ZERO = Fr() + FrStar()", objects)


def _autolev_strings(tree: ast.AST) -> list[str]:
    """Strings in Autolev's spelling of a vector or dyadic (``"UVEC>"``,
    ``"P_O_Q>"``) that ``al.…`` calls take."""
    out = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and _al_calls(node)):
            continue
        func = node.func
        root = func.value if isinstance(func, ast.Attribute) else None
        while isinstance(root, ast.Attribute):
            root = root.value
        if not (isinstance(root, ast.Name) and root.id == "al"):
            continue
        for arg in [*node.args, *(k.value for k in node.keywords)]:
            if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
                if re.search(r">+'*$", arg.value) or re.search(r"\w>", arg.value):
                    out.append(arg.value)
    return out


@pytest.mark.parametrize("path", sorted(MODULES.glob("*.py")), ids=lambda p: p.stem)
def test_no_runtime_call_takes_an_autolev_vector_name(path: Path) -> None:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    assert not _autolev_strings(tree)


def main() -> int:
    for stem in ("tutor6", "whipple_benchmark"):
        good, total, others = share(MODULES / f"{stem}.py")
        print(f"{stem}: {good}/{total} = {good / total:.0%} sympy; not: {others}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
