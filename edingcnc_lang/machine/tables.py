"""The dialect's tables as data: modal groups, order of execution, parameter ranges.

G and M numbers are stored as integer tenths (G38.2 -> 382) so they compare
exactly.  The interpreter and the linter both read these tables; neither keeps
its own copy.
"""
from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType


def code_key(value: float) -> int:
    """A G/M number as integer tenths: 38.2 -> 382, 1 -> 10."""
    return int(round(value * 10))


def code_name(letter: str, key: int) -> str:
    """Integer tenths back to the familiar spelling: ('G', 382) -> 'G38.2'."""
    whole, tenth = divmod(key, 10)
    return f"{letter}{whole}" + (f".{tenth}" if tenth else "")


TOOL_CHANGE_SUB = "change_tool"  # the sub M6 calls when it is defined
TOOL_CHANGE = code_key(6)


def m_sub_name(key: int) -> str | None:
    """The sub an M code without a built-in runs (``m100`` for M100), None for M codes with a tenth.

    The interpreter and the linter both name the sub this way, so what a job runs and what the
    linter links an M code to cannot differ.
    """
    whole, tenth = divmod(key, 10)
    return None if tenth else f"m{whole}"


def m_code_sub(key: int) -> str | None:
    """The sub an M code (integer tenths) runs if it is defined: ``m100``, ``change_tool`` for M6."""
    return TOOL_CHANGE_SUB if key == TOOL_CHANGE else m_sub_name(key)


def _groups(spec: dict[str, tuple[float, ...]]) -> Mapping[int, str]:
    return MappingProxyType({code_key(c): group for group, codes in spec.items() for c in codes})


G_GROUPS: Mapping[int, str] = _groups({
    "motion": (0, 1, 2, 3, 33, 33.1, 38.2, 73, 74, 76, 80, 81, 82, 83, 84, 85, 86, 87, 88, 89),
    "plane": (17, 18, 19),
    "distance": (90, 91),
    "feed_mode": (93, 94, 95),
    "spindle_mode": (96, 97),
    "units": (20, 21, 70, 71),
    "cutter_comp": (40, 41, 42, 41.1, 42.1),
    "length_offset": (43, 43.1, 49),
    "return_mode": (98, 99),
    "coord_system": (54, 55, 56, 57, 58, 59, 59.1, 59.2, 59.3),
    "path_control": (61, 61.1, 64),
    "rotation": (68, 69),
    "scaling": (50, 51),
    "non_modal": (4, 10, 28, 30, 53, 92, 92.1, 92.2, 92.3),
})
G_80 = code_key(80)


def same_line_winner(group: str, first: int, second: int) -> int | None:
    """Which of two G codes of one modal group on one line takes effect; None: they conflict.

    G80 beside another motion code gives way to it, as rs274 does (LinuxCNC's read_g): the CAM
    safe-start line ``G0 G90 G40 G21 G17 G94 G80`` cancels no cycle twice and means G0.
    """
    if group == "motion" and G_80 in (first, second):
        return second if first == G_80 else first
    return None


# The canned cycles the interpreter runs (cycles.py expands each into moves; G76, the lathe's
# threading cycle, is spindle-synchronised motion in machine/threads.py).
CANNED_CYCLES = frozenset(code_key(c) for c in (73, 74, 81, 82, 83, 84, 85, 86, 87, 88, 89))

M_GROUPS: Mapping[int, str] = _groups({
    "stopping": (0, 1, 2, 30, 60),
    "tool_change": (6,),
    "spindle": (3, 4, 5),
    "coolant": (7, 8, 9),
    "overrides": (48, 49, 50, 51, 52, 53),
    "io": (54, 55, 56, 57),
    "laser": (10, 11),                               # manual 3.7.11: laser off / on
    "thc": (20, 21, 22, 23),                         # 3.7.10: torch height control off, on, set voltage Q
    "printer": (104, 106, 107, 109, 140, 143, 190),  # 3.7.12: 3D printing, S a temperature or fan value
    "misc": (26, 27, 80, 81, 90, 91, 92, 93, 94, 95, 96, 97, 100),
})
# M codes whose S is not a spindle speed (3.7.12: a temperature in degrees C, or the fan's 0..100 %).
OWN_M_WORDS: Mapping[int, frozenset[str]] = MappingProxyType(
    {code_key(c): frozenset("S") for c in (104, 106, 109, 140, 143, 190)})

