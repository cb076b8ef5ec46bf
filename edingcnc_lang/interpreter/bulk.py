"""The bulk path: runs of plain G0/G1 lines executed without building nodes."""
from __future__ import annotations

import math
import re

from .. import nodes as n
from ..canon import AXES
from ..errors import EcncError
from ..line_parser import plain_block, plain_words
from .state import AXIS_INDEX, G_0, G_1, G_91, G_94, MachineState

_NUM = r"([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))[ \t]*"
CAM_LINE = re.compile(r"[ \t]*(?:[Gg][ \t]*" + _NUM + ")?" + "".join(
    f"(?:[{a}{a.lower()}][ \\t]*{_NUM})?" for a in AXES + "F") + r"(?:;.*)?$")


class BulkPath(MachineState):
    """CAM output is mostly such lines; they go to the canon in one ``straight_moves`` call per run."""

    def _exec_plain_run(self, run: n.PlainRun) -> None:
        """Plain lines: straight moves in bulk while they are simple, any other line on its own."""
        lines = run.lines
        done = 0
        while done < len(lines):
            done = self._simple_moves(run.path, lines, done)
            if done < len(lines):
                lineno, text = lines[done]
                self.execute(plain_block(text, run.path, lineno))
                done += 1

    def _exec_plain_lines(self, run: n.PlainRun) -> None:
        """Plain lines one statement at a time, for an observer that watches every line."""
        for lineno, text in run.lines:
            self.execute(plain_block(text, run.path, lineno))

    def _simple_moves(self, path: str, lines: tuple[tuple[int, str], ...], first: int) -> int:
        """Execute lines[first:] as long as each is a plain G0/G1 move; returns the first it left.

        This is the per-line work of ``_exec_plain`` and ``_execute_line`` for the case that
        dominates CAM output (axis words, F, G0/G1, N only; G94; no tangential knife, not on a
        lathe), done without building nodes.  G68 does not stop it: rotation is a later pipeline
        stage that the bulk moves pass through like any other.  Anything unusual, including every error, is left to the
        general path so messages stay exactly the same.
        """
        if self.tanknife or self.clamped or self.tca_guard or self.modal["feed_mode"] != G_94 or self.config.lathe:
            return first  # (a lathe's moves carry the spindle speed along them, which bulk rows do not)
        motion: int | None = self.modal["motion"]
        if motion not in (G_0, G_1):
            motion = None  # the line must name G0 or G1 itself
        scale = self.scale
        offset = self.offset()
        incremental = self.modal["distance"] == G_91
        budget = self.max_steps
        pos = self.pos
        feed = self.feed
        batch: list[tuple[str, int, tuple[float, ...], float]] = []
        feeds: list[float] = []  # the feed in force at each move of the batch
        room = len(lines) if budget is None else budget - self.steps  # statements left in the step budget
        done = 0
        index = first
        for index in range(first, len(lines)):
            if done >= room:
                break
            lineno, text = lines[index]
            line_motion: int | None
            new_feed: float | None
            cam = CAM_LINE.match(text)
            if cam is not None:  # the usual shape: [G0|G1] [X] [Y] [Z] [A] [B] [C] [F], in that order
                g, x, y, z, a, b, c, f = cam.groups()
                if g is not None:
                    g_value = float(g)
                    if g_value != 0.0 and g_value != 1.0:
                        break
                    line_motion = G_0 if g_value == 0.0 else G_1
                else:
                    line_motion = motion
                if line_motion is None:
                    break
                if f is not None:
                    new_feed = float(f) * scale
                    if new_feed < 0:
                        break
                    feed = new_feed
                if x is None and y is None and z is None and a is None and b is None and c is None:
                    done += 1
                    motion = line_motion
                    continue
                base = pos if incremental else offset
                target = list(pos)
                if x is not None:
                    target[0] = base[0] + float(x) * scale
                if y is not None:
                    target[1] = base[1] + float(y) * scale
                if z is not None:
                    target[2] = base[2] + float(z) * scale
                if a is not None:
                    target[3] = base[3] + float(a)
                if b is not None:
                    target[4] = base[4] + float(b)
                if c is not None:
                    target[5] = base[5] + float(c)
            else:
                parsed = self._plain_move_words(text, motion, scale)
                if parsed is None:
                    break
                line_motion, axes, new_feed = parsed
                if line_motion is None:
                    break
                if new_feed is not None:
                    feed = new_feed
                if not axes:
                    done += 1
                    motion = line_motion
                    continue
                base = pos if incremental else offset
                target = list(pos)
                for axis, value in axes:
                    target[axis] = base[axis] + value
            if line_motion == G_1:
                if feed <= 0:
                    break
                batch.append(("linear", lineno, tuple(target), feed))
            else:
                batch.append(("rapid", lineno, tuple(target), 0.0))
            feeds.append(feed)
            pos = target
            done += 1
            motion = line_motion
        else:
            index = len(lines)
        self.steps += done
        if batch:
            self.path, self.line = path, batch[-1][1]
            try:
                self.canon.straight_moves(path, tuple(self.pos), batch)
            except EcncError as err:  # a move was refused: the state is that of the move before it
                failed = next((k for k, item in enumerate(batch)
                               if err.location is not None and item[1] == err.location.line), 0)
                self.job_distance += _travelled(self.pos, batch[:failed])
                if failed:
                    self.pos = list(batch[failed - 1][2])
                self.feed = feeds[failed]
                self.modal["motion"] = G_1 if batch[failed][0] == "linear" else G_0
                self.line = batch[failed][1]
                raise
            self.job_distance += _travelled(self.pos, batch)
        self.pos = list(pos)
        self.feed = feed
        if motion is not None:
            self.modal["motion"] = motion
        return index

    @staticmethod
    def _plain_move_words(text: str, motion: int | None, scale: float
                          ) -> tuple[int | None, list[tuple[int, float]], float | None] | None:
        """A plain line's motion code, axis values and feed, if it is nothing but a straight move."""
        seen: set[str] = set()
        axes: list[tuple[int, float]] = []
        new_feed = None
        for letter, number in plain_words(text):
            letter = letter.upper()
            if letter in seen:
                return None
            seen.add(letter)
            value = float(number)
            axis = AXIS_INDEX.get(letter)
            if axis is not None:
                axes.append((axis, value * scale if axis < 3 else value))
            elif letter == "F" and value >= 0:
                new_feed = value * scale
            elif letter == "G" and (value == 0.0 or value == 1.0):
                motion = G_0 if value == 0.0 else G_1
            elif letter != "N":
                return None
        return motion, axes, new_feed


# The statements this part executes, by method name (machine.py builds the dispatch table).
STATEMENTS = {n.PlainRun: "_exec_plain_run"}


def _travelled(start: list[float], batch: list[tuple[str, int, tuple[float, ...], float]]) -> float:
    """The XYZ length of a batch of straight moves from ``start`` (GetJobDistance counts it)."""
    points = [start[:3], *(end[:3] for _kind, _line, end, _feed in batch)]
    return sum(map(math.dist, points, points[1:]))
