;* @unit inch
msg "Grüße"
G0 X1
