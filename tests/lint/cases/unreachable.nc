; Code after an unconditional end in the same block never runs.
#27 = 1
GoSub after_the_end
If [#27 == 1]
    errmsg "stop here"
    G0 X1                ; expect: S209
    G0 X2
EndIf
If [#27 == 2]
    M30                  ; the end of its own block: nothing after it there
Else
    G0 X3
EndIf
/M30                     ; block delete may skip it, so it is not unconditional
G0 X4
G0 X5 M2
G0 X6                    ; expect: S209

Sub after_the_end        ; subs after the end are definitions, not dead code
    G0 Z1
EndSub
