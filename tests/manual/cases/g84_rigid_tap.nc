; §3.6.20.6 G84: with M3 S600, F1 feeds 600 mm/min, synchronised; M4 at the bottom, out at the feed
; manual: linear 0 0 -10 feed=600 sync=1
; manual-event: spindle m=4
; manual: linear 0 0 5 feed=600 sync=1
; manual-event: spindle m=3
M3 S600
G0 X0 Y0 Z5
G98 G84 X0 Y0 Z-10 R1 F1
M30
