"""What ``ecnc sim`` prints: the ``--json`` document and the lines for a person."""
from __future__ import annotations

from dataclasses import asdict
from typing import Any

from edingcnc_lang.sim.compare import Deviation
from edingcnc_lang.sim.job import SimResult


def to_json(result: SimResult, deviation: Deviation | None = None) -> dict[str, Any]:
    """``{"stock": {...}, "collisions": [...], "time": s, ...}`` (docs/simulation.md)."""
    stock = result.stock
    doc: dict[str, Any] = {
        "stock": {"box": [round(v, 6) for v in stock.box_bounds], "resolution": stock.resolution,
                  "cells": [stock.shape[1], stock.shape[0]],
                  "removed_volume": round(stock.removed_volume, 3),
                  "remaining_volume": round(stock.remaining_volume, 3)},
        "collisions": [f.to_json() for f in result.findings],
        "time": round(result.seconds, 3),
        "moves": result.moves,
        "shank_checked": result.shank_checked,
        "tools": {str(n): {k: v for k, v in asdict(t).items() if k != "number" and v is not None}
                  for n, t in sorted(result.tools.items())},
        "notes": result.notes,
    }
    if deviation is not None:
        doc["compare"] = deviation.to_json()
    if result.error is not None:
        doc["error"] = result.error.to_json()
    return doc


def summary(result: SimResult, deviation: Deviation | None = None) -> list[str]:
    """The findings, one line each (``FILE:LINE: error: ...``), then notes and the volumes."""
    lines = [f.format() for f in result.findings]
    lines += [f"note: {note}" for note in result.notes]
    errors = sum(f.severity == "error" for f in result.findings)
    hints = len(result.findings) - errors
    stock = result.stock
    lines.append(f"removed {stock.removed_volume:,.1f} mm³, {stock.remaining_volume:,.1f} mm³ left "
                 f"({stock.shape[1]} x {stock.shape[0]} cells of {stock.resolution:g} mm, {result.moves:,} moves, "
                 f"{result.seconds:.1f} s); {errors} collision{'s' * (errors != 1)}, {hints} hint{'s' * (hints != 1)}")
    if deviation is not None:
        lines.append(deviation.line())
    return lines
