"""What ``ecnc sim`` writes for round stock: the ``--json`` document and the lines for a person
(``--bar`` and ``--stock cylinder:``), the half-section picture of a turned profile and the revolved
part as a closed STL mesh (``--bar``), the unwrapped depth map of a bar on a rotary axis."""
from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np

from edingcnc_lang.sim.compare import Deviation
from edingcnc_lang.sim.lathe import BarResult
from edingcnc_lang.sim.rotary import CylinderResult
from edingcnc_lang.sim.round_stock import EPS, RoundStock

SECTORS = 128  # facets around the axis in the STL


def to_json(result: BarResult | CylinderResult) -> dict[str, Any]:
    """The box sim's document (``stock.removed_volume``, ``collisions``...) with the bar's size:
    ``bar`` (DIAMETER, LENGTH, Z0 of its face) or ``cylinder`` (DIAMETER, LENGTH, X0)."""
    stock = result.stock
    size = [round(2 * stock.radius, 6), round(stock.length, 6)]
    where = {"bar": [*size, round(stock.start + stock.length, 6)]} if isinstance(result, BarResult) else \
        {"cylinder": [*size, round(stock.start, 6)], "axis": result.axis}
    doc: dict[str, Any] = {
        "stock": {**where, "resolution": stock.resolution, "cells": [stock.shape[0], stock.shape[1]],
                  "removed_volume": round(stock.removed_volume, 3),
                  "remaining_volume": round(stock.remaining_volume, 3)},
        "collisions": [f.to_json() for f in result.findings],
        "time": round(result.seconds, 3),
        "moves": result.moves,
        "tools": {str(n): {k: v for k, v in asdict(t).items() if k != "number" and v is not None}
                  for n, t in sorted(result.tools.items())},
        "notes": result.notes,
    }
    if isinstance(result, BarResult) and result.chuck is not None:
        doc["stock"]["chuck"] = round(result.chuck, 6)
    if result.error is not None:
        doc["error"] = result.error.to_json()
    return doc


def summary(result: BarResult | CylinderResult) -> list[str]:
    """The findings, one line each (``FILE:LINE: error: ...``), then notes and the volumes."""
    lines = [f.format() for f in result.findings]
    lines += [f"note: {note}" for note in result.notes]
    errors = sum(f.severity == "error" for f in result.findings)
    stock = result.stock
    lines.append(f"removed {stock.removed_volume:,.1f} mm³, {stock.remaining_volume:,.1f} mm³ left "
                 f"({stock.shape[0]} slices of {stock.resolution:g} mm x {stock.shape[1]} angles, {result.moves:,} moves, "
                 f"{result.seconds:.1f} s); {errors} collision{'s' * (errors != 1)}")
    return lines


def draw_bar(result: BarResult, out: Path, fmt: str, title: str, deviation: Deviation | None = None) -> None:
    """The half section: Z across, X up (as the job writes it: a diameter on a diameter lathe), the
    material left shaded over the bar's outline, the chuck hatched, the findings marked; with
    ``deviation`` (``--compare-stl``) the intended part's profile drawn over it."""
    from matplotlib.figure import Figure

    from edingcnc_lang.outputs import save_figure
    from edingcnc_lang.sim.picture import DPI, MARKERS

    stock = result.stock
    scale = 2.0 if result.diameter_mode else 1.0
    z, outer, inner = stock.profile()
    edges = stock.start + np.arange(stock.shape[0] + 1) * stock.resolution
    fig = Figure(figsize=(9.0, 4.5), dpi=DPI)
    ax = fig.add_subplot(1, 1, 1)
    top = stock.radius * scale
    ax.fill_between(edges, 0, top, color="#dddddd", label="bar")
    solid = outer > inner + EPS
    ax.stairs(np.where(solid, outer, np.nan) * scale, edges, baseline=np.where(solid, inner, np.nan) * scale,
              fill=True, color="#4c72b0", label="part")
    if deviation is not None:  # the bar's radius less the part's, per slice (one angle cell)
        intended = outer.astype(np.float64) - deviation.map[:, 0]
        ax.stairs(intended * scale, edges, color="#d62728", linestyle="--", linewidth=1.2,
                  label=f"{Path(deviation.file).name} (max over-cut {deviation.max_overcut:.3f} mm)")
    if isinstance(result, BarResult) and result.chuck is not None:
        ax.axvspan(edges[0] - 0.05 * stock.length, result.chuck, ymin=0, ymax=1, fill=False, hatch="//",
                   edgecolor="#7f7f7f", label="chuck")
    for kind, (marker, colour) in {**MARKERS, "chuck": ("P", "#2ca02c")}.items():
        points = [f.position for f in result.findings if f.kind == kind]
        if points:
            ax.scatter([p[2] for p in points], [p[0] for p in points], marker=marker, s=60, c=colour,
                       edgecolors="white", zorder=3, label=f"{kind} ({len(points)})")
            for p, f in zip(points, [f for f in result.findings if f.kind == kind]):
                ax.annotate(str(f.line), (p[2], p[0]), xytext=(4, 4), textcoords="offset points", fontsize=7)
    ax.set_xlim(edges[0] - 0.05 * stock.length, edges[-1] + 0.05 * stock.length)
    ax.set_ylim(0, top * 1.25)
    ax.set_xlabel("Z mm")
    ax.set_ylabel("X mm (diameter)" if result.diameter_mode else "X mm (radius)")
    ax.set_title(title, fontsize=9)
    ax.legend(loc="upper left", fontsize=7, ncol=4)
    fig.tight_layout()
    save_figure(fig, out, fmt, DPI)


