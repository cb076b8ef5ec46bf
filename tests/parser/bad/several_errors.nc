G0 X1
G0 X1+
G1 Y2*3
EndWhile
G0 @
