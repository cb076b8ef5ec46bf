"""Views of a 3D toolpath on paper: the projections, the colour schemes and the titles, as data.

Shared by the matplotlib pictures; no matplotlib here, so the tables can be tested and reused alone.
"""
from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from edingcnc_lang.motion.planner.estimate import format_duration
from edingcnc_lang.plot.names import VIEW_NAMES
from edingcnc_lang.plot.toolpath import FEED_KINDS, KINDS, RAPID_KINDS, Toolpath

_C, _S = math.cos(math.radians(30.0)), math.sin(math.radians(30.0))

# view -> (2x3 projection of machine XYZ onto the page, horizontal label, vertical label)
# top: seen from +Z; front: from -Y; side: from +X; iso: from the front-left-top corner (-X, -Y, +Z);
# lathe: the turning plane as a lathe hand sees it, the spindle axis Z across and X up.
VIEWS: dict[str, tuple[tuple[tuple[float, float, float], tuple[float, float, float]], str, str]] = dict(zip(
    VIEW_NAMES, (
        (((1.0, 0.0, 0.0), (0.0, 1.0, 0.0)), "X (mm)", "Y (mm)"),
        (((1.0, 0.0, 0.0), (0.0, 0.0, 1.0)), "X (mm)", "Z (mm)"),
        (((0.0, 1.0, 0.0), (0.0, 0.0, 1.0)), "Y (mm)", "Z (mm)"),
        (((_C, -_C, 0.0), (_S, _S, 1.0)), "", ""),
        (((0.0, 0.0, 1.0), (1.0, 0.0, 0.0)), "Z (mm)", "X (mm, radius)"),
    ), strict=True))

TOOL_COLORS = ("#1f77b4", "#2ca02c", "#9467bd", "#d62728", "#ff7f0e", "#17becf", "#8c564b", "#e377c2",
               "#bcbd22", "#7f7f7f")
KIND_COLORS = {"rapid": "#7f7f7f", "linear": "#1f77b4", "arc": "#2ca02c", "probe": "#9467bd", "home": "#8c564b"}
RAPID_COLOR = KIND_COLORS["rapid"]
SPEED_COLORMAP = "viridis"


def projection(view: str) -> np.ndarray:
    """The 2x3 matrix that puts machine XYZ on the page for ``view``."""
    return np.array(VIEWS[view][0], dtype=float)


def auto_view(path: Toolpath) -> str:
    """``top`` for mills; ``lathe`` (Z across, X up) for a lathe's job in work coordinates and for a
    job that never moves Y but moves X and Z."""
    if getattr(path, "part", False):  # (``ecnc diff`` passes its Recording, which has no part view)
        return "lathe"
    if not len(path):
        return "top"
    points = np.vstack((path.starts[:, :3], path.ends[:, :3]))
    span = points.max(axis=0) - points.min(axis=0)
    return "lathe" if span[1] < 1e-9 and span[0] > 0.0 and span[2] > 0.0 else "top"


def box_edges(lower: Sequence[float] | np.ndarray, upper: Sequence[float] | np.ndarray) -> np.ndarray:
    """The 12 edges of an axis-aligned box, as (12, 2, 3) segment end points."""
    lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
    corners = np.array([[hi[a] if (k >> a) & 1 else lo[a] for a in range(3)] for k in range(8)])
    pairs = [(k, k | (1 << a)) for k in range(8) for a in range(3) if not (k >> a) & 1]
    return np.array([[corners[i], corners[j]] for i, j in pairs])


def feed_tools(path: Toolpath) -> list[int]:
    """The tools that cut (made feed moves), in order of their numbers: the ones that get colours."""
    cutting = np.isin(path.kinds, list(FEED_KINDS))
    return sorted({int(t) for t in np.unique(path.tools[cutting])})


def tool_color(tools: Sequence[int], tool: int) -> str:
    """The colour of ``tool`` among the cutting ``tools`` (the first colour for a tool not among them)."""
    position = list(tools).index(tool) if tool in tools else 0
    return TOOL_COLORS[position % len(TOOL_COLORS)]


def kind_name(kind: int) -> str:
    return KINDS[kind]


def is_rapid(kind: int) -> bool:
    return kind in RAPID_KINDS


def size_text(lower: np.ndarray, upper: np.ndarray, view: str = "top", diameter: bool = False) -> str:
    """The part's size, ``X 84.00 x Y 44.00 x Z 14.00 mm``; in the lathe view the turning plane's
    two, in the order the picture shows them (``Z 120.00 x X 4.00 mm``, X a radius): a lathe has no Y.
    ``diameter``: a part in work coordinates on a diameter lathe, whose X is its largest diameter
    (``Z 52.00 x diameter 62.00 mm``)."""
    if view == "lathe" and diameter:
        return f"Z {upper[2] - lower[2]:.2f} x diameter {2.0 * max(abs(upper[0]), abs(lower[0])):.2f} mm"
    size = dict(zip("XYZ", upper - lower))
    axes = "ZX" if view == "lathe" else "XYZ"
    return " x ".join(f"{axis} {size[axis]:.2f}" for axis in axes) + " mm"


def title_text(path: Toolpath) -> str:
    """The job name, its moves and tools, the time estimate when the planner gave one, and any error."""
    name = path.job.replace("\\", "/").rsplit("/", 1)[-1]
    tools = sorted({int(t) for t in path.tools.tolist() if t})
    parts = [name, f"{len(path):,} moves"]
    if tools:
        parts.append("tools " + ", ".join(f"T{t}" for t in tools))
    if path.kinematics.lower() not in ("", "trivial"):
        parts.append(f"kinematics {path.kinematics}")
    if path.seconds > 0.0:
        parts.append(f"about {format_duration(path.seconds)}")  # as the run summary says it
    text = "  \u2014  ".join(parts)
    if path.error is not None:
        text += "\nstopped: " + path.error.format().splitlines()[0]
    return text
