; §3.3 (p. 7): "Es ist ein Fehler, dass der Wert von Parameter 5220 alles andere als eine ganze Zahl zwischen eins und neun ist"
; ini: bad_5220.ini
; manual-error: L3 must be a whole number 1..9
G0 X1
M30
