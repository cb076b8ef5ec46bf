"""Plane geometry of cutter radius compensation: sweeps, corner points and the queued moves.

Everything here works in the active plane's (first, second) frame (``canon.PLANES``), so the
compensation stage can think of the XY plane only, whatever plane is selected.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

from edingcnc_lang.canon import PLANES, Arc, Move, Pose

LEFT = 1
RIGHT = -1
CONCAVE_TOLERANCE = 0.05  # radians: corners sharper than this either way are corners, as in LinuxCNC
# Radians an arc whose end moved back may grow by before it counts as gouging.  LinuxCNC 2.9 compares
# the angles with a slack chosen by the program's units (0.0254 under G21, 0.001 under G20, as if they
# were lengths); we take the same, so the same near-tangent arcs pass and the same ones are refused.
ARC_SWEEP_SLACK_MM = 0.0254
ARC_SWEEP_SLACK_INCH = 0.001

Point = tuple[float, float]


def tool_inside_arc(side: int, turn: int) -> bool:
    """Whether the tool runs on the inside of an arc turning ``turn`` (+1 counter-clockwise)."""
    return (side == LEFT and turn > 0) or (side == RIGHT and turn < 0)


def find_turn(start: Point, center: Point, turn: int, end: Point) -> float:
    """Signed angle (radians) an arc sweeps from ``start`` to ``end``; ``turn`` counts turns, sign = sense."""
    if turn == 0:
        return 0.0
    alpha = math.atan2(start[1] - center[1], start[0] - center[0])
    beta = math.atan2(end[1] - center[1], end[0] - center[0])
    if turn > 0:
        if beta <= alpha:
            beta += 2 * math.pi
        return beta - alpha + (turn - 1) * 2 * math.pi
    if alpha <= beta:
        alpha += 2 * math.pi
    return beta - alpha + (turn + 1) * 2 * math.pi


def at(origin: Point, distance: float, angle: float) -> Point:
    """The point ``distance`` from ``origin`` in direction ``angle``."""
    return (origin[0] + distance * math.cos(angle), origin[1] + distance * math.sin(angle))


@dataclass
class Frame:
    """The compensation plane: which pose indices are its first, second and normal axes."""

    plane: str

    def __post_init__(self) -> None:
        self.first, self.second, self.normal = PLANES[self.plane]

    def point(self, pose: Pose | list[float]) -> Point:
        return (pose[self.first], pose[self.second])

    def center(self, arc: Arc) -> Point:
        """An arc's centre in this frame (``Arc.center`` is in the plane's name order)."""
        return (arc.center[1], arc.center[0]) if self.plane == "XZ" else arc.center

    def named(self, center: Point) -> tuple[float, float]:
        return (center[1], center[0]) if self.plane == "XZ" else center

    def pose(self, base: Pose | list[float], point: Point, normal: float | None = None) -> list[float]:
        """``base`` with its in-plane coordinates replaced (and its normal one, if given)."""
        pose = list(base)
        pose[self.first], pose[self.second] = point
        if normal is not None:
            pose[self.normal] = normal
        return pose


@dataclass
class Queued:
    """A compensated move not yet handed on: its end may still move back into a concave corner."""

    origin: Move                 # the programmed move: what compensation does not change comes from it
    kind: str                    # "rapid" | "linear" | "arc"
    end: list[float]
    feed: float
    direction: Point = (0.0, 0.0)  # straight moves: the programmed direction, to detect reversal
    center: Point | None = None    # arcs, in the frame
    turn: int = 0                  # arcs: +1 counter-clockwise, -1 clockwise
    sweep: float = 0.0             # arcs: the angle swept when queued

    def to_move(self, start: Pose, frame: Frame) -> Move:
        arc = None
        if self.center is not None:
            closed = math.dist(frame.point(start), frame.point(self.end)) < 1e-9
            arc = Arc(frame.named(self.center), frame.plane, self.turn, 1 if closed else 0)
        return replace(self.origin, kind=self.kind, start=start, end=tuple(self.end), feed=self.feed, arc=arc)
