; V306: the only write of #100 is in a sub nothing calls.
G0 X[#100]                   ; expect: V306
G0 Y[#100]                   ; reported once per file
#101 = 2
G0 X[#101]                   ; written at the top level: fine
M30
Sub never_called             ; expect: S210
    #100 = 5
    #101 = 3
    G0 X[#100]               ; a read in the dead sub itself is not reported
EndSub
