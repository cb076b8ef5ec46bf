; reformatted.nc: pocket.nc renumbered, G01 for G1, trailing zeros, comments, an arc and a line split in two, CRLF
%
; pocket.nc -- a 2.5D job: a rounded pocket, four bolt holes and a row of deep holes
;
; Stock 100 x 60 x 20 mm in the vise; work zero (G54) at the front-left corner
; of the top face. Pocket 60 x 30 x 6 mm (X20..80, Y15..45) with 5 mm corner
; radii, roughed in two 3 mm layers leaving 0.3 mm on the walls, then finished.
;   T1  6 mm flat end mill, centre cutting
;   T2  5 mm drill
(MSG pocket.nc: check the vise jaw and the G54 offset before starting)
N10 G17 G21 G40 G49 G80 G90 G94
N20 G10 L2 P1 X100.000 Y50.000 Z-80.000 (vise jaw corner in machine coordinates)
N30 G54

; ---------------------------------------------------------------- T1 pocket
N40 T1 M06
N50 G43 (length offset of the tool in the spindle)
N60 S12000 M03
N70 M08
N80 G00 Z10.000
N90 G00 X35.000 Y30.000
N100 G00 Z1.000

; layer 1: plunge on the centre line, then clockwise rings outwards (G2)
N110 G01 Z-3.000 F300.000
N120 G01 X65.000 F1200.000
N130 X69.000
N140 Y26.000 (ring 8 mm in from the wall path)
N150 X31.000
N160 Y34.000
N170 X69.000
N180 Y30.000
N190 X73.000
N200 Y22.000 (ring 4 mm in)
N210 X27.000
N220 Y38.000
N230 X73.000
N240 Y30.000
N250 X76.7
N260 Y20.000 (roughing contour, 0.3 mm left on the wall)
N270 G02 X76.202082 Y18.797918 I-1.700 J0.000 (first half)
N280 X75.000 Y18.300 I-1.202082 J1.202082
N290 G01 X50.0000 (halfway: Länge 25 mm)
N300 X25.000
N310 G02 X23.3 Y20.000 I0.000 J1.7
N320 G01 Y40.000
N330 G02 X25.000 Y41.7 I1.7 J0.000
N340 G01 X75.000
N350 G02 X76.7 Y40.000 I0.000 J-1.7
N360 G01 Y30.000
N370 G00 Z1.000
N380 G00 X35.000 Y30.000

; layer 2: the same path 3 mm deeper
N390 G01 Z-6.000 F300.000
N400 G01 X65.000 F1200.000
N410 X69.000
N420 Y26.000
N430 X31.000
N440 Y34.000
N450 X69.000
N460 Y30.000
N470 X73.000
N480 Y22.000
N490 X27.000
N500 Y38.000
N510 X73.000
N520 Y30.000
N530 X76.7
N540 Y20.000
N550 G02 X75.000 Y18.3 I-1.7 J0.000
N560 G01 X25.000
N570 G02 X23.3 Y20.000 I0.000 J1.7
N580 G01 Y40.000
N590 G02 X25.000 Y41.7 I1.7 J0.000
N600 G01 X75.000
N610 G02 X76.7 Y40.000 I0.000 J-1.7
N620 G01 Y30.000

; finishing pass at full depth, counter-clockwise (G3 climbs on an inside wall)
N630 G01 X77.000 F600.000
N640 Y40.000
N650 G03 X75.000 Y42.000 I-2.000 J0.000
N660 G01 X25.000
N670 G03 X23.000 Y40.000 I0.000 J-2.000
N680 G01 Y20.000
N690 G03 X25.000 Y18.000 I2.000 J0.000
N700 G01 X75.000
N710 G03 X77.000 Y20.000 I0.000 J2.000
N720 G01 Y30.000
N730 G01 X76.000 (leave the wall before lifting)
N740 G00 Z10.000

; ----------------------------------------------------------- T2 drilling
N750 T2 M06
N760 G43
N770 S3000 M03
N780 M08
N790 G00 Z10.000
N800 G00 X8.000 Y8.000

; bolt holes in the four corners, 8 mm deep; G99 returns to R between holes
N810 G99 G81 X8.000 Y8.000 Z-8.000 R2.000 F200.000
N820 X92.000
N830 Y52.000
N840 G98 X8.000 (last one returns to the start height, Z10)
N850 G80

; five deep holes along the back edge, X30..X70 at 10 mm pitch, 12 mm deep.
; In G91 each repeat (L) moves X by 10; R is measured from Z10, Z from R.
N860 G00 X20.000 Y52.000
N870 G91 G98 G83 X10.000 R-8.000 Z-14.000 Q3 L5 F150.000
N880 G80 G90

; ----------------------------------------------------------------- the end
N890 M05 M09
N900 G00 Z25.000
N910 G00 X0.000 Y70.000 (present the part to the operator)
N920 M30
%
