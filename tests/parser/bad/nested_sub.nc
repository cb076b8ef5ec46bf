Sub a
Sub b
EndSub
