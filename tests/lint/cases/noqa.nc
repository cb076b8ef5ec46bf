; noqa silences findings on its line; noqa: CODES only those codes.
G1 X5 F0                 ; noqa
G1 X5 F0                 ; NOQA: G503
G1 X5 F0                 ; noqa: G5
; expect-next-line: G503
G1 X5 F0                 ; noqa: V302, S2
; expect-next-line: G503
G1 X5 F0 M3 M4           ; noqa: G500
M30
