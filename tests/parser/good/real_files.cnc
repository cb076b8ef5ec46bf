;@unit mm
; Items seen in published macro files.
Sub probe_angle
  #100 = ATAN[#101]                 ; one operand: the plain arc tangent
  #102 = ATAN[#103]/[#104]          ; two operands where "/[" follows
  #105 = ATAN[1]/2                  ; one operand, then a division
  #106 = [ATAN[1] / [2]]            ; "/[" after ATAN: two operands
  msg "probed at " %d " angle " #100
  logmsg %d ", " #102
  warnmsg "check " %d
  errmsg "failed " %d
EndSub
Sub zhc_commands
  ZHCINIT [10] [5] [4]
  ZHCINITEX [10] [8] [5] [4]
  ZHCADDPOINT
  ZHCS zHeightCompTable.txt
  ZHCL zHeightCompTable.txt
  ZHCcheck 20
  ZHC on
  GetHeightControlVact 3001
  GetHeightControlVset 3002
  Service oilpump
EndSub
