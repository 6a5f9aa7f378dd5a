"""Autolev settings and recorded responses (shared by the workspace, the
transcript and the numerical jobs; imports nothing else of the runtime)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

__all__ = ["Settings", "Response"]

_ON_OFF = {"ON": True, "OFF": False}


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
    overwrite: bool = True
    autoexpress: bool = False

    def set(self, name: str, value: Any = None) -> None:
        """Apply a setting line such as ``Digits 7`` or ``AutoRHS ALL``."""
        key = name.lower()
        word = str(value).upper() if value is not None else "ON"
        if key == "digits":
            n = int(value)
            if not 1 <= n <= 17:
                raise ValueError(f"Digits must be between 1 and 17, not {n}")
            self.digits = n
        elif key == "autoepsilon":
            self.autoepsilon = float(value)
        elif key == "autorhs":
            if word not in ("ON", "OFF", "ALL"):
                raise ValueError(f"AutoRHS takes ON, OFF or ALL, not {value}")
            self.autorhs = word
        elif key == "complex":
            if word not in ("ON", "OFF", "AUTO"):
                raise ValueError(f"Complex takes ON, OFF or AUTO, not {value}")
            self.complex = word
        elif key in ("beepsound", "pause"):
            pass  # interactive conveniences: nothing to do in a batch run
        elif key in ("degrees", "factoring", "autoz", "overwrite", "autoexpress"):
            if word not in _ON_OFF:
                raise ValueError(f"{name} takes ON or OFF, not {value}")
            setattr(self, key, _ON_OFF[word])
        else:
            raise ValueError(f"unknown setting {name}")


@dataclass(frozen=True)
class Response:
    """One ``-> (n) NAME = value`` line, kept symbolic until printed."""

    line: int | None
    label: str
    value: Any
    digits: int
