"""A two-arm SCARA for the tests: joints X and Y are the shoulder and elbow angles (degrees),
Z passes through.  Arms of 200 and 150 mm reach an annulus of 50..350 mm about the shoulder."""
import math

from edingcnc_lang.kinematics.base import KinematicsDomainError, KinematicsPlugin

L1, L2 = 200.0, 150.0


class Scara(KinematicsPlugin):
    JOINT_KINDS = ("rotary", "rotary", "linear", "rotary", "rotary", "rotary")  # the arms turn

    def inverse(self, pos, tool_length=0.0):
        x, y, z, a, b, c = pos
        r = math.hypot(x, y)
        if not abs(L1 - L2) <= r <= L1 + L2:
            raise KinematicsDomainError(f"X{x:g} Y{y:g} is {r:g} mm from the shoulder: out of the arms' reach")
        elbow = math.acos(max(-1.0, min(1.0, (r * r - L1 * L1 - L2 * L2) / (2 * L1 * L2))))
        shoulder = math.atan2(y, x) - math.atan2(L2 * math.sin(elbow), L1 + L2 * math.cos(elbow))
        return (math.degrees(shoulder), math.degrees(elbow), z, a, b, c)

    def forward(self, joints, tool_length=0.0):
        s, e, z, a, b, c = joints
        s, e = math.radians(s), math.radians(e)
        return (L1 * math.cos(s) + L2 * math.cos(s + e), L1 * math.sin(s) + L2 * math.sin(s + e), z, a, b, c)


KINEMATICS = Scara
