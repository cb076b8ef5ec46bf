@unit cm
G0 X1
