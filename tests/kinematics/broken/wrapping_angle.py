"""Broken on purpose: a polar table whose angle joint comes from atan2, so it wraps at 180 degrees
on the negative X axis, which the proving box crosses (K202)."""
import math

from edingcnc_lang.kinematics.base import KinematicsPlugin


class WrappingPolar(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        return (math.hypot(x, y), 0.0, z, a, b, math.degrees(math.atan2(y, x)))

    def forward(self, joints, tool_length=0.0):
        r, _, z, a, b, angle = joints
        t = math.radians(angle)
        return (r * math.cos(t), r * math.sin(t), z, a, b, 0.0)
