"""Parsing: source lines -> AST statements, streaming, with errors in the user's terms.

Each line is one statement, so a single line is parsed at a time (``line_parser.py``: the fast
paths, the grammar, the error messages) and this module assembles the multi-line blocks (Sub,
If, While) from the stream, in the four reading modes, and offers the whole-file entry points.
"""
from __future__ import annotations

import os
import re
from array import array
from bisect import bisect_left
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import replace
from functools import partial
from itertools import islice

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang import speedups
from edingcnc_lang.codes import Severity
from edingcnc_lang.diagnostics import Diagnostic, SyntaxErrors
from edingcnc_lang.syntax.dialogs import SYNTAX_CODES, dialog_fields
from edingcnc_lang.syntax.input_limits import INTEGER_DIGITS, MAX_BLOCK_DEPTH, MAX_GCODE_LINE, MAX_NUMBER_DIGITS
from edingcnc_lang.syntax.line_parser import CONDITION_LINE, parse_line, parse_line_grammar
from edingcnc_lang.syntax.plain_words import FAST_LINE, FAST_WORD, PLAIN_LINE, is_fast_line, plain_block, plain_words  # re-exported: the public API
from edingcnc_lang.syntax.blocks import Close, LineResult, Open
from edingcnc_lang.syntax.fastparse import COMPILED_ASSEMBLE, COMPILED_READER, GIVE_UP, compiled_statements, new_node
from edingcnc_lang.syntax.source import iter_file_blocks, iter_text_lines
from edingcnc_lang.syntax.tree_builder import LineError as _LineError

__all__ = ["CHUNK_LINES", "RUN_LENGTH", "UNITS", "CheckedFile", "StatementReader", "check_file",
           "is_fast_line", "parse_file", "parse_line", "parse_line_grammar", "parse_text", "plain_block",
           "plain_words", "read_statements"]

UNITS = frozenset({"mm", "inch"})

_UNIT_RE = re.compile(r"^\s*(?:;\s*\*?\s*)?@unit\b\s*(\S*)", re.IGNORECASE)
RUN_LENGTH = 512  # plain lines per PlainRun chunk: large enough to amortise, small enough to stream
READ_AHEAD = 128  # lines inside a block the compiled reader reads in one call (tree and lint reads)
CHUNK_LINES = 8192
# Whether a line is plain does not depend on which digits it has (the word grammar reads any ASCII
# digit alike): written with every digit as 9, the lines of a chunk fall into a few shapes.
_DIGITS_AS_NINE = str.maketrans("012345678", "999999999")
# In a tolerant read only a line that goes on with '[' is taken for a broken If/While head: prose
# such as "If the probe does not trip, ..." must not open a block.
_TOLERANT_CONDITION = re.compile(r"^\s*(if|while)(?![a-z0-9_])\s*\[", re.IGNORECASE)


def _batched(lines: Iterable[str]) -> Iterator[list[str]]:
    """Lines in lists of CHUNK_LINES."""
    source = iter(lines)
    while chunk := list(islice(source, CHUNK_LINES)):
        yield chunk


def _chunks(blocks: Iterable[list[str]]) -> Iterator[tuple[int, list[str]]]:
    """The lines in lists of at most CHUNK_LINES, with the line number of each list's first line."""
    base = 1
    for block in blocks:
        for first in range(0, len(block), CHUNK_LINES):
            chunk = block[first:first + CHUNK_LINES] if len(block) > CHUNK_LINES else block
            yield base, chunk
            base += len(chunk)


def non_plain_lines(chunk: list[str]) -> list[int]:
    """Indices of the lines of a chunk that are not plain word lines (``FAST_LINE``): the lines with
    every digit written as 9 fall into a few shapes (a CAM job's lines into tens per chunk), and each
    shape is matched once.

    The reference for ``_speedups.non_plain_lines`` (the check pass's scan, compiled).
    """
    if max(map(len, chunk)) > MAX_GCODE_LINE:  # rare: parse_line refuses the long ones
        return [i for i, text in enumerate(chunk) if len(text) > MAX_GCODE_LINE or not FAST_LINE.match(text)]
    shapes = "\n".join(chunk).translate(_DIGITS_AS_NINE).split("\n")
    others = {shape for shape in set(shapes) if not FAST_LINE.match(shape)}
    return [i for i, shape in enumerate(shapes) if shape in others] if others else []


