%
N10 G0 X0 Y0 Z5
n20 g1 x-.5 y+2. z1 f100
G38.2 G91 Z+2
m6t[#5011]
G1X-[#210/2+10]Y[#4104*2]
G[2*1] X1 Y1
/G0 X100 ; skipped with block delete on
N10 G0 Z10 (N numbers may repeat)
G0 X1 ( inline ) Y2 ; trailing comment
%
