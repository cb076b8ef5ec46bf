"""Coverage of macro files: which lines ran, which If/Else and While branches were taken, which subs
no test reached.

Recording is an ``Observer`` (``machine/observe.py``) on every test's run; what a file *could*
run comes from parsing it the way a run loads it (tolerant: a line that does not parse is still a
line that could be reached).  Lines are the first lines of statements inside subs and at the top
level (not ``Sub``/``EndSub``, ``Else``, ``EndIf``, ``EndWhile``, comments or blank lines); each If
and each While has two branches: then/else (an If without Else still has its "skip" side) and
enter/leave.
"""
from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine.observe import Observer

if TYPE_CHECKING:
    from edingcnc_lang.machine.observe import MachineView
    from edingcnc_lang.machine.state import CallFrame

BRANCH_NAMES = {(n.If, True): "then", (n.If, False): "else", (n.While, True): "enter", (n.While, False): "leave"}


@dataclass
class CoverageData:
    """What the runs reached, keyed by the macro file's real path (a file reached through a symlink
    is still one file); merged across tests and workers."""

    lines: set[tuple[str, int]] = field(default_factory=set)
    branches: set[tuple[str, int, bool]] = field(default_factory=set)
    subs: set[tuple[str, str]] = field(default_factory=set)  # (path, lower-case name)
    files: set[str] = field(default_factory=set)              # the macro files the runs loaded

    def update(self, other: CoverageData) -> None:
        self.lines |= other.lines
        self.branches |= other.branches
        self.subs |= other.subs
        self.files |= other.files


class CoverageObserver(Observer):
    """Records the statements, branches and sub calls of macro files (the job's own are left out)."""

    def __init__(self, data: CoverageData) -> None:
        self.data = data
        self.paths: dict[str, str] = {}  # as spans name a macro file -> its real path (one key per file)

    def watch(self, macro_files: Iterable[str | os.PathLike[str]]) -> None:
        """The run's macro files (``Run.macro_files()``), named as their statements' spans name them."""
        self.paths = {os.fspath(p): os.path.realpath(p) for p in macro_files}
        self.data.files |= set(self.paths.values())

    def statement(self, machine: MachineView, stmt: n.Stmt) -> None:
        real = self.paths.get(machine.path)
        if real is not None:
            self.data.lines.add((real, stmt.span.line))

    def branch(self, machine: MachineView, stmt: n.If | n.While, taken: bool) -> None:
        real = self.paths.get(stmt.span.path)
        if real is not None:
            self.data.branches.add((real, stmt.span.line, taken))

    def call(self, machine: MachineView, frame: CallFrame, sub: n.Sub) -> None:
        real = self.paths.get(sub.span.path)
        if real is not None:
            self.data.subs.add((real, sub.name.lower()))

    def line_by_line(self, machine: MachineView, run: n.PlainRun) -> bool:
        """Chunks of plain lines come only from jobs (macro files are read whole), which are not
        measured: keep the fast path."""
        return False


@dataclass(frozen=True)
class Shape:
    """What one macro file could run: statement lines, branch points, subs (name -> line)."""

    lines: frozenset[int]
    branches: tuple[tuple[int, bool, str], ...]  # (line, taken, "then"/"else"/"enter"/"leave")
    subs: dict[str, tuple[str, int]]             # lower-case name -> (name as written, line)
    sub_ends: dict[str, int] = field(default_factory=dict)  # lower-case name -> the line of its EndSub


def shape_of(path: str) -> Shape:
    """Parse a macro file as a run loads it and list what could run in it."""
    from edingcnc_lang.syntax.parser import read_statements

    reader = read_statements(path, tolerant=True)
    body = tuple(reader)
    lines: set[int] = set()
    branches: list[tuple[int, bool, str]] = []
    subs: dict[str, tuple[str, int]] = {}
    ends: dict[str, int] = {}
    for stmt in body:
        if isinstance(stmt, n.Sub):
            subs.setdefault(stmt.name.lower(), (stmt.name, stmt.span.line))
            ends.setdefault(stmt.name.lower(), stmt.end_span.line)
            statements = _walk(stmt.body)
        elif isinstance(stmt, n.BadLine):  # prose between subs: a run never executes it
            continue
        else:
            statements = _walk((stmt,))
        for inner in statements:
            lines.add(inner.span.line)
            if isinstance(inner, (n.If, n.While)):
                branches += [(inner.span.line, taken, BRANCH_NAMES[type(inner), taken]) for taken in (True, False)]
    return Shape(frozenset(lines), tuple(branches), subs, ends)


