; §3.6.20.6 G84 without a turning spindle: F per revolution means nothing
; manual-error: L4 G84 needs the spindle turning
G0 Z5
G84 X0 Y0 Z-5 R1 F1
M30
