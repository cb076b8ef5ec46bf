; §3.7.3 M6: when the tool change is complete, the spindle is stopped
; manual-event: spindle m=3
; manual-event: tool_change tool=1
; manual-event: spindle m=5
M3 S1000
T1 M6
M30
