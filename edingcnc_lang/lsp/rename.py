"""Rename a sub or a variable across the files of a folder (the job, ``macro.cnc``, ``user_macro.cnc``).

A sub is renamed where it is defined and wherever a ``GoSub`` reaches it (the calls the linter
resolves, so a same-named sub of another folder is left alone).  A variable ``#n`` is renumbered
wherever the folder's files name it: ``#n`` in any expression or assignment, a ``dlgmsg`` field
and the target of a command that writes it (``GetToolInfo``, ``modbus ... un``).  What cannot be
renamed safely is refused with the reason: a sub the controller or an M code calls by its name,
a controller parameter, a name already taken.
"""
from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.knowledge import parameter_number
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.lint.names import is_entry_point
from edingcnc_lang.lint.project import command_writes, sub_key
from edingcnc_lang.lint.walk import dialog_fields, walk
from edingcnc_lang.lsp.formatting import split_comment
from edingcnc_lang.lsp.lexer import token_at, tokens
from edingcnc_lang.lsp.model import LanguageModel, Place, definition_place

USER_VARIABLES = range(27, 5000)  # #1..#26 are the M-code subs' arguments, #5000 up the controller's
_NEW_SUB = re.compile(r"[A-Za-z0-9_]+")
_NEW_VARIABLE = re.compile(r"#?\s*([0-9]+)")


class RenameRefused(ValueError):
    """A rename that would change what the program does; the message says why."""


@dataclass(frozen=True)
class Target:
    """What the cursor names: a sub (its definition's file and node) or a variable number."""

    place: Place  # the text to replace at the cursor (a sub's name, a variable's digits)
    sub: tuple[SourceFile, n.Sub] | None = None
    variable: int | None = None


def target_at(model: LanguageModel, path: str, line: int, col: int) -> Target | None:
    """The sub or variable at 0-based ``line``/``col`` (None: nothing renamable there).

    A sub the controller or an M code calls by name is refused here already, so the editor says
    why before the user types a new name.
    """
    file = model.source(path)
    token = token_at(file.line(line + 1), col) if file else None
    if token is None:
        return None
    if token.kind == "param":
        number = parameter_number(token.text[1:])
        if number is None or number not in USER_VARIABLES:
            raise RenameRefused(f"{token.text[:12]} is not a user variable (#27..#4999): its number means something "
                                "to the controller or to an M-code sub")
        return Target(Place(path, line, token.start + 1, token.end), variable=number)
    if token.kind != "sub":
        return None
    found = model.resolve(path, token.text)
    if found is None:
        return None
    if is_entry_point(found[1].name):
        raise RenameRefused(f"Sub {found[1].name} is called by its name (by the controller or an M code): "
                            "renamed, it would no longer run")
    return Target(Place(path, line, token.start, token.end), sub=found)


def rename(model: LanguageModel, path: str, line: int, col: int, new_name: str) -> dict[str, list[Place]]:
    """The places to write ``new_name`` (as ``new_text`` gives it) at, by file."""
    target = target_at(model, path, line, col)
    if target is None:
        raise RenameRefused("nothing to rename here: put the cursor on a sub's name or a #variable")
    places = _sub_places(model, path, target, new_name) if target.sub else _variable_places(model, path, target,
                                                                                             new_name)
    found: dict[str, list[Place]] = {}
    for place in sorted(set(places), key=lambda p: (p.path, p.line, p.start)):
        found.setdefault(place.path, []).append(place)
    return found


def new_text(new_name: str) -> str:
    """What replaces each place: the sub name as typed, a variable's number without its ``#``."""
    match = _NEW_VARIABLE.fullmatch(new_name.strip())
    number = parameter_number(match.group(1)) if match else None
    return str(number) if number is not None else new_name.strip()


def _sub_places(model: LanguageModel, path: str, target: Target, new_name: str) -> list[Place]:
    assert target.sub is not None
    name = new_name.strip()
    if not _NEW_SUB.fullmatch(name):
        raise RenameRefused(f"{new_name!r} is not a sub name (letters, digits and _)")
    if is_entry_point(name):
        raise RenameRefused(f"Sub {name} would be called by the controller or an M code: choose another name")
    file, sub = target.sub
    for where in {path, file.path}:
        taken = model.resolve(where, name)
        if taken is not None and taken[1] is not sub:
            raise RenameRefused(f"a Sub {taken[1].name} exists already ({taken[0].path}:{taken[1].span.line})")
    return [definition_place(file, sub), *model.calls_to(sub_key(file, sub), path)]


def _variable_places(model: LanguageModel, path: str, target: Target, new_name: str) -> list[Place]:
    assert target.variable is not None
    match = _NEW_VARIABLE.fullmatch(new_name.strip())
    if not match:
        raise RenameRefused(f"{new_name[:40]!r} is not a variable: write #NUMBER")
    new = parameter_number(match.group(1))
    if new is None or new not in USER_VARIABLES:
        raise RenameRefused(f"#{match.group(1)[:12]} is not a user variable (#27..#4999)")
    files = model.folder(path)
    if new != target.variable:
        for file in files:
            clash = next(_variable_places_in(file, new), None)
            if clash is not None:
                raise RenameRefused(f"#{new} is used already ({file.path}:{clash.line + 1}): renaming #"
                                    f"{target.variable} to it would merge two variables")
    return [place for file in files for place in _variable_places_in(file, target.variable)]


def _variable_places_in(file: SourceFile, number: int) -> Iterator[Place]:
    """Where ``file`` names variable ``number``: the digits of each ``#n``, dlgmsg field and command target."""
    for index, text in enumerate(file.lines):
        for token in tokens(text):
            if token.kind == "param" and parameter_number(token.text[1:]) == number:
                yield Place(file.path, index, token.start + 1, token.end)
    digits = re.compile(rf"(?<![\w.#]){number}(?![\w.])|(?<=[uU]){number}(?![\w.])")
    for stmt, _scope in walk(file.body):
        if isinstance(stmt, n.Dialog):
            for index, literal in dialog_fields(stmt):
                if index == number:
                    span = literal.span
                    yield Place(file.path, span.line - 1, span.col - 1, span.end_col - 1)
        elif isinstance(stmt, n.Command) and number in command_writes(stmt):
            code = split_comment(file.line(stmt.span.line))[0]
            after = code.lower().find(stmt.name) + len(stmt.name)
            for found in digits.finditer(code, max(after, 0)):
                yield Place(file.path, stmt.span.line - 1, found.start(), found.end())
