; Parameter indices, read-only system variables, never-written variables.
#27 = 5
#28 = [#27 * 2]
G0 X[#28]
#0 = 1                   ; expect: V300
#6000 = 1                ; expect: V300
G0 X[#[5990 + 20]]       ; expect: V300
#5001 = 10               ; expect: V301
#[5000 + 67] = 1         ; expect: V301
#5020 = #5001            ; reading a read-only variable is fine
G0 X[#29]                ; expect: V302
G0 Y[#29]                ; only the first read of #29 in a file is reported
G0 Z[#4000]              ; persistent variables come from cnc.ini: not reported
dlgmsg "Setup" "Depth" 30
G0 Z[#30]                ; a dlgmsg field counts as written
GetToolInfo first 31
G0 Z[#31]                ; GetToolInfo stores into its variable
If [#5001 > 0]]          ; expect: V304
    G0 X1
EndIf
While [#27 < 0]]         ; expect: V304
    #27 = [#27 + 1]
EndWhile
M30
