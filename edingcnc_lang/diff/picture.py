"""Both toolpaths in one picture, what differs drawn over them in one colour per kind of change
(``style.KINDS``, with a legend): OLD thin light grey, NEW grey where it is unchanged; NEW's changed
moves in their change's colour (OLD's own for what NEW no longer does).  With ``--stock`` a second
panel maps where the cut parts differ (NEW - OLD, mm)."""
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
from edingcnc_lang.diff.style import KINDS, OLD_COLOR, SAME_COLOR, drawn, kind_of
from edingcnc_lang.outputs import save_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from edingcnc_lang.diff.part import PartComparison
    from edingcnc_lang.plot.toolpath import Toolpath

DRAW_STEP = math.radians(3.0)  # arcs drawn in chords of this angle, as ecnc plot draws them
CHANGED_WIDTH = 2.6


def _segments(rec: Recording, project: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every piece of ``rec``'s path on the page, and the move each belongs to."""
    samples = sample(rec, arc_step=DRAW_STEP)
    page = samples.points[:, :3] @ project.T
    pieces = np.stack((page[:-1], page[1:]), axis=1)
    keep = ~samples.jump[1:] if len(samples.jump) else np.zeros(0, dtype=bool)  # no line across a jump
    return pieces[keep], samples.owner[1:][keep]


def draw_diff(comparison: Comparison, out: Path, view: str = "auto", fmt: str | None = None) -> Path:
    """Write the picture of ``comparison`` to ``out`` (.png, .svg or .pdf)."""
    fmt = fmt or picture_target(out)
    from matplotlib.figure import Figure

    old, new = comparison.old, comparison.new
    # auto_view reads only the moves' starts and ends, which a recording has too
    view = v.auto_view(cast("Toolpath", new if len(new) else old)) if view == "auto" else view
    project = v.projection(view)
    part = comparison.part
    fig = Figure(figsize=(SIZE_INCHES[0] * (1.5 if part is not None else 1.0), SIZE_INCHES[1]), dpi=DPI)
    share = 0.6 if part is not None else 1.0
    ax = fig.add_axes((0.07 * share, 0.08, 0.68 * share, 0.82))
    old_pieces, old_owner = _segments(old, project)
    new_pieces, new_owner = _segments(new, project)
    fitted = [p.reshape(-1, 2) for p in (old_pieces, new_pieces) if len(p)] or [np.zeros((1, 2))]
    _add(ax, old_pieces, OLD_COLOR, 0.8, "OLD")
    new_rapid = np.isin(new.kinds, RAPID_KINDS)[new_owner] if len(new_owner) else np.zeros(0, dtype=bool)
    _add(ax, new_pieces[~new_rapid], SAME_COLOR, FEED_WIDTH * 0.7, "NEW, unchanged")
    _add(ax, new_pieces[new_rapid], SAME_COLOR, RAPID_WIDTH, "NEW rapid, unchanged", dashed=True)
    marks: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for change in drawn(comparison):
        key = kind_of(change)
        mine, theirs = marks.setdefault(key, (np.zeros(len(new), dtype=bool), np.zeros(len(old), dtype=bool)))
        if change.what in ("removed", "replaced") and change.old_moves:  # what NEW no longer does, on OLD's path
            theirs[change.old_moves[0]:change.old_moves[1] + 1] = True
        if change.what != "removed" and change.new_moves:
            mine[change.new_moves[0]:change.new_moves[1] + 1] = True
    for key, (shade, label) in KINDS.items():
        if key not in marks:
            continue
        for mask, pieces, owner in ((marks[key][0], new_pieces, new_owner), (marks[key][1], old_pieces, old_owner)):
            if not len(owner) or not mask.any():
                continue
            marked = mask[owner]
            _add(ax, pieces[marked], shade, CHANGED_WIDTH, label, zorder=3, alpha=0.85)
            label = "_"  # one legend entry per kind
            # a ring where each marked move ends too: a change seen end-on (a plunge from the top) still shows
            last = np.append(owner[1:] != owner[:-1], True)
            ends = np.unique(np.round(pieces[marked & last, 1], 6), axis=0)
            ax.plot(ends[:, 0], ends[:, 1], ls="none", marker="o", ms=6, mfc="none", mec=shade, mew=1.2, zorder=4)
    _frame(ax, fitted, view)
    verdict = ("same" if comparison.same else "differs" if comparison.max_deviation is None
               else f"differs, largest deviation {comparison.max_deviation:.4g} mm")
    fig.suptitle(f"OLD {Path(old.name).name} vs NEW {Path(new.name).name}: {verdict}", x=0.02, ha="left", fontsize=11)
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=9, frameon=False)
    if part is not None:
        _draw_part(fig, part)
    save_figure(fig, out, fmt, DPI)
    return out


def _draw_part(fig: Figure, part: PartComparison) -> None:
    """The deviation of the cut parts, NEW - OLD (blue: NEW cuts deeper, red: OLD does), regions boxed."""
    ax = fig.add_axes((0.66, 0.12, 0.27, 0.74))
    difference = part.new.top.astype(np.float64) - part.old.top
    ny, nx = difference.shape
    r = part.old.resolution
    extent = (part.old.x0, part.old.x0 + nx * r, part.old.y0, part.old.y0 + ny * r)
    scale = max(part.max_deviation, part.tolerance)
    image = ax.imshow(difference, origin="lower", extent=extent, cmap="RdBu", vmin=-scale, vmax=scale,
                      interpolation="nearest")
    for region in part.regions:
        x0, y0, x1, y1 = region.bounds
        ax.plot([x0, x1, x1, x0, x0], [y0, y0, y1, y1, y0], color="#222", lw=0.8)
    ax.set_aspect("equal")
    ax.set_title("the same part" if part.same else f"parts differ: up to {part.max_deviation:.3g} mm", fontsize=10)
    ax.tick_params(labelsize=8)
    bar = fig.colorbar(image, ax=ax, fraction=0.05, pad=0.03)
    bar.set_label("NEW - OLD, mm (blue: NEW cuts deeper)", fontsize=8)
    bar.ax.tick_params(labelsize=8)


def _add(ax: Axes, pieces: np.ndarray, shade: str, width: float, label: str, dashed: bool = False,
         zorder: float = 2, alpha: float = 1.0) -> None:
    from matplotlib.collections import LineCollection

    if not len(pieces):
        return
    ax.add_collection(LineCollection(list(pieces), colors=shade, linewidths=width, linestyles="--" if dashed else "-",
                                     zorder=zorder, alpha=alpha))
    if label != "_":
        ax.plot([], [], color=shade, lw=width, ls="--" if dashed else "-", label=label, alpha=alpha)
