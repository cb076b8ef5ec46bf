; §3.7.10 M20..M22 THC, §3.7.11 M10/M11 laser, §3.7.5 M52/M53, §3.7.2 M91 with no [SPINDLE_1] offsets
; manual-event: laser m=11 on=True
; manual-event: laser m=10 on=False
; manual-event: thc m=21 on=True
; manual-event: thc m=22 q=120.0
; manual-event: thc m=20 on=False
; manual-event: override m=52 p=1.0
; manual-event: override m=53 p=0.0
; manual-event: m_code m=91
M11
M10
M21
M22 Q120
M20
M52 P1
M53 P0
M91
M30