# G codes other controllers know, with what to use on EdingCNC (shown with "unknown G code").
UNKNOWN_G_HINTS: Mapping[int, str] = MappingProxyType({
    code_key(7): "LinuxCNC's diameter mode is not an EdingCNC code; a lathe takes X as a diameter "
                 "when cnc.ini sets [INTERPRETER] diameterProgramming = 1",
    code_key(8): "LinuxCNC's radius mode is not an EdingCNC code; a lathe takes X as a radius "
                 "when cnc.ini sets [INTERPRETER] diameterProgramming = 0",
    code_key(90.1): "LinuxCNC's absolute arc centres; EdingCNC sets this for all arcs with cnc.ini "
                    "[INTERPRETER] absoluteCenterCoords = 1",
    code_key(91.1): "LinuxCNC's incremental arc centres; EdingCNC's default (absoluteCenterCoords = 0)",
    code_key(15): "polar coordinates of other controls are not an EdingCNC code",
    code_key(16): "polar coordinates of other controls are not an EdingCNC code",
})

# G codes only a lathe knows (cnc.ini [SYSTEM] machineType = 1): constant surface speed needs X
# to be the distance from the spindle's axis, and G76 threads a turning part.  A mill stops at them.
LATHE_ONLY_G = frozenset(code_key(c) for c in (76, 96))


def lathe_code_message(key: int) -> str:
    """What a mill says of a lathe code (shared by the run and ``ecnc lint --ini``)."""
    return (f"{code_name('G', key)} is a lathe code and this machine is a mill: "
            "a lathe's cnc.ini (--ini) sets [SYSTEM] machineType = 1")


# Words a G code takes as its own parameters on its line, so no other step of the line sees them.
# G64 (manual 3.6.16): P rounding tolerance, Q line-merge tolerance, R and S the look-ahead angles,
# D the corner deviation, F the ramp filter; never the spindle speed or the feed.
OWN_G_WORDS: Mapping[int, frozenset[str]] = MappingProxyType({code_key(64): frozenset("PQRSDF")})
# Of these, the lengths (converted from inch under G20) and the angles in degrees.
G64_LENGTHS = frozenset("PQD")

# G codes that take the axis words of their line (so a motion on the same line may not).
AXIS_WORD_USERS = frozenset(code_key(c) for c in (10, 28, 30, 92))

MM_PER_INCH = 25.4  # G20 programs: every length word is this many mm
MAX_M_WORDS = 4
LETTER_ARGS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"  # M-sub arguments: A=#1 .. Z=#26
ABSENT_ARGUMENT = -1e10

# --------------------------------------------------------------------------- parameters

FIRST_PARAM, LAST_PARAM = 1, 5999
ARG_PARAMS = range(1, 27)
VOLATILE_PARAMS = range(27, 4000)

READ_ONLY_PARAMS: tuple[range, ...] = (
    range(5001, 5007), range(5051, 5077), range(5081, 5087), range(5101, 5127), range(5131, 5134), range(5141, 5144),
    range(5150, 5153), range(5380, 5381), range(5397, 5398),
)
# Numbers the manual reserves (for the rotation coordinate systems 1..8): a macro must not use them.
RESERVED_PARAMS: tuple[range, ...] = tuple(range(5230 + 20 * k, 5231 + 20 * k) for k in range(8))

