(Pocket and outline for the estimate example)
G10 L2 P1 X50 Y50 Z-80 (work zero: stock top at machine Z-80)
; T1: 6 mm flat end mill - roughing the pocket (Tasche für T1, Ø 6), G64 P0.02 from the ini
T1 M6
S18000 M3
G0 X100 Y100 Z5
G1 Z-2 F600
G1 X200 F2400
Y150
X100
Y100
G1 X110 Y110
G1 X190
Y140
X110
Y110
G0 Z5
; T2: 3 mm end mill - exact corners for the outline (G61), a round corner with G2/G3
T2 M6
S20000 M3
G4 P2 (spindle up to speed)
G0 X90 Y90
G0 Z5
G1 Z-3 F400
G61
G1 X210 F1800
Y160
G3 X190 Y180 R20
G1 X110
G2 X90 Y160 R20
G1 Y90
G64
G0 Z20
M5
G0 X0 Y0
M30
