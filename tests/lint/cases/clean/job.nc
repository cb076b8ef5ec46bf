%
(MSG a job that calls into the macro files beside it)
N10 G17 G21 G40 G90 G94
N20 T1 M6
N30 G43
#27 = 5
#28 = [#27 * 2]
GoSub User_2                        ; macro.cnc, names ignore case
GoSub spot                          ; user_macro.cnc
M110 P2 Q5                          ; an M-code sub from macro.cnc
If [#28 > 0]
    G0 X[#28] Y[ABS[#27]]
    G1 Z-1 F200
EndIf
/ G0 X100                           ; block delete
G0 Z10
M30
%
