"""The motion step of a line: straight moves, arcs, probing and the tangential knife."""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

from edingcnc_lang.syntax import nodes as n
from edingcnc_lang.machine import tables as t
from edingcnc_lang.canon import PLANES, Arc
from edingcnc_lang.machine.geometry import ArcError, ArcPlan, center_from_radius, check_radius, radius_tolerance, sweep
from edingcnc_lang.host import checked_trip
from edingcnc_lang.machine.state import (
    AXIS_SET,
    CENTER_WORDS,
    G_0,
    G_1,
    G_2,
    G_3,
    G_38_2,
    G_51,
    G_53,
    G_68,
    G_80,
    G_93,
    MIN_PROBE_DISTANCE,
    PROBE_BACK_OFF,
    MachineState,
    PLANE_OF,
    UNSUPPORTED_MOTION,
    fmt_point,
    xyz_distance,
)
from edingcnc_lang.machine.threads import SYNC_MOTION

ARC_CHORDS = 64  # feed per revolution under CSS: the spindle speed is averaged over this many chords


class Moves(MachineState):
    """Decides what is programmed and hands each move to the canon; the pipeline's stages do the rest."""

    def _motion(self, words: Mapping[str, float], g: Mapping[str, int], non_modal: int | None,
                span: n.Span) -> None:
        motion = g.get("motion")
        g53 = non_modal == G_53
        has_axes = not AXIS_SET.isdisjoint(words)
        if motion == G_80:
            if has_axes:
                raise self.fail("G80 cancels the canned cycle; it takes no axis words", span)
            self.modal["motion"] = G_80
            self.cycle.words.clear()
            return
        previous = self.modal["motion"]
        if motion is not None:
            if motion in UNSUPPORTED_MOTION:
                raise self.fail(f"{t.code_name('G', motion)} is not supported by this simulator", span)
            self.modal["motion"] = motion
        elif (not has_axes or non_modal in t.AXIS_WORD_USERS or g.get("rotation") == G_68
              or g.get("scaling") == G_51):  # their X Y are a pivot or factors, not a target
            if g53:
                raise self.fail("G53 needs an axis word and G0, G1 or G38.2", span)
            return
        motion = self.modal["motion"]
        if motion == G_80:
            raise self.fail("axis words without a motion mode: G80 is active, add G0 or G1", span)
        if g53 and motion not in (G_0, G_1, G_38_2):  # G53 G38.2: probing in machine coordinates (zero_z)
            raise self.fail("G53 moves in machine coordinates only with G0, G1 or G38.2", span)
        if g53:
            self.refuse_with_comp("G53", span)
        if motion in t.CANNED_CYCLES:
            self._cycle(motion, words, span, new_sequence=previous != motion)
        elif motion in SYNC_MOTION:
            self._synchronised(motion, words, span)
        elif motion in (G_2, G_3):
            self._arc(motion, words, span)
        elif has_axes:
            target = self._target(words, g53)
            if motion == G_0:
                self._move("rapid", target)
            elif motion == G_1:
                feed = self._feed_for(xyz_distance(self.pos, target), words, span, [self.pos[0], target[0]])
                if self.guards.tanknife and math.hypot(target[0] - self.pos[0], target[1] - self.pos[1]) > 1e-9:
                    target[5] = self._knife_align(math.degrees(math.atan2(target[1] - self.pos[1],
                                                                          target[0] - self.pos[0])))
                self._move("linear", target, feed)
            else:
                self._probe(target, words, span)
        elif motion == G_38_2:
            raise self.fail("G38.2 needs at least one of X, Y, Z", span)

    def _arc(self, motion: int, words: Mapping[str, float], span: n.Span) -> None:
        plane = PLANE_OF[self.modal["plane"]]
        first, second, _ = PLANES[plane]
        clockwise = (motion == G_2) != self.config.reverse_g2g3
        end = self._target(words)
        try:
            plan = self.arc_plan(plane, clockwise, self.pos, end, words)
        except ArcError as err:
            s, e = (self.pos[first], self.pos[second]), (end[first], end[second])
            where = (f"start ({fmt_point(s)})" + (f", centre ({fmt_point(err.center)})" if err.center else "")
                     + f", end ({fmt_point(e)})")
            raise self.fail(f"{err}; {where} in the {plane} plane", span) from None
        s, center = (self.pos[first], self.pos[second]), plan.center
        feed = self._feed_for(plan.length, words, span, self._arc_xs(plane, s, center, plan.angle, clockwise))
        if self.guards.tanknife and plane == "XY":  # the knife follows the tangent all along the arc
            normal_deg = -90.0 if clockwise else 90.0
            start_tangent = math.degrees(math.atan2(s[1] - center[1], s[0] - center[0])) + normal_deg
            c_start = self._knife_align(start_tangent)
            end[5] = c_start + math.degrees(plan.angle) * (-1.0 if clockwise else 1.0)
        self._move("arc", end, feed, plan.arc)

    def arc_plan(self, plane: str, clockwise: bool, start: Sequence[float], end: Sequence[float],
                 words: Mapping[str, float]) -> ArcPlan:
        """The arc from ``start`` to ``end`` (machine) that a line's R or centre words describe, in the
        general path and the bulk path alike; ArcError when they describe none."""
        first, second, normal = PLANES[plane]
        s = (start[first], start[second])
        e = (end[first], end[second])
        scale = self.scale
        tolerance = radius_tolerance(self.inch)
        if "R" in words:
            center = center_from_radius(s, e, words["R"] * scale, clockwise, tolerance)
        else:
            w1, w2 = CENTER_WORDS[plane]
            if w1 not in words and w2 not in words:
                raise ArcError(f"an arc needs R or centre words {w1}/{w2} in the {plane} plane")
            if self.config.absolute_center_coords:
                work = self.work_position()
                work[first], work[second] = words.get(w1, 0.0) * scale, words.get(w2, 0.0) * scale
                if self.diameter_mode and 0 in (first, second):  # an absolute X centre is a diameter too
                    work[0] /= 2.0
                machine = self.to_machine(work)
                center = (machine[first], machine[second])
            else:
                d1, d2 = words.get(w1, 0.0) * scale, words.get(w2, 0.0) * scale
                center = (s[0] + d1, s[1] + d2)
            try:
                check_radius(s, center, e, tolerance)
            except ArcError as err:
                raise ArcError(str(err), center) from None
        angle, full = sweep(s, center, e, clockwise, self.config.full_circle_theta_epsilon, "R" in words, tolerance)
        radius = math.hypot(s[0] - center[0], s[1] - center[1])
        length = math.hypot(radius * angle, end[normal] - start[normal])
        named = (center[1], center[0]) if plane == "XZ" else center
        return ArcPlan(Arc(named, plane, -1 if clockwise else 1, full), center, angle, length)

    def _arc_xs(self, plane: str, start: tuple[float, float], center: tuple[float, float], angle: float,
                clockwise: bool) -> list[float]:
        """Machine X at evenly spaced points of an arc (feed per revolution under CSS needs them)."""
        if plane == "YZ" or self.css() is None:
            return [self.pos[0]]
        x_slot = 0 if plane == "XY" else 1  # the arc's in-plane pair is (x, y) or (z, x)
        radius = math.hypot(start[0] - center[0], start[1] - center[1])
        begin = math.atan2(start[1] - center[1], start[0] - center[0])
        turn = -angle if clockwise else angle
        points = [begin + turn * i / ARC_CHORDS for i in range(ARC_CHORDS + 1)]
        return [(center[0] + radius * math.cos(a), center[1] + radius * math.sin(a))[x_slot] for a in points]

    def _knife_align(self, direction: float) -> float:
        """Turn C to ``direction`` (the equivalent angle nearest the current C) before a cut.

        A turn larger than tanKnifeAngleForLiftUp lifts the knife, turns it and lowers it
        again (three moves); a smaller one turns in place.  Returns the new C.
        """
        g68 = self.rotation.turn
        if g68 is not None and g68.plane == "XY":  # the cut runs turned on the machine
            direction += g68.angle
        current = self.pos[5]
        target = current + ((direction - current + 180.0) % 360.0 - 180.0)
        turn = abs(target - current)
        if turn < 1e-9:
            return current
        knife = self.config.tanknife
        if turn > knife.angle_for_lift_up:
            down = self.pos[2]
            self._move("rapid", self.pos[:2] + [down + knife.lift_up_distance] + self.pos[3:])
            self._move("rapid", self.pos[:5] + [target])
            self._move("rapid", self.pos[:2] + [down] + self.pos[3:])
        else:
            self._move("rapid", self.pos[:5] + [target])
        return target

    def _probe(self, target: list[float], words: Mapping[str, float], span: n.Span) -> None:
        self.refuse_with_comp("probing (G38.2)", span)
        if any(abs(target[i] - self.pos[i]) > 1e-9 for i in range(3, 6)):
            raise self.fail("G38.2 cannot move a rotary axis", span)
        if self.modal["feed_mode"] == G_93:
            raise self.fail("G38.2 is not allowed in inverse time mode (G93)", span)
        distance = xyz_distance(self.pos, target)
        if distance < MIN_PROBE_DISTANCE:
            raise self.fail(f"G38.2 target is {distance:.4f} mm away; it must be at least {MIN_PROBE_DISTANCE} mm",
                            span)
        feed = self._feed_for(distance, words, span)
        goal = self.machine_frame(target)  # the host sees machine coordinates
        start = self.machine_frame(self.pos)
        trip = self.host.probe(start, goal) if self.host.probe else goal
        try:
            trip = checked_trip(trip, start, goal)
        except ValueError as err:
            raise self.fail(str(err), span) from None
        self._move("probe", self.program_frame(trip) if trip is not None else target, feed)
        if trip is None:  # manual 3.6.10.1: no trip even slightly past the target is an error
            self.params.set(t.PROBE_TRIPPED, 0.0)
            raise self.fail("G38.2 reached its target without the probe tripping (no contact)", span)
        work = self.reported_position()
        for axis in range(6):
            self.params.set(t.PROBE_MACHINE + axis, trip[axis])
            self.params.set(t.PROBE_WORK + axis, work[axis])
            self.params.set(t.PROBE_JOINTS + axis, trip[axis])
        self.params.set(t.PROBE_TRIPPED, 1.0)
        self._probe_back_off(start, feed)

    def _probe_back_off(self, start: tuple[float, ...], feed: float) -> None:
        """Manual 3.6.10.1 (p. 25): "Wenn die Sonde auslöst, wird die Sonde am Ende der Befehlsausführung leicht
        vom Auslösepunkt zurückgezogen": back towards the start by the RS274/NGC reference canon's 0.254 mm
        (0.01 inch: the same length; the shortest probe move the manual allows), never past the start."""
        here = self.machine_frame(self.pos)
        travelled = xyz_distance(start, here)
        if travelled <= 1e-12:
            return
        step = min(PROBE_BACK_OFF, travelled) / travelled
        back = [h + (s - h) * step if axis < 3 else h for axis, (h, s) in enumerate(zip(here, start))]
        self._move("probe", self.program_frame(back), feed)  # part of the probe command
