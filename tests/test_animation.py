"""Seeing the model move (issue 34): Autolev's ``Animate``, ``result.animate()``,
``result.plot()``, notebook display and ``read_table``.

tutor6 (a double pendulum: O -> P along A1>, P -> Q along B1>) with
``Animate(N, O, A, B)`` before its CODE statement is the reference: P and Q
must be where QA, QB and the lengths put them."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from al2py_runtime import read_table
from al2py_runtime.jobs.records import NumericsError
from al2py_runtime.jobs.tables import format_table
from conftest import ROOT, load_module

from al2py import AutolevError, convert

TUTOR6 = (ROOT / "examples" / "tutor6.al").read_text(encoding="utf-8")
ANIMATED = TUTOR6.replace(
    "CODE Dynamics() tutor6.c", "Animate(N, O, A, B)\nCODE Dynamics() tutor6.c"
)


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return tmp_path_factory.mktemp("animation")


@pytest.fixture(scope="module")
def animated(folder):
    code = convert(ANIMATED, "tutor6.al").code
    return load_module(code, folder, "tutor6")


@pytest.fixture(scope="module")
def result(animated):
    return animated.run()


# ---------------------------------------------------------------- Animate


def test_animate_is_converted_and_recorded(animated):
    code = convert(ANIMATED, "tutor6.al").code
    assert "al.numerics.animate(N, O_, A, B, line=87)" in code
    spec = animated.al.numerics.job().animate
    assert spec.newtonian is animated.N and spec.point is animated.O_
    assert spec.frames == (animated.A, animated.B) and spec.line == 87


@pytest.mark.parametrize(
    "line, message, column",
    [
        ("Animate(A, O, B)", "expects a Newtonian frame here", 9),
        ("Animate(N, A, B)", "expects a point here", 12),
        ("Animate(N, O, P)", "expects a frame or body here", 15),
        ("Animate(N, O)", "Animate takes at least 3 arguments, not 2", 1),
    ],
)
def test_animate_arguments_are_checked(line, message, column):
    text = ANIMATED.replace("Animate(N, O, A, B)", line)
    with pytest.raises(AutolevError) as info:
        convert(text, "tutor6.al")
    assert message in info.value.message
    assert (info.value.span.line, info.value.span.col) == (87, column)


def test_positions_are_the_model_kinematics(result, animated):
    """P = LA*A1>, Q = P + LB*B1> from O, in N, at three rows."""
    movie = result.animate()
    la, lb = animated.evaluate("LA"), animated.evaluate("LB")
    qa, qb = np.radians(result["QA"]), np.radians(result["QB"])
    assert movie.scene.names == ["O", "P", "Q"]
    for row in (0, 37, len(qa) - 1):
        p = la * np.array([np.cos(qa[row]), np.sin(qa[row]), 0.0])
        q = p + lb * np.array([np.cos(qb[row]), np.sin(qb[row]), 0.0])
        assert movie.positions["P"][row] == pytest.approx(p, abs=1e-12)
        assert movie.positions["Q"][row] == pytest.approx(q, abs=1e-12)
        assert movie.positions["O"][row] == pytest.approx([0, 0, 0], abs=0)
        # B's triad: B1> points from P to Q
        b1 = movie.scene.axes[row, 1, :, 0]
        assert b1 == pytest.approx((q - p) / lb, abs=1e-12)
    assert movie.scene.layout.lines == [(0, 1), (1, 2)]  # O-P (A), P-Q (B)
    assert movie.scene.layout.anchors == [0, 1]  # A's triad at O, B's at P


def test_a_module_without_animate_animates_on_request(folder):
    plain = load_module(convert(TUTOR6, "tutor6.al").code, folder, "tutor6_plain")
    r = plain.run(tfinal=1)
    movie = r.animate()  # every frame but N (no bodies); O has V_O_N> = 0>
    assert movie.scene.frame_names == ["A", "B"]
    assert movie.scene.layout.origin.name == "O"
    only = r.animate(frames=["B"], points=["Q"], origin="P")
    # P first (the origin), then B's line to Q, then the declared O
    assert only.scene.names == ["P", "Q", "O"] and only.positions["P"] == pytest.approx(
        np.zeros((len(r["T"]), 3))
    )
    with pytest.raises(NumericsError, match="not a frame or body"):
        r.animate(frames=["Z"])


def test_html_is_self_contained(result, folder):
    path = folder / "tutor6.html"
    movie = result.animate(path)
    assert movie.path == path
    page = path.read_text(encoding="utf-8")
    assert page.startswith("<!DOCTYPE html>") and "<canvas" in page
    assert "http" not in page and "src=" not in page  # nothing to fetch
    data = json.loads(re.search(r"var D = (\{.*?\}), id", page).group(1))
    assert len(data["t"]) == len(result["T"]) == len(data["P"])
    assert data["names"] == ["O", "P", "Q"] and data["frames"] == ["A", "B"]
    # the same input gives the same page
    assert result.animate().html() == page


def _screenshot(page: Path, out: Path) -> np.ndarray:
    from PIL import Image

    subprocess.run(
        [
            shutil.which("chromium"),
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            f"--screenshot={out}",
            "--window-size=700,600",
            page.as_uri(),
        ],
        check=True,
        capture_output=True,
        timeout=120,
    )
    return np.asarray(Image.open(out).convert("L"), dtype=float)


@pytest.mark.skipif(
    shutil.which("chromium") is None, reason="needs chromium (Debian's package)"
)
def test_the_page_draws_in_a_browser(result, folder):
    """Headless Chromium renders the page; the player's drawing is on it:
    the same page without its script differs by the pendulum."""
    pytest.importorskip("PIL", reason="needs Pillow to read the screenshot")
    page = folder / "shown.html"
    result.animate(page)
    bare = folder / "bare.html"
    bare.write_text(
        re.sub(r"<script>.*</script>", "", page.read_text(), flags=re.S),
        encoding="utf-8",
    )
    drawn = _screenshot(page, folder / "shown.png")
    blank = _screenshot(bare, folder / "bare.png")
    assert drawn.std() > 5.0  # not a blank page
    changed = np.abs(drawn - blank) > 60
    assert changed.sum() > 1000, changed.sum()  # links, points, triads


def test_gif(result, folder):
    pytest.importorskip("matplotlib")
    pytest.importorskip("PIL")
    short = result.animate(speed=10)
    path = short.save(folder / "tutor6.gif")
    assert path.read_bytes()[:6] in (b"GIF89a", b"GIF87a")
    with pytest.raises(NumericsError, match=r"\.html, \.gif or \.mp4"):
        short.save(folder / "tutor6.avi")


def test_command_line_animate(folder):
    module = folder / "tutor6_cli.py"
    module.write_text(convert(ANIMATED, "tutor6.al").code, encoding="utf-8")
    out = folder / "cli"
    run = subprocess.run(
        [
            sys.executable,
            str(module),
            "--animate",
            "--tfinal",
            "1",
            "--outdir",
            str(out),
        ],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert f"Wrote {out / 'tutor6.html'}" in run.stdout
    assert (out / "tutor6.1").exists() and "<canvas" in (
        out / "tutor6.html"
    ).read_text()


def test_a_solve_has_nothing_to_animate(tmp_path):
    text = "Variables X\nZero = [X - 2]\nInput X = 1\nCODE Nonlinear(Zero, X) s.c\n"
    m = load_module(convert(text, "s.al").code, tmp_path, "s")
    with pytest.raises(NumericsError, match="no motion to animate"):
        m.run().animate()


# ------------------------------------------------------------------ plots


def test_plot_returns_a_figure(result):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    fig = result.plot()
    assert isinstance(fig, Figure)
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["STRETCH (m)", "QA (deg)", "QB (deg)", "ECHECK (joules)"]
    assert fig.axes[-1].get_xlabel() == "T (sec)"
    phase = result.plot(x="QA", y="QB")
    (ax,) = phase.axes
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("QA (deg)", "QB (deg)")
    x, y = ax.lines[0].get_data()
    assert np.array_equal(x, result["QA"]) and np.array_equal(y, result["QB"])
    both = result.plot(y=["QA", "QB"], overlay=True)
    assert len(both.axes) == 1 and len(both.axes[0].lines) == 2
    with pytest.raises(NumericsError, match="not a column"):
        result.plot(y="NOPE")


# ---------------------------------------------------------------- display


def test_result_html(result):
    page = result._repr_html_()
    assert "CODE Dynamics tutor6" in page
    assert "<th>QA<br>(deg)</th>" in page and "<th>T<br>(sec)</th>" in page
    assert page.count("<tr>") == 1 + 6  # the header and the head of the rows
    assert f"... {len(result['T']) - 6} more rows" in page


@pytest.mark.skipif(
    not all(
        __import__("importlib").util.find_spec(m)
        for m in ("nbclient", "nbformat", "ipykernel")
    ),
    reason="needs the notebook extra (nbclient, nbformat, ipykernel)",
)
def test_a_notebook_shows_results_and_animations(folder, animated):
    """A real Jupyter kernel runs a notebook: a Result shows its table, an
    animation plays inline, an AUTOLEV value keeps sympy's LaTeX."""
    import nbformat
    from nbclient import NotebookClient

    cells = [
        f"import sys; sys.path.insert(0, {str(folder)!r})\nimport tutor6_nb as m",
        "r = m.run(tfinal=2)\nr",
        "r.animate()",
        'm.AUTOLEV["LOQ"]',
    ]
    (folder / "tutor6_nb.py").write_text(convert(ANIMATED, "tutor6.al").code)
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": folder}}
    ).execute()
    outputs = [cell.outputs for cell in nb.cells]
    table = outputs[1][0]["data"]["text/html"]
    assert "CODE Dynamics tutor6" in table and "<th>QB<br>(deg)</th>" in table
    player = outputs[2][0]["data"]["text/html"]
    assert "<canvas" in player and "<script>" in player
    assert "text/latex" in outputs[3][0]["data"]


