; §3.7.12 M106 S (p. 66 "S = 0-100", the table p. 55 "S = 0-255, für 0-100% PWM"): the 0..255 scale (docs/dialect.md)
; manual-event: printer m=106 fan=180.0 unit=0..255
; manual-event: printer m=106 fan=255.0 percent=100.0
; manual-error: L7 the fan value must lie in 0..255
M106 S180
M106
M106 S300
M30
