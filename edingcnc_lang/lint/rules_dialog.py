"""D rules: the shape of ``dlgmsg "title" "label" index ...`` (decided in ``edingcnc_lang.syntax.dialogs``).

Index range and read-only targets are checked by V300/V301.
"""
from __future__ import annotations

from collections.abc import Iterator

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.syntax.dialogs import dialog_fields
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.project import Project
from edingcnc_lang.lint.registry import at, at_line, rule



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
