"""Go to definition, find references, document and workspace symbols: all about subs.

A sub is named by ``Sub name``, called by ``GoSub name``, by its M code (``Sub m100``
runs on ``M100``) or by the controller (``change_tool`` on M6).  The cursor on any of
these finds the sub the way a call from that file reaches it.
"""
from __future__ import annotations

from dataclasses import dataclass

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.lint.model import SourceFile
from edingcnc_lang.machine.tables import m_code_sub
from edingcnc_lang.lint.project import sub_key
from edingcnc_lang.lint.walk import walk
from edingcnc_lang.knowledge import code_key_of
from edingcnc_lang.lsp.lexer import code_number, token_at
from edingcnc_lang.lsp.model import LanguageModel, Place, definition_place


@dataclass(frozen=True)
class Symbol:
    """A sub as an outline entry: its name, the lines it spans (0-based, inclusive), its name's place."""

    name: str
    first_line: int
    last_line: int
    end_col: int
    selection: Place


def sub_at(model: LanguageModel, path: str, line: int, col: int) -> tuple[SourceFile, n.Sub] | None:
    """The sub named, called or run by an M code at 0-based ``line``/``col``."""
    file = model.source(path)
    token = token_at(file.line(line + 1), col) if file else None
    if token is None:
        return None
    if token.kind == "sub":
        return model.resolve(path, token.text)
    if token.kind == "code":
        letter, number = code_number(token)
        key = code_key_of(number)
        name = m_code_sub(key) if letter == "M" and key is not None else None
        return model.resolve(path, name) if name else None
    return None


def definition(model: LanguageModel, path: str, line: int, col: int) -> Place | None:
    found = sub_at(model, path, line, col)
    return definition_place(*found) if found else None


def references(model: LanguageModel, path: str, line: int, col: int, declaration: bool) -> list[Place]:
    """Every call of the sub at the cursor from the files of the folder (and its definition if asked)."""
    found = sub_at(model, path, line, col)
    if found is None:
        return []
    places = [definition_place(*found)] if declaration else []
    places += model.calls_to(sub_key(*found), found[0].path)
    return sorted(set(places), key=lambda p: (p.path, p.line, p.start))


def document_symbols(model: LanguageModel, path: str) -> list[Symbol]:
    """The subs of a file with the lines from ``Sub`` to ``EndSub``."""
    file = model.source(path)
    if file is None:
        return []
    return [_symbol(file, stmt) for stmt in file.body if isinstance(stmt, n.Sub)]


def workspace_symbols(model: LanguageModel, query: str) -> list[tuple[str, Place]]:
    """Subs whose name contains ``query`` (ignoring case) in the workspace's macro files and open files."""
    wanted = query.lower()
    return [(sub.name, definition_place(file, sub))
            for file in model.workspace() for name, sub in file.subs.items() if wanted in name]


def folding_ranges(model: LanguageModel, path: str) -> list[tuple[int, int]]:
    """(first, last) 0-based lines of each Sub, If and While, the end line left visible."""
    file = model.source(path)
    if file is None:
        return []
    found = []
    for stmt, _scope in walk(file.body):
        if isinstance(stmt, (n.Sub, n.If, n.While)):
            last = min(stmt.end_span.line, len(file.lines) + 1) - 2  # before EndSub/EndIf/EndWhile
            if last > stmt.span.line - 1:
                found.append((stmt.span.line - 1, last))
    return found


def _symbol(file: SourceFile, sub: n.Sub) -> Symbol:
    last = sub.end_span.line if sub.end_span.line >= sub.span.line else len(file.lines)
    last = min(max(last, sub.span.line), max(len(file.lines), 1))
    return Symbol(sub.name, sub.span.line - 1, last - 1, len(file.line(last)), definition_place(file, sub))
