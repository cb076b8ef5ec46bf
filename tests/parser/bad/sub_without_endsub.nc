G0 X0
Sub change_tool
  G0 Z0
