%
(FACE A 62 MM BAR, 1.5 MM OFF IN 0.5 MM PASSES, EXAMPLE LATHE, X IN DIAMETER)
(run: ecnc run --ini examples/lathe/cnc.ini examples/lathe/facing.nc)
(or with the dialog, as at the User button: gosub face_dialog, ecnc run --answer ok)
G18 G21 G90 G40
gosub home_all

gosub lathe_defaults
#1400 = 1          (tool: the roughing insert)
#1401 = 62         (stock diameter)
#1402 = 0          (face to the centre)
#1403 = 1.5        (Z of the stock face)
#1404 = 0          (finished face: work Z0)
#1405 = 0.5        (depth per pass)
#1406 = 180        (surface speed, m/min)
#1407 = 2500       (maximum rpm under G96)
#1408 = 0.12       (feed, mm/rev)
gosub cycle_face

G28
M30
%
