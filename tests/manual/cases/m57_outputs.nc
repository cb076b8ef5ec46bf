; §3.7.8 (pp. 64-65): M57 P61/P62 read flood and mist, P63/P64 the spindle (tool) on and direction outputs
; manual-event: msg text=flood 1 mist 1 tool 1 dir 1
; manual-event: msg text=flood 0 mist 0 tool 1 dir 0
M7
M8 M3 S1000
M57 P61
#1 = #5399
M57 P62
#2 = #5399
M57 P63
#3 = #5399
M57 P64
msg "flood "#1" mist "#2" tool "#3" dir "#5399
M9 M4
M57 P61
#1 = #5399
M57 P62
#2 = #5399
M57 P63
#3 = #5399
M57 P64
msg "flood "#1" mist "#2" tool "#3" dir "#5399
M30
