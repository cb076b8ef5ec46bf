; §3.7.12 3D printing: S of M104/M109/M140/M190/M106 is a temperature or a fan value, not the spindle speed
; manual-event: printer m=104 extruder=200.0
; manual-event: printer m=140 bed=60.0
; manual-event: printer m=106 fan=50.0
; manual: linear 10 0 0 feed=100 spindle=1000
M3 S1000
M104 S200
M140 S60
M106 S50
G1 X10 F100
M30
