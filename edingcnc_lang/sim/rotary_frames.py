"""The bar on a rotary axis being cut, for ``ecnc view --stock cylinder:``: its unrolled depth map
every so many moves.

As ``frames.py`` and ``bar_frames.py`` do, the job is simulated once more beside the viewer's run
(the same moves in the same order, so move numbers match), through ``simulate_cylinder``'s own
snapshot hook: every ``N``-th move (at most ``FRAMES`` frames) the depth below the bar's surface
over (axial position, the bar's own angle), as ``ecnc sim -o`` draws it, is averaged over square
blocks of cells so that a frame has at most ``CELLS`` of them, and quantised to 8 bits of the
deepest block of the job.  The page's ``rotary-data`` block holds the frames, where each shown move
leaves the tool on the bar (the marker) and the findings with their move, line and place.
"""
from __future__ import annotations

import base64
import math
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.frames import Frames
from edingcnc_lang.sim.rotary import simulate_cylinder
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool

CELLS = 8192  # blocks of a frame at most (48 frames x 8192 bytes: at most about 520 kB of base64)


def coarse_depth(stock: RoundStock, cells: int = CELLS) -> tuple[np.ndarray, int]:
    """The depth below the bar's surface, (angle blocks, axial blocks), each block the mean of
    ``step`` x ``step`` cells (the last ones along the axis repeat its end, around it wrap past
    360°) so that there are at most ``cells``; returns it and ``step``."""
    slices, angles = stock.shape
    step = max(1, math.ceil(math.sqrt(slices * angles / cells)))
    while math.ceil(slices / step) * math.ceil(angles / step) > cells:
        step += 1
    depth = stock.radius - stock.outer.astype(np.float64)
    depth = np.pad(depth, ((0, -slices % step), (0, 0)), mode="edge")
    depth = np.pad(depth, ((0, 0), (0, -angles % step)), mode="wrap")
    blocks = depth.reshape(depth.shape[0] // step, step, depth.shape[1] // step, step).mean(axis=(1, 3))
    return blocks.T, step


def rotary_frames(job: Path, stock: RoundStock, options: RunOptions, moves: int, shown: np.ndarray,
                  tools: dict[int, Tool] | None, first_tool: int | None, name: str | None) -> dict[str, Any]:
    """Cut the bar with ``job`` (of ``moves`` moves) and return the page's ``rotary-data``; ``shown``
    are the job's move numbers the page's moves end at (the tool's marker for each)."""
    frames: Frames[RoundStock] = Frames(moves, lambda cut: coarse_depth(cut)[0])
    result = simulate_cylinder(job, stock, options, tools, first_tool, name, every=frames.every,
                               on_snapshot=frames.snapshot, tips=True)
    maps = frames.close(stock, result.moves)
    step = coarse_depth(stock)[1]
    deepest = max(float(maps[-1].max()), 0.0)
    stacked = np.clip(maps / (deepest or 1.0), 0.0, 1.0)
    tips = result.tips if result.tips is not None else np.zeros((0, 2), np.float32)
    marks = tips[np.clip(shown, 0, len(tips) - 1)] if len(tips) else np.full((len(shown), 2), np.nan, np.float32)
    return {"axis": result.axis, "start": stock.start, "length": stock.length, "radius": stock.radius,
            "block": step * stock.resolution, "blockAngle": step * 360.0 / stock.shape[1],
            "n": stacked.shape[2], "m": stacked.shape[1], "deepest": deepest, "moves": frames.at,
            "depths": base64.b64encode(np.round(stacked * 255).astype(np.uint8).tobytes()).decode(),
            "tips": base64.b64encode(np.ascontiguousarray(marks, "<f4").tobytes()).decode(),
            "findings": [{"move": f.move, "line": f.line, "kind": f.kind,
                          "along": round(f.position[1] if result.axis == "B" else f.position[0], 4),
                          "angle": None if f.angle is None else round(f.angle, 3)} for f in result.findings]}
