"""Kinematics: the plug-in interface, the loader, the built-ins and path sampling.

See docs/kinematics.md.  The interpreter uses ``load_kinematics`` and the ``Kinematics``
protocol; plug-in authors subclass ``KinematicsPlugin``.
"""
from edingcnc_lang.kinematics import abi
from edingcnc_lang.kinematics.base import (
    Kinematics,
    KinematicsDomainError,
    KinematicsPlugin,
    Pose,
    VectorisedKinematics,
    setting_float,
)
from edingcnc_lang.kinematics.builtin import (
    CoreXYKinematics,
    CylinderMapping,
    TrivialKinematics,
    bend_knife_correction,
)
from edingcnc_lang.kinematics.loader import available_kinematics, load_kinematics
from edingcnc_lang.kinematics.sampling import sample_arc, sample_line

__all__ = [
    "abi", "Kinematics", "KinematicsDomainError", "KinematicsPlugin", "Pose", "VectorisedKinematics",
    "setting_float", "CoreXYKinematics", "CylinderMapping", "TrivialKinematics", "bend_knife_correction",
    "available_kinematics", "load_kinematics", "sample_arc", "sample_line",
]
