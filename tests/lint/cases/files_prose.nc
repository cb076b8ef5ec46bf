; Lines of text someone forgot to comment out.
G0 X0
Remember to check the vise first    ; expect: F603
G0 X1 Y2 Z3
M30
