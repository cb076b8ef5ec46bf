"""Breakpoints: where the run stops, and on which condition.

A source breakpoint is verified against the statements of its file: it moves to the next line a
statement starts on, or is refused with the reason.  Conditions and log
messages are the dialect's expressions (``expressions``); a hit condition is ``N`` or ``== N``
(the Nth hit), ``>= N``, ``> N`` or ``% N`` (every Nth hit).  A function breakpoint names a Sub,
``M6`` (the tool-change sub) or a user M code (``M100``).
"""
from __future__ import annotations

import os
import re
import stat
from bisect import bisect_left
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from operator import itemgetter
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.errors import EcncError
from edingcnc_lang.records import record
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.syntax.parser import read_statements
from edingcnc_lang.debug.expressions import ExpressionError, evaluate, interpolate, parse_expression

if TYPE_CHECKING:
    from edingcnc_lang.run_records import CheckedJob
    from edingcnc_lang.runner import Run

HIT = re.compile(r"\s*(==|>=|>|%)?\s*([0-9]{1,9})\s*$")  # a count past 999,999,999 is never reached


def file_key(path: str) -> str:
    """One spelling per file, whatever the editor or the run calls it."""
    return os.path.normcase(os.path.realpath(path))


@dataclass
class Breakpoint:
    """One breakpoint as the client set it, verified; ``hits`` counts the times it was reached."""

    id: int
    line: int
    verified: bool
    message: str | None = None
    condition: n.Expr | None = None
    hit: tuple[str, int] | None = None
    log: str | None = None
    hits: int = 0

    def to_json(self, path: str | None = None) -> dict[str, object]:
        body: dict[str, object] = {"id": self.id, "verified": self.verified, "line": self.line}
        if path:
            body["source"] = {"path": path}
        if self.message:
            body["message"] = self.message
        return body


@record(frozen=True)
class Decision:
    """What reaching a breakpoint means: stop, print a log line, or neither."""

    stop: bool = False
    log: str | None = None


@dataclass
class Breakpoints:
    """Every breakpoint of the session; the observer asks ``at(path, line)`` before a statement."""

    by_file: dict[str, dict[int, Breakpoint]] = field(default_factory=dict)
    functions: dict[str, Breakpoint] = field(default_factory=dict)  # sub name (lower case) -> breakpoint
    _next_id: int = 0
    _keys: dict[str, str] = field(default_factory=dict)  # the run's path spelling -> file_key

    def new_id(self) -> int:
        self._next_id += 1
        return self._next_id

    def set_source(self, path: str, specs: Iterable[dict[str, object]]) -> list[Breakpoint]:
        """Replace the breakpoints of one file with ``specs`` (DAP SourceBreakpoint objects)."""
        key = file_key(path)
        known = file_facts(key)
        placed: dict[int, Breakpoint] = {}
        answer = []
        for spec in specs:
            bp = self._make(spec)
            wanted = int(spec.get("line", 0))  # type: ignore[call-overload]
            if isinstance(known, str):
                bp.line, bp.verified, bp.message = wanted, False, known
            else:
                line = known.first_at(wanted)
                if line is None:
                    bp.line, bp.verified = wanted, False
                    bp.message = f"no statement on or after line {wanted} is ever executed"
                else:
                    bp.line = line
            if bp.verified and bp.line in placed:
                bp.verified, bp.message = False, f"line {bp.line} already has a breakpoint"
            if bp.verified:
                placed[bp.line] = bp
            answer.append(bp)
        if placed:
            self.by_file[key] = placed
        else:
            self.by_file.pop(key, None)
        return answer

    def set_functions(self, specs: Iterable[dict[str, object]],
                      subs: dict[str, tuple[str, int]]) -> list[Breakpoint]:
        """Replace the function breakpoints; ``subs`` maps each known sub name to where it is defined
        (its file and the line of its ``Sub``, which the breakpoint reports)."""
        self.functions = {}
        answer = []
        for spec in specs:
            bp = self._make(spec)
            name = sub_of(str(spec.get("name", "")))
            if name not in subs:
                bp.verified = False
                bp.message = f"no Sub {name} in the job or the macro files"
            else:
                bp.line = subs[name][1]
                if bp.verified:
                    self.functions[name] = bp
            answer.append(bp)
        return answer

    def _make(self, spec: dict[str, object]) -> Breakpoint:
        bp = Breakpoint(self.new_id(), int(spec.get("line", 0) or 0), True)  # type: ignore[call-overload]
        try:
            if spec.get("condition"):
                bp.condition = parse_expression(str(spec["condition"]))
            if spec.get("hitCondition"):
                match = HIT.match(str(spec["hitCondition"]))
                if match is None:
                    shown = str(spec["hitCondition"])
                    shown = shown if len(shown) <= 40 else shown[:40] + "..."
                    raise ExpressionError(f"hit condition {shown!r}: write N, >= N, > N or % N "
                                          "(N up to 999,999,999)")
                bp.hit = (match.group(1) or "==", int(match.group(2)))
        except ExpressionError as err:
            bp.verified, bp.message = False, str(err)
        if spec.get("logMessage"):
            bp.log = str(spec["logMessage"])
        return bp

    def watched(self, path: str) -> dict[int, Breakpoint] | None:
        """The breakpoints of the file the run calls ``path`` (None: none there)."""
        key = self._keys.get(path)
        if key is None:
            key = self._keys[path] = file_key(path)
        return self.by_file.get(key)

    def any_between(self, path: str, first: int, last: int) -> bool:
        lines = self.watched(path)
        return bool(lines) and any(first <= line <= last for line in lines)  # type: ignore[union-attr]


