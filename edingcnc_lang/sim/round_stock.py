"""Round stock: the material as radii over (axial cells, angle cells): a lathe's bar, a bar on a
mill's rotary A axis.

Axial cell ``i`` is the slice of ``resolution`` mm whose centre is ``start + (i + 0.5) r`` along
the axis (the lathe's Z); angle cell ``k`` the sector of ``360 / angles`` degrees around it.  Each
cell's material lies between an inner radius (a bore, 0 for a solid bar) and an outer radius, as a
ray from the axis sees it: a pocket under an overhang, or a cavity closed on every side, is not
held.  A lathe's cut sweeps every angle while the spindle turns, so a lathe bar has one angle
column; on the A axis the angle cells are about a slice wide at the surface.  Two float32 per
cell: a 100 mm x 300 mm bar at 0.1 mm is 3,000 axial cells, 24 kB with one angle column; with
angle cells of 0.1 mm at its surface (3,142 of them) it would be 9.4 million cells, 75 MB.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.sim.stock import MAX_CELLS, StockError
from edingcnc_lang.syntax.input_limits import MAX_SIM_LENGTH

EPS = 1e-4  # mm: a change of radius smaller than this removes nothing (float32 rounding of the cut)


@dataclass
class RoundStock:
    """A bar from ``start`` to ``start + length`` along its axis, of ``radius``; ``outer``/``inner``
    are (axial cells, angle cells) float32 radii."""

    start: float
    length: float
    radius: float
    resolution: float
    outer: np.ndarray
    inner: np.ndarray

    @classmethod
    def bar(cls, diameter: float, length: float, start: float, resolution: float, angles: int = 1) -> RoundStock:
        """A solid bar of ``diameter`` from ``start`` to ``start + length``, cut into slices of ``resolution``."""
        if not (resolution > 0 and math.isfinite(resolution)):
            raise StockError(f"the resolution must be a positive number of mm, not {resolution}")
        if not (0 < diameter <= MAX_SIM_LENGTH and 0 < length <= MAX_SIM_LENGTH and abs(start) <= MAX_SIM_LENGTH):
            raise StockError(f"the bar must have a positive diameter and length (got {diameter:g}, {length:g})")
        across = length / resolution
        if not across * angles <= MAX_CELLS:
            raise StockError(f"{across:.6g} x {angles} cells at {resolution:g} mm are too many "
                             f"(at most {MAX_CELLS:,}): use a coarser --resolution")
        count = max(1, round(across))
        outer = np.full((count, angles), diameter / 2.0, dtype=np.float32)
        return cls(start, length, diameter / 2.0, length / count, outer, np.zeros_like(outer))

    @classmethod
    def cylinder(cls, diameter: float, length: float, start: float, resolution: float) -> RoundStock:
        """A bar on a rotary axis: angle cells of about ``resolution`` mm at its surface (at least 8)."""
        if not (resolution > 0 and 0 < diameter <= MAX_SIM_LENGTH):
            raise StockError("the resolution and the diameter must be positive numbers of mm")
        around = math.pi * diameter / resolution  # a float first: past the doubles it is no int
        if not around * max(length / resolution, 1.0) <= MAX_CELLS:
            raise StockError(f"{length / resolution:.6g} x {around:.6g} cells at {resolution:g} mm are too many "
                             f"(at most {MAX_CELLS:,}): use a coarser --resolution")
        return cls.bar(diameter, length, start, resolution, max(8, math.ceil(around)))

    @property
    def shape(self) -> tuple[int, int]:
        return self.outer.shape

    def centres(self) -> np.ndarray:
        """The axial position of each slice's centre."""
        return self.start + (np.arange(self.shape[0]) + 0.5) * self.resolution

    def cell_of(self, position: np.ndarray) -> np.ndarray:
        """The slice index nearest below each axial position (may lie outside 0..count-1)."""
        return np.floor((position - self.start) / self.resolution - 0.5).astype(np.int64)

    def _volume(self, outer: np.ndarray, inner: np.ndarray) -> float:
        area = np.maximum(outer.astype(np.float64) ** 2 - inner.astype(np.float64) ** 2, 0.0)
        return float(area.sum()) * math.pi / self.shape[1] * self.resolution

    @property
    def initial_volume(self) -> float:
        return math.pi * self.radius ** 2 * self.resolution * self.shape[0]

    @property
    def remaining_volume(self) -> float:
        return self._volume(self.outer, self.inner)

    @property
    def removed_volume(self) -> float:
        return self.initial_volume - self.remaining_volume

    def angle_step(self) -> float:
        """Degrees per angle cell."""
        return 360.0 / self.shape[1]

    def profile(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Axial centres, outer and inner radii of angle column 0 (a lathe part's whole profile)."""
        return self.centres(), self.outer[:, 0].astype(np.float64), self.inner[:, 0].astype(np.float64)

    def cut(self, cells: np.ndarray, low: np.ndarray, high: np.ndarray, open_top: bool = True) -> np.ndarray:
        """Remove, in cell ``cells[k]`` (``slice * angles + angle``: the slice itself on a lathe),
        the material a tool spans from radius ``low[k]`` to ``high[k]``, the entries in the order
        the tool made them.  A tool is the solid its nose leads, as a ray
        from the axis sees it: an outside tool takes everything above its lowest point (the outer
        radius sinks to ``low``); one whose nose reaches the bore or the axis and not the surface as
        the earlier cuts left it (a drill, a boring bar) takes everything up to ``high`` (the inner
        radius rises).  Without ``open_top`` (a mill's tool on a rotary axis, whose side a ray may
        leave below the surface) a cut takes material only where its ray reaches the surface.
        Returns per entry the depth of material it removed (0 where none)."""
        outer = self.outer.reshape(-1)  # views: the cuts land in the stock
        inner = self.inner.reshape(-1)
        order = np.argsort(cells, kind="stable")  # grouped by slice, in the tool's order within each
        cell, lo, hi = cells[order], low[order], high[order]
        start_top, start_bore = outer[cell].astype(np.float64), inner[cell].astype(np.float64)
        bore = start_bore
        top = float(start_top.max()) if len(cell) else 0.0  # no running minimum above it counts
        groups = Groups(cell)
        floor = np.maximum(lo, 0.0)  # a cut goes no deeper than the axis
        for _ in range(2):  # the second time with the bore as the earlier entries of the cell left it
            at_bore = lo <= bore + EPS
            outside = ~at_bore if open_top else ~at_bore & (hi >= start_top - EPS)
            before = np.minimum(start_top, groups.running_min(np.where(outside, lo, np.inf), top))
            surface = hi >= before - EPS  # a cut from outside if it reaches the surface
            if open_top:
                surface |= ~at_bore
            before = np.minimum(start_top, groups.running_min(np.where(surface, floor, np.inf), top))
            while not open_top:  # a chain of cuts, each reaching only the surface the one before left
                grown = surface | (hi >= before - EPS)  # grows as the surface sinks: its end is the cut in order
                if np.array_equal(grown, surface):
                    break
                surface = grown
                before = np.minimum(start_top, groups.running_min(np.where(surface, floor, np.inf), top))
            surface &= lo < before - EPS
            boring = at_bore & ~surface & (hi > bore + EPS) & (before > bore + EPS)
            if not boring.any() or bore is not start_bore:
                break
            bore = np.maximum(start_bore, -groups.running_min(np.where(boring, -hi, np.inf), 0.0))
        depth = np.zeros(len(cell))
        depth[surface] = np.maximum(before[surface] - np.maximum(lo[surface], bore[surface]), 0.0)
        depth[boring] = np.minimum(hi[boring], before[boring]) - bore[boring]
        _fold(np.minimum, outer, cell[surface], floor[surface].astype(np.float32))
        if boring.any():
            _fold(np.maximum, inner, cell[boring], hi[boring].astype(np.float32))
        removed = np.empty(len(cells))
        removed[order] = depth
        return removed


def _fold(ufunc: np.ufunc, target: np.ndarray, cells: np.ndarray, values: np.ndarray) -> None:
    """``ufunc.at(target, cells, values)`` for ``cells`` ascending: each cell's values folded first
    (``reduceat``), then into the target once.  The same numbers: a least (greatest) value is one of
    them whatever the order, and no cut leaves a -0 for a tie to tell apart from 0."""
    if not len(cells):
        return
    starts = np.flatnonzero(np.r_[True, cells[1:] != cells[:-1]])
    where = cells[starts]
    target[where] = ufunc(target[where], ufunc.reduceat(values, starts))


class Groups:
    """Entries grouped by cell (``groups`` ascending): what every running minimum over them shares."""

    def __init__(self, groups: np.ndarray) -> None:
        self.base = (groups - groups[0]).astype(np.float64) if len(groups) else np.zeros(0)
        self.new = groups[1:] != groups[:-1]  # where a group starts (after the first)

    def running_min(self, values: np.ndarray, ceiling: float) -> np.ndarray:
        """Per entry, the least of the earlier ``values`` of its group; where there is none, inf or a
        number above ``ceiling`` (the callers clamp to at most it).  Shifting each group below all
        earlier ones by more than the values' spread and ``ceiling`` makes one running minimum serve
        all (an earlier group's minimum, shifted, is what an entry with none sees)."""
        if not len(values):
            return values
        finite = np.isfinite(values)
        span = 1.0
        if finite.any():
            most, least = values.max(where=finite, initial=-np.inf), values.min(where=finite, initial=np.inf)
            span = float(max(float(most), ceiling) - least) + 1.0
        shift = self.base[:-1] * span
        out = np.empty(len(values))
        out[0] = np.inf
        running = out[1:]
        np.subtract(values[:-1], shift, out=running)
        np.minimum.accumulate(running, out=running)
        running += shift
        running[self.new] = np.inf
        return out
