; §3.5 (p. 14): a group-1 code and a group-0 code that both use axis words on one line are an error (rs274 agrees)
; manual-error: L5 G1 and G28 both use the axis words
G0 X5
G1 X6 F100
G1 G28 X10
M30
