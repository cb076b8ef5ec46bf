msg "hello"
msg "T"#5011" ok"[#1*2]" mm"
warnmsg "careful: " #5001
errmsg "stop here"
LogMsg ";-----"
logmsg "X=" #5001 " Y=" #5002
dlgmsg "Set up" "width" 27 "depth" 28
logfile "probe;log.txt" 1
logfile probe.txt 0
(MSG this is an operator message)
home x
Home Z
homeTandem y
homeIsEstop on
KIN ON
kin off
KIN CTRL 11 100 -50
KIN CTRL 12 [#1 * 2]
KIN Y2A
KIN y2yaz2zc
tanknife on
TANKNIFE off
PrepareLinDeltaHome
PrepareLinDeltaHome 10
TCAGuard on
ZHC off
LaserEngrave on
ZHCINIT 10 10 5 5
ZHCADDPOINT
ZHCS grid.txt
GetToolInfo first 100
GetToolInfo next 100
modbus s1 f3 a100 n2 v200
GetJobDistance 300
Exec "notepad.exe" "readme.txt"
