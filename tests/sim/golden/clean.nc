; ecnc sim --stock 0,0,-10,60,40,0 --tools clean.toml --tool 2 --resolution 0.2
; a ball-end pass with arcs and a helix entry, then a V-bit engraving: nothing to report
G21 G90 G17
S15000 M3
G0 Z5
G0 X20 Y20
G1 Z0 F300
G2 X20 Y20 Z-3 I5 J0 L3
G1 X40 F1200
G3 X40 Y30 I0 J5
G1 X20
G0 Z5
M5
T3 M6
S18000 M3
G0 X10 Y5
G1 Z-0.5 F200
G1 X50 Y8
G0 Z5
M30
