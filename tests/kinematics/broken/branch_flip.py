"""Broken on purpose: a two-link arm that picks elbow-up for Y >= 0 and elbow-down below, so the
joints jump where the proving box crosses Y = 0 (K201)."""
import math

from edingcnc_lang.kinematics.base import KinematicsPlugin

L1 = L2 = 100.0


class BranchFlip(KinematicsPlugin):
    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        cos_elbow = (x * x + y * y - L1 * L1 - L2 * L2) / (2 * L1 * L2)
        elbow = math.acos(max(-1.0, min(1.0, cos_elbow))) * (1.0 if y >= 0 else -1.0)
        shoulder = math.atan2(y, x) - math.atan2(L2 * math.sin(elbow), L1 + L2 * math.cos(elbow))
        return (math.degrees(shoulder), math.degrees(elbow), z, a, b, c)

    def forward(self, joints, tool_length=0.0):
        shoulder, elbow, z, a, b, c = joints
        s, e = math.radians(shoulder), math.radians(elbow)
        return (L1 * math.cos(s) + L2 * math.cos(s + e), L1 * math.sin(s) + L2 * math.sin(s + e), z, a, b, c)
