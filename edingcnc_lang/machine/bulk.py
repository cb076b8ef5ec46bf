"""The bulk path: runs of plain G0/G1 lines executed without building nodes, as one ``Batch``.

CAM output is mostly lines such as ``G1 X.. Y.. Z..``.  While the machine is in a state where
such a line can only be a straight move (``batchable``, the one place that decides it), a run of
them is turned into targets by ``plain_moves`` and handed to the canon as one ``Batch``: the
array form of the ``Move`` records the general path would have made, with the same spindle and
caller.  The step budget and GetJobDistance are counted by the general path's own helpers
(``MachineState.travelled``); any other line, and every error, goes to the general path, so
messages stay exactly the same.

``plain_moves`` here is the reference; ``speedups.plain_moves`` is the same function compiled
(``edingcnc_lang/_speedups.c``), used when it is built and ``ECNC_PURE_PYTHON`` is not set.
The equivalence tests run both and compare whole moves with the general path's.
"""
from __future__ import annotations

import re
from collections.abc import Sequence

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang import speedups
from edingcnc_lang.canon import Batch
from edingcnc_lang.errors import EcncError
from edingcnc_lang.syntax.plain_words import FAST_NUMBER, plain_block, plain_words
from edingcnc_lang.machine.state import G_0, G_1, G_91, G_94, MachineState, StatementTable

NO_MOTION = -1  # the motion in force is neither G0 nor G1: a line must name one itself
# The usual order of a CAM line's words, [N] [G] [X] [Y] [Z] [A] [B] [C] [F]; the words are
# line_parser's (FAST_NUMBER), so it reads a line as plain_words would, only faster.  Each
# optional word is "(?:...|)", which Python's engine runs faster than "(?:...)?".
_VALUE = rf"([+-]?{FAST_NUMBER})[ \t]*"
_USUAL = (rf"[ \t]*(?:[Nn][ \t]*[+-]?{FAST_NUMBER}[ \t]*|)"
          + "".join(f"(?:[{a}{a.lower()}][ \\t]*{_VALUE}|)" for a in "GXYZABCF") + r"(?:;.*|)")
USUAL_ORDER = re.compile(_USUAL + "$")
_WORD_COLUMN = {letter: column for column, letter in enumerate("GXYZABCF")}

# What plain_moves returns: the index of the first line it left, the steps it took (lines it
# consumed), the motion and feed in force after them, and the moves as columns: kinds, line
# numbers, end points, feeds (0 for rapids) and the feed in force at each move.
Scanned = tuple[int, int, int, float, list[str], list[int], list[tuple[float, ...]], list[float], list[float]]


def plain_moves(lines: Sequence[tuple[int, str]], first: int, pos: Sequence[float], offset: Sequence[float],
                scale: float, incremental: bool, motion: int, feed: float, room: int) -> Scanned:
    """Targets of lines[first:] while each is a plain straight move: the batch form of a line's steps.

    A line may hold G0/G1, X Y Z A B C, F and N words, each once, and nothing else; F >= 0; a G1
    needs a feed.  Axis values are scaled by ``scale`` (inch) on X Y Z; a target is the position
    plus the value under G91, the work offset plus it under G90, as the general path's
    ``_target``.  It stops at the first other line, or after ``room`` lines (the step budget).
    """
    kinds: list[str] = []
    numbers: list[int] = []
    ends: list[tuple[float, ...]] = []
    feeds: list[float] = []
    in_force: list[float] = []
    position = tuple(pos)
    done = 0
    for lineno, text in lines[first:first + max(room, 0)]:
        usual = USUAL_ORDER.match(text)
        row = usual.groups() if usual is not None else _words_row(text)
        if row is None:
            break
        g, x, y, z, a, b, c, f = row  # the number texts, empty or None where the line has no such word
        line_motion, new_feed = motion, feed
        if g:
            value = float(g)
            if value != 0.0 and value != 1.0:
                break
            line_motion = G_0 if value == 0.0 else G_1
        if f:
            value = float(f)
            if value < 0:
                break
            new_feed = value * scale
        if line_motion == NO_MOTION:
            break
        if x or y or z or a or b or c:
            if line_motion == G_1:
                if new_feed <= 0:
                    break
                kinds.append("linear")
                feeds.append(new_feed)
            else:
                kinds.append("rapid")
                feeds.append(0.0)
            base = position if incremental else offset
            position = (base[0] + float(x) * scale if x else position[0],
                        base[1] + float(y) * scale if y else position[1],
                        base[2] + float(z) * scale if z else position[2],
                        base[3] + float(a) if a else position[3],
                        base[4] + float(b) if b else position[4],
                        base[5] + float(c) if c else position[5])
            numbers.append(lineno)
            ends.append(position)
            in_force.append(new_feed)
        motion, feed = line_motion, new_feed
        done += 1
    return first + done, done, motion, feed, kinds, numbers, ends, feeds, in_force


