"""What the model's parts use of the script they belong to.

:class:`~.model.Model` is given, in its constructor, the small objects it
uses and nothing else: the script's :class:`~al2py_runtime.names.table.NameTable`
(declarations, right-hand sides, stored values), its
:class:`~al2py_runtime.names.settings.Settings`, its
:class:`~al2py_runtime.safety.Statements`, the list of unit-norm
quantities, and a :class:`ScriptNames`: the operations on Autolev names
(evaluating, normalizing, assigning and responding) that the model's commands
call.  The workspace (:class:`al2py_runtime.workspace.Workspace`) is the one
implementation of :class:`ScriptNames`; this protocol is the whole of what
the model may call on it, so a reader (or ``mypy``) sees each use.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, Protocol

if TYPE_CHECKING:
    from ..intermediates.autoz import Intermediates

__all__ = ["ScriptNames"]


class ScriptNames(Protocol):
    """The script's operations on Autolev names that the model calls."""

    # ------------------------------------------------------------ values

    def val(self, x: Any) -> Any:
        """The value of an Autolev name or expression (a name's right-hand
        side for a vector, matrix or dyadic)."""
        ...

    def form(self, x: Any) -> Any:
        """``x`` written out as the script sees it (intermediates expanded
        while ``AutoZ`` is OFF)."""
        ...

    def normalize(self, value: Any, *, rearrange: bool = False) -> Any:
        """Autolev's automatic treatment of a new value."""
        ...

    def resolve(self, expr: Any, keep: Iterable[Any] = ()) -> Any:
        """``expr`` with every right-hand side substituted but ``keep``."""
        ...

    def resolver(self, keep: Iterable[Any] = ()) -> Callable[[Any], Any]:
        """:meth:`resolve` as a function of one expression (memoized)."""
        ...

    def name_of(self, obj: Any) -> str:
        """The Autolev spelling of a declared symbol or derivative."""
        ...

    def specified_inputs(self, unknowns: list[Any]) -> list[Any]:
        """The specified quantities (and derivatives) a solve keeps."""
        ...

    # ----------------------------------------------------- intermediates

    @property
    def book(self) -> Intermediates:
        """The book of ``Z`` intermediates (made on first use)."""
        ...

    @property
    def intermediates(self) -> Intermediates | None:
        """The book while ``AutoZ`` is ON, else None."""
        ...

    def solver_book(self, unknowns: int, eqs: Any = None) -> Intermediates | None:
        """The book a linear solve of ``unknowns`` unknowns names with."""
        ...

    def book_if_made(self) -> Intermediates | None:
        """The book if any intermediate was ever made."""
        ...

    # ------------------------------------------- declarations, responses

    def variables(self, *names: str, line: int | None = None) -> Any:
        """``Variables X', Y''``: declares functions of time."""
        ...

    def assign(self, target: str, value: Any, *, line: int | None = None) -> Any:
        """``TARGET = value``, with Autolev's response."""
        ...

    def update(self, target: str, value: Any, *, line: int | None = None) -> Any:
        """``TARGET := value`` (``ZERO`` rearranged by ``Kane()``)."""
        ...

    def respond(self, label: str, value: Any, *, line: int | None = None) -> None:
        """Record Autolev's response ``-> (n) LABEL = value``."""
        ...
