"""``python -m al2py`` is the ``al2py`` command."""

from .cli import main

raise SystemExit(main())
