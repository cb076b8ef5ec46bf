#!/usr/bin/env python3
"""Compare ``ecnc run`` with LinuxCNC's rs274 on random cutter-compensated contours.

Programs nobody wrote for the tests: seeded random contours (polygons with arcs between their
corners, in G17 and G18, G90/G91, G20/G21, G55, G41/G42 with tool numbers and G41.1/G42.1 with
diameters) and random near-tangent line/arc chains (kinks under the tangency tolerance, the
hardest case for the corner rules).  Each runs through rs274 (as scripts/regen_linuxcnc_goldens.py
runs it, with tests/golden/linuxcnc/tools.ini) and through our interpreter; they must make the
same moves (0.003 mm) or refuse at the same line.  Disagreements are printed with their seed and
the program is kept in the output folder.  Arcs whose rounded words put start and end more than
our tolerance apart (docs/language.md: 0.002 mm or 0.1 %; LinuxCNC takes 0.0002 in under G20) are
counted apart as "arc tolerance": a known, documented difference, not one of compensation.
LinuxCNC is needed; run it by hand:

    flock /tmp/rs274.lock python scripts/compare_random_comp.py [--seeds 0:300] [--kind both] [--keep DIR]
"""
from __future__ import annotations

import argparse
import math
import random
import re
import sys
import tempfile
from pathlib import Path
from typing import Any, Callable

import regen_linuxcnc_goldens as golden

from edingcnc_lang.canon import Move
from edingcnc_lang.errors import EcncError
from edingcnc_lang.runner import RunOptions, run_file

TOLERANCE = 0.003  # rs274 prints 4 decimals; inch programs convert them
ARC_TOLERANCE_MESSAGE = "start and end are not on one circle"
ERROR_LINE = re.compile(r"^N(\d+)")
Outcome = tuple[str, Any, str]  # ("ok", moves, "") or ("error", line, message)


def polygon_job(rng: random.Random) -> str:
    """A star-shaped polygon whose sides are lines or arcs, in a random frame, units and side."""
    plane = rng.choice(["G17"] * 4 + ["G18"])
    a, b, ci, cj = ("X", "Y", "I", "J") if plane == "G17" else ("X", "Z", "I", "K")
    scale = 1 / golden.MM_PER_INCH if rng.random() < 0.2 else 1.0
    f = lambda v: f"{v * scale:.4f}"  # noqa: E731
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(rng.randint(3, 9)))
    points = [(round(rng.uniform(15, 40) * math.cos(t), 3), round(rng.uniform(15, 40) * math.sin(t), 3)) for t in angles]
    if rng.random() < 0.5:
        points.reverse()
    side = rng.choice(["G41", "G42"])
    comp = f"{side} {rng.choice(['D1', 'D1', 'D3', 'D3', 'D2'])}" if rng.random() < 0.7 else \
        f"{side}.1 {rng.choice(['D2.5', 'D4', 'D8', 'D1'])}"
    lines = ["( random polygon )", f"{'G21' if scale == 1.0 else 'G20'} {plane} G90 G94"]
    if rng.random() < 0.3:
        lines += [f"G10 L2 P2 X{rng.randint(-50, 50)} Y{rng.randint(-50, 50)} Z{rng.randint(-20, 0)}", "G55"]
    x0, y0 = points[0]
    lines += [f"G0 {a}{f(x0 * 2.5)} {b}{f(y0 * 2.5)}", comp, f"G1 {a}{f(x0)} {b}{f(y0)} F{f(500)}"]
    incremental, current = False, points[0]
    for point in points[1:] + [points[0]]:
        if rng.random() < 0.15:
            incremental = not incremental
            lines.append("G91" if incremental else "G90")
        word = (lambda c, c0: f(c - c0)) if incremental else (lambda c, c0: f(c))
        dx, dy = point[0] - current[0], point[1] - current[1]
        if rng.random() < 0.3 and math.hypot(dx, dy) > 1e-3:
            k = rng.uniform(-1.5, 1.5)  # the centre off the chord's middle, either side
            cx, cy = (current[0] + point[0]) / 2 - dy * k / 2, (current[1] + point[1]) / 2 + dx * k / 2
            lines.append(f"{rng.choice(['G2', 'G3'])} {a}{word(point[0], current[0])} {b}{word(point[1], current[1])} "
                         f"{ci}{f(cx - current[0])} {cj}{f(cy - current[1])}")
        else:
            lines.append(f"G1 {a}{word(point[0], current[0])} {b}{word(point[1], current[1])}")
        if rng.random() < 0.1:
            lines.append(f"G1 {'Z' if plane == 'G17' else 'Y'}{f(-0.5 if incremental else rng.uniform(-3, 0))}")
        current = point
    lines += ["G90"] if incremental else []
    lines += ["G40", f"G1 {a}{f(x0 * 2.5)} {b}{f(y0 * 2.5)}", "G54", "G17", "M2"]
    return "\n".join(lines) + "\n"


