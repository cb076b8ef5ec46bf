; §3.6.11 (p. 27): cutter compensation on a mill only in the XY plane ("zum Drehen ist die ZX-Ebene")
; manual-error: L4 cutter compensation works in the XY plane (G17) on a mill, not in YZ
G19
G41.1 D4
G1 Y0 Z0 F100
M30
