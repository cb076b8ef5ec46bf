%
(M12x1.5 OUTSIDE THREAD ON A SPIGOT, M20x1.5 INSIDE THREAD IN A BUSH, EXAMPLE LATHE, X IN DIAMETER)
(run: ecnc run --ini examples/lathe/cnc.ini examples/lathe/threading.nc)
(G76 as EdingCNC reads it: I the crest diameter, J and K radial depths beyond it;)
(the side comes from where the tool starts: outside the crest or inside the bore)
G18 G21 G90 G40
gosub home_all
gosub lathe_defaults

(outside: the crest is the turned 12 mm diameter, the root 12 - 2 x 0.92 = 10.16)
#1450 = 3          (tool: 16ER 1.5 ISO)
#1451 = 12         (major diameter: the crest)
#1452 = 1.5        (pitch)
#1453 = 0          (Z start)
#1454 = -20        (Z end)
#1455 = 0.12       (first cut, radial)
#1456 = 600        (rpm)
#1457 = 2          (spring passes)
#1458 = 29.5       (infeed angle)
gosub cycle_thread

(inside, the next part: a bush bored to 20 - 2 x 0.81 = 18.38, threaded out to 20)
#1470 = 6          (tool: 16IR 1.5 ISO)
#1471 = 20         (major diameter)
#1472 = 1.5        (pitch)
#1473 = 0          (Z start: the bore's mouth at the face)
#1474 = -15        (Z end)
#1475 = 0.1        (first cut, radial)
#1476 = 500        (rpm)
#1477 = 1          (spring passes)
gosub cycle_thread_inside

G28
M30
%
