"""D rules: the shape of ``dlgmsg "title" "label" index ...`` (decided in ``edingcnc_lang.dialogs``).

Index range and read-only targets are checked by V300/V301.
"""
from __future__ import annotations

from collections.abc import Iterator

from .. import nodes as n
from ..diagnostics import Diagnostic
from ..dialogs import dialog_fields
from .model import SourceFile
from .project import Project
from .registry import at, at_line, rule



def _string_col(file: SourceFile, dialog: n.Dialog, text: str) -> int:
    """Column of a quoted string on the dialog's line (strings carry no span of their own)."""
    found = file.line(dialog.span.line).find(f'"{text}"', dialog.span.col - 1)
    return found + 1 if found >= 0 else dialog.span.col


@rule("D400", "D401", "D402", "D403")
def dialog_shape(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for dialog, _scope in project.facts(file).dialogs:
        for problem in dialog_fields(dialog)[1]:
            item = problem.item
            if isinstance(item, str):
                yield at_line(problem.code, problem.message, file, dialog.span.line, _string_col(file, dialog, item))
            else:
                yield at(problem.code, problem.message, dialog.span if item is None else item.span)
