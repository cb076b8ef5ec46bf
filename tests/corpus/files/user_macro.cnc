;@unit mm
; user_macro.cnc of a router with two spindles and a plasma torch
Sub user_3 ; spindle 2 for the small cutter
    M91
    If [#5390 <> 1]
        errmsg "spindle select failed"
    EndIf
    M3 S18000
    G4 P0.5
    M5
    M90
EndSub

Sub user_4 ; torch height control readout
    GetHeightControlVact 130
    GetHeightControlVset 131
    msg "THC actual " #130 " V, set " #131 " V"
    Service oilpump
EndSub

Sub user_5 ; rotary axis clamp around an index move
    M27
    G0 A90
    M26
    G0 X10
    M27
EndSub
