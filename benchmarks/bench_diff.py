"""``ecnc diff`` on two generated 300,000-line jobs, against running both (the issue's bound: at most 2x).

OLD is a zigzag of short cuts with a half circle every tenth move (``bench_plot.write_job``); the
pairs compared are OLD with a reformatted copy of itself (N words, G01, trailing zeros: the same)
and OLD with an edited copy (a lead-in inserted half way, one feed changed, one cut moved 0.05 mm), and
OLD against itself reversed (the moves' lines in the opposite order: no move identical, so nothing to
anchor on; ``--reversed-lines`` long, 20,000 by default).
Prints the wall and CPU time and peak memory of ``ecnc run --json`` (planned: the time estimate the diff
reports too) of each job, of ``ecnc diff`` of each pair, and the ratios diff / (run OLD + run NEW) (CPU
time too: on a loaded machine the wall time says more about the others).

    python benchmarks/bench_diff.py [--lines N] [--repeat N]
    python benchmarks/bench_diff.py --scaling 4    # OLD against itself reversed at 1, 2, 4, 8 times
                                                   # --reversed-lines: linear when the time per move stays flat
    python benchmarks/bench_diff.py --against CHECKOUT --repeat 3   # each diff alternately with another
                                                   # checkout's (its source folder on PYTHONPATH, extensions built in place)
"""
from __future__ import annotations

import argparse
import re
import statistics
import tempfile
from collections.abc import Callable
from pathlib import Path

from bench_plot import write_job
from bench_run import ECNC, measure

Timing = tuple[float, float, float]


def reformat(old: Path, new: Path) -> None:
    """The same job as another post-processor might write it."""
    out = []
    for number, line in enumerate(old.read_text(encoding="ascii").splitlines(), start=1):
        line = re.sub(r"\bG([0-3])\b", r"G0\1", line)
        line = re.sub(r"([XYZR]-?\d+)(?=\s|$)", r"\1.000", line)
        out.append(f"N{number % 10_000 * 10} {line}")  # at most five digits (E115)
    new.write_text("\n".join(out) + "\n", encoding="ascii")


def edit(old: Path, new: Path) -> None:
    """A lead-in half way, a feed changed, one cut moved 0.05 mm in Y."""
    lines = old.read_text(encoding="ascii").splitlines()
    middle = len(lines) // 2
    while not (lines[middle].startswith("G1 X") and lines[middle - 1].startswith("G1 X")):
        middle += 1
    x, y = (float(v) for v in re.findall(r"[XY](-?[\d.]+)", lines[middle - 1])[:2])
    lines.insert(middle, f"G1 X{x + 0.1:.3f} Y{y + 0.3:.3f}")  # the lead-in
    lines.insert(middle + 1, f"G1 X{x:.3f} Y{y:.3f}")
    quarter = len(lines) // 4
    while not lines[quarter].startswith("G1 X"):
        quarter += 1
    lines[quarter] += " F900"
    lines[quarter + 1] += " F800"
    three = 3 * len(lines) // 4
    while not lines[three].startswith("G1 X") or "Y0.000" not in lines[three]:
        three += 1
    lines[three] = lines[three].replace("Y0.000", "Y0.050")
    new.write_text("\n".join(lines) + "\n", encoding="ascii")


def reverse(old: Path, new: Path, lines: int) -> None:
    """The moves of the job's first ``lines`` lines driven backwards, last first (each arc the other way
    round): the same path, no move the same as OLD's."""
    text = old.read_text(encoding="ascii").splitlines()
    head, points, moves = text[:4], [(0.0, 0.0)], []
    for line in text[4:lines]:
        found = re.match(r"G([123]) X(-?[\d.]+) Y(-?[\d.]+)(.*)", line)
        if found:
            points.append((float(found.group(2)), float(found.group(3))))
            moves.append((found.group(1), found.group(4)))
    out = head + [f"G1 X{points[-1][0]:.3f} Y{points[-1][1]:.3f}"]
    for (word, rest), (x, y) in zip(moves[::-1], points[-2::-1]):
        word = {"2": "3", "3": "2"}.get(word, word)
        out.append(f"G{word} X{x:.3f} Y{y:.3f}{rest}")
    new.write_text("\n".join(out + ["G0 Z5", "M30"]) + "\n", encoding="ascii")


