"""One move as a timed path: its geometry, its samples at a given speed, and the speeds and
accelerations those samples ask of each axis.

The motion stage uses these to pick the speed a move runs at (the programmed feed, capped by
the axis limits; rapids as fast as the limits allow) and to check the joints against their
``maxVelocity``/``maxAcceleration``.  Dynamics are measured on the samples themselves, so the
same code serves Cartesian axes and joints, lines and arcs, and any kinematics.
``geometry_of`` is also used for limit checks without sampling, so numpy is only imported by
the functions that sample or measure.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from collections.abc import Sequence
from typing import TYPE_CHECKING, NamedTuple

from edingcnc_lang import speedups
from edingcnc_lang.canon import PLANES, Arc, Move, Pose
from edingcnc_lang.records import record

if TYPE_CHECKING:
    import numpy as np

# On a curve the acceleration goes to two jobs: turning (v^2 / r) and speeding up along it.  As in
# LinuxCNC, the turn may use at most sqrt(3)/2 of an axis' (or joint's) acceleration and the change
# of speed gets what is left, so that together they stay within the limit (docs/planner.md).
CURVATURE_SHARE = math.sqrt(3.0) / 2.0
_COMPILED_FRAME = speedups.compiled("arc_frame")  # arc_frame in C, or None on the Python core


_TURN = 2.0 * math.pi


def arc_sweep(start_angle: float, end_angle: float, turns: int, full_circle_epsilon: float = 1e-12) -> float:
    """Signed angle swept (radians): ``turns`` > 0 counter-clockwise, < 0 clockwise.

    |turns| = 1 goes the short way round in the requested direction (a full circle when start
    and end are less than ``full_circle_epsilon`` radians apart, as ``[INTERPRETER]
    fullCircleThetaEpsilon`` decides); each further turn adds one full revolution.
    """
    if turns == 0:
        raise ValueError("turns must be non-zero: its sign is the direction of the arc")
    direction = 1.0 if turns > 0 else -1.0
    sweep = (direction * (end_angle - start_angle)) % (2.0 * math.pi)
    if sweep <= full_circle_epsilon or sweep == 0.0:
        sweep = 2.0 * math.pi
    return direction * (sweep + 2.0 * math.pi * (abs(turns) - 1))


class ArcFrame(NamedTuple):
    """An arc's circle in its plane: in-plane axes ``u``, ``v``, centre, start and end radius,
    start angle, signed sweep, and its XYZ length (helix included).  A named tuple: a batch's arcs are
    read as rows of numbers (``motion.arc_table``), and a frozen dataclass took five times as long to build."""

    u: int
    v: int
    center: tuple[float, float]
    r0: float
    r1: float
    start_angle: float
    sweep: float
    linear: float


def arc_frame(start: Sequence[float], end: Sequence[float], center: Sequence[float], normal: int, turns: int,
              full_circle_epsilon: float = 1e-12) -> ArcFrame:
    """The circle of an arc about ``center`` in the plane normal to axis ``normal`` (see ``sample_arc``)."""
    u, v = (normal + 1) % 3, (normal + 2) % 3
    cu, cv = float(center[u]), float(center[v])
    return ArcFrame(u, v, (cu, cv), *_circle(start, end, cu, cv, u, v, normal, turns, full_circle_epsilon))


def _circle(start: Sequence[float], end: Sequence[float], cu: float, cv: float, u: int, v: int, normal: int,
            turns: int, full_circle_epsilon: float) -> tuple[float, float, float, float, float]:
    """``arc_frame``'s numbers after its centre: start and end radius, start angle, signed sweep, XYZ length."""
    su, sv = start[u] - cu, start[v] - cv
    r0 = math.hypot(su, sv)
    r1 = math.hypot(end[u] - cu, end[v] - cv)
    a0 = math.atan2(sv, su)
    sweep = arc_sweep(a0, math.atan2(end[v] - cv, end[u] - cu), turns, full_circle_epsilon)
    return r0, r1, a0, sweep, math.hypot(abs(sweep) * (r0 + r1) / 2.0, end[normal] - start[normal])


ARC_ROW = 10  # the numbers of an arc in arc_frame_rows: move index, u, v, centre (2), r0, r1, start angle, sweep, linear


