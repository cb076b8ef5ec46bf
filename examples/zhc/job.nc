; Z height compensation: probe a 5 x 4 grid as the stock zhcmgrid sub does, then engrave a line
; that follows the tilted board.  Run it with a surface to probe:
;   ecnc run examples/zhc/job.nc --probe-surface examples/zhc/surface.csv --trace -
G21 G90 G17
#4100 = 5      ; nx
#4101 = 4      ; ny
#4102 = 5      ; upper Z
#4103 = -5     ; probe to
#4104 = 25     ; grid size
#4105 = 200    ; probe feed
G0 Z[#4102]
G0 X0 Y0
ZHCINIT [#4104] [#4100] [#4101]
#111 = 0
While [#111 < #4101]
  #110 = 0
  While [#110 < #4100]
    G0 Z[#4102]
    G0 X[#110 * #4104] Y[#111 * #4104]
    ; (no simulation guard: with --probe-surface the simulation really probes)
    G38.2 F[#4105] Z[#4103]   ; noqa: G504
    If [#5067 == 1]
      ZHCADDPOINT
    EndIf
    #110 = [#110 + 1]
  EndWhile
  #111 = [#111 + 1]
EndWhile
G0 Z[#4102]
ZHCS zHeightCompTable.txt
ZHCcheck 20
msg "table done " %d
ZHC on
G0 X10 Y10
G1 Z-0.1 F300
G1 X90
G1 Y50
ZHC off
G0 Z5
M30
