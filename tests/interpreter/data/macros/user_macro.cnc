;@unit mm
; User macro file: its subs win over macro.cnc.

#251 = 7                   ; top-level statement of the user macro

Sub shared
    #300 = 2
EndSub

Sub only_user
    #302 = 1
EndSub
