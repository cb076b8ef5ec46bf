; parallel/job.nc -- two identical parts at once with KIN Z2ZC: the second spindle's Z motor
; (joint C) copies every Z move of the first.
; README: ecnc run --ini examples/parallel/cnc.ini examples/parallel/job.nc --trace parallel.csv
G17 G21 G90 G94
KIN Z2ZC
G0 X20 Y20
#1 = 0
While [#1 < 3]
  #1 = [#1 + 1]
  G1 Z[-2 * #1] F300        ; both spindles step down 2 mm
  G1 X80 F1000
  G1 Y40
  G1 X20
  G1 Y20
EndWhile
G0 Z0
KIN OFF
