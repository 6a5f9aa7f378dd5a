"""Autolev's vocabulary, said once: what each Autolev word means.

* :mod:`.kinds`: :class:`Kind` (what an expression is) and :class:`Decl`
  (what a declaration makes a name);
* :mod:`.builtins`: one :class:`Builtin` row per built-in function or
  command (arity, result-kind rule, implementation, degree variant, whether
  it responds, printed name);
* :mod:`.forms`: one :class:`NameForm` row per syntactical form
  (``P_O_Q>``, ``V_P_N>``, ``N_A``, ``A1>``...).

The transpiler's analysis and generator, ``al2py check``, the transcript's
printer and the numeric backends all read these tables; adding a built-in
is one :func:`register` call.  This package depends only on sympy (and
:mod:`al2py_runtime.functions`, the implementations).

>>> lookup("Atan2").max_args, Decl.of_keyword("POINTS"), Form.DCM.row.spell("N", "A")
(2, <Decl.POINT: 'point'>, 'N_A')
"""

from .builtins import (
    BUILTINS,
    LIST_COMMANDS,
    Builtin,
    Style,
    by_spelling,
    complex_functions,
    library,
    lookup,
    numeric_namespace,
    printed_name,
    register,
    registered,
    unregister,
)
from .forms import FORMS, Form, Match, NameForm, match, unit_vector
from .kinds import (
    FRAME_DECLS,
    MASSIVE_DECLS,
    OBJECT_DECLS,
    POINT_DECLS,
    QUANTITY_DECLS,
    SCALAR_DECLS,
    TIME_DECLS,
    Decl,
    Kind,
)

__all__ = [
    "BUILTINS",
    "FORMS",
    "FRAME_DECLS",
    "LIST_COMMANDS",
    "MASSIVE_DECLS",
    "OBJECT_DECLS",
    "POINT_DECLS",
    "QUANTITY_DECLS",
    "SCALAR_DECLS",
    "TIME_DECLS",
    "Builtin",
    "Decl",
    "Form",
    "Kind",
    "Match",
    "NameForm",
    "Style",
    "by_spelling",
    "complex_functions",
    "library",
    "lookup",
    "match",
    "numeric_namespace",
    "printed_name",
    "register",
    "registered",
    "unregister",
    "unit_vector",
]
