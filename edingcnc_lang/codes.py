"""The registry of diagnostic codes: one table, shared by the parser, the checker and the linter.

Codes are stable public names (scripts filter on them).  The first letter
groups them: E syntax, S structure, V expressions and variables, D dialogs,
G G/M-code usage, F files, C configuration.
"""
from __future__ import annotations

from dataclasses import dataclass
from enum import Enum


class Severity(str, Enum):
    ERROR = "error"
    WARNING = "warning"


@dataclass(frozen=True)
class Code:
    code: str
    severity: Severity
    summary: str


def _table(*rows: tuple[str, Severity, str]) -> dict[str, Code]:
    return {code: Code(code, severity, summary) for code, severity, summary in rows}


E, W = Severity.ERROR, Severity.WARNING

CODES: dict[str, Code] = _table(
    ("E100", E, "syntax error: the line is not a valid statement"),
    ("E101", E, "unclosed '[' in an expression"),
    ("E102", E, "unbalanced ']' without a matching '['"),
    ("E103", E, "unclosed '(' comment"),
    ("E104", E, "unterminated string"),
    ("E105", E, "expression without brackets after a word (write X[10+5], not X10+5)"),
    ("E106", E, "If/While condition is not one bracketed expression (EdingCNC G1171)"),
    ("E107", E, "unknown KIN mode"),
    ("E108", E, "word letter without a value"),
    ("E109", E, "invalid @unit directive"),
    ("S200", E, "EndIf without If"),
    ("S201", E, "Else without If"),
    ("S202", E, "EndWhile without While"),
    ("S203", E, "EndSub without Sub"),
    ("S204", E, "block not closed: If without EndIf, While without EndWhile, Sub without EndSub"),
    ("S205", E, "Sub defined inside another Sub"),
    ("S206", E, "second Else in one If"),
)


def lookup(code: str) -> Code:
    """The registered code; an unknown code is a programming error."""
    return CODES[code]
