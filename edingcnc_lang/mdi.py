"""MDI: one virtual machine that executes typed lines at once, like the controller's MDI line.

``MdiSession`` keeps the machine (position, modal state, offsets, parameters, the subs of the
macro files) from one line to the next.  A line is G-code or a macro statement; a block
(``If``/``While``/``Sub`` ... ``End...``) is given whole once it is closed (``open_blocks`` says
whether more lines are needed); a line that is only an expression or ``#n`` is evaluated, not
run.  Lines are numbered over the whole session, so errors and the trace name the line typed.
"""
from __future__ import annotations

import re
from collections.abc import Iterable
from contextlib import suppress
from dataclasses import dataclass

from edingcnc_lang.canon import Pose
from edingcnc_lang.diagnostics import SyntaxErrors
from edingcnc_lang.errors import EcncError, Interrupted, Location
from edingcnc_lang.syntax.nodes import Block
from edingcnc_lang.syntax.parser import parse_text
from edingcnc_lang.runner import Run, RunOptions

MDI_PATH = "<mdi>"
_VALUE_OF = "#1 = ["  # an expression line is evaluated as the value of this assignment (then "]")

# The first word of a line that opens (+1) or closes (-1) a block; Else neither.
BLOCK_WORDS = {"if": 1, "while": 1, "sub": 1, "endif": -1, "endwhile": -1, "endsub": -1}
_FIRST_WORD = re.compile(r"\s*(?:N\d+\s*)?([A-Za-z]+)")


def open_blocks(lines: Iterable[str]) -> int:
    """How many blocks the lines leave open (0: the text is complete and can run)."""
    depth = 0
    for line in lines:
        match = _FIRST_WORD.match(line)
        if match:
            depth += BLOCK_WORDS.get(match.group(1).lower(), 0)
    return max(depth, 0)


@dataclass(frozen=True)
class MdiOutcome:
    """What one executed text did: its value (an expression alone), or whether the machine moved."""

    value: float | None
    moved: bool
    position: Pose  # work coordinates (mm, degrees) as #5001.. read them: X a diameter in diameter mode
    machine: Pose   # machine coordinates
    ended: bool     # M2 or M30 ended "the program"; the machine stays as it is


class MdiSession:
    """A machine for typed lines, configured as a run is (``RunOptions``: ini, macro files, answers)."""

    def __init__(self, options: RunOptions | None = None) -> None:
        self._run = Run(options or RunOptions())
        self._interp = self._run.interpreter
        self.lines_read = 0
        macros = self._run.load_macros()
        try:
            self._run.start(macros)
        finally:
            self._flush()

    def execute(self, text: str) -> MdiOutcome:
        """Run ``text`` (one line, or a closed block); raises ``EcncError`` as a run would."""
        first = self.lines_read + 1
        self.lines_read += text.count("\n") + 1
        source = "\n" * (first - 1) + text  # so spans carry the session's line numbers
        try:
            program = parse_text(source, MDI_PATH)
        except SyntaxErrors:
            value = self._value(text, first)
            if value is None:
                raise
            return self._outcome(value, moved=False, ended=False)
        self._interp.define_subs(program.subs.values())
        moves = self._run.motion.moves
        try:
            ended = not self._interp.run(program.body)
        except BaseException:
            with suppress(EcncError, OSError):
                self._flush()
            raise
        self._flush()
        return self._outcome(None, self._run.motion.moves != moves, ended)

    def interrupted(self) -> Interrupted:
        """The error for Ctrl-C while a line ran: it names the line reached."""
        return Interrupted("interrupted (Ctrl-C)", Location(self._interp.path, self._interp.line))

    def close(self) -> None:
        """Flush and close what the session writes (a trace, samples)."""
        self._flush()
        self._run.motion.close()

    def _value(self, text: str, line: int) -> float | None:
        """The value of ``text`` if it is only an expression (``#5001``, ``[2 * SIN[30]]``), else None."""
        try:
            program = parse_text("\n" * (line - 1) + f"{_VALUE_OF}{text}]", MDI_PATH)
        except SyntaxErrors:
            return None
        block = program.body[0] if len(program.body) == 1 else None
        if not isinstance(block, Block) or block.words or len(block.assigns) != 1:
            return None
        try:
            return self._interp.evaluator.value(block.assigns[0].value)
        except EcncError as err:  # its column in the line as typed, not in the wrapped one
            where = err.location
            if where is not None and where.line == line and where.col > len(_VALUE_OF):
                err.location = Location(where.path, where.line, where.col - len(_VALUE_OF))
            raise

    def _outcome(self, value: float | None, moved: bool, ended: bool) -> MdiOutcome:
        position = tuple(self._interp.reported_position())  # X a diameter on a diameter lathe, as #5001
        return MdiOutcome(value, moved, position, self._run.machine_position(), ended)

    def _flush(self) -> None:
        self._run.pipeline.flush()
