"""Watching a run statement by statement: the seam the debugger and macro coverage build on.

An ``Observer`` is handed to ``RunOptions.observer``; the interpreter calls it before every
statement it executes, at every If/While decision and around every sub call.  The base class
does nothing, so an observer overrides only what it needs.  An observer may block (a debugger
waiting for the user) and may read or write the machine it is shown; it must not run
statements itself.  Without an observer the interpreter pays one ``is None`` test per call.

Plain lines of the job reach the interpreter in chunks (``n.PlainRun``) that the bulk path
executes without building nodes; ``line_by_line`` decides whether a chunk is instead executed
one statement at a time, so that ``statement`` sees each of its lines (the cost is the general
path's speed for that chunk).
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n

if TYPE_CHECKING:
    from edingcnc_lang.machine.state import CallFrame, MachineState


class Observer:
    """Hooks called by the interpreter as it runs; every one is optional (the base does nothing)."""

    def statement(self, machine: MachineState, stmt: n.Stmt) -> None:
        """Before ``stmt`` executes; ``machine.path``/``machine.line`` are already its place."""

    def branch(self, machine: MachineState, stmt: n.If | n.While, taken: bool) -> None:
        """An If chose its then-part (True) or its else-part (False); a While's condition was
        evaluated: True enters (or repeats) the body, False leaves the loop."""

    def call(self, machine: MachineState, frame: CallFrame, sub: n.Sub) -> None:
        """A sub is entered (GoSub, M6's change_tool, a user M code, ...); ``frame`` is on the stack."""

    def ret(self, machine: MachineState, frame: CallFrame) -> None:
        """A sub returned, normally or by an error; ``frame`` is still on the stack."""

    def line_by_line(self, machine: MachineState, run: n.PlainRun) -> bool:
        """Whether this chunk of plain lines runs statement by statement (default: yes)."""
        return True
