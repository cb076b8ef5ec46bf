"""The workspace a plug-in is proven over, and seeded sample poses in it.

The box comes from, in order: ``--box``; the Cartesian limits of the ini (``[KINEMATICS]
positiveLimitX`` ...); the joint limits of the ini (``[JOINT_n] positiveLimit``) mapped through the
plug-in's forward kinematics; else a default cube.  Rotary axes whose limits mean "unlimited"
(|limit| >= 10000, as cnc.ini writes 99999) are proven over one turn, -180..180, and so is a
rotary axis that neither the ini nor the default limits but that turns the machine (moving it
moves another joint than its own): a 5-axis plug-in is never proven at A0 B0 C0 alone.
"""
from __future__ import annotations

import math

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from edingcnc_lang.kinematics.base import PLUGIN_FAILURES, Kinematics

if TYPE_CHECKING:
    from edingcnc_lang.config.machine_config import MachineConfig

DEFAULT_BOX = ((-100.0, 100.0), (-100.0, 100.0), (-100.0, 100.0), (0.0, 0.0), (0.0, 0.0), (0.0, 0.0))
UNLIMITED = 10_000.0
ONE_TURN = (-180.0, 180.0)


@dataclass(frozen=True)
class Workspace:
    """Six (low, high) ranges; an axis with low == high is held fixed."""

    box: tuple[tuple[float, float], ...]
    source: str

    @property
    def lows(self) -> np.ndarray:
        return np.array([lo for lo, _ in self.box])

    @property
    def extents(self) -> np.ndarray:
        return np.array([hi - lo for lo, hi in self.box])

    @property
    def varying(self) -> list[int]:
        """Indices of the axes that move."""
        return [i for i, (lo, hi) in enumerate(self.box) if hi > lo]

    @property
    def size(self) -> float:
        """The diagonal of the box: the scale tolerances are relative to (at least 1)."""
        return max(1.0, float(np.linalg.norm(self.extents)))

    @property
    def centre(self) -> tuple[float, ...]:
        return tuple(float(v) for v in self.lows + self.extents / 2.0)

    def random(self, count: int, rng: np.random.Generator) -> np.ndarray:
        """``count`` poses drawn uniformly, with the corners and the centre first (where plug-ins break)."""
        corners = _corners(self)
        uniform = self.lows + rng.random((max(0, count - len(corners)), 6)) * self.extents
        return np.vstack((corners, uniform))[:count]


def _corners(space: Workspace) -> np.ndarray:
    """The centre and every corner of the moving axes (at most 64 poses)."""
    axes = space.varying
    rows = [list(space.centre)]
    for mask in range(2 ** len(axes)):
        row = list(space.centre)
        for bit, axis in enumerate(axes):
            row[axis] = space.box[axis][(mask >> bit) & 1]
        rows.append(row)
    return np.array(rows, dtype=float)


def parse_box(values: Sequence[float]) -> Workspace:
    """``X0,X1,Y0,Y1,Z0,Z1[,A0,A1[,B0,B1[,C0,C1]]]`` from the command line (one value, split into numbers)."""
    if len(values) % 2 or not 6 <= len(values) <= 12:
        raise ValueError("--box takes X0,X1,Y0,Y1,Z0,Z1 and optionally A0,A1,B0,B1,C0,C1 (6 to 12 numbers, "
                         f"got {len(values)}), e.g. --box=-200,200,-200,200,0,150")
    if not all(math.isfinite(v) for v in values):  # nan or inf: no pose to sample between them
        raise ValueError(f"--box takes finite numbers, not {next(v for v in values if not math.isfinite(v))}")
    pairs = [(min(values[i], values[i + 1]), max(values[i], values[i + 1])) for i in range(0, len(values), 2)]
    pairs += [(0.0, 0.0)] * (6 - len(pairs))
    return Workspace(tuple(pairs), "--box")


def _limited(pair: tuple[float, float], axis: int) -> tuple[float, float]:
    lo, hi = pair
    if axis >= 3 and (abs(lo) >= UNLIMITED or abs(hi) >= UNLIMITED):
        return ONE_TURN
    return (min(lo, hi), max(lo, hi))


