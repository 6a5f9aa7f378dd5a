"""The same script gives the same module: in one process or many, under any
hash seed, alone or inside ``al2py convert DIR``, first or 500th.

The analysis once kept its facts by ``id()`` of IR nodes, and some nodes were
temporaries; a freed node's address could be given to the next one, so a
lookup found another name's symbol (tutor8's ``Solve(PERTURB, dU{1:2}')``
became ``[dU2', dU2']`` about once in 33 conversions).  Facts are now kept by
``Node.nid``, which is never reused, and every reader shares the expanded
nodes of ``X{a:b}``.

``make test`` runs small versions.  The full sizes of issue 23 (tutor8 2,000
times and the range script 500 times in one process, tutor8 in 200 fresh
processes) run in the full tier: ``make test-full`` (``pytest --full``).
"""

from __future__ import annotations

import ast
import hashlib
import os
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT, SHARED, full_tier

from al2py import convert, ir


def range_script(solves: int = 20) -> str:
    """Our own script: ``solves`` Solve statements over index ranges."""
    lines = [
        "% Solve over index ranges, many times (issue 23)",
        "Newtonian N",
        f"Variables Q{{1:{solves + 1}}}'",
        f"Constants K{{1:{solves}}}",
    ]
    for k in range(1, solves + 1):
        lines += [
            f"E{k}A = Q{k}'' + K{k}*Q{k + 1}'' - K{k}*Q{k}",
            f"E{k}B = Q{k + 1}'' - K{k}*Q{k}'",
            f"Solve([E{k}A; E{k}B], Q{{{k}:{k + 1}}}'')",
        ]
    return "\n".join(lines) + "\n"


def digest(code: str) -> str:
    return hashlib.sha256(code.encode()).hexdigest()


def distinct_modules(text: str, filename: str, times: int) -> set[str]:
    return {digest(convert(text, filename).code) for _ in range(times)}


# ------------------------------------------------------------ identities


def test_node_identity_is_not_value_or_span():
    span = ir.Span("f.al", 1, 1)
    a, b = ir.Name(span, "X"), ir.Name(span, "X")
    assert a == b and hash(a) == hash(b)
    assert a.nid != b.nid
    import dataclasses

    c = dataclasses.replace(a, primes=1)
    assert c.nid not in (a.nid, b.nid)


def test_indexed_names_are_expanded_once_and_shared():
    node = ir.IndexedNames(ir.Span("f.al", 1, 1), "dU", ((1, 2),), primes=1)
    first, second = node.names, node.names
    assert first is second
    assert [n.autolev for n in first] == ["DU1'", "DU2'"]
    assert len({n.nid for n in first}) == 2
    # the expansion is not content: walks and rebuilds ignore it
    assert [name for name, _ in ir.content(node)] == [
        "span",
        "stem",
        "ranges",
        "primes",
        "suffix",
    ]


def _id_calls(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return [
        f"{path.relative_to(ROOT)}:{node.lineno}"
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Name)
        and node.func.id == "id"
    ]


def test_no_table_is_keyed_by_id():
    """No ``id(...)`` anywhere in the transpiler or the runtime: an address is
    reused once its object is freed, so it identifies nothing."""
    files = [
        p
        for folder in (ROOT / "src", ROOT / "runtime")
        for p in sorted(folder.rglob("*.py"))
        if "_antlr" not in p.parts
    ]
    assert len(files) > 30
    found = [hit for p in files for hit in _id_calls(p)]
    assert found == []


# ------------------------------------------------------------ one process


def test_tutor8_is_one_module_in_one_process():
    path = SHARED / "tutor8.al"
    modules = distinct_modules(path.read_text(), str(path), 2000 if full_tier() else 40)
    assert len(modules) == 1
    code = convert(path.read_text(), str(path)).code
    # the unknowns of Solve(PERTURB, dU{1:2}') are dU1' and dU2', in order
    assert "[dU1.diff(t), dU2.diff(t)]" in code


def test_range_script_is_one_module_in_one_process():
    text = range_script()
    modules = distinct_modules(text, "ranges.al", 500 if full_tier() else 40)
    assert len(modules) == 1
    code = convert(text, "ranges.al").code
    for k in range(1, 21):
        assert f"[Q{k}.diff(t, 2), Q{k + 1}.diff(t, 2)]" in code


# ------------------------------------------------------------ many processes

_CHILD = (
    "import hashlib, sys; from al2py import convert; "
    "p = sys.argv[1]; "
    "print(hashlib.sha256(convert(open(p).read(), p).code.encode()).hexdigest())"
)


def _in_fresh_processes(path: Path, seeds: list[int]) -> set[str]:
    out = set()
    for seed in seeds:
        env = {**os.environ, "PYTHONHASHSEED": str(seed)}
        proc = subprocess.run(
            [sys.executable, "-c", _CHILD, str(path)],
            capture_output=True,
            text=True,
            env=env,
            timeout=120,
            check=True,
        )
        out.add(proc.stdout.strip())
    return out


def test_fresh_processes_and_hash_seeds_give_the_same_bytes(tmp_path):
    script = tmp_path / "ranges.al"
    script.write_text(range_script())
    for path in (SHARED / "tutor8.al", script):
        here = digest(convert(path.read_text(), str(path)).code)
        assert _in_fresh_processes(path, [0, 1, 4242]) == {here}


@pytest.mark.slow
@pytest.mark.full
def test_tutor8_in_200_fresh_processes():
    path = SHARED / "tutor8.al"
    here = digest(convert(path.read_text(), str(path)).code)
    assert _in_fresh_processes(path, list(range(200))) == {here}


# ------------------------------------------------------------ a folder


def test_convert_folder_of_copies_equals_each_alone(tmp_path):
    """40 copies (full tier; 4 otherwise) each of tutor8, tutor9 and the range
    script, converted as one folder by the CLI, give the modules that
    converting each alone gives."""
    copies = 40 if full_tier() else 4
    src, out = tmp_path / "src", tmp_path / "out"
    scripts = {
        "tutor8.al": (SHARED / "tutor8.al").read_text(),
        "tutor9.al": (SHARED / "tutor9.al").read_text(),
        "ranges.al": range_script(),
    }
    for i in range(copies):
        for name, text in scripts.items():
            folder = src / f"copy{i:02d}"
            folder.mkdir(parents=True, exist_ok=True)
            (folder / name).write_text(text)
    proc = subprocess.run(
        [sys.executable, "-m", "al2py", "convert", str(src), "-o", str(out)],
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert proc.returncode == 0, proc.stderr
    for name, text in scripts.items():
        alone = convert(text, name).code
        written = {
            (out / f"copy{i:02d}" / name.replace(".al", ".py")).read_text()
            for i in range(copies)
        }
        assert written == {alone}, name


def test_transcripts_are_the_same_under_any_hash_seed(tmp_path):
    """A module prints the same transcript in every process: AutoZ
    intermediates are defined in the order of their names, not of a set
    (tutor7's Z definitions came out in another order per hash seed)."""
    path = SHARED / "tutor7.al"
    module = tmp_path / "tutor7.py"
    module.write_text(convert(path.read_text(), str(path)).code)
    out = set()
    for seed in (0, 1, 2, 3):
        proc = subprocess.run(
            [sys.executable, str(module), "--no-run"],
            capture_output=True,
            text=True,
            env={**os.environ, "PYTHONHASHSEED": str(seed)},
            timeout=300,
            check=True,
        )
        out.add(proc.stdout)
    (text,) = out
    assert "Z1 = " in text  # tutor7 says AutoZ ON
