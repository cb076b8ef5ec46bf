"""Macro keywords, commands and functions: the rows behind hover, completion and help.

One row per word: (name as written, title, arguments, detail).  A command added to the
grammar gets its row here.
"""
from __future__ import annotations

Row = tuple[str, str, str, str]

KEYWORDS: tuple[Row, ...] = (
    ("Sub", "define a subroutine", "name",
     "Sub name ... EndSub. Subs cannot nest. Sub mNNN defines the M code NNN; change_tool, home_x, user_1, "
     "start ... are called by the controller."),
    ("EndSub", "end of a subroutine", "", "Returns to the caller."),
    ("GoSub", "call a subroutine", "name",
     "Looked up, ignoring case, in the file, then user_macro.cnc, then macro.cnc. Calls nest at most 64 deep."),
    ("If", "conditional block", "[condition]",
     "If [cond] ... Else ... EndIf. The condition is one bracketed expression: If [[#1 > 0] and [#2 > 0]] (G1171 otherwise)."),
    ("Else", "other branch of an If", "", ""),
    ("EndIf", "end of an If", "", ""),
    ("While", "loop", "[condition]", "While [cond] ... EndWhile: repeats while the condition is not 0."),
    ("EndWhile", "end of a While", "", ""),
)

COMMANDS: tuple[Row, ...] = (
    ("msg", "operator message", '"text" #n [expr] ...', "Shows the text (strings and values joined); does not stop."),
    ("warnmsg", "warning message", '"text" ...', "Shows a warning; the controller pauses until Cycle Start."),
    ("errmsg", "error message", '"text" ...', "Shows the text and aborts the job."),
    ("dlgmsg", "dialog", '"title" "label" number ...',
     "Up to 15 fields, each a label (at most 31 characters) and a bare variable number (no #). "
     "The fields show the current values; OK stores the entries. #5398 = 1 after OK, -1 after Cancel."),
    ("logfile", "choose the log file", "name mode", "Mode 0 starts the file afresh, 1 appends."),
    ("logmsg", "write to the log file", '"text" ...', "Appends a line to the log file."),
    ("home", "home one joint", "x|y|z|a|b|c", "Kinematics are off while homing."),
    ("homeTandem", "home a gantry pair", "x|y|z|a|b|c", "Homes a master/slave pair of joints."),
    ("homeIsEstop", "home switches as E-stop", "on|off", "No effect in simulation."),
    ("KIN", "kinematics", "ON|OFF|CTRL id p1..p6|X2A|X2XA|Y2A|Y2YA|Z2C|Z2ZC|Y2YAZ2ZC",
     "Switches the kinematics on or off, passes up to 6 values to its control function, or selects a built-in axis mapping."),
    ("tanknife", "tangential knife", "on|off", "While on, C turns to follow the XY direction of the cut."),
    ("PrepareLinDeltaHome", "delta robot homing", "[velocity]", "Moves the three delta joints up until all home switches are active."),
    ("TCAGuard", "tool change area guard", "on|off", ""),
    ("ZHC", "Z height compensation", "on|off",
     "While on (#5151 = 1) every move's Z follows the measured grid, bilinear between its points; "
     "lines are split where they cross grid cells."),
    ("ZHCINIT", "start a Z height grid", "gridSize nX nY",
     "nX by nY points gridSize apart, from the work zero; the points are then probed and added."),
    ("ZHCINITEX", "start a Z height grid (extended)", "gridSizeX gridSizeY nX nY", "As ZHCINIT with separate X and Y spacing."),
    ("ZHCADDPOINT", "add a point to the Z height grid", "",
     "Stores the last probe position's Z at the grid point nearest its XY."),
    ("ZHCS", "save the Z height grid", "file", "Writes the table as text (see docs/language.md)."),
    ("ZHCL", "load a Z height grid", "file", "Reads a table ZHCS wrote (an ecnc addition)."),
    ("ZHCcheck", "Z height grid statistics", "n", "Reports how many points are measured and their lowest, highest and mean height."),
    ("GetHeightControlVact", "torch height control: actual voltage", "N", "Writes the actual arc voltage into #N (0 in simulation)."),
    ("GetHeightControlVset", "torch height control: set voltage", "N", "Writes the set arc voltage into #N (0 in simulation)."),
    ("Service", "service command", "cmd", "Service functions of the controller (oil pump, counters); reported as an event by ecnc."),
    ("LaserEngrave", "laser engraving mode", "on|off", ""),
    ("GetToolInfo", "enumerate the tools the loaded job uses", "num|first|next N", "Writes into #N (-1 after the last tool); num counts the tools."),
    ("GetJobDistance", "job distance", "N", "Writes the job's path length into #N."),
    ("modbus", "Modbus transfer", "s.. f.. a.. ...", "Accepted and reported as an event by ecnc."),
    ("Exec", "run an external program", "command", "ecnc never runs it unless explicitly allowed."),
)

FUNCTIONS: tuple[Row, ...] = (
    ("ABS", "absolute value", "[x]", ""),
    ("ACOS", "arc cosine in degrees", "[x]", "x must lie in -1..1."),
    ("ASIN", "arc sine in degrees", "[x]", "x must lie in -1..1."),
    ("ATAN", "arc tangent in degrees", "[y]/[x] or [x]",
     "ATAN[y]/[x] is the angle of (x, y), in (-180, 180]; ATAN[x] alone is the plain arc tangent, in (-90, 90)."),
    ("COS", "cosine of degrees", "[x]", ""),
    ("EXP", "e to the power x", "[x]", ""),
    ("FIX", "round down", "[x]", "Towards minus infinity."),
    ("FUP", "round up", "[x]", "Towards plus infinity."),
    ("LN", "natural logarithm", "[x]", "x must be above 0."),
    ("ROUND", "round to nearest", "[x]", "Halves away from zero."),
    ("SIN", "sine of degrees", "[x]", ""),
    ("SQRT", "square root", "[x]", "x must not be negative."),
    ("TAN", "tangent of degrees", "[x]", ""),
)
