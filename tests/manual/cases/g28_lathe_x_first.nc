; §3.6.8 lathe: "Bei Drehmaschine wird zuerst die X-Achse bewegt"
; ini: lathe.ini
; manual: rapid 100 0 -50
; manual: rapid 100 0 300
#5161 = 100
#5163 = 300
G0 X20 Z-50
G28
M30
