; §3.6.20.10 G87, steps 2..13: offset I J, oriented stop, down, centre, start, up to K, back down, stop, out
; manual: rapid 13 0 2
; manual-event: spindle m=5
; manual: rapid 13 0 -20
; manual: rapid 10 0 -20
; manual-event: spindle m=3
; manual: linear 10 0 -12 feed=100
; manual: linear 10 0 -20 feed=100
; manual-event: spindle m=5
; manual: rapid 13 0 -20
; manual: rapid 13 0 5
; manual: rapid 10 0 5
; manual-event: spindle m=3
M3 S800
G0 X0 Y0 Z5
G98 G87 X10 Y0 Z-20 R2 I3 J0 K-12 F100
M30
