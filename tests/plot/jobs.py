"""Small jobs whose pictures are known: a square contour, a circle, a rapid, two tools."""
from __future__ import annotations

from pathlib import Path

SQUARE = """\
(square.nc: a 50 mm square contour, X10..60 Y10..60, cut 1 mm deep)
G17 G21 G90 G94
T1 M6
G0 X10 Y10 Z5
G1 Z-1 F300
G1 X60 F1000
Y60
X10
Y10
G0 Z5
M30
"""

CIRCLE = """\
G17 G21 G90
T3 M6
G0 X70 Y40 Z2
G1 Z-1 F200
G2 X70 Y40 I-30 J0 F800   ; full circle, radius 30, centre X40 Y40
G0 Z2
G0 X0 Y0                   ; a long rapid back to the work zero
M30
"""

TWO_TOOLS = """\
G21 G90
T1 M6
G0 X0 Y0 Z2
G1 Z-1 F100
G1 X20
G0 Z2
T2 M6
G0 X40 Y0
G1 Z-2 F100
G1 Y20
G0 Z10
M30
"""


def write(folder: Path, name: str, text: str, newline: str = "\n") -> Path:
    path = folder / name
    path.write_bytes(text.replace("\n", newline).encode("latin-1"))
    return path
