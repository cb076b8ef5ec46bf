; Parser findings are lint findings, with their own codes.
G0 X[10 + 5]
G0 X10+5                 ; expect: E105
G1 X[1 + [2 * 3]         ; expect: E101
G1 X1 ]                  ; expect: E102
G0 X1 (open comment      ; expect: E103
msg "no closing quote    ; expect: E104
If [#5001 > 0] AND [#5002 > 0]   ; expect: E106
    G0 X1
EndIf
KIN X2B                  ; expect: E107
; expect-next-line: E108   (a comment after it would change the message)
G1 X
; expect-next-line: E100
G0 @
N123456 G1 X1 ; expect: E115 (manual 3.4.1: five digits at most)
G0 X1 ( T1: End Mill (6 mm) ) ; expect: E116 (manual 3.4.4: comments do not nest)
M30
