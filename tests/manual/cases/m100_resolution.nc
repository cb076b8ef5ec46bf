; §3.7.12 M100 P (p. 66): "Ändern Sie die Achsenauflösung im laufenden Betrieb um einen Faktor (Faktor 1 ist Standard)"
; manual-event: m_code m=100 p=1.01
; manual-error: L5 the resolution factor must be more than 0
M100 P1.01
M100 P0
M30
