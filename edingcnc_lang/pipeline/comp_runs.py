"""Cutter compensation of a long batch: its runs of plain line-line corners as arrays.

Most corners of a CAM contour under G41/G42 are straight on or inside (concave) corners between
two straight moves.  For those the compensated path needs no look at anything but the programmed
points, so a whole run is computed at once: the same corner functions as one move at a time
(``comp_geometry``), through ``ARRAYS`` (numpy arrays, the trigonometry elementwise through the very
``math`` functions, so the results are the same bits), and the run goes on to the next stage as one
piece of a ``Batch``.  Whatever needs more (an outside corner's arc, a move without motion in the
plane, a corner the tool refuses) is left to the stage's own code for single moves, and the run goes
on after it: a batch gives the moves, events and errors that its moves would give one by one.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from itertools import islice
from operator import itemgetter
from typing import TYPE_CHECKING, Any

import numpy as np

from edingcnc_lang.canon import Batch
from edingcnc_lang.pipeline.comp_geometry import (
    Ops,
    Queued,
    at,
    cut_back,
    half_corner,
    heading,
    inside_corner,
    line_corner,
    outside_corner,
    reverses,
    side_angle,
)

if TYPE_CHECKING:
    from edingcnc_lang.pipeline.cutter_comp import CutterCompensation

Array = np.ndarray


def _atan2(y: Array, x: Array) -> Array:
    return np.fromiter(map(math.atan2, y.tolist(), x.tolist()), np.float64, len(y))


def _cos(angle: Array) -> Array:
    return np.fromiter(map(math.cos, angle.tolist()), np.float64, len(angle))


def _sin(angle: Array) -> Array:
    return np.fromiter(map(math.sin, angle.tolist()), np.float64, len(angle))


def _tan(angle: Array) -> Array:
    return np.fromiter(map(math.tan, angle.tolist()), np.float64, len(angle))


def _where(condition: Any, yes: Array, no: Array) -> Array:
    return np.where(condition, yes, no)


# numpy's own atan2 and tan (SIMD) differ from math's in the last bit now and then: only the
# arithmetic, which IEEE fixes to the bit, runs in numpy
ARRAYS: Ops[Array] = Ops(_atan2, _cos, _sin, _tan, _where)


def _after(first: float, column: Array) -> Array:
    """``first`` followed by ``column`` without its last value (the value each move finds before it)."""
    return np.concatenate(((first,), column[:-1]))


def _steady(stage: CutterCompensation) -> bool:
    """Whether the stage holds exactly one straight move back, as after any line-line corner."""
    queue = stage.queue
    return (len(queue) == 1 and isinstance(queue[0], Queued) and queue[0].center is None
            and stage.endpoint is not None and bool(stage.side) and not stage.first)


class LineRun:
    """The corners at the starts of batch moves ``base``.., computed for the stage's state there.

    They stay valid after the stage took one of them on its own (the compensated end of a moving
    straight move does not depend on its corner) up to ``limit``: the first move without motion
    in the plane, or whose end depends on a corner not worked out yet.
    """

    def __init__(self, stage: CutterCompensation, batch: Batch, base: int) -> None:
        frame = self.frame = stage.frame
        self.base = base
        count = len(batch) - base
        tx = np.fromiter(map(itemgetter(frame.first), islice(batch.ends, base, None)), np.float64, count)
        ty = np.fromiter(map(itemgetter(frame.second), islice(batch.ends, base, None)), np.float64, count)
        sx, sy = _after(stage.program[0], tx), _after(stage.program[1], ty)
        still = np.flatnonzero((tx == sx) & (ty == sy))
        limit = int(still[0]) if len(still) else count
        tx, ty, sx, sy = tx[:limit], ty[:limit], sx[:limit], sy[:limit]
        side, radius = stage.side, stage.radius
        cx0, cy0 = frame.point(stage.current)
        alpha0 = heading(ARRAYS, (sx, sy), (tx, ty))
        gamma = side_angle(side)
        # each end depends on the corner before it only through line_corner's choice of turn for alpha:
        # guess the choices from the directions to the tool (each move's alpha + gamma, in (-pi, pi]), and
        # repeat until they agree with the corners they give
        toward_tool = _after(math.atan2(cy0 - sy[0], cx0 - sx[0]) if limit else 0.0, alpha0 + gamma)
        toward_tool = np.where(toward_tool > math.pi, toward_tool - 2 * math.pi,
                               np.where(toward_tool <= -math.pi, toward_tool + 2 * math.pi, toward_tool))
        adjusted = line_corner(ARRAYS, side, toward_tool, alpha0)[1]
        for _ in range(3):
            ex, ey = at(ARRAYS, (tx, ty), radius, adjusted + gamma)
            cx, cy = _after(cx0, ex), _after(cy0, ey)
            theta, alpha, beta, _ = line_corner(ARRAYS, side, heading(ARRAYS, (sx, sy), (cx, cy)), alpha0)
            changed = np.flatnonzero(alpha != adjusted)
            if not len(changed):
                break
            adjusted = alpha
        else:
            limit = int(changed[0])
        self.limit = limit
        concave = inside_corner(beta)
        half = half_corner(beta)
        # where each move starts: cut back into an inside corner, else where the tool is
        hx, hy = cx.copy(), cy.copy()
        inside = np.flatnonzero(concave & (half != 0.0))
        if len(inside):
            hx[inside], hy[inside] = cut_back(ARRAYS, radius, (cx[inside], cy[inside]), theta[inside], gamma,
                                              half[inside])
        dx, dy = tx - sx, ty - sy
        queued = stage.queue[0]
        assert isinstance(queued, Queued) and stage.endpoint is not None
        back = reverses((_after(queued.direction[0], dx), _after(queued.direction[1], dy)),
                        (_after(stage.endpoint[0], hx), _after(stage.endpoint[1], hy)), (hx, hy))
        outside = ~concave & outside_corner(beta)
        self.bad = np.flatnonzero(outside | (concave & ((half == 0.0) | back))).tolist()
        self.outside, self.concave, self.half = outside, concave, half
        self.hx, self.hy, self.ex, self.ey, self.tx, self.ty, self.dx, self.dy = hx, hy, ex, ey, tx, ty, dx, dy

    def count_from(self, stage: CutterCompensation, index: int) -> int:
        """How many moves from batch move ``index`` on this run can take (0: the stage takes that one)."""
        i = index - self.base
        if i >= self.limit or self.outside[i]:
            return 0
        if self.concave[i]:  # checked against where the stage really is (it may have taken the move before)
            queued = stage.queue[0]
            assert isinstance(queued, Queued) and stage.endpoint is not None
            if self.half[i] == 0.0 or reverses(queued.direction, stage.endpoint,
                                                  (float(self.hx[i]), float(self.hy[i]))):
                return 0
        following = self.bad[bisect_right(self.bad, i)] if self.bad and self.bad[-1] > i else self.limit
        return min(following, self.limit) - i

    def take(self, stage: CutterCompensation, batch: Batch, index: int, count: int) -> None:
        """Compensate batch moves ``index`` .. ``index + count - 1``: hand on the move the stage holds and all
        but the last of them, and hold the last one back, as the stage does move by move."""
        frame, i = self.frame, index - self.base
        queued = stage.queue[0]
        assert isinstance(queued, Queued)
        queued.end = frame.pose(queued.end, (float(self.hx[i]), float(self.hy[i])))
        stage._dequeue()
        last = i + count - 1
        if count > 1:
            stage._hand_on_run(batch, index, frame.poses(islice(batch.ends, index, index + count - 1),
                                                         self.hx[i + 1:last + 1].tolist(),
                                                         self.hy[i + 1:last + 1].tolist()))
        move = batch.move(index + count - 1, batch.ends[index + count - 2] if index + count > 1 else batch.start)
        end = (float(self.ex[last]), float(self.ey[last]))
        stage.queue.append(Queued(move, move.kind, frame.pose(move.end, end), move.feed,
                                  direction=(float(self.dx[last]), float(self.dy[last]))))
        stage.endpoint = (float(self.hx[last]), float(self.hy[last]))
        stage.current = frame.pose(move.end, end)
        stage.program = (float(self.tx[last]), float(self.ty[last]))


def take_batch(stage: CutterCompensation, batch: Batch) -> None:
    """Compensate ``batch`` (straight moves without G96) on ``stage``: runs of plain corners as arrays,
    every other move on its own."""
    index, count, run = 0, len(batch), None
    quiet_until = 0  # after a run that took little: no new one before this move (its set-up costs)
    taken = 0
    while index < count:
        if run is not None and index - run.base >= run.limit:
            if taken < stage.long_run // 2:
                quiet_until = index + stage.long_run
            run = None
        if _steady(stage):
            if run is None and index >= quiet_until and count - index >= stage.long_run \
                    and stage.frame.point(batch.ends[index]) != stage.program:
                run, taken = LineRun(stage, batch, index), 0
            if run is not None:
                plain = run.count_from(stage, index)
                if plain:
                    run.take(stage, batch, index, plain)
                    index += plain
                    taken += plain
                    continue
        stage._take(batch.move(index, batch.ends[index - 1] if index else batch.start))
        index += 1
