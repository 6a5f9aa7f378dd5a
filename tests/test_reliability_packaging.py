"""Issue 12, item 13: packaging.  ``al2py`` depends on the ``al2py-runtime``
distribution instead of shipping a copy; LICENSE, ``py.typed``, CHANGELOG; black
pinned to one major version; and a clear message if the runtime is missing."""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _project(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def test_al2py_depends_on_the_runtime_distribution_and_ships_no_copy():
    root = _project(ROOT / "pyproject.toml")
    runtime = _project(ROOT / "runtime" / "pyproject.toml")
    version = runtime["project"]["version"]
    deps = root["project"]["dependencies"]
    assert f"al2py-runtime=={version}" in deps
    setuptools = root["tool"]["setuptools"]
    assert not any(p.startswith("al2py_runtime") for p in setuptools["packages"])
    assert "al2py_runtime" not in str(setuptools.get("package-dir", {}))
    assert root["project"]["version"] == version


def test_black_is_pinned_to_one_major_version():
    deps = _project(ROOT / "pyproject.toml")["project"]["dependencies"]
    (black,) = [d for d in deps if re.match(r"black\b", d)]
    low = re.search(r">=(\d+)", black)
    high = re.search(r"<(\d+)", black)
    assert low and high and int(high.group(1)) == int(low.group(1)) + 1
    import black as black_module

    assert int(black_module.__version__.split(".")[0]) == int(low.group(1))


def test_license_typed_markers_and_changelog_exist():
    for project in (ROOT, ROOT / "runtime"):
        meta = _project(project / "pyproject.toml")["project"]
        assert meta["license"] == "BSD-3-Clause"  # SPDX string: no setuptools warning
        for name in meta["license-files"]:
            text = (project / name).read_text()
            assert text.startswith("BSD 3-Clause License")
    assert (ROOT / "src" / "al2py" / "py.typed").is_file()
    assert (ROOT / "runtime" / "al2py_runtime" / "py.typed").is_file()
    changelog = (ROOT / "CHANGELOG.md").read_text()
    assert changelog.startswith("# Changelog") and "## 0.1.0" in changelog


def test_templates_are_declared_package_data():
    """setuptools warned that 'al2py.templates' was absent from packages."""
    setuptools = _project(ROOT / "pyproject.toml")["tool"]["setuptools"]
    assert "al2py.templates" in setuptools["packages"]
    assert setuptools["package-data"]["al2py.templates"] == ["*.j2"]
    assert (ROOT / "src" / "al2py" / "templates" / "module.py.j2").is_file()


def test_makefile_installs_the_runtime_first():
    text = (ROOT / "Makefile").read_text()
    runtime = text.index('install --quiet -e "./runtime')
    root = text.index('install --quiet -e ".[dev,plot]"')
    assert runtime < root


def test_missing_runtime_gives_a_clear_message(tmp_path):
    (tmp_path / "x.al").write_text("Constants A\nE = A + 1\n")
    code = (
        "import sys; sys.modules['al2py_runtime'] = None\n"
        "from al2py.cli import main; sys.exit(main(['x.al']))\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path
    )
    assert run.returncode == 3
    assert run.stderr.strip() == (
        "al2py: error: the al2py-runtime distribution is not installed "
        "(al2py depends on it): pip install al2py-runtime"
    )
