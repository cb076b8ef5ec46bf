"""The cut part compared: both jobs cut the same stock (by ``ecnc sim``'s ``sim.simulate``, which the
caller runs: a product does not import another, docs/architecture.md), then the two height fields
are compared cell by cell.  The answer does not depend on the order of the moves: a toolpath done
in another order that removes the same material is the same part.

Cells whose heights differ by more than the tolerance form regions (cells that touch on a grid of
blocks of ``REGION_GAP`` mm, at most ``REGION_GRID`` a side, each block touching the 24 around it);
each region names the OLD and NEW lines whose cuts pass over it.  With the stock, every rapid of
NEW into the material is a finding at its line.
"""
from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol

import numpy as np

from edingcnc_lang.diff.compare import Change
from edingcnc_lang.diff.record import RAPID_KINDS, Recording


class CutStock(Protocol):
    """The height field of a cut stock (``sim.Stock``): cell (j, i) at ``x0 + (i + 0.5) r``, ``y0 + (j + 0.5) r``."""

    x0: float
    y0: float
    resolution: float
    top: np.ndarray


class CutTool(Protocol):
    @property
    def diameter(self) -> float: ...


class CutFinding(Protocol):
    @property
    def kind(self) -> str: ...
    @property
    def line(self) -> int: ...
    @property
    def depth(self) -> float: ...
    @property
    def tool(self) -> int: ...


class Cut(Protocol):
    """One job's simulation (``sim.SimResult``): the stock as cut, where its origin is in machine
    coordinates, the tools that cut and what the simulation found."""

    @property
    def stock(self) -> CutStock: ...
    @property
    def frame(self) -> tuple[float, float, float]: ...
    @property
    def tools(self) -> Mapping[int, CutTool]: ...
    @property
    def findings(self) -> Iterable[CutFinding]: ...


REGION_GRID = 256   # blocks a side the regions are found on (a region is cells that touch on this grid)
REGION_GAP = 1.0    # mm: differing cells closer than about this are one region
REGIONS = 20        # regions listed, largest deviation first


@dataclass
class Region:
    """Cells that differ and touch: where (work XY), how much, which lines cut there."""

    bounds: tuple[float, float, float, float]   # XMIN, YMIN, XMAX, YMAX
    max_deviation: float
    area: float
    deeper: str            # "new" where NEW removes more material, "old" where OLD does, "both" mixed
    old_lines: tuple[int, int] | None
    new_lines: tuple[int, int] | None

    def to_json(self) -> dict[str, Any]:
        return {"bounds": [round(v, 4) for v in self.bounds], "max_deviation": round(self.max_deviation, 6),
                "area": round(self.area, 3), "deeper": self.deeper,
                "old_lines": list(self.old_lines) if self.old_lines else None,
                "new_lines": list(self.new_lines) if self.new_lines else None}


@dataclass
class PartComparison:
    """Both parts as cut, and how they differ."""

    old: CutStock
    new: CutStock
    tolerance: float
    max_deviation: float
    mean_deviation: float   # over the cells that differ (0 when none does)
    regions: list[Region]
    rapids: list[Change] = field(default_factory=list)  # NEW's rapids into the stock

    @property
    def same(self) -> bool:
        return not self.regions

    def to_json(self) -> dict[str, Any]:
        return {"same": self.same, "max_deviation": round(self.max_deviation, 6),
                "mean_deviation": round(self.mean_deviation, 6), "resolution": self.old.resolution,
                "regions": [r.to_json() for r in self.regions]}


def compare_parts(before: Cut, after: Cut, old: Recording, new: Recording, tolerance: float = 0.001) -> PartComparison:
    """Compare the parts ``before`` (OLD's cut) and ``after`` (NEW's, of the same stock); the recordings
    give the lines of the moves over each region."""
    difference = after.stock.top.astype(np.float64) - before.stock.top
    differs = np.abs(difference) > tolerance
    size = np.abs(difference[differs])
    regions = _regions(before, after, difference, differs, old, new)
    rapids = [Change("rapid_into_stock", None, (f.line, f.line), distance=f.depth, tool=f.tool)
              for f in after.findings if f.kind == "rapid_into_stock"]
    return PartComparison(before.stock, after.stock, tolerance, float(size.max()) if size.size else 0.0,
                          float(size.mean()) if size.size else 0.0, regions, rapids)


