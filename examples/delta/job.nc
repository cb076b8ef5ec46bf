; delta/job.nc -- a linear delta robot (deltakins): L = 250 mm arms, R = 125 mm, 200 mm travel.
; Homing runs at joint level: PrepareLinDeltaHome drives the three carriages up to their
; switches at 416.5063509 mm, home x/y/z mark them, and KIN ON finds the effector at (0, 0, 200).
; README: ecnc run --ini examples/delta/cnc.ini examples/delta/job.nc --json --samples delta.npz
G17 G21 G90 G94
PrepareLinDeltaHome 40
home x
home y
home z
KIN ON
G0 Z60
G1 X40 Y0 Z20 F1500         ; down to the work
G3 X40 Y0 I-40 J0           ; a full circle of 80 mm diameter
G1 X0 Y0 Z60
G0 Z200
; #1000.. are written by the kinematics (userOutputStartVariable in cnc.ini)
msg "carriages at " #1000 " " #1001 " " #1002  ; noqa: V302
