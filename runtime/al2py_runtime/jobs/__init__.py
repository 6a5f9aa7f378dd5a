"""Numerical ``CODE`` jobs: recording, compiling and running them.

* :mod:`.records` -- what ``Input``, ``Output`` and ``CODE`` record
* :mod:`.numerics` -- :class:`Numerics`, a script's recorder of those statements
* :mod:`.run` -- performing a job (integration, solves, output rows)
* :mod:`.backends` -- compiling right-hand sides (lambdify, C, LLVM)
* :mod:`.budget` -- limits that keep a job from running forever
* :mod:`.tables`, :mod:`.results` -- output tables and their views
* :mod:`.viewing` -- plots (matplotlib figures) and HTML for notebooks
* :mod:`.scene`, :mod:`.animation` -- what ``Animate`` shows, and playing it
* :mod:`.reading` -- output tables read back from files
* :mod:`.units` -- ``UnitSystem`` and unit conversion
"""