def reached(bp: Breakpoint, evaluator: Evaluator) -> Decision:
    """Count a hit of ``bp`` if its condition holds; stop or log as it says.  A condition that cannot
    be evaluated stops (the user should see why), with the reason as the log line."""
    if bp.condition is not None:
        try:
            if evaluate(evaluator, bp.condition) == 0.0:
                return Decision()
        except ExpressionError as err:
            return Decision(True, f"breakpoint condition: {err}")
    bp.hits += 1
    if bp.hit is not None:
        op, count = bp.hit
        ok = {"==": bp.hits == count, ">=": bp.hits >= count, ">": bp.hits > count,
              "%": count > 0 and bp.hits % count == 0}[op]
        if not ok:
            return Decision()
    if bp.log is not None:
        return Decision(False, interpolate(evaluator, bp.log))
    return Decision(True)


def sub_of(name: str) -> str:
    """The sub a function breakpoint's name means: ``M6`` -> change_tool, ``M100`` -> m100."""
    word = name.strip()
    match = re.fullmatch(r"[Mm]\s*(\d+)", word)
    if match:
        return t.m_code_sub(t.code_key(int(match.group(1)))) or word.lower()
    return word.lower()


@record(frozen=True)
class Facts:
    """What the debugger needs to know of a file: the lines statements start on (``first_at``), its
    subs, and the syntax error that keeps it from running (None if it parses).

    A statement starts on every line but the ``others`` (a job's few lines that are not plain: the
    check lists them), and on those of them in ``starts``: so a 200,000-line job's lines are not
    listed one by one."""

    count: int  # the file's lines
    others: Sequence[int]  # ascending
    starts: tuple[int, ...]  # ascending
    subs: tuple[tuple[str, int], ...]  # (lower-case name, line of its Sub)
    error: EcncError | None = None

    def first_at(self, wanted: int) -> int | None:
        """The first line on or after ``wanted`` that a statement starts on (None: there is none)."""
        line = max(wanted, 1)
        starts = self.starts
        at = bisect_left(starts, line)
        found = [starts[at]] if at < len(starts) else []
        others = self.others
        at = bisect_left(others, line)
        if at < len(others) and others[at] == line:  # past the run of others it starts: others[k] - k
            low, high = at, len(others)  # is the same along a run and grows after it
            while high - low > 1:
                middle = (low + high) // 2
                low, high = (middle, high) if others[middle] - middle == line - at else (low, middle)
            line = others[low] + 1
        if line <= self.count:
            found.append(line)
        return min(found, default=None)


Stamp = tuple[int, int]  # a file's version: its modification time (ns) and size
_known: dict[str, tuple[Stamp, Facts]] = {}  # file_key -> the Facts of that version (the last 32 files)


