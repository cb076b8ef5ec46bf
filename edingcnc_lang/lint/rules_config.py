"""C rules: the machine configuration (``cnc.ini``) as the configuration loader validates it.

The loader raises on the first bad value; the linter reports that value as a
finding instead, so an ini is linted like any other file.
"""
from __future__ import annotations

import os

from edingcnc_lang.config.machine_config import load_config
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import ConfigError

USER_OUTPUT_KEYS = ("userOutputStartVariable", "userOutputNumVariables")


def check_config(path: str | os.PathLike[str]) -> tuple[list[Diagnostic], frozenset[int]]:
    """Findings for an ini file, and the variables its kinematics writes (user outputs)."""
    try:
        config = load_config(path)
    except ConfigError as err:
        code = "C700" if err.message.startswith(USER_OUTPUT_KEYS) else "C701"
        where = err.location
        line, col = (where.line, where.col) if where else (0, 0)
        return [Diagnostic.make(code, err.message, os.fspath(path), max(line, 1), max(col, 1))], frozenset()
    start, count = config.user_output_start, config.user_output_count
    return list(config.warnings), frozenset(range(start, start + count)) if start else frozenset()
