"""Cutter compensation of a batch: its runs of corners between straight moves in one loop.

Most corners of a CAM contour under G41/G42 are corners between two straight moves: straight on,
inside (concave, the move before cut back) or outside (the tool goes round the corner point).  For
those the compensated path needs no look at anything but the programmed points, so ``comp_lines``
computes a whole run of them, one after the other, with the very operations of the stage's
``_straight`` (``comp_geometry``'s ``line_corner``, ``at``, ``cut_back`` and ``reverses``, in the same
order: the same bits), without a record per move, and the run goes on to
the next stage as one piece of a ``Batch``, with the arcs (or rapids) that go round its outside
corners.  The compiled core has it in C (``csrc/speedups_comp.c``); neither needs numpy.  Whatever
needs more (an arc, a move without motion in the plane, a corner the tool refuses) is left to the
stage's own code for single moves, and the run goes on after it: a batch gives the moves, events and
errors that its moves would give one by one.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING

from edingcnc_lang import speedups
from edingcnc_lang.canon import Arc, Batch, Pose
from edingcnc_lang.errors import EcncError
from edingcnc_lang.pipeline.comp_geometry import CONCAVE_TOLERANCE, HALF_PI, LEFT, Point, Queued, side_angle

if TYPE_CHECKING:
    from collections.abc import Sequence

    from edingcnc_lang.pipeline.cutter_comp import CutterCompensation

# What a run needs of the stage and leaves it: the held move's programmed end (x, y), compensated end
# (x, y), programmed direction (x, y) and compensated start (x, y, the stage's endpoint), and the
# compensated end's coordinate on the plane's normal axis.
State = tuple[float, float, float, float, float, float, float, float, float]
# a batch's columns: kinds, lines, ends, feeds
Columns = tuple["Sequence[str]", "Sequence[int]", "Sequence[Pose]", "Sequence[float]"]
# the moves a run hands on, as columns of a batch, and its arcs column (None: all straight)
Made = tuple["Sequence[str]", "Sequence[int]", "Sequence[Pose]", "Sequence[float]", "Sequence[Arc | None] | None"]
# an outside corner: the batch move it comes before, where the tool goes round it to, and the corner
Corner = tuple[int, Pose, float, float]


def comp_lines(columns: Columns, index: int, stop: int, frame: tuple[int, int, int, str], side: int, radius: float,
               state: State, after_arc: bool, arc: type[Arc]) -> tuple[int, Point, Made, State]:
    """Compensate the straight moves ``index`` to ``stop - 1`` of a batch's ``columns`` while their corners are plain.

    The stage holds one move back, as ``state`` says: a straight one, or an arc (``after_arc``: then only a
    straight-on corner, a tangent, may follow it here); ``frame`` is the plane's first, second and
    normal axes in a pose and its name.  Stops before a move without motion in the plane or whose
    corner the stage refuses (a fold or a reversal), and before an outside corner whose arc might be
    closed.  Returns how many moves it took; where the held move ends (cut back into an inside corner);
    the moves it hands on after the held one (all it took but the last, each after the ``arc`` record,
    or the rapid, that goes round the outside corner before it); and the state the last move leaves,
    held back in turn.
    """
    kinds, lines, ends, feeds = columns
    first, second, normal, plane = frame
    axes = first, second, normal
    sx, sy, cx, cy, qx, qy, px, py, level = state
    left = side == LEFT
    gamma = side_angle(side)
    atan2, cos, sin, tan = math.atan2, math.cos, math.sin, math.tan
    pi, half_pi, tolerance = math.pi, HALF_PI, CONCAVE_TOLERANCE  # locals: the loop looks them up every move
    turn, low, high = 2 * pi, -tolerance, pi + tolerance
    held, previous = (0.0, 0.0), None
    poses: list[Pose] = []
    corners: list[Corner] = []
    append = poses.append
    plane_xy = axes == (0, 1, 2)
    # no counter (enumerate makes an int a move): the moves taken so far are the held one (the first,
    # ``previous`` set) and those handed on (``poses``)
    for pose in ends[index:stop]:
        tx, ty = pose[first], pose[second]
        if tx == sx and ty == sy:  # no motion in the plane
            break
        theta = atan2(cy - sy, cx - sx)  # line_corner(heading(start, current), heading(start, target))
        alpha = atan2(ty - sy, tx - sx)
        if left:
            if theta < alpha:
                theta = theta + turn
            beta = theta - alpha - half_pi
        else:
            if alpha < theta:
                alpha = alpha + turn
            beta = alpha - theta - half_pi
        alpha = alpha + gamma
        if beta < low or beta > high:  # inside_corner: cut the move before back (half_corner, cut_back)
            half = (beta + pi) / 2.0
            if half == 0.0 or (after_arc and previous is None):
                break
            distance, theta = radius / tan(half), theta + gamma
            hx = cx + distance * cos(theta)
            hy = cy + distance * sin(theta)
            if qx * (hx - px) + qy * (hy - py) < 0.0:  # reverses
                break
            px, py = hx, hy
        elif beta > tolerance:  # outside_corner: round the corner point, from the tool to beside it
            if (after_arc and previous is None) or qx * (cx - px) + qy * (cy - py) < 0.0:  # reverses
                break
            px = sx + radius * cos(alpha)  # at(start, radius, alpha + gamma)
            py = sy + radius * sin(alpha)
            if abs(px - cx) < 1e-9 and abs(py - cy) < 1e-9:  # an arc that may be closed: a whole circle
                break
            hx, hy = cx, cy
            moved = list(pose)
            moved[first], moved[second], moved[normal] = px, py, level
            corners.append((index + len(poses) + (previous is not None), tuple(moved), sx, sy))  # this move's index
        else:
            hx = px = cx
            hy = py = cy
        if previous is None:
            held = (hx, hy)
        elif plane_xy:
            _, _, z, a, b, c = previous
            append((hx, hy, z, a, b, c))
        else:
            moved = list(previous)
            moved[first], moved[second] = hx, hy
            append(tuple(moved))
        previous = pose
        qx = tx - sx
        qy = ty - sy
        cx = tx + radius * cos(alpha)  # at(target, radius, alpha + gamma)
        cy = ty + radius * sin(alpha)
        sx, sy, level = tx, ty, pose[normal]
    made = _with_corners(kinds, lines, feeds, index, poses, corners, plane, -1 if left else 1, arc)
    return len(poses) + (previous is not None), held, made, (sx, sy, cx, cy, qx, qy, px, py, level)


def _with_corners(kinds: Sequence[str], lines: Sequence[int], feeds: Sequence[float], index: int, poses: list[Pose],
                  corners: list[Corner], plane: str, turn: int, arc: type[Arc]) -> Made:
    """The columns of the moves ``index``.. ending at ``poses``, each outside corner's move before its move."""
    stop = index + len(poses)
    if not corners:
        return kinds[index:stop], lines[index:stop], poses, feeds[index:stop], None
    made: tuple[list[str], list[int], list[Pose], list[float], list[Arc | None]] = ([], [], [], [], [])
    out_kinds, out_lines, out_ends, out_feeds, out_arcs = made

    def moves(low: int, high: int) -> None:
        out_kinds.extend(kinds[low:high])
        out_lines.extend(lines[low:high])
        out_ends.extend(poses[low - index:high - index])
        out_feeds.extend(feeds[low:high])
        out_arcs.extend([None] * (high - low))

    at = index
    for k, corner, x, y in corners:
        moves(at, k)
        straight = kinds[k] != "linear"  # a rapid goes straight round the corner
        out_kinds.append("rapid" if straight else "arc")
        out_lines.append(lines[k])
        out_ends.append(corner)
        out_feeds.append(0.0 if straight else feeds[k])
        out_arcs.append(None if straight else arc((y, x) if plane == "XZ" else (x, y), plane, turn, 0))
        at = k
    moves(at, stop)
    if not any(out_arcs):  # rapids only: an arcs column of None says so
        return out_kinds, out_lines, out_ends, out_feeds, None
    return made


