;@unit mm
; Main macro file for the control-flow tests.

#250 = [#250 + 1]          ; top-level statement: runs once, when the file is loaded

Sub change_tool
    ; what the controller hands over on M6
    #200 = #5011           ; requested tool
    #201 = #5008           ; tool in the spindle
    #202 = #5015           ; 0 until the change succeeds
    #5015 = 1
    M6 T[#5011]            ; commit the new tool (runs the built-in M6)
    #203 = #5008
EndSub

Sub shared
    #300 = 1               ; macro.cnc's version (the user macro's wins)
EndSub

Sub only_main
    #301 = 1
EndSub

Sub m100
    ; M100 with letter arguments
    #310 = #1              ; A
    #311 = #16             ; P
    #312 = #17             ; Q
    #313 = #26             ; Z
EndSub

Sub m3
    ; a user override of the spindle start: counts, then runs the built-in M3
    #320 = [#320 + 1]
    M3
EndSub
