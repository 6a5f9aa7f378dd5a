"""The packages as a user installs them: both wheels built, installed
non-editable in a fresh virtual environment, and used there from a folder
that holds nothing of the checkout.

An editable install (``make install``, CI) reads the source tree, so it cannot
see a module the wheel leaves out; this test can (a hand-kept package list
once shipped the runtime without ``al2py_runtime.vocabulary``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import venv
from pathlib import Path

import pytest
from conftest import ROOT

pytestmark = pytest.mark.wheel

# Every runtime module, imported one by one in the fresh environment.
_IMPORT_ALL = """
import importlib, pkgutil, sys
import al2py_runtime
names = sorted(m.name for m in pkgutil.walk_packages(al2py_runtime.__path__, "al2py_runtime."))
for name in names:
    importlib.import_module(name)
assert not any(p.startswith(sys.argv[1]) for p in (getattr(m, "__file__", None) or "" for m in list(sys.modules.values())))
print(len(names))
"""


def _environ() -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    env.pop("VIRTUAL_ENV", None)
    return env


def _run(args, cwd: Path, check: bool = True) -> subprocess.CompletedProcess:
    run = subprocess.run(
        [str(a) for a in args], cwd=cwd, env=_environ(), capture_output=True, text=True
    )
    if check and run.returncode != 0:
        pytest.fail(f"{args} failed ({run.returncode}):\n{run.stdout}\n{run.stderr}")
    return run


@pytest.fixture(scope="module")
def wheels(tmp_path_factory) -> dict[str, Path]:
    if shutil.which("pip", path=str(Path(sys.executable).parent)) is None:
        pytest.skip("pip is not available beside this interpreter")
    out = tmp_path_factory.mktemp("wheels")
    # Built from a copy of the tracked files, as a clean checkout has them:
    # nothing a developer left in the tree (egg-info, caches) reaches a wheel.
    src = tmp_path_factory.mktemp("checkout") / "al2py"
    files = subprocess.run(
        ["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=False
    )
    if files.returncode != 0:
        pytest.skip("not a git checkout: cannot tell the tracked files")
    for name in files.stdout.decode().split("\0"):
        if name and (ROOT / name).is_file():
            (src / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(ROOT / name, src / name)
    _run(
        [
            sys.executable,
            "-m",
            "pip",
            "wheel",
            "--quiet",
            "--no-deps",
            "-w",
            out,
            src / "runtime",
            src,
        ],
        cwd=out,
    )
    found = {p.name.split("-")[0]: p for p in out.glob("*.whl")}
    assert set(found) == {"al2py", "al2py_runtime"}, found
    return found


def _fresh_env(path: Path) -> Path:
    venv.EnvBuilder(with_pip=True, clear=True).create(path)
    return path / "bin" / "python"


def test_the_runtime_wheel_alone_installs_and_every_module_imports(wheels, tmp_path):
    python = _fresh_env(tmp_path / "env")
    _run(
        [python, "-m", "pip", "install", "--quiet", wheels["al2py_runtime"]],
        cwd=tmp_path,
    )
    run = _run([python, "-c", _IMPORT_ALL, str(ROOT)], cwd=tmp_path)
    assert int(run.stdout.strip()) >= 40  # the runtime has about 50 modules
    # and the transpiler is not there: the runtime works without it
    assert _run([python, "-c", "import al2py"], cwd=tmp_path, check=False).returncode


def test_both_wheels_convert_import_and_run_tutor6(wheels, tmp_path):
    python = _fresh_env(tmp_path / "env")
    _run(
        [
            python,
            "-m",
            "pip",
            "install",
            "--quiet",
            wheels["al2py_runtime"],
            wheels["al2py"],
        ],
        cwd=tmp_path,
    )
    work = tmp_path / "work"
    work.mkdir()
    shutil.copy(ROOT / "examples" / "tutor6.al", work / "tutor6.al")
    al2py = python.parent / "al2py"
    _run([al2py, "tutor6.al", "-o", "tutor6.py"], cwd=work)
    run = _run([python, "tutor6.py"], cwd=work)
    assert "Wrote tutor6.1 (101 rows" in run.stdout
    # the final row of the table: Autolev's tutorial run ends at T = 20
    last = (work / "tutor6.1").read_text().split("\n")[-2].split()
    assert float(last[0]) == 20.0
    code = "import tutor6; r = tutor6.run(); print(len(r['QA']), r['QA'][-1])"
    rows, qa = _run([python, "-c", code], cwd=work).stdout.split()
    assert int(rows) == 101 and float(qa) == pytest.approx(float(last[2]), rel=1e-6)
    _run([python, "-c", _IMPORT_ALL, str(ROOT)], cwd=work)

    # A broken runtime install says what is missing, not "not installed".
    site = _run(
        [
            python,
            "-c",
            "import al2py_runtime, os; print(os.path.dirname(al2py_runtime.__file__))",
        ],
        cwd=work,
    ).stdout.strip()
    shutil.rmtree(Path(site) / "vocabulary")
    broken = _run([al2py, "tutor6.al", "-o", "again.py"], cwd=work, check=False)
    assert broken.returncode != 0
    assert "al2py_runtime.vocabulary is missing" in broken.stderr
    assert "Traceback" not in broken.stderr
