"""Names for numbered variables, found where authors already write them.

Sources, strongest first (``SOURCES``): an explicit annotation or sidecar entry
(``convention.py``), the label a ``dlgmsg`` shows beside the field (``"pitch" 1554``), the comment
on an assignment (``#1700 = 0 ;; Z1``), a header comment that lists numbers (``;; #2001 = cutting
speed``, ``;[5012] actual tool X offset``, ``; #4507 sensor position X``), and the manual for system
variables (``kinds.manual_name``).  Every candidate is kept with its file, line and sub, so the
linter can see two subs name one number differently; the map shows the strongest.
"""
from __future__ import annotations

import re
from bisect import bisect_right
from collections.abc import Iterable, Iterator, Mapping, Sequence

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.records import record
from edingcnc_lang.machine.tables import FIRST_PARAM, LAST_PARAM
from edingcnc_lang.varmap import convention
from edingcnc_lang.varmap.kinds import manual_name

ANNOTATION, DLGMSG, COMMENT, HEADER, MANUAL = "annotation", "dlgmsg", "comment", "header", "manual"
SOURCES = (ANNOTATION, DLGMSG, COMMENT, HEADER, MANUAL)  # precedence: the first wins
_RANK = {source: rank for rank, source in enumerate(SOURCES)}
_LONGEST = 80  # a comment longer than this is prose, not a name
_LONGEST_RANGE = 100  # ``; #5001-#5006 ...`` names each number of a range this long at most

# A comment line that starts by naming a number: ``; #4507 text``, ``;; #1500 = 1 ;; Z1``,
# ``;[5012] text``, ``; #5061-#5066 text``.
_HEADER = re.compile(r"^\s*;+\s*(?:#(?P<a>\d{1,4})(?:\s*-\s*#(?P<b>\d{1,4})|\s*\.\.\s*#?(?P<d>\d{1,4}))?"
                     r"|\[(?P<c>\d{1,4})\])"
                     r"(?![\d.\]])\s*(?P<rest>.*)$")
_VALUE = re.compile(r"^=\s*[-+]?[\d.]+\s*;+\s*(?P<text>.*)$")  # ``= 12 ;; diameter A``
_COMMENT = re.compile(r";+\s*(?P<semi>.*)$|\((?P<paren>[^)]*)\)\s*$")
_LETTER = re.compile(r"[^\W\d_]")
_NUMBERS = re.compile(r"#\s*(\d+)")  # the numbers an assignment's value reads
# a line that starts by assigning a number
_ASSIGNMENT = re.compile(r"\s*(?:/\s*)?(?:N\d+\s+)?#(\d+)\s*=(?!=)", re.IGNORECASE)
_TARGETS = re.compile(r"#\s*\[?\s*[\d#]+\s*\]?\s*=(?!=)")  # every assignment on a line


@record(frozen=True)
class Candidate:
    """One name a source gives ``#number``, and where."""

    number: int
    name: str
    source: str  # one of SOURCES
    path: str
    line: int
    col: int
    sub: str | None  # the sub the name is written in (None: top level or the sidecar)
    description: str = ""

    @property
    def rank(self) -> int:
        return _RANK[self.source]


@record(frozen=True, eq=False)
class Source:
    """What one file's names are read from: its lines, its dialogs with the sub each is in, and its
    subs' lines.  ``source_of`` walks a syntax tree for them; the linter hands over the dialogs its
    own walk already found (``lint.project``)."""

    path: str
    lines: Sequence[str]
    dialogs: Sequence[tuple[n.Dialog, str | None]]
    subs: Sequence[tuple[int, int, str]]  # (first line, last line, name) of each Sub, in line order


def source_of(path: str, lines: Sequence[str], body: Sequence[n.Stmt]) -> Source:
    """The dialogs and subs of a syntax tree."""
    dialogs = [(stmt, sub) for stmt, sub in statements(body) if isinstance(stmt, n.Dialog)]
    return Source(path, lines, dialogs, sub_lines(body))


