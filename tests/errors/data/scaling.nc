; Run errors of G51 scaling: each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
G51 X2
G2 X10 Y0 I5 J0 F100
;### 1: an arc cannot be scaled by different factors in the XY plane (2 and 1); use G51 P or break the arc into lines
---
G51
;### 1: G51 needs a factor: P for X and Y alike, or X and/or Y
---
G51 P2 X2
;### 1: G51 takes either P (one factor for X and Y) or X/Y (a factor per axis), not both
---
G51 P0
;### 1: G51 factor 0: a factor of 0 would flatten the job
