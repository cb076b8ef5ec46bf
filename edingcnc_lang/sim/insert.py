"""A lathe insert beyond its nose, and the holder behind it: their sweep in the bar's half-plane.

With ``insert_angle`` (the insert's included angle: 80 for a C insert, 55 D, 35 V, 60 T) the
insert is its nose and its two cutting edges, each ``insert_size`` mm long from the sharp corner
(ISO's size: CNMG 120408 is 12; at least long enough for the back to clear the nose), closed by
its back: a triangle whose rounded tip is the nose.  It points the way ``orientation`` puts the
imaginary tip (1..8; its bisector runs from the tip through the nose's centre), so an 80° insert
at orientation 2 has one edge 5° off the face and one 5° off the turned diameter, as an SCLCR
holder holds it.  With ``holder_width`` the holder is a strip of that width from the insert's far
end outwards, unbounded: along +X for an outside tool (its side flush with the insert's leading
side), along +Z out of the bore for an inside one (orientations 3, 4 and 8: a boring bar, its top
flush with the insert's; a bar reaching across the axis meets the bore's far side).  Each part
swept along a stroke is convex, so its lowest and highest radius at a slice's centre lie on the
sweep of its outline: the outline's segments at both ends of the stroke and the paths of their
corners.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.pipeline.comp_geometry import TIP_X, TIP_Z
from edingcnc_lang.sim.round_stock import EPS, RoundStock
from edingcnc_lang.sim.sweep import split_long
from edingcnc_lang.sim.tools import Tool
from edingcnc_lang.sim.turning import envelope, ranges_over, slices

DEFAULT_INSERT_SIZE = 12.0  # mm: a cutting edge's length when the tools file gives none (CNMG 12..)
INSIDE = (3, 4, 8)          # the tip points +X, away from the axis: a boring bar's
TOUCH = 1e-9                # mm: a slice's centre this close to a vertical segment lies on it


@dataclass(frozen=True)
class Holder:
    """A strip from ``start`` along its axis (+Z if ``along_z``, else +X) outwards, between the
    lateral offsets ``side`` (radius offsets along Z, Z offsets along X), all from the nose's centre."""

    along_z: bool
    start: float
    side: tuple[float, float]


@dataclass(frozen=True)
class InsertShape:
    """The insert's outline beyond the nose (segments (k, 2, 2) of (Z, radius) offsets from the
    nose's centre; none without ``insert_angle``), its extent, and the holder."""

    nose: float
    outline: np.ndarray
    z_extent: tuple[float, float]
    r_low: float
    holder: Holder | None


def insert_shape(tool: Tool) -> InsertShape | None:
    """The insert and holder of ``tool``; None for a bare nose (no ``insert_angle``, no ``holder_width``)."""
    if tool.insert_angle is None and tool.holder_width is None:
        return None
    nose = tool.nose_radius or 0.0
    orientation = tool.orientation or 0
    tip = np.array([TIP_Z.get(orientation, 0), TIP_X.get(orientation, 0)], dtype=float)
    points = [np.array(p) for p in ((-nose, 0.0), (nose, 0.0), (0.0, -nose), (0.0, nose))]
    outline = np.zeros((0, 2, 2))
    if tool.insert_angle is not None and tip.any():
        tip /= np.hypot(*tip)
        half = math.radians(tool.insert_angle) / 2.0
        corner = tip * nose / math.sin(half)  # the sharp corner the edges meet at
        # at least so long that the back clears the nose (a nose that big is on no insert that small)
        size = max(tool.insert_size or DEFAULT_INSERT_SIZE, nose * (1.0 + 1.0 / math.sin(half)) / math.cos(half))
        ends, touches = [], []
        for turn in (half, -half):
            c, s = math.cos(turn), math.sin(turn)
            edge = np.array([-(c * tip[0] - s * tip[1]), -(s * tip[0] + c * tip[1])])  # the bisector turned
            ends.append(corner + size * edge)
            touches.append(corner + nose / math.tan(half) * edge)
        outline = np.array([[touches[0], ends[0]], [touches[1], ends[1]], [ends[0], ends[1]]])
        points += ends
    cloud = np.array(points)
    holder = None
    if tool.holder_width is not None:
        along_z = orientation in INSIDE
        axis, lateral = (0, 1) if along_z else (1, 0)
        lead = tip[lateral] if not along_z else 1.0  # a boring bar's top is flush with the insert's
        low, high = float(cloud[:, lateral].min()), float(cloud[:, lateral].max())
        width = tool.holder_width
        side = (low, low + width) if lead < 0 else (high - width, high) if lead > 0 else (-width / 2, width / 2)
        holder = Holder(along_z, float(cloud[:, axis].max()), side)
    return InsertShape(nose, outline, (float(cloud[:, 0].min()), float(cloud[:, 0].max())),
                       float(cloud[:, 1].min()), holder)