def sub_lines(body: Sequence[n.Stmt]) -> list[tuple[int, int, str]]:
    """(first line, last line, name) of each Sub of a file."""
    return [(s.span.line, s.end_span.line or s.span.line, s.name) for s in body if isinstance(s, n.Sub)]


class Names:
    """Every candidate name of every number in a set of files, and the problems of their annotations."""

    def __init__(self, files: Iterable[Source], sidecars: Iterable[str] = ()) -> None:
        self.candidates: dict[int, list[Candidate]] = {}
        self.problems: list[convention.Problem] = []
        for path in dict.fromkeys(sidecars):
            self._explicit(convention.sidecar(path), None)
        for source in files:
            self._explicit(convention.annotations_in(source.path, source.lines), _SubLines(source.subs))
            for candidate in _inferred(source):
                self.candidates.setdefault(candidate.number, []).append(candidate)
        for found in self.candidates.values():
            found.sort(key=lambda c: c.rank)  # stable: in file order within a source

    def _explicit(self, found: Iterable[convention.Explicit | convention.Problem], subs: _SubLines | None) -> None:
        for item in found:
            if isinstance(item, convention.Problem):
                self.problems.append(item)
            elif (other := self._explicit_name(item.number)) is not None and other.name != item.name:
                self.problems.append(convention.Problem(
                    item.path, item.line, item.col,
                    f"#{item.number} is already named {other.name} ({other.path}:{other.line})"))
            else:
                sub = subs.at(item.line) if subs is not None else None
                self.candidates.setdefault(item.number, []).append(Candidate(
                    item.number, item.name, ANNOTATION, item.path, item.line, item.col, sub, item.description))

    def _explicit_name(self, number: int) -> Candidate | None:
        return next((c for c in self.candidates.get(number, ()) if c.source == ANNOTATION), None)

    def best(self, number: int) -> Candidate | None:
        """The name shown for ``#number``: the strongest source's first, else the manual's."""
        found = self.candidates.get(number)
        if found:
            return found[0]
        title = manual_name(number)
        return Candidate(number, title, MANUAL, "", 0, 0, None) if title else None

    def name(self, number: int) -> str | None:
        best = self.best(number)
        return best.name if best is not None else None

    def labelled(self) -> dict[int, str]:
        """Every number some file names (not the manual's), with its name: for the debugger and tests."""
        return {number: found[0].name for number, found in self.candidates.items() if found}


class _SubLines:
    """Which sub a line is in, from the subs' first and last lines."""

    def __init__(self, ranges: Sequence[tuple[int, int, str]]) -> None:
        self.ranges = ranges
        self.firsts = [first for first, _last, _name in ranges]

    def at(self, line: int) -> str | None:
        i = bisect_right(self.firsts, line) - 1
        if i >= 0 and line <= self.ranges[i][1]:
            return self.ranges[i][2]
        return None


def statements(body: Sequence[n.Stmt], sub: str | None = None) -> Iterator[tuple[n.Stmt, str | None]]:
    """Every statement with the name of its sub, nested ones included, in source order."""
    for stmt in body:
        yield stmt, sub
        if isinstance(stmt, n.Sub):
            yield from statements(stmt.body, stmt.name)
        elif isinstance(stmt, n.If):
            yield from statements(stmt.then, sub)
            yield from statements(stmt.orelse, sub)
        elif isinstance(stmt, n.While):
            yield from statements(stmt.body, sub)


def _inferred(source: Source) -> Iterator[Candidate]:
    """The dlgmsg labels, assignment comments and header comments of one file."""
    path, lines = source.path, source.lines
    for dialog, sub in source.dialogs:
        yield from _labels(path, dialog, sub)
    subs = _SubLines(source.subs)
    for lineno, text in enumerate(lines, 1):
        if ";" in text or "(" in text:
            if "=" in text and _ASSIGNMENT.match(text):
                found = _assignment_comment(path, lineno, text, subs)
                if found is not None:
                    yield found
            elif "#" in text or "[" in text:
                yield from _header(path, lineno, text, subs)


