"""``ecnc plot``: a toolpath picture with matplotlib (PNG, SVG or PDF by the file's extension).

Rapids dashed, feeds solid, arcs as arcs; coloured by tool, kind, programmed feed or planned speed;
the work zero, the machine's travel from cnc.ini and the part's bounding box with its size.
Pictures are drawn on a bare ``Figure`` with the Agg canvas: no pyplot, no GUI, no global state.
``Picture.to_pixels`` maps machine XYZ to the saved image's pixels, so tests can look at the
picture the way a person would.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, overload

import numpy as np

from edingcnc_lang.plot import views as v
from edingcnc_lang.picture_formats import picture_target
from edingcnc_lang.plot.toolpath import KINDS, Toolpath
from edingcnc_lang.outputs import save_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from matplotlib.transforms import Bbox

SIZE_INCHES = (11.0, 7.5)
DPI = 100
MARGIN = 0.06        # of the drawing's span, around what is fitted
FEED_WIDTH = 1.3
RAPID_WIDTH = 0.8


@dataclass(frozen=True)
class Picture:
    """A written picture and where machine coordinates landed on it."""

    path: Path
    view: str
    width: int          # pixels (PNG)
    height: int
    matrix: np.ndarray  # 3x3: page coordinates -> display pixels, origin bottom left
    axes: tuple[int, int, int, int]  # the drawing area in PNG pixels: left, top, right, bottom
    part_label: tuple[int, int, int, int] | None = None  # where the part's size is written, likewise

    def to_pixels(self, points: Sequence[Sequence[float]]) -> np.ndarray:
        """Machine XYZ points -> (column, row) pixels of the PNG, row 0 at the top."""
        page = np.asarray(points, dtype=float)[:, :3] @ v.projection(self.view).T
        display = np.column_stack((page, np.ones(len(page)))) @ self.matrix.T
        return np.column_stack((display[:, 0], self.height - display[:, 1]))


@overload
def plot_toolpath(path: Toolpath, out: Path, view: str = "auto", color: str = "tool",
                  fit: str = "job", fmt: str | None = None) -> Picture: ...


@overload
def plot_toolpath(path: Toolpath, out: None = None, view: str = "auto", color: str = "tool",
                  fit: str = "job", fmt: str | None = None, *, ax: Axes) -> None: ...


def plot_toolpath(path: Toolpath, out: Path | None = None, view: str = "auto", color: str = "tool",
                  fit: str = "job", fmt: str | None = None, *, ax: Axes | None = None) -> Picture | None:
    """Draw ``path`` into the file ``out``, or onto the matplotlib axes ``ax`` of the caller's own
    figure (a notebook, a GUI; nothing is written and None is returned).  ``fit`` is ``job`` (the
    path and the work zero), ``part`` (the part's bounding box: rapids to a tool changer far away are
    cut off) or ``machine`` (the whole travel from cnc.ini).  ``fmt``: the format its command already
    checked (see ``picture_target``)."""
    if ax is not None:
        draw_toolpath(ax.figure, ax, path, view, color, fit)  # type: ignore[arg-type]
        return None
    if out is None:
        raise ValueError("plot_toolpath needs a file to write (out) or axes to draw on (ax=)")
    fmt = fmt or picture_target(out)
    from matplotlib.figure import Figure

    fig = Figure(figsize=SIZE_INCHES, dpi=DPI)
    ax = fig.add_axes((0.07, 0.08, 0.68, 0.82))
    view, label = draw_toolpath(fig, ax, path, view, color, fit)
    matrix = ax.transData.get_affine().get_matrix().copy()  # final: the axes sit where add_axes put them
    extent = ax.get_window_extent()
    save_figure(fig, out, fmt, DPI)
    width, height = (int(round(s * DPI)) for s in SIZE_INCHES)
    axes = (int(extent.x0), int(height - extent.y1), int(extent.x1), int(height - extent.y0))
    where = None if label is None else (int(label.x0), int(height - label.y1), int(label.x1), int(height - label.y0))
    return Picture(out, view, width, height, matrix, axes, where)


def draw_toolpath(fig: Figure, ax: Axes, path: Toolpath, view: str = "auto", color: str = "tool",
                  fit: str = "job") -> tuple[str, Bbox | None]:
    """Everything ``plot_toolpath`` draws, onto ``ax`` of ``fig``: the path, the work zero, the part
    and limit boxes, the part's size, the title and the legend; returns the view drawn and where the
    part's size was written."""
    view = v.auto_view(path) if view == "auto" else view
    project = v.projection(view)
    fitted = _draw_path(fig, ax, path, view, color)
    _draw_work_zero(ax, path, project)
    boxes = _draw_boxes(ax, path, project)
    if fit == "part" and "part" in boxes:
        fitted = [boxes["part"]]
    else:
        fitted += [boxes[name] for name in ("zero", "part", "limits" if fit == "machine" else "") if name in boxes]
    _frame(ax, fitted, view)
    if view == "lathe" and path.part:
        _label_lathe_axes(ax, path.x_diameter)
    label = _label_part(fig, ax, path, view, boxes.get("part"))
    fig.suptitle(v.title_text(path), x=0.07, ha="left", fontsize=11)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=9, frameon=False)
    return view, label


