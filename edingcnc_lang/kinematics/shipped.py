"""Where the shipped plug-ins (the repo's ``kins/`` folder) live.

Installed, ``kins/`` is the package ``edingcnc_lang.kins``; a source checkout reaches it through
the symlink ``edingcnc_lang/kins``, and where git could not create that link (Windows without
symlink support) through the top-level package ``kins`` with PYTHONPATH at the repo root.
Everything that needs it goes through this module so that the difference is handled once.
"""
from __future__ import annotations

import importlib
from contextlib import AbstractContextManager
from pathlib import Path
from types import ModuleType

INSTALLED = "edingcnc_lang.kins"
SOURCE_CHECKOUT = "kins"


def import_shipped(module: str = "") -> ModuleType:
    """Import ``edingcnc_lang.kins[.module]``, falling back to the source checkout's ``kins``."""
    suffix = f".{module}" if module else ""
    try:
        return importlib.import_module(INSTALLED + suffix)
    except ModuleNotFoundError as err:
        if err.name not in (INSTALLED, INSTALLED + suffix):
            raise
        return importlib.import_module(SOURCE_CHECKOUT + suffix)


def header_dir() -> AbstractContextManager[Path]:
    """A context giving a real folder holding ``edingcnc_kins.h`` (package data ``kins/c``)."""
    from importlib import resources  # only to build C plug-ins: every run imports this module

    return resources.as_file(resources.files(import_shipped()) / "c")
