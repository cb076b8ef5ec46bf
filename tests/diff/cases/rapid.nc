; rapid.nc: the approach of layer 1 comes down to Z-13 in rapid
%
; pocket.nc -- a 2.5D job: a rounded pocket, four bolt holes and a row of deep holes
;
; Stock 100 x 60 x 20 mm in the vise; work zero (G54) at the front-left corner
; of the top face. Pocket 60 x 30 x 6 mm (X20..80, Y15..45) with 5 mm corner
; radii, roughed in two 3 mm layers leaving 0.3 mm on the walls, then finished.
;   T1  6 mm flat end mill, centre cutting
;   T2  5 mm drill
(MSG pocket.nc: check the vise jaw and the G54 offset before starting)
G17 G21 G40 G49 G80 G90 G94
G10 L2 P1 X100 Y50 Z-80         ; vise jaw corner in machine coordinates
G54

; ---------------------------------------------------------------- T1 pocket
T1 M6
G43                             ; length offset of the tool in the spindle
S12000 M3
M8
G0 Z10
G0 X35 Y30
G0 Z-13

; layer 1: plunge on the centre line, then clockwise rings outwards (G2)
G1 Z-3 F300
G1 X65 F1200
X69
Y26                             ; ring 8 mm in from the wall path
X31
Y34
X69
Y30
X73
Y22                             ; ring 4 mm in
X27
Y38
X73
Y30
X76.7
Y20                             ; roughing contour, 0.3 mm left on the wall
G2 X75 Y18.3 I-1.7 J0
G1 X25
G2 X23.3 Y20 I0 J1.7
G1 Y40
G2 X25 Y41.7 I1.7 J0
G1 X75
G2 X76.7 Y40 I0 J-1.7
G1 Y30
G0 Z1
G0 X35 Y30

; layer 2: the same path 3 mm deeper
G1 Z-6 F300
G1 X65 F1200
X69
Y26
X31
Y34
X69
Y30
X73
Y22
X27
Y38
X73
Y30
X76.7
Y20
G2 X75 Y18.3 I-1.7 J0
G1 X25
G2 X23.3 Y20 I0 J1.7
G1 Y40
G2 X25 Y41.7 I1.7 J0
G1 X75
G2 X76.7 Y40 I0 J-1.7
G1 Y30

; finishing pass at full depth, counter-clockwise (G3 climbs on an inside wall)
G1 X77 F600
Y40
G3 X75 Y42 I-2 J0
G1 X25
G3 X23 Y40 I0 J-2
G1 Y20
G3 X25 Y18 I2 J0
G1 X75
G3 X77 Y20 I0 J2
G1 Y30
G1 X76                          ; leave the wall before lifting
G0 Z10

; ----------------------------------------------------------- T2 drilling
T2 M6
G43
S3000 M3
M8
G0 Z10
G0 X8 Y8

; bolt holes in the four corners, 8 mm deep; G99 returns to R between holes
G99 G81 X8 Y8 Z-8 R2 F200
X92
Y52
G98 X8                          ; last one returns to the start height, Z10
G80

; five deep holes along the back edge, X30..X70 at 10 mm pitch, 12 mm deep.
; In G91 each repeat (L) moves X by 10; R is measured from Z10, Z from R.
G0 X20 Y52
G91 G98 G83 X10 R-8 Z-14 Q3 L5 F150
G80 G90

; ----------------------------------------------------------------- the end
M5 M9
G0 Z25
G0 X0 Y70                       ; present the part to the operator
M30
%