def thinned(path: Toolpath, max_moves: int | None = None) -> Toolpath:
    """``path`` with at most about ``max_moves`` moves (the viewer's budget), thinned as the viewer
    thins (``decimate``): a picture of a 300,000-move job took 17 KB a move in matplotlib and
    failed at 2.2 GB.  A kept move that stands for the ones dropped before it is drawn straight
    from where the previous kept move ended."""
    from edingcnc_lang.plot.viewer import MAX_MOVES, decimate

    chosen = decimate(path, max_moves or MAX_MOVES)
    keep = chosen.keep
    if len(keep) == len(path):
        return path
    merged = chosen.count > 1
    starts = path.starts[keep].copy()
    previous_end = np.vstack((path.starts[:1], path.ends[keep[:-1]]))
    starts[merged] = previous_end[merged]
    arcs = {new: path.arcs[old] for new, old in enumerate(keep.tolist()) if old in path.arcs and not merged[new]}
    return replace(path, kinds=path.kinds[keep], tools=path.tools[keep], lines=path.lines[keep],
                   callers=path.callers[keep], files=path.files[keep], feeds=path.feeds[keep], starts=starts,
                   ends=path.ends[keep], joints=path.joints[keep], arcs=arcs, times=path.times[keep],
                   speeds=path.speeds[keep])


def _segments(page: np.ndarray) -> np.ndarray:
    """A polyline's (N, 2) page points as N - 1 two-point segments."""
    return np.stack((page[:-1], page[1:]), axis=1)


def _draw_path(fig: Figure, ax: Axes, path: Toolpath, view: str, color: str) -> list[np.ndarray]:
    """The moves as line collections, one per style; returns the page points to fit the view to.

    By tool or kind, each run of alike moves is one path (dashes run on along it, and matplotlib
    draws a few long paths far faster than many short ones); by feed or speed every segment has
    its own colour.
    """
    from matplotlib.collections import LineCollection

    path = thinned(path)
    project = v.projection(view)
    cutting = v.feed_tools(path)
    fitted: list[np.ndarray] = []
    if color in ("tool", "kind"):
        key = path.tools if color == "tool" else path.kinds.astype(np.int32)
        groups: dict[tuple[bool, str], list[np.ndarray]] = {}
        for line in path.polylines(key):
            rapid = v.is_rapid(line.kind)
            if color == "kind":
                shade = v.KIND_COLORS[v.kind_name(line.kind)]
            else:
                shade = v.RAPID_COLOR if rapid else v.tool_color(cutting, line.tool)
            groups.setdefault((rapid, shade), []).append(line.points @ project.T)
        for (rapid, shade), pages in sorted(groups.items(), key=lambda item: not item[0][0]):
            fitted.extend(pages)
            ax.add_collection(LineCollection(pages, colors=shade, linewidths=RAPID_WIDTH if rapid else FEED_WIDTH,
                                             linestyles="--" if rapid else "-", zorder=1 if rapid else 2))
            if not rapid and view == "top":
                _mark_end_on(ax, np.concatenate([_segments(page) for page in pages]), shade)
        for label, (rapid, shade) in _legend_entries(path, color, groups):
            ax.plot([], [], color=shade, ls="--" if rapid else "-", lw=RAPID_WIDTH if rapid else FEED_WIDTH,
                    label=label)
        return fitted
    values = path.feeds if color == "feed" else path.speeds
    rapid_pages, feed_pieces, feed_values = [], [], []
    for line in path.polylines(path.kinds.astype(np.int32)):
        page = line.points @ project.T
        if v.is_rapid(line.kind):
            rapid_pages.append(page)
        else:
            feed_pieces.append(_segments(page))
            feed_values.append(values[line.moves])
    if rapid_pages:
        fitted.extend(rapid_pages)
        ax.add_collection(LineCollection(rapid_pages, colors=v.RAPID_COLOR, linewidths=RAPID_WIDTH, linestyles="--"))
        ax.plot([], [], color=v.RAPID_COLOR, ls="--", lw=RAPID_WIDTH, label="rapid")
    if feed_pieces:
        feeds = np.concatenate(feed_pieces)
        fitted.append(feeds.reshape(-1, 2))
        collection = LineCollection(list(feeds), cmap=v.SPEED_COLORMAP, linewidths=FEED_WIDTH, zorder=2)
        collection.set_array(np.concatenate(feed_values))
        ax.add_collection(collection)
        if view == "top":
            _mark_end_on(ax, feeds, "black")
        label = "programmed feed (mm/min)" if color == "feed" else "planned speed (mm/min)"
        fig.colorbar(collection, ax=ax, label=label, location="bottom", shrink=0.6, pad=0.1)
    return fitted


