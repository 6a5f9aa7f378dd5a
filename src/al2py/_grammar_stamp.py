"""Record which grammar the committed ANTLR parser was generated from.

``python -m al2py._grammar_stamp --write`` stores the SHA-256 of
``grammar/Autolev.g4`` in ``src/al2py/_antlr/GRAMMAR_SHA256``;
``--check`` exits with status 1 when the stamp does not match the grammar
(i.e. someone edited the grammar and forgot ``make grammar``).
"""

from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

__all__ = [
    "GRAMMAR_PATH",
    "STAMP_PATH",
    "grammar_sha256",
    "read_stamp",
    "write_stamp",
    "is_fresh",
    "main",
]

_PACKAGE_DIR = Path(__file__).resolve().parent
GRAMMAR_PATH = _PACKAGE_DIR.parents[1] / "grammar" / "Autolev.g4"
STAMP_PATH = _PACKAGE_DIR / "_antlr" / "GRAMMAR_SHA256"


def grammar_sha256(path: Path = GRAMMAR_PATH) -> str:
    """Hex SHA-256 of the grammar file's bytes."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


def read_stamp(path: Path = STAMP_PATH) -> str | None:
    """The recorded digest, or None if there is no stamp file."""
    if not path.is_file():
        return None
    return path.read_text(encoding="ascii").strip()


def write_stamp(grammar: Path = GRAMMAR_PATH, stamp: Path = STAMP_PATH) -> str:
    """Write the grammar's digest to the stamp file and return it."""
    digest = grammar_sha256(grammar)
    stamp.parent.mkdir(parents=True, exist_ok=True)
    stamp.write_text(digest + "\n", encoding="ascii")
    return digest


def is_fresh(grammar: Path = GRAMMAR_PATH, stamp: Path = STAMP_PATH) -> bool:
    """True if the stamp matches the current grammar file."""
    if not grammar.is_file():
        return False
    return read_stamp(stamp) == grammar_sha256(grammar)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m al2py._grammar_stamp",
        description="Write or check the grammar stamp of the generated parser.",
    )
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--write", action="store_true", help="record the digest")
    group.add_argument("--check", action="store_true", help="exit 1 if stale")
    args = parser.parse_args(argv)
    if not GRAMMAR_PATH.is_file():
        print(f"grammar not found: {GRAMMAR_PATH}", file=sys.stderr)
        return 1
    if args.write:
        digest = write_stamp()
        print(f"{STAMP_PATH.name}: {digest}")
        return 0
    if is_fresh():
        return 0
    print(
        f"{STAMP_PATH} is stale: run `make grammar` to regenerate the parser",
        file=sys.stderr,
    )
    return 1


if __name__ == "__main__":
    sys.exit(main())
