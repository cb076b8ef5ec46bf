;@unit mm
msg "Grüße"
G0 X1
