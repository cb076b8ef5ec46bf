; Run errors of Z height compensation commands: each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
ZHC on
;### 1: ZHC on: there is no height table (probe one with ZHCINIT and ZHCADDPOINT, or load one with ZHCL)
---
ZHCINIT 10 3 3
ZHC on
;### 1: ZHC on: 0 of 9 points are measured
---
ZHCADDPOINT
;### 1: ZHCADDPOINT before ZHCINIT: there is no grid to add the point to
---
ZHCINIT 10 3 3
G0 X100
G38.2 Z-5 F100
ZHCADDPOINT
;### 1: ZHCADDPOINT: the probe point X100 Y0 (machine) is not on the ZHC grid
---
ZHCINIT 10 3
;### 1: ZHCINIT expects gridSize nX nY, e.g. ZHCINIT 10 5 4 (got '10 3')
---
ZHCINIT 0 3 3
;### 1: ZHCINIT: grid sizes must be above 0 and nX, nY whole numbers from 1 (at most 100,000 points); got 0 x 0 mm, 3 x 3 points
---
ZHCINIT 10 5 nan
;### 1: ZHCINIT expects gridSize nX nY, e.g. ZHCINIT 10 5 4 (got '10 5 nan')
---
ZHCINITEX 1 1 [
;### 1: ZHCINITEX expects gridSizeX gridSizeY nX nY (got '1 1 [')
---
ZHCL missing.txt
;### 1: cannot read the height table LOGS/missing.txt: No such file or directory
