"""Broken on purpose: a polar table whose angle joint comes from atan(y / x) where atan2 belongs,
so every pose with X < 0 lands on the opposite side (K101) and the angle jumps by 180 degrees
on the Y axis (K201)."""
import math

from edingcnc_lang.kinematics.base import KinematicsPlugin


class PolarAtan(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        angle = math.degrees(math.atan(y / x)) if x else math.copysign(90.0, y)
        return (math.hypot(x, y), 0.0, z, a, b, angle)

    def forward(self, joints, tool_length=0.0):
        r, _, z, a, b, angle = joints
        t = math.radians(angle)
        return (r * math.cos(t), r * math.sin(t), z, a, b, 0.0)
