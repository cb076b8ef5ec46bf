; §3.6.3.2 (p. 20): start and end radii differing by more than 0.002 mm are an error, whatever the radius
; manual: arc 3000 0.002 0 feed=100
; manual-error: L7 start and end are not on one circle
G0 X1000
G2 X3000 Y0.002 I1000 J0 F100
G0 X1000 Y0
G2 X3000 Y0 I1000.0015 J0
M30
