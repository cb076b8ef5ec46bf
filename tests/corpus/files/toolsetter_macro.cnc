;*****************************************
;* Werkstatt-Makros nach dem Muster der mitgelieferten macro.cnc
;* #4995 Tasterhoehe, #4996 sichere Hoehe, #4997/#4998 Tasterposition, #4999 Futterhoehe
;*****************************************

Sub zero_z
  #4995 = 43      ;Tasterhoehe
  if [[#5380==0] and [#5397==0]] ;nur an der Maschine
    msg "Z-Null mit Taster"
  endif
    (Antasten, langsam)
    f30
    g53 g38.2 z[#5103 + #4995] ;nicht unter die Tasterhoehe
    (zurueck zum Kontaktpunkt)
    g90 g0 z#5063
    G92 z#4995
    g91 (inkrementell)
    g0 z5
    g90 (absolut)
Endsub

sub m_tool_no_dlg
    if [#5025 < 1] ;direkt aufgerufen: Werkzeug 1
        #5025 = 1
    endif
    #5016 = #5025           ;Werkzeugnummer
    #5017 = #[5400 + #5016] ;Laenge aus der Werkzeugtabelle
    #5018 = #[5500 + #5016] ;Durchmesser
    if [[#5016 < 1] OR [#5016 > 99]]
        ErrMsg "Werkzeug muss 1 .. 99 sein"
    endif
    if [#5016 <> #5008]
        m6 t#5016
    endif
    g0 g53 z#4996
    g00 g53 x#4997 y#4998
    g38.2 g91 z-20 f30
    g90
    g0 g53 z#4996
    if [#5397 == 0]
        #[5400 + #5016] = [#5053-#4999]
        msg "gemessen="#[5400 + #5016]" fuer Werkzeug "#5016 " am " %d
    endif
endsub

sub measure_used_tools
    GetToolInfo num 5025
    Msg "Werkzeuge im Programm: " #5025
    #5026 = 0
    While [#5026 <= 6]
        #[5030 + #5026] = 0
        #5026 = [#5026 + 1]
    endwhile
    GetToolInfo first 5025
    while [[#5025 >= 0] and [#5025 <= 6]] ;-1 nach dem letzten
        #[5030 + #5025] = 1
        GetToolInfo next 5025
    endwhile
    dlgmsg "Messen? 1 => JA 0 => NEIN)" "Werkzeug 1" 5031 "Werkzeug 2" 5032 "Werkzeug 3" 5033
    if [#5398 == 1]
        #5026 = 1
        While [#5026 <= 3]
            if [#[5030 + #5026] == 1]
                #5025 = #5026
                gosub m_tool_no_dlg
            endif
            #5026 = [#5026 + 1]
        endwhile
    else
        msg "abgebrochen"
    endif
endsub

sub change_tool
    TCAGuard off
    #5019 = #5151
    if [#5019 == 1]
        ZHC off
    endif
    m5
    #5015 = 0
    If [ [#5011] <> [#5008] ]
        msg "Werkzeug "#5008" raus, "#5011" rein"
        #5015 = 1
    else
        msg "Werkzeug ist schon drin"
        #5015 = 1
    endif
    If [[#5015] == 1]
        m6t[#5011]
        if [#5011 <> 0]
            G43
        else
            G49
        endif
    else
        errmsg "Werkzeugwechsel fehlgeschlagen"
    endif
    g1
    TCAGuard on
    if [#5019 == 1]
        ZHC on
    endif
EndSub