# the check pass's scan on the core that runs (speedups.py chooses)
_non_plain_lines: Callable[[list[str]], list[int]] = non_plain_lines
if speedups.SPEEDUPS is not None:  # the C reads its limits from the one table (input_limits.py)
    _non_plain_lines = partial(speedups.compiled("non_plain_lines"), MAX_GCODE_LINE, INTEGER_DIGITS, MAX_NUMBER_DIGITS)


# --------------------------------------------------------------------------- structure

class _Frame:
    """An open block while its body is being collected (a plain class: one per block, and a
    dataclass would cost start-up time for nothing)."""

    __slots__ = ("opener", "source", "body", "orelse", "in_else")

    def __init__(self, opener: Open, source: str) -> None:
        self.opener = opener
        self.source = source
        self.body: list[n.Stmt] = []
        self.orelse: list[n.Stmt] = []
        self.in_else = False

    def add(self, stmt: n.Stmt) -> None:
        (self.orelse if self.in_else else self.body).append(stmt)

    def close(self, end: n.Span) -> n.Stmt:
        o = self.opener
        if o.kind == "Sub":
            return new_node(n.Sub, (o.name, tuple(self.body), o.span, end))
        assert o.cond is not None
        if o.kind == "If":
            return new_node(n.If, (o.cond, tuple(self.body), tuple(self.orelse), self.in_else, o.extra, o.span, end))
        return new_node(n.While, (o.cond, tuple(self.body), o.extra, o.span, end))

    def describe(self) -> str:
        o = self.opener
        return f"Sub {o.name} (line {o.span.line})" if o.kind == "Sub" else f"{o.kind} (line {o.span.line})"


_END_OF = {"Sub": "EndSub", "If": "EndIf", "While": "EndWhile"}
_OPENER_OF = {"EndSub": "Sub", "EndIf": "If", "EndWhile": "While", "Else": "If"}
_ORPHAN_CODE = {"EndSub": "S203", "EndIf": "S200", "EndWhile": "S202", "Else": "S201"}


