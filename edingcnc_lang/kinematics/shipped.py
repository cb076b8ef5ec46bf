"""Where the shipped plug-ins (the repo's ``kins/`` folder) live: the package ``edingcnc_lang.kins``.

``edingcnc_lang/kins`` is a real folder, a copy of the top-level ``kins/`` (the source of truth,
kept equal by ``scripts/sync_package_data.py`` and pinned by ``tests/packaging/test_package_data.py``), so an
installed wheel, an editable install and a Windows clone all find it the same way.  Everything that
needs it goes through this module.
"""
from __future__ import annotations

import importlib
from contextlib import AbstractContextManager
from pathlib import Path
from types import ModuleType

INSTALLED = "edingcnc_lang.kins"


def import_shipped(module: str = "") -> ModuleType:
    """Import ``edingcnc_lang.kins[.module]``."""
    return importlib.import_module(INSTALLED + (f".{module}" if module else ""))


def header_dir() -> AbstractContextManager[Path]:
    """A context giving a real folder holding ``edingcnc_kins.h`` (package data ``kins/c``)."""
    from importlib import resources  # only to build C plug-ins: every run imports this module

    return resources.as_file(resources.files(import_shipped()) / "c")
