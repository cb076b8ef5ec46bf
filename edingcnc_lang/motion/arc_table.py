"""The arcs among a run of moves as one table: each arc's frame, worked out once.

A CAM job has arcs by the hundred thousand.  The motion stage checks a batch's arcs against the
limits and the planner needs their lengths, tangents and radii, and the limits report their
extremes; all of them read the same numbers (``kinematics.trajectory.arc_frame``), so they are
computed once per batch (``arc_frame_rows``, one call for all of its arcs) and kept as
rows of an array: one row per arc, its move's index among the moves first.  The planner keeps the
tables of a window's batches with its moves, their indices counted in the window.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from edingcnc_lang import speedups
from edingcnc_lang.canon import Arc, Pose
from edingcnc_lang.kinematics.trajectory import ARC_ROW, ArcFrame, arc_frame_rows

_FRAME_BYTES = speedups.compiled("arc_frame_bytes")  # the compiled core's rows as doubles, or None

_NO_ROWS = np.empty((0, ARC_ROW))


class ArcTable:
    """Rows of ``ARC_ROW`` numbers, one per arc: the index of its move, then its ``ArcFrame``
    (in-plane axes u and v, centre, start and end radius, start angle, signed sweep, XYZ length)."""

    __slots__ = ("rows",)

    def __init__(self, rows: np.ndarray = _NO_ROWS) -> None:
        self.rows = rows

    @classmethod
    def of(cls, start: Pose, ends: Sequence[Pose], arcs: Sequence[Arc | None]) -> ArcTable:
        """The arcs of moves from ``start`` through ``ends`` (``arcs[i]`` None for a straight move)."""
        if _FRAME_BYTES is not None:  # no float object per number
            return cls(np.frombuffer(_FRAME_BYTES(start, ends, arcs), dtype=float).reshape(-1, ARC_ROW))
        return cls(np.array(arc_frame_rows(start, ends, arcs), dtype=float).reshape(-1, ARC_ROW))

    @classmethod
    def joined(cls, tables: Sequence[ArcTable]) -> ArcTable:
        """One table of several, in their order."""
        if len(tables) == 1:
            return tables[0]
        return cls(np.concatenate([table.rows for table in tables]) if tables else _NO_ROWS)

    def __len__(self) -> int:
        return len(self.rows)

    @property
    def index(self) -> np.ndarray:
        """The move of each arc."""
        return self.rows[:, 0].astype(np.intp)

    def column(self, name: str) -> np.ndarray:
        """One of the frame's numbers for every arc: "u", "v" (as indices), "cu", "cv", "r0", "r1",
        "start_angle", "sweep" or "linear"."""
        values = self.rows[:, _COLUMNS[name]]
        return values.astype(np.intp) if name in ("u", "v") else values

    def shifted(self, offset: int) -> ArcTable:
        """The same arcs, their moves' indices moved by ``offset``."""
        rows = self.rows.copy()
        rows[:, 0] += offset
        return ArcTable(rows)

    def before(self, count: int) -> ArcTable:
        """The arcs among the first ``count`` moves."""
        return self if not len(self.rows) or self.rows[-1, 0] < count else ArcTable(self.rows[self.rows[:, 0] < count])

    def after(self, count: int) -> ArcTable:
        """The arcs of the moves from ``count`` on, counted from there (what is left when ``count`` are done)."""
        return ArcTable(self.rows[self.rows[:, 0] >= count]).shifted(-count)

    def frame(self, k: int) -> ArcFrame:
        """Arc ``k``'s frame, as ``arc_frame`` gives it."""
        _, u, v, cu, cv, r0, r1, angle, sweep, linear = self.rows[k].tolist()
        return ArcFrame(int(u), int(v), (cu, cv), r0, r1, angle, sweep, linear)

    def circle_within(self, low: Sequence[float], high: Sequence[float]) -> np.ndarray:
        """For each arc, whether its whole circle (the larger of its radii) lies within ``low``..``high``,
        as ``machine.geometry.circle_within`` decides it: then neither it nor its extremes can be outside."""
        rows = self.rows
        u, v = rows[:, 1].astype(np.intp), rows[:, 2].astype(np.intp)
        cu, cv, radius = rows[:, 3], rows[:, 4], np.maximum(rows[:, 5], rows[:, 6])
        lower, upper = np.asarray(low, dtype=float), np.asarray(high, dtype=float)
        return ((lower[u] <= cu - radius) & (cu + radius <= upper[u])
                & (lower[v] <= cv - radius) & (cv + radius <= upper[v]))

    def extremes(self, ends: np.ndarray, low: Sequence[float], high: Sequence[float]) -> np.ndarray:
        """The points (rows of six) where the arcs whose circle leaves ``low``..``high`` reach their extremes,
        for all of them at once: ``reach.frame_extremes`` of each arc (its move ending at column ``ends[:, i]``
        of the (6, n) ``ends``) with the same numbers (the same operations, element by element), grouped by
        quadrant rather than arc by arc.  What the limits report and the limit check read of a batch's arcs."""
        rows = self.rows[~self.circle_within(low, high)]
        moves, u, v = rows[:, 0].astype(np.intp), rows[:, 1].astype(np.intp), rows[:, 2].astype(np.intp)
        cu, cv, radius = rows[:, 3], rows[:, 4], np.maximum(rows[:, 5], rows[:, 6])
        start_angle, sweep = rows[:, 7], rows[:, 8]
        direction = np.where(sweep < 0.0, -1.0, 1.0)
        reach = np.minimum(np.abs(sweep), 2.0 * math.pi) + 1e-12
        points = []
        for k in range(4):  # as machine.geometry.arc_extremes
            quadrant = k * math.pi / 2
            hit = np.flatnonzero((direction * (quadrant - start_angle)) % (2 * math.pi) <= reach)
            point = ends[:, moves[hit]].T.copy()
            rows_hit = np.arange(len(hit))
            point[rows_hit, u[hit]] = cu[hit] + radius[hit] * math.cos(quadrant)
            point[rows_hit, v[hit]] = cv[hit] + radius[hit] * math.sin(quadrant)
            points.append(point)
        return np.concatenate(points)


_COLUMNS = {name: k for k, name in enumerate(("index", "u", "v", "cu", "cv", "r0", "r1", "start_angle", "sweep",
                                                "linear"))}