# Named system parameters (dialect reference, section 10).
POS_WORK = 5001            # ..5006 work position X..C
TOOL_CURRENT = 5008
TOOL_RADIUS = 5009
TOOL_Z_OFFSET = 5010
TOOL_NEW = 5011
TOOL_X_TOTAL = 5012        # the current tool's X offset + xDelta, as the table stores it (lathe)
TOOL_G43_OFFSET = 5013
TOOL_G43_X_OFFSET = 5014   # the X offset G43 applies: a radius (half the table's value in diameter mode)
TOOL_CHANGED = 5015
PROBE_MACHINE = 5051       # ..5056
PROBE_WORK = 5061          # ..5066
PROBE_TRIPPED = 5067
PROBE_INPUT = 5068
SPINDLE_SPEED = 5070
POS_MACHINE = 5071         # ..5076
PROBE_JOINTS = 5081        # ..5086
SOFT_LIMIT_NEG = 5101      # ..5106
SOFT_LIMIT_POS = 5111      # ..5116
HOME_POSITION = 5121       # ..5126
TCA_NEGATIVE = 5131        # ..5133 tool-change area, machine X Y Z (cnc.ini [KINEMATICS] negativeLimitTCAX..)
TCA_POSITIVE = 5141        # ..5143
KIN_TYPE = 5150
ZHC_ACTIVE = 5151
SPINDLE_ON = 5152
G28_HOME = 5161            # ..5166
G30_HOME = 5181            # ..5186
G68_ACTIVE = 5190          # 5191..5193 pivot, 5194..5196 angles
SCALING_ACTIVE = 5200      # G51: 5201..5203 centre (work X Y Z), 5204..5206 factors X Y Z
G92_OFFSET = 5211          # ..5216
COORD_SYSTEM = 5220        # 1..9
COORD_OFFSETS = 5221       # system k (1..9) axis i (0..5) at 5221 + 20*(k-1) + i
COORD_STRIDE = 20
SIMULATION = 5380
SPINDLE_SELECTED = 5390    # 0 standard spindle (M90), 1..7 alternate spindles (M91..M97)
ALT_SPINDLE_OFFSET = 5391  # 5391..5393: the alternate spindle's (M91's) offsets X Y Z (manual 3.1, p. 4)
RENDERING = 5397
DIALOG_RESULT = 5398
IO_RESULT = 5399
TOOL_LENGTH = 5400         # + tool number (1..99)
TOOL_DIAMETER = 5500
TOOL_X_OFFSET = 5600
TOOL_ORIENTATION = 5700
TOOL_X_WEAR = 5800
TOOL_Z_WEAR = 5900
MAX_TOOL = 99


def is_read_only(index: int) -> bool:
    return any(index in r for r in READ_ONLY_PARAMS)


def coord_offset_param(system: int, axis: int) -> int:
    """Parameter holding axis ``axis`` (0 = X) of coordinate system ``system`` (1 = G54)."""
    return COORD_OFFSETS + COORD_STRIDE * (system - 1) + axis


COORD_SYSTEM_CODES = tuple(code_key(c) for c in (54, 55, 56, 57, 58, 59, 59.1, 59.2, 59.3))

# --------------------------------------------------------------------------- order of execution

# The actions of one line, in the order the controller executes them (dialect reference, section
# 9), each with what triggers it: a G group, an M group or a letter word of the line ("always" for
# the motion, which also runs on axis words alone).  A (MSG) comment and an M-code sub call come
# before all of these.
ORDER_OF_EXECUTION: tuple[tuple[str, str, str], ...] = (
    ("feed_mode", "G", "feed_mode"),
    ("feed", "word", "F"),
    ("spindle_mode", "G", "spindle_mode"),
    ("spindle_speed", "word", "S"),
    ("tool_select", "word", "T"),
    ("tool_change", "M", "tool_change"),
    ("spindle", "M", "spindle"),
    ("coolant", "M", "coolant"),
    ("overrides", "M", "overrides"),
    ("io", "M", "io"),
    ("laser", "M", "laser"),
    ("thc", "M", "thc"),
    ("printer", "M", "printer"),
    ("m_state", "M", "misc"),
    ("dwell", "G", "non_modal"),
    ("plane", "G", "plane"),
    ("units", "G", "units"),
    ("cutter_comp", "G", "cutter_comp"),
    ("length_offset", "G", "length_offset"),
    ("coord_system", "G", "coord_system"),
    ("path_control", "G", "path_control"),
    ("distance", "G", "distance"),
    ("return_mode", "G", "return_mode"),
    ("rotation", "G", "rotation"),
    ("scaling", "G", "scaling"),
    ("non_modal", "G", "non_modal"),
    ("motion", "always", ""),
    ("stopping", "M", "stopping"),
)
