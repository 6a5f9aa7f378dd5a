"""al2py: convert Autolev (.al) scripts into readable Python modules.

>>> from al2py import convert
>>> code = convert("Constants A, B\\nX = 4*(A+B) - 3*(a-b)\\n", "intro.al").code
>>> "al.assign('X'" in code
True
"""

__version__ = "0.1.0"

from .errors import AutolevError, InternalError  # noqa: E402
from .transpile import Conversion, convert  # noqa: E402

__all__ = ["convert", "Conversion", "AutolevError", "InternalError", "__version__"]
