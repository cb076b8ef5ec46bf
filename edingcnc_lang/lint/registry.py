"""The rule registry: each rule names the codes it reports and checks one file at a time.

Codes, severities and summaries live in ``edingcnc_lang.codes`` (shared with
the parser); this module only knows which function reports which codes, so the
driver can skip rules whose codes are all deselected.
"""
from __future__ import annotations

from collections.abc import Callable, Iterable

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang.codes import CODES
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project

Check = Callable[[SourceFile, Project], Iterable[Diagnostic]]


@record(frozen=True)
class Rule:
    """A check and the codes it reports (the driver skips it when all of them are deselected)."""

    codes: tuple[str, ...]
    check: Check


RULES: list[Rule] = []


def rule(*codes: str) -> Callable[[Check], Check]:
    """Register a check as reporting ``codes`` (each must be in the code table)."""
    unknown = [c for c in codes if c not in CODES]
    if unknown:
        raise KeyError(f"codes missing from edingcnc_lang.codes: {unknown}")

    def register(check: Check) -> Check:
        RULES.append(Rule(codes, check))
        return check

    return register


def at(code: str, message: str, span: n.Span) -> Diagnostic:
    """A finding at the start of a node."""
    return Diagnostic.make(code, message, span.path, span.line, max(span.col, 1))


def at_line(code: str, message: str, file: SourceFile, line: int, col: int = 1) -> Diagnostic:
    """A finding at a line and column of a file."""
    return Diagnostic.make(code, message, file.path, line, max(col, 1))
