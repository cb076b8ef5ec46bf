;@unit mm
Sub spot
    G81 X0 Y0 Z-1 R2 F100
    G80
EndSub
