While [1]
EndIf
