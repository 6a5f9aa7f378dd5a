"""Long runs of operators convert in linear time (issue 32).

A FILENAME token that could hold ``-`` or ``/`` made the lexer look ahead
across a whole ``----A`` or ``A-A-A`` run at each of its characters
(quadratic: 5,000 unary minus signs took 14 s, 20,000 did not finish in
60 s).  For each kind of run this converts N and 4N terms in the same
process, alternating turns, and prints the ratio of the best times: about 4
for linear cost, about 16 for quadratic.  Exit status 1 if a ratio exceeds
:data:`LIMIT`.

Run: ``.venv/bin/python benchmarks/operator_runs.py``.
"""

from __future__ import annotations

import sys
import time

from al2py import convert

N = 1000
TURNS = 3
LIMIT = 8.0  # between linear (4) and quadratic (16)

RUNS = {
    "unary minus": lambda n: "-" * n + "A",
    "A-A-A": lambda n: "-".join(["A"] * n),
    "A/A/A": lambda n: "/".join(["A"] * n),
}


def seconds(expr: str) -> float:
    start = time.perf_counter()
    convert(f"Constants A\nX = {expr}\n", "run.al")
    return time.perf_counter() - start


def main() -> int:
    worst = 0.0
    for name, make in RUNS.items():
        small, large = [], []
        for _ in range(TURNS):  # alternating, so load affects both alike
            small.append(seconds(make(N)))
            large.append(seconds(make(4 * N)))
        ratio = min(large) / min(small)
        worst = max(worst, ratio)
        print(
            f"{name:12s} {N} terms {min(small):6.2f} s, {4 * N} terms "
            f"{min(large):6.2f} s: ratio {ratio:4.1f} (linear 4, quadratic 16)"
        )
    return 1 if worst > LIMIT else 0


if __name__ == "__main__":
    sys.exit(main())