def _regions(before: Cut, after: Cut, difference: np.ndarray, differs: np.ndarray,
             old: Recording, new: Recording) -> list[Region]:
    """The regions of cells that differ, largest deviation first (at most ``REGIONS``)."""
    if not differs.any():
        return []
    stock = before.stock
    ny, nx = differs.shape
    block = max(1, math.ceil(max(ny, nx) / REGION_GRID), math.ceil(REGION_GAP / stock.resolution))
    padded = np.zeros((math.ceil(ny / block) * block, math.ceil(nx / block) * block), dtype=bool)
    padded[:ny, :nx] = differs
    coarse = np.asarray(padded.reshape(padded.shape[0] // block, block, padded.shape[1] // block, block).any(axis=(1, 3)),
                        dtype=bool)
    labels = _label(coarse)
    fine = np.repeat(np.repeat(labels, block, axis=0), block, axis=1)[:ny, :nx]
    fine = np.where(differs, fine, 0)
    radius = max([t.diameter / 2 for r in (before, after) for t in r.tools.values()], default=0.0)
    found = []
    for label in range(1, int(labels.max()) + 1):
        rows, cols = np.nonzero(fine == label)
        if not rows.size:
            continue
        r = stock.resolution
        bounds = (stock.x0 + cols.min() * r, stock.y0 + rows.min() * r,
                  stock.x0 + (cols.max() + 1) * r, stock.y0 + (rows.max() + 1) * r)
        values = difference[rows, cols]
        deeper = "new" if (values < 0).all() else "old" if (values > 0).all() else "both"
        # the moves that reach down to the higher of the two surfaces there: those that made the difference
        top = float(np.maximum(before.stock.top[rows, cols], after.stock.top[rows, cols]).max())
        found.append(Region(bounds, float(np.abs(values).max()), float(rows.size * r * r), deeper,
                            _lines_over(old, before.frame, bounds, radius, top),
                            _lines_over(new, after.frame, bounds, radius, top)))
    found.sort(key=lambda region: -region.max_deviation)
    return found[:REGIONS]


def _label(mask: np.ndarray) -> np.ndarray:
    """Connected regions (a block touches those up to two away) of a small boolean grid, numbered from 1."""
    labels = np.zeros(mask.shape, dtype=np.int32)
    count = 0
    for start in zip(*np.nonzero(mask)):
        if labels[start]:
            continue
        count += 1
        labels[start] = count
        queue = deque([start])
        while queue:
            j, i = queue.popleft()
            for dj in (-2, -1, 0, 1, 2):
                for di in (-2, -1, 0, 1, 2):
                    a, b = j + dj, i + di
                    if 0 <= a < mask.shape[0] and 0 <= b < mask.shape[1] and mask[a, b] and not labels[a, b]:
                        labels[a, b] = count
                        queue.append((a, b))
    return labels


def _lines_over(rec: Recording, frame: tuple[float, float, float], bounds: tuple[float, float, float, float],
                radius: float, top: float) -> tuple[int, int] | None:
    """The first and last job line of the cutting moves that pass over ``bounds`` (work XY; the tool's
    radius around them) at or below ``top`` (work Z, the tool length of the first move)."""
    lowest = np.minimum(rec.starts[:, 2], rec.ends[:, 2]) - frame[2]
    cutting = ~np.isin(rec.kinds, RAPID_KINDS) & (lowest <= top + 1e-6)
    low = np.minimum(rec.starts[:, :2], rec.ends[:, :2]) - frame[:2]
    high = np.maximum(rec.starts[:, :2], rec.ends[:, :2]) - frame[:2]
    arcs = rec.frames[:, 0] >= 0  # an arc's box: its circle's (a bound, not the arc's own)
    if arcs.any():
        reach = np.maximum(rec.frames[arcs, 4], rec.frames[arcs, 5])
        centre = np.zeros((int(arcs.sum()), 2))
        u, v = rec.frames[arcs, 0].astype(int), rec.frames[arcs, 1].astype(int)
        for axis in (0, 1):
            centre[:, axis] = np.where(u == axis, rec.frames[arcs, 2], np.where(v == axis, rec.frames[arcs, 3],
                                                                                 rec.starts[arcs, axis]))
        low[arcs] = np.minimum(low[arcs], centre - reach[:, None] - frame[:2])
        high[arcs] = np.maximum(high[arcs], centre + reach[:, None] - frame[:2])
    over = cutting & np.all(low <= np.array(bounds[2:]) + radius, axis=1) & \
        np.all(high >= np.array(bounds[:2]) - radius, axis=1)
    lines = rec.lines[over]
    lines = lines[lines > 0]
    return (int(lines.min()), int(lines.max())) if lines.size else None
