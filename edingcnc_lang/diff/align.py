"""How far each point of one path is from the other path: the nearest segment, found through a grid.

Both runs are dense polylines (``record.sample``).  ``nearest`` measures points against a stretch of
the other polyline (pieces of arcs to their circle): the segments are filed by the grid cell of pieces
at most ``2 * reach`` long, a point looks in its own cell and the 26 around it, so every segment within
``reach`` of it is found and measured exactly (a fine grid first, ``NEAR``, then the whole reach for the
points it left); a point farther than ``reach`` from all of them is
measured against a bounded sample of the stretch's points (``FAR_POINTS``) instead.  A few points
against a long stretch (a job driven backwards: one move left to measure against all of the other) skip
the runs of segments whose box is farther than the nearest found (``_by_boxes``).  Work and memory
grow with the points and the segments near each, never with their product.
"""
from __future__ import annotations

import numpy as np

from edingcnc_lang.diff.record import PathSamples, slots

BRUTE = 1 << 16      # point-segment pairs measured at once, all against all (below 64 times this in all, or
                     # for fewer points than a 64th of the segments, no grid is built)
CHUNK = 4096         # points looked up at once
NEAR = 0.25          # mm: the reach of the fine grid
FAR_POINTS = 4096    # points of the other stretch a far point is measured against
BLOCK = 32           # segments in a box, for a few points against a long stretch
BOX_POINTS = 16      # points bounded against all the boxes at once
NEIGHBOURS = np.array([(i, j, k) for i in (-1, 0, 1) for j in (-1, 0, 1) for k in (-1, 0, 1)], dtype=np.int64)


