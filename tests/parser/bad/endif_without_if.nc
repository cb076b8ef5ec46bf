G0 X1
EndIf
