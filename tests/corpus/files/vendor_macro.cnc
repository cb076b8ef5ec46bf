;@unit mm
;*********************************************************************
; Maschinenhersteller-Makros  -  Fräse FX-600  (Version 2.3)
; Geändert: Werkzeuglängenmessung, Kantenantastung mit Winkelkorrektur
;*********************************************************************

; persistent settings written by the setup dialog
#4500 = 25      ; Tasterhöhe / probe height
#4501 = 150     ; Antastvorschub / probe feed

Sub user_1 ; Kante antasten und Winkel berechnen (edge angle)
    If [[#5380 == 0] and [#5397 == 0]]
        msg "Kante wird angetastet"
    EndIf
    G90 G0 Z10
    G0 X0 Y0
    G38.2 G91 Y20 F[#4501]
    G90
    If [#5067 <> 1]
        errmsg "Taster hat nicht ausgelöst (no contact)"
    EndIf
    #101 = #5062
    G0 Y0
    G0 X50
    G38.2 G91 Y20 F[#4501]
    G90
    If [#5067 <> 1]
        errmsg "Taster hat nicht ausgelöst (no contact)"
    EndIf
    #102 = #5062
    ; one-operand ATAN as the vendor ships it: the edge angle from the two touches 50 mm apart
    #103 = ATAN[[#102 - #101] / 50]
    #104 = ATAN[#102 - #101]/[50]          ; the same with two operands
    If [ABS[#103 - #104] > 0.000001]
        errmsg "ATAN forms disagree"
    EndIf
    msg "Winkel = " #103 " Grad"
    G0 Y0
    G68 X0 Y0 R[#103]
EndSub

Sub user_2 ; Werkzeuglänge messen
    G53 G0 Z0
    G0 X0 Y0
    G53 G38.2 Z-80 F[#4501]
    If [#5067 == 1]
        #5401 = [#5053 - #4500]
        msg "Länge T1 = " #5401
    EndIf
    G53 G0 Z0
EndSub
