"""``ecnc sim`` on a generated 200,000-line 3D finishing job at 0.2 mm, against ``ecnc run`` of it.

The job is a raster finish of a wavy surface (``z = 2 sin(x/8) cos(y/11) - 3``) over 100 x 100 mm
with a 6 mm ball end mill: 200 rows 0.5 mm apart, 1,000 points 0.1 mm apart on each, against
``ecnc run -q`` and ``ecnc run --trace`` of it (the bound: the simulation within 5 times
``run --trace``).  Also prints the memory of the height field of a
1 m x 1 m table at 0.25 mm, and the peak memory of each command.

``--only wrap``: a 200,000-line 4-axis wrapping job instead (``--stock cylinder:40,100,20`` at
0.2 mm, a 3 mm flat end mill with its shank checked, X and A moving together on every line: 200
passes of 1,000 lines, each pass 100 mm along the bar and a turn round it, 1 mm deep), against
``ecnc run --trace`` of it, the commands alternating (the bound: the simulation within 20 times).

    python benchmarks/bench_sim.py [--repeat N] [--rows N] [--only wrap]
"""
from __future__ import annotations

import argparse
import math
import os
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from bench_run import ECNC, ENV, NEUTRAL_CWD


def measure(cmd: list[str]) -> tuple[float, float, float]:
    """Wall seconds, CPU seconds (user + system) and peak RSS (MB) of one run of ``cmd``.  The CPU
    time is the figure to compare on a shared machine: it does not grow with other jobs' load."""
    start = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=NEUTRAL_CWD, env=ENV)
    _, _, usage = os.wait4(proc.pid, 0)
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


def write_job(path: Path, rows: int, points: int = 1000) -> int:
    """The raster finish; returns its number of lines."""
    lines = ["G21 G90 G17", "S18000 M3", "G0 Z5", "G0 X0 Y0"]
    for row in range(rows):
        y = 0.5 * row
        xs = [0.1 * k for k in range(points)] if row % 2 == 0 else [0.1 * k for k in range(points - 1, -1, -1)]
        for x in xs:
            z = 2.0 * math.sin(x / 8.0) * math.cos(y / 11.0) - 3.0
            lines.append(f"G1 X{x:.3f} Y{y:.3f} Z{z:.4f} F3000")
    lines += ["G0 Z5", "M30"]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return len(lines)


def write_wrap(path: Path, passes: int, points: int = 1000) -> int:
    """The wrapping job on the A axis; returns its number of lines."""
    lines = ["G21 G90 G17", "S18000 M3", "G0 Z25", "G0 X20 Y0 A0", "G1 Z19 F1000"]
    for row in range(passes):
        shift = 1.8 * row
        steps = range(points) if row % 2 == 0 else range(points - 1, -1, -1)
        lines += [f"G1 X{20 + 0.1 * k:.3f} A{shift + 0.36 * k:.3f} F3000" for k in steps]
    lines += ["G0 Z25", "M30"]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")
    return len(lines)


def bench_wrap(tmp: Path, repeat: int, passes: int) -> None:
    """The wrapping job: ``ecnc sim --stock cylinder:`` and ``run --trace`` alternately."""
    job, tools = tmp / "wrap.nc", tmp / "tools.toml"
    count = write_wrap(job, passes)
    tools.write_text('[tool.0]\nshape = "flat"\ndiameter = 3\nflute_length = 6\n', encoding="ascii")
    commands = {"run --trace": ECNC + ["run", "--trace", str(tmp / "trace.csv"), str(job), "-q"],
                "ecnc sim": ECNC + ["sim", str(job), "--stock", "cylinder:40,100,20", "--resolution", "0.2",
                                    "--tools", str(tools), "--tool", "0"]}
    runs: dict[str, list[tuple[float, float, float]]] = {name: [] for name in commands}
    print(f"{count:,} lines (4-axis wrap)")
    for _ in range(repeat):  # alternating: the machine's load falls on both alike
        for name, command in commands.items():
            runs[name].append(measure(command))
    for name, results in runs.items():
        print(f"{name:>11}: {statistics.median(r[0] for r in results):6.2f} s wall, "
              f"{statistics.median(r[1] for r in results):6.2f} s CPU, {max(r[2] for r in results):5.0f} MB peak")
    cpu = {name: statistics.median(r[1] for r in results) for name, results in runs.items()}
    wall = {name: statistics.median(r[0] for r in results) for name, results in runs.items()}
    print(f"sim / run --trace: {cpu['ecnc sim'] / cpu['run --trace']:.1f}x in CPU time, "
          f"{wall['ecnc sim'] / wall['run --trace']:.1f}x in wall time (bound: 20x)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--rows", type=int, default=200)
    parser.add_argument("--only", choices=["wrap"], help="the 4-axis wrapping job on round stock instead")
    args = parser.parse_args()
    if args.only == "wrap":
        with tempfile.TemporaryDirectory() as folder:
            bench_wrap(Path(folder), args.repeat, args.rows)
        return
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        job, tools = tmp / "finish.nc", tmp / "tools.toml"
        count = write_job(job, args.rows)
        tools.write_text('[tool.0]\nshape = "ball"\ndiameter = 6\nflute_length = 15\n', encoding="ascii")
        commands = {"ecnc run": ECNC + ["run", str(job), "-q"],
                    "run --trace": ECNC + ["run", "--trace", str(tmp / "trace.csv"), str(job), "-q"],
                    "ecnc sim": ECNC + ["sim", str(job), "--stock", "-5,-5,-10,105,105,0", "--resolution", "0.2",
                                        "--tools", str(tools), "--tool", "0"]}
        walls, cpus = {}, {}
        print(f"{count:,} lines, {args.rows * 1000:,} moves")
        for name, command in commands.items():
            runs = [measure(command) for _ in range(args.repeat)]
            walls[name] = statistics.median(r[0] for r in runs)
            cpus[name] = statistics.median(r[1] for r in runs)
            print(f"{name:>11}: {walls[name]:6.2f} s wall, {cpus[name]:6.2f} s CPU, {max(r[2] for r in runs):5.0f} MB peak")
        print(f"sim / run: {cpus['ecnc sim'] / cpus['ecnc run']:.1f}x in CPU time, "
              f"{walls['ecnc sim'] / walls['ecnc run']:.1f}x in wall time")
        print(f"sim / run --trace: {cpus['ecnc sim'] / cpus['run --trace']:.1f}x in CPU time, "
              f"{walls['ecnc sim'] / walls['run --trace']:.1f}x in wall time (bound: 5x)")
    cells = round(1000 / 0.25) ** 2
    print(f"1 m x 1 m at 0.25 mm: {cells:,} cells, {cells * 4 / 2**20:.0f} MiB of heights "
          f"(float32; a stock read from STL keeps a second copy for the volumes)")


if __name__ == "__main__":
    main()
