%
(A ROUGHING PASS DEEPER THAN THE INSERT'S EDGES: ECNC SIM FINDS THE HOLDER AT ITS LINE)
(ecnc sim --ini examples/lathe/cnc.ini examples/round/deep.nc --bar 40,60,1 --chuck 20)
(   --tools examples/round/insert-tools.toml -o deep.png)
G18 G21 G90 G40
M6 T1
G97 S1200 M3
G95 F0.15
(face 0.5 mm off the end, then a 2 mm pass: both within the edges)
G0 X44 Z0.5
G1 X-1
G0 Z2
G0 X36
G1 Z-30
G1 X40
G0 Z2
(the mistake: from 36 to 8 in one pass, 14 mm deep against 11.5 mm of edge)
G0 X8
G1 Z-12
G1 X40
G0 X44 Z2
M5
M30
%