LINES = speedups.compiled("comp_lines") or comp_lines


def _steady(stage: CutterCompensation) -> bool:
    """Whether the stage holds exactly one move back, as after any corner but the entry arc's."""
    queue = stage.queue
    return (len(queue) == 1 and isinstance(queue[0], Queued) and stage.endpoint is not None and bool(stage.side)
            and not stage.first)


def _take_run(stage: CutterCompensation, batch: Batch, index: int, stop: int) -> int:
    """Compensate a run of batch moves from ``index`` (before ``stop``) with plain corners: hand on the
    move the stage holds, the corners and all but the last of the moves, and hold the last one back,
    as the stage does move by move.  Returns how many it took (0: the stage takes move ``index`` itself)."""
    frame, queued, current = stage.frame, stage.queue[0], stage.current
    assert isinstance(queued, Queued) and stage.endpoint is not None
    state = (*stage.program, current[frame.first], current[frame.second], *queued.direction, *stage.endpoint,
             current[frame.normal])
    taken, held, made, state = LINES((batch.kinds, batch.lines, batch.ends, batch.feeds), index, stop,
                                     (frame.first, frame.second, frame.normal, frame.plane), stage.side,
                                     stage.radius, state, queued.center is not None, Arc)
    if not taken:
        return 0
    queued.end = frame.pose(queued.end, held)
    stage._dequeue()
    if made[0]:
        stage._hand_on_run(batch, made)
    sx, sy, cx, cy, dx, dy, hx, hy, _ = state
    last = index + taken - 1
    move = batch.move(last, batch.ends[last - 1] if last else batch.start)
    stage.queue.append(Queued(move, move.kind, frame.pose(move.end, (cx, cy)), move.feed, direction=(dx, dy)))
    stage.endpoint = (hx, hy)
    stage.current = frame.pose(move.end, (cx, cy))
    stage.program = (sx, sy)
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
