; §3.6.17 G68: I1 about X (YZ plane), J1 about Y (XZ), K1 about Z (XY); without them the active plane
; manual-event: rotation on=True angle=90.0 plane=YZ
; manual: rapid 0 0 10
; manual-event: rotation on=True angle=90.0 plane=XZ
; manual: rapid 10 0 0
; manual-event: rotation on=True angle=90.0 plane=XY
; manual: rapid 0 10 0
; manual-event: rotation on=True angle=90.0 plane=YZ
; manual: rapid 0 0 10
G68 I1 R90
G0 Y10 Z0
G69
G68 J1 R90
G0 X0 Y0 Z10
G69
G68 K1 R90
G0 X10 Y0 Z0
G69
G19 G68 R90
G0 X0 Y10 Z0
M30