def holder_reach(holder: Holder) -> tuple[float, float, float]:
    """The holder's Z extent (low, high: inf along Z) and lowest radius, as offsets from the nose's centre."""
    if holder.along_z:
        return holder.start, math.inf, holder.side[0]
    return holder.side[0], holder.side[1], holder.start


def outline_envelope(a: np.ndarray, b: np.ndarray, outline: np.ndarray,
                     z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest radius at ``z`` of the outline's segments swept from ``a`` to ``b`` (per row)."""
    low = np.full(len(z), np.inf)
    high = np.full(len(z), -np.inf)
    for p, q in outline:
        for u, v in ((a + p, a + q), (b + p, b + q), (a + p, b + p), (a + q, b + q)):
            lo, hi = _at(z, u, v)
            low, high = np.minimum(low, lo), np.maximum(high, hi)
    return low, high


def _at(z: np.ndarray, u: np.ndarray, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The segments ``u``-``v`` (rows of (Z, radius)) at ``z``: their radius (both ends of a vertical
    one), inf/-inf where they do not reach ``z``."""
    dz = v[:, 0] - u[:, 0]
    flat = np.abs(dz) <= 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.where(flat, 0.0, (z - u[:, 0]) / np.where(flat, 1.0, dz))
    radius = u[:, 1] + np.clip(t, 0.0, 1.0) * (v[:, 1] - u[:, 1])
    on = ~flat & (t >= -1e-12) & (t <= 1.0 + 1e-12)
    upright = flat & (np.abs(z - u[:, 0]) <= TOUCH)
    low = np.where(on, radius, np.where(upright, np.minimum(u[:, 1], v[:, 1]), np.inf))
    high = np.where(on, radius, np.where(upright, np.maximum(u[:, 1], v[:, 1]), -np.inf))
    return low, high


def holder_envelope(a: np.ndarray, b: np.ndarray, holder: Holder, z: np.ndarray,
                    ceiling: float) -> tuple[np.ndarray, np.ndarray]:
    """Lowest and highest radius at ``z`` of the holder swept from ``a`` to ``b`` (inf/-inf where it
    is not there; ``ceiling`` stands for the unbounded top of an outside holder)."""
    if holder.along_z:  # the nose's centre at or below z - start along Z: the strip between its sides
        low, high = _over(a, b, -np.inf, z - holder.start)
        low, high = low + holder.side[0], high + holder.side[1]
        return low, np.maximum(high, -low)  # a bar across the axis reaches the bore's far side
    low, _ = _over(a, b, z - holder.side[1], z - holder.side[0])
    return low + holder.start, np.where(np.isfinite(low), ceiling, -np.inf)


def _over(a: np.ndarray, b: np.ndarray, z_low: np.ndarray | float,
          z_high: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The least and greatest radius of the stroke ``a``-``b`` where its Z lies in [z_low, z_high]
    (inf/-inf where it never does)."""
    dz = b[:, 0] - a[:, 0]
    flat = np.abs(dz) <= 1e-12
    with np.errstate(divide="ignore", invalid="ignore"):
        t0 = (z_low - a[:, 0]) / np.where(flat, 1.0, dz)
        t1 = (z_high - a[:, 0]) / np.where(flat, 1.0, dz)
    first = np.where(flat, 0.0, np.maximum(np.minimum(t0, t1), 0.0))
    last = np.where(flat, 1.0, np.minimum(np.maximum(t0, t1), 1.0))
    inside = np.where(flat, (a[:, 0] >= z_low) & (a[:, 0] <= z_high), first <= last)
    r0 = a[:, 1] + first * (b[:, 1] - a[:, 1])
    r1 = a[:, 1] + last * (b[:, 1] - a[:, 1])
    return np.where(inside, np.minimum(r0, r1), np.inf), np.where(inside, np.maximum(r0, r1), -np.inf)


def insert_envelope(a: np.ndarray, b: np.ndarray, shape: InsertShape, z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The whole insert's (nose and edges) lowest and highest radius at ``z`` swept from ``a`` to ``b``."""
    low, high = envelope(a, b, shape.nose, z)
    edge_low, edge_high = outline_envelope(a, b, shape.outline, z)
    return np.minimum(low, edge_low), np.maximum(high, edge_high)


def insert_spans(stock: RoundStock, a: np.ndarray, b: np.ndarray, shape: InsertShape, first: np.ndarray,
                 last: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``turning.spans`` for the whole insert: (segment, slice, low, high) of the nose and edges."""
    seg, cell, z = slices(stock, a, b, shape.z_extent, first, last)
    low, high = insert_envelope(a[seg], b[seg], shape, z)
    keep = np.isfinite(low)
    return seg[keep], cell[keep], low[keep], high[keep]


def holder_ranges(stock: RoundStock, a: np.ndarray, b: np.ndarray, holder: Holder) -> tuple[np.ndarray, np.ndarray]:
    """The slices under the holder along each stroke (an inside tool's reach to the bar's face)."""
    low, high, _ = holder_reach(holder)
    return ranges_over(stock, np.minimum(a[:, 0], b[:, 0]) + low,
                       np.minimum(np.maximum(a[:, 0], b[:, 0]) + high, stock.start + stock.length))


def holder_spans(stock: RoundStock, a: np.ndarray, b: np.ndarray, shape: InsertShape,
                 open_top: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(stroke, slice, low, high) where the holder, moved along each stroke in steps, is at material
    the insert's cut along the stroke up to that step has not taken (the material as the earlier
    strokes left it decides the rest, in ``RoundStock.cut``).  The step is a quarter of the holder's
    distance from the nose's centre: within one the insert's cut is not yet counted, so a holder
    flush with the insert's leading side meets what the edge has not reached."""
    holder = shape.holder
    assert holder is not None
    starts, ends, owner = split_long(a, b, max(stock.resolution, holder.start / 4.0))
    first, last = holder_ranges(stock, starts, ends, holder)
    z_low, z_high, _ = holder_reach(holder)
    seg, cell, z = slices(stock, starts, ends, (z_low, z_high), first, last)
    low, high = holder_envelope(starts[seg], ends[seg], holder, z, 2.0 * stock.radius + 1.0)
    cut_low, cut_high = insert_envelope(a[owner[seg]], starts[seg], shape, z)
    if open_top:  # the insert took everything above its lowest point
        meets = low < cut_low - EPS
    else:  # an inside insert opened the bore up to its highest point where it reached the bore
        bore = stock.inner[cell, 0].astype(np.float64)
        meets = (cut_low > np.maximum(low, bore) + EPS) | (high > cut_high + EPS)
    keep = np.isfinite(low) & meets
    return owner[seg[keep]], cell[keep], low[keep], high[keep]
