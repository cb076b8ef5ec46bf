"""Plane geometry of cutter radius compensation: sweeps, corner points and the queued moves.

Everything here works in the active plane's (first, second) frame (``canon.PLANES``), so the
compensation stage can think of the XY plane only, whatever plane is selected.  A run of plain
line-line corners in a batch is computed by ``comp_runs.comp_lines`` with the very operations of the
corner functions below, in the same order, so it gets the bits the moves get one by one.
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

HALF_PI = math.pi / 2

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


# ---------------------------------------------------------------- a corner between two straight moves
# (LinuxCNC's convert_straight_comp2): the tool is at ``current``, a radius to the side of the corner
# ``start``, and the next move goes on from ``start`` to ``target``.

def heading(origin: Point, toward: Point) -> float:
    """The direction (radians) from ``origin`` to ``toward``."""
    return math.atan2(toward[1] - origin[1], toward[0] - origin[0])


def line_corner(side: int, theta: float, alpha: float) -> tuple[float, float, float, float]:
    """``theta`` (corner to tool) and ``alpha`` (the next move) brought into one turn; with the turn
    ``beta`` the tool makes at the corner and ``gamma``, the tool's side as an angle from the move.

    Returns (theta, alpha, beta, gamma); the next move's compensated end is
    ``at(target, radius, alpha + gamma)``.
    """
    if side == LEFT:
        if theta < alpha:
            theta = theta + 2 * math.pi
        return theta, alpha, theta - alpha - HALF_PI, side_angle(side)
    if alpha < theta:
        alpha = alpha + 2 * math.pi
    return theta, alpha, alpha - theta - HALF_PI, side_angle(side)


def side_angle(side: int) -> float:
    """The tool's side as an angle from the direction of the move."""
    return HALF_PI if side == LEFT else -HALF_PI


def inside_corner(beta: float) -> bool:
    """Whether the corner turns into the tool (concave): the previous move is cut back."""
    return beta < -CONCAVE_TOLERANCE or beta > math.pi + CONCAVE_TOLERANCE


def outside_corner(beta: float) -> bool:
    """Whether a corner that is not inside turns away from the tool (convex): the tool goes round it."""
    return beta > CONCAVE_TOLERANCE


def half_corner(beta: float) -> float:
    """Half the angle of an inside corner (0: the moves fold back onto each other)."""
    return (beta + math.pi) / 2.0


def cut_back(radius: float, current: Point, theta: float, gamma: float, half: float) -> Point:
    """Where the tool touches both sides of an inside corner (``half`` from ``half_corner``, not 0)."""
    return at(current, radius / math.tan(half), theta + gamma)


def reverses(direction: Point, endpoint: Point, point: Point) -> bool:
    """Whether moving a straight move's end from ``endpoint`` to ``point`` turns it against its
    programmed ``direction`` (the tool would gouge)."""
    return direction[0] * (point[0] - endpoint[0]) + direction[1] * (point[1] - endpoint[1]) < 0


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


# A lathe tool's controlled point (the imaginary tip its offsets were measured to) seen from the
# nose's centre, by its orientation 1..8 (the tool table's, #5700 + n), in tool radii along machine
# X and Z: the manual's figure (pp. 5-6: orientation 2 is X -r, Z -r; 9 has none) and LinuxCNC's
# latheorigin_x/z (interp_queue.cc), which agree.  Compensation moves the nose centre; the machine
# is sent the controlled point.
TIP_X = {1: -1, 2: -1, 6: -1, 3: 1, 4: 1, 8: 1}
TIP_Z = {2: -1, 3: -1, 7: -1, 1: 1, 4: 1, 5: 1}


def tip_shift(orientation: int, radius: float) -> tuple[float, float]:
    """(X, Z) from the nose centre to the controlled point; (0, 0) for 0 (a mill's tool), 9 and others."""
    return TIP_X.get(orientation, 0) * radius, TIP_Z.get(orientation, 0) * radius


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

    def arc(self, start: Pose, frame: Frame) -> Arc | None:
        """The circle of the move handed on from ``start`` (None: straight); ends that meet: a full circle."""
        if self.center is None:
            return None
        closed = math.dist(frame.point(start), frame.point(self.end)) < 1e-9
        return Arc(frame.named(self.center), frame.plane, self.turn, 1 if closed else 0)

    def to_move(self, start: Pose, frame: Frame) -> Move:
        return replace(self.origin, kind=self.kind, start=start, end=tuple(self.end), feed=self.feed,
                       arc=self.arc(start, frame))
