"""Broken on purpose: forward scales X by 1.01, so forward(inverse(p)) misses p (K101)."""
from edingcnc_lang.kinematics.base import KinematicsPlugin


class ScaledForward(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        return tuple(pos)

    def forward(self, joints, tool_length=0.0):
        return (joints[0] * 1.01, *joints[1:])
