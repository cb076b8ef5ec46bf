"""Both toolpaths in one picture with what differs drawn over them: OLD thin grey, NEW in the plot
module's tool colours, and on top the NEW moves off OLD's path, the OLD moves NEW no longer makes,
moves whose feed, speed or tool changed, and rapids lower than any of OLD's."""
from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, cast

import numpy as np

from edingcnc_lang.plot import views as v
from edingcnc_lang.picture_formats import picture_target
from edingcnc_lang.plot.render import DPI, FEED_WIDTH, RAPID_WIDTH, SIZE_INCHES, _frame
from edingcnc_lang.diff.compare import Comparison
from edingcnc_lang.diff.record import RAPID_KINDS, Recording, sample
from edingcnc_lang.outputs import save_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from edingcnc_lang.plot.toolpath import Toolpath

DRAW_STEP = math.radians(3.0)  # arcs drawn in chords of this angle, as ecnc plot draws them
OLD_COLOR = "#b0b0b0"
# what differs -> colour, line width, label
HIGHLIGHTS = {
    "new": ("#d62728", 3.0, "NEW off OLD's path"),
    "old": ("#ff7f0e", 3.0, "OLD only (not in NEW)"),
    "value": ("#9467bd", 2.4, "feed, speed or tool changed"),
    "rapid": ("#e377c2", 3.0, "rapid below every OLD rapid"),
}


def _segments(rec: Recording, project: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every piece of ``rec``'s path on the page, and the move each belongs to."""
    samples = sample(rec, arc_step=DRAW_STEP)
    page = samples.points[:, :3] @ project.T
    pieces = np.stack((page[:-1], page[1:]), axis=1)
    return pieces, samples.owner[1:]


def _marked(count: int, spans: list[tuple[int, int] | None]) -> np.ndarray:
    mask = np.zeros(count, dtype=bool)
    for span in spans:
        if span is not None:
            mask[span[0]:span[1] + 1] = True
    return mask


def draw_diff(comparison: Comparison, out: Path, view: str = "auto", fmt: str | None = None) -> Path:
    """Write the picture of ``comparison`` to ``out`` (.png, .svg or .pdf)."""
    fmt = fmt or picture_target(out)
    from matplotlib.collections import LineCollection
    from matplotlib.figure import Figure

    old, new = comparison.old, comparison.new
    # auto_view reads only the moves' starts and ends, which a recording has too
    view = v.auto_view(cast("Toolpath", new if len(new) else old)) if view == "auto" else view
    project = v.projection(view)
    fig = Figure(figsize=SIZE_INCHES, dpi=DPI)
    ax = fig.add_axes((0.07, 0.08, 0.68, 0.82))
    fitted: list[np.ndarray] = []
    old_pieces, old_owner = _segments(old, project)
    new_pieces, new_owner = _segments(new, project)
    for pieces in (old_pieces, new_pieces):
        if len(pieces):
            fitted.append(pieces.reshape(-1, 2))
    _add(ax, old_pieces, OLD_COLOR, 0.8, "OLD", LineCollection)
    new_rapid = np.isin(new.kinds, RAPID_KINDS)[new_owner] if len(new_owner) else np.zeros(0, dtype=bool)
    cutting = sorted({int(t) for t in np.unique(new.tools[~np.isin(new.kinds, RAPID_KINDS)])}) if len(new) else []
    _add(ax, new_pieces[new_rapid], v.RAPID_COLOR, RAPID_WIDTH, "NEW rapid", LineCollection, dashed=True)
    for tool in cutting:
        chosen = ~new_rapid & (new.tools[new_owner] == tool)
        _add(ax, new_pieces[chosen], v.tool_color(cutting, tool), FEED_WIDTH, f"NEW T{tool}", LineCollection)
    changes = comparison.changes
    marks = {
        "new": _marked(len(new), [c.new_moves for c in changes["deviations"] if c.what != "removed"]),
        "old": _marked(len(old), [c.old_moves for c in changes["deviations"] if c.what == "removed"]),
        "value": _marked(len(new), [c.new_moves for name in ("feeds", "spindle", "tool_moves")
                                    for c in changes[name]]),
        "rapid": _marked(len(new), [c.new_moves for c in changes["rapids"]]),
    }
    for name, (shade, width, label) in HIGHLIGHTS.items():
        pieces, owner = (old_pieces, old_owner) if name == "old" else (new_pieces, new_owner)
        if len(owner) and marks[name].any():
            marked = marks[name][owner]
            _add(ax, pieces[marked], shade, width, label, LineCollection, zorder=3, alpha=0.75)
            # a ring where each marked move ends too: a change seen end-on (a plunge from the top) still shows
            last = np.append(owner[1:] != owner[:-1], True)
            ends = np.unique(np.round(pieces[marked & last, 1], 6), axis=0)
            ax.plot(ends[:, 0], ends[:, 1], ls="none", marker="o", ms=6, mfc="none", mec=shade, mew=1.2, zorder=4)
    if not fitted:
        fitted.append(np.zeros((1, 2)))
    _frame(ax, fitted, view)
    verdict = ("same" if comparison.same else "differs" if comparison.max_deviation is None
               else f"differs, largest deviation {comparison.max_deviation:.4g} mm")
    fig.suptitle(f"OLD {Path(old.name).name} vs NEW {Path(new.name).name}: {verdict}", x=0.07, ha="left", fontsize=11)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=9, frameon=False)
    save_figure(fig, out, fmt, DPI)
    return out


def _add(ax: Axes, pieces: np.ndarray, shade: str, width: float, label: str, collection: type,
         dashed: bool = False, zorder: float = 2, alpha: float = 1.0) -> None:
    if not len(pieces):
        return
    ax.add_collection(collection(pieces, colors=shade, linewidths=width, linestyles="--" if dashed else "-",
                                 zorder=zorder, alpha=alpha))
    ax.plot([], [], color=shade, lw=width, ls="--" if dashed else "-", label=label, alpha=alpha)
