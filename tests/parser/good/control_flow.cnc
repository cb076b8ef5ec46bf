;@unit mm
; Subs, ifs, whiles, gosubs: keywords in any case
Sub change_tool ; called by M6
    If [#5011 == #5008] THEN
        #5015 = 1
    Else
        G53 G0 Z0
        IF [[#5380 == 0] and [#5397 == 0]]
            M0
        ENDIF
        #5015 = 1
    EndIf
    M6 T[#5011]
EndSub

SUB 1st_sub
    while [#1 < 10]
        #1 = [#1 + 1]
        WHILE [#2 < 3]
            #2 = [#2 + 1]
        endwhile
    ENDWHILE
ENDSUB

sub m100
    msg "M100 called with P=" #16
endsub

If [#5068 <> #4984]]
    gosub CHANGE_TOOL
EndIf
GoSub 1st_sub
M100 P3
