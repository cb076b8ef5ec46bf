"""The bar being turned, for ``ecnc view --bar``: its profile every so many moves.

As ``frames.py`` does for the box stock, the job is simulated once more beside the viewer's run
(the same moves in the same order, so move numbers match); every ``N``-th move the profile (outer
and inner radius of each slice) is averaged down to at most ``SLICES`` slices and quantised to 16
bits of the bar's radius.  The page's ``bar-data`` block holds the frames, the chuck's face and the
findings (move, line, kind, where); the viewer draws the half section in the work's ZX plane (X a
radius, as the lathe view's path is) under the path, growing as the player runs.
"""
from __future__ import annotations

import base64
import math
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.runner import RunOptions
from edingcnc_lang.sim.frames import Frames
from edingcnc_lang.sim.lathe import simulate_bar
from edingcnc_lang.sim.round_stock import RoundStock
from edingcnc_lang.sim.tools import Tool

SLICES = 400  # slices of a frame at most (48 frames x 2 radii x 400 x 2 bytes: about 100 kB of base64)


def coarse_profile(stock: RoundStock, size: int = SLICES) -> tuple[np.ndarray, float]:
    """Outer and inner radii (2, n) averaged over runs of slices so that there are at most
    ``size``; returns them and the run's length in mm."""
    step = max(1, math.ceil(stock.shape[0] / size))
    _, outer, inner = stock.profile()
    radii = np.stack((outer, np.minimum(inner, outer)))
    padded = np.pad(radii, ((0, 0), (0, -len(outer) % step)), mode="edge")
    return padded.reshape(2, -1, step).mean(axis=2), step * stock.resolution


def bar_frames(job: Path, stock: RoundStock, options: RunOptions, moves: int, tools: dict[int, Tool] | None,
               first_tool: int | None, name: str | None, chuck: float | None) -> dict[str, Any]:
    """Turn the bar with ``job`` and return the page's ``bar-data`` (work coordinates, X a radius)."""
    frames: Frames[RoundStock] = Frames(moves, lambda cut: coarse_profile(cut)[0])
    result = simulate_bar(job, stock, options, tools, first_tool, name, chuck, every=frames.every,
                          on_snapshot=frames.snapshot)
    stacked = np.clip(frames.close(stock, result.moves) / stock.radius, 0.0, 1.0)
    scale = 2.0 if result.diameter_mode else 1.0
    return {"z0": stock.start, "slice": coarse_profile(stock)[1], "n": stacked.shape[2], "radius": stock.radius,
            "chuck": chuck, "moves": frames.at,
            "radii": base64.b64encode(np.round(stacked * 65535).astype("<u2").tobytes()).decode(),
            "findings": [{"move": f.move, "line": f.line, "kind": f.kind, "z": round(f.position[2], 4),
                          "x": round(f.position[0] / scale, 4)} for f in result.findings]}
