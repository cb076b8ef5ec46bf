; §3.6.16 G64 P .. R .. S .. D ..: the look-ahead words; S is the second angle, not a spindle speed
; manual-event: path_control mode=G64 p=0.1 r=6 s=100 d=0.002
; manual-event: path_control mode=G64 p=0.1 f=1
; manual: linear 10 0 0 feed=1200 spindle=18000
G90 G21
G64 P0.1 R6 S100 D0.002
M3 S18000
G1 X1 F1200
G64 P0.1 F1
G1 X10
M30
