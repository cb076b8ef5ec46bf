; §3.6.5 G10 L2 P1 X3.5 Y17.2 sets the origin of G54; P must be 1..9
; manual: rapid 3.5 17.2 0
; manual-error: L7 G10 L2 needs a coordinate system P1..P9
G10 L2 P1 X3.5 Y17.2
G54 G0 X0 Y0
G10 L2 P9 Z1
G10 L2 P0 X1
M30
