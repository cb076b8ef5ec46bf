"""Numbers fixed by the EdingCNC kinematics plug-in ABI (docs/kinematics.md).

Kept as plain integer constants so Python plug-ins, the ctypes bridge and the C
header all speak the same numbers.
"""
from __future__ import annotations

from enum import IntEnum

# Control IDs passed to ``control`` / ``KinematicsControl``.
OPEN = 1
CLOSE = 2
OFF = 3
ON = 4
USER_OUTPUT = 5          # project decision: the plug-in fills dData[0..11] with its user output
JOINT_LIMITS = 9
KIN_LIMITS = 10
USER1, USER2, USER3, USER4, USER5, USER6 = range(11, 17)

SETTING = 100            # project decision: one [KINEMATICS] setting at load, see docs/kinematics.md
SETTING_KEY_BYTES = 63   # the key, NUL-terminated in cData[0..63]; its value in dData[SETTING_VALUE]
SETTING_VALUE = 8        # dData[8] (past cData): the value as a number, NaN when it is not one
CONTROL_DATA_LEN = 12    # doubles in KIN_CONTROLDATA.dData
USER_OUTPUT_LEN = 12     # at most this many user-output values


class KinType(IntEnum):
    """``KinematicsType()`` values; also what #5150 reports."""

    UNDEFINED = 0
    TRIVIAL = 1
    CYLINDER_A = 2
    VIRTUAL_C = 3
    LINEAR_DELTA = 4
    COREXY = 5
    CUSTOM_1 = 18
    CUSTOM_12 = 30
    TRUNNION_AC = 31
    TRUNNION_BC = 32
