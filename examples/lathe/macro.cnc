;@unit mm
; ============================================================================
; macro.cnc for the example lathe (cnc.ini: machineType = 1, diameterProgramming = 1)
;
; X is programmed as a DIAMETER everywhere, also in #5001 (work X) and in the
; dialogs of user_macro.cnc. The cross slide itself (#5071, the trace) moves
; the radius.
;
; The turret indexes without measuring: tool offsets come from the tool table
; (length = Z offset, width = X offset as a diameter, zDelta/xDelta = wear) and are applied
; with G43 after every change.
; ============================================================================

Sub home_all
    ; X first: the cross slide pulls the tool away from the part and the
    ; tailstock before the carriage travels along Z.
    home x
    home z
    msg "X and Z are homed"
EndSub

Sub home_x
    home x
EndSub

Sub home_z
    home z
EndSub

Sub change_tool
    ; #5011 = requested tool, #5008 = tool in the turret position now.
    #5015 = 0
    If [[#5011 < 1] or [#5011 > 8]]
        errmsg "The turret has stations 1..8, not T"#5011
    EndIf
    If [#5011 <> #5008]
        M5 M9
        G28                             ; index clear of the part (X first)
        msg "Turret to T"#5011
        If [[#5380 == 0] and [#5397 == 0]]
            M54 P3                      ; index request
            M56 P3 L1 Q5                ; wait for "in position", 5 s
            If [#5399 == -1]
                errmsg "Turret did not index to T"#5011
            EndIf
            M55 P3
        EndIf
    EndIf
    #5015 = 1
    M6 T[#5011]
    G43                                 ; X and Z offsets of the new tool
EndSub

Sub start
    G18 G40 G80 G90 G94 G97
EndSub

Sub user_reset
    M5 M9
EndSub

; The user buttons open the turning cycles of user_macro.cnc.
Sub user_1
    GoSub face_dialog
EndSub

Sub user_2
    GoSub turn_dialog
EndSub

Sub user_3
    GoSub thread_dialog
EndSub

Sub user_5
    GoSub tool_x_from_diameter
EndSub

; Set the X offset of the tool in the turret from a diameter it has just turned
; (a skim cut, then measure). The tool table keeps width and xDelta as
; DIAMETER values (#5600 + tool, #5800 + tool), as every X here; G43 moves the
; cross slide by half of them. #5012 is the tool's width + xDelta after G43.
Sub tool_x_from_diameter
    dlgmsg "X offset of the turret tool: the diameter just turned" "Measured diameter" 1490
    If [#5398 == -1]
        msg "X offset left as it was"
    Else
        If [#1490 <= 0]
            errmsg "A turned diameter is greater than 0"
        EndIf
        G43                                 ; the tool's own offsets in force
        #1491 = [#5001 - #1490]             ; how far the reading is off (diameter)
        #[5600 + #5008] = [#5012 - #[5800 + #5008] + #1491]
        G43                                 ; apply the corrected width
        msg "T"#5008" width = "#[5600 + #5008]" mm (diameter), X reads "#5001
    EndIf
EndSub

Sub user_4
    ; Spindle warm-up at a fixed speed (G97), 10 s per step.
    G97
    #5020 = 500
    While [#5020 <= 2500]
        S[#5020] M3
        G4 P10
        #5020 = [#5020 + 1000]
    EndWhile
    M5
EndSub
