; Run errors of G87 back boring: each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
G87 X0 Z-20 R2 F100
;### 1: G87 needs K, the level the back bore ends at (between the bottom and R)
---
M3 S1000
G87 X0 Z-20 R2 K5 F100
;### 1: G87 K (5) must lie between the bottom Z (-20) and R (2)
