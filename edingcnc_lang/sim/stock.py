"""The stock as a height field: the top Z of the material over a grid of XY cells.

Cell (j, i) is the square of side ``resolution`` whose centre is ``x0 + (i + 0.5) r``,
``y0 + (j + 0.5) r``; its material stands from ``bottom`` up to ``top[j, i]`` (a cell with no
material left has ``top == bottom``).  Coordinates are the job's work coordinates (the first work
offset).  One float32 per cell: 4 bytes, so a 1 m x 1 m table at 0.25 mm is 16 million cells and
64 MB (61 MiB; the sweep's scratch arrays are bounded per chunk, not per table; a stock read from
STL keeps a second copy, its uncut top, for the volumes).  What a height field
cannot hold (undercuts, material under an overhang) is not modelled.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from edingcnc_lang.errors import EXIT_USAGE, EcncError
from edingcnc_lang.syntax.input_limits import MAX_SIM_LENGTH

MAX_CELLS = 400_000_000  # 1.6 GB of heights: more is a typo in --stock or --resolution


class StockError(EcncError):
    """A stock or resolution that cannot be simulated: the user's input (exit 2)."""

    exit_code = EXIT_USAGE
    kind = "usage"


@dataclass
class Stock:
    """The height field; ``initial`` is the top before cutting (for the volumes), None for a box
    (whose top is ``height`` everywhere: no second copy of a large field)."""

    x0: float
    y0: float
    resolution: float
    bottom: float
    height: float          # the box's top (the highest point of a non-box stock)
    top: np.ndarray                 # (ny, nx) float32
    initial: np.ndarray | None = None  # (ny, nx) float32

    @classmethod
    def box(cls, lower: tuple[float, float, float], upper: tuple[float, float, float],
            resolution: float) -> Stock:
        """A block from ``lower`` to ``upper`` (XYZ), cut into cells of ``resolution`` mm."""
        nx, ny = grid_size(lower, upper, resolution)
        top = np.full((ny, nx), upper[2], dtype=np.float32)
        return cls(lower[0], lower[1], resolution, lower[2], upper[2], top)

    @property
    def shape(self) -> tuple[int, int]:
        return self.top.shape

    @property
    def box_bounds(self) -> list[float]:
        """XMIN, YMIN, ZMIN, XMAX, YMAX, ZMAX of the grid (the cells cover it whole)."""
        ny, nx = self.shape
        r = self.resolution
        return [self.x0, self.y0, self.bottom, self.x0 + nx * r, self.y0 + ny * r, self.height]

    def xs(self) -> np.ndarray:
        return self.x0 + (np.arange(self.shape[1]) + 0.5) * self.resolution

    def ys(self) -> np.ndarray:
        return self.y0 + (np.arange(self.shape[0]) + 0.5) * self.resolution

    def cell_volume(self, top: np.ndarray) -> float:
        """mm³ of material under ``top`` (down to the bottom), summed in float64 a band of rows at a
        time, so a large field needs no float64 copy of itself."""
        bottom = np.float32(self.bottom)
        total = 0.0
        for rows in np.array_split(top, max(1, top.shape[0] // 256)):
            total += float(np.sum(np.maximum(rows - bottom, np.float32(0.0)), dtype=np.float64))
        return total * self.resolution ** 2

    @property
    def initial_volume(self) -> float:
        if self.initial is None:
            ny, nx = self.shape
            return nx * ny * (self.height - self.bottom) * self.resolution ** 2
        return self.cell_volume(self.initial)

    @property
    def remaining_volume(self) -> float:
        return self.cell_volume(self.top)

    @property
    def removed_volume(self) -> float:
        return self.initial_volume - self.remaining_volume


def grid_size(lower: tuple[float, float, float], upper: tuple[float, float, float],
              resolution: float) -> tuple[int, int]:
    """Cells across X and Y for a box; a box of no size, or of too many cells, is refused."""
    if not (resolution > 0 and math.isfinite(resolution)):
        raise StockError(f"the resolution must be a positive number of mm, not {resolution}")
    corners = (*lower, *upper)
    if any(not abs(v) <= MAX_SIM_LENGTH for v in corners):
        raise StockError(f"a stock corner lies beyond {MAX_SIM_LENGTH:g} mm (the limit; got "
                         f"{', '.join(f'{v:g}' for v in corners)})")
    sizes = [u - lo for lo, u in zip(lower, upper)]
    if any(not math.isfinite(s) or s <= 0 for s in sizes):
        raise StockError("the stock box must have XMIN < XMAX, YMIN < YMAX and ZMIN < ZMAX "
                         f"(got {', '.join(f'{v:g}' for v in corners)})")
    across = [s / resolution for s in sizes[:2]]  # floats first: a count past the doubles is no int
    if not across[0] * across[1] <= MAX_CELLS:
        raise StockError(f"{across[0]:.6g} x {across[1]:.6g} cells at {resolution:g} mm are too many "
                         f"(at most {MAX_CELLS:,}): use a coarser --resolution")
    nx, ny = (max(1, round(cells)) for cells in across)
    if nx * ny > MAX_CELLS:
        raise StockError(f"{nx} x {ny} cells at {resolution:g} mm are too many (at most {MAX_CELLS:,}): "
                         "use a coarser --resolution")
    return nx, ny
