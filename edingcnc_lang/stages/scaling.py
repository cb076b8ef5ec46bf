"""G51 scaling as a pipeline stage: X and Y of every move scaled about a centre; Z never.

The interpreter sends a ``scaling`` event when G51 takes effect (data: ``on``, ``factors`` x y z,
``center`` machine x y) and when G50 or M2/M30 end it.  Arcs keep their shape only when both of
their plane's factors have the same size (a negative factor mirrors, which reverses an arc made
by mirroring one axis); any other arc is refused, naming its line.  Each scaled move starts where
the previous move really ended, so switching scaling on or off never jumps.
"""
from __future__ import annotations

from collections.abc import Sequence

from ..canon import PLANES, Arc, Canon, Event, Move, Pose
from ..config import MachineConfig
from ..errors import Location, MachineError
from .base import Stage, each_move


class Scaling(Stage):
    """Scales X and Y about the G51 centre while G51 is on."""

    def __init__(self, next_canon: Canon, config: MachineConfig) -> None:
        super().__init__(next_canon, config)
        self.factors: tuple[float, float, float] | None = None
        self.center = (0.0, 0.0, 0.0)
        self.at: Pose | None = None  # where the last move handed on really ended

    def move(self, move: Move) -> None:
        if self.factors is not None or (self.at is not None and move.start != self.at):
            move = self._scaled(move)
        self.next.move(move)
        self.at = move.end

    def straight_moves(self, path: str, start: Pose, batch: Sequence[tuple[str, int, Pose, float]]) -> None:
        if self.factors is None and (self.at is None or self.at == start):
            self.next.straight_moves(path, start, batch)
            self.at = batch[-1][2] if batch else self.at
            return
        for move in each_move(path, start, batch):
            self.move(move)

    def event(self, event: Event) -> None:
        if event.kind == "scaling":
            if event.data.get("on"):
                self.factors = tuple(event.data["factors"])  # type: ignore[assignment]
                cx, cy = event.data["center"]
                self.center = (cx, cy, 0.0)
            else:
                self.factors = None
        elif event.kind == "end":
            self.factors = None
        self.next.event(event)

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        pose = self.next.kinematics(mode, args, self.at or pos, path, line)
        self.at = pose
        return pose

    def point(self, pose: Pose) -> Pose:
        """A programmed pose as the machine reaches it."""
        if self.factors is None:
            return pose
        return tuple(c + f * (p - c) for p, f, c in zip(pose[:3], self.factors, self.center)) + pose[3:]

    def _scaled(self, move: Move) -> Move:
        start = self.at if self.at is not None else self.point(move.start)
        arc = move.arc
        if arc is not None and self.factors is not None:
            arc = self._scaled_arc(move, arc)
        return Move(move.kind, move.path, move.line, start, self.point(move.end), move.feed, arc)

    def _scaled_arc(self, move: Move, arc: Arc) -> Arc:
        assert self.factors is not None
        first, second, _ = PLANES[arc.plane]
        f1, f2 = self.factors[first], self.factors[second]
        if abs(f1) != abs(f2):
            raise MachineError(f"an arc cannot be scaled by different factors in the {arc.plane} plane "
                               f"({f1:g} and {f2:g}); use G51 P or break the arc into lines",
                               Location(move.path, move.line))
        in_frame = (arc.center[1], arc.center[0]) if arc.plane == "XZ" else arc.center  # (first, second)
        pose = [0.0] * 6
        pose[first], pose[second] = in_frame
        center = self.point(tuple(pose))  # type: ignore[arg-type]
        new = (center[first], center[second])
        turn = arc.turn if f1 * f2 > 0 else -arc.turn
        return Arc((new[1], new[0]) if arc.plane == "XZ" else new, arc.plane, turn, arc.full_turns)
