"""Watching a run statement by statement: the seam the debugger and macro coverage build on.

An ``Observer`` is handed to ``RunOptions.observer``; the interpreter calls it before every
statement it executes, at every If/While decision and around every sub call.  The base class
does nothing, so an observer overrides only what it needs.  An observer may block (a debugger
waiting for the user); it is shown a ``MachineView``, not the machine: what it may read (where
the run is, the call stack, the position, the variables, expressions' values) and the two
changes a debugger makes, each a method (a variable set by the user, the folder of the run's
files).  It must not run statements itself.  Without an observer the interpreter pays one
``is None`` test per call.

Plain lines of the job reach the interpreter in chunks (``n.PlainRun``) that the bulk path
executes without building nodes; ``line_by_line`` decides whether a chunk is instead executed
one statement at a time, so that ``statement`` sees each of its lines (the cost is the general
path's speed for that chunk).
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n

if TYPE_CHECKING:
    from edingcnc_lang.machine.evaluator import Evaluator
    from edingcnc_lang.machine.parts import CallFrame
    from edingcnc_lang.machine.state import MachineState


class MachineView:
    """The machine as an observer sees it: read-only, but for the two methods that say what they change."""

    __slots__ = ("_machine",)

    def __init__(self, machine: MachineState) -> None:
        self._machine = machine

    @property
    def path(self) -> str:
        """The file of the statement being executed."""
        return self._machine.path

    @property
    def line(self) -> int:
        """Its line."""
        return self._machine.line

    @property
    def steps(self) -> int:
        """Statements, loop turns and holes executed so far (the step budget's count)."""
        return self._machine.budget.steps

    @property
    def stack(self) -> Sequence[CallFrame]:
        """The sub calls in progress, outermost first (each frame is where its call was made)."""
        return self._machine.flow.stack

    @property
    def position(self) -> tuple[float, ...]:
        """Machine coordinates x y z a b c (mm, degrees)."""
        return tuple(self._machine.pos)

    def variable(self, index: int) -> float:
        """Parameter ``#index`` now."""
        return self._machine.params.read(index)

    @property
    def evaluator(self) -> Evaluator:
        """Values of the dialect's expressions against the variables now (it reads, never writes)."""
        return self._machine.evaluator

    def set_variable(self, index: int, value: float) -> None:
        """Write ``#index`` as a statement would (the debugger's setVariable, replayed on a re-run)."""
        self._machine.params.write(index, value)

    def move_files(self, scratch: Path, folder: Path) -> None:
        """From here on the run's files (logfile, ZHCS) go to ``folder``, and a log file opened under
        ``scratch`` (a debugger's re-run wrote there) is written at its place under ``folder``."""
        self._machine.move_files(scratch, folder)


class Observer:
    """Hooks called by the interpreter as it runs; every one is optional (the base does nothing)."""

    def statement(self, machine: MachineView, stmt: n.Stmt) -> None:
        """Before ``stmt`` executes; ``machine.path``/``machine.line`` are already its place."""

    def branch(self, machine: MachineView, stmt: n.If | n.While, taken: bool) -> None:
        """An If chose its then-part (True) or its else-part (False); a While's condition was
        evaluated: True enters (or repeats) the body, False leaves the loop."""

    def call(self, machine: MachineView, frame: CallFrame, sub: n.Sub) -> None:
        """A sub is entered (GoSub, M6's change_tool, a user M code, ...); ``frame`` is on the stack."""

    def ret(self, machine: MachineView, frame: CallFrame) -> None:
        """A sub returned, normally or by an error; ``frame`` is still on the stack."""

    def line_by_line(self, machine: MachineView, run: n.PlainRun) -> bool:
        """Whether this chunk of plain lines runs statement by statement (default: yes)."""
        return True
