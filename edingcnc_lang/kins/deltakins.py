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
SAFETY_SLACK = 1.0 + 1e-9  # relative: rounding of sampled arcs, far below any machine's resolution
BLOCK = 16_384  # samples per pass of the inverse: a block's temporaries stay in the CPU cache


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
        """jk = z + sqrt(L^2 - (tx_k - x)^2 - (ty_k - y)^2) for the three towers k, block by block."""
        joints = pos.copy()
        for first in range(0, len(pos), BLOCK):
            joints[first:first + BLOCK, 0:3] = self._carriage_heights(pos[first:first + BLOCK], first).T
        if len(joints):
            self.last_joints = tuple(joints[-1, 0:3].tolist())
        return joints

    def _carriage_heights(self, pos: np.ndarray, first: int) -> np.ndarray:
        """(3, n) joint positions of a block of poses; ``first`` is the block's first sample in the batch.

        The work is done in place on (3, n) arrays with one contiguous row per axis or tower:
        numpy streams through contiguous rows several times faster than through the columns of
        an (n, 6) array.
        """
        x, y, z = pos[:, 0:3].T.copy()
        radicand = np.subtract.outer(self.towers[:, 0], x)
        np.square(radicand, out=radicand)
        dy = np.subtract.outer(self.towers[:, 1], y)
        np.square(dy, out=dy)
        np.subtract(self.arm ** 2, radicand, out=radicand)
        np.subtract(radicand, dy, out=radicand)
        # 0: not set; a point on the circle itself is inside (an arc sampled along it lands 1e-14 beyond)
        far = np.hypot(x, y) > self.safety_radius * SAFETY_SLACK if self.safety_radius > 0.0 else None
        # one cheap pass when every sample is reachable; NaN fails ">=" and takes the exact check too
        if not radicand.min(initial=np.inf) >= 0.0 or (far is not None and far.any()):
            bad = (radicand < 0.0).any(axis=0)
            if far is not None:
                bad |= far
            if bad.any():
                index = int(np.flatnonzero(bad)[0])
                self._raise_unreachable(pos[index], radicand[:, index], first + index)
        heights = np.sqrt(radicand, out=radicand)  # in place: the radicand becomes the carriage heights
        heights += z
        return heights

    def _raise_unreachable(self, pose: np.ndarray, radicand: np.ndarray, sample: int) -> None:
        """``radicand`` holds the three towers' values at ``pose``, sample number ``sample`` of the batch."""
        x, y, z = (float(v) for v in pose[0:3])
        short = [JOINT_NAMES[k] for k in range(3) if radicand[k] < 0.0]
        reason = (f"the arm of joint {', '.join(short)} is too short" if short else
                  f"it is {math.hypot(x, y):g} mm from the centre, beyond "
                  f"linDeltaSafetyRadius = {self.safety_radius:g}")
        raise KinematicsDomainError(f"X{x:g} Y{y:g} Z{z:g} is out of reach of the delta robot: {reason}",
                                    sample=sample)

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