class StatementReader:
    """Streams the statements of a source, top level only, as soon as each is complete.

    Diagnostics are collected in ``diagnostics`` (parsing goes on at the next
    line); ``unit`` holds the ``@unit`` directive once the first line is read.
    """

    def __init__(self, lines: Iterable[str], path: str, *, mode: str = "tree",
                 non_plain: Sequence[int] | None = None, tolerant: bool = False,
                 check_dialogs: bool | None = None, on_chunk: Callable[[list[str]], None] | None = None,
                 blocks: Iterable[list[str]] | None = None) -> None:
        self.path = path
        # The lines come one by one (``lines``) or, cheaper for a big file, in lists (``blocks``, then
        # ``lines`` is not read): either way they are taken in chunks.
        self._blocks = _batched(lines) if blocks is None else blocks
        # Whoever needs more of the text than statements (the T words GetToolInfo lists) sees
        # every chunk of lines as it is read, so the file is not read again for it.
        self.on_chunk = on_chunk
        self.lines = 0  # how many lines have been read so far (all of them, once iterated)
        self._recent: list[tuple[int, list[str]]] = []  # the last chunks read: an error's line text
        # A tolerant read (macro files) keeps a line that does not parse as a BadLine statement and
        # lists it in ``warnings``: the controller only fails on the lines it executes.
        self.tolerant = tolerant
        self.warnings: list[Diagnostic] = []
        # The dlgmsg shapes the controller calls a syntax error although the grammar takes them (G1167):
        # a job's check reports them before anything moves.
        self.check_dialogs = mode == "check" if check_dialogs is None else check_dialogs
        # How plain word lines (most of a CAM job) are delivered: "tree" as Block nodes like any
        # line; "check" not at all at the top level (checking keeps nothing); "run" as PlainRun
        # chunks at the top level and PlainBlock nodes inside blocks, the cheapest forms to execute;
        # "lint" as PlainRun chunks at the top level (the linter keeps the few it needs) and nodes inside.
        self.mode = mode
        # Line numbers of the lines that are not plain: recorded by a "check" read (not by a "lint" read),
        # reused by a "run" read.
        self.non_plain: Sequence[int] = non_plain if non_plain is not None else array("I")
        self._known = non_plain is not None
        self.unit: str | None = None
        self.diagnostics: list[Diagnostic] = []
        self._skipped = 0  # blocks open beyond MAX_BLOCK_DEPTH, whose lines are dropped

    def _error(self, code: str, message: str, line: int, col: int, source: str = "") -> None:
        self.diagnostics.append(Diagnostic.make(code, message, self.path, line, col, source))

    def __iter__(self) -> Iterator[n.Stmt]:
        stack: list[_Frame] = []
        path = self.path
        bulk = self.mode != "tree"
        read_ahead = COMPILED_READER and self.mode in ("tree", "lint")  # (the others read plain lines otherwise)
        lineno = 0
        for base, chunk in _chunks(self._blocks):
            self.lines = base + len(chunk) - 1
            self._recent = [*self._recent[-1:], (base, chunk)]
            if self.on_chunk is not None:
                self.on_chunk(chunk)
            # Plain lines at the top level are skipped (check) or handed over in runs (run) in
            # bulk: the regular-expression engine finds the few other lines of a chunk.
            others = self._others(base, chunk) if bulk else []
            parsed: list[LineResult | object] = []  # the compiled reader's results of chunk[ahead:...]
            ahead = 0
            i, count = 0, len(chunk)
            while i < count:
                if bulk and not stack:
                    k = bisect_left(others, i)
                    j = others[k] if k < len(others) else count
                    if j > i:
                        if self.mode != "check":
                            for first in range(i, j, RUN_LENGTH):
                                last = min(first + RUN_LENGTH, j)
                                yield n.PlainRun(path, tuple(zip(range(base + first, base + last), chunk[first:last])))
                        i = j
                        continue
                lineno = base + i
                if stack and read_ahead and not self._skipped:
                    # Inside a block every line is parsed: the compiled reader reads the next lines in
                    # one call, and its assembler adds them to the blocks as _fit would, up to a line
                    # it leaves to _fit (a dlgmsg, a Sub, an end line that does not fit) or _line.
                    if not ahead <= i < ahead + len(parsed):
                        ahead, parsed = i, compiled_statements(chunk[i:i + READ_AHEAD], path, lineno) or []
                    stop, done = COMPILED_ASSEMBLE(parsed, i - ahead, chunk, ahead, stack, _Frame,  # type: ignore[misc]
                                                   MAX_BLOCK_DEPTH)
                    if stop > i - ahead:
                        i = ahead + stop
                        lineno = base + i - 1
                        if done is not None:
                            yield done
                        continue
                    result = parsed[i - ahead]
                    if result is not GIVE_UP:
                        yield from self._fit(stack, result, chunk[i], lineno)  # type: ignore[arg-type]
                        i += 1
                        continue
                yield from self._line(stack, chunk[i], lineno, bulk)
                i += 1
        yield from self._unwind(stack, lineno + 1, report=True)

    def line_text(self, number: int) -> str | None:
        """The text of line ``number`` if it is among the lines read last (two chunks), else None."""
        for base, chunk in self._recent:
            if base <= number < base + len(chunk):
                return chunk[number - base]
        return None

    def _others(self, base: int, chunk: list[str]) -> list[int]:
        """Indices (within the chunk) of the chunk's lines that are not plain word lines."""
        if self._known:
            first = bisect_left(self.non_plain, base)
            last = bisect_left(self.non_plain, base + len(chunk))
            return [number - base for number in self.non_plain[first:last]]
        others = _non_plain_lines(chunk)
        if self.mode != "lint":  # (a lint reads each file once: nobody asks for them)
            self.non_plain.extend([base + i for i in others])  # type: ignore[attr-defined]
        return others

    def _line(self, stack: list[_Frame], text: str, lineno: int, bulk: bool) -> Iterator[n.Stmt]:
        """One line taken on its own: parse it and fit it into the block structure."""
        path = self.path
        if lineno == 1 and self._read_unit(text):
            return
        if bulk and stack and self.mode == "run" and not self._skipped and len(text) <= MAX_GCODE_LINE \
                and FAST_LINE.match(text):
            stack[-1].add(plain_block(text, path, lineno))
            return
        try:
            result = parse_line(text, path, lineno)
        except _LineError as err:
            yield from self._bad_line(stack, err, text, lineno)
            return
        yield from self._fit(stack, result, text, lineno)

    def _fit(self, stack: list[_Frame], result: LineResult, text: str, lineno: int) -> Iterator[n.Stmt]:
        """Fit what a line says into the block structure."""
        if result is None:
            return
        if self._skipped and not isinstance(result, Open):  # inside blocks nested too deeply: dropped
            if isinstance(result, Close) and result.kind != "Else":
                self._skipped -= 1
            return
        if isinstance(result, n.Dialog) and (self.check_dialogs or self.tolerant):
            result = self._check_dialog(result, text)
        if isinstance(result, Open):
            if result.kind == "Sub" and stack and not self._skipped:
                self._error("S205", f"Sub {result.name} starts inside {stack[0].describe()}: "
                            f"close that first (subs cannot be nested)", lineno, result.span.col, text)
                yield from self._unwind(stack, lineno, report=False)
            self._push(stack, result, text)
        elif isinstance(result, Close):
            done = self._close(stack, result, text)
            if done is not None:
                yield done
        elif stack:
            stack[-1].add(result)
        else:
            yield result

    def _bad_line(self, stack: list[_Frame], err: _LineError, text: str, lineno: int) -> Iterator[n.Stmt]:
        """A line that does not parse: an error, or (tolerant) a warning and a BadLine in its place."""
        path = self.path
        opener = (_TOLERANT_CONDITION if self.tolerant else CONDITION_LINE).match(text)
        if self.tolerant:
            self.warnings.append(replace(Diagnostic.make(err.code, err.message, path, lineno, err.col, text),
                                         severity=Severity.WARNING))
            bad = n.BadLine(err.code, err.message, err.col, n.Span(path, lineno, err.col, lineno, len(text) + 1), text)
            if opener is None and stack:
                stack[-1].add(bad)
            elif opener is None:
                yield bad
        else:
            self._error(err.code, err.message, lineno, err.col, text)
        if opener:  # keep the block structure so its EndIf/EndWhile still matches
            span = n.Span(path, lineno, opener.start(1) + 1, lineno, len(text) + 1)
            head = Open(opener.group(1).capitalize(), span, cond=n.Number(1.0 if self.tolerant else 0.0))
            self._push(stack, head, text)
            if self.tolerant and stack and stack[-1].opener is head:  # reaching the head is the error
                stack[-1].add(n.BadLine(err.code, err.message, err.col, span, text))

    def _check_dialog(self, dialog: n.Dialog, text: str) -> n.Stmt:
        """Report the dlgmsg shapes the controller refuses when it reads the line (G1167); a tolerant
        read warns and keeps the line as a BadLine, an error only if a run reaches it."""
        bad: n.Stmt = dialog
        for problem in dialog_fields(dialog)[1]:
            if problem.code in SYNTAX_CODES:
                item = problem.item
                col = (text.find(f'"{item}"') + 1 or dialog.span.col) if isinstance(item, str) \
                    else (item.span.col if item is not None else dialog.span.col)
                if not self.tolerant:
                    self._error(problem.code, problem.message, dialog.span.line, col, text)
                    continue
                self.warnings.append(replace(Diagnostic.make(problem.code, problem.message, self.path,
                                                             dialog.span.line, col, text), severity=Severity.WARNING))
                if bad is dialog:
                    bad = n.BadLine(problem.code, problem.message, col, dialog.span, text)
        return bad

    def _push(self, stack: list[_Frame], opener: Open, text: str) -> None:
        """Open a block; one nested deeper than MAX_BLOCK_DEPTH is reported and skipped to its end."""
        if len(stack) < MAX_BLOCK_DEPTH:
            stack.append(_Frame(opener, text))
            return
        if not self._skipped:
            self._error("E112", f"blocks nested more than {MAX_BLOCK_DEPTH} deep (If, While and Sub inside "
                        "each other, the nesting limit): move the inner part into a Sub", opener.span.line,
                        opener.span.col, text)
        self._skipped += 1

    def raise_errors(self) -> None:
        """Raise SyntaxErrors with every diagnostic, in line order, if there is any."""
        if self.diagnostics:
            raise SyntaxErrors(sorted(self.diagnostics, key=lambda d: (d.line, d.col)))

    def _read_unit(self, text: str) -> bool:
        """Record a first-line ``@unit`` directive; True if the line was one."""
        match = _UNIT_RE.match(text)
        if not match:
            return False
        unit = match.group(1).lower()
        if unit in UNITS:
            self.unit = unit
        else:
            col = match.start(1) + 1
            self._error("E109", f"@unit must be 'mm' or 'inch', not '{match.group(1)}'", 1, col, text)
        return True

    def _close(self, stack: list[_Frame], close: Close, text: str) -> n.Stmt | None:
        """Apply an end line (or Else) to the stack; returns a finished top-level statement."""
        want = _OPENER_OF[close.kind]
        line, col = close.span.line, close.span.col
        if not (stack and stack[-1].opener.kind == want) and not any(f.opener.kind == want for f in stack):
            hint = (f" ({stack[-1].describe()} is still open: close it with "
                    f"{_END_OF[stack[-1].opener.kind]})") if stack else ""
            self._error(_ORPHAN_CODE[close.kind], f"{close.kind} without {want}{hint}", line, col, text)
            return None
        while stack[-1].opener.kind != want:
            inner = stack.pop()
            self._error("S204", f"{inner.describe()} has no {_END_OF[inner.opener.kind]} before "
                        f"this {close.kind}", line, col, text)
            stack[-1].add(inner.close(close.span))
        frame = stack[-1]
        if close.kind == "Else":
            if frame.in_else:
                self._error("S206", f"second Else in {frame.describe()}", line, col, text)
            frame.in_else = True
            return None
        stack.pop()
        stmt = frame.close(close.span)
        if stack:
            stack[-1].add(stmt)
            return None
        return stmt

    def _unwind(self, stack: list[_Frame], line: int, report: bool) -> Iterator[n.Stmt]:
        """Close every open block (at end of file, or on a nested Sub)."""
        end = n.Span(self.path, line, 0, line, 0)
        while stack:
            frame = stack.pop()
            if report:
                o = frame.opener
                self._error("S204", f"{frame.describe()} has no {_END_OF[o.kind]}",
                            o.span.line, o.span.col, frame.source)
            stmt = frame.close(end)
            if stack:
                stack[-1].add(stmt)
            else:
                yield stmt


