; probe_corner.nc -- find the front-left top corner of the stock with a touch
; probe and make it the work zero of the active coordinate system.
;
; Before starting: probe in the spindle, jogged to about 10 mm in from the left
; and the front edge, a few mm above the top face.
;
; Probing only makes sense on the machine, so it sits behind the simulation
; guard. To watch the probe moves off-line, run it as the machine would:
;   ecnc run --no-simulation examples/probe_corner.nc --trace probe.csv
; (the simulated probe touches at the end of each search move).

#27 = 2.0          ; probe ball diameter (mm)
#28 = 100          ; probe feed (mm/min)
#29 = 25           ; longest search move (mm)
#30 = [#27 / 2]    ; ball radius

G17 G21 G40 G90 G94
If [[#5380 == 0] and [#5397 == 0]]
    If [#5068 == 1]
        errmsg "The probe input is already active: check the probe and its cable"
    EndIf
    warnmsg "Probe above the front-left corner? Press Start to probe"
    GoSub probe_corner
    ; report the new offsets (system n keeps X Y Z at #[5201 + 20 * n] ...)
    #31 = [5201 + 20 * #5220]
    msg "Corner set in work system "#5220": X"#[#31]" Y"#[#31 + 1]" Z"#[#31 + 2]
Else
    msg "Simulation: probing skipped (use --no-simulation to simulate the probe)"
EndIf
M30

Sub probe_corner
    ; ---- Z: touch the top face
    G38.2 G91 Z-[#29] F[#28]
    G90
    If [#5067 <> 1]
        errmsg "Top face not found within "#29" mm"
    EndIf
    G10 L20 P[#5220] Z0             ; the contact point is Z0
    G91 G0 Z5
    G90

    ; ---- X: come from the left, 3 mm below the top face
    G91 G0 X-20
    G0 Z-8
    G38.2 X[#29] F[#28]
    G90
    If [#5067 <> 1]
        errmsg "Left face not found within "#29" mm"
    EndIf
    G10 L20 P[#5220] X-[#30]        ; the ball centre is one radius left of the face
    G91 G0 X-3
    G90 G0 Z5

    ; ---- Y: come from the front, 3 mm below the top face
    G0 X10
    G91 G0 Y-20
    G90 G0 Z-3
    G38.2 G91 Y[#29] F[#28]
    G90
    If [#5067 <> 1]
        errmsg "Front face not found within "#29" mm"
    EndIf
    G10 L20 P[#5220] Y-[#30]
    G91 G0 Y-3
    G90 G0 Z10
    G0 X0 Y0
EndSub
