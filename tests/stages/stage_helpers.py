"""A canon that records what reaches it, to test stages alone."""
from __future__ import annotations

from collections.abc import Sequence

from edingcnc_lang.canon import Event, Move, Pose

ZERO: Pose = (0.0,) * 6


def pose(x: float = 0.0, y: float = 0.0, z: float = 0.0) -> Pose:
    return (x, y, z, 0.0, 0.0, 0.0)


def line(x0: float, y0: float, x1: float, y1: float, number: int = 1, feed: float = 100.0) -> Move:
    return Move("linear", "job.nc", number, pose(x0, y0), pose(x1, y1), feed)


class Recorder:
    """Records moves, bulk batches, events and kinematics calls as tuples, in arrival order."""

    def __init__(self) -> None:
        self.log: list[tuple[object, ...]] = []

    def move(self, move: Move) -> None:
        self.log.append(("move", move))

    def straight_moves(self, path: str, start: Pose, batch: Sequence[tuple[str, int, Pose, float]]) -> None:
        self.log.append(("batch", start, tuple(batch)))

    def event(self, event: Event) -> None:
        self.log.append(("event", event.kind))

    def kinematics(self, mode: str, args: tuple[float, ...], pos: Pose, path: str, line: int) -> Pose:
        self.log.append(("kinematics", mode))
        return pos

    def moves(self) -> list[Move]:
        return [entry[1] for entry in self.log if entry[0] == "move"]  # type: ignore[misc]
