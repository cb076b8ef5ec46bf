%
(SHAFT 62 -> 50 WITH M12x1.5 END, EXAMPLE LATHE, X IN DIAMETER)
(run: ecnc run --ini examples/lathe/cnc.ini examples/lathe/shaft.nc --json)
G18 G21 G90 G40
gosub home_all

(face with the cycle, parameters set here instead of in the dialog)
gosub lathe_defaults
#1401 = 62
#1403 = 1
#1404 = 0
gosub cycle_face

(OD roughing and finishing of the 50 mm diameter, 40 mm long)
#1422 = 62
#1423 = 50
#1424 = 0
#1425 = -40
gosub cycle_turn

(12 mm spigot, turned by hand-written blocks at constant surface speed)
M6 T2
G96 S220 D3000 M3
G95 F0.1
G0 X54 Z2
G0 X16
G1 Z0
G1 X12 Z-2                 (chamfer)
G1 Z-22
G1 X48
G3 X50 Z-23 R1
G0 X56
G0 Z2

(thread M12x1.5 on the spigot, 20 mm long)
#1451 = 12
#1452 = 1.5
#1453 = 0
#1454 = -20
gosub cycle_thread

(part off at 45 mm, fixed speed)
M6 T4
G97 S700 M3
G95 F0.05
G0 X66                     (clear of the 62 mm collar first)
G0 Z-48
G1 X2
G0 X60
G94 M5
G28
M30
%
