"""A parsed source file as the linter sees it: its lines, statements and parser findings."""
from __future__ import annotations

import os
from itertools import chain
from collections.abc import Iterator, Mapping
from types import MappingProxyType

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang.diagnostics import Diagnostic
from edingcnc_lang.errors import UnreadableFile
from edingcnc_lang.syntax.line_parser import parse_line
from edingcnc_lang.syntax.parser import StatementReader
from edingcnc_lang.syntax.source import iter_file_blocks, iter_text_lines
from edingcnc_lang.syntax.plain_words import plain_words
from edingcnc_lang.lint.walk import ends_program


@record(frozen=True, eq=False)  # one object per file: compared and hashed by identity
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


def load_source(path: str | os.PathLike[str], is_macro: bool, text: str | None = None,
                stream: bool = False) -> SourceFile:
    """Read and parse a file (or ``text``, its unsaved contents in an editor); syntax errors become findings.

    With ``stream`` the top-level plain motion lines that no rule can report on are not kept
    (``ecnc lint`` of a million-line CAM job); the body is then not the whole file.
    """
    shown = os.fspath(path)
    try:  # the file's lines in the lists it is read in: nothing is done per line here
        blocks = list(iter_file_blocks(path)) if text is None else [list(iter_text_lines(text))]
    except OSError as exc:
        raise UnreadableFile.of(shown, exc) from None
    lines = tuple(chain.from_iterable(blocks))
    reader = StatementReader((), shown, mode="lint" if stream else "tree", blocks=blocks)
    body = tuple(_kept(reader, shown) if stream else reader)
    subs: dict[str, n.Sub] = {}
    for stmt in body:
        if isinstance(stmt, n.Sub):
            subs.setdefault(stmt.name.lower(), stmt)
    return SourceFile(shown, lines, body, reader.unit, tuple(reader.diagnostics), is_macro,
                      MappingProxyType(subs))


def stream_source(path: str | os.PathLike[str], is_macro: bool) -> SourceFile:
    """``load_source`` as ``ecnc lint`` reads files from disk: plain motion lines are not kept."""
    return load_source(path, is_macro, stream=True)


_MOTION_LETTERS = frozenset("GXYZABCF")  # not S: G521 checks a constant S against the ini


def _kept(reader: StatementReader, path: str) -> Iterator[n.Stmt]:
    """The statements of a "lint" read, each top-level plain line a Block unless it is plain motion.

    Plain motion (at most one G, which is G0 or G1, axis words, a non-zero F) gives no rule
    anything to report, calls nothing and ends nothing; the statement after a program end is
    always kept, since S209 reports it.
    """
    after_end = False
    for stmt in reader:
        if type(stmt) is not n.PlainRun:
            yield stmt
            after_end = ends_program(stmt)
            continue
        for lineno, text in stmt.lines:
            if not after_end and _plain_motion(plain_words(text)):
                continue  # decided from the words as text: no nodes are built for the lines dropped
            block = parse_line(text, path, lineno)
            assert isinstance(block, n.Block)
            yield block
            after_end = ends_program(block)


def _plain_motion(words: list[tuple[str, str]]) -> bool:
    """At most one G, which is G0 or G1, then axis words and a non-zero F; a leading N word is
    the line number (``make_block`` takes it out of the words)."""
    if words and words[0][0] in "Nn":
        words = words[1:]
    g = [float(value) for letter, value in words if letter in "Gg"]
    return (len(g) <= 1 and all(value in (0.0, 1.0) for value in g)
            and all(letter.upper() in _MOTION_LETTERS for letter, _ in words)
            and all(float(value) != 0.0 for letter, value in words if letter in "Ff"))
