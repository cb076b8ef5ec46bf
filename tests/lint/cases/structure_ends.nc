; Unmatched ends are reported where they stand.
G0 X1
EndIf                    ; expect: S200
Else                     ; expect: S201
EndWhile                 ; expect: S202
EndSub                   ; expect: S203
If [#5001 > 0]
    G0 X2
Else
    G0 X3
Else                     ; expect: S206
EndIf
While [#5001 > 5]        ; expect: S204
    G0 X4
EndIf                    ; expect: S200
