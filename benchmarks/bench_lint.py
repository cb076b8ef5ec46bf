"""Lint throughput on 30,000 lines of generated macro code (target: under 1 s).

The code is generated deterministically (fixed seed) in the style of real
macro files: subs with If/While blocks, assignments, expressions, messages,
dialogs, guarded probing, G-code moves and comments.  Prints the wall time of
``lint_paths`` and, separately, how much of it the parser takes.

    PYTHONPATH=. python3 benchmarks/bench_lint.py [LINES]
"""
from __future__ import annotations

import random
import sys
import tempfile
import time
from pathlib import Path

from edingcnc_lang.lint import lint_paths
from edingcnc_lang.lint.model import load_source

SEED = 20240501


def _sub(rng: random.Random, number: int) -> list[str]:
    """One sub of 20..40 lines; variables #1000+ are assigned before they are read."""
    base = 1000 + 3 * (number % 900)
    a, b, c = base, base + 1, base + 2
    lines = [f"Sub user_macro_{number}", f"    ; generated sub {number}: moves, maths and checks",
             f"    #{a} = {rng.randint(1, 50)}", f"    #{b} = [#{a} * {rng.uniform(0.5, 2):.3f} + #4000]",
             f"    #{c} = 0"]
    for _ in range(rng.randint(3, 6)):
        kind = rng.randrange(6)
        if kind == 0:
            lines += [f"    While [#{c} < #{a}]",
                      f"        G1 X[#{c} * 2.5] Y[SIN[#{c} * 10] * #{b}] F[#4001 + 100]",
                      f"        #{c} = [#{c} + 1]", "    EndWhile"]
        elif kind == 1:
            lines += [f"    If [[#{a} > {rng.randint(0, 40)}] and [#{b} <> 0]]",
                      f"        msg \"value \"#{a}\" ok\"", "    Else",
                      f"        warnmsg \"value \"#{b}\" is low\"", "    EndIf"]
        elif kind == 2:
            lines += ["    If [[#5380 == 0] and [#5397 == 0]]",
                      f"        G38.2 G91 Z-[#4013 + {rng.randint(1, 9)}] F[#4001]", "        G90",
                      "        If [#5067 <> 1]", "            errmsg \"probe did not touch\"",
                      "        EndIf", "    EndIf"]
        elif kind == 3:
            x, y = rng.uniform(-100, 100), rng.uniform(-100, 100)
            lines += [f"    G0 X{x:.3f} Y{y:.3f}", f"    G1 Z-{rng.uniform(0, 5):.3f} F{rng.randint(100, 900)}",
                      f"    G2 X{x + 10:.3f} Y{y:.3f} I5 J0", "    G0 Z5"]
        elif kind == 4:
            lines += [f"    dlgmsg \"Setup {number}\" \"Depth\" {a} \"Width\" {b}",
                      "    If [#5398 <> 1]", "        msg \"cancelled\"", "    EndIf"]
        else:
            lines += [f"    #{b} = [ABS[#{a} - #{b}] / 2 + ROUND[#{a} MOD 7]]   ; tidy up",
                      f"    G53 G0 Z[#4012] ; park", f"    M3 S[#{a} * 100]", "    M5"]
    return [*lines, "EndSub", ""]


def generate(folder: Path, total: int) -> Path:
    rng = random.Random(SEED)
    lines = [";@unit mm", "; generated for bench_lint.py", ""]
    number = 0
    while True:
        sub = _sub(rng, number)
        if len(lines) + len(sub) > total:
            break
        lines += sub
        number += 1
    lines += ["; end of the generated subs"] * (total - len(lines))
    path = folder / "macro.cnc"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def main(total: int = 30_000) -> None:
    with tempfile.TemporaryDirectory() as tmp:
        path = generate(Path(tmp), total)
        lines = len(path.read_text(encoding="utf-8").splitlines())
        start = time.perf_counter()
        load_source(path, is_macro=True)
        parse_time = time.perf_counter() - start
        start = time.perf_counter()
        findings = lint_paths([path])
        wall = time.perf_counter() - start
    print(f"lines:       {lines}")
    print(f"findings:    {len(findings)}")
    print(f"lint time:   {wall:.3f} s ({lines / wall:,.0f} lines/s)")
    print(f"parse alone: {parse_time:.3f} s ({100 * parse_time / wall:.0f}% of lint)")
    print(f"target < 1 s: {'met' if wall < 1 else 'NOT met'}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 30_000)
