"""The shape of ``dlgmsg "title" "label" index ...``, shared by the job check, the run and the linter.

A dialog is a title string followed by pairs of a label string and a bare
parameter number.  The grammar accepts any list of strings and values, so this
is where the controller's G1167 ("syntax error") and "unnamed string too long"
are decided, once for every stage.
"""
from __future__ import annotations

from collections.abc import Iterator

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record

MAX_FIELDS = 15
MAX_LABEL = 31
SHAPE = 'write dlgmsg "title" "label" 27 "label" 28 ... (EdingCNC G1167)'
# What the controller refuses when it reads the line (the job check finds these before any move);
# D400/D401 (too many fields, long labels) are refused when the dialog is shown.
SYNTAX_CODES = frozenset({"D402", "D403"})


@record(frozen=True)
class Field:
    """One field of a dialog: its label and the literal parameter number it edits."""

    label: str
    index: n.Number


@record(frozen=True)
class Problem:
    """A shape mistake: its code, message, and the item it is about (None: the whole dialog)."""

    code: str
    message: str
    item: n.MessageItem | None


def dialog_fields(dialog: n.Dialog) -> tuple[list[Field], list[Problem]]:
    """The fields of a dialog and every shape problem, in item order."""
    fields: list[Field] = []
    problems = list(_problems(dialog, fields))
    return fields, problems


def _problems(dialog: n.Dialog, fields: list[Field]) -> Iterator[Problem]:
    items = dialog.items
    if not items or not isinstance(items[0], str):
        yield Problem("D402", f"dlgmsg must start with its title in quotes: {SHAPE}", items[0] if items else None)
        return
    labels = 0
    label: str | None = None  # the label waiting for its parameter number
    for item in items[1:]:
        if isinstance(item, str):
            if label is not None:
                yield Problem("D402", f'label "{label}" has no variable number after it: {SHAPE}', label)
            label = item
            labels += 1
            if labels == MAX_FIELDS + 1:
                total = sum(isinstance(other, str) for other in items[1:])
                yield Problem("D400", f"dlgmsg has {total} fields; at most {MAX_FIELDS} fit: split it into two dialogs",
                              item)
            if len(item) > MAX_LABEL:
                yield Problem("D401", f'label "{item}" is {len(item)} characters; the controller allows '
                              f"{MAX_LABEL} (unnamed string too long): shorten it", item)
        elif label is None:
            yield Problem("D402", f"a value where a label string belongs: {SHAPE}", item)
        elif isinstance(item, n.Param) and isinstance(item.index, n.Number):
            shown = f"{item.index.value:g}"
            yield Problem("D403", f"field variable written as #{shown}: give the bare number {shown} "
                          "(EdingCNC G1167)", item)
            label = None
        elif isinstance(item, n.Number) and item.value.is_integer():
            fields.append(Field(label, item))
            label = None
        else:
            yield Problem("D402", f"the variable number of a field must be a plain whole number: {SHAPE}", item)
            label = None
    if label is not None:
        yield Problem("D402", f'label "{label}" has no variable number after it: {SHAPE}', label)
