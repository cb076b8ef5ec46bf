%
(A 40 MM BAR TURNED TO A STEPPED PIN, ON THE EXAMPLE LATHE, X IN DIAMETER)
(ecnc sim --ini examples/lathe/cnc.ini examples/round/bar.nc --bar 40,80,1 --chuck 25)
(   --tools examples/round/bar-tools.toml -o bar.png --stl bar.stl)
G18 G21 G90 G40
M6 T1
G97 S1200 M3
G95 F0.15
(face 1 mm off the end in two passes, past the axis)
G0 X44 Z0.5
G1 X-1
G0 Z2
G0 X44
G0 Z0
G1 X-1
G0 Z2
(rough 40 -> 30 over 35 mm in 1 mm passes)
#1 = 38
while [#1 >= 30]
  G0 X[#1] Z2
  G1 Z-35
  G1 X[#1 + 2]
  G0 Z2
  #1 = [#1 - 2]
endwhile
(25 mm spigot 15 long with a 1 mm chamfer, then a groove)
G0 X23 Z2
G1 Z0
G1 X25 Z-1
G1 Z-15
G1 X30
G0 X44
G0 Z-25
G1 X26 F0.05
G0 X44
G0 Z2
M5
M30
%
