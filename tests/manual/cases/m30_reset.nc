; §3.7.1 M30: G17 G90 G94 M48 G40 M5 G1 M9, the coordinate system kept; M104 heaters off (3.7.12)
; manual-event: override m=48
; manual-event: coolant m=9
; manual-event: printer m=30 off=True
; manual-event: end m=30
G19 G91 G95 G55
M3 S100 M8
M104 S200
M30