def tangent_chain_job(rng: random.Random) -> str:
    """Lines and arcs that mostly continue each other's direction, with small and large kinks."""
    scale = 1 / golden.MM_PER_INCH if rng.random() < 0.4 else 1.0
    f = lambda v: f"{v * scale:.4f}"  # noqa: E731
    lines = ["( random tangent chain )", f"{'G21' if scale == 1.0 else 'G20'} G17 G90 G94", "G0 X-30 Y0",
             f"{rng.choice(['G41', 'G42'])} {rng.choice(['D1', 'D3', 'D2'])}", f"G1 X0 Y0 F{f(500)}"]
    x = y = heading = 0.0
    for _ in range(rng.randint(3, 8)):
        heading += rng.choice([0.0, rng.uniform(-0.06, 0.06), rng.uniform(-1.5, 1.5)])
        if rng.random() < 0.5:
            length = rng.uniform(3, 25)
            x, y = x + length * math.cos(heading), y + length * math.sin(heading)
            lines.append(f"G1 X{f(x)} Y{f(y)}")
            continue
        radius, ccw = rng.uniform(4, 30), rng.random() < 0.5
        normal = heading + (math.pi / 2 if ccw else -math.pi / 2)
        cx, cy = x + radius * math.cos(normal), y + radius * math.sin(normal)
        end_angle = math.atan2(y - cy, x - cx) + rng.uniform(0.2, 4.5) * (1 if ccw else -1)
        ex, ey = cx + radius * math.cos(end_angle), cy + radius * math.sin(end_angle)
        lines.append(f"{'G3' if ccw else 'G2'} X{f(ex)} Y{f(ey)} I{f(cx - x)} J{f(cy - y)}")
        x, y, heading = ex, ey, end_angle + (math.pi / 2 if ccw else -math.pi / 2)
    lines += ["G40", f"G1 X{f(x + 30 * math.cos(heading))} Y{f(y + 30 * math.sin(heading))}", "M2"]
    return "\n".join(lines) + "\n"


def theirs(rs274: str, program: Path) -> Outcome:
    result = golden.run_rs274(rs274, program)
    stray = [t for t in result.stdout.splitlines() if t.strip() and not golden.CANON_LINE.match(t)]
    if result.returncode != 0 or stray:
        said = [t.strip() for t in result.stderr.splitlines() if t.strip()]
        line = next((int(m[1]) for t in said for m in [ERROR_LINE.match(t)] if m), None)
        return "error", line, " ".join(said[1:2])
    return "ok", golden.fold(golden.parse_canon(result.stdout)).moves, ""


def ours(program: Path) -> Outcome:
    moves: list[Move] = []

    def keep(move: Move, _joints: object) -> None:
        if math.dist(move.start, move.end) > 1e-9 or move.arc is not None:
            moves.append(move)

    try:
        run_file(program, RunOptions(ini=golden.TOOLS, on_move=keep))
    except EcncError as err:
        return "error", err.location.line if err.location else None, err.message
    return "ok", moves, ""


def _close(a: Any, b: Any) -> bool:
    return all(abs(x - y) <= TOLERANCE for x, y in zip(a, b))


def same_move(mine: Move, ref: dict[str, Any]) -> bool:
    if mine.kind != ref["kind"] or not _close(mine.end, ref["end"]):
        return False
    return ref["kind"] != "arc" or (mine.arc is not None and mine.arc.turn == ref["turn"]
                                    and _close(mine.arc.center, ref["center"]))


def differs(a: Outcome, b: Outcome) -> str:
    """'' when rs274 (``a``) and ecnc (``b``) agree, else what differs."""
    if a[0] == b[0] == "error":
        return "" if a[1] == b[1] else f"both refuse, rs274 at line {a[1]} ({a[2]}), ecnc at {b[1]} ({b[2]})"
    if a[0] != b[0]:
        return f"rs274 {a[0]} {a[2]} / ecnc {b[0]} {b[2]}"
    bad = next((i for i, (m, r) in enumerate(zip(b[1], a[1])) if not same_move(m, r)), None)
    if bad is None and len(a[1]) == len(b[1]):
        return ""
    return f"moves differ ({len(a[1])} / {len(b[1])}), first at move {bad}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", default="0:300", help="FIRST:END, the seeds of each kind")
    parser.add_argument("--kind", choices=("polygon", "tangent", "both"), default="both")
    parser.add_argument("--keep", type=Path, help="folder for the programs that disagree (default: a temporary one)")
    args = parser.parse_args()
    first, end = (int(v) for v in args.seeds.split(":"))
    kinds: dict[str, Callable[[random.Random], str]] = {"polygon": polygon_job, "tangent": tangent_chain_job}
    chosen = list(kinds) if args.kind == "both" else [args.kind]
    rs274 = golden.find_rs274()
    counts = {"same moves": 0, "same refusal": 0, "arc tolerance": 0, "different": 0}
    with tempfile.TemporaryDirectory() as tmp:
        keep = args.keep or Path(tmp)
        keep.mkdir(parents=True, exist_ok=True)
        for kind in chosen:
            for seed in range(first, end):
                program = keep / f"{kind}_{seed}.ngc"
                program.write_text(kinds[kind](random.Random(seed)))
                a, b = theirs(rs274, program), ours(program)
                problem = differs(a, b)
                if problem and b[0] == "error" and b[2].startswith(ARC_TOLERANCE_MESSAGE):
                    counts["arc tolerance"] += 1
                    continue
                if problem:
                    counts["different"] += 1
                    print(f"{kind} seed {seed}: {problem}")
                    continue
                counts["same refusal" if a[0] == "error" else "same moves"] += 1
                program.unlink()
    print(", ".join(f"{v} {k}" for k, v in counts.items()))
    sys.exit(1 if counts["different"] else 0)


if __name__ == "__main__":
    main()
