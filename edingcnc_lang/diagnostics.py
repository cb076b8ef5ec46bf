"""Diagnostics: plain records with a stable code, a position and a message.

The parser, the checker and the linter all report through this one record so
every front end (CLI text, JSON, SARIF, the API) renders them the same way.
"""
from __future__ import annotations



from edingcnc_lang.codes import Severity, lookup
from edingcnc_lang.errors import EXIT_SYNTAX, EcncError, Location, printable, shortened
from edingcnc_lang.records import record


@record(frozen=True)
class Diagnostic:
    """One finding at a place in a file: a plain record, so any output format can show it."""

    path: str
    line: int
    col: int
    code: str
    message: str
    severity: Severity = Severity.ERROR
    source: str = ""  # the offending source line, for the caret display

    @classmethod
    def make(cls, code: str, message: str, path: str, line: int, col: int,
             source: str = "") -> "Diagnostic":
        """Build a diagnostic with the severity its code is registered with."""
        return cls(path, line, col, code, message, lookup(code).severity, source)

    @property
    def location(self) -> Location:
        return Location(self.path, self.line, self.col)

    def __post_init__(self) -> None:
        object.__setattr__(self, "message", shortened(self.message))  # a quoted 65,000-letter name, cut

    def format(self, with_source: bool = True) -> str:
        """``PATH:LINE:COL: error: message`` and, if known, the line with a caret (a long line
        only around the caret, so one finding prints a few hundred characters, not 65,000)."""
        text = printable(f"{self.location}: {self.severity.value}: {self.message}")
        if with_source and self.source:
            source, caret_col = _excerpt(self.source, max(self.col, 1))
            prefix = "".join("\t" if ch == "\t" else " " for ch in printable(source[:caret_col - 1]))
            text += f"\n    {printable(source)}\n    {prefix}^"
        return text


EXCERPT = 160  # characters of a source line shown under a finding, around its column


def _excerpt(line: str, col: int) -> tuple[str, int]:
    """The part of ``line`` shown, and the caret's column in it: the line itself when short, else
    EXCERPT characters around ``col`` with "…" where it was cut."""
    if len(line) <= EXCERPT:
        return line, col
    start = max(0, min(col - 1 - EXCERPT // 2, len(line) - EXCERPT))
    end = start + EXCERPT
    head = "…" if start else ""
    return head + line[start:end] + ("…" if end < len(line) else ""), col - start + len(head)


class SyntaxErrors(EcncError):
    """Raised when a file has syntax errors; carries every one of them (exit 65)."""

    exit_code = EXIT_SYNTAX
    kind = "syntax"

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        first = diagnostics[0]
        super().__init__(first.message, first.location)
        self.diagnostics = diagnostics

    def format(self) -> str:
        return "\n".join(d.format() for d in self.diagnostics)
