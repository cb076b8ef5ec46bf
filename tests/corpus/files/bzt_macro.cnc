; macro.cnc  Fräsmaschine  BZT  -  Stand 03/2021
; Änderungen: Werkzeugwechsel mit Längenmessung, Höhenkarte für Platinen
;
; Hinweis für den Benutzer:
; die Variablen #4000..#4010 werden im Setup-Dialog gesetzt

#4000 = 10        ; Sicherheitshöhe
#4001 = 120       ; Tastervorschub

Sub user_1 ; Nullpunkt Z mit Taster (zero_z style)
    G53 G0 Z0
    G53 G38.2 Z-60 F[#4001]
    If [#5067 == 1]
        G0 Z[#5063 + 2]
        G38.2 G91 Z-5 F30
        G90
        #5011 = [#5053 - 15.02]
        msg "Z-Null gesetzt um " %d
    Else
        errmsg "Taster nicht ausgelöst"
    EndIf
    G53 G0 Z0
EndSub

Sub user_2 ; Ecke antasten, Winkel der Kante
    G0 Z5
    G0 X0 Y-10
    G0 Z-2
    G38.2 Y10 F[#4001]
    #110 = #5062
    G0 Y-10
    G0 X40
    G38.2 Y10 F[#4001]
    #111 = #5062
    G0 Y-10
    G0 Z5
    #112 = ATAN[[#111 - #110] / 40]
    msg "Kantenwinkel " #112 " Grad  " %d
    G68 X0 Y0 R[#112]
    G69
EndSub

Sub user_3 ; Höhenkarte
    If [#4100 == 0] ; Vorgabewerte beim ersten Aufruf
        #4100 = 4
        #4101 = 3
        #4102 = 20
    EndIf
    dlgmsg "Höhenkarte Raster" "Punkte in X-Richtung (nx)" 4100 "Punkte in Y-Richtung (ny)" 4101 "Raster" 4102
    If [#5398 == 1]
        ZHCINIT [#4102] [#4100] [#4101]
        #120 = 0
        While [#120 < #4101]
            #121 = 0
            While [#121 < #4100]
                G0 Z5
                G0 X[#121 * #4102] Y[#120 * #4102]
                G38.2 Z-10 F[#4001]
                ZHCADDPOINT
                #121 = [#121 + 1]
            EndWhile
            #120 = [#120 + 1]
        EndWhile
        G0 Z5
        ZHCS hoehe.txt
        ZHCcheck 20
    EndIf
EndSub

Sub user_4 ; Plasma / THC Anzeige
    GetHeightControlVact 130
    GetHeightControlVset 131
    logfile thc.log 1
    logmsg "Vact=" #130 " Vset=" #131 " " %d
    Service 3
    warnmsg "THC: " #130
EndSub

Sub user_5 ; Drehachse klemmen, Werkzeugtabelle
    M26
    G0 X10 Y10
    M27
    G0 A90
    M90
    M91
    #140 = #5390
    G10 L10 P3 Z0
    G10 L11 P4 Z0
    TCAGuard on
    G0 X50
    TCAGuard off
    M54 E1 Q500
    M57 E1
    #141 = #5399
    GetJobDistance 142
    msg "Weg: " #142 " PWM " #141
EndSub

Sub user_6 ; Zyklen
    G0 X0 Y0 Z10
    M4 S500
    G74 X10 Y10 Z-5 R2 F100 P0.5
    G80
    M3 S800
    G87 X20 Y20 Z-20 R2 I2 J0 K-5 F100
    G80
    M5
EndSub

Sub user_9 ; alte Variante, nicht mehr benutzt
    If [#4005 == 99]
        Diese Routine misst die Werkzeuglänge am festen Taster
        und speichert sie in der Werkzeugtabelle. Sie ist durch
        user_1 ersetzt worden.
    EndIf
EndSub

Sub change_tool
    msg "Werkzeug " #5011
EndSub
