"""The variable map: a name, a kind, writers and readers for every numbered variable.

``names`` finds the names authors already write (``convention``: the explicit ``;@var`` and
``variables.toml``; dlgmsg labels, comments, the manual), ``kinds`` sorts numbers by what they
are, ``model`` holds the map and ``render`` prints it.  Who writes and reads a number comes from
the linter's facts (``lint.variable_uses``, ``lint.variable_map``), which build on this package.
"""
