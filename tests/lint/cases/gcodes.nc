; G and M words on one line.
G17 G21 G90 G94
G0 G1 X10                ; expect: G500
G90 G91 X1               ; expect: G500
M3 M4 S1000              ; expect: G500
M3 M8 S1000
G53 G0 Z0
G0 G53 X0
G53 X10                  ; expect: G501
G53 G2 X1 Y1 R5          ; expect: G501
; probing in machine coordinates (the stock zero_z) is no G501
G53 G38.2 Z-10 F100      ; noqa: G504,G505
G7 X20                   ; expect: G509
G90.1                    ; expect: G509
G2 X10 Y0 I5 J0
G3 X0 Y0 R5
G2 I5                    ; a full circle: centre given, no end point
G2 X10 Y10               ; expect: G502
G1 X5 F0                 ; expect: G503
G1 X5 F[0]               ; expect: G503
G81 X1 Y1 Z-2 R1 F0      ; expect: G503
G0 X1 F0                 ; rapids ignore the feed
T99 M6
T100 M6                  ; expect: G506
M3 M8 M48 M54 P1
M3 M8 M48 M54 P1 M62     ; expect: G507,G510
M123                     ; expect: G510
M104 S200 M100           ; 3D printing codes (manual 3.7.12) are built-in
G7 G0 X20                ; expect: G509
G12 X1                   ; expect: G509
G96 S100 D2000 M3
G97 S500
G33 Z-1 K1
M30