def _mark_end_on(ax: Axes, segments: np.ndarray, shade: str) -> None:
    """A ring where feed moves run straight at the viewer (drilled holes seen from the top): they
    would otherwise not show at all."""
    end_on = np.hypot(*(segments[:, 1] - segments[:, 0]).T) < 1e-6
    if end_on.any():
        points = np.unique(np.round(segments[end_on, 0], 6), axis=0)
        ax.plot(points[:, 0], points[:, 1], ls="none", marker="o", ms=5, mfc="none", mec=shade, mew=1.2, zorder=3)


def _legend_entries(path: Toolpath, color: str, groups: dict[tuple[bool, str], Any]
                    ) -> list[tuple[str, tuple[bool, str]]]:
    entries: list[tuple[str, tuple[bool, str]]] = []
    if color == "kind":
        present = {int(k) for k in np.unique(path.kinds)}
        for kind in sorted(present):
            entries.append((KINDS[kind], (v.is_rapid(kind), v.KIND_COLORS[KINDS[kind]])))
        return entries
    cutting = v.feed_tools(path)
    for tool in cutting:
        entries.append((f"T{tool}" if tool else "no tool", (False, v.tool_color(cutting, tool))))
    if any(rapid for rapid, _ in groups):
        entries.append(("rapid", (True, v.RAPID_COLOR)))
    return entries


def _draw_work_zero(ax: Axes, path: Toolpath, project: np.ndarray) -> None:
    zero = np.asarray(path.work_zero, dtype=float)
    origin = zero @ project.T
    ax.plot(*origin, marker="o", ms=7, mfc="none", mec="black", mew=1.5, ls="none", zorder=4, label="work zero")
    ax.plot(*origin, marker="+", ms=7, color="black", mew=1.0, zorder=4)


def _draw_boxes(ax: Axes, path: Toolpath, project: np.ndarray) -> dict[str, np.ndarray]:
    """The part's bounding box with its size, and the machine's travel; returns the page points of
    the work zero, the part box and the limits box, for whichever the picture is fitted to."""
    from matplotlib.collections import LineCollection

    boxes = {"zero": np.asarray(path.work_zero, dtype=float)[None, :] @ project.T}
    bounds = path.bounds()
    if bounds is not None:
        edges = v.box_edges(*bounds) @ project.T
        boxes["part"] = edges.reshape(-1, 2)
        ax.add_collection(LineCollection(edges, colors="#444444", linewidths=0.7, linestyles=":", zorder=3))
        ax.plot([], [], color="#444444", lw=0.7, ls=":", label="part bounding box")
    if path.limits is not None:
        edges = v.box_edges(*path.limits) @ project.T
        ax.add_collection(LineCollection(edges, colors="#b22222", linewidths=1.0, linestyles="-.",
                                         zorder=0.6))  # above the grid, which may fall on the limits
        ax.plot([], [], color="#b22222", lw=1.0, ls="-.", label="machine limits (cnc.ini)")
        boxes["limits"] = edges.reshape(-1, 2)
    return boxes


