"""Start-up times: the first five minutes of use (issue 12, item 12).

Measures, as wall time of a fresh process (best of five):

* ``al2py --version`` and ``al2py --help`` (target: under 0.3 s; they must not
  import sympy);
* ``python -c pass`` (the interpreter alone) and ``import sympy``, for scale;
* ``import tutor6`` for the module generated from examples/tutor6.al (sympy,
  the runtime and the symbolic derivation).

Run: ``.venv/bin/python benchmarks/startup.py``.  Exit status 1 if
``al2py --version`` takes 0.3 s or more.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TARGET = 0.3
REPEATS = 5


def best(cmd: list[str], cwd: Path | None = None) -> float:
    times = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        subprocess.run(cmd, cwd=cwd, check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> int:
    al2py = shutil.which("al2py", path=str(Path(sys.executable).parent))
    al2py_cmd = [al2py] if al2py else [sys.executable, "-m", "al2py"]
    rows = [
        ("python -c pass", best([sys.executable, "-c", "pass"])),
        ("al2py --version", best([*al2py_cmd, "--version"])),
        ("al2py --help", best([*al2py_cmd, "--help"])),
        ("python -c 'import sympy'", best([sys.executable, "-c", "import sympy"])),
    ]
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        subprocess.run(
            [*al2py_cmd, str(ROOT / "examples" / "tutor6.al"), "-o", "tutor6.py"],
            cwd=work,
            check=True,
        )
        rows.append(
            (
                "import tutor6 (generated)",
                best([sys.executable, "-c", "import tutor6"], work),
            )
        )
    base = rows[0][1]
    print(f"{'command':<28} {'seconds':>8} {'x python':>9}")
    for name, seconds in rows:
        print(f"{name:<28} {seconds:8.3f} {seconds / base:9.1f}")
    version = rows[1][1]
    verdict = "under" if version < TARGET else "NOT under"
    print(f"\nal2py --version: {version:.3f} s, {verdict} the {TARGET} s target")
    return 0 if version < TARGET else 1


if __name__ == "__main__":
    raise SystemExit(main())
