"""Size limits stop with a located message, never an exhausted machine (issue 32).

``Variables X{100000000}`` grew past 5 GB while converting; 20,000 unary minus
signs did not convert in 60 s (the lexer looked ahead across the whole run
for a file name); a converted 3,000-term power chain failed at import with a
Python ``MemoryError`` traceback; a 40x40 symbolic ``Det`` imported silently
for minutes.  Each runs in a child process under a memory cap
(``resource.setrlimit``) and a time limit.
"""

from __future__ import annotations

import io
import re
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

import pytest

from al2py import cli, convert
from al2py.errors import AutolevError

resource = pytest.importorskip("resource")  # POSIX only

MEMORY_CAP = 2 * 1024**3  # bytes of address space for each child
LOCATED = re.compile(r"^(\w+)\.al:(\d+):(\d+): error: \S")


def _capped() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_CAP, MEMORY_CAP))


def _al2py(tmp_path: Path, name: str, text: str, timeout: float = 90):
    (tmp_path / f"{name}.al").write_text(text, encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "al2py", f"{name}.al", "-o", f"{name}.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=timeout,
        preexec_fn=_capped,
    )


def test_a_huge_index_range_stops_at_its_braces(tmp_path):
    run = _al2py(tmp_path, "big", "Constants A\nVariables X{100000000}\nY = A\n")
    assert run.returncode == 2, run.stderr
    m = LOCATED.match(run.stderr)
    assert m and m.groups() == ("big", "2", "12"), run.stderr
    assert "100000000 names" in run.stderr and "Traceback" not in run.stderr


def test_index_ranges_of_real_size_convert():
    code = convert("Variables Q{12}'\nConstants L{3,3}\nZ = Q1 + L33\n", "s.al").code
    assert "Q12" in code and "L33" in code


def test_the_index_ranges_of_a_file_are_limited_together():
    text = "".join(f"Constants C{k}_{{10000}}\n" for k in range(11))
    with pytest.raises(AutolevError) as info:
        convert(text, "s.al")
    assert info.value.span.line == 11


def test_twenty_thousand_unary_minus_signs_stop_quickly_and_located(tmp_path):
    text = "Constants A\nB = A\nX = " + "-" * 20_000 + "A\n"
    run = _al2py(tmp_path, "neg", text, timeout=60)
    assert "Traceback" not in run.stderr
    if run.returncode == 2:
        m = LOCATED.match(run.stderr)
        assert m and m.group(2) == "3", run.stderr
        assert "nested too deeply" in run.stderr
    else:
        assert run.returncode == 0, run.stderr


@pytest.mark.parametrize("op", ["-", "/"])
def test_operator_chains_without_blanks_convert(op, tmp_path):
    """``A-A-A-...`` and ``A/A/A/...`` (no blank for the lexer to stop at)."""
    import sympy as sp
    from conftest import load_module

    result = convert("Constants A\nX = " + op.join(["A"] * 1500) + "\n", "s.al")
    module = load_module(result.code, tmp_path, result.module)
    a = module.A
    expected = -1498 * a if op == "-" else a**-1498
    assert sp.simplify(module.al.value("X") - expected) == 0


@pytest.mark.parametrize(
    "text, filename",
    [
        ("Save my-model.all\n", "my-model.all"),
        ("Run ../lib/kin.al\n", "../lib/kin.al"),
        ("Run sub\\kin.al\n", "sub\\kin.al"),
        ("Save ~/x.all\n", "~/x.all"),
    ],
)
def test_file_names_with_separators_still_read(text, filename):
    from al2py.parser import parse

    assert parse(text).statements[0].filename == filename


def test_a_file_name_cannot_hold_a_blank():
    from al2py.parser import parse

    with pytest.raises(AutolevError, match="blank"):
        parse("Save my model.all\n")


def test_a_power_chain_python_cannot_load_is_refused_at_conversion(tmp_path):
    text = "Constants A\nB = A\nX = " + "^".join(["A"] * 3000) + "\n"
    run = _al2py(tmp_path, "pow", text)
    assert "Traceback" not in run.stderr
    assert run.returncode == 2, "converted a module Python cannot import"
    m = LOCATED.match(run.stderr)
    assert m and m.group(2) == "3", run.stderr


def test_memory_exhausted_while_converting_is_located(tmp_path, monkeypatch):
    import al2py.transpile

    def exhausted(*args, **kwargs):
        raise MemoryError

    monkeypatch.setattr(al2py.transpile, "convert", exhausted)
    path = tmp_path / "m.al"
    path.write_text("Constants A\nX = A + A + A + A\nY = A\n")
    out, err = io.StringIO(), io.StringIO()
    with redirect_stdout(out), redirect_stderr(err):
        status = cli.main([str(path), "-o", str(tmp_path / "m.py")])
    assert status == 2
    first = err.getvalue().splitlines()[0]
    assert re.match(r"^.+m\.al:2:1: error: out of memory", first), first


def test_a_40x40_symbolic_det_is_refused_with_its_line(tmp_path):
    rows = "; ".join(
        ", ".join(f"A{(i * 7 + j) % 5}" for j in range(40)) for i in range(40)
    )
    text = f"Constants A0, A1, A2, A3, A4\nM = [{rows}]\nD = Det(M)\n"
    run = _al2py(tmp_path, "det", text)
    assert run.returncode == 0, run.stderr
    done = subprocess.run(
        [sys.executable, "det.py"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=100,
        preexec_fn=_capped,
    )
    assert done.returncode == 2 and "Traceback" not in done.stderr
    assert done.stderr.startswith("det.al:3: error: Det of a 40x40 matrix"), done.stderr


def test_a_large_triangular_det_is_its_diagonal():
    import sympy as sp
    from al2py_runtime.matrices import det

    a = sp.Symbol("A")
    m = sp.diag(*[a + k for k in range(30)])
    m[0, 29] = a**2
    assert det(m) == sp.Mul(*[a + k for k in range(30)])
    n = sp.Matrix(4, 4, lambda i, j: sp.Symbol(f"a{i}{j}"))
    assert sp.expand(det(n) - n.det(method="bareiss")) == 0
