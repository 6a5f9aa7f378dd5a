"""Autolev's names: the name table's keys, settings, printing and the transcript.

* :mod:`.keys` -- Autolev spellings as keys (``"M0[2,2]"``, ``"STRETCH'"``)
* :mod:`.settings` -- ``AutoRHS``, ``Digits``... and the :class:`Response` record
* :mod:`.printing` -- values printed in Autolev's syntax
* :mod:`.transcript` -- the numbered transcript of a script's responses
* :mod:`.variables` -- functions of time for ``Variables`` and ``Specified``
"""
