"""Autolev's settings: the one table both the runtime and the transpiler use.

Each setting takes a whole number (``Digits 7``), a number
(``AutoEpsilon 1.0E-7``) or one of a few words (``AutoRHS ALL``).

>>> s = Settings()
>>> s.set("Digits", 5); s.digits
5
>>> check_setting("OVERWRITE", "ALL") is None
True
>>> check_setting("DEGREES", "MAYBE")
'DEGREES takes ON, OFF'
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..safety import Statements, statement

__all__ = ["SETTINGS", "Settings", "Response", "check_setting"]

#: Name -> "int" (1 to 17), "number", or the words it takes.
SETTINGS: dict[str, tuple[str, ...] | str] = {
    "DIGITS": "int",
    "DEGREES": ("ON", "OFF"),
    "AUTORHS": ("ON", "OFF", "ALL"),
    "FACTORING": ("ON", "OFF"),
    "AUTOEPSILON": "number",
    "COMPLEX": ("ON", "OFF", "AUTO"),
    "AUTOZ": ("ON", "OFF"),
    # ALL: overwrite every file without asking (Autolev asked per file).
    "OVERWRITE": ("ON", "OFF", "ALL"),
    "AUTOEXPRESS": ("ON", "OFF"),
    # Interactive conveniences; accepted and recorded, nothing to do in batch.
    "BEEPSOUND": ("ON", "OFF"),
    "PAUSE": "number",
}


def check_setting(name: str, value: str | None) -> str | None:
    """A plain-English message if ``name value`` is not a valid setting."""
    allowed = SETTINGS.get(name.upper())
    if allowed is None:
        return f"setting '{name}' is not supported yet"
    word = (value or "").upper()
    if allowed == "int":
        if not word.isdigit() or not 1 <= int(word) <= 17:
            return f"{name} takes a whole number from 1 to 17"
    elif allowed == "number":
        try:
            float(word)
        except ValueError:
            return f"{name} takes a number"
    elif word not in allowed:
        return f"{name} takes {', '.join(allowed)}"
    return None


@dataclass
class Settings:
    """Autolev settings (tutorial §6.5 and the Summary's "Default settings")."""

    digits: int = 7
    degrees: bool = False
    autorhs: str = "ON"  # OFF | ON | ALL
    factoring: bool = True
    autoepsilon: float = 1.0e-7
    complex: str = "OFF"  # OFF | ON | AUTO
    autoz: bool = False
    overwrite: str = "ON"  # ON | OFF | ALL
    autoexpress: bool = False
    beepsound: bool = True
    pause: float = 0.0
    #: the workspace's statement calls (a failing setting line names its
    #: ``.al`` line); None for settings made by hand
    statements: Statements | None = field(default=None, repr=False, compare=False)

    @statement
    def set(self, name: str, value: Any = None) -> None:
        """Apply a setting line such as ``Digits 7`` or ``AutoRHS ALL``."""
        key = name.upper()
        text = str(value) if value is not None else "ON"
        message = check_setting(key, text)
        if message is not None:
            raise ValueError(message)
        kind = SETTINGS[key]
        if kind == "int":
            new: Any = int(text)
        elif kind == "number":
            new = float(text)
        elif kind == ("ON", "OFF"):
            new = text.upper() == "ON"
        else:
            new = text.upper()
        setattr(self, key.lower(), new)


@dataclass(frozen=True)
class Response:
    """One ``-> (n) NAME = value`` line, kept symbolic until printed."""

    line: int | None
    label: str
    value: Any
    digits: int
    #: printed exactly as computed: the user's own Factor/Expand/... result,
    #: which display simplification must not undo
    verbatim: bool = False
    #: AutoZ was ON: intermediates are shown by name (their definitions
    #: first), else written out
    autoz: bool = False
