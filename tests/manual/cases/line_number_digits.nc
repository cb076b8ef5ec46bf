; §3.4.1 (p. 7): a line number has at most five digits ("000009 ist beispielsweise nicht in Ordnung")
; manual-error: L4 a line number has at most 5 digits
N12345 G0 X1
N000009 G0 X2
M30
