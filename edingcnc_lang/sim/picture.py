"""The cut stock as a picture: a shaded relief seen from above, the findings marked on it, and
with ``--compare-stl`` a second panel of the deviation from the part (matplotlib, the ``plot``
extra; a bare ``Figure`` on the Agg canvas, as ``ecnc plot`` draws)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from edingcnc_lang.sim.compare import Deviation
from edingcnc_lang.sim.findings import CutFinding
from edingcnc_lang.sim.stock import Stock
from edingcnc_lang.outputs import save_figure

DPI = 120
MAX_LABELS = 40    # findings labelled with their line number; more would be a smudge
MAX_PIXELS = 1600   # cells drawn across the longer side; a finer field is shown every n-th cell
MARKERS = {"rapid_into_stock": ("X", "#d62728"), "shank": ("s", "#ff7f0e"), "holder": ("D", "#8c564b"),
           "spindle_off": ("o", "#9467bd"), "plunge": ("v", "#1f77b4"), "outside_stock": ("^", "#7f7f7f")}


def draw_stock(stock: Stock, out: Path, fmt: str, findings: list[CutFinding], title: str,
               deviation: Deviation | None = None) -> None:
    """Write the picture of the cut stock to ``out`` in format ``fmt`` (png, svg or pdf)."""
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import LightSource, Normalize
    from matplotlib.figure import Figure

    step = max(1, math.ceil(max(stock.shape) / MAX_PIXELS))
    heights = stock.top[::step, ::step].astype(np.float64)
    x0, y0, z0, x1, y1, z1 = stock.box_bounds
    extent = (x0, x1, y0, y1)
    panels = 2 if deviation is not None else 1
    aspect = (y1 - y0) / max(x1 - x0, 1e-9)
    width = 7.5 * panels
    fig = Figure(figsize=(width, min(max(7.5 * aspect + 1.2, 3.5), 12.0)), dpi=DPI)
    ax = fig.add_subplot(1, panels, 1)
    light = LightSource(azdeg=315, altdeg=45)
    low, high = float(heights.min()), float(heights.max())
    high = max(high, low + 1e-3)
    shaded = light.shade(heights[::-1], cmap=_cmap(), vert_exag=1.0, dx=stock.resolution * step,
                         dy=stock.resolution * step, blend_mode="soft", vmin=low, vmax=high)
    ax.imshow(shaded, extent=extent, interpolation="nearest")
    scale = ScalarMappable(Normalize(low, high), _cmap())
    fig.colorbar(scale, ax=ax, shrink=0.8, label="Z mm")
    _mark(ax, findings)
    ax.set_xlabel("X mm")
    ax.set_ylabel("Y mm")
    ax.set_title(title, fontsize=9)
    if deviation is not None:
        _draw_deviation(fig, fig.add_subplot(1, 2, 2), deviation, step, extent)
    fig.tight_layout()
    save_figure(fig, out, fmt, DPI)


def _cmap():
    from matplotlib import colormaps

    return colormaps["viridis"]


def _mark(ax, findings: list[CutFinding]) -> None:
    """One marker per finding where the tool was, labelled with its line; one legend entry per kind."""
    for kind, (marker, colour) in MARKERS.items():
        points = [f.position for f in findings if f.kind == kind]
        if points:
            xs, ys = zip(*[(p[0], p[1]) for p in points])
            ax.scatter(xs, ys, marker=marker, s=60, c=colour, edgecolors="white", linewidths=0.8,
                       label=f"{kind} ({len(points)})", zorder=3)
    if len(findings) <= MAX_LABELS:  # each place names its lines, while that stays readable
        places: dict[tuple[float, float], list[str]] = {}
        for f in findings:
            lines = places.setdefault((round(f.position[0], 1), round(f.position[1], 1)), [])
            if str(f.line) not in lines:
                lines.append(str(f.line))
        for (x, y), lines in places.items():
            ax.annotate(", ".join(lines), (x, y), xytext=(5, 5), textcoords="offset points", fontsize=7,
                        color="#111111", zorder=4)
    if findings:  # below the picture, where it covers no finding's label
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=len(MARKERS), fontsize=7, frameon=False)


def _draw_deviation(fig, ax, deviation: Deviation, step: int, extent: tuple[float, ...]) -> None:
    values = deviation.map[::step, ::step]
    limit = max(deviation.max_overcut, deviation.max_undercut, 1e-3)
    image = ax.imshow(values[::-1], extent=extent, cmap="RdBu_r", vmin=-limit, vmax=limit, interpolation="nearest")
    ax.set_facecolor("#dddddd")
    ax.set_xlabel("X mm")
    ax.set_title(f"against {Path(deviation.file).name}: over-cut {deviation.max_overcut:.3f} mm, "
                 f"under-cut {deviation.max_undercut:.3f} mm, mean |dev| {deviation.mean:.3f} mm", fontsize=9)
    fig.colorbar(image, ax=ax, shrink=0.8, label="cut minus part, mm (red: left, blue: gouged)")
