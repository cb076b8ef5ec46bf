;@unit cm        ; expect: E109
Sub user_1
    G0 X1
EndSub
