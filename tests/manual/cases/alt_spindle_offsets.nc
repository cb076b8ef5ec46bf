; §3.1 (p. 4) #5391..#5393 "Alt Spindel Offset X - Z", §3.7.2 M91: a program's offsets apply to the 2nd spindle
; manual-event: msg text=offset 0
; manual: rapid 10 0 0
; manual: rapid 0 0 0
msg "offset "#5391
#5391 = 10
M91
G0 X0
M90
G0 X0
M30
