; ecnc sim --stock 0,0,-12,40,30,0 --tools collisions.toml --tool 1 --resolution 0.25
; Fräsen ohne Rücksicht: every kind of finding, at its line (Latin-1, CRLF)
G21 G90 G17
G0 Z5
G0 X-5 Y10
G0 Z-1
G0 X45
G0 Z5
S12000 M3
G0 X10 Y20
G1 Z-4 F300
G1 X30 F1000
G1 Z-8
G1 X10
G1 Z-13
G1 X30
G0 Z5
M5
G0 X5 Y5
G1 Z-1 F300
G2 X35 Y5 I15 J0
G0 Z20
M30
