; §3.6.8 G28/G30: via the programmed point to the home of all axes; Z first when home is higher, else last
; manual: rapid 3 1 -5
; manual: rapid 3 1 0
; manual: rapid 10 20 0
; manual: rapid 1 1 40
; manual: rapid 30 40 40
; manual: rapid 30 40 35
#5161 = 10
#5162 = 20
#5181 = 30
#5182 = 40
#5183 = 35
G0 X1 Y1 Z-5
G28 X3
G0 X1 Y1 Z40
G30
M30
