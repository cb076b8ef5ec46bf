%
(Welle mit M16x2 - Radiusprogrammierung)
G18 G21 G90
GoSub params_laengs
GoSub params_gewinde
G28
M30
%
