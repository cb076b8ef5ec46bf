"""Broken on purpose: every inverse call nudges an internal offset, so answers drift (K503)."""
from edingcnc_lang.kinematics.base import KinematicsPlugin


class Drifting(KinematicsPlugin):
    def __init__(self, settings):
        super().__init__(settings)
        self.calls = 0

    def inverse(self, pos, tool_length=0.0):
        self.calls += 1
        return (pos[0] + self.calls * 1e-6, *pos[1:])

    def forward(self, joints, tool_length=0.0):
        return (joints[0] - self.calls * 1e-6, *joints[1:])