def _label_part(fig: Figure, ax: Axes, path: Toolpath, view: str, corners: np.ndarray | None) -> Bbox | None:
    """The part's size beside its box, at the first corner (above left, above right, below left,
    below right) where the words stay inside the drawing: not over the legend, not cut off.
    Called once the view is framed, since where the words fall depends on it."""
    bounds = path.bounds()
    if corners is None or bounds is None:
        return None
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(fig).get_renderer()
    inside = ax.get_window_extent(renderer)
    label = None
    for (x, y), ha, va, dy in ((_vertex(corners, top=True, left=True), "left", "bottom", 4),
                               (_vertex(corners, top=True, left=False), "right", "bottom", 4),
                               (_vertex(corners, top=False, left=True), "left", "top", -4),
                               (_vertex(corners, top=False, left=False), "right", "top", -4)):
        if label is not None:
            label.remove()
        label = ax.annotate(f"part {v.size_text(*bounds, view=view, diameter=path.part and path.x_diameter)}",
                            (x, y), xytext=(0, dy),
                            textcoords="offset points", ha=ha, va=va, fontsize=8, color="#444444", zorder=5,
                            bbox={"boxstyle": "square,pad=0.15", "fc": "white", "ec": "none", "alpha": 0.8})
        extent = label.get_window_extent(renderer)
        if (extent.x0 >= inside.x0 and extent.x1 <= inside.x1
                and extent.y0 >= inside.y0 and extent.y1 <= inside.y1):
            break
    return extent


def _vertex(corners: np.ndarray, top: bool, left: bool) -> tuple[float, float]:
    """The box's highest (or lowest) drawn corner, the leftmost (or rightmost) of those at that
    height: a true corner of the box in every view, the iso view's top vertex included."""
    height = corners[:, 1].max() if top else corners[:, 1].min()
    level = corners[np.isclose(corners[:, 1], height, rtol=0.0, atol=1e-6 * (1.0 + abs(height)))]
    x = level[:, 0].min() if left else level[:, 0].max()
    return float(x), float(height)


def _frame(ax: Axes, fitted: list[np.ndarray], view: str) -> None:
    """Equal scales, the view fitted to ``fitted`` with a margin, labels and a light grid."""
    points = np.vstack(fitted)
    low, high = points.min(axis=0), points.max(axis=0)
    center, span = (low + high) / 2.0, np.maximum(high - low, 1.0) * (1.0 + 2.0 * MARGIN)
    box = ax.get_position()  # figure fractions, after any colour bar took its share
    box_ratio = (box.height * SIZE_INCHES[1]) / (box.width * SIZE_INCHES[0])
    if span[1] / span[0] < box_ratio:  # widen the short side so one mm is as long across as up
        span[1] = span[0] * box_ratio
    else:
        span[0] = span[1] / box_ratio
    ax.set_xlim(center[0] - span[0] / 2.0, center[0] + span[0] / 2.0)
    ax.set_ylim(center[1] - span[1] / 2.0, center[1] + span[1] / 2.0)
    _project, xlabel, ylabel = v.VIEWS[view]
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if view == "iso":
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title("isometric view", fontsize=9, loc="left")
    ax.grid(True, color="#e0e0e0", lw=0.5)
    ax.set_axisbelow(True)


def _label_lathe_axes(ax: Axes, diameter: bool) -> None:
    """A turning job in work coordinates: Z from the work zero across, X up, its ticks read as
    diameters on a diameter lathe (the drawing stays true to scale: a half section in radius)."""
    from matplotlib.ticker import FuncFormatter

    ax.set_xlabel("Z (mm, work)")
    if diameter:
        ax.yaxis.set_major_formatter(FuncFormatter(lambda value, _pos: f"{2.0 * value:g}"))
        ax.set_ylabel("X (mm, diameter)")
    else:
        ax.set_ylabel("X (mm, radius)")
