"""The virtual C axis of the EdingCNC kinematics seed: C rotates the XY plane about a point.

C exists only in Cartesian space: its value is remembered as the rotation angle and the
C motor stays at 0.  The rotation point is where the kinematics was switched on (control ON
passes the machine position), or whatever USER1 sets.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import VectorisedKinematics

X, Y, C = 0, 1, 5


def rotate_xy(xy: np.ndarray, point: tuple[float, float], angle_deg: np.ndarray | float) -> np.ndarray:
    """Rotate (N, 2) points counter-clockwise by ``angle_deg`` about ``point``."""
    t = np.radians(angle_deg)
    cos_t, sin_t = np.cos(t), np.sin(t)
    dx, dy = xy[:, 0] - point[0], xy[:, 1] - point[1]
    return np.column_stack((point[0] + dx * cos_t - dy * sin_t, point[1] + dx * sin_t + dy * cos_t))


class RotateKins(VectorisedKinematics):
    """Virtual C (type 3); user output is [rotation point x, y, angle]."""

    name = "rotatekins"
    KIN_TYPE = abi.KinType.VIRTUAL_C
    VERSION = "EDINGCNC-LANG VIRTUAL C 1.0"

    def __init__(self, settings: Mapping[str, str]) -> None:
        super().__init__(settings)
        self.point = (0.0, 0.0)
        self.angle = 0.0

    def control(self, control_id: int, data: list[float]) -> int:
        if control_id in (abi.ON, abi.USER1):
            self.point = (float(data[0]), float(data[1]))
        elif control_id == abi.USER2:
            self.angle = float(data[0])
        elif control_id == abi.USER3:
            data[0], data[1] = self.point
        if control_id in (abi.USER1, abi.USER2, abi.USER3):
            return 0
        return super().control(control_id, data)

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        joints = pos.copy()
        joints[:, C] = 0.0
        if self.enabled and len(pos):
            joints[:, X:Y + 1] = rotate_xy(pos[:, X:Y + 1], self.point, pos[:, C])
            self.angle = float(pos[-1, C])
        return joints

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        pos = joints.copy()
        pos[:, C] = self.angle
        if self.enabled:
            pos[:, X:Y + 1] = rotate_xy(joints[:, X:Y + 1], self.point, -self.angle)
        return pos

    def user_output(self) -> Sequence[float]:
        return (self.point[0], self.point[1], self.angle)


KINEMATICS = RotateKins
