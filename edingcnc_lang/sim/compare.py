"""The cut stock against the intended part: where too much or too little was removed.

The part's STL (in the stock's work coordinates) is rasterised onto the stock's grid as its top
surface; over the cells the part covers, the deviation is the cut height minus the part's height:
positive where material was left (under-cut), negative where the tool went into the part
(over-cut, a gouge).  Cells outside the part's outline are not compared (whether the job should
clear them, or leave tabs and a frame, the part cannot tell).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.errors import Location
from edingcnc_lang.sim.stl import StlError, raster_top, read_stl
from edingcnc_lang.sim.stock import Stock


@dataclass
class Deviation:
    """The deviation map (NaN outside the part) and its figures in mm."""

    file: str
    map: np.ndarray
    max_overcut: float     # deepest gouge into the part, 0 when none
    max_undercut: float    # thickest material left on the part, 0 when none
    mean: float            # mean of |deviation| over the compared cells
    cells: int

    def line(self) -> str:
        """The report's line: the worst over- and under-cut and the mean."""
        return (f"against {self.file}: over-cut {self.max_overcut:.3f} mm, under-cut {self.max_undercut:.3f} mm, "
                f"mean |deviation| {self.mean:.3f} mm over {self.cells:,} cells")

    def to_json(self) -> dict[str, Any]:
        return {"file": self.file, "cells": self.cells, "max_overcut": round(self.max_overcut, 4),
                "max_undercut": round(self.max_undercut, 4), "mean_deviation": round(self.mean, 4)}


def compare(stock: Stock, part: str | Path) -> Deviation:
    """The deviation of the cut stock from the part in ``part`` (an STL file)."""
    top, covered = raster_top(stock, read_stl(part))
    if not covered.any():
        raise StlError("the part does not lie over the stock (no cell of the stock is under it)", Location(str(part)))
    deviation = np.where(covered, stock.top.astype(np.float64) - np.maximum(top, stock.bottom), np.nan)
    values = deviation[covered]
    return Deviation(str(part), deviation, max(0.0, -float(values.min())), max(0.0, float(values.max())),
                     float(np.abs(values).mean()), int(covered.sum()))
