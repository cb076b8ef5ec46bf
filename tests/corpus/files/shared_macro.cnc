;@unit mm
; macro.cnc as shared on the forum: zero_z, ZHC grid, job info
; (ZHCcheck and %d as published)

Sub zero_z
    G53 G38.2 Z-50 F100
    If [#5067 == 1]
        G10 L20 P[#5220] Z[#4506]
        msg "Z zero set at " %d
    Else
        warnmsg "no touch"
    EndIf
    G0 Z10
EndSub

Sub zhcmgrid
    #4100 = 4      ; nx
    #4101 = 3      ; ny
    #4102 = 5      ; upper Z
    #4103 = -5     ; probe depth
    #4104 = 20     ; grid size
    #4105 = 200    ; probe feed
    dlgmsg "ZHC grid" "points X" 4100 "points Y" 4101 "grid size" 4104
    If [#5398 == 1]
        G0 Z[#4102]
        G0 X0 Y0
        ZHCINIT [#4104] [#4100] [#4101]
        #111 = 0
        #114 = 1
        While [#111 < #4101]
            If [#114 == 1]
                #110 = 0
                While [#110 < #4100]
                    G0 Z[#4102]
                    G0 X[#110 * #4104] Y[#111 * #4104]
                    G38.2 F[#4105] Z[#4103]
                    If [#5067 == 1]
                        ZHCADDPOINT
                    EndIf
                    #110 = [#110 + 1]
                EndWhile
                #114 = 0
            Else
                #110 = [#4100 - 1]
                While [#110 > -1]
                    G0 Z[#4102]
                    G0 X[#110 * #4104] Y[#111 * #4104]
                    G38.2 F[#4105] Z[#4103]
                    If [#5067 == 1]
                        ZHCADDPOINT
                    EndIf
                    #110 = [#110 - 1]
                EndWhile
                #114 = 1
            EndIf
            #111 = [#111 + 1]
        EndWhile
        G0 Z[#4102]
        ZHCS zHeightCompTable.txt
        msg "Done " %d
        ZHCcheck 20
    Else
        msg "Operation canceled"
    EndIf
EndSub

Sub engrave_on_surface
    GoSub zhcmgrid
    ZHC on
    If [#5151 <> 1]
        errmsg "ZHC did not switch on"
    EndIf
    G0 X5 Y5
    G1 Z-0.2 F300
    G1 X55
    G1 Y35
    G0 Z5
    ZHC off
EndSub

Sub job_info
    GetJobDistance 120
    logfile "jobinfo.txt" 1
    logmsg %d " distance " #120
EndSub