def _walk(body: Iterable[n.Stmt]) -> Iterator[n.Stmt]:
    for stmt in body:
        yield stmt
        if isinstance(stmt, n.If):
            yield from _walk(stmt.then)
            yield from _walk(stmt.orelse)
        elif isinstance(stmt, n.While):
            yield from _walk(stmt.body)


@dataclass(frozen=True)
class FileCoverage:
    """One macro file's figures, as the reports show them."""

    path: str
    lines_total: int
    lines_hit: frozenset[int]
    missed: tuple[int, ...]
    branches_total: int
    branches_hit: int
    branches_missed: tuple[tuple[int, str], ...]  # (line, "then"/"else"/"enter"/"leave")
    subs_never_run: tuple[str, ...]
    branches: tuple[tuple[int, str, bool], ...] = ()  # every branch: (line, name, taken), for LCOV and Cobertura
    subs: tuple[tuple[str, int, bool], ...] = ()       # every sub: (name as written, line, run)
    sub_ends: tuple[int, ...] = ()                     # the line of each sub's EndSub, in the order of ``subs``

    def missed_by_sub(self) -> list[tuple[str | None, tuple[int, ...]]]:
        """The lines not run of the subs that ran (and of the top level, None), sub by sub in file
        order: a sub no test ran is all missed and named in ``subs_never_run`` instead."""
        spans = [(name, first, last) for (name, first, run), last in zip(self.subs, self.sub_ends) if run]
        never = [(first, last) for (_name, first, run), last in zip(self.subs, self.sub_ends) if not run]
        groups: dict[str | None, list[int]] = {}
        for line in self.missed:
            if any(first <= line <= last for first, last in never):
                continue
            owner = next((name for name, first, last in spans if first <= line <= last), None)
            groups.setdefault(owner, []).append(line)
        return [(name, tuple(lines)) for name, lines in groups.items()]

    def to_json(self) -> dict[str, object]:
        return {"lines": {"total": self.lines_total, "hit": len(self.lines_hit), "missed": list(self.missed)},
                "branches": {"total": self.branches_total, "hit": self.branches_hit,
                             "missed": [{"line": line, "branch": name} for line, name in self.branches_missed]},
                "subs_never_run": list(self.subs_never_run)}


def summarise(data: CoverageData) -> list[FileCoverage]:
    """Per macro file the runs loaded, in path order."""
    report = []
    for path in sorted(data.files):
        if not Path(path).is_file():
            continue
        shape = shape_of(path)
        hit = frozenset(line for p, line in data.lines if p == path) & shape.lines
        taken = {(line, way) for p, line, way in data.branches if p == path}
        called = {name for p, name in data.subs if p == path}
        report.append(FileCoverage(
            path=display_path(path), lines_total=len(shape.lines), lines_hit=hit,
            missed=tuple(sorted(shape.lines - hit)), branches_total=len(shape.branches),
            branches_hit=sum((line, way) in taken for line, way, _ in shape.branches),
            branches_missed=tuple((line, name) for line, way, name in shape.branches if (line, way) not in taken),
            subs_never_run=tuple(written for key, (written, _line) in sorted(shape.subs.items(), key=lambda i: i[1][1])
                                 if key not in called),
            branches=tuple((line, name, (line, way) in taken) for line, way, name in shape.branches),
            subs=tuple((written, line, key in called)
                       for key, (written, line) in sorted(shape.subs.items(), key=lambda i: i[1][1])),
            sub_ends=tuple(shape.sub_ends.get(key, line)
                           for key, (_written, line) in sorted(shape.subs.items(), key=lambda i: i[1][1]))))
    return report


def display_path(path: str) -> str:
    """A path as reports show it: relative to the current folder when it lies below it."""
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative
