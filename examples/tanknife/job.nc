; tanknife/job.nc -- a 45 degree bend knife (tanknifeBendingAngle = 90): while the knife is in
; the Z band [tanknifeZlo, tanknifeZhi] the kinematics shift the XY motors sideways as far as
; the blade is below tanknifeZhi, so the bent tip enters the material where it is programmed.
; The band is -42 .. -40 mm here (no work offset is used, so work Z = machine Z).
; README: ecnc run --ini examples/tanknife/cnc.ini examples/tanknife/job.nc --trace tanknife.csv
G17 G21 G90 G94
G0 X50 Y50 Z-30 C0
tanknife on
G1 Z-42 F300                 ; plunge: the joints move 2 mm along C + 90 degrees
G1 X150 F1500
G0 Z-30
G0 X150 Y50 C90
G1 Z-42 F300
G1 Y120 F1500
G0 Z-30
tanknife off
