; lint-ini: lathe_spindle.ini
G18 G0 X20 Z2
G97 S4000 M3 ; expect: G521
S50 ; expect: G521
S1500
G96 S80 D3500 ; expect: G521
S200
G97 S900
G76 P1.5 Z-20 I-2 J0.2 K0.92 ; expect: G520
G76 P1.5 Z-20 I12 J0.2 K0.92
M30
