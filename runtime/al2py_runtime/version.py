"""The runtime's version (one place: ``__init__`` and generated programs read it)."""

__version__ = "0.2.0"
