"""A lathe tool's nose swept along a move, as the radii it spans in each slice of a bar.

The spindle turns the bar under the tool, so a move removes the solid of revolution of what its
nose sweeps in the (Z, radius) half-plane: a disc of the nose radius moved along a segment, a
stadium (the segment offset by the radius on both sides, closed by two half circles).  Each slice
of the bar is cut along its centre line: the stadium's lower and upper edges there are exact (end
caps and offset segment), so no sampling error is added beyond the slice width.  A nose narrower
than a slice (a point tool plunging) still cuts the slice nearest to it.
"""
from __future__ import annotations

import numpy as np

from edingcnc_lang.sim.round_stock import RoundStock

CHUNK = 65_536  # (segment, slice) pairs evaluated at once: scratch arrays that stay in the cache
BLOCK = 64      # slices per block of the coarse maximum that rules out strokes above the surface


def ranges(stock: RoundStock, a: np.ndarray, b: np.ndarray, nose: float) -> tuple[np.ndarray, np.ndarray]:
    """The first and last slice under each stroke (``last < first``: none); a stroke narrower than
    a slice, with no slice centre under it, gets the slice nearest to it."""
    return ranges_over(stock, np.minimum(a[:, 0], b[:, 0]) - nose, np.maximum(a[:, 0], b[:, 0]) + nose)


def ranges_over(stock: RoundStock, z_low: np.ndarray, z_high: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``ranges`` of strokes whose tool reaches from ``z_low`` to ``z_high`` along the axis."""
    count = stock.shape[0]
    first = np.clip(np.ceil((z_low - stock.start) / stock.resolution - 0.5).astype(np.int64), 0, count)
    last = np.clip(np.floor((z_high - stock.start) / stock.resolution - 0.5).astype(np.int64), -1, count - 1)
    nearest = np.clip(np.round((0.5 * (z_low + z_high) - stock.start) / stock.resolution - 0.5).astype(np.int64),
                      0, count - 1)
    inside = (z_high >= stock.start) & (z_low <= stock.start + stock.length)
    narrow = inside & (last < first)
    first = np.where(narrow, nearest, first)
    return first, np.where(narrow, nearest, np.where(inside, last, first - 1))


def reaching(stock: RoundStock, a: np.ndarray, b: np.ndarray, nose: float, first: np.ndarray,
             last: np.ndarray) -> np.ndarray:
    """Which strokes may touch the material: those over some slice whose nose goes below the highest
    outer radius there (a block maximum: a stroke wholly above the surface can change nothing);
    ``nose`` is how far the tool reaches below its path."""
    outer = stock.outer.max(axis=1)
    blocks = -(-len(outer) // BLOCK)
    padded = np.full(blocks * BLOCK + BLOCK, -np.inf, dtype=np.float32)
    padded[:len(outer)] = outer
    tops = padded.reshape(-1, BLOCK).max(axis=1)  # a last block of -inf: the end of a range
    over = last >= first
    bounds = np.empty(2 * len(first), dtype=np.int64)
    bounds[0::2] = np.where(over, first, 0) // BLOCK
    bounds[1::2] = np.where(over, last, 0) // BLOCK + 1
    top = np.maximum.reduceat(tops, bounds)[0::2]
    return over & (np.minimum(a[:, 1], b[:, 1]) - nose < top)


def spans(stock: RoundStock, a: np.ndarray, b: np.ndarray, nose: float, first: np.ndarray,
          last: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """For segments of the nose centre from ``a`` to ``b`` ((n, 2): Z, radius) with nose radius
    ``nose`` over slices ``first..last``: the (segment, slice, low radius, high radius) of every
    slice the stadium covers."""
    seg, cell, z = slices(stock, a, b, (-nose, nose), first, last)
    low, high = envelope(a[seg], b[seg], nose, z)
    keep = np.isfinite(low)
    return seg[keep], cell[keep], low[keep], high[keep]


def slices(stock: RoundStock, a: np.ndarray, b: np.ndarray, reach: tuple[float, float], first: np.ndarray,
           last: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Every (segment, slice) pair of ``first..last``, and the Z to cut it at: the slice's centre,
    kept within the tool's reach (offsets ``reach`` from the path) so a narrow stroke cuts its slice."""
    counts = np.maximum(last - first + 1, 0)
    seg = np.repeat(np.arange(len(a)), counts)
    cell = np.arange(len(seg)) - np.repeat(np.cumsum(counts) - counts, counts) + np.repeat(first, counts)
    z_low = np.minimum(a[:, 0], b[:, 0]) + reach[0]
    z_high = np.maximum(a[:, 0], b[:, 0]) + reach[1]
    return seg, cell, np.clip(stock.centres()[cell], z_low[seg], z_high[seg])


def envelope(a: np.ndarray, b: np.ndarray, nose: float, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The stadium's lowest and highest radius at ``z`` (per row; inf/-inf where it does not reach z)."""
    low = np.full(len(z), np.inf)
    high = np.full(len(z), -np.inf)
    for end in (a, b):  # the end caps (the points themselves for a point tool)
        off = z - end[:, 0]
        reach = np.abs(off) <= nose + 1e-12
        half = np.sqrt(np.maximum(nose * nose - off * off, 0.0))
        low = np.where(reach, np.minimum(low, end[:, 1] - half), low)
        high = np.where(reach, np.maximum(high, end[:, 1] + half), high)
    dz, dr = b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]
    length = np.hypot(dz, dr)
    slanted = np.abs(dz) > 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        steps = np.where(slanted, dz, 1.0)
        shift_z = np.where(dz >= 0, dr, -dr) / length * nose  # the normal whose radius part points down
        shift_r = -np.abs(dz) / length * nose
        t = (z - shift_z - a[:, 0]) / steps  # the lower offset segment
        on = slanted & (t >= 0.0) & (t <= 1.0)
        low = np.where(on, np.minimum(low, a[:, 1] + t * dr + shift_r), low)
        t = (z + shift_z - a[:, 0]) / steps  # the upper one
        on = slanted & (t >= 0.0) & (t <= 1.0)
        high = np.where(on, np.maximum(high, a[:, 1] + t * dr - shift_r), high)
    return low, high
