G1 X0
If [#1 > 0] AND [#2 > 0]
  G0 X1
EndIf
