; §3.6.20.2 G81, second example: from (1, 2, 3), G91 G81 G98 X4 Y5 Z-0.6 R1.8 L3
; manual: rapid 1 2 4.8
; manual: rapid 5 7 4.8
; manual: linear 5 7 4.2
; manual: rapid 5 7 4.8
; manual: rapid 9 12 4.8
; manual: linear 9 12 4.2
; manual: rapid 9 12 4.8
; manual: rapid 13 17 4.8
; manual: linear 13 17 4.2
; manual: rapid 13 17 4.8
G0 X1 Y2 Z3
G91 G81 G98 X4 Y5 Z-0.6 R1.8 L3 F100
M30
