"""Cutter radius compensation (G41/G42) as a pipeline stage, following LinuxCNC's interpreter.

The interpreter sends the programmed path and a ``cutter_comp`` event when G41/G42/G40 take
effect (data: ``side`` "left" | "right" | "off", ``radius`` in mm, ``plane``).  This stage moves
the path sideways by the tool radius in the selected plane:

- the entry move (the first move after G41/G42) ends a radius to the side of its programmed end,
  square to its direction (an entry arc: on the line from its end to its centre); it must be
  longer than the radius;
- at an outside (convex) corner the tool goes round the corner point on an arc of the tool
  radius (a G0 goes straight to where that arc would end);
- at an inside (concave) corner the previous move is cut back to where the tool touches both
  sides (line-line, line-arc, arc-line and arc-arc intersections); a corner the tool cannot fit
  into without cutting into the part is refused, naming the line;
- after G40 the last move ends at its compensated end point and the next move (the exit move,
  straight) goes from there to its programmed end;
- on a lathe (the event's ``orientation``, XZ plane) the path computed is the nose centre's, and
  every compensated point is handed on moved to the tool's controlled point (``tip_shift``).

A compensated move is held back until the next move shows which kind of corner follows; events
programmed meanwhile wait behind it.  Moves without in-plane motion (plunges) wait with it.

A batch goes through ``comp_runs``: its runs of corners between straight moves (straight on,
inside, and outside ones with their arcs) are computed in one loop (in C on the compiled core) with
the operations of the corner functions here (``comp_geometry``) and go on as one batch; every other
move (the contour's arcs among them) is taken here, one at a time, with the very same results.
Released moves go on as batches (an arc in the batch's arcs column); a move under G96 alone.
"""
from __future__ import annotations

import math
from dataclasses import replace

from edingcnc_lang.canon import Arc, Batch, Canon, Event, Move, Pose
from edingcnc_lang.events import CutterCompEvent, EndEvent
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.pipeline.base import FLUSHING_EVENTS, Stage
from edingcnc_lang.pipeline.comp_runs import Made, take_batch
from edingcnc_lang.pipeline.comp_geometry import (
    ARC_SWEEP_SLACK_INCH,
    ARC_SWEEP_SLACK_MM,
    CONCAVE_TOLERANCE,
    HALF_PI,
    LEFT,
    RIGHT,
    Frame,
    Point,
    Queued,
    at,
    cut_back,
    find_turn,
    half_corner,
    heading,
    inside_corner,
    line_corner,
    outside_corner,
    reverses,
    tip_shift,
    tool_inside_arc,
)

SIDES = {"left": LEFT, "right": RIGHT}


def _refuse(move: Move | Event, what: str) -> MachineError:
    return MachineError(f"cutter compensation: {what}", Location(move.path, move.line))


