; GoSub resolves against macro.cnc beside the job, ignoring case.
GoSub probe_tool
GoSub PROBE_TOOL
GoSub measure_all        ; expect: S208
G0 X[#100] Y[#101]       ; written in macro.cnc: not reported
G0 Z[#102]               ; expect: V302
M30