def arc_frame_rows(start: Pose, ends: Sequence[Pose], arcs: Sequence[Arc | None]) -> list[float]:
    """The frames of a batch's arcs (moves from ``start`` through ``ends``, arcs where ``arcs`` has one), as
    one flat list of ``ARC_ROW`` numbers per arc: its index among the moves, then its ``arc_frame``.

    The planner and the motion stage read a batch's arcs as columns (``motion.arc_table``): a frame per
    arc, each the very numbers ``arc_geometry(...).frame`` gives (``arc_circle``, then ``_circle``'s steps,
    without a Geometry, an ArcFrame or a call per arc: tests/kinematics/test_arc_frame_rows.py holds the two
    equal).  The reference for ``_speedups.arc_frame_rows``."""
    rows: list[float] = []
    extend, hypot, atan2 = rows.extend, math.hypot, math.atan2
    circles: dict[tuple[str, int, int], tuple[int, int, int, int, float]] = {}  # arc_circle's, by its arguments
    previous = start
    for index, arc in enumerate(arcs):
        end = ends[index]
        if arc is not None:
            key = (arc.plane, arc.turn, arc.full_turns)
            circle = circles.get(key)
            if circle is None:
                circle = circles[key] = arc_circle(arc)
                if not circle[3]:
                    raise ValueError("turns must be non-zero: its sign is the direction of the arc")  # (arc_sweep's)
            u, v, normal, turns, epsilon = circle
            c1, c2 = arc.center
            cu, cv = (float(c2), float(c1)) if u == 2 else (float(c1), float(c2))  # (XZ: named x, z; u is z)
            # _circle and arc_sweep, inlined (a call each took a fifth of the time an arc took here)
            su, sv = previous[u] - cu, previous[v] - cv
            r0, r1 = hypot(su, sv), hypot(end[u] - cu, end[v] - cv)
            a0 = atan2(sv, su)
            direction = 1.0 if turns > 0 else -1.0
            sweep = (direction * (atan2(end[v] - cv, end[u] - cu) - a0)) % _TURN
            if sweep <= epsilon or sweep == 0.0:
                sweep = _TURN
            sweep = direction * (sweep + _TURN * (abs(turns) - 1))
            extend((float(index), float(u), float(v), cu, cv, r0, r1, a0, sweep,
                    hypot(abs(sweep) * (r0 + r1) / 2.0, end[normal] - previous[normal])))
        previous = end
    return rows


@dataclass
class Geometry:
    """The path of a move in machine coordinates; ``center`` is None for a straight move.

    Not a frozen dataclass, though nothing changes one once made: the motion stage makes one for
    every move it samples, and a frozen one took several times as long to build."""

    start: tuple[float, ...]
    end: tuple[float, ...]
    center: tuple[float, float, float] | None = None
    normal: int = 2
    turns: int = 1
    full_circle_epsilon: float = 1e-12

    def sample(self, speed: float, dt: float) -> tuple[np.ndarray, np.ndarray]:
        """Times after the move start and poses, every ``dt`` at ``speed`` (mm/s, or deg/s if rotary only)."""
        from edingcnc_lang.kinematics.sampling import sample_arc, sample_line

        if self.center is None:
            return sample_line(self.start, self.end, speed, dt)
        return sample_arc(self.start, self.end, self.center, self.normal, self.turns, speed, dt,
                          self.full_circle_epsilon)

    @property
    def frame(self) -> ArcFrame:
        """The circle of an arc move (not for straight moves), computed once: the planner and the limits
        report both ask (kept by hand: functools.cached_property takes a lock on every read)."""
        frame: ArcFrame | None = self.__dict__.get("_frame")
        if frame is None:
            assert self.center is not None
            if _COMPILED_FRAME is None:
                frame = arc_frame(self.start, self.end, self.center, self.normal, self.turns, self.full_circle_epsilon)
            else:
                frame = ArcFrame._make(_COMPILED_FRAME(self.start, self.end, self.center, self.normal, self.turns,
                                                       self.full_circle_epsilon))
            self.__dict__["_frame"] = frame
        return frame

    def chord_speed(self, max_velocity: np.ndarray) -> float:
        """Path speed at which the straight chord of the move keeps every axis within its velocity limit
        (the first guess of the motion stage's sampling of a rapid)."""
        import numpy as np

        delta = np.abs(np.subtract(self.end, self.start))
        linear = float(np.linalg.norm(delta[:3]))
        length = linear if linear > 0.0 else float(np.linalg.norm(delta[3:]))
        if length == 0.0:
            return float(np.min(max_velocity[:3])) if np.isfinite(max_velocity[:3]).any() else 1.0
        with np.errstate(divide="ignore"):
            bound = np.where(delta > 0.0, max_velocity * length / delta, np.inf)
        speed = float(bound.min())
        return speed if math.isfinite(speed) else 1000.0

    def points_at(self, s: np.ndarray) -> np.ndarray:
        """Poses at fractions ``s`` (0..1) of the path: for arcs, of the sweep; s = 1 is the end exactly."""
        import numpy as np

        if self.center is None:
            p0, p1 = np.asarray(self.start, dtype=float), np.asarray(self.end, dtype=float)
            pts = p0 + s[:, None] * (p1 - p0)
            pts[s >= 1.0] = p1
            return pts
        from edingcnc_lang.kinematics.sampling import arc_points

        return arc_points(self.start, self.end, self.frame, s)


