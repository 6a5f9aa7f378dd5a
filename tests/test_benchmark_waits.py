"""``benchmarks/waits.py``'s paired ratios (issue 35): each turn over the
floor's turn just before it, and one measurement's over another's of the
same round, the median over the rounds."""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))

from waits import Series  # noqa: E402


def _series(rounds: list[tuple[float, float, float, float]]) -> Series:
    """Rounds of (floor, import, floor, code) wall times (CPU the same)."""
    series = Series()
    for floor_a, imp, floor_b, code in rounds:
        series.add("floor", floor_a, floor_a)
        series.add("import", imp, imp)
        series.add("floor", floor_b, floor_b)
        series.add("code", code, code)
    return series


def test_each_turn_is_paired_with_the_floors_turn_before_it():
    # the machine twice as slow in the second round: every turn doubled
    series = _series([(1.0, 3.0, 1.0, 4.5), (2.0, 6.0, 2.0, 9.0), (1.0, 2.0, 1.0, 4.0)])
    assert series.paired("import") == 3.0  # median of 3, 3, 2
    assert series.paired("code") == 4.5  # median of 4.5, 4.5, 4
    assert series.paired("code", "import") == 1.5  # of 1.5, 1.5, 2
    # the machine twice as slow while the code ran in two rounds of three:
    # the ratio of the medians says 3, each round 1.5
    slow = _series([(1.0, 3.0, 2.0, 9.0), (1.0, 3.0, 2.0, 9.0), (1.0, 3.0, 1.0, 4.5)])
    assert slow.median("code")[0] / slow.median("import")[0] == 3.0
    assert slow.paired("code", "import") == 1.5
    assert slow.paired("code") == 4.5


def test_no_turns_no_ratio():
    series = Series()
    assert series.paired("import") is None
    series.add("import", 3.0, 3.0)  # no floor before it: not paired
    assert series.paired("import") is None
    assert series.median("import") == (3.0, 3.0)