def _to_segments(a: np.ndarray, b: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distances of points ``p`` to segments ``a``-``b`` (row by row or broadcast) and where they meet."""
    ab = b - a
    span = np.einsum("...i,...i->...", ab, ab)
    t = np.einsum("...i,...i->...", p - a, ab) / np.where(span > 0.0, span, 1.0)
    t = np.clip(t, 0.0, 1.0)
    near = a + t[..., None] * ab
    return np.linalg.norm(p - near, axis=-1), t


def _to_arcs(a: np.ndarray, b: np.ndarray, p: np.ndarray, center: np.ndarray, normal: np.ndarray,
             radius: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distances of points ``p`` (n, D) to pieces of circles (less than half a turn each) from ``a`` to ``b``
    about ``center`` (n, 3), with the normal axis ``normal`` and ``radius`` (helices: the height goes
    with the angle), and where they meet (0..1 of the angle)."""
    rows = np.arange(len(normal))
    i1, i2 = (normal + 1) % 3, (normal + 2) % 3

    def in_plane(x: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        return x[rows, i1] - center[rows, i1], x[rows, i2] - center[rows, i2], x[rows, normal]

    (au, av, an), (bu, bv, bn), (pu, pv, pn) = in_plane(a), in_plane(b), in_plane(p)
    span = np.arctan2(au * bv - av * bu, au * bu + av * bv)
    turned = np.arctan2(au * pv - av * pu, au * pu + av * pv)
    s = np.where(span != 0.0, turned / np.where(span != 0.0, span, 1.0), -1.0)
    inside = (s >= 0.0) & (s <= 1.0)
    s = np.clip(s, 0.0, 1.0)
    off = (np.hypot(pu, pv) - radius) ** 2 + (pn - (an + s * (bn - an))) ** 2
    if p.shape[1] > 3:  # rotary axes turning along the arc: straight in the angle
        off += np.sum((p[:, 3:] - (a[:, 3:] + s[:, None] * (b[:, 3:] - a[:, 3:]))) ** 2, axis=1)
    to_a, to_b = np.linalg.norm(p - a, axis=1), np.linalg.norm(p - b, axis=1)
    return (np.where(inside, np.sqrt(off), np.minimum(to_a, to_b)),
            np.where(inside, s, np.where(to_a <= to_b, 0.0, 1.0)))


class Stretch:
    """Segments of one path (those of the moves ``first``..``stop`` - 1) to measure points against."""

    def __init__(self, samples: PathSamples, first: int, stop: int) -> None:
        low, high = np.searchsorted(samples.owner, (first, stop))
        ends = np.arange(max(int(low), 1), int(high))
        ends = ends[~samples.jump[ends]]  # a segment ends at point k + 1; one that ends at a jump is no path
        self.samples = samples
        self.index = ends - 1              # segment numbers in ``samples``
        self.a, self.b = samples.points[ends - 1], samples.points[ends]
        self.arc = samples.arc_of[ends - 1] if len(ends) else np.zeros(0, dtype=np.int32)
        if not len(ends) and high > low:   # one point only (a job of one move that goes nowhere)
            self.index = np.array([int(low)])
            self.a = self.b = samples.points[int(low):int(low) + 1]
            self.arc = np.full(1, -1, dtype=np.int32)

    def __len__(self) -> int:
        return len(self.a)

    def boxes(self) -> tuple[np.ndarray, np.ndarray]:
        """Low and high corners (XYZ) of a box around each run of ``BLOCK`` segments: a segment lies in
        the box of its ends, a piece of an arc in that and the box of its circle (measured to the circle
        at a point's angle, a helix's height between its ends)."""
        lows, highs = [], []
        for first in range(0, len(self), BLOCK * 2048):  # a chunk at a time: little memory besides the boxes
            a, b = self.a[first:first + BLOCK * 2048, :3], self.b[first:first + BLOCK * 2048, :3]
            low, high = np.minimum(a, b), np.maximum(a, b)
            arcs = np.flatnonzero(self.arc[first:first + BLOCK * 2048] >= 0)
            if arcs.size:
                moves = self.arc[first + arcs]
                center, radius = self.samples.centers[moves], np.abs(self.samples.radii[moves])[:, None]
                ring_low, ring_high = center - radius, center + radius
                rows, normal = np.arange(len(arcs)), self.samples.normals[moves]
                ring_low[rows, normal], ring_high[rows, normal] = low[arcs, normal], high[arcs, normal]
                low[arcs], high[arcs] = np.minimum(low[arcs], ring_low), np.maximum(high[arcs], ring_high)
            starts = np.arange(0, len(a), BLOCK)
            lows.append(np.minimum.reduceat(low, starts, axis=0))
            highs.append(np.maximum.reduceat(high, starts, axis=0))
        return np.concatenate(lows), np.concatenate(highs)

    def measure(self, points: np.ndarray, segments: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distances of ``points`` to this stretch's ``segments`` (row by row), pieces of arcs to their circle."""
        a, b = self.a[segments], self.b[segments]
        dist, at = _to_segments(a, b, points)
        arcs = self.arc[segments]
        if (arcs >= 0).any():
            where = np.flatnonzero(arcs >= 0)
            moves = arcs[where]
            s = self.samples
            dist[where], at[where] = _to_arcs(a[where], b[where], points[where], s.centers[moves], s.normals[moves],
                                              s.radii[moves])
        return dist, at


def nearest(points: np.ndarray, stretch: Stretch, reach: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """For each point: its distance to ``stretch``, the nearest segment (its number in the samples, -1: the
    stretch is empty) and where on it (0..1).  Exact within ``reach``; beyond it, to the nearest of a
    bounded sample of the stretch's points."""
    count, size = len(points), len(stretch)
    distance = np.full(count, np.inf)
    segment = np.full(count, -1, dtype=np.int64)
    at = np.zeros(count)
    if not count or not size:
        return distance, segment, at
    if (count * size <= BRUTE * 64 or count * 64 < size) and size > BRUTE:  # a few points, a long stretch
        _by_boxes(points, stretch, distance, segment, at)
    elif count * size <= BRUTE * 64 or count * 64 < size:  # few points (a short stretch): all against all
        for low in range(0, count, max(1, BRUTE // size)):
            chosen = np.arange(low, min(count, low + max(1, BRUTE // size)))
            for first in range(0, size, BRUTE):
                cols = np.arange(first, min(size, first + BRUTE))
                rows, cols = np.repeat(chosen, len(cols)), np.tile(cols, len(chosen))
                _keep(distance, segment, at, rows, cols, *stretch.measure(points[rows], cols))
    else:  # a fine grid first (most points lie on the other path), a coarse one for the points it leaves
        for near in sorted({min(reach, NEAR), reach}):
            grid, todo = _Grid(stretch, 2.0 * near), np.flatnonzero(distance > near)
            for low in range(0, len(todo), CHUNK):
                chosen = todo[low:low + CHUNK]
                rows, cols = grid.candidates(points[chosen, :3])
                rows = chosen[rows]
                _keep(distance, segment, at, rows, cols, *stretch.measure(points[rows], cols))
    far = np.flatnonzero(distance > reach)
    if far.size:  # nothing near: the nearest of up to FAR_POINTS of the stretch's ends is near enough to say so
        pick = np.unique(np.linspace(0, size - 1, min(size, FAR_POINTS)).astype(np.int64))
        for low in range(0, far.size, 256):
            chosen = far[low:low + 256]
            gaps = np.linalg.norm(points[chosen, None, :] - stretch.b[None, pick, :], axis=2)
            best = np.argmin(gaps, axis=1)
            closer = gaps[np.arange(len(chosen)), best] < distance[chosen]
            distance[chosen[closer]] = gaps[np.arange(len(chosen)), best][closer]
            segment[chosen[closer]], at[chosen[closer]] = pick[best[closer]], 1.0
    known = segment >= 0
    segment[known] = stretch.index[segment[known]]
    return distance, segment, at


def _by_boxes(points: np.ndarray, stretch: Stretch, distance: np.ndarray, segment: np.ndarray,
              at: np.ndarray) -> None:
    """All against all, less the segments that cannot be nearest: a box around each run of ``BLOCK``
    segments bounds their distance from below; the nearest box's segments give a distance, and only the
    boxes as near as that (and a margin for rounding) are measured.  A segment left out is farther than
    the nearest, so the nearest (the first of equally near ones) is the one all against all finds."""
    low, high = stretch.boxes()
    for first in range(0, len(points), BOX_POINTS):
        chosen = np.arange(first, min(len(points), first + BOX_POINTS))
        p = points[chosen, :3]
        bound = np.zeros((len(chosen), len(low)))
        for axis in range(3):
            out = np.maximum(low[None, :, axis] - p[:, None, axis], p[:, None, axis] - high[None, :, axis])
            bound += np.maximum(out, 0.0) ** 2
        bound = np.sqrt(bound)
        rows, cols = _block_pairs(chosen, np.argmin(bound, axis=1), len(stretch))
        upper = np.full(len(points), np.inf)
        np.minimum.at(upper, rows, stretch.measure(points[rows], cols)[0])
        limit = upper[chosen] * (1.0 + 1e-9) + 1e-6
        which, blocks = np.nonzero(~(bound > limit[:, None]))  # a NaN bound is measured
        rows, cols = _block_pairs(chosen[which], blocks, len(stretch))
        _keep(distance, segment, at, rows, cols, *stretch.measure(points[rows], cols))


def _block_pairs(rows: np.ndarray, blocks: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (point, segment) of each point in ``rows`` with the segments of its block, in order."""
    rows = np.repeat(rows, BLOCK)
    cols = (np.repeat(blocks * BLOCK, BLOCK).reshape(-1, BLOCK) + np.arange(BLOCK)).ravel()
    inside = cols < size
    return rows[inside], cols[inside]


def _keep(distance: np.ndarray, segment: np.ndarray, at: np.ndarray, rows: np.ndarray, cols: np.ndarray,
          dist: np.ndarray, where: np.ndarray) -> None:
    """For each point in ``rows``, keep the nearest of its candidates if nearer than what it has."""
    if not len(rows):
        return
    order = np.lexsort((dist, rows))
    first = order[np.flatnonzero(np.r_[True, rows[order][1:] != rows[order][:-1]])]
    better = dist[first] < distance[rows[first]]
    first = first[better]
    distance[rows[first]], segment[rows[first]], at[rows[first]] = dist[first], cols[first], where[first]


class _Grid:
    """The stretch's segments filed by the cell of each piece's middle (pieces at most one cell long)."""

    def __init__(self, stretch: Stretch, cell: float) -> None:
        a, b = stretch.a[:, :3], stretch.b[:, :3]
        pieces = np.maximum(1, np.ceil(np.linalg.norm(b - a, axis=1) / cell)).astype(np.int64)
        owner, slot = slots(np.arange(len(a)), pieces)
        middle = a[owner] + ((slot + 0.5) / pieces[owner])[:, None] * (b[owner] - a[owner])
        self.cell = cell
        cells = np.floor(middle / cell).astype(np.int64)
        self.low = cells.min(axis=0) - 1
        self.span = cells.max(axis=0) - self.low + 2
        codes = self._code(cells)
        order = np.argsort(codes, kind="stable")
        self.codes, self.owner = codes[order], owner[order]

    def _code(self, cells: np.ndarray) -> np.ndarray:
        c = np.clip(cells - self.low, 0, self.span - 1)
        return (c[:, 0] * self.span[1] + c[:, 1]) * self.span[2] + c[:, 2]

    def candidates(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Pairs (point, segment) of every segment filed in the cells around each point."""
        cells = np.floor(points / self.cell).astype(np.int64)
        rows, cols = [], []
        for offset in NEIGHBOURS:
            code = self._code(cells + offset)
            low = np.searchsorted(self.codes, code, side="left")
            high = np.searchsorted(self.codes, code, side="right")
            which, slot = slots(np.arange(len(points)), high - low)
            rows.append(which)
            cols.append(self.owner[low[which] + slot])
        return np.concatenate(rows), np.concatenate(cols)


def matched_moves(segment: np.ndarray, at: np.ndarray, other: PathSamples) -> np.ndarray:
    """The move of the other path each point lies on (a point at a vertex counts with the move that ends there)."""
    seg = np.maximum(segment, 0)
    index = np.where((at <= 1e-9) & (seg > 0), seg, seg + 1)
    index = np.minimum(index, len(other.owner) - 1)
    moves = other.owner[index] if len(other.owner) else np.zeros_like(index)
    return np.where(segment >= 0, moves, -1)
