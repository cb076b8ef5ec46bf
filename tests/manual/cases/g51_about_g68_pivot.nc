; §3.6.13 (p. 33): "In Kombination mit G68 sind der Drehpunkt und der Skalierungspunkt die gleich"
; manual: rapid 20 30 0
G68 X10 Y10 R0
G51 P2 I50 J50
G0 X15 Y20
M30
