; §3.7.1 M60: as M30, but the spindle and coolant stay on (nesting)
; manual-event: override m=48
; manual-event: end m=60
M3 S100 M8
M60
