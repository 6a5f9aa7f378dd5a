"""The generated module of each tutorial script, byte for byte (black's habit).

Each ``.al`` below has its module kept as ``tests/golden/modules/STEM.py``.
A change to the generator shows as a diff of those files: this test fails on
any byte difference and prints the unified diff; ``make golden`` (that is,
``python tests/test_golden_modules.py``) writes them again, for review with
``git diff tests/golden/modules``.

The tutorial's examples are ``tests/tutorial/tutor*.al`` (``tutor1.al`` is a
golden case, ``tutor6.al`` is ``examples/``).
"""

from __future__ import annotations

import difflib
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
MODULES = ROOT / "tests" / "golden" / "modules"


def sources() -> list[Path]:
    """Every ``.al`` whose module is kept, in a fixed order."""
    return [
        ROOT / "examples" / "tutor6.al",
        *sorted((ROOT / "tests" / "golden" / "cases").glob("*.al")),
        *sorted((ROOT / "tests" / "tutorial").glob("tutor*.al")),
        ROOT / "tests" / "models" / "whipple_benchmark.al",
    ]


def generate(path: Path) -> str:
    """The module al2py writes for ``path`` (named by its base name only, so
    the bytes do not depend on where the checkout is)."""
    from al2py import convert

    return convert(
        path.read_text(encoding="utf-8"), path.name, script_dir=path.parent
    ).code


def golden_path(path: Path) -> Path:
    return MODULES / f"{path.stem}.py"


@pytest.mark.parametrize("path", sources(), ids=lambda p: p.stem)
def test_module_is_golden(path: Path) -> None:
    kept = golden_path(path)
    assert kept.exists(), f"{kept} is missing: run 'make golden'"
    want = kept.read_text(encoding="utf-8")
    got = generate(path)
    if got != want:
        diff = "".join(
            difflib.unified_diff(
                want.splitlines(keepends=True),
                got.splitlines(keepends=True),
                fromfile=f"{kept.relative_to(ROOT)} (kept)",
                tofile=f"{kept.relative_to(ROOT)} (generated)",
            )
        )
        pytest.fail(
            f"the module of {path.relative_to(ROOT)} changed ('make golden' "
            f"writes it again):\n{diff}",
            pytrace=False,
        )


def test_every_golden_module_has_a_source() -> None:
    """No stale module: each kept ``.py`` belongs to one of the sources."""
    stems = {p.stem for p in sources()}
    assert len(stems) == len(sources()), "two sources share a module name"
    stale = sorted(p.name for p in MODULES.glob("*.py") if p.stem not in stems)
    assert not stale, f"modules without a source (delete them): {stale}"


def write_all() -> int:
    """``make golden``: write every kept module again; print which changed."""
    MODULES.mkdir(parents=True, exist_ok=True)
    for path in sources():
        kept = golden_path(path)
        code = generate(path)
        old = kept.read_text(encoding="utf-8") if kept.exists() else None
        if old != code:
            kept.write_text(code, encoding="utf-8")
            print(f"wrote {kept.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(write_all())
