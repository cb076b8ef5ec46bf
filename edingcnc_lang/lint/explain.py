"""The long explanation of a lint code (``ecnc help CODE``, ``ecnc lint --explain CODE``), and of a
``ecnc kins check`` finding code (``ecnc help K101``).

The texts are docs/lint.md's, docs/kinematics.md's and (for the R codes of errors that stop a run) docs/errors.md's, copied into package data by scripts/regen_code_explanations.py so
an installed ``ecnc`` has them; the registry (codes.py) gives the severity and summary.
"""
from __future__ import annotations

import json
from functools import cache
from importlib import resources

from edingcnc_lang.codes import CODES, KINS_CODES, RETIRED, RUNTIME_CODES
from edingcnc_lang.lint.driver import UnknownCode


@cache
def _texts() -> dict[str, str]:
    data = resources.files(__package__).joinpath("explanations.json").read_text(encoding="utf-8")
    return dict(json.loads(data))


def explain(code: str) -> str:
    """``CODE (severity): summary`` and the long text (a retired code: why); raises UnknownCode for a
    code never registered."""
    key = code.strip().upper()
    if key in RETIRED:
        return f"{key}: {RETIRED[key]}"
    runtime = RUNTIME_CODES.get(key)
    if runtime is not None:
        return _with_text(key, f"{key} (runtime): {runtime.summary}")
    entry = CODES.get(key)
    if entry is None:
        raise UnknownCode(code)
    return _with_text(entry.code, f"{entry.code} ({entry.severity.value}): {entry.summary}")


def explain_kins(code: str) -> str | None:
    """``K101 (kins check, round trip): summary`` and the long text; None for a code not in KINS_CODES."""
    key = code.strip().upper()
    if key not in KINS_CODES:
        return None
    check, summary = KINS_CODES[key]
    return _with_text(key, f"{key} (kins check, {check}): {summary}")


def _with_text(code: str, head: str) -> str:
    text = _texts().get(code)
    return f"{head}\n\n{text}" if text else head
