;@unit mm
; ============================================================================
; edingcnc-lang default macro file
;
; Loaded when neither --macro nor the ini names a macro file. It provides the
; subs the controller calls by name (home_all, home_x .. home_c, change_tool,
; user_1 .. user_11, start, user_reset) and doubles as a tour of the dialect.
;
; Settings kept between runs (#4000..#4999 are stored in cnc.ini [VARIABLES];
; set them with User 2 and User 9):
;   #4000  probe search distance, mm          #4001  probe feed, mm/min
;   #4002  touch plate thickness, mm
;   #4003  park position X, machine coords    #4004  park position Y
;   #4005  tool change position X, machine   #4006  tool change position Y
;   #4010  tool setter X, machine coords      #4011  tool setter Y
;   #4012  machine Z where a zero-length tool touches the setter
;   #4013  tool setter search distance, mm (0 = no automatic measuring)
; Scratch values use #5020..#5029, the range set aside for macros.
;
; Probing and waiting for the operator only make sense on a real machine, so
; those parts sit inside the simulation guard:
;   If [[#5380 == 0] and [#5397 == 0]]   (#5380 simulation, #5397 rendering)
; ============================================================================


; ---------------------------------------------------------------- homing ----

Sub home_all
    ; Z first, so the tool is clear of clamps and stock before X and Y travel
    home z
    home x
    home y
    msg "X, Y and Z are homed"
EndSub

Sub home_x
    home x
EndSub

Sub home_y
    home y
EndSub

Sub home_z
    home z
EndSub

Sub home_a
    home a
EndSub

Sub home_b
    home b
EndSub

Sub home_c
    home c
EndSub


; ----------------------------------------------------------- tool change ----

Sub change_tool
    ; Called by M6 with #5011 = the requested tool and #5008 = the tool in the
    ; spindle. Success is reported through #5015; "M6 T.." at the end commits.
    #5015 = 0
    If [#5011 == #5008]
        msg "Tool "#5011" is already in the spindle"
        #5015 = 1
    Else
        M5                              ; spindle off before anything moves
        M9                              ; and coolant off
        G53 G0 Z0                       ; Z to the top of its travel first
        G53 G0 X[#4005] Y[#4006]        ; then to the tool change position
        msg "Change tool: take out T"#5008", put in T"#5011
        If [[#5380 == 0] and [#5397 == 0]]
            M0                          ; wait until the operator presses Start
            If [#4013 > 0]
                GoSub measure_tool
            EndIf
        EndIf
        #5015 = 1
        M6 T[#5011]
    EndIf
EndSub

Sub measure_tool
    ; Touch the tool on the setter and store its length in the tool table
    ; (#5401..#5499 hold the lengths of tools 1..99).
    If [#4001 <= 0]
        errmsg "Set the probe feed (#4001) with User 2 first"
    EndIf
    G53 G0 Z0
    G53 G0 X[#4010] Y[#4011]
    G38.2 G91 Z-[#4013] F[#4001]
    G90
    If [#5067 <> 1]
        errmsg "The tool setter was not reached within "#4013" mm"
    EndIf
    #[5400 + #5011] = [#5053 - #4012]   ; #5053 = machine Z where it touched
    msg "T"#5011" measured: length "#[5400 + #5011]" mm"
    G53 G0 Z0
EndSub


; ----------------------------------------------------------- user buttons ---

Sub user_1
    ; Zero the work Z on a touch plate lying on the stock.
    If [[#5380 == 0] and [#5397 == 0]]
        If [[#4000 <= 0] or [#4001 <= 0]]
            errmsg "Set the probe distance and feed with User 2 first"
        EndIf
        G38.2 G91 Z-[#4000] F[#4001]    ; search down, stop at contact
        G90
        If [#5067 == 1]
            ; at the trip point (#5063) the work Z is the plate thickness; the probe has backed off since
            G10 L20 P[#5220] Z[#4002 + #5003 - #5063]
            G0 Z[#4002 + 5]             ; lift off the plate
            msg "Work Z set on a "#4002" mm plate"
        Else
            errmsg "No contact within "#4000" mm"
        EndIf
    Else
        msg "Simulation: Z probing skipped"
    EndIf
EndSub

Sub user_2
    ; Edit the probe settings; OK stores the values, Cancel keeps the old ones.
    ; Fields take bare variable numbers (no #) and show the current values.
    dlgmsg "Probe settings" "Search distance (mm)" 4000 "Probe feed (mm/min)" 4001 "Plate thickness (mm)" 4002
    If [#5398 == 1]
        msg "Probe: search "#4000" mm at F"#4001", plate "#4002" mm"
    Else
        msg "Probe settings unchanged"
    EndIf
EndSub

Sub user_3
    ; Park: Z up, then X and Y to the park position (machine coordinates).
    G53 G0 Z0
    G53 G0 X[#4003] Y[#4004]
EndSub

Sub user_4
    ; Remember the current machine position as the park position for User 3.
    #4003 = #5071
    #4004 = #5072
    msg "Park position is now X"#4003" Y"#4004
EndSub

Sub user_5
    ; Spindle warm-up: 30 s at each of 6000, 12000 and 18000 rpm.
    ; (G4 P is in seconds unless cnc.ini sets g4InMilliseconds.)
    #5020 = 6000
    While [#5020 <= 18000]
        msg "Warm-up at "#5020" rpm"
        S[#5020] M3
        G4 P30
        #5020 = [#5020 + 6000]
    EndWhile
    M5
    msg "Warm-up done"
EndSub

Sub user_6
    ; Go to the work zero of the active coordinate system, Z last.
    G53 G0 Z0
    G0 X0 Y0
EndSub

Sub user_7
    ; Show the tool in the spindle and the active work offset.
    ; Work offsets of system n (1 = G54) start at #[5201 + 20 * n].
    If [#5008 > 0]
        msg "T"#5008": length "#[5400 + #5008]" mm, diameter "#[5500 + #5008]" mm"
    Else
        msg "No tool in the spindle"
    EndIf
    #5020 = [5201 + 20 * #5220]
    msg "Work system "#5220": X"#[#5020]" Y"#[#5020 + 1]" Z"#[#5020 + 2]
EndSub

Sub user_8
    ; Safe stop: spindle and coolant off, Z to the top.
    M5 M9
    G53 G0 Z0
    msg "Spindle and coolant off, Z up"
EndSub

Sub user_9
    ; Edit the tool change settings (positions in machine coordinates).
    dlgmsg "Tool change" "Change position X" 4005 "Change position Y" 4006 "Setter X" 4010 "Setter Y" 4011 "Setter Z of 0-length tool" 4012 "Setter search (0 = off)" 4013
    If [#5398 <> 1]
        msg "Tool change settings unchanged"
    EndIf
EndSub

Sub user_10
    ; Append the current work and machine position to positions.txt.
    logfile "positions.txt" 1
    logmsg "work X"#5001" Y"#5002" Z"#5003"  machine X"#5071" Y"#5072" Z"#5073
    msg "Position logged"
EndSub

Sub user_11
    ; Repeatability check: touch the surface three times, show the mean Z.
    If [[#5380 == 0] and [#5397 == 0]]
        If [[#4000 <= 0] or [#4001 <= 0]]
            errmsg "Set the probe distance and feed with User 2 first"
        EndIf
        #5020 = 0                       ; sum of the measured Z values
        #5021 = 0                       ; touches so far
        While [#5021 < 3]
            G38.2 G91 Z-[#4000] F[#4001]
            G90
            If [#5067 <> 1]
                errmsg "No contact within "#4000" mm"
            EndIf
            #5020 = [#5020 + #5063]     ; #5063 = work Z of the contact
            #5021 = [#5021 + 1]
            G91 G0 Z2
            G90
        EndWhile
        msg "Mean surface Z "[#5020 / 3]" after "#5021" touches"
    Else
        msg "Simulation: repeatability check skipped"
    EndIf
EndSub


; ------------------------------------------------------- start and reset ----

Sub start
    ; Called when a job starts: begin from a known modal state. The feed mode (G94/G95) stays
    ; as the ini's initialString sets it: a lathe starts in G95.
    G40 G80 G90
EndSub

Sub user_reset
    ; Called on reset: make sure nothing keeps turning or flowing.
    M5 M9
EndSub