# --------------------------------------------------------------------------- whole files

def read_statements(path: str | os.PathLike[str], *, mode: str = "tree",
                    non_plain: Sequence[int] | None = None, tolerant: bool = False,
                    check_dialogs: bool | None = None, name: str | None = None,
                    on_chunk: Callable[[list[str]], None] | None = None) -> StatementReader:
    """A streaming reader over a file (statements are parsed as you iterate); see StatementReader.

    ``name`` is what spans and errors call the file (``<stdin>`` for a copy of standard input).
    """
    return StatementReader((), os.fspath(path) if name is None else name, mode=mode, non_plain=non_plain,
                           tolerant=tolerant, check_dialogs=check_dialogs, on_chunk=on_chunk,
                           blocks=iter_file_blocks(path))


@record(frozen=True)
class CheckedFile:
    """What checking a file found out: its subs, which lines are not plain (for the run's reader), how many lines."""

    subs: dict[str, n.Sub]
    non_plain: Sequence[int]
    lines: int = 0


def check_file(path: str | os.PathLike[str], name: str | None = None,
               on_chunk: Callable[[list[str]], None] | None = None,
               on_statement: Callable[[n.Stmt], None] | None = None) -> CheckedFile:
    """Read a whole file without keeping its plain lines: raise SyntaxErrors if anything is wrong.

    ``on_chunk`` sees the lines as they are read (see StatementReader), so nothing else need read them;
    ``on_statement`` sees each top-level statement that is not a plain line (the debugger's breakpoint lines).
    """
    reader = read_statements(path, mode="check", name=name, on_chunk=on_chunk)
    subs: dict[str, n.Sub] = {}
    for stmt in reader:
        if on_statement is not None:
            on_statement(stmt)
        if isinstance(stmt, n.Sub):
            subs.setdefault(stmt.name.lower(), stmt)
    reader.raise_errors()
    return CheckedFile(subs, reader.non_plain, reader.lines)


def parse_text(text: str, path: str = "<string>") -> n.Program:
    """Parse a whole string; raises SyntaxErrors listing every error found."""
    return _collect(StatementReader(iter_text_lines(text), path))


def parse_file(path: str | os.PathLike[str], *, check_dialogs: bool = False) -> n.Program:
    """Parse a whole file; raises SyntaxErrors listing every error found (with ``check_dialogs``
    also the dlgmsg shapes the controller refuses, G1167)."""
    return _collect(read_statements(path, check_dialogs=check_dialogs))


def _collect(reader: StatementReader) -> n.Program:
    body = tuple(reader)
    reader.raise_errors()
    return n.Program(reader.path, body, reader.unit)
