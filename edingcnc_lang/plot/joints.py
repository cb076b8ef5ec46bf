"""``ecnc plot --joints``: what the motors do, joint positions over time, one strip per joint.

On a kinematic machine (delta, rotate, cylinder, tangential knife) a straight line of the program
is a curve for the motors; this shows it.  The data are the run's samples at the interpolation
rate (the ``--samples`` columns), so the curves are what the simulator fed to the joints.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from edingcnc_lang.errors import EcncError, Location
from edingcnc_lang.plot import views as v
from edingcnc_lang.picture_formats import picture_target
from edingcnc_lang.plot.render import DPI
from edingcnc_lang.plot.toolpath import SAMPLE_ROWS, Toolpath
from edingcnc_lang.outputs import save_figure

JOINT_COLUMNS = ("jx", "jy", "jz", "ja", "jb", "jc")
STRIP_INCHES = 1.6
MAX_CURVE_POINTS = SAMPLE_ROWS  # samples drawn per joint: far more than the picture's pixels, a bounded figure
WIDTH_INCHES = 11.0


def moving_joints(path: Toolpath) -> list[int]:
    """The joints that move during the run (all configured ones when none does)."""
    samples = path.samples or {}
    count = min(len(path.joint_names) or 6, len(JOINT_COLUMNS))
    present = [i for i in range(count) if JOINT_COLUMNS[i] in samples and len(samples[JOINT_COLUMNS[i]])]
    # over every sample: the thinned ones could miss a short move
    spread = path.sample_spread or {JOINT_COLUMNS[i]: np.ptp(samples[JOINT_COLUMNS[i]]) for i in present}
    moving = [i for i in present if spread[JOINT_COLUMNS[i]] > 1e-9]
    return moving or present


def joint_kind(path: Toolpath, joint: int) -> str:
    """"rotary" or "linear": as the plug-in declares it (a SCARA's arms), else by the joint's name."""
    if path.joint_kinds is not None:
        return path.joint_kinds[joint]
    name = path.joint_names[joint] if joint < len(path.joint_names) else JOINT_COLUMNS[joint]
    return "rotary" if name.upper() in ("A", "B", "C", "JA", "JB", "JC") else "linear"


def plot_joints(path: Toolpath, out: Path, fmt: str | None = None) -> Path:
    """Draw the joint positions over time into ``out`` (PNG, SVG or PDF; ``fmt`` when already checked)."""
    fmt = fmt or picture_target(out)
    if not path.samples or not len(path.samples.get("t", ())):
        raise EcncError("the job made no moves, so there are no joint positions to plot", Location(path.job))
    from matplotlib.figure import Figure

    joints = moving_joints(path)
    step = max(1, -(-len(path.samples["t"]) // MAX_CURVE_POINTS))  # a long job: every step-th sample
    t = path.samples["t"][::step]
    height = 1.2 + STRIP_INCHES * len(joints)
    fig = Figure(figsize=(WIDTH_INCHES, height), dpi=DPI, layout="constrained")
    axes = fig.subplots(len(joints), 1, sharex=True, squeeze=False)[:, 0]
    for ax, joint in zip(axes, joints):
        name = path.joint_names[joint] if joint < len(path.joint_names) else JOINT_COLUMNS[joint]
        ax.plot(t, path.samples[JOINT_COLUMNS[joint]][::step], color=v.TOOL_COLORS[joint % len(v.TOOL_COLORS)], lw=1.2)
        unit = "deg" if joint_kind(path, joint) == "rotary" else "mm"
        ax.set_ylabel(f"joint {joint} ({name})\n{unit}", fontsize=8)
        ax.grid(True, color="#e0e0e0", lw=0.5)
    axes[-1].set_xlabel("time (s)")
    title = f"{v.title_text(path)}\njoint positions over time"
    fig.suptitle(title, x=0.01, ha="left", fontsize=11)
    save_figure(fig, out, fmt, DPI)
    return out