def _read(key: str) -> Facts:
    """One read of the file: the run's reader (plain lines listed, not parsed), or for a macro file
    with lines that do not parse, the tolerant reader (those lines wait as BadLine)."""
    error = None
    try:
        reader = read_statements(key, mode="run")
        statements = list(reader)
        reader.raise_errors()
    except EcncError as err:
        error = err
        reader = read_statements(key, tolerant=True)
        statements = list(reader)
        reader.raise_errors()
    subs = tuple((stmt.name.lower(), stmt.span.line) for stmt in statements if isinstance(stmt, n.Sub))
    return Facts(reader.lines, range(1, reader.lines + 1), tuple(sorted(set(_starts(statements, [])))), subs, error)


def _stamp(path: str, key: str) -> Stamp:
    """The version of the file; raises the EcncError of a file that cannot be read."""
    try:
        info = os.stat(key)
    except OSError as err:
        raise EcncError(f"cannot read {path}: {err.strerror}") from None
    if not stat.S_ISREG(info.st_mode):  # a FIFO would block the adapter, a device never end
        raise EcncError(f"cannot read {path}: not a regular file")
    return info.st_mtime_ns, info.st_size


def _remember(key: str, stamp: Stamp, found: Facts) -> Facts:
    _known.pop(key, None)
    if len(_known) >= 32:
        del _known[next(iter(_known))]
    _known[key] = (stamp, found)
    return found


def facts(path: str) -> Facts:
    """The file's Facts, read once per version of it (the launch and the breakpoints share them);
    raises the EcncError of a file that cannot be read or whose blocks do not close."""
    key = file_key(path)
    stamp = _stamp(path, key)
    known = _known.get(key)
    if known is not None and known[0] == stamp:
        return known[1]
    return _remember(key, stamp, _read(key))


@record(frozen=True)
class JobCheck:
    """The launch's check of the job (``Run.check_job``), which the run takes instead of checking the
    job again while the file is the version that was checked."""

    checked: CheckedJob
    path: str
    stamp: Stamp

    def current(self) -> CheckedJob | None:
        """The check, if the file is still the version checked (else the run checks it again)."""
        try:
            return self.checked if _stamp(self.path, file_key(self.path)) == self.stamp else None
        except EcncError:
            return None


def job_facts(run: Run, job: Path) -> tuple[Facts, JobCheck | None]:
    """The job's Facts, taken from the check pass its run needs anyway (a job is read once for both:
    the lines a statement starts on are the plain lines, which the check lists, and those of the
    statements it parses); with the check, for the run.  A job whose check fails is read as ``facts``
    reads a file (its error, if it has one, is the launch's), and the run checks it again."""
    path = str(job)
    key = file_key(path)
    stamp = _stamp(path, key)
    starts: list[int] = []
    subs: list[tuple[str, int]] = []

    def seen(stmt: n.Stmt) -> None:
        if isinstance(stmt, n.Sub):
            subs.append((stmt.name.lower(), stmt.span.line))
        _starts((stmt,), starts)

    try:
        checked = run.check_job(job, on_statement=seen)
    except EcncError:
        return facts(path), None
    file = checked.file
    found = Facts(file.lines, file.non_plain, tuple(sorted(set(starts))), tuple(subs))
    return _remember(key, stamp, found), JobCheck(checked, path, stamp)


def file_facts(key: str) -> Facts | str:
    """The file's Facts, or why they are unknown."""
    try:
        return facts(key)
    except EcncError as err:
        return err.message


def _starts(statements: Iterable[n.Stmt], into: list[int]) -> list[int]:
    """The lines the statements (nested ones included) start on, added to ``into``; a run of plain
    lines adds its line numbers in one step (most of a job)."""
    for stmt in statements:
        if isinstance(stmt, n.Sub):
            _starts(stmt.body, into)
        elif isinstance(stmt, n.If):
            into.append(stmt.span.line)
            _starts(stmt.then, into)
            _starts(stmt.orelse, into)
        elif isinstance(stmt, n.While):
            into.append(stmt.span.line)
            _starts(stmt.body, into)
        elif isinstance(stmt, n.PlainRun):
            into.extend(map(itemgetter(0), stmt.lines))
        else:
            into.append(stmt.span.line)
    return into