class CutterCompensation(Stage):
    """Offsets the programmed path by the tool radius while G41/G42 is on."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.side = 0                      # LEFT, RIGHT or 0 (off, or a radius of 0)
        self.radius = 0.0
        self.sweep_slack = ARC_SWEEP_SLACK_MM  # by the program's units when compensation came on
        self.frame = Frame("XY")
        self.first = True                  # the next move is the entry move
        self.program: Point = (0.0, 0.0)   # programmed in-plane end of the last move
        self.current: list[float] = []     # compensated end of the last move (all axes)
        self.queue: list[Queued | Event] = []
        self.endpoint: Point | None = None  # where the queued moves start (LinuxCNC's endpoint)
        self.emitted: Pose | None = None   # where the machine is after the moves handed on
        self.exit_from: Pose | None = None  # after G40: where the exit move starts
        self.tip = (0.0, 0.0)              # a lathe tool: X, Z from the nose centre to its controlled point
        # compensated moves released during one call, handed on together as one Batch; the arcs among
        # them (the batch's arcs column, None while they are all straight)
        self.out: Batch | None = None
        self.out_arcs: list[Arc | None] | None = None

    # ---------------------------------------------------------------- canon
    def move(self, move: Move) -> None:
        try:
            self._take(move)
        finally:
            self._send()

    def move_batch(self, batch: Batch) -> None:
        if not self.side and self.exit_from is None:
            self._send()
            self.next.move_batch(batch)
            return
        try:
            if self.side and batch.css is None and self.tip == (0.0, 0.0):
                take_batch(self, batch)
            else:
                batch.each(self._take)
        finally:
            self._send()

    def _take(self, move: Move) -> None:
        if not self.side:
            self._uncompensated(move)
        elif move.kind == "arc":
            self._arc(move)
        elif move.kind in ("rapid", "linear"):
            self._straight(move)
        else:
            self.flush()
            self.next.move(move)

    def event(self, event: Event) -> None:
        if isinstance(event, CutterCompEvent):
            self._switch(event)
        if not self.queue:
            self._send()
            self.next.event(event)
        else:
            self.queue.append(event)
            if isinstance(event, FLUSHING_EVENTS):
                self.flush()
        if isinstance(event, EndEvent):  # M2/M30 end compensation without an exit move
            self.side, self.first, self.exit_from = 0, True, None
        self._send()  # moves the event released (G40's last one) go on before the next call

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        self.flush()
        return self.next.kinematics(mode, args, pos, path, line)

    def flush(self) -> None:
        self._dequeue()
        self._send()

    # ---------------------------------------------------------------- output
    def _hand_on(self, item: Queued, start: Pose) -> Pose:
        """Hand a released move on: it joins the batch being collected while it shares the batch's
        spindle, caller and file (a move under G96 goes on alone); returns where it ends."""
        origin = item.origin
        if self.tip != (0.0, 0.0):
            self._at_tip(item)
        if origin.css is not None:
            self._send()
            move = item.to_move(start, self.frame)
            self.next.move(move)
            return move.end
        end = tuple(item.end)
        self._append(self._collecting(origin, start), item.kind, origin.line, end, item.feed,
                     item.arc(start, self.frame))
        return end

    def _append(self, out: Batch, kind: str, line: int, end: Pose, feed: float, arc: Arc | None) -> None:
        """Add one move to ``out``, the batch being collected."""
        out.kinds.append(kind)  # type: ignore[attr-defined]
        out.lines.append(line)  # type: ignore[attr-defined]
        out.ends.append(end)  # type: ignore[attr-defined]
        out.feeds.append(feed)  # type: ignore[attr-defined]
        if arc is not None and self.out_arcs is None:
            self.out_arcs = [None] * (len(out.lines) - 1)
        if self.out_arcs is not None:
            self.out_arcs.append(arc)

    def _at_tip(self, item: Queued) -> None:
        """A lathe tool's move, computed for the nose centre, moved to the tool's controlled point."""
        dx, dz = self.tip
        item.end = list(item.end)
        item.end[0] += dx
        item.end[2] += dz
        if item.center is not None:  # XZ frame points are (z, x)
            item.center = (item.center[0] + dz, item.center[1] + dx)

    def _hand_on_run(self, source: Batch, made: Made) -> None:
        """Hand on the moves a run of ``source``'s moves made (``comp_runs.comp_lines``), as columns."""
        kinds, lines, ends, feeds, arcs = made
        out = self._collecting(source, self.emitted)  # type: ignore[arg-type]
        if arcs is not None and self.out_arcs is None:
            self.out_arcs = [None] * len(out.lines)
        out.kinds.extend(kinds)  # type: ignore[attr-defined]
        out.lines.extend(lines)  # type: ignore[attr-defined]
        out.ends.extend(ends)  # type: ignore[attr-defined]
        out.feeds.extend(feeds)  # type: ignore[attr-defined]
        if self.out_arcs is not None:
            self.out_arcs.extend([None] * len(ends) if arcs is None else arcs)
        self.emitted = ends[-1]

    def _collecting(self, source: Move | Batch, start: Pose) -> Batch:
        """The batch being collected, if moves from ``source`` (same file, spindle, caller) may join it;
        else a new one starting at ``start``, after handing on the one before."""
        out = self.out
        if out is None or (out.path, out.spindle, out.sync, out.caller) != (source.path, source.spindle,
                                                                              source.sync, source.caller):
            self._send()
            out = self.out = Batch(source.path, start, [], [], [], [], source.spindle, None, source.sync,
                                   source.caller)
        return out

    def _send(self) -> None:
        """Hand on the batch collected so far (before anything else goes on, so the order stays)."""
        out, arcs, self.out, self.out_arcs = self.out, self.out_arcs, None, None
        if out is not None:
            self.next.move_batch(out if arcs is None else replace(out, arcs=arcs))

    # ---------------------------------------------------------------- on and off
    def _switch(self, event: CutterCompEvent) -> None:
        side = SIDES.get(event.side, 0)
        if side:
            radius = event.radius or 0.0
            if radius < 0:  # a negative radius (a worn or nominal-size tool) swaps the side
                side, radius = -side, -radius
            self.side = side if radius > 0 else 0
            self.radius = radius
            self.frame = Frame(event.plane or "XY")
            self.sweep_slack = ARC_SWEEP_SLACK_INCH if event.inch else ARC_SWEEP_SLACK_MM
            orientation = (event.orientation or 0) if self.frame.plane == "XZ" else 0
            self.tip = tip_shift(orientation, radius)
            self.first = True
            return
        if self.side and not self.first:  # G40: the last move ends at its compensated end (checked as any corner)
            self._move_endpoint_and_flush(self.frame.point(self.current), event)
            end = list(self.current)
            end[0] += self.tip[0]
            end[2] += self.tip[1]
            self.exit_from = tuple(end)
        self.side = 0
        self.first = True
        self.tip = (0.0, 0.0)

    def _uncompensated(self, move: Move) -> None:
        if self.exit_from is not None:  # the exit move starts where compensation left the tool
            if move.kind == "arc":
                raise _refuse(move, "the move after G40 must be a straight move, not an arc")
            move = replace(move, start=self.exit_from)
            self.exit_from = None
        self._send()
        self.next.move(move)

    # ---------------------------------------------------------------- queue
    def _enqueue(self, item: Queued) -> None:
        self.queue.append(item)

    def _dequeue(self) -> None:
        """Hand on everything queued, in order."""
        queue, self.queue = self.queue, []
        self.endpoint = None
        for item in queue:
            if isinstance(item, Event):
                self._send()
                self.next.event(item)
                continue
            start = self.emitted if self.emitted is not None else tuple(item.end)
            self.emitted = self._hand_on(item, start)

    def _move_endpoint_and_flush(self, point: Point, move: Move | Event | None) -> None:
        """End every queued move at ``point`` (cut back into a corner), refusing reversals; hand them on.

        ``move``: what moved the end (the next move, or the G40 event), named by a refusal.
        """
        frame = self.frame
        for item in self.queue:
            if isinstance(item, Event):
                continue
            if item.center is not None:
                new_sweep = find_turn(self.endpoint, item.center, item.turn, point) if self.endpoint else 0.0
                if (move is not None and item.sweep and self.endpoint is not None
                        and abs(new_sweep) > abs(item.sweep) + self.sweep_slack):
                    raise _refuse(move, "an arc in an inside corner cannot be reached by the tool without gouging")
            elif move is not None and self.endpoint is not None:
                if reverses(item.direction, self.endpoint, point):
                    raise _refuse(move, "a straight move in an inside corner cannot be reached by the tool "
                                       "without gouging (the tool is larger than the corner)")
            item.end = frame.pose(item.end, point)
        self._dequeue()
        self.endpoint = point

    def _begin(self, move: Move) -> Point:
        """The programmed start of the entry move, in the frame; the tool is there (or where G40 left it)."""
        self.emitted = self.exit_from or move.start
        self.exit_from = None
        self.current = list(move.start)
        return self.frame.point(move.start)

    # ---------------------------------------------------------------- straight moves
    def _straight(self, move: Move) -> None:
        frame = self.frame
        target = frame.point(move.end)
        if self.first:
            self._entry(move, target)
            return
        start = self.program
        current = frame.point(self.current)
        if target == start:  # no motion in the plane: it keeps the compensated position
            self._enqueue(Queued(move, move.kind, frame.pose(move.end, current), move.feed))
            self.current = frame.pose(move.end, current)
            return
        side, radius = self.side, self.radius
        theta, alpha, beta, gamma = line_corner(side, heading(start, current),
                                                heading(start, target))
        end = at(target, radius, alpha + gamma)
        front = self._front()
        concave = inside_corner(beta)
        if not concave and beta > math.pi - CONCAVE_TOLERANCE and front is not None and front.center is not None \
                and ((side == RIGHT and front.turn > 0) or (side == LEFT and front.turn < 0)):
            concave = True  # over the round top of an "h": stay on the outside
        if not concave and outside_corner(beta):  # outside corner: round it
            mid = at(start, radius, alpha + gamma)
            self._move_endpoint_and_flush(current, move)
            corner = frame.pose(move.end, mid, self.current[frame.normal])
            if move.kind == "linear":
                self._enqueue(Queued(move, "arc", corner, move.feed, center=start,
                                     turn=-1 if side == LEFT else 1))
            else:
                self._enqueue(Queued(move, "rapid", corner, 0.0))
            self._dequeue()
            self.endpoint = mid
        elif concave:
            if front is None or front.center is None:
                half = half_corner(beta)
                if half == 0.0:
                    raise _refuse(move, "a zero-degree inside corner cannot be compensated")
                self._move_endpoint_and_flush(cut_back(radius, current, theta, gamma, half), move)
            else:
                self._move_endpoint_and_flush(self._arc_line_corner(front, start, target, move), move)
        else:  # straight on (or a tangent arc-line junction)
            self._dequeue()
            self.endpoint = current
        self._enqueue(Queued(move, move.kind, frame.pose(move.end, end), move.feed,
                             direction=(target[0] - start[0], target[1] - start[1])))
        self.current = frame.pose(move.end, end)
        self.program = target

    def _entry(self, move: Move, target: Point) -> None:
        current = self._begin(move)
        distance = math.dist(current, target)
        if distance <= self.radius:
            raise _refuse(move, f"the entry move ({distance:.4f} mm in the plane) must be longer than the tool "
                               f"radius {self.radius:.4f} mm")
        alpha = math.atan2(target[1] - current[1], target[0] - current[0]) + HALF_PI * self.side
        end = at(target, self.radius, alpha)
        self.endpoint = current
        self._enqueue(Queued(move, move.kind, self.frame.pose(move.end, end), move.feed,
                             direction=(math.cos(alpha), math.sin(alpha))))
        self.first = False
        self.current = self.frame.pose(move.end, end)
        self.program = target

    def _front(self) -> Queued | None:
        return next((item for item in self.queue if isinstance(item, Queued)), None)

    def _arc_line_corner(self, prev: Queued, start: Point, target: Point, move: Move) -> Point:
        """Where a compensated arc meets the compensated line that follows it in an inside corner."""
        assert prev.center is not None
        radius, side = self.radius, self.side
        old = math.dist(prev.center, self.frame.point(prev.end))
        base = math.atan2(target[1] - start[1], target[0] - start[0])
        theta = base + HALF_PI if prev.turn > 0 else base - HALF_PI
        phi = math.atan2(prev.center[1] - start[1], prev.center[0] - start[0])
        inside = tool_inside_arc(side, prev.turn)
        uncompensated = old + radius if inside else old - radius
        d = uncompensated * math.cos(theta - phi)
        ratio = (d - radius if inside else d + radius) / old
        if not -1.0 <= ratio <= 1.0:
            raise _refuse(move, "the arc-to-line corner is too tight for the tool without gouging")
        sign = (-1 if prev.turn > 0 else 1) if inside else (1 if prev.turn > 0 else -1)
        return at(prev.center, old, sign * math.acos(ratio) + theta + math.pi)

    # ---------------------------------------------------------------- arcs
    def _arc(self, move: Move) -> None:
        assert move.arc is not None
        if self.first:
            self._arc_entry(move, move.arc)
            return
        frame = self.frame
        start, end_p = self.program, frame.point(move.end)
        center = frame.center(move.arc)
        turn = move.arc.turn
        current = frame.point(self.current)
        side, radius = self.side, self.radius
        arc_radius = math.dist(center, end_p)
        theta = math.atan2(current[1] - start[1], current[0] - start[0])
        theta = theta - HALF_PI if side == LEFT else theta + HALF_PI
        delta = math.atan2(center[1] - start[1], center[0] - start[0])
        alpha = delta - HALF_PI if turn > 0 else delta + HALF_PI
        beta = theta - alpha if side == LEFT else alpha - theta
        if beta > 1.5 * math.pi:
            beta -= 2 * math.pi
        elif beta < -HALF_PI:
            beta += 2 * math.pi
        inside = tool_inside_arc(side, turn)
        if inside:
            gamma = math.atan2(center[1] - end_p[1], center[0] - end_p[0])
            if arc_radius <= radius:
                raise _refuse(move, f"the tool radius {radius:.4f} mm does not fit inside the arc of radius "
                                   f"{arc_radius:.4f} mm")
        else:
            gamma = math.atan2(end_p[1] - center[1], end_p[0] - center[0])
            delta += math.pi
        new_end = at(end_p, radius, gamma)
        sweep = find_turn(start, center, turn, end_p)
        arc_end = frame.pose(move.end, new_end)
        if inside_corner(beta) or (abs(beta - math.pi) < CONCAVE_TOLERANCE and not inside):
            front = self._front()
            if front is None or front.center is None:
                mid = self._line_arc_corner(center, arc_radius, theta, beta, turn, move)
            else:
                mid = self._arc_arc_corner(front, center, arc_radius, turn, move)
            self._move_endpoint_and_flush(mid, move)
        elif outside_corner(beta):  # outside corner: round it first
            corner = at(start, radius, delta)
            self._dequeue()
            self._enqueue(Queued(move, "arc", frame.pose(move.end, corner, self.current[frame.normal]),
                                 move.feed, center=start, turn=-1 if side == LEFT else 1))
            self._dequeue()
            self.endpoint = corner
        else:
            self._dequeue()
            self.endpoint = current
        self._enqueue(Queued(move, "arc", arc_end, move.feed, center=center, turn=turn, sweep=sweep))
        self.current = arc_end
        self.program = end_p

    def _arc_entry(self, move: Move, arc: Arc) -> None:
        """An arc as the entry move: it ends a radius to the side of its end, on a circle through the tool."""
        frame = self.frame
        current = self._begin(move)
        end_p, center = frame.point(move.end), frame.center(arc)
        if math.dist(current, end_p) <= self.radius:
            raise _refuse(move, "the entry arc must end further than the tool radius from where it starts")
        if tool_inside_arc(self.side, arc.turn) and math.dist(center, end_p) <= self.radius:
            raise _refuse(move, f"the tool radius {self.radius:.4f} mm does not fit inside the arc of radius "
                                f"{math.dist(center, end_p):.4f} mm")
        toward = (center, end_p) if tool_inside_arc(self.side, arc.turn) else (end_p, center)
        end = at(end_p, self.radius, math.atan2(toward[0][1] - toward[1][1], toward[0][0] - toward[1][0]))
        # the compensated arc's centre: on the line from its end towards the programmed centre,
        # equally far from the end and from the start (the tool)
        half = math.dist(current, end) / 2.0
        towards_center = math.atan2(center[1] - end[1], center[0] - end[0])
        cosine = math.cos(math.atan2(current[1] - end[1], current[0] - end[0]) - towards_center)
        if abs(cosine) < 1e-4:
            raise _refuse(move, "the tool radius is not smaller than the radius of the entry arc")
        new_center = at(end, half / cosine, towards_center)
        self.endpoint = None
        self._enqueue(Queued(move, "arc", frame.pose(move.end, end), move.feed, center=new_center,
                             turn=arc.turn, sweep=find_turn(current, new_center, arc.turn, end)))
        self.first = False
        self.current = frame.pose(move.end, end)
        self.program = end_p

    def _line_arc_corner(self, center: Point, arc_radius: float, theta: float, beta: float, turn: int,
                         move: Move) -> Point:
        """Where a compensated line meets the compensated arc that follows it in an inside corner."""
        radius = self.radius
        offset = arc_radius * math.sin(beta - HALF_PI)
        if tool_inside_arc(self.side, turn):
            distance = arc_radius - radius
            ratio = (offset + radius) / distance
            self._fits(ratio, move)
            angle = theta + math.asin(ratio) if turn > 0 else theta - math.asin(ratio)
        else:
            distance = arc_radius + radius
            ratio = (offset - radius) / distance
            self._fits(ratio, move)
            angle = theta + math.pi - math.asin(ratio) if turn > 0 else theta + math.pi + math.asin(ratio)
        return at(center, distance, angle)

    def _arc_arc_corner(self, prev: Queued, center: Point, arc_radius: float, turn: int, move: Move) -> Point:
        """Where two compensated arcs meet in an inside corner."""
        assert prev.center is not None
        old = math.dist(prev.center, self.frame.point(prev.end))
        new = arc_radius - self.radius if tool_inside_arc(self.side, turn) else arc_radius + self.radius
        between = math.dist(prev.center, center)
        if old == 0 or between == 0:
            raise _refuse(move, "two arcs with the same centre cannot meet in a corner")
        ratio = (old ** 2 + between ** 2 - new ** 2) / (2 * old * between)
        if not -1.0 <= ratio <= 1.0:
            raise _refuse(move, "the arc-to-arc corner is too tight for the tool without gouging")
        pullback = math.acos(ratio)
        direction = math.atan2(center[1] - prev.center[1], center[0] - prev.center[0])
        sign = (1 if turn > 0 else -1) if tool_inside_arc(self.side, prev.turn) else (-1 if turn > 0 else 1)
        return at(prev.center, old, direction + sign * pullback)

    @staticmethod
    def _fits(ratio: float, move: Move) -> None:
        if not -1.0 <= ratio <= 1.0:
            raise _refuse(move, "an arc in an inside corner cannot be reached by the tool without gouging")
