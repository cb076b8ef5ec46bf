If [1]
Else
Else
EndIf
