#!/usr/bin/env python3
"""Compare ``ecnc run`` with LinuxCNC's rs274 on LinuxCNC's own cutter compensation examples.

These programs were written by the LinuxCNC project, not for our tests, so they check that
compensated contours agree beyond the goldens.  They are read from the installed package
(``/usr/share/linuxcnc/ncfiles``; Debian's ``linuxcnc-uspace``) and not copied into this
repository.  Both sides get the same tool table (rs274's in inches, ours as a cnc.ini in mm);
every straight move and arc end point is compared in order (0.002 mm), zero-length moves left out.

    flock /tmp/rs274.lock python scripts/compare_linuxcnc_examples.py
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

from regen_linuxcnc_goldens import MM_PER_INCH, PLANE_NAMES, parse_canon

from edingcnc_lang.canon import Move
from edingcnc_lang.runner import RunOptions, run_file

NCFILES = Path("/usr/share/linuxcnc/ncfiles")
EXAMPLES = ("comp.ngc", "comp-g1.ngc", "comp311.ngc", "comp311_2.ngc",
            "gmoccapy_2_tools_with_cutter_radius_compensation.ngc")
TOOLS_INCH = {1: 0.125, 2: 0.0625, 3: 0.201, 4: 1.0}  # LinuxCNC's sim.tbl, plus the 1" tool comp-g1 asks for
EMPTY_MACRO = Path(__file__).resolve().parent.parent / "tests" / "interpreter" / "data" / "empty_macro.cnc"
ARC_AXES = {"XY": (0, 1, 2), "XZ": (2, 0, 1), "YZ": (1, 2, 0)}
TOLERANCE = 0.002

End = tuple[str, tuple[float, float, float]]


def rs274_moves(program: Path, folder: Path) -> list[End]:
    """The end points rs274 moves to, in mm, in order."""
    table = folder / "sim.tbl"
    table.write_text("".join(f"T{n} P{n} D{d} ;\n" for n, d in TOOLS_INCH.items()))
    out = subprocess.run(["rs274", "-g", "-t", str(table), str(program)], capture_output=True, text=True,
                         check=False, timeout=60).stdout
    scale, plane, moves = 1.0, "XY", []
    for call in parse_canon(out):
        values = [float(a) for a in call.args] if call.name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED",
                                                                   "ARC_FEED") else []
        if call.name == "USE_LENGTH_UNITS":
            scale = MM_PER_INCH if "INCH" in call.args[0] else 1.0
        elif call.name == "SELECT_PLANE":
            plane = PLANE_NAMES[call.args[0]]
        elif call.name == "ARC_FEED":
            end = [0.0, 0.0, 0.0]
            first, second, normal = ARC_AXES[plane]
            end[first], end[second], end[normal] = values[0], values[1], values[5]
            moves.append(("arc", tuple(v * scale for v in end)))
        elif values:
            moves.append(("rapid" if call.name == "STRAIGHT_TRAVERSE" else "linear",
                          tuple(v * scale for v in values[:3])))
    return _without_standstills(moves)  # type: ignore[arg-type]


def ecnc_moves(program: Path, folder: Path) -> list[End]:
    ini = folder / "cnc.ini"
    ini.write_text("".join(f"[TOOL_{n}]\ndiameter = {d * MM_PER_INCH}\n" for n, d in TOOLS_INCH.items()))
    moves: list[Move] = []
    run_file(program, RunOptions(ini=ini, macro=EMPTY_MACRO, on_move=lambda move, _joints: moves.append(move)))
    return _without_standstills([(m.kind, m.end[:3]) for m in moves])  # type: ignore[misc]


def _without_standstills(moves: list[End]) -> list[End]:
    kept: list[End] = []
    for kind, end in moves:
        if kind == "arc" or not kept or max(abs(a - b) for a, b in zip(end, kept[-1][1])) > 1e-9:
            kept.append((kind, end))
    return kept


def main() -> None:
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in EXAMPLES:
            program = NCFILES / name
            if not program.is_file():
                sys.exit(f"{program} not found: install Debian's linuxcnc-uspace")
            theirs, ours = rs274_moves(program, Path(tmp)), ecnc_moves(program, Path(tmp))
            differ = [i for i, (a, b) in enumerate(zip(theirs, ours))
                      if a[0] != b[0] or max(abs(x - y) for x, y in zip(a[1], b[1])) > TOLERANCE]
            ok = not differ and len(theirs) == len(ours)
            failures += not ok
            print(f"{'same' if ok else 'DIFFERENT'}  {name}: rs274 {len(theirs)} moves, ecnc {len(ours)}"
                  + (f"; first difference at move {differ[0] + 1}: {theirs[differ[0]]} / {ours[differ[0]]}"
                     if differ else ""))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
