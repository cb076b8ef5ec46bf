"""Stages that map every programmed pose to a machine pose (G51 scaling, G68 rotation).

A ``PoseTransform`` passes moves through ``forward`` while it is on, starts each move where the
previous one really ended (so switching on or off never jumps), keeps the bulk path whole while
it is off, and answers kinematics calls in the interpreter's (programmed) frame.
"""
from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import replace

from edingcnc_lang.canon import PLANES, Arc, Batch, Move, Pose
from edingcnc_lang.errors import Location, MachineError
from edingcnc_lang.pipeline.base import Stage


def map_center(arc: Arc, mapping: Callable[[Pose], Pose]) -> tuple[float, float]:
    """An arc's centre (in its plane's name order) sent through a pose mapping."""
    first, second, _ = PLANES[arc.plane]
    in_frame = (arc.center[1], arc.center[0]) if arc.plane == "XZ" else arc.center
    pose = [0.0] * 6
    pose[first], pose[second] = in_frame
    mapped = mapping(tuple(pose))
    return (mapped[second], mapped[first]) if arc.plane == "XZ" else (mapped[first], mapped[second])


class PoseTransform(Stage):
    """Base of the pose-mapping stages; subclasses say when they are on and how points and arcs map."""

    at: Pose | None = None  # where the last move handed on really ended

    @property
    def on(self) -> bool:
        raise NotImplementedError

    def forward(self, pose: Pose) -> Pose:
        """A programmed pose as the machine reaches it."""
        raise NotImplementedError

    def inverse(self, pose: Pose) -> Pose:
        """The programmed pose the machine pose ``pose`` corresponds to."""
        raise NotImplementedError

    def arc(self, arc: Arc, where: Location) -> Arc:
        """The arc data of a mapped arc move (or an error naming the move's line, ``where``)."""
        raise NotImplementedError

    def move(self, move: Move) -> None:
        if self.on or (self.at is not None and move.start != self.at):
            start = self.at if self.at is not None else self.forward(move.start)
            arc = self.arc(move.arc, Location(move.path, move.line)) if move.arc is not None and self.on else move.arc
            end = self.forward(move.end) if self.on else move.end
            move = replace(move, start=start, end=end, arc=arc)  # the pose is all a transform owns
        self.next.move(move)
        self.at = move.end

    def move_batch(self, batch: Batch) -> None:
        if not batch.lines:
            return
        if batch.css is not None and self.on:  # the spindle speed follows the programmed X: move by move
            batch.each(self.move)
            return
        if self.on or (self.at is not None and self.at != batch.start):
            start = self.at if self.at is not None else self.forward(batch.start)
            ends = [self.forward(end) for end in batch.ends] if self.on else batch.ends
            arcs = self._mapped_arcs(batch, start, ends) if self.on and batch.arcs is not None else batch.arcs
            batch = replace(batch, start=start, ends=ends, arcs=arcs)
        self.next.move_batch(batch)
        self.at = batch.end

    def _mapped_arcs(self, batch: Batch, start: Pose, ends: Sequence[Pose]) -> list[Arc | None]:
        """A batch's arcs mapped; when one is refused, the moves before it are handed on first, as one
        move at a time would have."""
        assert batch.arcs is not None
        arcs: list[Arc | None] = []
        for index, arc in enumerate(batch.arcs):
            try:
                arcs.append(None if arc is None else self.arc(arc, Location(batch.path, batch.lines[index])))
            except MachineError:
                if index:
                    self.next.move_batch(replace(batch.head(index), start=start, ends=ends[:index], arcs=arcs))
                    self.at = ends[index - 1]
                raise
        return arcs

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        actual = self.next.kinematics(mode, args, self.at or self.forward(pos), path, line)
        self.at = actual
        return self.inverse(actual) if self.on else actual
