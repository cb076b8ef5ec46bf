"""A parsed source file as the linter sees it: its lines, statements and parser findings."""
from __future__ import annotations

import os
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from .. import nodes as n
from ..diagnostics import Diagnostic
from ..errors import UnreadableFile
from ..parser import StatementReader
from ..source import iter_file_lines, iter_text_lines


@dataclass(frozen=True, eq=False)  # one object per file: compared and hashed by identity
class SourceFile:
    """One parsed file as the rules see it: its lines, statements, subs and syntax findings."""

    path: str
    lines: tuple[str, ...]
    body: tuple[n.Stmt, ...]
    unit: str | None
    parse_errors: tuple[Diagnostic, ...]
    is_macro: bool  # a macro library (macro.cnc, user_macro.cnc, --macro ...), not a job
    subs: Mapping[str, n.Sub]  # first definition of each sub, by lower-case name

    def line(self, number: int) -> str:
        """Source line ``number`` (1-based), or "" past the end."""
        return self.lines[number - 1] if 0 < number <= len(self.lines) else ""


def load_source(path: str | os.PathLike[str], is_macro: bool, text: str | None = None) -> SourceFile:
    """Read and parse a file (or ``text``, its unsaved contents in an editor); syntax errors become findings."""
    shown = os.fspath(path)
    try:
        lines = tuple(iter_file_lines(path) if text is None else iter_text_lines(text))
    except OSError as exc:
        raise UnreadableFile.of(shown, exc) from None
    reader = StatementReader(lines, shown)
    body = tuple(reader)
    subs: dict[str, n.Sub] = {}
    for stmt in body:
        if isinstance(stmt, n.Sub):
            subs.setdefault(stmt.name.lower(), stmt)
    return SourceFile(shown, lines, body, reader.unit, tuple(reader.diagnostics), is_macro,
                      MappingProxyType(subs))
