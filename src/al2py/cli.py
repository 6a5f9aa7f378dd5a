"""The ``al2py`` command line.

    al2py tutor6.al -o tutor6.py     convert one script
    al2py - < tutor6.al              read standard input, write standard output

Exit status: 0 on success, 2 for errors in the input (``file:line:col:
error: ...``), 3 for a bug in al2py itself.  No traceback reaches the user.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from . import __version__
from .errors import AutolevError, InternalError
from .transpile import convert

__all__ = ["main"]

EXIT_OK, EXIT_INPUT, EXIT_BUG = 0, 2, 3


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="al2py",
        description="Convert an Autolev (.al) script into a readable Python module "
        "built on sympy.physics.mechanics.",
        epilog="Run the result with 'python OUT.py' to print Autolev's transcript, "
        "or 'import' it to use the model.",
    )
    p.add_argument("input", help="the .al file to convert ('-' reads standard input)")
    p.add_argument(
        "-o",
        "--output",
        metavar="OUT.py",
        help="where to write the module ('-' or omitted: standard output)",
    )
    p.add_argument("--version", action="version", version=f"al2py {__version__}")
    return p


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    try:
        return _convert_file(args.input, args.output)
    except AutolevError as exc:
        print(exc.format(), file=sys.stderr)
        return EXIT_INPUT
    except InternalError as exc:
        print(f"al2py: internal error: {exc} (please report this bug)", file=sys.stderr)
        return EXIT_BUG
    except RecursionError:
        print("al2py: error: the input is nested too deeply", file=sys.stderr)
        return EXIT_INPUT
    except Exception as exc:  # noqa: BLE001 - last line of defence: no traceback
        name = type(exc).__name__
        print(
            f"al2py: internal error: {name}: {exc} (please report this bug)",
            file=sys.stderr,
        )
        return EXIT_BUG


def _convert_file(source: str, output: str | None) -> int:
    if source == "-":
        text, filename = sys.stdin.read(), "<stdin>"
    else:
        path = Path(source)
        try:
            text = path.read_text(encoding="utf-8", errors="replace")
        except OSError as exc:
            print(
                f"al2py: error: cannot read {source}: {exc.strerror}", file=sys.stderr
            )
            return EXIT_INPUT
        filename = source
    result = convert(text, filename)
    if output is None or output == "-":
        sys.stdout.write(result.code)
        return EXIT_OK
    out = Path(output)
    if source != "-" and out.exists() and out.resolve() == Path(source).resolve():
        print(
            f"al2py: error: refusing to overwrite the input file {source}",
            file=sys.stderr,
        )
        return EXIT_INPUT
    _write_atomically(out, result.code)
    return EXIT_OK


def _write_atomically(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` via a temporary file and an atomic rename."""
    directory = path.parent if str(path.parent) else Path(".")
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
