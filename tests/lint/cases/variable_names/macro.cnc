;@unit mm
; One number, two meanings; reserved numbers; annotations.
;@var #1552 thread_major_diameter "diameter A of the thread"
;@var #1553 thread_minor_diameter
Sub user_1
    dlgmsg "Thread" "diameter A" 1552 "pitch" 1554
    #5020 = #5071 ;x1
    #5021 = #5072 ;y1
    #1553 = [#1552 - #1554]
    G0 X[#5020] Y[#5021] Z[#1553]
EndSub

Sub user_2
    ; expect-next-line: V305
    #5020 = 12 ;sensor position
    #5021 = 5 ;y1 of the sensor
    dlgmsg "Other" "pitch" 1554
    GoSub helper
EndSub

Sub helper
    ; the caller's number under another name: helper runs in user_2, so no finding
    #5020 = 3 ;probe offset
    G0 X[#5020] X[#1554]
EndSub

Sub user_3
    dlgmsg "Third" "depth" 1600
    G0 X[#1600]
EndSub

Sub user_4
    ; expect-next-line: V305
    dlgmsg "Fourth" "feed" 1600
    G0 X[#5231]              ; expect: V307
    #5250 = 1                ; expect: V307
    G0 X[#5241]              ; G55's X offset: fine
    G0 X[#5012]              ; the tool's X offset (manual): fine
EndSub
; expect-next-line: V308
;@var #27 1bad
; expect-next-line: V308
;@var #1552 another_name
; expect-next-line: V308
;@var 28 no_hash
