"""The stock being cut, for ``ecnc view --stock``: coarse height maps every so many moves.

The job is simulated once more beside the viewer's run (both runs make the same moves in the same
order, so move numbers match); every ``N``-th move the field is averaged down to at most
``SIZE`` x ``SIZE`` cells and quantised to 16 bits.  The frames go into the page as a second JSON
block (``stock-data``) that the viewer draws under the path, the frame of the move being shown.
"""
from __future__ import annotations

import base64
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any, Generic, TypeVar

import numpy as np

from edingcnc_lang.errors import EcncError
from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.job import simulate
from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.sim.tools import Tool
from edingcnc_lang.outputs import write_text

SIZE = 64      # cells across the longer side of a frame
FRAMES = 48    # frames in a page at most (about 400 kB of base64 at 64 x 64)
MARKER = '<script type="application/json" id="job-data">'


Cut = TypeVar("Cut")


class Frames(Generic[Cut]):
    """The frames a page plays, for every stock: the simulation's snapshot hook (``on_snapshot``,
    called every ``every``-th move of ``moves``, at most ``FRAMES`` times) keeps ``reduce`` of the
    stock as cut so far and the move it was taken before; ``close`` adds the stock at the end."""

    def __init__(self, moves: int, reduce: Callable[[Cut], np.ndarray]) -> None:
        self.every = max(1, math.ceil(max(moves, 1) / FRAMES))
        self.reduce = reduce
        self.frames: list[np.ndarray] = []
        self.at: list[int] = []

    def snapshot(self, index: int, cut: Cut) -> None:
        self.frames.append(self.reduce(cut))
        self.at.append(index)

    def close(self, cut: Cut, moves: int) -> np.ndarray:
        """The last frame (the stock after all ``moves``) added; all of them stacked."""
        self.snapshot(moves, cut)
        return np.stack(self.frames)


def coarse(stock: Stock, size: int = SIZE) -> tuple[np.ndarray, float]:
    """The field averaged over square blocks so that neither side has more than ``size`` blocks;
    returns the heights and the block's side in mm."""
    step = max(1, math.ceil(max(stock.shape) / size))
    ny, nx = stock.shape
    padded = np.pad(stock.top.astype(np.float64), ((0, -ny % step), (0, -nx % step)), mode="edge")
    blocks = padded.reshape(padded.shape[0] // step, step, padded.shape[1] // step, step)
    return blocks.mean(axis=(1, 3)), step * stock.resolution


def stock_frames(job: Path, stock: Stock, options: RunOptions, moves: int, tools: dict[int, Tool] | None,
                 first_tool: int | None, name: str | None) -> dict[str, Any]:
    """Simulate ``job`` and return the page's ``stock-data``: frames in machine coordinates."""
    frames: Frames[Stock] = Frames(moves, lambda cut: coarse(cut)[0])
    result = simulate(job, stock, options, tools, first_tool, name, every=frames.every, on_snapshot=frames.snapshot)
    heights = frames.close(stock, result.moves)
    fx, fy, fz = result.frame
    low, high = stock.bottom, stock.height
    stacked = np.clip((heights - low) / max(high - low, 1e-9), 0.0, 1.0)
    cell = coarse(stock)[1]
    return {"x0": stock.x0 + fx, "y0": stock.y0 + fy, "cell": cell, "nx": stacked.shape[2], "ny": stacked.shape[1],
            "bottom": low + fz, "top": high + fz, "moves": frames.at,
            "heights": base64.b64encode(np.round(stacked * 65535).astype("<u2").tobytes()).decode()}


def add_to_page(page: Path, data: dict[str, Any], block: str = "stock-data") -> None:
    """Put the frames into a page ``ecnc view`` wrote, as a JSON block (``block``: its id) before the job's own."""
    text = page.read_text(encoding="utf-8")
    if MARKER not in text:
        raise EcncError(f"{page} is not a page of ecnc view (no job data in it)")
    body = json.dumps(data, separators=(",", ":"), allow_nan=False)
    text = text.replace(MARKER, f'<script type="application/json" id="{block}">{body}</script>\n{MARKER}', 1)
    write_text(page, text)
