"""``al2py convert DIR -o OUTDIR``: a whole library, keeping its layout."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import sympy as sp
from conftest import ROOT

from al2py import cli

LIBRARY = ROOT / "tests" / "library"
BAD_SCRIPT = "Constants A\nE = A + Q\n"  # Q is undeclared


def convert(*args: str, capsys) -> tuple[int, str, str]:
    status = cli.main(["convert", *args])
    out, err = capsys.readouterr()
    return status, out, err


def tree(root: Path) -> set[str]:
    return {p.relative_to(root).as_posix() for p in root.rglob("*") if p.is_file()}


def import_value(module_dir: Path, module: str, name: str) -> str:
    run = subprocess.run(
        [sys.executable, "-c", f"import {module}; print({module}.AUTOLEV[{name!r}])"],
        capture_output=True,
        text=True,
        cwd=module_dir,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    return run.stdout.strip()


def test_library_keeps_its_layout(tmp_path, capsys):
    out = tmp_path / "py"
    status, stdout, err = convert(str(LIBRARY), "-o", str(out), capsys=capsys)
    assert status == 0, err
    assert stdout == ""
    assert tree(out) == {
        "algebra/linear.py",
        "pendulum/frames.py",
        "pendulum/main.py",
    }
    # RUN frames.al and the ENERGY macro (energy.a) resolved beside main.al
    code = (out / "pendulum" / "main.py").read_text()
    assert 'al.assign("KE_Q"' in code or "KE_Q" in code
    tip = sp.sympify(import_value(out / "pendulum", "main", "TIP"))
    assert [float(x) for x in tip] == pytest.approx([0.8660254, 2.5])
    assert import_value(out / "algebra", "linear", "H") == "5"
    # progress on stderr, one line per file, then a summary
    lines = err.splitlines()
    assert sum(line.startswith("[") and line.endswith("... ok") for line in lines) == 3
    assert lines[-1].startswith("al2py: converted 3 of 3 scripts into")


def test_one_bad_file_does_not_stop_the_rest(tmp_path, capsys):
    lib = tmp_path / "lib"
    shutil.copytree(LIBRARY, lib)
    (lib / "algebra" / "bad.al").write_text(BAD_SCRIPT)
    (lib / "algebra" / "bad.py").write_text("# not ours\n")
    out = tmp_path / "out"
    status, _, err = convert(str(lib), "-o", str(out), "-q", capsys=capsys)
    assert status == 2
    assert f"{lib / 'algebra' / 'bad.al'}:2:9: error: undeclared name 'Q'" in err
    assert "Traceback" not in err
    assert not any(line.startswith("[") for line in err.splitlines())  # -q
    assert tree(out) == {
        "algebra/linear.py",
        "pendulum/frames.py",
        "pendulum/main.py",
    }
    assert "converted 3 of 4 scripts" in err and "1 failed" in err


def test_real_process_relative_paths_and_jobs(tmp_path):
    lib = tmp_path / "lib"
    shutil.copytree(LIBRARY, lib)
    (lib / "pendulum" / "broken.al").write_text("Constants A\nX = A +\n")
    run = subprocess.run(
        [sys.executable, "-m", "al2py", "convert", "lib", "-o", "out", "-j", "2"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=300,
    )
    assert run.returncode == 2
    assert run.stdout == ""
    assert "lib/pendulum/broken.al:2:8: error: unexpected end of input" in run.stderr
    assert "[4/4]" in run.stderr
    assert tree(tmp_path / "out") == {
        "algebra/linear.py",
        "pendulum/frames.py",
        "pendulum/main.py",
    }


def test_macros_found_through_autolevpath(tmp_path, capsys, monkeypatch):
    macros = tmp_path / "macros"
    macros.mkdir()
    (macros / "twice.a").write_text("#2# = 2*(#1#)\n")
    lib = tmp_path / "lib" / "deep"
    lib.mkdir(parents=True)
    (lib / "uses.al").write_text("Constants A\nTWICE(A+1, Y)\n")
    monkeypatch.setenv("AUTOLEVPATH", str(macros))
    status, _, err = convert(
        str(tmp_path / "lib"), "-o", str(tmp_path / "o"), capsys=capsys
    )
    assert status == 0, err
    y = import_value(tmp_path / "o" / "deep", "uses", "Y")
    assert sp.expand(sp.sympify(y) - 2 * sp.Symbol("A")) == 2


def test_names_that_are_not_identifiers_become_importable(tmp_path, capsys):
    src = tmp_path / "src"
    src.mkdir()
    (src / "2link.al").write_text("Constants A\nE = A + 1\n")
    (src / "my-model.al").write_text("Constants A\nE = A + 2\n")
    status, _, err = convert(str(src), "-o", str(tmp_path / "o"), capsys=capsys)
    assert status == 0, err
    assert tree(tmp_path / "o") == {"m_2link.py", "my_model.py"}


def test_two_scripts_for_one_module_is_an_error(tmp_path, capsys):
    src = tmp_path / "src"
    src.mkdir()
    (src / "my-model.al").write_text("Constants A\nE = A + 1\n")
    (src / "my_model.al").write_text("Constants A\nE = A + 2\n")
    status, _, err = convert(str(src), "-o", str(tmp_path / "o"), capsys=capsys)
    assert status == 2
    assert "would overwrite" in err
    assert tree(tmp_path / "o") == {"my_model.py"}


def test_usage_errors(tmp_path, capsys):
    (tmp_path / "file").write_text("")
    (tmp_path / "x.al").write_text("Constants A\n")
    status, _, err = convert(str(tmp_path), "-o", str(tmp_path / "file"), capsys=capsys)
    assert status == 2 and "is not a folder" in err
    status, _, err = convert(str(tmp_path / "none"), "-o", "o", capsys=capsys)
    assert status == 2 and "no such file or folder" in err
    with pytest.raises(SystemExit) as exc:  # -o is required
        cli.main(["convert", str(tmp_path)])
    assert exc.value.code == 2
    capsys.readouterr()
