; Run errors of moves, arcs, G10, G53, probing and canned cycles: each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
G0 X10
G2 X0 Y10 R4 F100
;### 1: R4 is too small to reach the end point: the chord is 14.1421 mm long; start (10.0000, 0.0000), end (0.0000, 10.0000) in the XY plane
---
G0 X10
G2 X0 Y10 F100
;### 1: an arc needs R or centre words I/J in the XY plane; start (10.0000, 0.0000), end (0.0000, 10.0000) in the XY plane
---
G2 X0 Y0 R5 F100
;### 1: an R-form arc needs an end point different from its start point; start (0.0000, 0.0000), end (0.0000, 0.0000) in the XY plane
---
G2 X0.001 R0 F100
;### 1: R0 is no radius: an R-form arc needs R other than 0; start (0.0000, 0.0000), end (0.0010, 0.0000) in the XY plane
---
G2 X5 I0 J0 F100
;### 1: the arc centre lies on its start point (radius 0); start (0.0000, 0.0000), centre (0.0000, 0.0000), end (5.0000, 0.0000) in the XY plane
---
G10 L2 P10 X1
;### 1: G10 L2 needs a coordinate system P1..P9 (P1 = G54 .. P9 = G59.3)
---
G10 L2 X1
;### 1: G10 L2 needs a coordinate system P1..P9 (P1 = G54 .. P9 = G59.3)
---
G10 L2 P0 X1
;### 1: G10 L2 needs a coordinate system P1..P9 (P1 = G54 .. P9 = G59.3)
---
G10 L20 P10 X1
;### 1: G10 L20 needs a coordinate system P0..P9 (P1 = G54, P0 = the active one)
---
G10 L5 P1 X1
;### 1: G10 needs L1, L10 or L11 (tool table), L2 or L20 (coordinate system)
---
G10 L1 P0 Z1
;### 1: G10 L1 needs a tool number P1..P99
---
G53 G2 X1 R3 F100
;### 1: G53 moves in machine coordinates only with G0, G1 or G38.2
---
G41 D1
G53 G0 X1
;### 1: G53 is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
G53
;### 1: G53 needs an axis word and G0, G1 or G38.2
---
G38.2 Z-0.1 F100
;### 1: G38.2 target is 0.1000 mm away; it must be at least 0.254 mm
---
G93
G38.2 Z-10 F100
;### 1: G38.2 is not allowed in inverse time mode (G93)
---
G38.2 Z-10 A5 F100
;### 1: G38.2 cannot move a rotary axis
---
G38.2 Z-10
;### 1: feed rate is 0: program an F word before this feed move (EdingCNC error G1516)
---
G38.2 Z-10 F0
;### 1: feed rate is 0: program an F word before this feed move (EdingCNC error G1516)
---
G0 Z10
G81 X5 Z3 R2 F100
;### 1: R (2) is below the hole bottom Z (3)
---
G0 Z10
G93 G81 X5 Z-3 R2 F100
;### 1: canned cycles are not allowed in inverse time mode (G93)
---
G0 Z10
G83 X5 Z-3 R2 F100
;### 1: G83 needs a peck depth Q greater than 0
---
G0 Z10
G73 X5 Z-3 R2 Q0 F100
;### 1: G73 needs a peck depth Q greater than 0
---
G0 Z10
G81 X5 Z-3 F100
;### 1: G81 needs R
---
G0 Z10
G81 X5 Z-3 R2 L0 F100
;### 1: L (repeat count) must be a whole number of at least 1
---
G0 Z10
G81 X5 Z-3 R2 A5 F100
;### 1: canned cycles cannot move rotary axes
---
G41 D1
G81 X5 Z-3 R2 F100
;### 1: a canned cycle is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
G80 X5
;### 1: G80 cancels the canned cycle; it takes no axis words
---
G0 X1 G1 Y2
;### 7: G0 and G1 are in the same modal group; use one per line
---
G17 G18
;### 5: G17 and G18 are in the same modal group; use one per line
---
G90 G91 X1
;### 5: G90 and G91 are in the same modal group; use one per line
---
M3 M4
;### 4: M3 and M4 are in the same modal group; use one per line
---
M3 M8 M48 M54 P1 M27
;### 1: 5 M words on one line; at most 4 are allowed
---
S-1 M3
;### 1: spindle speed S-1 is negative
---
T100
;### 1: tool T100 does not exist (tools are T0..T99)
---
T2.5
;### 1: tool T2.5 does not exist (tools are T0..T99)
---
G0 X1 X2
;### 7: word X appears twice on this line
---
G12 X1
;### 1: unknown G code G12
---
F-5
;### 1: negative feed rate
---
G4
;### 1: G4 needs a dwell time P (seconds) of 0 or more
---
G51
;### 1: G51 needs a factor: P for X and Y alike, or X and/or Y