def scaling(tmp: Path, old: Path, lines: int, steps: int, timed: Callable[..., Timing]) -> None:
    """The reversed pair at ``lines``, twice as many, ...: CPU microseconds per move of the diff and of running
    both jobs; a diff that is linear in the moves whatever their order keeps its figure flat."""
    for step in range(steps):
        count = lines << step
        forward, backward = tmp / f"forward{count}.nc", tmp / f"reversed{count}.nc"
        reverse(old, backward, count)
        reverse(backward, forward, count + 10)
        moves = sum(1 for line in backward.read_text(encoding="ascii").splitlines() if line.startswith("G"))
        both = timed("run", forward, "--json")[1] + timed("run", backward, "--json")[1]
        wall, cpu, peak = timed("diff", forward, backward, "--json")
        print(f"reversed, {moves:>9,} moves: diff {cpu / moves * 1e6:6.1f} us CPU a move ({cpu:.2f} s, {wall:.2f} s wall, "
              f"{peak:.0f} MB), running both {both / moves * 1e6:6.1f} us a move: {cpu / both:.2f} x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lines", type=int, default=300_000)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--reversed-lines", type=int, default=20_000)
    parser.add_argument("--against", metavar="CHECKOUT", type=Path,
                        help="Time each diff alternately with this checkout's (paired: the ratio after / before).")
    parser.add_argument("--scaling", type=int, default=0,
                        help="Only the reversed pair, at this many sizes from --reversed-lines on, each twice the last.")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        old, same, edited = tmp / "old.nc", tmp / "same.nc", tmp / "edited.nc"
        write_job(old, args.lines)

        def median(runs: list[Timing]) -> Timing:
            return (statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs),
                    max(r[2] for r in runs))

        def timed(*command: object) -> Timing:
            return median([measure([*ECNC, *map(str, command)]) for _ in range(args.repeat)])

        def paired(*command: object) -> tuple[Timing, Timing | None]:
            """This checkout's timing and, with --against, the other's, run alternately."""
            if args.against is None:
                return timed(*command), None
            older = {"PYTHONPATH": str(args.against.resolve())}
            mine, theirs = [], []
            for _ in range(args.repeat):
                mine.append(measure([*ECNC, *map(str, command)]))
                theirs.append(measure([*ECNC, *map(str, command)], older))
            return median(mine), median(theirs)

        if args.scaling:
            scaling(tmp, old, args.reversed_lines, args.scaling, timed)
            return
        reformat(old, same)
        edit(old, edited)
        forward, backward = tmp / "forward.nc", tmp / "reversed.nc"
        reverse(old, backward, args.reversed_lines)
        reverse(backward, forward, args.reversed_lines + 10)  # the same moves forwards, as the reversed job starts

        runs = {job.name: timed("run", job, "--json") for job in (old, same, edited, forward, backward)}
        for name, (wall, cpu, peak) in runs.items():
            print(f"ecnc run --json {name:<11} {wall:7.2f} s wall {cpu:7.2f} s CPU {peak:6.0f} MB")
        for first, job in ((old, same), (old, edited), (forward, backward)):
            (wall, cpu, peak), before = paired("diff", first, job, "--json")
            both, both_cpu = (runs[first.name][k] + runs[job.name][k] for k in (0, 1))
            print(f"ecnc diff {first.name:<10} {job.name:<11} {wall:7.2f} s wall {cpu:7.2f} s CPU {peak:6.0f} MB"
                  f"  = {wall / both:.2f} x running both ({cpu / both_cpu:.2f} x in CPU time)")
            if before is not None:
                print(f"  against {args.against}: {before[0]:7.2f} s wall {before[1]:7.2f} s CPU {before[2]:6.0f} MB"
                      f"  = {before[1] / both_cpu:.2f} x running both in CPU time; after / before {cpu / before[1]:.2f}")


if __name__ == "__main__":
    main()
