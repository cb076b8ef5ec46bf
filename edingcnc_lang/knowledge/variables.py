"""The parameters (#1..#5999) by number: their names and what they hold.

One row per range: (first, last, name, detail).  In a name, ``{axis}`` becomes the axis of
a six-number range (X..C), ``{n}`` the position in the range counted from 1 (the tool
number of the tool table).  Which numbers are read-only comes from ``tables.py``.
"""
from __future__ import annotations

from edingcnc_lang.machine.tables import RESERVED_PARAMS

Row = tuple[int, int, str, str]

ROWS: tuple[Row, ...] = (
    (1, 26, "M-code sub argument {letter}",
     "In a Sub mNNN, the letter words of the calling line (A = #1 ... Z = #26); an absent letter reads -1e10."),
    (27, 3999, "user variable", "Volatile: starts at 0 in each run."),
    (4000, 4999, "persistent user variable", "Stored in cnc.ini [VARIABLES]: kept from run to run."),
    (5001, 5006, "work position {axis}", "Current position in the active work coordinates."),
    (5008, 5008, "current tool", "The tool in the spindle."),
    (5009, 5009, "tool radius", "Radius of the current tool."),
    (5010, 5010, "tool Z offset", "Z offset of the current tool: length + zDelta (set at M6 and G43)."),
    (5011, 5011, "new tool", "During M6 / change_tool: the tool asked for."),
    (5012, 5012, "tool X offset", "Lathe: X offset of the current tool, width + xDelta as the tool table keeps it "
     "(a diameter value on a diameter lathe; set at M6 and G43)."),
    (5013, 5013, "G43 Z offset", "The length offset applied by G43."),
    (5014, 5014, "G43 X offset", "Lathe: the X offset G43 applies, a radius (half the table's value on a diameter lathe)."),
    (5015, 5015, "tool change succeeded", "change_tool sets it to 1 when the change worked."),
    (5016, 5050, "macro scratch", "Free for the tool change and stock macros."),
    (5051, 5056, "probe position {axis}, machine", "Where the last G38.2 tripped, machine coordinates."),
    (5061, 5066, "probe position {axis}, work", "Where the last G38.2 tripped, work coordinates."),
    (5067, 5067, "probe tripped", "1 if the last G38.2 touched, 0 if it reached its target without contact."),
    (5068, 5068, "probe input", "The live state of the probe input."),
    (5069, 5069, "handwheel counter", "The count of the handwheel encoder."),
    (5070, 5070, "spindle speed", "The spindle speed in revolutions per second (under G96 it follows X)."),
    (5071, 5076, "machine position {axis}", "Current position in machine coordinates."),
    (5081, 5086, "probe position {axis}, joints", "Where the last G38.2 tripped, joint coordinates."),
    (5101, 5106, "negative soft limit {axis}", "From cnc.ini."),
    (5111, 5116, "positive soft limit {axis}", "From cnc.ini."),
    (5121, 5126, "home position {axis}", "From cnc.ini."),
    (5131, 5133, "tool-change area negative limit {axis}",
     "Machine coordinates, from cnc.ini [KINEMATICS] negativeLimitTCAX/Y/Z (the area TCAGuard protects)."),
    (5141, 5143, "tool-change area positive limit {axis}", "From cnc.ini [KINEMATICS] positiveLimitTCAX/Y/Z."),
    (5150, 5150, "kinematics type",
     "1 trivial, 2 A-cylinder, 3 virtual C, 4 linear delta, 5 CoreXY, 18..30 custom, 31/32 trunnion AC/BC."),
    (5151, 5151, "Z height compensation active", "1 while ZHC is on."),
    (5152, 5152, "spindle on", "1 while the spindle turns."),
    (5161, 5166, "G28 position {axis}", "Machine coordinates G28 goes to."),
    (5181, 5186, "G30 position {axis}", "Machine coordinates G30 goes to."),
    (5190, 5190, "G68 rotation active", "1 while G68 is on."),
    (5191, 5193, "G68/G51 point {axis}", "The pivot of the G68 rotation, or the centre of the G51 scaling."),
    (5194, 5194, "G68 angle XY", "The angle of a G68 rotation in the XY plane (about Z: G17 or K1)."),
    (5195, 5195, "G68 angle YZ", "The angle of a G68 rotation in the YZ plane (about X: G19 or I1)."),
    (5196, 5196, "G68 angle XZ", "The angle of a G68 rotation in the XZ plane (about Y: G18 or J1)."),
    (5200, 5200, "G51 scaling active", "1 while G51 scaling is on."),
    (5201, 5203, "G51 scaling centre {axis}", "The centre of the G51 scaling, work coordinates (Z is 0)."),
    (5204, 5206, "G51 scale factor {axis}", "The G51 factors; Z is always 1."),
    (5211, 5216, "G92 offset {axis}", "The G92 offsets."),
    (5220, 5220, "active coordinate system", "1..9: 1 = G54 ... 9 = G59.3."),
    *((5221 + 20 * k, 5226 + 20 * k, f"{name} offset {{axis}}", f"Work offset of coordinate system {k + 1}.")
      for k, name in enumerate(("G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"))),
    *((r.start, r.start, f"reserved (rotation coordinate system {k + 1})",
       "The manual reserves it for a rotation coordinate system: a macro must not use it.")
      for k, r in enumerate(RESERVED_PARAMS)),
    (5380, 5380, "simulation mode", "1 in simulation (ecnc sets it): guard probing with If [#5380 == 0]."),
    (5390, 5390, "spindle selection", "0 = M90 (the standard spindle) .. 7 = M97; kept in cnc.ini."),
    (5391, 5393, "alternate spindle offset {axis}",
     "The offsets M91 applies ([SPINDLE_1] at the start, a program may write them); kept in cnc.ini."),
    (5397, 5397, "render mode", "1 while the controller renders the job for its preview."),
    (5398, 5398, "dlgmsg result", "1 after OK, -1 after Cancel."),
    (5399, 5399, "M56/M57 result", "The input or output read by M56/M57; -1 after an M56 time-out."),
    (5401, 5499, "tool {n} length", "Tool table."),
    (5501, 5599, "tool {n} diameter", "Tool table."),
    (5601, 5699, "tool {n} X offset", "Tool table."),
    (5701, 5799, "tool {n} orientation", "Tool table."),
    (5801, 5899, "tool {n} X wear", "Tool table."),
    (5901, 5999, "tool {n} Z wear", "Tool table."),
)