# --------------------------------------------------------------- tables


def test_read_table_gives_the_printed_digits(result, folder):
    (path,) = result.write(folder / "tables")
    back = read_table(path)
    assert back.tables[0].names == result.tables[0].names
    assert [c.unit for c in back.tables[0].columns] == [
        "sec",
        "m",
        "deg",
        "deg",
        "joules",
    ]
    assert back.digits == result.digits and back.time_unit == "sec"
    # written again, the same bytes: equal to the digits printed
    text = format_table(back.tables[0], back.digits, path.name, back.time_unit)
    assert text == path.read_text()
    step = 10.0 ** (1 - result.digits)
    assert np.allclose(back["QA"], result["QA"], rtol=step, atol=0)
    assert repr(back).startswith("<Result of table tutor6.1: 101 rows")
    assert "table tutor6.1" in back._repr_html_()
    pytest.importorskip("matplotlib")
    assert back.plot(y="QA").axes[0].get_ylabel() == "QA (deg)"


def test_read_table_errors(tmp_path):
    bad = tmp_path / "x.1"
    bad.write_text("% FILE: x.1\n 1.0  2.0\n 3.0\n")
    with pytest.raises(NumericsError, match="different numbers"):
        read_table(bad)
    bad.write_text("% FILE: x.1\n 1.0  abc\n")
    with pytest.raises(NumericsError, match=r"x\.1:2: not a row of numbers"):
        read_table(bad)
    with pytest.raises(NumericsError, match="cannot read"):
        read_table(tmp_path / "absent.1")


