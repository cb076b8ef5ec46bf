"""How far a move reaches, for the exact limit check of a machine whose joints are its axes.

A straight move reaches no further than its end point (its start was checked as the end of the
move before); an arc may bulge beyond both ends, to the extremes of its circle that it sweeps over.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

from edingcnc_lang.canon import PLANES, Move, Pose
from edingcnc_lang.kinematics.base import as_pose
from edingcnc_lang.kinematics.trajectory import geometry_of
from edingcnc_lang.machine.geometry import arc_extremes, circle_within, sweep


def reach_points(move: Move, lower: Sequence[float], upper: Sequence[float]) -> list[Pose]:
    """The points that bound ``move``: its end and, for an arc, the extremes of its circle it sweeps
    over; those are left out when the whole circle lies within ``lower``..``upper`` (the usual case),
    since then they cannot be outside."""
    points = [move.end]
    if move.arc is None:
        return points
    first, second, _ = PLANES[move.arc.plane]
    geo = geometry_of(move)
    assert geo.center is not None
    center = (geo.center[first], geo.center[second])
    s, e = (move.start[first], move.start[second]), (move.end[first], move.end[second])
    radius = math.hypot(s[0] - center[0], s[1] - center[1])
    if circle_within(center, radius, (first, second), lower, upper):
        return points
    clockwise = move.arc.turn < 0
    # the interpreter's decision: a full circle, or the arc between its ends (never a circle)
    angle = 2 * math.pi if move.arc.full_turns else sweep(s, center, e, clockwise, -1.0, r_form=True)[0]
    start_angle = math.atan2(s[1] - center[1], s[0] - center[0])
    for p1, p2 in arc_extremes(center, radius, start_angle, angle, clockwise):
        extreme = list(move.end)
        extreme[first], extreme[second] = p1, p2
        points.append(as_pose(extreme))
    return points
