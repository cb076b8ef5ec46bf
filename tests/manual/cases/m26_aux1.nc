; §3.7.9 (p. 65): "M26 P1 aktiviert die Klemme und ... P1 bedeutet AUX 1"; M27 P1 releases it
; manual-event: output port=1 on=True
; manual-event: msg text=aux1 1
; manual-event: output port=1 on=False
M26 P1
M57 P1
msg "aux1 "#5399
M27 P1
M30
