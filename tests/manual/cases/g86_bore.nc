; §3.6.20.9 G86: feed to Z, dwell P, spindle stop, rapid out, spindle restarted
; manual: linear 0 0 -5 feed=100
; manual-event: dwell seconds=1.5
; manual-event: spindle m=5
; manual: rapid 0 0 5
; manual-event: spindle m=3
M3 S1000
G0 X0 Y0 Z5
G98 G86 X0 Y0 Z-5 R1 P1.5 F100
M30
