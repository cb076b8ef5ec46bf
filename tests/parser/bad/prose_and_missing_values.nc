Parameter setup for the pocket
G1 X30 Y O30
Pocket1 G1
G1 X[1] Y Z2
