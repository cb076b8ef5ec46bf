"""D rules: the shape of ``dlgmsg "title" "label" index ...``.

A dialog is a title string followed by pairs of a label string and a bare
variable number.  Index range and read-only targets are checked by V300/V301.
"""
from __future__ import annotations

from collections.abc import Iterator

from .. import nodes as n
from ..diagnostics import Diagnostic
from .model import SourceFile
from .project import Project
from .registry import at, at_line, rule

MAX_FIELDS = 15
MAX_LABEL = 31
_SHAPE = 'write dlgmsg "title" "label" 27 "label" 28 ... (EdingCNC G1167)'


def _string_col(file: SourceFile, dialog: n.Dialog, text: str) -> int:
    """Column of a quoted string on the dialog's line (strings carry no span of their own)."""
    found = file.line(dialog.span.line).find(f'"{text}"', dialog.span.col - 1)
    return found + 1 if found >= 0 else dialog.span.col


def _value_span(item: n.MessageItem, dialog: n.Dialog) -> n.Span:
    return dialog.span if isinstance(item, str) else item.span


@rule("D400", "D401", "D402", "D403")
def dialog_shape(file: SourceFile, project: Project) -> Iterator[Diagnostic]:
    for dialog, _scope in project.facts(file).dialogs:
        yield from _check(file, dialog)


def _check(file: SourceFile, dialog: n.Dialog) -> Iterator[Diagnostic]:
    items = dialog.items
    if not items or not isinstance(items[0], str):
        yield at("D402", f"dlgmsg must start with its title in quotes: {_SHAPE}",
                 _value_span(items[0], dialog) if items else dialog.span)
        return
    fields = 0
    label: str | None = None  # the label waiting for its variable number
    for item in items[1:]:
        if isinstance(item, str):
            if label is not None:
                yield at_line("D402", f'label "{label}" has no variable number after it: {_SHAPE}',
                              file, dialog.span.line, _string_col(file, dialog, label))
            label = item
            fields += 1
            if fields == MAX_FIELDS + 1:
                yield at_line("D400", f"dlgmsg has more than {MAX_FIELDS} fields: split it into two dialogs",
                              file, dialog.span.line, _string_col(file, dialog, item))
            if len(item) > MAX_LABEL:
                yield at_line("D401", f'label "{item}" is {len(item)} characters; the controller allows '
                              f"{MAX_LABEL} (unnamed string too long): shorten it", file,
                              dialog.span.line, _string_col(file, dialog, item))
        elif label is None:
            yield at("D402", f"a value where a label string belongs: {_SHAPE}", item.span)
        elif isinstance(item, n.Param) and isinstance(item.index, n.Number):
            shown = f"{item.index.value:g}"
            yield at("D403", f"field variable written as #{shown}: give the bare number {shown} "
                     "(EdingCNC G1167)", item.span)
            label = None
        elif isinstance(item, n.Number) and item.value.is_integer():
            label = None
        else:
            yield at("D402", f"the variable number of a field must be a plain whole number: {_SHAPE}",
                     item.span)
            label = None
    if label is not None:
        yield at_line("D402", f'label "{label}" has no variable number after it: {_SHAPE}',
                      file, dialog.span.line, _string_col(file, dialog, label))
