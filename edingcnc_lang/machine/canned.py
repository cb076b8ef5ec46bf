"""Canned cycles (G73, G81..G89): sticky words, levels and holes; cycles.py expands each hole.

The concern's state is one record, ``parts.CycleState`` (``machine.cycle``): what a cycle keeps from line
to line and the straight moves it holds back to hand on as one batch.  A run of lines that only
name the next hole (``X.. Y..`` under G81) is drilled in bulk (``hole_run``): the first line takes
the general path, then, while nothing the bulk form does not model is in force, the levels are
worked out once and the holes' moves read from the lines' text in one go (``hole_runs.hole_moves``).
"""
from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from functools import cache
from types import ModuleType
from typing import TYPE_CHECKING, Any, NamedTuple

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang import speedups
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES, PLANES
from edingcnc_lang.errors import MachineError
from edingcnc_lang.events import DwellEvent, PauseEvent, SpindleEvent
from edingcnc_lang.syntax.plain_words import plain_block
from edingcnc_lang.machine.hole_runs import hole_moves
from edingcnc_lang.machine.state import CENTER_WORDS, G_91, G_93, G_99, MachineState, PLANE_OF, format_value

G_74 = t.code_key(74)
G_87 = t.code_key(87)
_HOLE_MOVES: Callable[..., Any] = speedups.compiled("hole_moves") or hole_moves  # the moves of a run of holes

if TYPE_CHECKING:
    from edingcnc_lang.machine.cycles import Step


@cache
def _cycles() -> ModuleType:
    """cycles.py, loaded when a job first drills (not at start-up), and then at the cost of a call."""
    from edingcnc_lang.machine import cycles

    return cycles


class _Levels(NamedTuple):
    """A cycle line's levels along the drilling axis (work coordinates), before any climb to R."""

    work: list[float]  # where the tool is (work coordinates)
    old: float         # the level the holes start from
    r_level: float
    bottom: float
    feed: float        # mm/min of the feed steps
    repeats: int       # L


