"""How far a move reaches, for the exact limit check of a machine whose joints are its axes.

A straight move reaches no further than its end point (its start was checked as the end of the
move before); an arc may bulge beyond both ends, to the extremes of its circle that it sweeps over.
A batch of moves reaches no further than the bounds of its end points and its arcs' extremes.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

from edingcnc_lang.canon import PLANES, Arc, Pose
from edingcnc_lang.kinematics.base import as_pose
from edingcnc_lang.machine.geometry import arc_extremes, circle_within, sweep


def reach_points(start: Pose, end: Pose, arc: Arc | None, lower: Sequence[float],
                 upper: Sequence[float]) -> list[Pose]:
    """The points that bound a move from ``start`` to ``end``: its end and, for an arc, the extremes of
    its circle it sweeps over; those are left out when the whole circle lies within ``lower``..``upper``
    (the usual case), since then they cannot be outside.

    Takes the move's fields rather than a ``Move``, so a batch's columns need not become records."""
    points = [end]
    if arc is None:
        return points
    first, second, _ = PLANES[arc.plane]
    center = (arc.center[1], arc.center[0]) if arc.plane == "XZ" else arc.center  # XZ is named (x, z)
    s, e = (start[first], start[second]), (end[first], end[second])
    radius = math.hypot(s[0] - center[0], s[1] - center[1])
    if circle_within(center, radius, (first, second), lower, upper):
        return points
    clockwise = arc.turn < 0
    # the interpreter's decision: a full circle, or the arc between its ends (never a circle)
    angle = 2 * math.pi if arc.full_turns else sweep(s, center, e, clockwise, -1.0, r_form=True)[0]
    start_angle = math.atan2(s[1] - center[1], s[0] - center[0])
    for p1, p2 in arc_extremes(center, radius, start_angle, angle, clockwise):
        extreme = list(end)
        extreme[first], extreme[second] = p1, p2
        points.append(as_pose(extreme))
    return points


def column_bounds(ends: Sequence[Pose]) -> tuple[list[float], list[float]]:
    """The least and greatest value of each axis over the poses ``ends`` (not empty): what a batch's
    straight moves reach.  The reference for ``speedups.column_bounds``."""
    columns = list(zip(*ends))
    return [min(column) for column in columns], [max(column) for column in columns]