def test_a_table_written_by_autolevs_own_program(tmp_path):
    """PendulumDynamics.c, Autolev's program from the judge (docs/judge.md),
    built and run here: its PendulumDynamics.1 reads back with its labels
    and units, and equals al2py's run on the same .in values."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import autolev_programs as judge

    if shutil.which("cc") is None:
        pytest.skip("no C compiler (cc)")
    pairs = {p.name: p for p in judge.discover()}
    name = "AutolevToolKit:PendulumDynamics.c"
    if name not in pairs:
        pytest.skip(f"{name} not fetched under {judge.mirror_root()}")
    script, program = judge.extract(pairs[name], tmp_path)
    module = judge.convert_and_import(script)
    job = judge.job_for(module, pairs[name].program)
    prog = judge.CProgram.parse(program.read_text(encoding="latin-1"))
    values = judge._values(prog, job, judge._integration_for(job))
    judge.write_in(prog, values, program.parent / prog.infile)
    exe = judge.compile_program(program, shared=False)
    subprocess.run([str(exe)], cwd=program.parent, capture_output=True, timeout=300)
    path = program.parent / (prog.outfiles % 1)
    theirs = read_table(path)
    table = theirs.tables[0]
    assert table.names == ["omega", "theta", "k", "p", "longoutput"]
    units = [c.unit for c in table.columns]
    assert units == ["radian/sec", "radian", "joules", "joules", None]
    assert theirs.digits == 7
    assert np.array_equal(table.data, judge.read_table(path))
    from al2py_runtime.jobs.run import run_job

    ours = run_job(job, judge._overrides(prog, job, values))
    assert np.allclose(theirs["THETA"], ours["THETA"], rtol=1e-5, atol=1e-8)


@pytest.mark.slow  # the bicycle's import and first run (20-40 s on 2 cores)
def test_the_bicycle_animates(tmp_path):
    """Our Whipple script (benchmarks/animation.py times it): the rear
    contact at (Q1, Q2, 0), the rear wheel's center RR above it along L3>,
    each body's triad at its mass center."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    import animation as bench

    module = bench.load(tmp_path, 101)
    result = module.run()
    movie = result.animate()
    assert movie.scene.frame_names == ["R", "B", "H", "F"]
    names = movie.scene.names
    assert [names[k] for k in movie.scene.layout.anchors] == ["RO", "BO", "HO", "FO"]
    p, ro = movie.positions["P"], movie.positions["RO"]
    q1, q2, q4 = (result.states[n] for n in ("Q1", "Q2", "Q4"))
    assert p == pytest.approx(np.stack([q1, q2, 0 * q1], axis=1), abs=1e-12)
    assert (ro - p)[:, 2] == pytest.approx(-0.3 * np.cos(q4), abs=1e-12)
    assert len(movie.times) == 101 and movie.data()["follow"]  # it rides off


def test_command_line_animate_without_a_model(tmp_path):
    """An ODE job of plain variables has nothing to place: a note, the
    tables are written, and the exit status is 0."""
    text = (
        "Variables X'\nX' = -X\nInput X = 1, TFINAL = 1\nOutput T, X\n"
        "CODE ODE() decay.c\n"
    )
    module = tmp_path / "decay.py"
    module.write_text(convert(text, "decay.al").code, encoding="utf-8")
    run = subprocess.run(
        [sys.executable, str(module), "--animate", "--outdir", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert "note: no animation: animate: the model has no Newtonian frame" in (
        run.stderr
    )
    assert (tmp_path / "decay.1").exists() and not (tmp_path / "decay.html").exists()


@pytest.mark.skipif(shutil.which("ffmpeg") is not None, reason="ffmpeg is present")
def test_mp4_without_ffmpeg_says_so(result, folder):
    pytest.importorskip("matplotlib")
    with pytest.raises(NumericsError, match="needs ffmpeg"):
        result.animate(folder / "tutor6.mp4")
