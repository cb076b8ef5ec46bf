; dialog_setup.nc -- face the top of a block; the operator enters the sizes.
;
; Work zero (G54) at the front-left corner of the top face. The tool path runs
; back and forth along X, stepping in Y by 70 % of the tool diameter, and goes
; a little past every edge so the face is cut cleanly.

; defaults, shown in the dialog (dlgmsg takes bare variable numbers, no #)
#27 = 60           ; width along X (mm)
#28 = 40           ; length along Y (mm)
#29 = 1.0          ; total depth (mm)
#30 = 2            ; number of depth passes
#31 = 10           ; tool diameter (mm)
#32 = 1500         ; feed (mm/min)

dlgmsg "Face milling" "Width X (mm)" 27 "Length Y (mm)" 28 "Total depth (mm)" 29 "Depth passes" 30 "Tool diameter (mm)" 31 "Feed (mm/min)" 32

If [#5398 <> 1]
    msg "Face milling cancelled"
    M30
EndIf

If [[[#27 <= 0] or [#28 <= 0]] or [[#29 <= 0] or [#31 <= 0]]]
    errmsg "Width, length, depth and tool diameter must be greater than 0"
EndIf
If [[#30 < 1] or [#32 <= 0]]
    errmsg "Give at least one pass and a feed above 0"
EndIf

#30 = ROUND[#30]           ; whole passes only
#33 = [#31 * 0.7]          ; step-over between rows
#34 = [#29 / #30]          ; depth of one pass
#35 = [#31 / 2 + 2]        ; run-out past the X edges
#36 = 1                    ; pass counter
msg "Facing "#27" x "#28" mm, "#29" mm deep in "#30" passes"

G17 G21 G40 G90 G94
T3 M6
G43
S8000 M3
G0 Z5

While [#36 <= #30]
    #37 = [0 - #34 * #36]  ; Z of this pass
    #38 = 0                ; Y of the current row
    #39 = 1                ; 1: cutting towards +X, -1: towards -X
    #40 = 0                ; becomes 1 after the last row
    G0 X[0 - #35] Y0
    G1 Z[#37] F300         ; off the part, so this plunge cuts air
    While [#40 == 0]
        If [#39 == 1]
            G1 X[#27 + #35] F[#32]
        Else
            G1 X[0 - #35] F[#32]
        EndIf
        If [#38 >= #28]
            #40 = 1
        Else
            #38 = [#38 + #33]
            If [#38 > #28]
                #38 = #28      ; the last row runs along the back edge
            EndIf
            G1 Y[#38]
            #39 = [0 - #39]
        EndIf
    EndWhile
    G0 Z5
    #36 = [#36 + 1]
EndWhile

M5
G0 Z25
G0 X0 Y0
msg "Face done"
M30
