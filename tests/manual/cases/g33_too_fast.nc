; §3.6.9 (p. 24): an error if the spindle speed makes the move exceed the machine's velocity limits
; ini: slow_mill.ini
; manual: linear 0 0 -10 feed=6000 sync=2
; manual-error: L8 more than its maximum velocity of 7200 mm/min
M3 S3000
G33 Z-10 K2
G0 Z0
G33 Z-10 K10
M30
