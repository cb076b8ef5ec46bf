;@unit mm
Sub Probe_Tool
    #100 = 1
EndSub

Sub user_1
    #101 = 2
EndSub
