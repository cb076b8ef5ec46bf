G0 X1 (comment
