; §3.6.10.1 (p. 25): "Wenn die Sonde auslöst, wird die Sonde ... leicht vom Auslösepunkt zurückgezogen" (0.254 mm)
; manual: probe 0 0 -20 feed=100
; manual: probe 0 0 -19.746 feed=100
G0 Z10
G38.2 Z-20 F100
M30