def _labels(path: str, dialog: n.Dialog, sub: str | None) -> Iterator[Candidate]:
    """``dlgmsg "title" "label" 27 ...``: each label names the field after it."""
    items = dialog.items
    for label, field in zip(items[1:], items[2:]):
        if isinstance(label, str) and isinstance(field, n.Number) and field.value.is_integer():
            number = int(field.value)
            if FIRST_PARAM <= number <= LAST_PARAM and _LETTER.search(label):
                span = field.span
                yield Candidate(number, label.strip(), DLGMSG, path, span.line, span.col, sub)


def _assignment_comment(path: str, line: int, text: str, subs: _SubLines) -> Candidate | None:
    """``#1700 = 0 ;; Z1``: on a line that assigns one number, the comment names it, unless the line
    updates it from itself (``#5026 = [#5026 + 1] ; next`` says what the line does)."""
    match = _COMMENT.search(text)
    if match is None or "noqa" in text.lower():
        return None
    code = text[:match.start()]
    if len(_TARGETS.findall(code)) != 1:
        return None
    number = int(_ASSIGNMENT.match(text)[1])  # type: ignore[index]
    reads = _NUMBERS.findall(code, code.find("=") + 1)
    if not FIRST_PARAM <= number <= LAST_PARAM or any(int(found) == number for found in reads):
        return None
    comment = _cleaned(match["semi"] if match["semi"] is not None else match["paren"])
    if comment is None:
        return None
    return Candidate(number, comment, COMMENT, path, line, match.start() + 1, subs.at(line))


def _header(path: str, lineno: int, text: str, subs: _SubLines) -> Iterator[Candidate]:
    """A comment line that starts with a number (or a range of them) and says what it holds."""
    match = _HEADER.match(text)
    if match is None:
        return
    rest = match["rest"]
    if rest.startswith("="):
        value = _VALUE.match(rest)
        rest = value["text"] if value else rest[1:]
    name = _cleaned(rest)
    if name is None:
        return
    first = int(match["a"] or match["c"])
    last = int(match["b"] or match["d"] or first)
    if not FIRST_PARAM <= first <= last <= LAST_PARAM or last - first >= _LONGEST_RANGE:
        return
    col = match.start("rest") + 1
    for number in range(first, last + 1):
        yield Candidate(number, name, HEADER, path, lineno, col, subs.at(lineno))


def _cleaned(text: str) -> str | None:
    """A comment as a name: separators trimmed; None when it is empty, code, or prose."""
    text = text.strip().lstrip(";-:=").strip()
    if not text or "#" in text or len(text) > _LONGEST or not _LETTER.search(text):
        return None
    return text


def names_of_paths(paths: Iterable[str], texts: Mapping[str, str] | None = None) -> Names:
    """The names in files read from disk (and in ``texts``: name -> text, a job given as text), with
    the sidecars beside the files: what the debugger and ``ecnc test`` show beside numbers.  A file
    that cannot be read names nothing."""
    from edingcnc_lang.gcpause import whole_trees
    from edingcnc_lang.syntax.parser import StatementReader
    from edingcnc_lang.syntax.source import iter_file_lines, iter_text_lines

    sources: list[tuple[str, list[str]]] = [(name, list(iter_text_lines(text))) for name, text in (texts or {}).items()]
    for path in dict.fromkeys(paths):
        try:
            sources.append((path, list(iter_file_lines(path))))
        except (OSError, UnicodeError):
            continue
    # "lint": the plain word lines at the top level (a job's bulk) come as runs of lines, unparsed (names
    # come from the lines' text, dialogs and subs); the nodes are dropped at once: the collector paused
    with whole_trees():
        files = [source_of(path, lines, tuple(StatementReader(lines, path, mode="lint", tolerant=True)))
                 for path, lines in sources]
    return Names(files, (convention.sidecar_of(path) for path in dict.fromkeys(paths)))


def label(number: int, names: Mapping[int, str]) -> str:
    """``#1552 thread_major_diameter``, or ``#1552`` when nothing names it (messages, the debugger)."""
    name = names.get(number)
    return f"#{number} {name}" if name else f"#{number}"
