"""Cutter compensation of a batch: its runs of plain line-line corners in one loop.

Most corners of a CAM contour under G41/G42 are straight on or inside (concave) corners between
two straight moves.  For those the compensated path needs no look at anything but the programmed
points, so ``comp_lines`` computes a whole run of them, one after the other, with the very
operations of the stage's ``_straight`` (``comp_geometry``'s ``line_corner``, ``at``, ``cut_back`` and
``reverses``, in the same order: the same bits), without a record per move, and the run goes on to
the next stage as one piece of a ``Batch``.  The compiled core has it in C (``csrc/speedups_comp.c``);
neither needs numpy.  Whatever needs more (an arc, an outside corner's arc, a move without motion in
the plane, a corner the tool refuses) is left to the stage's own code for single moves, and the run
goes on after it: a batch gives the moves, events and errors that its moves would give one by one.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from edingcnc_lang import speedups
from edingcnc_lang.canon import Batch, Pose
from edingcnc_lang.errors import EcncError
from edingcnc_lang.pipeline.comp_geometry import CONCAVE_TOLERANCE, HALF_PI, LEFT, Point, Queued, side_angle

if TYPE_CHECKING:
    from collections.abc import Sequence

    from edingcnc_lang.pipeline.cutter_comp import CutterCompensation

# where a run leaves the stage: the last move's compensated end (x, y), its programmed direction (x, y),
# where it starts (x, y, the stage's endpoint) and its programmed end (x, y)
Last = tuple[float, float, float, float, float, float, float, float]


def comp_lines(ends: Sequence[Pose], index: int, stop: int, first: int, second: int, side: int, radius: float,
               program: Point, current: Point, direction: Point, endpoint: Point
               ) -> tuple[int, Point, list[Pose], Last]:
    """Compensate the straight moves ending at ``ends[index:stop]`` while their corners are plain.

    The stage holds one straight move back (programmed ``direction``, starting at ``endpoint``, its
    compensated end ``current``, programmed end ``program``); ``first`` and ``second`` are the plane's
    axes in a pose.  Stops before a move without motion in the plane, with an outside corner, or whose
    corner the stage refuses (a fold or a reversal).
    Returns how many moves it took; where the held move ends, cut back into the first corner; the
    ends of the taken moves but the last, as poses; and the last one as ``Last`` (held back in turn).
    """
    sx, sy = program
    cx, cy = current
    qx, qy = direction
    px, py = endpoint
    left = side == LEFT
    gamma = side_angle(side)
    atan2, cos, sin, tan = math.atan2, math.cos, math.sin, math.tan
    turn, low, high = 2 * math.pi, -CONCAVE_TOLERANCE, math.pi + CONCAVE_TOLERANCE
    held, poses, previous = (0.0, 0.0), [], None
    append = poses.append
    plane_xy = (first, second) == (0, 1)
    k = index
    for k, pose in enumerate(ends[index:stop], index):  # noqa: B007 (k: how far the run got)
        tx, ty = pose[first], pose[second]
        if tx == sx and ty == sy:  # no motion in the plane
            break
        theta = atan2(cy - sy, cx - sx)  # line_corner(heading(start, current), heading(start, target))
        alpha = atan2(ty - sy, tx - sx)
        if left:
            if theta < alpha:
                theta = theta + turn
            beta = theta - alpha - HALF_PI
        else:
            if alpha < theta:
                alpha = alpha + turn
            beta = alpha - theta - HALF_PI
        if beta < low or beta > high:  # inside_corner: cut the move before back (half_corner, cut_back)
            half = (beta + math.pi) / 2.0
            if half == 0.0:
                break
            distance, theta = radius / tan(half), theta + gamma
            hx = cx + distance * cos(theta)
            hy = cy + distance * sin(theta)
            if qx * (hx - px) + qy * (hy - py) < 0:  # reverses
                break
        elif beta > CONCAVE_TOLERANCE:  # outside_corner: the tool goes round it
            break
        else:
            hx, hy = cx, cy
        if previous is None:
            held = (hx, hy)
        elif plane_xy:
            _, _, z, a, b, c = previous
            append((hx, hy, z, a, b, c))
        else:
            made = list(previous)
            made[first], made[second] = hx, hy
            append(tuple(made))
        previous = pose
        qx, qy, px, py = tx - sx, ty - sy, hx, hy
        alpha = alpha + gamma  # at(target, radius, alpha + gamma)
        cx = tx + radius * cos(alpha)
        cy = ty + radius * sin(alpha)
        sx, sy = tx, ty
    else:
        k = stop
    return k - index, held, poses, (cx, cy, qx, qy, px, py, sx, sy)


LINES = speedups.compiled("comp_lines") or comp_lines


def _steady(stage: CutterCompensation) -> bool:
    """Whether the stage holds exactly one straight move back, as after any line-line corner."""
    queue = stage.queue
    return (len(queue) == 1 and isinstance(queue[0], Queued) and queue[0].center is None
            and stage.endpoint is not None and bool(stage.side) and not stage.first)


def _take_run(stage: CutterCompensation, batch: Batch, index: int, stop: int) -> int:
    """Compensate a run of batch moves from ``index`` (before ``stop``) with plain corners: hand on the
    move the stage holds and all but the last of them, and hold the last one back, as the stage does
    move by move.  Returns how many it took (0: the stage takes move ``index`` itself)."""
    frame, queued = stage.frame, stage.queue[0]
    assert isinstance(queued, Queued) and stage.endpoint is not None
    taken, held, poses, (ex, ey, dx, dy, hx, hy, tx, ty) = LINES(
        batch.ends, index, stop, frame.first, frame.second, stage.side, stage.radius, stage.program,
        frame.point(stage.current), queued.direction, stage.endpoint)
    if not taken:
        return 0
    queued.end = frame.pose(queued.end, held)
    stage._dequeue()
    if poses:
        stage._hand_on_run(batch, index, poses)
    last = index + taken - 1
    move = batch.move(last, batch.ends[last - 1] if last else batch.start)
    stage.queue.append(Queued(move, move.kind, frame.pose(move.end, (ex, ey)), move.feed, direction=(dx, dy)))
    stage.endpoint = (hx, hy)
    stage.current = frame.pose(move.end, (ex, ey))
    stage.program = (tx, ty)
    return taken


def take_batch(stage: CutterCompensation, batch: Batch) -> None:
    """Compensate ``batch`` (without G96) on ``stage``: runs of plain corners in one loop, every other
    move on its own; a move refused says how many of the batch were made before it (``EcncError.done``)."""
    index, count, arcs = 0, len(batch), batch.arcs
    stop = count if arcs is None else 0  # the next arc (or the end): runs stop before it
    while index < count:
        if stop <= index and arcs is not None:
            stop = next((k for k in range(index, count) if arcs[k] is not None), count)
        if index < stop and _steady(stage):
            taken = _take_run(stage, batch, index, stop)
            if taken:
                index += taken
                continue
        try:
            stage._take(batch.move(index, batch.ends[index - 1] if index else batch.start))
        except EcncError as err:
            err.done = index
            raise
        index += 1
