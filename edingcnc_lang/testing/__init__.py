"""Unit tests for macro files: ``test_*.toml`` files run by ``ecnc test`` and by pytest (docs/testing.md).

One module per job: ``spec`` reads test files, ``execute`` runs one test through the embedding
API, ``checks`` compares what it did with what was expected, ``coverage`` records and sums up
what the macro files ran, ``session`` runs many tests (``-k``, ``-x``, ``-j``), ``reports``
writes coverage and JUnit reports, ``pytest_plugin`` is the pytest side.
"""