def _words_row(text: str) -> list[str] | None:
    """The G X Y Z A B C F number texts of a line whose words are in another order ('' where it
    has no such word); None when it has another word (but N) or one twice."""
    row = [""] * 8
    seen = ""
    for letter, number in plain_words(text):
        letter = letter.upper()
        if letter in seen or (letter not in _WORD_COLUMN and letter != "N"):
            return None
        seen += letter
        if letter != "N":
            row[_WORD_COLUMN[letter]] = number
    return row


class BulkPath(MachineState):
    """Runs of plain lines: straight moves in bulk while they are simple, any other line on its own."""

    def _exec_plain_run(self, run: n.PlainRun) -> None:
        """Plain lines: straight moves in bulk while they are simple, any other line on its own."""
        lines = run.lines
        done = 0
        while done < len(lines):
            if self.batchable():
                done = self._simple_moves(run.path, lines, done)
            if done < len(lines):
                lineno, text = lines[done]
                self.execute(plain_block(text, run.path, lineno))
                done += 1

    def _exec_plain_lines(self, run: n.PlainRun) -> None:
        """Plain lines one statement at a time, for an observer that watches every line."""
        for lineno, text in run.lines:
            self.execute(plain_block(text, run.path, lineno))

    def batchable(self) -> bool:
        """Whether a plain G0/G1 line can only be a straight move now, so it may go in a batch.

        Not with a tangential knife (it turns C), clamped rotary axes or TCAGuard (refusals per
        move), not outside G94 (the feed depends on the move), not under G96 (the speed follows
        X), not on a lathe (X words are diameters there).  G68, G51, G41/G42 and ZHC do not stop
        it: they are later pipeline stages, which take batches too.
        """
        return not (self.tanknife or self.clamped or self.tca_guard or self.modal["feed_mode"] != G_94
                    or self.css_setting is not None or self.config.lathe)

    def _simple_moves(self, path: str, lines: tuple[tuple[int, str], ...], first: int) -> int:
        """Execute lines[first:] as long as each is a plain G0/G1 move; returns the first it left."""
        motion = self.modal["motion"]
        budget = self.max_steps
        room = len(lines) if budget is None else budget - self.steps  # statements left in the step budget
        index, done, motion, feed, kinds, numbers, ends, feeds, in_force = speedups.plain_moves(
            lines, first, self.pos, self.offset(), self.scale, self.modal["distance"] == G_91,
            motion if motion in (G_0, G_1) else NO_MOTION, self.feed, room)
        self.steps += done
        if numbers:
            rpm, _css = self.spindle_along()
            self.path, self.line = path, numbers[-1]
            try:
                self.canon.straight_moves(Batch(path, tuple(self.pos), kinds, numbers, ends, feeds,
                                                rpm, None, 0.0, self.caller()))
            except EcncError as err:  # a move was refused: the state is that of the move before it
                failed = next((k for k, number in enumerate(numbers)
                               if err.location is not None and number == err.location.line), 0)
                self.travelled(self.pos, ends[:failed])
                if failed:
                    self.pos = list(ends[failed - 1])
                self.feed = in_force[failed]
                self.modal["motion"] = G_1 if kinds[failed] == "linear" else G_0
                self.line = numbers[failed]
                raise
            self.travelled(self.pos, ends)
            self.pos = list(ends[-1])
        self.feed = feed
        if motion != NO_MOTION:
            self.modal["motion"] = motion
        return index


# The statements this part executes (machine.py builds the dispatch table from every part's).
STATEMENTS: StatementTable = {n.PlainRun: BulkPath._exec_plain_run}
