; §3.7.5 M48..M51 (p. 61): M51 P50 turns 1000 rpm into 500 (the feed per revolution follows); M50 P0 waits for the operator
; manual-event: override m=50 p=50.0
; manual-event: spindle_speed rpm=1000
; manual: linear 10 0 0 feed=50 spindle=500
; manual-event: operator_wait m=50 override=feed
; manual-event: override m=50 p=0.0
; manual: linear 20 0 0 feed=500
; manual-event: override m=49
; manual: linear 30 0 0 spindle=1000
M50 P50
M3 S1000
M51 P50
G95 G1 X10 F0.1
G94
M48
M50 P0
G1 X20 F500
M49
X30
M30
