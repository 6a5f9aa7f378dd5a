"""A module is about as long as its script (issue 33): at most 1.5 lines of
Python per ``.al`` line for Moore's Whipple bicycle.

Each echo (``# al> ...``) ends its statement's first line when the two fit
black's 88 columns, and the fixed parts (the baked ``--help``, the functions
at the end) are short.  The ratio is the module's lines over the script's.
"""

from __future__ import annotations

from pathlib import Path

import black
from al2py_runtime.safety import echoed_source
from test_codegen_warnings import WHIPPLE, _extract

from al2py import convert

ROOT = Path(__file__).resolve().parent.parent

#: module lines per .al line: the figures measured when this was written
#: (before: whipple_benchmark 3.83, Moore's Whipple 2.08), with a little room
BENCHMARK_RATIO = 2.95
MOORE_RATIO = 1.5


def _ratio(path: Path) -> tuple[float, str]:
    text = path.read_text("latin-1")
    code = convert(text, path.name).code
    # each line of the script once, read back exactly; black's own layout
    assert echoed_source(code.splitlines()) == [ln.strip() for ln in text.splitlines()]
    assert black.format_str(code, mode=black.Mode()) == code
    return code.count("\n") / len(text.splitlines()), code


def test_whipple_benchmark_module_lines_per_al_line():
    ratio, code = _ratio(ROOT / "tests" / "models" / "whipple_benchmark.al")
    assert ratio <= BENCHMARK_RATIO, f"{ratio:.3f} lines per .al line"
    assert "Y.orient_axis(N, N.z, Q3)  # al> Simprot(N, Y, 3, Q3)\n" in code


def test_moores_whipple_module_lines_per_al_line(tmp_path):
    script = _extract(*WHIPPLE, tmp_path)  # skips when the corpus is absent
    ratio, _ = _ratio(script)
    assert ratio <= MOORE_RATIO, f"{ratio:.3f} lines per .al line"
