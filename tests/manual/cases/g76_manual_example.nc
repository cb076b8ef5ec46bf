; §3.6.18 G76 example: "Faden von z = 20 bis z = 10, Aussendurchmesser = 15 ... 10 Durchgaenge";
; I the crest diameter 15, J and K radial (docs/lathe.md): 10 cuts 0.1 apart, radius 7.4 .. 6.5
; ini: lathe_diameter.ini
; manual: linear 7.4 0 10 sync=1
; manual: linear 7.3 0 10 sync=1
; manual: linear 7.2 0 10 sync=1
; manual: linear 7.1 0 10 sync=1
; manual: linear 7.0 0 10 sync=1
; manual: linear 6.9 0 10 sync=1
; manual: linear 6.8 0 10 sync=1
; manual: linear 6.7 0 10 sync=1
; manual: linear 6.6 0 10 sync=1
; manual: linear 6.5 0 10 sync=1
G97 S300 M3
G0 X20 Z20
G76 P1.0 Z10 I15 J0.1 K1.0
M30
