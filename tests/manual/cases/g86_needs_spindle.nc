; §3.6.20.9 G86: "Es ist ein Fehler, wenn sich die Spindel nicht dreht"
; manual-error: L4 G86 needs the spindle turning
G0 Z5
G86 X0 Y0 Z-5 R1 P1 F100
M30
