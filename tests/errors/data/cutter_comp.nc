; Run errors of cutter radius compensation (G41/G42): each case ends at the error written after its line as ;### COL: message
; (tests/errors/test_error_goldens.py; pytest tests/errors --regen-goldens rewrites them)
---
;% ini=tools.ini
G0 X0 Y0
G41 D1
G1 X1 Y0 F100
;### 1: cutter compensation: the entry move (1.0000 mm in the plane) must be longer than the tool radius 2.0000 mm
---
;% ini=tools.ini
G0 X-10
G41 D2
G1 X0 Y0 F100
G1 X20
G1 Y20
G1 X19
G1 Y0
;### 1: cutter compensation: a straight move in an inside corner cannot be reached by the tool without gouging (the tool is larger than the corner)
---
;% ini=tools.ini
G0 X-10
G42 D2
G1 X0 F100
G2 X4 I2
;### 1: cutter compensation: the tool radius 5.0000 mm does not fit inside the arc of radius 2.0000 mm
---
;% ini=tools.ini
G0 X0 Y0
G41 D2
G1 X0 Y-20 F100
X1.7431 Y-19.9239
X3.4730 Y-19.6962
;### 1: cutter compensation: a straight move in an inside corner cannot be reached by the tool without gouging (the tool is larger than the corner)
X5.1764 Y-19.3185
---
;% ini=tools.ini
G41 D1
G42 D1
;### 1: G42: cutter compensation is already on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G18
;### 1: changing the plane (G17/G18/G19) is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G53 G0 X1
;### 1: G53 is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G81 X5 Z-3 R2 F100
;### 1: a canned cycle is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G55
;### 1: changing the coordinate system (G55) is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G92 X0
;### 1: G92 is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
T2 M6
;### 1: a tool change (M6) is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G43 H1
;### 1: changing the tool length offset (G43) is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G28
;### 1: G28 is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G41 D1
G38.2 Z-5 F100
;### 1: probing (G38.2) is not allowed while cutter compensation (G41/G42) is on; turn it off with G40 first
---
;% ini=tools.ini
G0 X-10
G41 D1
G1 X0 F100
G1 X10
G40
G2 X0 I-5
;### 1: cutter compensation: the move after G40 must be a straight move, not an arc
---
;% ini=tools.ini
G41 D1.5
;### 1: G41 D1.5: D is a tool number, T0..T99 (G41.1/G42.1 take a diameter)
---
;% ini=tools.ini
G42.1
;### 1: G42.1 needs D, the tool diameter
---
;% ini=tools.ini
G0 X0 Y0
G41 D2
G2 X4 I2 F100
;### 1: cutter compensation: the entry arc must end further than the tool radius from where it starts
