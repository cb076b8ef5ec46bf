;@unit mm
; G38.2 belongs under the simulation guard.  A check of #5067 after it is not asked for (the
; retired G505): a probe that does not touch is a run error, so the check never sees 0.
Sub user_1
    If [[#5380 == 0] and [#5397 == 0]]
        G38.2 Z-10 F100
        If [#5067 <> 1]
            errmsg "no contact"
        EndIf
    EndIf
EndSub

Sub user_2
    G38.2 Z-10 F100          ; expect: G504
    If [#5067 == 0]
        errmsg "no contact"
    EndIf
EndSub

Sub user_3
    If [#5380 == 0]          ; checking #5380 alone is enough
        G38.2 Z-10 F100      ; no #5067 check: nothing to report
    EndIf
EndSub

Sub user_4
    If [#5380 == 1]          ; the simulation branch ends the run ...
        errmsg "probing needs the real machine"
    EndIf
    G38.2 Z-10 F100          ; ... so this is guarded
    GoSub check_contact      ; a sub that reads #5067 counts as the check
EndSub

Sub user_5
    If [#5380 <> 0]
        msg "simulation: skipped"
    Else
        GoSub touch          ; touch only runs from guarded code
    EndIf
EndSub

Sub touch
    G38.2 Z-5 F50            ; two probes in a row: nothing to report
    G38.2 Z-6 F50
    If [#5067 <> 1]
        errmsg "no contact"
    EndIf
EndSub

Sub user_6
    GoSub touch_anywhere
    If [[#5380 == 0] and [#5397 == 0]]
        GoSub touch_anywhere
    EndIf
EndSub

Sub touch_anywhere
    G38.2 X10 F0             ; expect: G504, G503
    If [#5067 <> 1]
        errmsg "no contact"
    EndIf
EndSub

Sub check_contact
    If [#5067 <> 1]
        errmsg "no contact"
    EndIf
EndSub

; The render-mode guard (#5397, the job's preview) is enough: the Sorotec macro guards its probes with it
; alone, as its simulation may probe for testing.
Sub user_7
    If [#5397 == 0]          ; not while rendering
        G38.2 Z-10 F100
    EndIf
    If [[#5398 == 1] AND [#5397 == 0]]
        G38.2 Z-11 F100
    EndIf
    If [#5397 <> 0]
        msg "rendering: skipped"
    Else
        G38.2 Z-12 F100
    EndIf
    If [#5398 == 1]          ; a dialog's answer guards nothing
        G38.2 Z-13 F100      ; expect: G504
    EndIf
EndSub

Sub user_8
    If [#5397 == 1]          ; the rendering branch ends the run ...
        errmsg "not while rendering"
    EndIf
    G38.2 Z-10 F100          ; ... so this is guarded
EndSub
