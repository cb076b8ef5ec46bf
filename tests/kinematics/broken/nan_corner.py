"""Broken on purpose: a vertical arm of length 120 that returns NaN instead of raising
KinematicsDomainError where it cannot reach (the corners of a 200 mm box) (K401)."""
import numpy as np

from edingcnc_lang.kinematics.base import KinematicsPlugin

ARM = 120.0


class NanCorner(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        with np.errstate(invalid="ignore"):
            jz = z + float(np.sqrt(ARM ** 2 - x * x - y * y))
        return (x, y, jz, a, b, c)

    def forward(self, joints, tool_length=0.0):
        x, y, jz, a, b, c = joints
        return (x, y, jz - float(np.sqrt(ARM ** 2 - x * x - y * y)), a, b, c)
