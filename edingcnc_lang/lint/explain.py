"""The long explanation of a lint code (``ecnc help CODE``, ``ecnc lint --explain CODE``).

The texts are docs/lint.md's, copied into package data by scripts/regen_code_explanations.py so
an installed ``ecnc`` has them; the registry (codes.py) gives the severity and summary.
"""
from __future__ import annotations

import json
from functools import cache
from importlib import resources

from ..codes import CODES
from .driver import UnknownCode


@cache
def _texts() -> dict[str, str]:
    data = resources.files(__package__).joinpath("explanations.json").read_text(encoding="utf-8")
    return dict(json.loads(data))


def explain(code: str) -> str:
    """``CODE (severity): summary`` and the long text; raises UnknownCode for a code not registered."""
    entry = CODES.get(code.strip().upper())
    if entry is None:
        raise UnknownCode(code)
    head = f"{entry.code} ({entry.severity.value}): {entry.summary}"
    text = _texts().get(entry.code)
    return f"{head}\n\n{text}" if text else head
