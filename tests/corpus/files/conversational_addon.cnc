;@unit mm
; Conversational programming add-on: circle pocket
;
Conversational pocket add-on, version 1.2
Put this file next to macro.cnc and call it with F-key 3.
If the dialog does not show, check the menu configuration.

Sub circle_pocket
    #4600 = 20   ; diameter
    #4601 = 2    ; depth
    #4602 = 4    ; tool diameter
    dlgmsg "Circle pocket" "diameter" 4600 "depth" 4601 "tool diameter" 4602
    If [#5398 <> 1]
        M30
    EndIf
    #601 = [[#4600 - #4602] / 2]
    G0 Z5
    G0 X[#601] Y0
    G1 Z-[#4601] F200
    G2 X[#601] Y0 I-[#601] J0
    G0 Z5
    GoSub notes
EndSub

Sub notes
    If [#4699 == 1]
        Notes for the next version (never reached while #4699 is 0):
        - ramp in instead of plunging
        - finish pass with climb milling
        msg "unreachable"
    EndIf
EndSub
