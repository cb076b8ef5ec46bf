; §3.7.13 M1..M999: an M code without a built-in runs Sub mNNN; without one it does nothing, with a warning
; manual-event: warn text=M123 has no built-in meaning and no Sub m123 is defined: it does nothing
; manual-event: msg text=my M124
M123
M124 S5
M30
Sub m124
  msg "my M124"
EndSub
