; §3.6.20.11 G88: feed to Z, dwell, spindle stop, a stop for the operator, spindle on; no retract move
; manual: linear 0 0 -10 feed=100
; manual-event: dwell seconds=0.5
; manual-event: spindle m=5
; manual-event: pause m=0 cycle=G88
; manual-event: spindle m=3
M3 S800
G0 X0 Y0 Z5
G98 G88 X0 Y0 Z-10 R1 P0.5 F100
M30
