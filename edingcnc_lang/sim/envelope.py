"""The lowest surface a tool reaches over each cell while it moves along a straight segment.

The tip's Z is linear along the segment and the tool's profile is a convex, rising function of the
distance from its axis, so the height over a cell is a convex function of the position along the
segment: its lowest point is where the derivative vanishes, clamped to the part of the segment
that passes over the cell.  Flat, ball and vee tools have that point in closed form; a bull nose
is found by a golden-section search (exact to 4e-9 of the segment, thanks to convexity).
"""
from __future__ import annotations

import numpy as np

from .stock import Stock
from .tools import Tool

FAR = 1e9              # a parameter step that clamps to an end of the segment
GOLDEN = (np.sqrt(5.0) - 1.0) / 2.0
GOLDEN_STEPS = 40      # bull nose: the bracket shrinks to 0.618^40 = 4e-9 of the segment


class Geometry:
    """A segment seen from each of its cells: the part of the segment over the cell's disc of
    ``radius``, and the offsets the profiles need (``d²(t) = e2 + L2 (t - p)²``)."""

    def __init__(self, stock: Stock, a: np.ndarray, b: np.ndarray, cells: np.ndarray, radius: float) -> None:
        ny, nx = stock.shape
        r = stock.resolution
        ux = stock.x0 + (cells % nx + 0.5) * r - a[:, 0]
        uy = stock.y0 + (cells // nx + 0.5) * r - a[:, 1]
        dx, dy = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
        self.az, self.dz = a[:, 2], b[:, 2] - a[:, 2]
        self.l2 = dx * dx + dy * dy
        self.uu = ux * ux + uy * uy
        self.ud = ux * dx + uy * dy
        self.still = self.l2 < 1e-18           # a vertical (or null) move: the same disc all along
        l2 = np.where(self.still, 1.0, self.l2)
        self.p = np.where(self.still, 0.0, self.ud / l2)
        self.e2 = np.maximum(self.uu - self.ud * self.p, 0.0)
        disc = self.ud * self.ud - self.l2 * (self.uu - radius * radius)
        root = np.sqrt(np.maximum(disc, 0.0))
        self.lo = np.where(self.still, 0.0, np.maximum((self.ud - root) / l2, 0.0))
        self.hi = np.where(self.still, 1.0, np.minimum((self.ud + root) / l2, 1.0))
        inside = np.where(self.still, self.uu <= radius * radius, disc >= 0.0)
        self.ok = inside & (self.lo <= self.hi)

    def keep(self, chosen: np.ndarray) -> None:
        for name in ("az", "dz", "l2", "uu", "ud", "still", "p", "e2", "lo", "hi"):
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
        return g.az + t * g.dz + tool.profile(np.sqrt(g.d2(t)))  # type: ignore[no-any-return]

    lo, hi = g.lo.copy(), g.hi.copy()
    for _ in range(GOLDEN_STEPS):
        left, right = hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo)
        go_left = height(left) < height(right)
        hi = np.where(go_left, right, hi)
        lo = np.where(go_left, lo, left)
    return (lo + hi) / 2.0  # type: ignore[no-any-return]