class CannedCycles(MachineState):
    """Every hole and peck counts against the step budget."""

    def _cycle(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None:
        """A cycle line's holes; their straight moves go to the canon as one batch where the bulk path's would
        (``batchable``), handed on before any other move or event of the cycle and before an error it meets."""
        if self.cycle.pending is not None or not self.batchable():  # held already (the bulk path's run of holes)
            self._holes(motion, words, span, new_sequence)
            return
        with self.moves_held():
            self._holes(motion, words, span, new_sequence)

    def _levels(self, motion: int, words: Mapping[str, float], span: n.Span | None, new_sequence: bool) -> _Levels:
        """The words of a cycle line checked and made sticky, and its levels; no move yet."""
        cycles = _cycles()
        plane = PLANE_OF[self.modal["plane"]]
        normal = PLANES[plane][2]
        drill = AXES[normal]
        sticky = self.cycle.words
        back_boring = motion == G_87
        shift_letters = CENTER_WORDS[plane]  # G87's I J K: the sideways shift in the plane, K the bored level
        for letter, key in (("R", "R"), (drill, "Z"), ("P", "P"), ("Q", "Q"),
                            *(((shift_letters[0], "I"), (shift_letters[1], "J"), ("K", "K")) if back_boring else ())):
            if letter in words:
                sticky[key] = words[letter]
        if any(a in words for a in "ABC"):
            raise self.fail("canned cycles cannot move rotary axes", span)
        if self.modal["feed_mode"] == G_93:
            raise self.fail("canned cycles are not allowed in inverse time mode (G93)", span)
        self.refuse_with_comp("a canned cycle", span)
        for needed in ("R", "Z"):
            if needed not in sticky:
                raise self.fail(f"{t.code_name('G', motion)} needs {needed if needed == 'R' else drill}", span)
        if back_boring and "K" not in sticky:
            raise self.fail("G87 needs K, the level the back bore ends at (between the bottom and R)", span)
        if motion in cycles.NEEDS_Q and sticky.get("Q", 0) <= 0:
            raise self.fail(f"{t.code_name('G', motion)} needs a peck depth Q greater than 0", span)
        if motion in cycles.NEEDS_SPINDLE and (self.spindle.direction == 5 or self.rpm_at(self.pos[0]) <= 0):
            raise self.fail(f"{t.code_name('G', motion)} needs the spindle turning: program "
                            f"{'M4' if motion == G_74 else 'M3'} with an S word first", span)
        repeats = words.get("L", 1)
        if repeats != int(repeats) or repeats < 1:
            raise self.fail("L (repeat count) must be a whole number of at least 1", span)
        scale = self.scale
        work = self.work_position()
        if new_sequence:  # a new cycle sequence: G98 returns to the level it started from
            self.cycle.initial = work[normal]
        old = work[normal] if self.modal["return_mode"] == G_99 else self.cycle.initial
        incremental = self.modal["distance"] == G_91
        r_level = (old if incremental else 0.0) + sticky["R"] * scale
        bottom = (r_level if incremental else 0.0) + sticky["Z"] * scale
        if r_level < bottom:
            raise self.fail(f"R ({format_value(r_level / scale)}) is below the hole bottom "
                            f"{drill} ({format_value(bottom / scale)})", span)
        feed = self._feed_for(1.0, words, span)
        # G84/G74 (3.6.20.6/7): F is the pitch, mm per spindle revolution, in G94 as in G95
        self.cycle.pitch = self.feed if motion in cycles.TAPPING else 0.0
        return _Levels(work, old, r_level, bottom, feed, int(repeats))

    def _steps(self, motion: int, old: float, r_level: float, bottom: float, span: n.Span | None) -> list[Step]:
        """What the cycle does at each hole from ``old`` (after any climb to R)."""
        cycles = _cycles()
        plane = PLANE_OF[self.modal["plane"]]
        first, second, normal = PLANES[plane]
        scale = self.scale
        sticky = self.cycle.words
        clear = r_level if self.modal["return_mode"] == G_99 else old
        dwell = sticky.get("P", 0.0) / (1000.0 if self.config.g4_in_milliseconds else 1.0)
        extra = sticky.get("Q", 0.0) * scale
        if motion == G_87:
            extra = (r_level if self.modal["distance"] == G_91 else 0.0) + sticky["K"] * scale
            if not bottom <= extra <= r_level:
                raise self.fail(f"G87 K ({format_value(extra / scale)}) must lie between the bottom "
                                f"{AXES[normal]} ({format_value(bottom / scale)}) and R "
                                f"({format_value(r_level / scale)})", span)
            self.cycle.shift = {first: sticky.get("I", 0.0) * scale, second: sticky.get("J", 0.0) * scale}
        try:
            return cycles.CYCLES[motion](r_level, bottom, clear, dwell, extra)
        except cycles.CycleError as err:
            raise self.fail(str(err), span) from None

    def _holes(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None:
        plane = PLANE_OF[self.modal["plane"]]
        first, second, normal = PLANES[plane]
        work, old, r_level, bottom, feed, repeats = self._levels(motion, words, span, new_sequence)
        if old < r_level:  # start below R: climb to R first
            self._cycle_move("rapid", work, normal, r_level, feed)
            old = self.cycle.initial = r_level
        steps = self._steps(motion, old, r_level, bottom, span)
        clear = r_level if self.modal["return_mode"] == G_99 else old
        incremental = self.modal["distance"] == G_91
        scale = self.scale
        hole = list(work)
        cost = repeats * (1 + len(steps))
        room = self.budget.room()
        if room is not None and cost > room:
            self.spend(cost, span)  # L1000000000: the budget error now, not after minutes of drilling
        for _ in range(repeats):
            self.spend(1 + len(steps), span)
            for axis, letter in ((first, AXES[first]), (second, AXES[second])):
                if letter in words:
                    hole[axis] = (hole[axis] + words[letter] * scale) if incremental else words[letter] * scale
            hole[normal] = old
            self._cycle_move("rapid", hole, normal, old, feed)
            if old != r_level:
                self._cycle_move("rapid", hole, normal, r_level, feed)
            self._cycle_steps(steps, hole, normal, feed)
            old = clear

    def hole_run(self, path: str, lines: Sequence[tuple[int, str]], first: int, block: n.PlainBlock) -> int:
        """Lines of holes from ``first`` on (``block`` is its own), if it is one; returns the first line it left
        (``first``: not a hole).  Each stretch starts on the general path, the lines after it go in bulk while
        the levels stay put (``_steady_holes``); all their straight moves go to the canon as one batch, handed
        on before the first other line, or an error, as the canned cycles of one line are."""
        if not self._a_hole(block):
            return first
        index = first
        steady = True  # whether the cycle's state is one the bulk form models (it stays so within the run)
        with self.moves_held():
            while True:
                self.execute(block)
                index += 1
                if steady:
                    taken = self._steady_holes(path, lines, index)
                    steady = taken is not None
                    index = index if taken is None else taken
                if index == len(lines):
                    break
                block = plain_block(lines[index][1], path, lines[index][0])
                if not self._a_hole(block):
                    break
        return index

    def _a_hole(self, block: n.PlainBlock) -> bool:
        """Whether a plain line only drills the next hole of the canned cycle in force (its words are the two
        axes of the cycle's plane): nothing it does can emit an event or be read before the next line runs."""
        if self.modal["motion"] not in t.CANNED_CYCLES or self.observer is not None or not self.batchable():
            return False
        first, second, _ = PLANES[PLANE_OF[self.modal["plane"]]]
        return all(letter in (AXES[first], AXES[second]) for letter, _value, _col in block.words)

    def _steady_holes(self, path: str, lines: Sequence[tuple[int, str]], first: int) -> int | None:
        """The holes of lines[first:] in bulk, as long as each line only names the next hole; returns the first
        line it left.  None, taking none, unless every hole drills the same straight moves at the same levels
        (G73, G81, G83, G85; under G99 the R level reads back as the level the next hole starts from; under G91
        only G98, whose start level stays).  The moves join ``cycle.pending`` as the general path's would, the
        step budget counts each line and hole, and a line the budget cannot pay for is left to the general
        path, which reports it."""
        motion = self.modal["motion"]
        if first >= len(lines):
            return first
        if motion not in _cycles().STRAIGHT:
            return None
        axes = PLANES[PLANE_OF[self.modal["plane"]]]
        normal = axes[2]
        try:
            _work, old, r_level, bottom, feed, _repeats = self._levels(motion, {}, None, False)
            steps = self._steps(motion, old, r_level, bottom, None)
        except MachineError:
            return None  # (cannot happen after a line that drilled: the general path would say it at its line)
        if old < r_level:
            return None
        offset = self.offset()
        if self.modal["return_mode"] == G_99 and (r_level + offset[normal]) - offset[normal] != old:
            return None  # the next hole would start from another level (G91 G99: each hole R deeper)
        per_line = 2 + len(steps)  # the statement, the hole and its steps
        stop = len(lines)
        room = self.budget.room()
        if room is not None:
            stop = min(stop, first + max(0, room // per_line))
        kinds = ["rapid", *(["rapid"] if old != r_level else []),
                 *["rapid" if step.kind == "rapid" else "linear" for step in steps]]
        feeds = [0.0, *([0.0] if old != r_level else []), *[feed if step.kind == "feed" else 0.0 for step in steps]]
        levels = [old, *([r_level] if old != r_level else []), *[step.level for step in steps]]
        index, numbers, ends = _HOLE_MOVES(lines, first, stop, axes, self.pos, offset, self.scale,
                                           self.modal["distance"] == G_91, [level + offset[normal] for level in levels])
        count = index - first
        if count:
            pending = self.cycle.pending
            assert pending is not None  # (hole_run holds the moves)
            pending.kinds += kinds * count
            pending.lines += numbers
            pending.ends += ends
            pending.feeds += feeds * count
            self.budget.steps += count * per_line
            self.path, self.line = path, numbers[-1]
            self.pos = list(ends[-1])
        return index

    def _cycle_move(self, kind: str, work: list[float], normal: int, level: float, feed: float) -> None:
        point = list(work)
        point[normal] = level
        end = self.to_machine(point)
        if kind == "tap":  # spindle-synchronised, timed like G33.1 (the feed override does not act)
            self._sync_move(end, self.cycle.pitch, None)
        else:
            self._move("rapid" if kind == "rapid" else "linear", end, feed if kind == "feed" else 0.0)

    def _cycle_steps(self, steps: list[Step], hole: list[float], normal: int, feed: float) -> None:
        at = list(hole)  # where the tool is across the hole: its centre, or shifted past the bar (G87)
        at[normal] = self.work_position()[normal]
        programmed = self.spindle.direction  # what "spindle_start" turns back to
        switched = {"spindle_stop": 5, "spindle_start": programmed, "spindle_reverse": 3 if programmed == 4 else 4}
        tapping = True if self.cycle.pitch else None
        for step in steps:
            if step.kind in ("rapid", "feed", "tap"):
                self._cycle_move(step.kind, at, normal, step.level, feed)
                at[normal] = step.level
            elif step.kind in ("shift", "center"):
                for axis, offset in self.cycle.shift.items():
                    at[axis] = hole[axis] + (offset if step.kind == "shift" else 0.0)
                self._move("rapid", self.to_machine(at))
            elif step.kind == "dwell":
                self.flush_pending()
                self.canon.event(DwellEvent(self.path, self.line, step.level))
            elif step.kind == "pause":  # G88: the operator retracts by hand, then presses Start
                self.flush_pending()
                self.canon.event(PauseEvent(self.path, self.line, 0, "G88"))
            else:  # the spindle stops, starts or reverses: the moves after it carry its new speed
                self.flush_pending()
                spindle = self.spindle
                spindle.direction = switched[step.kind]
                on = spindle.direction != 5
                self.canon.event(SpindleEvent(self.path, self.line, spindle.direction, spindle.speed,
                                              self.rpm_at(self.pos[0]) if on else 0.0, tapping))
