; cylinder/job.nc -- engraving around a 50 mm bar on the A axis with KIN Y2A: the job is written in
; the flat XY plane; Y is wrapped onto the cylinder (A = Y * 180 / (pi * 25) degrees) about the
; calibrated rotation point (aAxisCalibratedRotationPointY = 200 in cnc.ini).
; README: ecnc run --ini examples/cylinder/cnc.ini examples/cylinder/job.nc --json
G17 G21 G90 G94
G0 X50 Y200 Z-30            ; above the bar, on its axis line
KIN Y2A
G1 Z-36 F300
G1 X150 Y39.27 F1200        ; a helix-like groove: 39.27 mm of surface = 90 degrees of A
G1 Y78.54                   ; another quarter turn
G0 Z-30
KIN OFF
