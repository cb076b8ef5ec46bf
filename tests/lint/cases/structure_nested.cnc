;@unit mm
Sub user_1
    G0 X1
Sub user_2               ; expect: S205
    G0 X2
EndSub
