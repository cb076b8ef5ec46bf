; V306: the job reads its own number before any write can have run.
G0 X[#200]                   ; expect: V306
#200 = 5
G0 X[#200]                   ; written above: fine
If [#201 > 0]                ; expect: V306
    #202 = 1
EndIf
G0 X[#202]                   ; one branch wrote it: a write may have run, fine
While [#203 < 3]             ; the loop body writes it: its next round reads it, fine
    #203 = [#203 + 1]
EndWhile
GoSub setup
G0 X[#204]                   ; the sub wrote it: fine
G0 Y[#205]                   ; expect: V306
#205 = 1
#201 = 1
G0 Z[#206]                   ; #206 is written by a sub: not the job's own, fine
M30
Sub setup
    #204 = 2
    #206 = 1
EndSub
