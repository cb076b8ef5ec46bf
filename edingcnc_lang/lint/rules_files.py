"""F rules (whole lines and files) and the parser's own syntax and structure findings."""
from __future__ import annotations

from collections.abc import Iterator

from edingcnc_lang.codes import CODES
from edingcnc_lang.syntax.input_limits import MAX_LINE_LENGTH
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at_line, rule

PARSER_CODES = tuple(c for c in CODES if c.startswith("E") or c in
                     ("S200", "S201", "S202", "S203", "S204", "S205", "S206"))
WARN_LENGTH, MAX_LENGTH = 256, 1055

@rule(*PARSER_CODES, "F603")
def syntax(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """The parser's findings (a line of prose among them is F603)."""
    yield from file.parse_errors


@rule("F600")
def unit_directive(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """EdingCNC 5 refuses a macro file whose first line does not declare its units."""
    declared = file.unit is not None or any(d.code == "E109" for d in file.parse_errors)
    if file.is_macro and not declared:
        yield at_line("F600", "macro file does not declare its units: make the first line "
                      "';@unit mm' (or ';@unit inch') (EdingCNC G1290: Macro does not specify unit)",
                      file, 1)


@rule("F601", "F602")
def line_length(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    """The controller reads 256 characters a line as documented and 1055 at most (a G-code line longer than
    256 is the parser's E114: macro statements such as dlgmsg are longer in real 4.03 macros)."""
    if max(map(len, file.lines), default=0) <= WARN_LENGTH:  # most files: one pass in C finds nothing
        return
    refused = {d.line for d in file.parse_errors if d.code == "E114"}
    for number, text in enumerate(file.lines, 1):
        if len(text) > MAX_LINE_LENGTH or number in refused:  # past the parser's limits: E110/E114 say so
            continue
        if len(text) > MAX_LENGTH:
            yield at_line("F602", f"line is {len(text)} characters long; the controller reads at most "
                          f"{MAX_LENGTH}: split it", file, number, MAX_LENGTH + 1)
        elif len(text) > WARN_LENGTH:
            yield at_line("F601", f"line is {len(text)} characters long; the manual allows {WARN_LENGTH}: "
                          "split it or shorten its comment", file, number, WARN_LENGTH + 1)