def geometry_of(move: Move) -> Geometry:
    """The path of a canon move (arcs: centre in all three linear axes, normal axis, signed turns)."""
    if move.arc is None:
        return Geometry(move.start, move.end)
    return arc_geometry(move.start, move.end, move.arc)


def arc_geometry(start: Pose, end: Pose, arc: Arc) -> Geometry:
    """The path of an arc from ``start`` to ``end``, for callers that hold no ``Move`` (a batch's columns)."""
    u, v, normal, turns, epsilon = arc_circle(arc)
    c1, c2 = arc.center
    center = list(start[:3])
    center[u], center[v] = (c2, c1) if u == 2 else (c1, c2)  # (XZ: the canon names the centre x, z; u is z)
    return Geometry(start, end, (center[0], center[1], center[2]), normal, turns, epsilon)


def arc_circle(arc: Arc) -> tuple[int, int, int, int, float]:
    """What the circle of an arc is as ``Geometry`` holds it, its centre aside: the plane's axes u and v (as
    ``arc_frame`` numbers them, (normal + 1) % 3 and (normal + 2) % 3), its normal axis, the signed turns and
    the full-circle epsilon ``arc_sweep`` is given.

    Whether an arc is a full circle was decided once, by the interpreter (``Arc.full_turns``); the
    path follows that decision, never an angle epsilon of its own: infinite (always) or -1 (never)."""
    u, v, normal = PLANES[arc.plane]
    return u, v, normal, arc.turn * max(1, arc.full_turns), math.inf if arc.full_turns else -1.0


@record(frozen=True)
class Dynamics:
    """Peak absolute velocity and acceleration of each axis along a sampled move."""

    velocity: np.ndarray
    acceleration: np.ndarray

    def ratios(self, max_velocity: np.ndarray, max_acceleration: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Per axis, how far the move goes beyond its limits (1 = exactly at the limit)."""
        return self.velocity / max_velocity, self.acceleration / max_acceleration

    def speed_factor(self, max_velocity: np.ndarray, max_acceleration: np.ndarray) -> float:
        """The factor to divide the path speed by to stay within both limits (velocity ~ v, accel ~ v^2)."""
        v_ratio, a_ratio = self.ratios(max_velocity, max_acceleration)
        return max(float(v_ratio.max(initial=0.0)), math.sqrt(float(a_ratio.max(initial=0.0))))


def dynamics(start_time: float, start: np.ndarray, t: np.ndarray, points: np.ndarray, dt: float) -> Dynamics:
    """Velocities between consecutive samples (from the move's start point on) and accelerations
    between consecutive steps inside the move.

    Steps shorter than dt/2 (the shortened last step of a move) are left out of the
    accelerations: over such a short step rounding dominates the difference quotient.  The
    velocity step where one move meets the next is not an acceleration of either (the
    controller's look-ahead blends it), so it is not measured here.
    """
    import numpy as np

    times = np.concatenate(([start_time], t))
    pts = np.vstack((start, points))
    steps = np.diff(times)
    moving = steps > 0.0
    width = pts.shape[1]
    if not moving.any():
        return Dynamics(np.zeros(width), np.zeros(width))
    velocity = np.diff(pts, axis=0)[moving] / steps[moving, None]
    peak_velocity = np.abs(velocity).max(axis=0)
    long_steps = steps[moving]
    usable = (long_steps[:-1] >= dt / 2.0) & (long_steps[1:] >= dt / 2.0)
    if not usable.any():
        return Dynamics(peak_velocity, np.zeros(width))
    between = (long_steps[:-1] + long_steps[1:])[usable, None] / 2.0
    acceleration = np.diff(velocity, axis=0)[usable] / between
    return Dynamics(peak_velocity, np.abs(acceleration).max(axis=0))


def move_length(move: Move) -> float:
    """How far the tool travels along ``move`` in X, Y and Z (mm), as the planner and GetJobDistance
    count it: the helix of an arc with all its turns (``Arc.full_turns``), else the straight line."""
    if move.arc is None:
        return math.dist(move.start[:3], move.end[:3])
    return geometry_of(move).frame.linear


def move_points(move: Move, max_step: float = 0.1) -> np.ndarray:
    """Poses along ``move`` (an N x 6 array, start and end included) at most ``max_step`` mm apart
    along its path, as the machine moves: arcs on their circle, the other axes in proportion."""
    import numpy as np

    if not max_step > 0.0:
        raise ValueError(f"max_step must be greater than 0, not {max_step!r}")
    count = max(1, math.ceil(move_length(move) / max_step))
    return geometry_of(move).points_at(np.linspace(0.0, 1.0, count + 1))
