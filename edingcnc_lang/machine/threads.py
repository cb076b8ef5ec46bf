"""Spindle-synchronised motion: G33 (a thread pass), G33.1 (rigid tapping) and the G76 cycle.

A synchronised move advances ``pitch`` mm of path per spindle revolution, so it runs at pitch x
rpm and is a ``linear`` move whose ``Move.sync`` is the pitch.  G76's passes come from the pure
``thread_passes.py``; this part checks the words it owns (plane, axis words, the spindle) and turns
the passes into machine moves.
"""
from __future__ import annotations

from collections.abc import Callable, Mapping

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.events import SpindleEvent
from edingcnc_lang.machine.thread_passes import G76Words, ThreadError, g76
from edingcnc_lang.machine.state import G, G_40, MachineState, PLANE_OF, format_value, xyz_distance

G_33 = G(33)
G_33_1 = G(33.1)
G_76 = G(76)
G76_LETTERS = "PZIJKRQHEL"
G76_SCALED = frozenset("PZJKE")      # lengths: converted from inch in G20 (I and Z are positions)


class Threading(MachineState):
    """G33, G33.1 and G76: each needs the spindle turning, since the feed is the spindle's pace."""

    def _synchronised(self, motion: int, words: Mapping[str, float], span: n.Span) -> None:
        name = f"G{format_value(motion / 10)}"
        if self.spindle.direction == 5 or self.rpm_at(self.pos[0]) <= 0:
            raise self.fail(f"{name} needs the spindle turning: program M3 or M4 with an S word first", span)
        if self.modal["cutter_comp"] != G_40:
            raise self.fail(f"{name} is not allowed while cutter compensation (G41/G42) is on", span)
        SYNC_MOTION[motion](self, words, span)

    def _sync_move(self, end: list[float], pitch: float, span: n.Span | None) -> None:
        """One synchronised move from here to ``end`` (its feed: pitch x the mean spindle speed)."""
        if xyz_distance(self.pos, end) <= 1e-12:
            return
        feed = pitch * self.mean_rpm([self.pos[0], end[0]], span)
        self._sync_speed_check(end, feed, span)
        self._move("linear", end, feed, sync=pitch)

    def _sync_speed_check(self, end: list[float], feed: float, span: n.Span | None) -> None:
        """Manual 3.6.9 (p. 24): an error "wenn die angeforderte Linearbewegung aufgrund der Spindeldrehzahl
        die Maschinengeschwindigkeitsgrenzen überschreitet": a synchronised move cannot slow down, so an axis
        that would have to go faster than its maxVelocity stops the run."""
        length = xyz_distance(self.pos, end)
        config = self.config
        for axis in range(3):
            limit = (config.cartesian_max_velocity[axis] if self.guards.kinematics_active
                     else config.joints[axis].max_velocity if axis < len(config.joints) else 0.0)
            speed = feed * abs(end[axis] - self.pos[axis]) / length / 60.0  # mm/s along this axis
            if limit > 0.0 and speed > limit * (1.0 + 1e-9):
                raise self.fail(f"the spindle speed asks {'XYZ'[axis]} for {speed * 60.0:.0f} mm/min (pitch x rpm), "
                                f"more than its maximum velocity of {limit * 60.0:.0f} mm/min: lower the spindle speed",
                                span)

    def _pitch(self, words: Mapping[str, float], code: str, span: n.Span) -> float | None:
        if "K" not in words:
            return None
        if words["K"] <= 0:
            raise self.fail(f"{code} K{format_value(words['K'])}: the pitch (distance per revolution) must be "
                            "greater than 0", span)
        return words["K"] * self.scale

    def _g33(self, words: Mapping[str, float], span: n.Span) -> None:
        pitch = self._pitch(words, "G33", span)
        if pitch is not None:
            self.spindle.sync_pitch = pitch
        elif self.spindle.sync_pitch <= 0:
            raise self.fail("G33 needs K, the pitch (distance per spindle revolution)", span)
        self._sync_move(self._target(words), self.spindle.sync_pitch, span)

    def _g33_1(self, words: Mapping[str, float], span: n.Span) -> None:
        """Rigid tapping: in at the pitch, the spindle reverses, out to the start, the spindle turns back."""
        pitch = self._pitch(words, "G33.1", span)
        if pitch is None:
            raise self.fail("G33.1 needs K, the pitch of the tap", span)
        start = list(self.pos)
        forward = self.spindle.direction
        self._sync_move(self._target(words), pitch, span)
        for direction in (7 - forward, forward):  # M3 <-> M4 and back again
            self.canon.event(SpindleEvent(self.path, self.line, direction, self.spindle.speed, self.rpm_at(self.pos[0]),
                                          rigid_tap=True))
            if direction != forward:
                self._sync_move(start, pitch, span)

    def _g76(self, words: Mapping[str, float], span: n.Span) -> None:
        if PLANE_OF[self.modal["plane"]] != "XZ":
            raise self.fail("G76 threads in the XZ plane: select G18 first", span)
        stray = [a for a in "XYABC" if a in words]
        if stray:
            raise self.fail(f"G76 takes no {stray[0]} word: the thread starts at the current position "
                            "and runs along Z to the Z word", span)
        values: dict[str, float | None] = {}
        for letter in G76_LETTERS:
            value = words.get(letter)
            if value is not None:
                value *= self.scale if letter in G76_SCALED else 1.0
            values[letter.lower()] = value
        if values["z"] is not None:
            values["z"] = self._target({"Z": words["Z"]})[2]
        if values["i"] is not None:
            self._g76_crest(words["I"], span)
            values["i"] = self._axis_values({"X": words["I"]})[0] + self.offset()[0]  # always absolute
        start = list(self.pos)
        try:
            passes = g76(G76Words(**values), start[0], start[2], words)
        except ThreadError as err:
            raise self.fail(str(err), span) from None
        self.spend(len(passes) // 4, span)
        for move in passes:
            end = list(self.pos)
            end[0], end[2] = move.x, move.z
            if move.kind == "rapid":
                self._move("rapid", end)
            else:
                self._sync_move(end, move.pitch, span)


    def _g76_crest(self, crest: float, span: n.Span) -> None:
        """I is the thread's crest diameter, always positive (manual 3.6.18); LinuxCNC's negative I
        (an offset from the drive line to an outside thread) is refused with what EdingCNC reads."""
        if crest > 0:
            return
        here = self.reported_position()[0]
        x_name = "diameter" if self.diameter_mode else "X"
        hint = (f"; for LinuxCNC's outside thread from X{format_value(here)} write the crest {x_name} "
                f"I{format_value(here + crest)}" if crest < 0 and here + crest > 0 else "")
        raise self.fail(f"G76 I{format_value(crest)}: EdingCNC reads I as the thread's crest {x_name} (an X "
                        f"position, always positive, manual 3.6.18), not as LinuxCNC's offset from the drive "
                        f"line; J and K are radial depths beyond the crest{hint}", span)


# The synchronised motion codes and what runs each.
SYNC_MOTION: Mapping[int, Callable[[Threading, Mapping[str, float], n.Span], None]] = {
    G_33: Threading._g33, G_33_1: Threading._g33_1, G_76: Threading._g76}
