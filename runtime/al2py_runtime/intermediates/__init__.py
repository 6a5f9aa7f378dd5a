"""Named intermediates: ``AutoZ``'s ``Z`` variables and the elimination with
named entries they (and :mod:`al2py_runtime.model.fastkane`) solve with.

* :mod:`.autoz` -- the :class:`~.autoz.Intermediates` book
* :mod:`.elimination` -- Gauss-Jordan elimination with numeric pivots
"""
