"""Lines of Autolev text as Autolev read them.

Only a line break ends a line: ``\\n``, ``\\r\\n`` or ``\\r``.  Python's
``str.splitlines()`` also breaks at a form feed, a vertical tab, the file,
group and record separators (``\\x1c``-``\\x1e``), NEL (``\\x85``) and the
Unicode line and paragraph separators (U+2028, U+2029): inside a ``%``
comment one of those would end the comment and turn the rest of the line
into code, and a transcript would number more lines than the script has.
Every split of script or transcript text goes through :func:`split_lines`.

This module imports nothing heavy (``al2py.batch`` uses it at import).
"""

from __future__ import annotations

import re

__all__ = ["split_lines", "OTHER_BREAKS"]

_LINE_BREAK = re.compile(r"\r\n|\r|\n")

#: characters ``str.splitlines()`` breaks at that are not line breaks here
OTHER_BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"


def split_lines(text: str) -> list[str]:
    """``text`` split at ``\\n``, ``\\r\\n`` and ``\\r`` only, like
    ``str.splitlines()`` otherwise (no empty last line after a final break).

    >>> split_lines("% a\\x0c Constants HIDDEN\\nB = 1\\n")
    ['% a\\x0c Constants HIDDEN', 'B = 1']
    >>> "% a\\x0c Constants HIDDEN\\nB = 1\\n".splitlines()
    ['% a', ' Constants HIDDEN', 'B = 1']
    """
    if not text:
        return []
    parts = _LINE_BREAK.split(text)
    if parts[-1] == "":
        parts.pop()
    return parts
