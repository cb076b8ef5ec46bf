"""``ecnc kins plot``: the reachable workspace and the Jacobian's condition number, in three slices.

Each slice goes through the centre of the workspace (XY at the middle Z, XZ at the middle Y, YZ at the
middle X).  The top row shows where the plug-in reaches (and where it returns NaN or raises); the bottom
row the log10 of the condition number, so singular regions glow before a machine finds them.
matplotlib is the ``plot`` extra and is imported only here.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from edingcnc_lang.canon import AXES
from edingcnc_lang.errors import require_extra
from edingcnc_lang.kinematics.base import Kinematics
from edingcnc_lang.kinematics.workbench.calls import Status, call_each
from edingcnc_lang.kinematics.workbench.geometry_checks import jacobian_conditions
from edingcnc_lang.kinematics.workbench.workspace import Workspace
from edingcnc_lang.picture_formats import picture_format
from edingcnc_lang.outputs import save_figure

SLICES = ((0, 1, 2), (0, 2, 1), (1, 2, 0))  # (horizontal axis, vertical axis, the axis held at its middle)
# reached, out of reach, raised, NaN, beyond the ini's joint limits (by Status)
STATUS_COLOURS = ("#4c9a2a", "#d9d9d9", "#d62728", "#ff7f0e", "#9ecae1")
STATUS_LABELS = ("reached", "out of reach", "raised", "NaN / inf", "beyond the joint limits")


def _pyplot():
    matplotlib = require_extra("matplotlib", "plot", "ecnc kins plot")
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def slice_grid(space: Workspace, across: int, up: int, resolution: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Poses on a resolution x resolution grid through the centre, and the two axis coordinates."""
    centre = np.array(space.centre)
    xs = np.linspace(*space.box[across], resolution) if space.extents[across] else np.array([centre[across]])
    ys = np.linspace(*space.box[up], resolution) if space.extents[up] else np.array([centre[up]])
    poses = np.tile(centre, (len(xs) * len(ys), 1))
    grid_x, grid_y = np.meshgrid(xs, ys)
    poses[:, across], poses[:, up] = grid_x.ravel(), grid_y.ravel()
    return poses, xs, ys


def plot_envelope(kins: Kinematics, space: Workspace, output: Path, label: str, resolution: int = 60,
                  fmt: str | None = None, joint_limits: Sequence[tuple[float, float]] | None = None) -> Path:
    """Draw the slices into ``output`` (PNG, SVG or PDF by its extension, ``fmt`` when already checked);
    with ``joint_limits`` (the ini's) a pose whose joints lie beyond them is not shown as reached."""
    fmt = fmt or picture_format(Path(output))
    plt = _pyplot()
    from matplotlib.colors import ListedColormap

    fig, grid = plt.subplots(2, 3, figsize=(15, 9.5), constrained_layout=True)
    axes_all = [a for a in space.varying if a < 3] or space.varying
    for col, (across, up, held) in enumerate(SLICES):
        poses, xs, ys = slice_grid(space, across, up, resolution)
        status = call_each(kins.inverse, poses, joint_limits).status.reshape(len(ys), len(xs))
        reach, cond = grid[0][col], grid[1][col]
        extent = (xs[0], xs[-1], ys[0], ys[-1])
        reach.imshow(status, origin="lower", extent=extent, aspect="auto", interpolation="nearest",
                     cmap=ListedColormap(STATUS_COLOURS), vmin=0, vmax=len(STATUS_COLOURS) - 1)
        held_at = space.centre[held]
        reach.set_title(f"reachable: {AXES[across]}{AXES[up]} at {AXES[held]}={held_at:g}")
        conds = np.full(len(poses), np.nan)
        ok = (status.ravel() == Status.OK)
        conds[ok] = jacobian_conditions(kins, poses[ok], space, axes_all)
        image = cond.imshow(np.log10(np.clip(conds, 1.0, 1e12)).reshape(len(ys), len(xs)), origin="lower",
                            extent=extent, aspect="auto", interpolation="nearest", cmap="magma_r", vmin=0, vmax=6)
        cond.set_title(f"log10 condition number: {AXES[across]}{AXES[up]}")
        for ax in (reach, cond):
            ax.set_xlabel(f"{AXES[across]} ({'mm' if across < 3 else 'deg'})")
            ax.set_ylabel(f"{AXES[up]} ({'mm' if up < 3 else 'deg'})")
    fig.colorbar(image, ax=list(grid[1]), shrink=0.8, label="log10 condition number (6 = singular)")
    legend = [plt.Rectangle((0, 0), 1, 1, color=c) for c in STATUS_COLOURS]
    fig.legend(legend, STATUS_LABELS, loc="outside upper right", ncols=len(STATUS_LABELS))
    fig.suptitle(f"{label}: workspace from {space.source}", x=0.01, ha="left")
    output = Path(output)
    save_figure(fig, output, fmt, 80)
    plt.close(fig)
    return output
