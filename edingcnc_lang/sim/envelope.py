"""The lowest surface a tool reaches over each cell while it moves along a straight segment.

The tip's Z is linear along the segment and the tool's profile is a convex, rising function of the
distance from its axis, so the height over a cell is a convex function of the position along the
segment: its lowest point is where the derivative vanishes, clamped to the part of the segment
that passes over the cell.  Flat, ball and vee tools have that point in closed form; a bull nose
is found by a golden-section search (exact to 4e-9 of the segment, thanks to convexity).
"""
from __future__ import annotations

from collections.abc import Callable

import numpy as np

from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.sim.tools import Tool

FAR = 1e9              # a parameter step that clamps to an end of the segment
GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0
GOLDEN_STEPS = 40      # bull nose: the bracket shrinks to 0.618^40 = 4e-9 of the segment
ROUNDING = 1e-5        # mm: what float32 arithmetic may be off by; a cell is skipped only below that
STILL = 1e-10          # mm²: a segment shorter than this in XY (10 nm) is a vertical move


class Geometry:
    """Segments seen from the cells around them: for each (segment, cell) pair within ``radius`` of
    the segment, the part of the segment over the cell (``lo``..``hi``) and the offsets the
    profiles need (``d²(t) = e2 + L2 (t - p)²``).  Pairs come segment by segment (``counts`` each,
    cell columns ``i`` and rows ``j``), so per-segment values are spread with ``np.repeat`` rather
    than gathered; pairs out of reach, or whose cell is already lower than the part of the tool
    (``floor(d)`` above the tip at distance d) can come, are dropped before the costlier half.
    Per pair everything is float32 (half the memory traffic, twice the numbers per instruction):
    the offsets are from the segment's midpoint, and heights are kept in float32 anyway."""

    def __init__(self, stock: Stock, a: np.ndarray, b: np.ndarray,
                 box: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray], radius: float,
                 floor: Callable[[np.ndarray], np.ndarray]) -> None:
        counts, i0, j0, i, j = box
        r, nx = stock.resolution, stock.shape[1]
        dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
        l2 = dx * dx + dy * dy
        still = l2 < STILL
        half_x, half_y = dx / 2.0, dy / 2.0
        # offsets from the segment's midpoint in float32: small numbers, so a µm is still a µm
        step = np.float32(r)
        mx = np.repeat((stock.x0 + (i0 + 0.5) * r - a[:, 0] - half_x).astype(np.float32), counts) + i * step
        my = np.repeat((stock.y0 + (j0 + 0.5) * r - a[:, 1] - half_y).astype(np.float32), counts) + j * step
        # the nearest the segment comes to the cell is at least its distance from the midpoint less
        # half the length; a cell already at or below the lowest the tool can reach over it (the
        # lowest tip plus the profile there) cannot be cut: most cells a finishing pass passes
        # again, left behind by the previous pass or row
        nearest = np.sqrt(mx * mx + my * my) - np.repeat(np.sqrt(np.where(still, 0.0, l2) / 4.0).astype(np.float32), counts)
        lowest_tip = np.repeat(np.minimum(a[:, 2], b[:, 2]).astype(np.float32), counts)
        bound = lowest_tip + floor(np.clip(nearest, np.float32(0.0), np.float32(radius))) - np.float32(ROUNDING)
        cells = np.repeat(j0 * nx + i0, counts) + j.astype(np.int64) * nx + i
        near = np.flatnonzero((nearest <= np.float32(radius)) & (stock.top.reshape(-1)[cells] > bound))
        self.seg = np.repeat(np.arange(len(a)), counts)[near]
        self.cell = cells[near]
        pair_dx, pair_dy = dx.astype(np.float32)[self.seg], dy.astype(np.float32)[self.seg]
        ux = mx[near] + pair_dx * np.float32(0.5)
        uy = my[near] + pair_dy * np.float32(0.5)
        self.l2 = np.where(still, 0.0, l2).astype(np.float32)[self.seg]
        uu = ux * ux + uy * uy
        ud = ux * pair_dx + uy * pair_dy
        disc = ud * ud - self.l2 * (uu - np.float32(radius * radius))  # < 0: the disc misses the cell (NaN below)
        self.still = still[self.seg]
        self.az = a[self.seg, 2].astype(np.float32)
        self.dz = (b[:, 2] - a[:, 2]).astype(np.float32)[self.seg]
        inv = np.float32(1.0) / np.where(self.still, np.float32(1.0), self.l2)
        with np.errstate(invalid="ignore"):
            root = np.sqrt(disc)
        self.lo = np.where(self.still, np.float32(0.0), np.maximum((ud - root) * inv, np.float32(0.0)))
        self.hi = np.where(self.still, np.float32(1.0), np.minimum((ud + root) * inv, np.float32(1.0)))
        self.uu, self.ud = uu, ud
        self.p = np.where(self.still, np.float32(0.0), ud * inv)
        self.e2 = np.maximum(uu - ud * self.p, np.float32(0.0))
        self.keep(np.flatnonzero(self.lo <= self.hi))

    def keep(self, chosen: np.ndarray) -> None:
        for name in ("seg", "cell", "az", "dz", "l2", "uu", "ud", "still", "p", "e2", "lo", "hi"):
            setattr(self, name, getattr(self, name)[chosen])

    def d2(self, t: np.ndarray) -> np.ndarray:
        return np.maximum(self.uu - 2.0 * t * self.ud + t * t * self.l2, 0.0)

    def downhill(self) -> np.ndarray:
        """The parameter of the lowest tip over the cell: a flat bottom reaches lowest at the end
        of its interval that is further down."""
        return np.where(self.dz >= 0.0, self.lo, self.hi)

    def clamp(self, step: np.ndarray) -> np.ndarray:
        """``p + step`` kept within the interval; a vertical move's lowest point is its lower end."""
        t = np.where(self.still, np.where(self.dz < 0.0, 1.0, 0.0), self.p + step)
        return np.clip(t, self.lo, self.hi)


def lowest(tool: Tool, g: Geometry) -> np.ndarray:
    """The lowest height of the tool's cutting surface over each cell along its segment."""
    if tool.shape == "flat":
        return g.az + g.downhill() * g.dz
    sign = -np.sign(g.dz)
    l2 = np.where(g.still, 1.0, g.l2)
    dz2 = g.dz * g.dz
    if tool.shape == "ball":
        w = np.maximum(tool.radius ** 2 - g.e2, 0.0)
        t = g.clamp(sign * np.sqrt(dz2 * w / (l2 * (l2 + dz2))))
    elif tool.shape == "vee":
        k2l2 = tool.cone_slope ** 2 * l2
        steep = k2l2 <= dz2
        step = np.sqrt(dz2 * g.e2 / (l2 * np.where(steep, 1.0, k2l2 - dz2)))
        t = g.clamp(sign * np.where(steep, FAR, step))
    else:
        t = _golden(tool, g)
    return g.az + t * g.dz + tool.profile(np.sqrt(g.d2(t)))


def _golden(tool: Tool, g: Geometry) -> np.ndarray:
    """The parameter minimising a convex profile's height over the interval (golden section)."""
    def height(t: np.ndarray) -> np.ndarray:
        return g.az + t * g.dz + tool.profile(np.sqrt(g.d2(t)))

    lo, hi = g.lo.copy(), g.hi.copy()
    for _ in range(GOLDEN_STEPS):
        left, right = hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo)
        go_left = height(left) < height(right)
        hi = np.where(go_left, right, hi)
        lo = np.where(go_left, lo, left)
    return (lo + hi) / 2.0
