"""How far a move reaches, for the exact limit check of a machine whose joints are its axes.

A straight move reaches no further than its end point (its start was checked as the end of the
move before); an arc may bulge beyond both ends, to the extremes of its circle that it sweeps over.
A batch of moves reaches no further than the bounds of its end points and its arcs' extremes.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from edingcnc_lang import speedups
from edingcnc_lang.canon import PLANES, Arc, Pose
from edingcnc_lang.kinematics.base import as_pose
from edingcnc_lang.kinematics.trajectory import ArcFrame, Geometry, arc_geometry
from edingcnc_lang.machine.geometry import arc_extremes, circle_within

if TYPE_CHECKING:
    from edingcnc_lang.motion.arc_table import ArcTable


def reach_points(start: Pose, end: Pose, arc: Arc | None, lower: Sequence[float],
                 upper: Sequence[float]) -> list[Pose]:
    """The points that bound a move from ``start`` to ``end``: its end and, for an arc, the extremes of
    its circle it sweeps over (``arc_extremes_of``); those are left out when the whole circle lies within
    ``lower``..``upper`` (the usual case, found here without building the arc's frame), since then they
    cannot be outside.

    Takes the move's fields rather than a ``Move``, so a batch's columns need not become records."""
    if arc is None:
        return [end]
    first, second, _ = PLANES[arc.plane]
    center = (arc.center[1], arc.center[0]) if arc.plane == "XZ" else arc.center  # XZ is named (x, z)
    radius = max(math.hypot(start[first] - center[0], start[second] - center[1]),
                 math.hypot(end[first] - center[0], end[second] - center[1]))
    if circle_within(center, radius, (first, second), lower, upper):
        return [end]
    return [end, *arc_extremes_of(arc_geometry(start, end, arc))]


def beyond(start: Pose, end: Pose, arc: Arc | None, lower: Sequence[float],
           upper: Sequence[float]) -> tuple[int, float] | None:
    """The first axis, and its value, at which a move reaches outside ``lower``..``upper``; None inside."""
    return first_outside(reach_points(start, end, arc, lower, upper), lower, upper)


def arcs_beyond(start: Pose, ends: Sequence[Pose], arcs: Sequence[Arc | None], lower: Sequence[float],
                upper: Sequence[float]) -> bool:
    """Whether an arc of a batch (moves from ``start`` through ``ends``) reaches outside ``lower``..``upper``,
    found arc by arc with ``beyond``.  The reference for ``_speedups.arcs_beyond``."""
    return any(arc is not None and beyond(begin, end, arc, lower, upper) is not None
               for begin, end, arc in zip((start, *ends), ends, arcs))


# ``arcs_beyond`` on the core that runs (the untimed run's check of a batch's arcs, which never loads numpy)
batch_arcs_beyond = speedups.compiled("arcs_beyond") or arcs_beyond


def table_beyond(arcs: ArcTable, ends: Sequence[Pose], lower: Sequence[float], upper: Sequence[float]) -> bool:
    """Whether an arc of a batch's table (its moves ending at ``ends``) reaches outside ``lower``..``upper``,
    as ``beyond`` finds it arc by arc: only an arc whose circle leaves them can, at its extremes."""
    import numpy as np

    if arcs.circle_within(lower, upper).all():
        return False  # the usual case, found without the ends as an array
    points = arcs.extremes(np.array(ends, dtype=float).T, lower, upper)
    return not ((np.asarray(lower) <= points) & (points <= np.asarray(upper))).all()


def first_outside(points: Sequence[Pose], lower: Sequence[float], upper: Sequence[float]) -> tuple[int, float] | None:
    """The first axis, and its value, at which one of ``points`` lies outside ``lower``..``upper``; None inside."""
    for point in points:
        for axis, value in enumerate(point):
            if not lower[axis] <= value <= upper[axis]:
                return axis, value
    return None


def arc_extremes_of(geometry: Geometry, low: Sequence[float] | None = None,
                    high: Sequence[float] | None = None) -> list[Pose]:
    """Points where an arc reaches its extremes in its plane (its ends are counted already); none when
    its whole circle lies within ``low``..``high``, which they could then not widen.

    The one reading of an arc's reach, for the motion stage's limit check, the limits report and the
    test runner's forbidden zones: the larger of its two radii (an arc whose ends lie on slightly
    different circles, within the radius tolerance, may reach either), over its sweep (a full circle
    once, however many turns it makes).
    """
    return frame_extremes(geometry.frame, geometry.end, low, high)


def frame_extremes(frame: ArcFrame, end: Pose, low: Sequence[float] | None = None,
                   high: Sequence[float] | None = None) -> list[Pose]:
    """``arc_extremes_of`` an arc ending at ``end`` whose frame is known (a batch's, ``motion.arc_table``)."""
    radius = max(frame.r0, frame.r1)
    if low is not None and high is not None and circle_within(frame.center, radius, (frame.u, frame.v), low, high):
        return []
    sweep = abs(frame.sweep)
    clockwise = frame.sweep < 0.0
    rows = []
    for p1, p2 in arc_extremes(frame.center, radius, frame.start_angle, min(sweep, 2.0 * math.pi), clockwise):
        row = list(end)
        row[frame.u], row[frame.v] = p1, p2
        rows.append(as_pose(row))
    return rows


def column_bounds(ends: Sequence[Pose]) -> tuple[list[float], list[float]]:
    """The least and greatest value of each axis over the poses ``ends`` (not empty): what a batch's
    straight moves reach.  The reference for ``_speedups.column_bounds``.

    A column of one value (Z, A, B, C mostly) is found with one pass instead of two: ``min`` and
    ``max`` of equal values give the first of them, so the bounds are that value, bit for bit."""
    count = len(ends)
    lows: list[float] = []
    highs: list[float] = []
    for column in zip(*ends):
        value = column[0]
        if column[-1] == value and column.count(value) == count:
            lows.append(value)
            highs.append(value)
        else:
            lows.append(min(column))
            highs.append(max(column))
    return lows, highs
