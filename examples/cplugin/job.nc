; cplugin/job.nc -- a CoreXY machine driven by a kinematics plug-in compiled from C
; README: build the plug-in first, then run the job:
;   ecnc kins build examples/cplugin/mycorexy.c
;   ecnc run --ini examples/cplugin/cnc.ini examples/cplugin/job.nc --json
; The ini names the plug-in "mycorexy.dll"; on Linux the loader finds mycorexy.so beside the ini.
G17 G21 G90 G94
KIN ON                      ; the belts now move together: motor X = x + y, motor Y = x - y
G0 X20 Y20 Z-5
G1 X120 F2400               ; a square with round corners
G3 X130 Y30 R10
G1 Y80
G3 X120 Y90 R10
G1 X20
G3 X10 Y80 R10
G1 Y30
G3 X20 Y20 R10
G0 Z0
; #1000.. are written by the kinematics (userOutputStartVariable in cnc.ini)
msg "belt motors at X" #1000 " Y" #1001  ; noqa: V302
