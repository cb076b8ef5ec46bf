"""Canned cycles (G73, G81..G89): sticky words, levels and holes; cycles.py expands each hole."""
from __future__ import annotations

from collections.abc import Mapping
from functools import cache
from types import ModuleType
from typing import TYPE_CHECKING

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import AXES, PLANES
from edingcnc_lang.events import DwellEvent, PauseEvent, SpindleEvent
from edingcnc_lang.machine.state import CENTER_WORDS, G_91, G_93, G_99, MachineState, PLANE_OF, format_value

G_74 = t.code_key(74)
G_87 = t.code_key(87)

if TYPE_CHECKING:
    from edingcnc_lang.machine.cycles import Step


@cache
def _cycles() -> ModuleType:
    """cycles.py, loaded when a job first drills (not at start-up), and then at the cost of a call."""
    from edingcnc_lang.machine import cycles

    return cycles


class CannedCycles(MachineState):
    """Every hole and peck counts against the step budget."""

    def _cycle(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None:
        """A cycle line's holes; their straight moves go to the canon as one batch where the bulk path's would
        (``batchable``), handed on before any other move or event of the cycle and before an error it meets."""
        if self.pending is not None or not self.batchable():  # held already (the bulk path's run of holes)
            self._holes(motion, words, span, new_sequence)
            return
        with self.moves_held():
            self._holes(motion, words, span, new_sequence)

    def _holes(self, motion: int, words: Mapping[str, float], span: n.Span, new_sequence: bool) -> None:
        cycles = _cycles()
        plane = PLANE_OF[self.modal["plane"]]
        first, second, normal = PLANES[plane]
        drill = AXES[normal]
        sticky = self.cycle_words
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
        if motion in cycles.NEEDS_SPINDLE and (self.spindle == 5 or self.rpm_at(self.pos[0]) <= 0):
            raise self.fail(f"{t.code_name('G', motion)} needs the spindle turning: program "
                            f"{'M4' if motion == G_74 else 'M3'} with an S word first", span)
        repeats = words.get("L", 1)
        if repeats != int(repeats) or repeats < 1:
            raise self.fail("L (repeat count) must be a whole number of at least 1", span)
        scale = self.scale
        work = self.work_position()
        if new_sequence:  # a new cycle sequence: G98 returns to the level it started from
            self.cycle_initial = work[normal]
        old = work[normal] if self.modal["return_mode"] == G_99 else self.cycle_initial
        incremental = self.modal["distance"] == G_91
        r_level = (old if incremental else 0.0) + sticky["R"] * scale
        bottom = (r_level if incremental else 0.0) + sticky["Z"] * scale
        if r_level < bottom:
            raise self.fail(f"R ({format_value(r_level / scale)}) is below the hole bottom "
                            f"{drill} ({format_value(bottom / scale)})", span)
        feed = self._feed_for(1.0, words, span)
        # G84/G74 (3.6.20.6/7): F is the pitch, mm per spindle revolution, in G94 as in G95
        self.cycle_pitch = self.feed if motion in cycles.TAPPING else 0.0
        if old < r_level:  # start below R: climb to R first
            self._cycle_move("rapid", work, normal, r_level, feed)
            old = self.cycle_initial = r_level
        clear = r_level if self.modal["return_mode"] == G_99 else old
        dwell = sticky.get("P", 0.0) / (1000.0 if self.config.g4_in_milliseconds else 1.0)
        extra = sticky.get("Q", 0.0) * scale
        if back_boring:
            extra = (r_level if incremental else 0.0) + sticky["K"] * scale
            if not bottom <= extra <= r_level:
                raise self.fail(f"G87 K ({format_value(extra / scale)}) must lie between the bottom "
                                f"{drill} ({format_value(bottom / scale)}) and R ({format_value(r_level / scale)})", span)
            self.cycle_shift = {first: sticky.get("I", 0.0) * scale, second: sticky.get("J", 0.0) * scale}
        try:
            steps = cycles.CYCLES[motion](r_level, bottom, clear, dwell, extra)
        except cycles.CycleError as err:
            raise self.fail(str(err), span) from None
        hole = list(work)
        cost = int(repeats) * (1 + len(steps))
        if self.max_steps is not None and cost > self.max_steps - self.steps:
            self.spend(cost, span)  # L1000000000: the budget error now, not after minutes of drilling
        for _ in range(int(repeats)):
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

    def _cycle_move(self, kind: str, work: list[float], normal: int, level: float, feed: float) -> None:
        point = list(work)
        point[normal] = level
        end = self.to_machine(point)
        if kind == "tap":  # spindle-synchronised, timed like G33.1 (the feed override does not act)
            self._sync_move(end, self.cycle_pitch, None)
        else:
            self._move("rapid" if kind == "rapid" else "linear", end, feed if kind == "feed" else 0.0)

    def _cycle_steps(self, steps: list[Step], hole: list[float], normal: int, feed: float) -> None:
        at = list(hole)  # where the tool is across the hole: its centre, or shifted past the bar (G87)
        at[normal] = self.work_position()[normal]
        programmed = self.spindle  # what "spindle_start" turns back to
        switched = {"spindle_stop": 5, "spindle_start": programmed, "spindle_reverse": 3 if programmed == 4 else 4}
        tapping = True if self.cycle_pitch else None
        for step in steps:
            if step.kind in ("rapid", "feed", "tap"):
                self._cycle_move(step.kind, at, normal, step.level, feed)
                at[normal] = step.level
            elif step.kind in ("shift", "center"):
                for axis, offset in self.cycle_shift.items():
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
                self.spindle = switched[step.kind]
                on = self.spindle != 5
                self.canon.event(SpindleEvent(self.path, self.line, self.spindle, self.speed,
                                              self.rpm_at(self.pos[0]) if on else 0.0, tapping))
