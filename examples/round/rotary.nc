; rotary.nc -- a 40 mm bar on the A axis of examples/cylinder/cnc.ini (its rotation point is machine
; Y200 Z-60: G54 is put there, so the bar's axis is work Y0 Z0): two cuts along the bar indexed 180 degrees
; apart (slots: the ini's T1 is a small cutter), a ring groove by turning A through 360 degrees, and a wrapped helix.
; ecnc sim --ini examples/cylinder/cnc.ini examples/round/rotary.nc --stock cylinder:40,100,20 -o rotary.png
G17 G21 G90 G94
G10 L2 P1 X0 Y200 Z-60 A0
G54
M6 T1
S12000 M3
G0 Z30
G0 X10 Y0 A0
G0 Z22
G1 Z17 F800        ; a slot 3 mm deep along the bar
G1 X75
G0 Z30
G0 X10 A180       ; indexed: the far side
G1 Z18
G1 X75
G0 Z30
G0 X90 A0
G1 Z18 F300        ; a ring groove 2 mm deep
G1 A360 F3000
G0 Z30
G0 X80 A0
G1 Z19 F300        ; a wrapped helix, one turn over 30 mm
G1 X110 A360 F1500
G0 Z30
M5
M30
