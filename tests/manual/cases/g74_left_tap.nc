; §3.6.20.7 G74: left-hand tapping, F per revolution, the spindle reversed at the bottom
; manual: linear 0 0 -8 feed=625 sync=1.25
; manual-event: spindle m=3
; manual: linear 0 0 2 feed=625 sync=1.25
; manual-event: spindle m=4
M4 S500
G0 X0 Y0 Z10
G99 G74 X0 Y0 Z-8 R2 F1.25
M30
