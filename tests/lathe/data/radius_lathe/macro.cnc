;@unit mm
; Drehzyklen (Radiusprogrammierung) - Parameter in #1400..#1430
; Aufruf: Parameter-Sub füllt die Werte, dann die Zyklus-Sub.

Sub change_tool
    #5015 = 1
    M6 T[#5011]
    G43
EndSub

; ---- Längsdrehen: Parameter
Sub params_laengs
    #1400 = 1        ; Werkzeug
    #1401 = 20       ; Rohteilradius
    #1402 = 16       ; Fertigradius
    #1403 = 0        ; Z Start
    #1404 = -25      ; Z Ende
    #1405 = 1        ; Zustellung
    #1406 = 160      ; Schnittgeschwindigkeit m/min
    #1407 = 1800     ; Drehzahlgrenze
    #1408 = 0.2      ; Vorschub mm/U
    dlgmsg "Längsdrehen" "Rohteil R" 1401 "Fertig R" 1402 "Z Ende" 1404 "Zustellung" 1405
    If [#5398 <> 1]
        errmsg "Abgebrochen"
    EndIf
    GoSub zyklus_laengs
EndSub

Sub zyklus_laengs
    If [#1405 <= 0]
        errmsg "Zustellung muss > 0 sein"
    EndIf
    If [#1402 >= #1401]
        errmsg "Fertigradius "#1402" >= Rohteilradius "#1401
    EndIf
    T[#1400] M6
    G96 S[#1406] D[#1407] M3
    G4 P0.5
    G95 F[#1408]
    #1410 = #1401
    G0 X[#1401 + 1] Z[#1403 + 1]
    While [#1410 > #1402]
        #1410 = [#1410 - #1405]
        If [#1410 < #1402]
            #1410 = #1402
        EndIf
        G0 X#1410
        G1 Z#1404
        G1 X[#1410 + 0.5]
        G0 Z[#1403 + 1]
    EndWhile
    G97 S800
    G94
    M5
EndSub

; ---- Gewinde: Parameter
Sub params_gewinde
    #1420 = 5        ; Werkzeug
    #1421 = 8        ; Außenradius (M16)
    #1422 = 2        ; Steigung
    #1423 = -20      ; Z Ende
    #1424 = 300      ; Drehzahl
    GoSub zyklus_gewinde
EndSub

Sub zyklus_gewinde
    If [#1422 <= 0]
        errmsg "Steigung fehlt"
    EndIf
    T[#1420] M6
    G97 S[#1424] M4
    G4 P1
    G0 X[#1421 + 1] Z4
    G76 P[#1422] Z[#1423] I[#1421] J0.1 K[0.6134 * #1422] Q30 H1
    G0 X[#1421 + 3]
    M5
EndSub
