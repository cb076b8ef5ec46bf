; §3.6.10.1 G38.2: a target closer than 0.254 mm is an error
; manual-error: L4 G38.2 target is 0.1000 mm away
G0 Z10
G38.2 Z9.9 F100
M30
