;@unit mm
; ============================================================================
; Turning cycles for the example lathe, driven by dialogs.
;
; Each cycle has a dialog sub that fills its parameters (#1400..#1499) and a
; cycle sub that cuts with them, so a job can also set the parameters itself
; and call the cycle sub directly (see shaft.nc). X values are diameters.
;
;   face_dialog   -> cycle_face      #1400..#1419
;   turn_dialog   -> cycle_turn      #1420..#1449
;   thread_dialog -> cycle_thread    #1450..#1469
;   (a job sets them) cycle_thread_inside #1470..#1479
;   #1499 = 1 once the defaults are filled in
;
; Cancel in any dialog ends the job (M30) before anything moves.
; ============================================================================

Sub lathe_defaults
    If [#1499 <> 1]
        ; facing
        #1400 = 1        ; tool
        #1401 = 62       ; stock diameter
        #1402 = 0        ; end diameter (0 = to the centre)
        #1403 = 1        ; Z of the stock face
        #1404 = 0        ; finished Z
        #1405 = 0.5      ; depth of cut per pass
        #1406 = 180      ; surface speed, m/min
        #1407 = 2500     ; maximum rpm (D)
        #1408 = 0.15     ; feed, mm/rev
        ; OD turning
        #1420 = 1        ; roughing tool
        #1421 = 2        ; finishing tool
        #1422 = 62       ; stock diameter
        #1423 = 50       ; finished diameter
        #1424 = 0        ; Z start
        #1425 = -40      ; Z end
        #1426 = 1.5      ; depth of cut per side
        #1427 = 0.2      ; finishing allowance per side
        #1428 = 200      ; surface speed, m/min
        #1429 = 3000     ; maximum rpm
        #1430 = 0.25     ; roughing feed, mm/rev
        #1431 = 0.08     ; finishing feed, mm/rev
        ; threading
        #1450 = 3        ; tool
        #1451 = 12       ; major diameter
        #1452 = 1.5      ; pitch
        #1453 = 0        ; Z start (thread starts here)
        #1454 = -20      ; Z end
        #1455 = 0.12     ; first cut depth (radial)
        #1456 = 600      ; spindle speed, rpm (threads at a fixed speed)
        #1457 = 2        ; spring passes
        #1458 = 29.5     ; infeed angle
        ; inside threading
        #1470 = 6        ; tool
        #1471 = 20       ; major diameter
        #1472 = 1.5      ; pitch
        #1473 = 0        ; Z start
        #1474 = -15      ; Z end
        #1475 = 0.1      ; first cut depth (radial)
        #1476 = 500      ; spindle speed, rpm
        #1477 = 1        ; spring passes
        #1499 = 1
    EndIf
EndSub

; ------------------------------------------------------------------ facing --

Sub face_dialog
    GoSub lathe_defaults
    dlgmsg "Facing" "Tool" 1400 "Stock diameter" 1401 "End diameter" 1402 "Z of stock face" 1403 "Finished Z" 1404 "Depth per pass" 1405 "Surface speed m/min" 1406 "Max rpm" 1407 "Feed mm/rev" 1408
    If [#5398 == -1]
        msg "Facing cancelled"
        M30
    EndIf
    GoSub cycle_face
EndSub

Sub cycle_face
    If [#1405 <= 0]
        errmsg "Facing: the depth per pass must be greater than 0"
    EndIf
    If [#1403 < #1404]
        errmsg "Facing: the stock face Z"#1403" lies below the finished Z"#1404
    EndIf
    If [#1402 >= #1401]
        errmsg "Facing: the end diameter must be smaller than the stock"
    EndIf
    M6 T[#1400]
    G18 G90
    G96 S[#1406] D[#1407] M4
    G4 P1                               ; let the spindle come up to speed
    G95 F[#1408]
    G0 X[#1401 + 4] Z[#1403 + 2]
    #1410 = #1403                       ; Z of the current pass
    While [#1410 > #1404]
        #1410 = [#1410 - #1405]
        If [#1410 < #1404]
            #1410 = #1404
        EndIf
        G0 Z#1410
        G1 X#1402
        G0 Z[#1410 + 1]
        G0 X[#1401 + 4]
    EndWhile
    G94 G97 S500
    M5
EndSub

; -------------------------------------------------------------- OD turning --

Sub turn_dialog
    GoSub lathe_defaults
    dlgmsg "OD turning" "Rough tool" 1420 "Finish tool" 1421 "Stock dia" 1422 "Finished dia" 1423 "Z start" 1424 "Z end" 1425 "Cut per side" 1426 "Allowance" 1427 "Vc m/min" 1428 "Max rpm" 1429 "Rough mm/rev" 1430 "Finish mm/rev" 1431
    If [#5398 == -1]
        msg "OD turning cancelled"
        M30
    EndIf
    GoSub cycle_turn
EndSub

Sub cycle_turn
    If [#1423 >= #1422]
        errmsg "Turning: finished diameter "#1423" is not below the stock "#1422
    EndIf
    If [#1425 >= #1424]
        errmsg "Turning: Z end must lie below Z start (towards the chuck)"
    EndIf
    If [[#1426 <= 0] or [#1427 < 0]]
        errmsg "Turning: depth per side must be > 0 and the allowance >= 0"
    EndIf
    ; roughing, diameter by diameter down to the allowance
    M6 T[#1420]
    G18 G90
    G96 S[#1428] D[#1429] M3
    G4 P1
    G95 F[#1430]
    #1440 = #1422                       ; diameter of the current pass
    #1441 = [#1423 + 2 * #1427]         ; last roughing diameter
    G0 X[#1422 + 2] Z[#1424 + 2]
    While [#1440 > #1441]
        #1440 = [#1440 - 2 * #1426]
        If [#1440 < #1441]
            #1440 = #1441
        EndIf
        G0 X#1440
        G1 Z#1425
        G1 X[#1440 + 1]                 ; 0.5 mm off the shoulder
        G0 Z[#1424 + 2]
    EndWhile
    ; finishing pass with its own tool
    M6 T[#1421]
    G96 S[#1428 * 1.2] D[#1429] M3
    G95 F[#1431]
    G0 X#1423 Z[#1424 + 2]
    G1 Z#1425
    G1 X[#1422 + 1]
    G0 Z[#1424 + 2]
    G94 G97 S500
    M5
EndSub

; --------------------------------------------------------------- threading --

Sub thread_dialog
    GoSub lathe_defaults
    dlgmsg "Thread (external)" "Tool" 1450 "Major diameter" 1451 "Pitch" 1452 "Z start" 1453 "Z end" 1454 "First cut (radial)" 1455 "Spindle rpm" 1456 "Spring passes" 1457 "Infeed angle" 1458
    If [#5398 == -1]
        msg "Threading cancelled"
        M30
    EndIf
    GoSub cycle_thread
EndSub

Sub cycle_thread
    If [#1452 <= 0]
        errmsg "Threading: the pitch must be greater than 0"
    EndIf
    If [[#1453 - #1454] < [2 * #1452]]
        errmsg "Threading: a thread shorter than two pitches?"
    EndIf
    #1460 = [0.6134 * #1452]            ; ISO external thread depth, radial (K)
    #1461 = [#1451 - 2 * #1460]         ; root (minor) diameter, for the message
    If [#1455 >= #1460]
        errmsg "Threading: the first cut is deeper than the thread"
    EndIf
    msg "Thread "#1451" x "#1452": root diameter "#1461
    M6 T[#1450]
    G18 G90
    G97 S[#1456] M3                     ; never thread under G96
    G4 P1
    ; start outside the crest, 3 pitches before the thread: an outside thread
    G0 X[#1451 + 2] Z[#1453 + 3 * #1452]
    ; I the crest diameter, J and K radial depths beyond it (manual 3.6.18)
    G76 P[#1452] Z[#1454] I[#1451] J[#1455] K[#1460] R1.5 Q[#1458] H[#1457] E[#1452] L2
    G0 X[#1451 + 4]
    M5
EndSub

; Inside thread in a bore of the minor diameter: the tool starts inside the
; bore (X below I) and cuts outwards to the major diameter.
;   #1470 tool  #1471 major diameter  #1472 pitch  #1473 Z start  #1474 Z end
;   #1475 first cut (radial)  #1476 rpm  #1477 spring passes
Sub cycle_thread_inside
    If [#1472 <= 0]
        errmsg "Inside thread: the pitch must be greater than 0"
    EndIf
    #1478 = [0.5413 * #1472]            ; ISO internal thread depth, radial (K)
    #1479 = [#1471 - 2 * #1478]         ; the bore: the thread's crest (I)
    M6 T[#1470]
    G18 G90
    G97 S[#1476] M3
    G4 P1
    G0 Z[#1473 + 3 * #1472]
    G0 X[#1479 - 2]                     ; inside the bore
    G76 P[#1472] Z[#1474] I[#1479] J[#1475] K[#1478] Q29.5 H[#1477]
    G0 Z[#1473 + 5]
    M5
EndSub
