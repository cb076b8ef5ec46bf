; §3.6.20.2 G81, first example: from (1, 2, 3) in G17, G90 G81 G98 X4 Y5 Z1.5 R2.8
; manual: rapid 4 5 3
; manual: rapid 4 5 2.8
; manual: linear 4 5 1.5
; manual: rapid 4 5 3
G0 X1 Y2 Z3
G90 G81 G98 X4 Y5 Z1.5 R2.8 F100
M30
