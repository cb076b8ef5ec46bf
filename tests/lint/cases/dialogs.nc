; dlgmsg: a title, then "label" index pairs.
dlgmsg "Setup" "Width" 27 "Length" 28
dlgmsg "Setup" "Width" #27 "Length" 28                        ; expect: D403
dlgmsg "Setup" 27 "Width" 28                                  ; expect: D402
dlgmsg "Setup" "Width" "Length" 28                            ; expect: D402
dlgmsg "Setup" "Width" [27 + 1]                               ; expect: D402
dlgmsg "Setup" "Width"                                        ; expect: D402
dlgmsg 27 "Width" 28                                          ; expect: D402
dlgmsg "Setup" "A label of exactly 31 character"  27
dlgmsg "Setup" "A label that is far too long to show" 27      ; expect: D401
dlgmsg "Many" "a" 31 "b" 32 "c" 33 "d" 34 "e" 35 "f" 36 "g" 37 "h" 38 "i" 39 "j" 40 "k" 41 "l" 42 "m" 43 "n" 44 "o" 45
dlgmsg "Many" "a" 31 "b" 32 "c" 33 "d" 34 "e" 35 "f" 36 "g" 37 "h" 38 "i" 39 "j" 40 "k" 41 "l" 42 "m" 43 "n" 44 "o" 45 "p" 46 ; expect: D400
dlgmsg "Bad" "x" 6000 "y" 5380                                ; expect: V300, V301
M30
