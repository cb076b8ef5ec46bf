; §3.4 (p. 7): blanks are allowed anywhere in a code line: "g0x + 0. 12 34y 7" is "g0 x + 0.1234 y7"
; manual: rapid 0.1234 7 0
g0x + 0. 12 34y 7
M30
