; rotate/job.nc -- the virtual C axis (rotatekins): C turns the XY plane about the point
; where KIN ON was given, so one square drawn at C = 0, 30, 60 and 90 comes out rotated.
; README: ecnc run --ini examples/rotate/cnc.ini examples/rotate/job.nc --json --samples rotate.csv
G17 G21 G90 G94
G0 X300 Y200 Z-10
KIN ON                      ; rotation point: X300 Y200 (#1000, #1001 show it)
#1 = 0
While [#1 < 120]
  G0 X300 Y200 C#1
  G1 X340 F1200
  G1 Y240
  G1 X300
  G1 Y200
  #1 = [#1 + 30]
EndWhile
KIN CTRL 12 0               ; USER2: angle back to 0 (the joints stay where they are)
KIN OFF
G0 Z0
