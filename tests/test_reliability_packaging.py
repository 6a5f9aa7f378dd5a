"""Issue 12, item 13: packaging.  ``al2py`` depends on the ``al2py-runtime``
distribution instead of shipping a copy; LICENSE, ``py.typed``, CHANGELOG; black
pinned to one major version; and a clear message if the runtime is missing."""

from __future__ import annotations

import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def _project(path: Path) -> dict:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def _setup_requirements() -> tuple[str, list[str], dict[str, list[str]]]:
    """The version, install_requires and extras that setup.py hands setuptools."""
    import setuptools

    seen: dict = {}
    real = setuptools.setup
    setuptools.setup = lambda **kw: seen.update(kw)
    try:
        source = (ROOT / "setup.py").read_text(encoding="utf-8")
        exec(
            compile(source, str(ROOT / "setup.py"), "exec"),
            {"__file__": str(ROOT / "setup.py")},
        )
    finally:
        setuptools.setup = real
    return seen["version"], seen["install_requires"], seen["extras_require"]


def test_the_version_is_written_once():
    """runtime/al2py_runtime/version.py is the one place: both projects'
    metadata, the pin on al2py-runtime and ``al2py.__version__`` follow it."""
    from importlib.metadata import version as installed

    import al2py_runtime

    import al2py

    version, deps, extras = _setup_requirements()
    assert version == al2py_runtime.__version__ == al2py.__version__
    # what pip installed says the same (al2py reads the runtime's file)
    assert installed("al2py") == installed("al2py-runtime") == version
    assert f"al2py-runtime=={version}" in deps
    assert all(f"=={version}" in d for d in extras["plot"] + extras["fast"])
    for project in (ROOT, ROOT / "runtime"):
        meta = _project(project / "pyproject.toml")["project"]
        assert "version" not in meta and "version" in meta["dynamic"]
    written = [
        path
        for path in (
            *ROOT.glob("*.toml"),
            *ROOT.glob("runtime/*.toml"),
            *ROOT.glob("src/al2py/*.py"),
        )
        if re.search(
            r"""version\s*=\s*["']\d+\.\d+""", path.read_text(encoding="utf-8")
        )
    ]
    assert written == []


def test_al2py_ships_no_copy_of_the_runtime_and_finds_its_packages():
    """Packages are discovered, not listed by hand (a hand list once left
    al2py_runtime.vocabulary out of the wheel)."""
    for project, where in ((ROOT, "src"), (ROOT / "runtime", ".")):
        setuptools = _project(project / "pyproject.toml")["tool"]["setuptools"]
        assert set(setuptools["packages"]) == {"find"}  # no hand-kept list
        assert setuptools["packages"]["find"]["where"] == [where]
    assert not (ROOT / "src" / "al2py_runtime").exists()


def test_black_is_pinned_to_one_major_version():
    _, deps, _ = _setup_requirements()
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
    # kept by release: the current version has its section
    import al2py_runtime

    assert f"\n## {al2py_runtime.__version__} (" in changelog


def test_templates_are_declared_package_data():
    """setuptools warned that 'al2py.templates' was absent from packages."""
    setuptools = _project(ROOT / "pyproject.toml")["tool"]["setuptools"]
    assert setuptools["package-data"]["al2py.templates"] == ["*.j2"]
    assert (ROOT / "src" / "al2py" / "templates" / "module.py.j2").is_file()


def test_makefile_installs_the_runtime_first():
    text = (ROOT / "Makefile").read_text()
    runtime = text.index('install --quiet -e "./runtime')
    root = text.index('install --quiet -e ".[dev,plot,notebook]"')
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
        "(al2py depends on it): pip install al2py-runtime (from a checkout: "
        "pip install ./runtime)"
    )


def test_the_tutorial_copies_are_the_tutorials():
    """The tests read the tutorial's examples from the project's own copies
    (``conftest.SHARED``); where the workplace's ``shared/tutorial`` is beside
    the checkout, the copies are its files, byte for byte, and all of them."""
    from conftest import SHARED, SHARED_TUTORIAL

    if not SHARED_TUTORIAL.is_dir():
        pytest.skip(f"{SHARED_TUTORIAL} is absent: nothing to compare the copies with")
    theirs = {p.name: p.read_bytes() for p in SHARED_TUTORIAL.iterdir() if p.is_file()}
    ours = {p.name: p.read_bytes() for p in SHARED.iterdir()}
    assert sorted(ours) == sorted(theirs)
    assert [n for n in ours if ours[n] != theirs[n]] == []
