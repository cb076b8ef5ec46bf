"""What each G and M code does and which words it takes: the rows behind hover, completion and help.

One row per code: (number, title, words, detail).  The modal group is not repeated here:
it comes from ``tables.G_GROUPS``/``M_GROUPS``, the tables the interpreter and linter use.
To document a new code, add a row; nothing else changes.
"""
from __future__ import annotations

Row = tuple[float, str, str, str]

G_ROWS: tuple[Row, ...] = (
    (0, "rapid move", "X Y Z A B C",
     "Moves to the end point at the machine's rapid speed (no cutting). Stays in force for later lines with axis words."),
    (1, "straight feed move", "X Y Z A B C F",
     "Moves in a straight line at the feed F (F must not be 0: EdingCNC G1516)."),
    (2, "clockwise arc", "X Y Z A B C I J K R F",
     "Arc in the active plane: centre by I J K (incremental unless absoluteCenterCoords = 1) or radius R "
     "(negative for more than 180 degrees). Without an end point and with I/J/K: a full circle."),
    (3, "counter-clockwise arc", "X Y Z A B C I J K R F", "As G2, turning the other way."),
    (4, "dwell", "P", "Waits P seconds."),
    (10, "set coordinate system offsets", "L P X Y Z A B C",
     "L2 P1..9 sets the offsets of G54..G59.3 to the given values; L20 sets them so the current position "
     "gets the given coordinates (like G92, stored in #5221..)."),
    (17, "XY plane", "", "Arcs and canned cycles work in the XY plane (the default)."),
    (18, "XZ plane", "", "Arcs and canned cycles work in the XZ plane."),
    (19, "YZ plane", "", "Arcs and canned cycles work in the YZ plane."),
    (20, "inch units", "", "Coordinates and feeds in inches. Takes effect after F on the same line: put it on a line of its own."),
    (21, "millimetre units", "", "Coordinates and feeds in millimetres."),
    (28, "go to the G28 position", "X Y Z A B C",
     "Rapid to the position stored in #5161..#5166 (machine coordinates), through the point on the line if any; "
     "with axis words only those axes move. Z moves first when it goes up; on a lathe X moves first."),
    (30, "go to the G30 position", "X Y Z A B C", "As G28, with the position in #5181..#5186."),
    (33, "spindle-synchronised threading", "X Y Z K",
     "A straight move advancing K (the pitch) per spindle revolution; needs the spindle turning. K stays in force."),
    (33.1, "rigid tapping", "X Y Z K",
     "Synchronised move to the end point at pitch K, the spindle reverses, back to the start, the spindle turns back."),
    (38.2, "straight probe", "X Y Z F",
     "Moves towards the target until the probe trips. Results: #5067 = 1 if it tripped, the position in "
     "#5061..#5066 (work) and #5051..#5056 (machine); then the probe backs off 0.254 mm. No contact even slightly past the target is a run error. Guard it with If [#5397 == 0] (not while rendering) or If [[#5380 == 0] and [#5397 == 0]]."),
    (40, "cutter compensation off", "", "Cancels G41/G42."),
    (41, "cutter compensation left", "D", "Offsets the path to the left by the tool radius of tool D (the current tool without D)."),
    (41.1, "cutter compensation left, given diameter", "D", "As G41 with the diameter in D."),
    (42, "cutter compensation right", "D", "Offsets the path to the right by the tool radius of tool D (the current tool without D)."),
    (42.1, "cutter compensation right, given diameter", "D", "As G42 with the diameter in D."),
    (43, "tool length offset on", "H",
     "G43 alone compensates the tool in the spindle, and follows every M6; G43 H.. applies tool H's length "
     "and stays after M6 (manual 3.6.12)."),
    (43.1, "dynamic tool length offset", "I K",
     "Applies the length offset K (lathe: X offset I) given on the line; stays after M6."),
    (49, "tool length offset off", "", "Cancels G43."),
    (50, "scaling off", "", "Cancels G51."),
    (51, "scaling on", "P X Y I J", "Scales X and Y: P one factor about the centre I J (default the work "
     "zero), or X Y a factor per axis; Z is not scaled."),
    (53, "machine coordinates for this line", "",
     "Non-modal: the G0 or G1 on the same line moves in machine coordinates. Needs G0 or G1 on the line."),
    (54, "coordinate system 1", "", "Work offsets #5221..#5226."),
    (55, "coordinate system 2", "", "Work offsets #5241..#5246."),
    (56, "coordinate system 3", "", "Work offsets #5261..#5266."),
    (57, "coordinate system 4", "", "Work offsets #5281..#5286."),
    (58, "coordinate system 5", "", "Work offsets #5301..#5306."),
    (59, "coordinate system 6", "", "Work offsets #5321..#5326."),
    (59.1, "coordinate system 7", "", "Work offsets #5341..#5346."),
    (59.2, "coordinate system 8", "", "Work offsets #5361..#5366."),
    (59.3, "coordinate system 9", "", "Work offsets #5381..#5386."),
    (61, "exact path", "", "Path control: follow the programmed path exactly."),
    (61.1, "exact stop", "", "Path control: stop at the end of each move."),
    (64, "continuous path", "P Q R S D F",
     "Path control: blend moves. P the rounding tolerance, Q the line-merge tolerance, R the look-ahead angle, "
     "S the second angle and D the corner deviation (V4.03), F the ramp filter. On a G64 line these letters are "
     "G64's: S is not a spindle speed and F not a feed (manual 3.6.16)."),
    (68, "rotate the coordinate system", "X Y Z I J K R",
     "Rotates by R degrees counter-clockwise about the pivot X Y Z (default the work zero): in the active "
     "plane, or about X (I1: YZ plane), Y (J1: XZ) or Z (K1: XY), one of them. Angle in #5194 (XY), #5195 (YZ) "
     "or #5196 (XZ)."),
    (69, "rotation off", "", "Cancels G68."),
    (70, "inch units (alias of G20)", "", "As G20."),
    (71, "millimetre units (alias of G21)", "", "As G21."),
    (73, "high-speed peck drilling cycle", "X Y Z R Q L F",
     "Pecks of depth Q, retracting 0.254 mm between pecks. Z, R and Q stay in force for later lines."),
    (74, "left-hand tapping cycle", "X Y Z R L F",
     "Rigid tapping: F is the pitch per spindle revolution (M4 S600 F1: 600 mm/min), synchronised; the spindle "
     "reverses at the bottom to feed out to the clear level, then turns back. Needs the spindle turning."),
    (76, "threading cycle", "P Z I J K R Q H E L",
     "Multi-pass thread from the current position to Z: P pitch, I the crest diameter (absolute, always "
     "positive; a start outside it cuts an outside thread, inside it an inside thread), J first cut and "
     "K thread depth beyond the crest (radial), R degression, Q compound angle, H spring passes, E/L taper. "
     "XZ plane (G18). Lathe only (machineType = 1 or 2)."),
    (80, "cancel canned cycle", "", "Ends the active canned cycle; axis words alone no longer drill."),
    (81, "drilling cycle", "X Y Z R L F", "Rapid to R, feed to Z, rapid out (to the start Z with G98, to R with G99). L repeats."),
    (82, "drilling cycle with dwell", "X Y Z R P L F", "As G81 with a dwell of P seconds at the bottom."),
    (83, "peck drilling cycle", "X Y Z R Q L F", "Pecks of depth Q, retracting to R after each one."),
    (84, "right-hand tapping cycle", "X Y Z R L F",
     "Rigid tapping: F is the pitch per spindle revolution (M3 S600 F1: 600 mm/min), synchronised; the spindle "
     "reverses at the bottom to feed out to the clear level, then turns back. Needs the spindle turning."),
    (85, "boring cycle, feed out", "X Y Z R L F", "Feed to Z and feed back out to R."),
    (86, "boring cycle, spindle stop, rapid out", "X Y Z R P L F",
     "Feed to Z, dwell P, stop the spindle, rapid out, restart the spindle. Needs the spindle turning."),
    (87, "back boring cycle", "X Y Z R I J K L F",
     "Shifts by I J past the bar, stops the spindle, goes below the part, centres, bores up to K and back, "
     "stops, shifts, retracts, centres, restarts. Needs the spindle turning."),
    (88, "boring cycle, spindle stop, manual out", "X Y Z R P L F",
     "Feed to Z, dwell P, stop the spindle, stop the program for the operator to retract by hand, restart "
     "the spindle. Needs the spindle turning."),
    (89, "boring cycle, dwell, feed out", "X Y Z R P L F", "Feed to Z, dwell P, feed back out."),
    (90, "absolute distances", "", "Axis words are positions in the active coordinate system."),
    (91, "incremental distances", "", "Axis words are distances from the current position."),
    (92, "coordinate offset", "X Y Z A B C", "Shifts coordinates so the current position gets the given values (stored in #5211..#5216; they add up)."),
    (92.1, "clear G92 offsets", "", "Cancels and zeroes the G92 offsets."),
    (92.2, "suspend G92 offsets", "", "Cancels the G92 offsets but keeps #5211..#5216."),
    (92.3, "restore G92 offsets", "", "Applies the offsets kept in #5211..#5216 again."),
    (93, "inverse time feed", "", "F is 1/minutes for each move: every G1/G2/G3 line needs its own F."),
    (94, "units per minute feed", "", "F is mm (or inch) per minute (the default)."),
    (95, "units per revolution feed", "", "F is mm (or inch) per spindle revolution."),
    (96, "constant surface speed", "S D",
     "S is the surface speed (m/min, ft/min in G20): the spindle speed follows the X radius, at most D rpm "
     "(and cnc.ini's spindleNmax). Lathe only (machineType = 1)."),
    (97, "spindle speed in rpm", "S", "S is the spindle speed in rpm (the default); without S the current speed is kept."),
    (98, "canned cycle returns to the start Z", "", "Retract to the Z the cycle started from."),
    (99, "canned cycle returns to R", "", "Retract to the R plane."),
)

