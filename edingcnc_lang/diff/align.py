"""Which point of one path lies on which part of the other: alignment by geometry, not by index.

Both runs are dense polylines (``record.sample``).  A cursor walks the OLD polyline while the NEW
points are taken in order: a block of points is first tried where the path lengths say it should be
(the fast path: a reformatted or re-split job never leaves it); a point that is not within the
tolerance there is looked for from the last point that was (so a lead-in inserted in NEW, a pass
split in two or moves removed cost only their own points), and a match far ahead is believed only
when the points after it follow.  The walk only goes forward, so a retraced path is matched to its
own pass.  Work and memory grow with the points, never with their square.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from edingcnc_lang.diff.record import PathSamples

BLOCK = 512          # points tried at once on the fast path
WINDOW = 256         # segments searched around the cursor for a point off the fast path
FAR = 65_536         # segments searched ahead for a point after a removed stretch
FAR_EVERY = 64       # in a long run of unmatched points, the far search is tried every this many
FAR_MOVES = 4        # ... and at the end of each of the first this many moves of the run
VERIFY = 6           # points after a far match that must follow it
CAPTURE = 1.0        # mm: an unmatched point this close to OLD drags the cursor along (a moved contour)
SLACK = 2.0          # mm of path, plus ...
SLACK_SHARE = 0.25   # ... this share of the path since the last match: how far from where it should be


@dataclass
class Alignment:
    """For every point of one path: how far it is from the other path, and where on it."""

    distance: np.ndarray   # (P,) float32 distance to the other path (inf: the other path is empty)
    segment: np.ndarray    # (P,) int32 index of the nearest segment of the other path (-1: none)
    at: np.ndarray         # (P,) float32, 0..1 along that segment


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


class _Walk:
    """The cursor over OLD's segments and the NEW points matched so far."""

    def __init__(self, new: PathSamples, old: PathSamples, tolerance: float) -> None:
        self.new, self.tolerance = new, tolerance
        pts = old.points if len(old.points) != 1 else np.vstack((old.points, old.points))
        self.a, self.b = pts[:-1], pts[1:]
        self.arc_of = old.arc_of if len(old.points) != 1 else np.full(1, -1, dtype=np.int32)
        self.centers, self.normals, self.radii = old.centers, old.normals, old.radii
        self.length = old.length if len(old.length) != 1 else np.zeros(2)
        self.segments = len(self.a)
        self.firm = 0          # segment of the last point within the tolerance
        self.soft = 0          # segment the cursor follows (a moved contour drags it past firm)
        self.pos_new = 0.0     # path length of NEW at the cursor
        self.pos_old = 0.0     # path length of OLD at the cursor
        self.firm_new = 0.0    # the same at the last point within the tolerance
        self.firm_old = 0.0

    def to_path(self, segments: np.ndarray, p: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Distances of ``p`` (broadcast) to OLD's ``segments``, pieces of arcs measured to their circle."""
        a, b = self.a[segments], self.b[segments]
        dist, at = _to_segments(a, b, p)
        arcs = self.arc_of[segments]
        if (arcs >= 0).any():
            where = np.nonzero(arcs >= 0)
            moves = arcs[where]
            dist[where], at[where] = _to_arcs(a[where], b[where], np.broadcast_to(p, a.shape)[where],
                                              self.centers[moves], self.normals[moves], self.radii[moves])
        return dist, at

    def follow(self, first: int, stop: int, pos_new: float, pos_old: float,
               floor: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Points ``first``..``stop`` matched where the path lengths put them (and one segment either side)."""
        expected = pos_old + (self.new.length[first:stop] - pos_new)
        index = np.searchsorted(self.length, expected, side="left") - 1  # a vertex: the segment ending there
        choices = np.clip(index[:, None] + np.array([0, 1, -1]), floor, self.segments - 1)
        dist, at = self.to_path(choices, self.new.points[first:stop, None, :])
        best = np.argmin(dist, axis=1)
        rows = np.arange(len(best))
        return dist[rows, best], choices[rows, best], at[rows, best]

    def positions(self, segments: np.ndarray, at: np.ndarray) -> np.ndarray:
        """Path lengths of OLD at ``at`` along ``segments``."""
        return self.length[segments] + at * (self.length[segments + 1] - self.length[segments])

    def along(self, segment: int, at: float) -> float:
        return float(self.length[segment] + at * (self.length[segment + 1] - self.length[segment]))

    def moved_to(self, point: int, segment: int, at: float, firm: bool) -> None:
        self.soft = max(self.soft, segment)
        self.pos_new, self.pos_old = float(self.new.length[point]), self.along(segment, at)
        if firm:
            self.firm = self.soft = segment
            self.firm_new, self.firm_old = self.pos_new, self.pos_old

    def expected(self, point: int) -> tuple[float, float]:
        """Where on OLD ``point`` should be, counted from the last firm match, and how far off it may be."""
        progress = float(self.new.length[point]) - self.firm_new
        return self.firm_old + progress, SLACK + SLACK_SHARE * progress

    def follows(self, point: int, segment: int, at: float) -> bool:
        """Do the points after ``point`` lie on OLD after ``segment``?"""
        stop = min(len(self.new.points), point + 1 + VERIFY)
        if stop <= point + 1:
            return True
        dist, _seg, _at = self.follow(point + 1, stop, float(self.new.length[point]), self.along(segment, at), segment)
        return bool(np.all(dist <= self.tolerance))

    def search(self, point: int, low: int, high: int) -> tuple[int, float, float] | None:
        """The segment in ``low``..``high`` within the tolerance of ``point`` nearest where it should be, that
        the next points follow (a path that passes the same place later is not taken for this one)."""
        p = self.new.points[point]
        expected, _slack = self.expected(point)
        for start in range(low, high, 8192):
            stop = min(high, start + 8192)
            dist, at = self.to_path(np.arange(start, stop), p)
            hits = np.flatnonzero(dist <= self.tolerance)
            if hits.size > 1:
                hits = hits[np.argsort(np.abs(self.positions(start + hits, at[hits]) - expected), kind="stable")]
            for hit in hits[:8]:
                if self.follows(point, start + int(hit), float(at[hit])):
                    return start + int(hit), float(dist[hit]), float(at[hit])
        return None


def align(new: PathSamples, old: PathSamples, tolerance: float) -> Alignment:
    """Match every point of ``new`` to the segment of ``old`` it lies on (or is nearest to), in order."""
    count = len(new.points)
    # 32-bit: 12 bytes a point (distances far below the tolerance need no more digits)
    distance = np.full(count, np.inf, dtype=np.float32)
    segment = np.full(count, -1, dtype=np.int32)
    at = np.zeros(count, dtype=np.float32)
    if not count or not len(old.points):
        return Alignment(distance, segment, at)
    walk = _Walk(new, old, tolerance)
    point, lost, lost_moves = 0, 0, 0
    while point < count:
        stop = min(count, point + BLOCK)
        dist, seg, where = walk.follow(point, stop, walk.pos_new, walk.pos_old, walk.firm)
        bad = np.flatnonzero(dist > tolerance)
        good = int(bad[0]) if bad.size else stop - point
        if good:
            distance[point:point + good], segment[point:point + good] = dist[:good], seg[:good]
            at[point:point + good] = where[:good]
            walk.moved_to(point + good - 1, int(seg[good - 1]), float(where[good - 1]), firm=True)
            point, lost, lost_moves = point + good, 0, 0
            continue
        low = max(walk.firm, walk.soft - WINDOW)
        high = min(walk.segments, walk.soft + WINDOW)
        found = walk.search(point, low, high)
        # far ahead: at the first points lost, at the end of each of the first moves lost (one long move
        # across a removed stretch, then the path goes on where OLD does), then now and then
        ends_move = point + 1 == count or new.owner[point + 1] != new.owner[point]
        if found is None and high < walk.segments and (lost % FAR_EVERY == 0 or (ends_move and lost_moves < FAR_MOVES)):
            found = walk.search(point, high, min(walk.segments, high + FAR))
        if found is not None:
            segment[point], distance[point], at[point] = found
            walk.moved_to(point, found[0], found[2], firm=True)
            point, lost, lost_moves = point + 1, 0, 0
            continue
        dist_all, at_all = walk.to_path(np.arange(low, high), new.points[point])
        # the nearest part of OLD about where the point should be drags the cursor along (a moved contour);
        # a part far from there that merely passes close (the same wall, later) does not
        expected, slack = walk.expected(point)
        plausible = np.abs(walk.positions(np.arange(low, high), at_all) - expected) <= slack
        pool = np.where(plausible, dist_all, np.inf)
        nearest = int(np.argmin(pool)) if plausible.any() else int(np.argmin(dist_all))
        segment[point], distance[point], at[point] = low + nearest, dist_all[nearest], at_all[nearest]
        if plausible.any() and dist_all[nearest] <= CAPTURE:
            walk.moved_to(point, low + nearest, float(at_all[nearest]), firm=False)
        point, lost, lost_moves = point + 1, lost + 1, lost_moves + ends_move
    return Alignment(distance, segment, at)


def matched_moves(alignment: Alignment, old: PathSamples) -> np.ndarray:
    """The OLD move each point lies on (a point at a vertex counts with the move that ends there)."""
    seg = np.maximum(alignment.segment, 0)
    ending = (alignment.at <= 1e-9) & (seg > 0)
    index = np.where(ending, seg, seg + 1)
    index = np.minimum(index, len(old.owner) - 1)
    moves = old.owner[index] if len(old.owner) else np.zeros_like(index)
    return np.where(alignment.segment >= 0, moves, -1)
