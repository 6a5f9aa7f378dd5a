"""No compiler or Octave warnings (issue 20) on the programs ``al2py code``
writes for published scripts: the Whipple bicycle (AutolevToolKit's
``Whipple.al``) and a BioMAC gait model (``gait2dc_dyn.al``), extracted from
the fetched repositories at run time (``$ALMIRROR``; skipped when absent).
C is built with ``-std=c99 -Wall -Wextra``, Fortran with ``gfortran -Wall``,
and each program runs one print step; any text on stderr fails.  tutor6 is
covered by ``test_codegen_targets.test_tutor6_in_each_language_matches_run``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from test_codegen_targets import LANGS, _run, _set_in

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))
import autolev_programs as judge  # noqa: E402

WHIPPLE = ("moorepants+AutolevToolKit", "models/Whipple/Whipple.al")
GAIT = ("mad-lab-fau+BioMAC-Sim-Toolbox", "src/model/gait2dc/c_files/gait2dc_dyn.al")


def _extract(repo: str, script: str, dest: Path) -> Path:
    """The script with the ``.al``/``.a``/``.r`` files of its folder."""
    git_dir = judge.mirror_root() / repo / "repo"
    if not git_dir.exists():
        pytest.skip(f"{repo} is not fetched under {judge.mirror_root()}")
    folder = str(Path(script).parent)
    for f in judge._git(
        git_dir, "ls-tree", "--name-only", "HEAD", f"{folder}/"
    ).split():
        if f.lower().endswith((".al", ".a", ".r")):
            (dest / Path(f).name).write_text(judge._show(git_dir, f), "latin-1")
    return dest / Path(script).name


def _code(script: Path, out: Path, *options: str) -> list[Path]:
    """``al2py code``: the files written (any error or warning fails)."""
    done = subprocess.run(
        [sys.executable, "-m", "al2py", "code", *options, script.name, "-o", str(out)],
        cwd=script.parent,
        capture_output=True,
        text=True,
        timeout=1200,
    )
    # notes (a file two programs share, docs/jobs.md) are not warnings
    noise = [ln for ln in done.stderr.splitlines() if "note: " not in ln]
    assert done.returncode == 0 and noise == [], done.stderr
    return [out / w.split()[-1] for w in done.stdout.splitlines() if "Wrote" in w]


@pytest.fixture(scope="module")
def whipple(tmp_path_factory):
    """Whipple.al's programs: its own CODE files (.m, .c) and --lang f."""
    work = tmp_path_factory.mktemp("whipple")
    script = _extract(*WHIPPLE, work)
    _code(script, work / "own")
    _code(script, work / "f", "--lang", "f")
    return work


@pytest.mark.slow  # the bicycle's derivation, twice (about a minute)
@pytest.mark.parametrize("lang", LANGS)
def test_whipple_programs_build_and_run_without_warnings(whipple, lang):
    folder = whipple / ("f" if lang == "f" else "own")
    stem = "WhippleDynamics"
    assert (folder / f"{stem}.{lang}").exists()
    # one print step (Octave interprets the 4000-line equations)
    _set_in(folder / f"{stem}.in", {"TFINAL": 0.01, "INTEGSTP": 0.01})
    _run(lang, folder, stem, timeout=1200)
    rows = judge.read_table(folder / f"{stem}.1")
    assert rows.shape == (2, 8)


@pytest.mark.slow
@pytest.mark.parametrize("lang", LANGS)
def test_gait_model_programs_without_warnings(tmp_path, lang):
    """gait2dc_dyn.al RUNs gait2dc_FK.al: both CODE Algebraic statements'
    programs (Encode only: they compute and write no file, as Autolev's),
    run at seeded nonzero values so that every trigonometric and drag term
    is evaluated (a value that is not finite would exit 2)."""
    script = _extract(*GAIT, tmp_path)
    out = tmp_path / "out"
    written = _code(script, out, "--lang", lang)
    stems = ["gait2dc_FK_al_raw", "gait2dc_dyn_al_raw"]
    assert written == [out / f"{s}.{e}" for s in stems for e in (lang, "in")]
    for stem in stems:
        names = [
            line[21:41].strip()
            for line in (out / f"{stem}.in").read_text().splitlines()[6:]
            if len(line) >= 60 and line[58] == "|"
        ]
        assert len(names) == {"gait2dc_FK_al_raw": 20, "gait2dc_dyn_al_raw": 59}[stem]
        _set_in(out / f"{stem}.in", {n: judge._seeded(n, 0.5, 1.5) for n in names})
        done = _run(lang, out, stem, timeout=1200)
        assert "Wrote" not in done.stdout
    assert sorted(f.name for f in out.glob("*.[0-9]")) == []