M_ROWS: tuple[Row, ...] = (
    (0, "program pause", "", "Pauses until Cycle Start."),
    (1, "optional pause", "", "Pauses when optional stop is on."),
    (2, "end of program", "", "Ends the program."),
    (3, "spindle on, clockwise", "S", "Starts the spindle at speed S (S must not be negative)."),
    (4, "spindle on, counter-clockwise", "S", "As M3, turning the other way."),
    (5, "spindle off", "", "Stops the spindle."),
    (6, "tool change", "T",
     "Calls Sub change_tool with #5011 = the new tool; inside change_tool, M6 T.. commits the tool (#5008). "
     "Afterwards the spindle is stopped (manual 3.7.3) and a plain G43 applies the new tool's length."),
    (7, "mist coolant on", "", ""),
    (8, "flood coolant on", "", ""),
    (9, "coolant off", "", "Mist and flood off."),
    (10, "laser off", "", "Laser mode (CNC7 CPUs): switches the laser off; under LaserEngrave on it switches "
     "exactly where the move on its line is."),
    (11, "laser on", "", "Laser mode: switches the laser on (see M10)."),
    (20, "torch height control off", "", "Plasma: the torch height control (THC) off."),
    (21, "torch height control on", "", "Plasma: the torch height control on."),
    (22, "torch height control set voltage", "Q", "Plasma: Q is the THC's set voltage."),
    (23, "torch height control", "Q", "Reported as an event by ecnc (the 4.03 manual lists M20..M22)."),
    (26, "axis clamp on", "P", "Clamps the rotary axes: a move that turns A, B or C is refused until M27; "
     "P1 switches AUX1 (the brake) on."),
    (27, "axis clamp off", "P", "Releases the rotary axes clamped by M26; P1 switches AUX1 off."),
    (30, "end of program and reset", "",
     "Ends the program and resets G17 G90 G94 G40 M5 M9 and the motion mode; the coordinate system is kept."),
    (48, "overrides enabled", "", "Feed and speed overrides on, the feed override back at the knob's value."),
    (49, "overrides disabled", "", "Feed and speed overrides off (100 %)."),
    (50, "feed override control", "P",
     "Sets the feed override to P percent; P0 waits for the operator's knob; a negative P switches it off."),
    (51, "spindle override control", "P",
     "Sets the spindle speed override to P percent; P0 waits for the operator; a negative P switches it off."),
    (52, "feed override from the analog input", "P", "M52 (P1) on, M52 P0 off; reported as an event by ecnc."),
    (53, "feed hold input", "P", "M53 (P1) enables the feed hold input, M53 P0 disables it; reported as an event."),
    (54, "set output", "P E Q", "Sets output P; M54 E<n> Q<0..1000> sets a PWM output."),
    (55, "clear output", "P", "Clears output P."),
    (56, "read input", "P L Q", "Reads input P into #5399; L1/L2 wait for high/low, Q is the timeout in seconds (-1 on timeout)."),
    (57, "read output", "P E", "Reads the state of output P (1/0: AUX1..n, 61 flood, 62 mist, 63 spindle on, "
     "64 its direction), or the value of PWM output E (0..1000), into #5399."),
    (60, "program end (nesting)", "", "Ends the program like M30."),
    (80, "drives on", "", "Kept as state by ecnc."),
    (81, "drives off", "", "Kept as state by ecnc."),
    (90, "standard spindle", "", "Selects the standard spindle: #5390 = 0."),
    (91, "alternate spindle 1", "", "Selects alternate spindle 1: #5390 = 1; the xOffset yOffset zOffset of [SPINDLE_1] "
     "move the controlled point."),
    (92, "alternate spindle 2", "", "Selects alternate spindle 2: #5390 = 2; the xOffset yOffset zOffset of [SPINDLE_2] "
     "move the controlled point."),
    (93, "alternate spindle 3", "", "Selects alternate spindle 3: #5390 = 3; the xOffset yOffset zOffset of [SPINDLE_3] "
     "move the controlled point."),
    (94, "alternate spindle 4", "", "Selects alternate spindle 4: #5390 = 4."),
    (95, "touch probe", "", "Selects the mounted touch probe: #5390 = 5; the offsets of [SPINDLE_3] apply."),
    (96, "alternate spindle 6", "", "Selects alternate spindle 6: #5390 = 6."),
    (97, "camera", "", "Selects the mounted camera: #5390 = 7; the offsets of [SPINDLE_4] apply."),
    (100, "axis resolution factor", "P",
     "3D printing: changes the axis resolution by factor P on the fly (1 the standard); a Sub m100 overrides it."),
    (104, "extruder temperature", "S", "3D printing: S is the extruder temperature in degrees C (not a spindle speed)."),
    (106, "part cooling fan on", "S", "3D printing: the fan on, S 0..255 for 0..100 % (default 255); not a spindle speed."),
    (107, "part cooling fan off", "", "3D printing: the fan off."),
    (109, "extruder temperature, wait", "S", "As M104, waiting until it is reached."),
    (140, "bed temperature", "S", "3D printing: S is the bed temperature in degrees C."),
    (143, "maximum extruder temperature", "S", "3D printing: S is the highest hot-end temperature allowed."),
    (190, "bed temperature, wait", "S", "As M140, waiting until it is reached."),
)
