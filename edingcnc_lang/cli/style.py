"""Colour for diagnostics on a terminal: error red, warning yellow, the caret line green.

Only for a terminal, and never when ``NO_COLOR`` is set (https://no-color.org) or ``TERM`` is
``dumb``; piped output stays plain text byte for byte.  The text is coloured after it is formatted,
so every format keeps one source of truth.
"""
from __future__ import annotations

import os
import re
from typing import IO

import click

# "PATH:LINE:COL: error: ..." and the labels of run messages; lint's "PATH:LINE:COL: CODE ..."
_LABEL = re.compile(r"^(\S.*?:\d+(?::\d+)?: )(error|warning)(:)", re.MULTILINE)
_LINT = re.compile(r"^(\S.*?:\d+:\d+: )([A-Z]\d{3})\b", re.MULTILINE)
_CARET = re.compile(r"^( +)(\^+)$", re.MULTILINE)
COLOURS = {"error": "red", "warning": "yellow"}


def wants_colour(stream: IO[str] | None) -> bool:
    """True for a terminal, unless NO_COLOR is set (to anything) or TERM is dumb."""
    if stream is None or "NO_COLOR" in os.environ or os.environ.get("TERM") == "dumb":
        return False
    isatty = getattr(stream, "isatty", None)
    return bool(isatty and isatty())


def colour_diagnostics(text: str) -> str:
    """Diagnostics text with ANSI colours: severity words, lint codes by severity, caret lines."""
    from edingcnc_lang.codes import CODES

    def label(match: re.Match[str]) -> str:
        word = match.group(2)
        return match.group(1) + click.style(word, fg=COLOURS[word], bold=True) + match.group(3)

    def code(match: re.Match[str]) -> str:
        entry = CODES.get(match.group(2))
        colour = COLOURS.get(entry.severity.value if entry else "", "red")
        return match.group(1) + click.style(match.group(2), fg=colour, bold=True)

    text = _LABEL.sub(label, text)
    text = _LINT.sub(code, text)
    return _CARET.sub(lambda m: m.group(1) + click.style(m.group(2), fg="green", bold=True), text)


def styled(text: str, stream: IO[str] | None) -> str:
    """``text`` coloured if ``stream`` wants colour, else unchanged."""
    return colour_diagnostics(text) if wants_colour(stream) else text
