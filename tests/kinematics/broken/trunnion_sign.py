"""Broken on purpose: an A trunnion table (rotation about X through the origin) whose forward turns
the wrong way.  The sign error only shows when A moves, so a proof with A held at 0 misses it
(K101, K102 once A is proven over a turn)."""
import math

from edingcnc_lang.kinematics.base import KinematicsPlugin


class TrunnionSign(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        t = math.radians(a)
        return (x, y * math.cos(t) - z * math.sin(t), y * math.sin(t) + z * math.cos(t), a, b, c)

    def forward(self, joints, tool_length=0.0):
        x, y, z, a, b, c = joints
        t = math.radians(a)
        return (x, y * math.cos(t) - z * math.sin(t), -y * math.sin(t) + z * math.cos(t), a, b, c)
