;@unit mm
; In an M-code sub, #1..#26 hold the letters of the calling line until another M-code sub runs.
Sub m101
    #27 = #24                ; X of the calling line, copied before any call
    M102 X5
    G0 X[#24]                ; expect: V303
    G0 X[#27]
    #24 = 3
    G0 X[#24]                ; assigned again after the call: fine
    G0 Y[#25]                ; expect: V303
EndSub

Sub m102
    G0 X[#24]
EndSub

Sub m103
    If [#1 > 0]
        GoSub plain          ; does not touch #1..#26
        GoSub calls_m102     ; may overwrite them
    Else
        G0 X[#1]             ; the other branch: the call did not run
    EndIf
    G0 X[#2]                 ; expect: V303
EndSub

Sub m3                       ; a redefined M3: M3 inside it is the built-in, not a call
    M3
    G0 X[#19]
EndSub

Sub plain
    G0 Z5
EndSub

Sub calls_m102
    M102 X1
EndSub
