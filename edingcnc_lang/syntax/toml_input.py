"""TOML files the commands read (``ecnc test``'s test files, ``ecnc sim``'s tools file), read
under the input limits of ``input_limits.py``: UTF-8 only, nesting bounded, numbers finite and
written with ASCII digits.

tomllib itself recurses once per nested array or inline table (100,000 ``[`` ended in a
RecursionError traceback) and gives a 400-digit integer as a Python int that ``float()`` cannot
take (OverflowError); here each is a ``TomlProblem`` with the line, for the caller to report as
its own error.
"""
from __future__ import annotations

import math
import re
import sys
from typing import Any

from edingcnc_lang.syntax.input_limits import MAX_BRACKET_DEPTH, MAX_NUMBER_DIGITS

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10 has the same parser as a package
    import tomli as tomllib

_WHOLE = re.compile(r"[0-9]+")


class TomlProblem(ValueError):
    """What is wrong with a TOML text, and its line (0: unknown)."""

    def __init__(self, message: str, line: int = 0) -> None:
        super().__init__(message)
        self.message = message
        self.line = line


def decode(raw: bytes) -> str:
    """The text of a TOML file: UTF-8 (an editor's BOM is no mistake); TomlProblem otherwise."""
    try:
        return raw.decode("utf-8-sig")
    except UnicodeDecodeError as err:
        line = raw[:err.start].count(b"\n") + 1
        raise TomlProblem(f"a TOML file must be UTF-8 ({err.reason} at byte {err.start})", line) from None


def parse(text: str) -> dict[str, Any]:
    """``text`` as TOML; TomlProblem (with the line) for a syntax error or nesting deeper than
    MAX_BRACKET_DEPTH."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise TomlProblem(*_located(str(err), text)) from None
    except RecursionError:
        data = None
    if data is None or _too_deep(data):
        raise TomlProblem(f"arrays and tables nested more than {MAX_BRACKET_DEPTH} deep (the nesting limit)", 1)
    return data


def _too_deep(data: Any) -> bool:
    """Whether ``data`` nests more than MAX_BRACKET_DEPTH arrays and tables (walked without recursion)."""
    stack = [(data, 0)]
    while stack:
        value, depth = stack.pop()
        if depth > MAX_BRACKET_DEPTH:
            return True
        if isinstance(value, dict):
            stack.extend((item, depth + 1) for item in value.values())
        elif isinstance(value, list):
            stack.extend((item, depth + 1) for item in value)
    return False


def _located(message: str, text: str) -> tuple[str, int]:
    """tomllib's message without its ``(at line L, column C)``, and that line (the last one at its end)."""
    found = re.search(r"\s*\(at line (\d+), column \d+\)$", message)
    if found:
        return message[:found.start()], int(found[1])
    found = re.search(r"\s*\(at end of document\)$", message)
    if found:
        return message[:found.start()] + " at the end of the file", max(1, text.count("\n") + (not text.endswith("\n")))
    return message, 0


def number(value: Any) -> float | None:
    """``value`` as a finite float if it is a TOML integer or float (not a boolean) a double holds; else None.

    A TOML integer of 400 digits is a Python int past the doubles: None, not OverflowError.
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        result = float(value)
    except OverflowError:
        return None
    return result if math.isfinite(result) else None


def whole_number(text: str) -> int | None:
    """``text`` as a whole number if it is ASCII digits only, at most MAX_NUMBER_DIGITS of them; else
    None (``²`` and ``٥٠٠٨`` are digits to ``str.isdigit``, not here)."""
    if len(text) > MAX_NUMBER_DIGITS or not _WHOLE.fullmatch(text):
        return None
    return int(text)
