;@unit mm
; Variable map example (docs/variables.md): a lathe threading button and a probing button.
;
; Numbers this file uses:
; #1560 = 1 ;; number of passes done
; #4200   spindle warm-up time in seconds
;
;@var #1552 thread_major_diameter "diameter A of the thread"
;@var #1553 thread_minor_diameter "computed from the pitch"

Sub user_1
    dlgmsg "Thread" "Z start" 1550 "Z end" 1551 "diameter A" 1552 "pitch" 1554 "depth per pass" 1555
    If [#5398 == -1]
        M30
    EndIf
    #1553 = [#1552 - 1.0825 * #1554]
    #1556 = [[#1552 - #1553] / 2] ;; thread depth
    #1560 = 0
    While [#1560 * #1555 < #1556]
        #1560 = [#1560 + 1]
        G0 X[#1552 - 2 * #1560 * #1555] Z[#1550]
        G33 Z[#1551] K[#1554]
        G0 X[#1552 + 1]
    EndWhile
EndSub

Sub user_2
    #5020 = #5071 ;x1
    #5021 = #5072 ;y1
    G4 P[#4200]
    G0 X[#5020] Y[#5021]
EndSub