def draw_unwrapped(result: CylinderResult, out: Path, fmt: str, title: str, deviation: Deviation | None = None
                   ) -> None:
    """The bar on the rotary axis unrolled: depth below its surface over X (Y on B) and the bar's own
    angle, the lines of the findings marked at their place along it (with ``deviation``: the bar's
    radius less the intended part's instead, red where material is left, blue where it gouged);
    below, the part shaded in 3D."""
    from matplotlib.figure import Figure

    from edingcnc_lang.outputs import save_figure
    from edingcnc_lang.sim.picture import DPI, MARKERS

    stock = result.stock
    step = max(1, math.ceil(max(stock.shape) / 1600))
    depth = (stock.radius - stock.outer[::step, ::step].astype(np.float64)).T
    fig = Figure(figsize=(9.0, 10.0), dpi=DPI)
    ax = fig.add_subplot(2, 1, 1)
    extent = (stock.start, stock.start + stock.length, 0.0, 360.0)
    if deviation is None:
        image = ax.imshow(depth, origin="lower", aspect="auto", cmap="magma_r", interpolation="nearest",
                          extent=extent, vmin=0.0)
        fig.colorbar(image, ax=ax, shrink=0.8, label="depth below the bar's surface, mm")
    else:
        worst = max(deviation.max_overcut, deviation.max_undercut, 1e-3)
        image = ax.imshow(deviation.map[::step, ::step].T, origin="lower", aspect="auto", cmap="RdBu_r",
                          interpolation="nearest", extent=extent, vmin=-worst, vmax=worst)
        fig.colorbar(image, ax=ax, shrink=0.8, label=f"left (+) / gouged (-) against {Path(deviation.file).name}, mm")
    for kind, (_marker, colour) in MARKERS.items():
        for f in (f for f in result.findings if f.kind == kind):
            along = f.position[1] if result.axis == "B" else f.position[0]
            ax.axvline(along, color=colour, linewidth=0.8)
            ax.annotate(f"{f.line} {kind}", (along, 355), fontsize=7, rotation=90, va="top", color=colour)
    ax.set_xlabel("Y mm" if result.axis == "B" else "X mm")
    ax.set_ylabel(f"bar angle, degrees (at {result.axis}0 the tool is at 90)")
    ax.set_title(title, fontsize=9)
    from edingcnc_lang.sim.rotary_output import draw_shaded

    draw_shaded(fig.add_subplot(2, 1, 2, projection="3d"), stock, result.axis)
    fig.tight_layout()
    save_figure(fig, out, fmt, DPI)


def bar_mesh(stock: RoundStock, sectors: int = SECTORS) -> Iterator[np.ndarray]:
    """The turned part as (N, 3, 3) triangles: each run of solid slices' profile (a closed polygon in
    the (Z, radius) half-plane) revolved about Z in ``sectors`` facets; closed, outward normals."""
    _, outer, inner = stock.profile()
    solid = outer > inner + EPS
    edges = stock.start + np.arange(stock.shape[0] + 1) * stock.resolution
    angles = np.linspace(0.0, 2.0 * math.pi, sectors + 1)
    angles[-1] = 0.0  # the last facet closes on the first one's vertices exactly
    cos, sin = np.cos(angles), np.sin(angles)
    index = 0
    while index < len(solid):
        if not solid[index]:
            index += 1
            continue
        end = index
        while end < len(solid) and solid[end]:
            end += 1
        yield _revolve(_outline(edges, outer, inner, index, end), cos, sin)
        index = end


def _outline(edges: np.ndarray, outer: np.ndarray, inner: np.ndarray, first: int, end: int) -> np.ndarray:
    """Slices ``first..end-1`` as one polygon (Z, r), counter-clockwise: along the bore, then back
    along the outside; repeated radii merged."""
    points: list[tuple[float, float]] = []
    for i in range(first, end):
        points += [(edges[i], float(inner[i])), (edges[i + 1], float(inner[i]))]
    for i in range(end - 1, first - 1, -1):
        points += [(edges[i + 1], float(outer[i])), (edges[i], float(outer[i]))]
    kept = [p for k, p in enumerate(points) if p != points[k - 1]]
    return np.array(kept)


def _revolve(polygon: np.ndarray, cos: np.ndarray, sin: np.ndarray) -> np.ndarray:
    p, q = polygon, np.roll(polygon, -1, axis=0)
    k0, k1 = slice(0, len(cos) - 1), slice(1, len(cos))

    def ring(points: np.ndarray, ks: slice) -> np.ndarray:  # (edges, sectors, 3)
        r = points[:, 1:2]
        return np.stack(np.broadcast_arrays(r * cos[ks], r * sin[ks], points[:, 0:1] + 0 * cos[ks]), axis=-1)

    a, b, c, d = ring(p, k0), ring(q, k0), ring(q, k1), ring(p, k1)
    first = np.stack((a, b, c), axis=2).reshape(-1, 3, 3)
    second = np.stack((a, c, d), axis=2).reshape(-1, 3, 3)
    triangles = np.concatenate((first, second))
    area = np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1)
    return triangles[area > 1e-12].astype(np.float32)
