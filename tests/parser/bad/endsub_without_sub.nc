EndSub
