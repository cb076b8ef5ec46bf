; Cutter compensation: arcs the compensated tool cannot fit inside.
G17 G21 G90 G94
G10 L1 P3 R2.5
G0 X-10 Y0
G41.1 D8
G1 X0 Y0 F500
G3 X8 Y0 R4              ; expect: G508
G3 X10 Y0 R5
G2 X18 Y0 R4             ; the tool is outside a clockwise arc with G41
G40
G42 D3
G1 X0 Y0
G2 X4 Y0 I2 J0           ; expect: G508
G2 X4 Y0 I[#1] J0        ; not known before the run
G3 X8 Y0 I2 J0           ; outside
G40
G42 D7
G2 X4 Y0 I2 J0           ; tool 7's radius is not known here
G40
G18
G41.1 D10
G3 X4 Z0 I2 K0           ; expect: G508
G40
M30
