"""The limits report: how close the job came to the machine's soft limits, per axis and per joint.

Axes are machine coordinates, measured against ``[KINEMATICS]`` limits on a machine with
kinematics other than trivial and against the joints' limits otherwise; joints against
``[JOINT_n]``.  Arcs count with their extremes, and with kinematics on the joints count at every
sample the motion stage evaluated, so the minimum and maximum are those of the whole path.
Only a move's extremes matter, so the planner keeps those of its samples (``joint_extremes``)
rather than the samples, and a window of long moves holds two rows per move.
"""
from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

from edingcnc_lang.canon import AXES, Pose
from edingcnc_lang.config.machine_config import MachineConfig

if TYPE_CHECKING:
    import numpy as np

    from edingcnc_lang.motion.arc_table import ArcTable


class LimitsReport:
    """Running minimum and maximum of every axis and joint (plain lists: a job that does not move needs no numpy)."""

    def __init__(self, config: MachineConfig) -> None:
        self.config = config
        self.axis_low, self.axis_high = [math.inf] * 6, [-math.inf] * 6
        self.joint_low, self.joint_high = [math.inf] * 6, [-math.inf] * 6

    def add(self, starts: np.ndarray, ends: np.ndarray, arcs: ArcTable, joints: list[Any] | None) -> None:
        """Moves from ``starts`` to ``ends`` (columns, (6, n)); ``joints[i]`` is move i's sampled joints (or
        just their ``joint_extremes``) or None (joints = position); ``joints`` None: the joints are the
        position for every move."""
        import numpy as np

        if not ends.shape[1]:
            return
        low, high = np.minimum(ends.min(axis=1), starts[:, 0]), np.maximum(ends.max(axis=1), starts[:, 0])
        # an arc whose whole circle lies within what the end points reach cannot reach further
        inside_low, inside_high = np.minimum(low, self.axis_low).tolist(), np.maximum(high, self.axis_high).tolist()
        extremes = arcs.extremes(ends, inside_low, inside_high)
        if len(extremes):
            low, high = np.minimum(low, np.min(extremes, axis=0)), np.maximum(high, np.max(extremes, axis=0))
        self._widen("axis", low.tolist(), high.tolist())
        if joints is None:  # the usual case: joints = position everywhere
            self._widen("joint", low.tolist(), high.tolist())
            return
        identity = [i for i, j in enumerate(joints) if j is None]
        joint_points = np.vstack([*(np.atleast_2d(np.asarray(j, dtype=float)) for j in joints if j is not None),
                                  starts[:, :1].T, ends[:, identity].T])
        self._widen("joint", joint_points.min(axis=0).tolist(), joint_points.max(axis=0).tolist())

    def add_extremes(self, low: list[float], high: list[float], arcs: ArcTable | None = None,
                     ends: Sequence[Pose] = ()) -> None:
        """What ``add`` does for moves whose joints are their positions, given the lowest and highest value of
        each axis over their end points (the C planner's window works them out) and the ``arcs`` among them
        (their moves ending at ``ends``): an arc whose circle leaves those reaches its extremes, as in ``add``."""
        if arcs is not None and len(arcs):
            import numpy as np

            from edingcnc_lang.motion.arc_table import ArcTable

            inside_low = np.minimum(low, self.axis_low).tolist()
            inside_high = np.maximum(high, self.axis_high).tolist()
            outside = arcs.rows[~arcs.circle_within(inside_low, inside_high)]
            if len(outside):  # (renumbered: their moves' end points are gathered, not the window's)
                arc_ends = np.array([ends[k] for k in outside[:, 0].astype(np.intp).tolist()], dtype=float).T
                rows = outside.copy()
                rows[:, 0] = np.arange(len(rows))
                extremes = ArcTable(rows).extremes(arc_ends, inside_low, inside_high)
                if len(extremes):
                    low = np.minimum(low, np.min(extremes, axis=0)).tolist()
                    high = np.maximum(high, np.max(extremes, axis=0)).tolist()
        self._widen("axis", low, high)
        self._widen("joint", low, high)

    @staticmethod
    def joint_extremes(joints: np.ndarray) -> np.ndarray:
        """What ``add`` needs of a move's sampled joints ((N, 6)): their lowest and highest value per joint,
        (2, 6); the report comes out the same as from every sample."""
        import numpy as np

        return np.vstack([joints.min(axis=0), joints.max(axis=0)])

    def _widen(self, which: str, low: list[float], high: list[float]) -> None:
        setattr(self, f"{which}_low", [min(a, b) for a, b in zip(getattr(self, f"{which}_low"), low)])
        setattr(self, f"{which}_high", [max(a, b) for a, b in zip(getattr(self, f"{which}_high"), high)])

    def to_json(self) -> dict[str, Any]:
        """``{"axes": {"x": {...}}, "joints": {"x": {...}}}``; each ``{"min", "max", "lower", "upper", "margin"}``.

        ``margin`` is the smaller distance left to either limit (negative: beyond it); axes that
        never moved report ``null`` values.
        """
        cfg = self.config
        joints_lower = [j.negative_limit for j in cfg.joints]
        joints_upper = [j.positive_limit for j in cfg.joints]
        axes_lower, axes_upper = cfg.axis_limits()
        return {"axes": _table(self.axis_low, self.axis_high, axes_lower, axes_upper),
                "joints": _table(self.joint_low, self.joint_high, joints_lower, joints_upper)}


def _table(low: list[float], high: list[float], lower: list[float], upper: list[float]) -> dict[str, Any]:
    table = {}
    for axis, lo, hi, limit_lo, limit_hi in zip(AXES.lower(), low, high, lower, upper):
        seen = math.isfinite(lo)
        table[axis] = {"min": lo if seen else None, "max": hi if seen else None, "lower": limit_lo, "upper": limit_hi,
                       "margin": min(lo - limit_lo, limit_hi - hi) if seen else None}
    return table
