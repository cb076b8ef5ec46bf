"""Linear delta robot: three vertical carriages, each with a parallel arm of length L to the effector.

The tower layout is LinuxCNC's ``lineardeltakins`` (so results can be compared with it): joint X
at (0, R), joint Y at (-R sin 60, -R cos 60), joint Z at (+R sin 60, -R cos 60).  A, B and C pass
straight through.
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from edingcnc_lang.errors import ConfigError
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import KinematicsDomainError, VectorisedKinematics

SIN_60 = math.sqrt(3.0) / 2.0
COS_60 = 0.5
JOINT_NAMES = ("X", "Y", "Z")


class DeltaKins(VectorisedKinematics):
    """Linear delta (type 4); user output is the last inverse's [jx, jy, jz]."""

    name = "deltakins"
    KIN_TYPE = abi.KinType.LINEAR_DELTA
    VERSION = "EDINGCNC-LANG LINEAR DELTA 1.0"

    def __init__(self, settings: Mapping[str, str]) -> None:
        super().__init__(settings)
        self.radius = self.setting("linDeltaRadius", 125.0)
        self.arm = self.setting("linDeltaArmLength", 250.0)
        self.safety_radius = self.setting("linDeltaSafetyRadius", 0.0)
        if not 0.0 < self.radius < self.arm:
            raise ConfigError(f"[KINEMATICS] needs 0 < linDeltaRadius < linDeltaArmLength "
                              f"(got {self.radius:g} and {self.arm:g})")
        r = self.radius
        self.towers = np.array([[0.0, r], [-SIN_60 * r, -COS_60 * r], [SIN_60 * r, -COS_60 * r]])
        self.last_joints: tuple[float, ...] = ()

    def inverse_rows(self, pos: np.ndarray, tool_length: float) -> np.ndarray:
        dx = self.towers[None, :, 0] - pos[:, 0:1]
        dy = self.towers[None, :, 1] - pos[:, 1:2]
        radicand = self.arm ** 2 - dx ** 2 - dy ** 2
        bad = (radicand < 0.0).any(axis=1)
        if self.safety_radius > 0.0:
            bad |= np.hypot(pos[:, 0], pos[:, 1]) > self.safety_radius
        if bad.any():
            self._raise_unreachable(pos, radicand, int(np.flatnonzero(bad)[0]))
        joints = pos.copy()
        joints[:, 0:3] = pos[:, 2:3] + np.sqrt(radicand)
        if len(joints):
            self.last_joints = tuple(float(j) for j in joints[-1, 0:3])
        return joints

    def _raise_unreachable(self, pos: np.ndarray, radicand: np.ndarray, index: int) -> None:
        x, y, z = (float(v) for v in pos[index, 0:3])
        short = [JOINT_NAMES[k] for k in range(3) if radicand[index, k] < 0.0]
        reason = (f"the arm of joint {', '.join(short)} is too short" if short else
                  f"it is {math.hypot(x, y):g} mm from the centre, beyond "
                  f"linDeltaSafetyRadius = {self.safety_radius:g}")
        raise KinematicsDomainError(f"X{x:g} Y{y:g} Z{z:g} is out of reach of the delta robot: {reason}",
                                    sample=index)

    def forward_rows(self, joints: np.ndarray, tool_length: float) -> np.ndarray:
        """Trilateration of three spheres of radius L about the carriage joints; the lower root."""
        n = len(joints)
        centres = np.concatenate((np.broadcast_to(self.towers, (n, 3, 2)), joints[:, 0:3, None]), axis=2)
        p1 = centres[:, 0]
        d21, d31 = centres[:, 1] - p1, centres[:, 2] - p1
        d = np.linalg.norm(d21, axis=1)
        ex = d21 / d[:, None]
        i = np.einsum("ij,ij->i", ex, d31)
        ey_raw = d31 - i[:, None] * ex
        j = np.linalg.norm(ey_raw, axis=1)
        ey = ey_raw / j[:, None]
        ez = np.cross(ex, ey)
        u = d / 2.0
        v = (i ** 2 + j ** 2) / (2.0 * j) - i * u / j
        height_sq = self.arm ** 2 - u ** 2 - v ** 2
        if (height_sq < 0.0).any():
            k = int(np.flatnonzero(height_sq < 0.0)[0])
            jx, jy, jz = (float(q) for q in joints[k, 0:3])
            raise KinematicsDomainError(
                f"joints X{jx:g} Y{jy:g} Z{jz:g} cannot be assembled: the carriages are further "
                f"apart than the arms reach", sample=k)
        down = np.where(ez[:, 2] > 0.0, -1.0, 1.0) * np.sqrt(height_sq)
        pos = joints.copy()
        pos[:, 0:3] = p1 + u[:, None] * ex + v[:, None] * ey + down[:, None] * ez
        return pos

    def user_output(self) -> Sequence[float]:
        return self.last_joints


KINEMATICS = DeltaKins
