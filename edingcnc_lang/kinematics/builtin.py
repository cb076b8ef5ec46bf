"""Kinematics built into the controller: trivial, CoreXY, the ``KIN`` axis mappings, the bend knife.

The batch methods work on the arrays they are given, so only the bend knife imports numpy itself.
"""
from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING

from edingcnc_lang.errors import MachineError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import VectorisedKinematics
from edingcnc_lang.records import record

if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import ArrayLike

X, Y, Z, A, B, C = range(6)


class TrivialKinematics(VectorisedKinematics):
    """joints = pos."""

    name = "trivial"
    KIN_TYPE = abi.KinType.TRIVIAL
    VERSION = "TRIVIAL 1.0"

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        return pos.copy()

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        return joints.copy()


class CoreXYKinematics(VectorisedKinematics):
    """Two belts drive X and Y together: jx = x + y, jy = x - y."""

    name = "corexy"
    KIN_TYPE = abi.KinType.COREXY
    VERSION = "COREXY 1.0"

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        joints = pos.copy()
        joints[:, X] = pos[:, X] + pos[:, Y]
        joints[:, Y] = pos[:, X] - pos[:, Y]
        return joints

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        pos = joints.copy()
        pos[:, X] = (joints[:, X] + joints[:, Y]) / 2.0
        pos[:, Y] = (joints[:, X] - joints[:, Y]) / 2.0
        return pos


@record(frozen=True)
class MappingSpec:
    """One ``KIN`` mode: an axis wrapped onto the A cylinder and/or motors that copy another axis.

    ``follow`` pairs are (motor, source axis): the motor is driven by the source axis and the
    Cartesian axis of the same letter is taken over (forward reports it as 0).  ``hold_z``
    keeps the Z motor where it was when the mapping started (the copied axis then lives
    only on the follower motor).
    """

    wrap: int | None = None
    follow: tuple[tuple[int, int], ...] = ()
    hold_z: bool = False


MAPPINGS: dict[str, MappingSpec] = {
    "X2A": MappingSpec(wrap=X),
    "Y2A": MappingSpec(wrap=Y),
    "X2XA": MappingSpec(follow=((A, X),)),
    "Y2YA": MappingSpec(follow=((A, Y),)),
    "Z2C": MappingSpec(follow=((C, Z),), hold_z=True),
    "Z2ZC": MappingSpec(follow=((C, Z),)),
    "Y2YAZ2ZC": MappingSpec(follow=((A, Y), (C, Z))),
}


class CylinderMapping(VectorisedKinematics):
    """The ``KIN X2A ... Y2YAZ2ZC`` modes (type 2).

    ``work_zero`` is the active work zero (machine coordinates) along the wrapped axis: Y for
    Y2A, X for X2A; Y2A uses the calibrated rotation point instead when cnc.ini says it is
    calibrated.  ``hold_z`` is the Z motor position when a Z2C mapping starts.
    """

    KIN_TYPE = abi.KinType.CYLINDER_A
    VERSION = "CYLINDER MAPPING 1.0"

    def __init__(self, mode: str, settings: Mapping[str, str], work_zero: float = 0.0,
                 hold_z: float = 0.0) -> None:
        super().__init__(settings)
        key = mode.upper()
        if key not in MAPPINGS:
            raise MachineError(f"unknown KIN mode {mode!r} (expected one of {', '.join(MAPPINGS)})")
        self.mode = key
        self.name = f"KIN {key}"
        self.spec = MAPPINGS[key]
        self.hold_z = hold_z
        self.enabled = True
        self.origin = work_zero
        self.deg_per_mm = 0.0
        if self.spec.wrap is not None:
            radius = self.setting("aAxisCalibratedCilinderRadius", 0.0)
            if not radius > 0.0:
                raise MachineError(
                    f"KIN {key} needs the A-axis cylinder radius: [KINEMATICS] "
                    f"aAxisCalibratedCilinderRadius must be > 0 (it is {radius:g})")
            self.deg_per_mm = 180.0 / (math.pi * radius)
            calibrated = self.setting("aAxisRotationPointIsCalibrated", 0.0) == 1.0
            if self.spec.wrap == Y and calibrated:
                self.origin = self.setting("aAxisCalibratedRotationPointY", 0.0)

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        joints = pos.copy()
        if self.spec.wrap is not None:
            joints[:, A] = (pos[:, self.spec.wrap] - self.origin) * self.deg_per_mm
            joints[:, self.spec.wrap] = self.origin
        for motor, source in self.spec.follow:
            joints[:, motor] = pos[:, source]
        if self.spec.hold_z:
            joints[:, Z] = self.hold_z
        return joints

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        pos = joints.copy()
        if self.spec.wrap is not None:
            pos[:, self.spec.wrap] = self.origin + joints[:, A] / self.deg_per_mm
            pos[:, A] = 0.0
        for motor, source in self.spec.follow:
            if self.spec.hold_z:
                pos[:, source] = joints[:, motor]
            pos[:, motor] = 0.0
        return pos


def bend_knife_correction(x: ArrayLike, y: ArrayLike, z_work: ArrayLike, c_deg: ArrayLike,
                          beta_deg: float, z_hi: float, z_lo: float
                          ) -> tuple[np.ndarray | float, np.ndarray | float]:
    """Joint XY of a 45 degree bend knife: the tip moves sideways as far as it goes below ``z_hi``.

    d = clamp(z_hi - z_work, 0, z_hi - z_lo); (jx, jy) = (x, y) + d * (cos(C + beta), sin(C + beta)).
    beta = 0 is a straight knife (no correction).  Scalars in give floats out, arrays broadcast.
    """
    import numpy as np

    xa, ya = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if beta_deg == 0.0:
        jx, jy = np.broadcast_arrays(xa, ya)
    else:
        depth = np.clip(z_hi - np.asarray(z_work, dtype=float), 0.0, max(z_hi - z_lo, 0.0))
        direction = np.radians(np.asarray(c_deg, dtype=float) + beta_deg)
        jx = xa + depth * np.cos(direction)
        jy = ya + depth * np.sin(direction)
    if np.ndim(jx) == 0:
        return float(jx), float(jy)
    return jx, jy
