; §3.6.12 A: plain G43 always compensates the tool in the spindle; B (G43 H) stays after M6 T
; manual: rapid 0 0 10
; manual: rapid 0 0 25
; manual: rapid 0 0 25
; manual: rapid 0 0 25
#5401 = 10
#5402 = 25
T1 M6
G43
G0 Z0
T2 M6
G0 Z0
G43 H2
T1 M6
G0 Z0
G43.1 K25
T2 M6
G0 Z0
M30