def from_cartesian_limits(config: MachineConfig) -> Workspace | None:
    """The ``[KINEMATICS]`` positive/negativeLimit<axis> values (read and checked by ``load_config``),
    if the ini gives the linear ones; a rotary axis it does not limit is held at 0."""
    if not all(config.gives_cartesian_limits(axis) for axis in range(3)):
        return None
    pairs = [_limited((lo, hi), axis) if config.gives_cartesian_limits(axis) else (0.0, 0.0)
             for axis, (lo, hi) in enumerate(zip(config.cartesian_negative_limits, config.cartesian_positive_limits))]
    return Workspace(tuple(pairs), "cnc.ini [KINEMATICS] limits")


def from_joint_limits(kins: Kinematics, joint_limits: Sequence[tuple[float, float]], seed: int) -> Workspace | None:
    """The bounding box of the poses the plug-in's forward gives inside the joint limits."""
    lows = np.array([lo for lo, _ in joint_limits], dtype=float)
    highs = np.array([hi for _, hi in joint_limits], dtype=float)
    clipped = [_limited((lo, hi), i) for i, (lo, hi) in enumerate(zip(lows, highs))]
    lows, highs = np.array([c[0] for c in clipped]), np.array([c[1] for c in clipped])
    rng = np.random.default_rng(seed)
    joints = lows + rng.random((2000, 6)) * (highs - lows)
    poses = []
    for row in joints:
        try:
            pose = kins.forward(tuple(float(v) for v in row))
        except PLUGIN_FAILURES:  # an unassemblable joint set is simply outside the workspace
            continue
        if all(np.isfinite(pose)):
            poses.append(pose)
    if not poses:
        return None
    found = np.array(poses)
    pairs = tuple((float(lo), float(hi)) for lo, hi in zip(found.min(axis=0), found.max(axis=0)))
    return Workspace(pairs, "cnc.ini joint limits through the plug-in's forward kinematics")


PROBE_ANGLES = (-150.0, 90.0)  # where a rotary axis is tried to see whether it turns the machine


def turning_rotaries(kins: Kinematics, space: Workspace) -> Workspace:
    """``space`` with every fixed rotary axis that moves another joint than its own widened to one
    turn: an ini or the default cube that holds A, B or C must not hide a 5-axis plug-in's rotary
    geometry (the ``--box`` is taken as given).  The plug-in is expected to be ON."""
    box = list(space.box)
    # off the centre: a rotation about the centre would leave it where it is
    centre = [float(v) for v in space.lows + space.extents * np.array([0.71, 0.29, 0.62, 0.5, 0.5, 0.5])]
    base = _joints(kins, centre)
    if base is None:
        return space
    turned = []
    for axis in (3, 4, 5):
        if box[axis][0] == box[axis][1] and any(_turns(kins, centre, base, axis, angle) for angle in PROBE_ANGLES):
            box[axis] = ONE_TURN
            turned.append("XYZABC"[axis])
    if not turned:
        return space
    return Workspace(tuple(box), (f"{space.source}; {' '.join(turned)} over one turn, "
                                    f"as {'it moves' if len(turned) == 1 else 'they move'} the joints"))


def _joints(kins: Kinematics, pose: Sequence[float]) -> np.ndarray | None:
    try:
        joints = np.array(kins.inverse(tuple(float(v) for v in pose)), dtype=float)
    except PLUGIN_FAILURES:
        return None
    return joints if joints.shape == (6,) and np.isfinite(joints).all() else None


def _turns(kins: Kinematics, centre: list[float], base: np.ndarray, axis: int, angle: float) -> bool:
    """Whether turning ``axis`` to ``angle`` moves any joint but its own (which may pass it through,
    or ignore it: a polar table's C joint comes from X and Y)."""
    pose = list(centre)
    pose[axis] = angle
    joints = _joints(kins, pose)
    if joints is None:  # an error or NaN there: the axis matters, and the checks will say how
        return True
    others = [i for i in range(6) if i != axis]
    return not np.allclose(joints[others], base[others], rtol=1e-9, atol=1e-9 * space_scale(centre))


def space_scale(pose: Sequence[float]) -> float:
    return max(1.0, float(np.max(np.abs(pose))))


def default_workspace() -> Workspace:
    return Workspace(DEFAULT_BOX, "default cube; give --box or --ini for your machine")
