;* @unit mm
; A hand-written macro file in the style found on real machines: nothing to report.

#4100 = 0                           ; top-level statements run when the file is loaded

Sub home_all
    home z
    home x
    homeTandem y
    msg "homed"
EndSub

Sub change_tool
    #5015 = 0
    If [#5011 == #5008]
        #5015 = 1
    Else
        M5 M9
        G53 G0 Z0
        If [[#5380 == 0] and [#5397 == 0]]
            warnmsg "Put in T"#5011", then press Start"
            GoSub tool_length
        EndIf
        #5015 = 1
        M6 T[#5011]
    EndIf
EndSub

Sub tool_length
    G53 G0 X[#4010] Y[#4011]
    G38.2 G91 Z-[#4013] F[#4001]
    G90
    If [#5067 <> 1]
        errmsg "tool setter not reached"
    EndIf
    #[5400 + #5011] = [#5053 - #4012]
EndSub

Sub m110                            ; M110 P<n> Q<s>: wait for input n, Q seconds at most
    #50 = #16                       ; P
    #51 = #17                       ; Q
    M56 P[#50] L1 Q[#51]
    If [#5399 == -1]
        errmsg "input "#50" did not switch within "#51" s"
    EndIf
EndSub

Sub m111                            ; M111 X<x>: park, then wait
    #52 = #24
    G53 G0 Z0
    G53 G0 X[#52]
    M110 P3 Q10
    msg "parked at "#52
EndSub

Sub user_1
    dlgmsg "Park" "Park X (mm)" 4003 "Wait input" 53 "Timeout (s)" 54
    If [#5398 == 1]
        M111 X[#4003]
    EndIf
EndSub

Sub user_2
    logfile "log.txt" 1
    #55 = 0
    While [#55 < 3]
        logmsg "pass "#55
        #55 = [#55 + 1]
    EndWhile
    GetJobDistance 56
    msg "distance "#56
EndSub

Sub user_3
    KIN OFF
    tanknife off
    G10 L2 P1 X0 Y0 Z0
    G54 G17 G21 G40 G49 G80 G90 G94
    G0 X0 Y0
    G1 X10 F500
    G2 X20 Y0 R5
    G3 X10 Y0 I-5 J0
    M3 S1000 M8
    M5 M9
    KIN ON
EndSub
