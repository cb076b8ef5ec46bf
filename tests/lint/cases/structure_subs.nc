; Subs and calls inside one job file.
GoSub drill
GoSub DRILL_ALL          ; case-insensitive: calls drill_all
GoSub missing_sub        ; expect: S208
M30

Sub drill
    G81 X0 Y0 Z-5 R2 F100
    G80
EndSub

Sub drill_all
    GoSub drill
EndSub

Sub Drill                ; expect: S207
    G0 X0
EndSub

Sub leftover             ; expect: S210
    G0 Z5
EndSub

Sub user_3               ; the controller calls user_N subs: never unused
    G0 Z10
EndSub

Sub m101                 ; M-code subs are called by M101 lines: never unused
    G0 Z10
EndSub
