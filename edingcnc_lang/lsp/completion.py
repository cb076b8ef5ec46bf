"""Completion: sub names after GoSub, G/M codes, commands, functions and parameters.

What is offered depends on the text before the cursor: a sub name after ``GoSub``,
parameters after ``#`` (system variables with their names and the numbers the file
uses), codes after ``G``/``M``, and at the start of a line the keywords and commands.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from edingcnc_lang import knowledge
from edingcnc_lang.lint.names import m_sub_number
from edingcnc_lang.lsp.lexer import token_at
from edingcnc_lang.lsp.model import LanguageModel, file_name

_GOSUB = re.compile(r"\s*(?:/\s*)?gosub\s+([A-Za-z0-9_]*)$", re.IGNORECASE)
_PARAM = re.compile(r"#(\d*)$")
_CODE = re.compile(r"(?<![A-Za-z0-9_])([GM])(\d*(?:\.\d*)?)$", re.IGNORECASE)
_WORD = re.compile(r"(?<![A-Za-z0-9_#])([A-Za-z_][A-Za-z0-9_]*)?$")
_LINE_START = re.compile(r"\s*(?:/\s*)?(?:N\d+\s*)?[A-Za-z_]*$", re.IGNORECASE)
_USED_PARAM = re.compile(r"#([0-9]+)")


@dataclass(frozen=True)
class Item:
    """One completion: the text to insert, a label, a one-line detail and the kind of thing it is."""

    label: str
    kind: str  # "code" | "sub" | "variable" | "keyword" | "command" | "function"
    detail: str
    documentation: str
    start: int  # the column the inserted text replaces from (0-based, up to the cursor)
    insert: str = ""  # the text inserted, when not the label (a variable's name inserts its number)


def complete(model: LanguageModel, path: str, line: int, col: int) -> list[Item]:
    """Everything that fits at 0-based ``line``/``col`` of ``path``."""
    file = model.source(path)
    text = file.line(line + 1) if file else ""
    before = text[:col]
    token = token_at(text, col)
    if token is not None and token.kind in ("comment", "string") and token.start < col:
        return []
    match = _GOSUB.match(before)
    if match:
        return _subs(model, path, col - len(match.group(1)))
    match = _PARAM.search(before)
    if match:
        lines = list(file.lines if file else ())
        if line < len(lines):  # the number being typed is not one the file uses
            rest = re.match(r"\d*", text[col:]).end()  # type: ignore[union-attr]
            lines[line] = text[:match.start()] + text[col + rest:]
        return _params(tuple(lines), match.start())
    items: list[Item] = []
    match = _CODE.search(before)
    if match:
        items += _codes(model, path, match.group(1).upper(), match.start())
    word = _WORD.search(before)
    start = word.start() if word else col
    if _LINE_START.fullmatch(before):
        items += _words(("keyword", "command"), start)
    if "[" in before:
        items += _words(("function",), start)
    return items


def _subs(model: LanguageModel, path: str, start: int) -> list[Item]:
    found = model.project(path)
    if found is None:
        return []
    items: dict[str, Item] = {}
    for source in found[1].files:
        for name, sub in source.subs.items():
            items.setdefault(name, Item(sub.name, "sub", f"Sub in {file_name(source.path)}, line {sub.span.line}",
                                        "", start))
    return list(items.values())


def _params(lines: tuple[str, ...], start: int) -> list[Item]:
    """The numbers the file uses first, then every system variable with its name."""
    used = sorted({number for text in lines for m in _USED_PARAM.findall(text)
                   if (number := knowledge.parameter_number(m)) is not None})
    items = [_variable(number, start) for number in used]
    return items + [Item(entry.name, "variable", entry.title, entry.markdown(), start)
                    for entry in knowledge.named_variables() if int(entry.name[1:]) not in used]


def _variable(number: int, start: int) -> Item:
    entry = knowledge.variable(number)
    return Item(f"#{number}", "variable", f"used in this file{': ' + entry.title if entry else ''}",
                entry.markdown() if entry else "", start)


def _codes(model: LanguageModel, path: str, letter: str, start: int) -> list[Item]:
    items = [Item(entry.name, "code", entry.title, entry.markdown(), start)
             for entry in knowledge.codes() if entry.kind == letter]
    if letter == "M":
        found = model.project(path)
        known = {item.label for item in items}
        for source in found[1].files if found else ():
            for name, sub in source.subs.items():
                number = m_sub_number(name)
                if number is not None and f"M{number}" not in known:
                    known.add(f"M{number}")
                    items.append(Item(f"M{number}", "code", f"runs Sub {sub.name}", "", start))
    return items


def _words(kinds: tuple[str, ...], start: int) -> list[Item]:
    return [Item(entry.name, entry.kind, entry.title, entry.markdown(), start)
            for kind in kinds for entry in knowledge.words(kind)]
