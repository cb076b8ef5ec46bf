;***************************************************************************************
;MY SHOP MACRO  V3.1   (based on a vendor macro, translated)
;CHANGELOG
;Added TCAGuard and ZHC handling to tool measurement
;***************************************************************************************
; Variables used
	;	#4100 ;number x points
	;   #4506 Safe Z Height in Machine

(INITIALIZE)
	IF [#3500 == 0]  ; IF [Initialize] is 0  proceed
		#3500 = 1			;set FLAG [initialized]
		IF [#4504 == 0]   	
			#4504 =50	; fast probe feed
		ENDIF
		msg "intialized"
	ENDIF

sub home_all ; HOMING
	gosub home_z
    gosub home_x
    G53 G01 Z#4633 F2000		; Move Z axis to HOME position
    msg"Homing complete"	
    ;homeIsEstop on
    m30
ENDSUB
Sub home_z
    msg "Homing Z Axis"
    M80
    g4p0.2
    home z
ENDSUB
Sub home_x
    home x
ENDSUB

Sub zero_set_rotation
	msg "Move to first point  press control-G to continue"
	m0
	#5020 = #5071 ;x1
	#5021 = #5072 ;y1
	m0
	#5022 = [#5071 + 100] ;x2
	#5023 = [#5072 + 3] ;y2
	#5024 = ATAN[#5023 - #5021]/[#5022 - #5020]
	#5025 = ATAN[[#5023 - #5021] / [#5022 - #5020]]
	IF [#5024 > 45]
       #5024 = [#5024 - 90] ;points are in Y direction
	ENDIF
	g68 R#5024
	#68 = 1
	msg "G68 R"#5024" applied, "#5025" check"
ENDSUB

sub zhcmgrid ; Surface Probing routine
	IF [#4100 == 0]
		#4100 = 4  ;number x points
		#4101 = 3   ;number y points
		#4102 = 10  ;max z height
		#4103 = -5  ;min z height
		#4104 = 10.0 ;X grid
		#4105 = 12.5 ;Y grid
        #4106 = 100 ;probing feed
	ENDIF
	#113 = 0
	#112 = 0
	dlgmsg "Surface Grid Probing" "Number of X points" 4100 "Number of Y points" 4101 "Clearance Z height (WCS)" 4102 "Z Probing (Absolut WCS)" 4103 "X Grid Size" 4104 "Y Grid Size" 4105 "Probe Feedrate" 4106
	IF [#5398 == 1] ; user pressed OK
		G90 ;absolute mode
    	G0 X0 Y0 ;to start point
		G0 z[#4102];to Z clearance height
        ZHCINITEX [#4104] [#4105] [#4100] [#4101] ;define gridSize nx ny
    	#111 = 0
    	WHILE [#111 < #4101]
          	#110 = 0
          	WHILE [#110 < #4100]
            	G0 z[#4102]
            	G0 x[#110 * #4104] y[#111 * #4105]
            	g38.2 F[#4106] z[#4103];probe down until touch
            	IF [#5067 == 1]
            		ZHCADDPOINT
            		msg "nx="[#110 +1]" ny="[#111+1]" added"
            		#113 = [#113+1]
            	ELSE
             		msg "nx="[#110 +1]" ny="[#111+1]" not added"
              		#112 = [#112+1]
            	ENDIF
            	#110 = [#110 + 1]
          	ENDWHILE
      		#111 = [#111 + 1] ;next ny
    	ENDWHILE
		G0 X0 Y0 ;to start point
    	ZHCS zHeightCompTable.txt ;Save measured table
    	msg "Done, "#113" points added, "#112" not added"
    	ZHCcheck 20
  	ELSE
    	msg "Operation canceled"
  	ENDIF
ENDSUB

sub change_tool ; TOOL CHANGE SEQUENCE
	TCAGuard off
    #5019 = #5151
    if [#5019 == 1]
        ZHC off
    endif
    #5015 = 0
    M9
	M5
    Dlgmsg "!!! Tool Update !!!" "Current Tool Number" 5008" New Tool Number" 5011
	G53 G0 Z0
	G90 G53 G0 Z[#4506 + 40]
    G38.2 G91 z-50 F[#4504]
    IF [#5067 == 1]
        G91 G0 Z2
        G90
        msg "Tool " #5008" changed to Tool " #5011 " "
        IF [ [#5017 <= 0] OR [ [#4509 + #5017 + 10] > [#4506] ] ]
            msg "check length"
        ENDIF
    ENDIF
	TCAGuard on
    IF [#5019 == 1]
        ZHC on
    ENDIF
ENDSUB
