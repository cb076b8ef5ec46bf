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
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import lru_cache
from operator import itemgetter

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.errors import EcncError
from edingcnc_lang.machine.evaluator import Evaluator
from edingcnc_lang.syntax.parser import read_statements
from edingcnc_lang.debug.expressions import ExpressionError, evaluate, interpolate, parse_expression

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


@dataclass
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
        lines = executable_lines(key)
        placed: dict[int, Breakpoint] = {}
        answer = []
        for spec in specs:
            bp = self._make(spec)
            wanted = int(spec.get("line", 0))  # type: ignore[call-overload]
            if isinstance(lines, str):
                bp.line, bp.verified, bp.message = wanted, False, lines
            else:
                at = bisect_left(lines, wanted)
                if at == len(lines):
                    bp.line, bp.verified = wanted, False
                    bp.message = f"no statement on or after line {wanted} is ever executed"
                else:
                    bp.line = lines[at]
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


@dataclass(frozen=True)
class Facts:
    """What the debugger needs to know of a file: the lines statements start on, its subs, and the
    syntax error that keeps it from running (None if it parses)."""

    lines: tuple[int, ...]
    subs: tuple[tuple[str, int], ...]  # (lower-case name, line of its Sub)
    error: EcncError | None = None


@lru_cache(maxsize=32)
def _facts(key: str, stamp: float) -> Facts:
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
    return Facts(tuple(sorted(set(_starts(statements, [])))), subs, error)


def facts(path: str) -> Facts:
    """The file's Facts, read once per version of it (the launch and the breakpoints share them);
    raises the EcncError of a file that cannot be read or whose blocks do not close."""
    key = file_key(path)
    try:
        info = os.stat(key)
    except OSError as err:
        raise EcncError(f"cannot read {path}: {err.strerror}") from None
    if not stat.S_ISREG(info.st_mode):  # a FIFO would block the adapter, a device never end
        raise EcncError(f"cannot read {path}: not a regular file")
    return _facts(key, info.st_mtime)


def executable_lines(key: str) -> tuple[int, ...] | str:
    """The lines of a file a statement starts on, or why they are unknown."""
    try:
        return facts(key).lines
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
