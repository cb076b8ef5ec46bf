"""``ecnc sim`` on a generated 200,000-line 3D finishing job at 0.2 mm, against ``ecnc run`` of it;
``--only turning``: ``ecnc sim --bar`` of a 20,000-line turning job; ``--only wrap``: ``--stock cylinder:`` of a
200,000-line 4-axis wrapping job; each against ``ecnc run --trace``.

The job is a raster finish of a wavy surface (``z = 2 sin(x/8) cos(y/11) - 3``) over 100 x 100 mm
with a 6 mm ball end mill: 200 rows 0.5 mm apart, 1,000 points 0.1 mm apart on each, against
``ecnc run -q`` and ``ecnc run --trace`` of it (the bound: the simulation within 5 times
``run --trace``).  The commands run alternately, ``--repeat`` rounds, medians.  ``--pure`` adds the
simulation on the pure-Python core (numpy's sweep); ``--against CHECKOUT`` adds the simulation of
another checkout of the package (its source folder on PYTHONPATH, its extensions built in place:
``python setup.py build_ext --inplace``), to pair a change with what came before.  Also prints the
memory of the height field of a 1 m x 1 m table at 0.25 mm, and the peak memory of each command.

The wrapping job (``--stock cylinder:40,100,20`` at
0.2 mm, a 3 mm flat end mill with its shank checked, X and A moving together on every line: 200
passes of 1,000 lines, each pass 100 mm along the bar and a turn round it, 1 mm deep), against
``ecnc run --trace`` of it, the commands alternating (the bound: the simulation within 20 times).

The turning job (on examples/lathe/cnc.ini, X a diameter) roughs a 100 x 300 bar from 98 to 62 in
1 mm passes over 190 mm (the ini's Z travel), then follows a wavy contour (``X = 58 + 2 sin(Z/3)``) down to 50 in
five finishing passes of short moves, 20,000 lines in all, at 0.1 mm: once with T1 as its
nose (0.4 mm), once as a 55° insert with its edges and a 25 mm holder (the holder's checks).

    python benchmarks/bench_sim.py [--repeat N] [--rows N] [--pure] [--against CHECKOUT] [--only raster|turning|wrap]

Latest figures (2026-12-05, 2 loaded cores, 5 rounds, CPU medians; docs/performance.md's ``ecnc sim``
table has the rest): ``run`` 0.26 s, ``run --trace`` 0.59 s, ``sim`` 1.98 s (3.3x ``run --trace``;
the code before the compiled sweep, ``--against``: 6.77 s, 11.4x), ``sim`` on the pure-Python core
7.12 s (12.0x).
"""
from __future__ import annotations

import argparse
import math
import tempfile
from pathlib import Path

from bench_run import ECNC, PURE, median_runs


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


def write_turning(path: Path, lines: int = 20_000) -> int:
    """The roughing passes, then finishing passes of the contour filling the rest of ``lines``."""
    out = ["G18 G21 G90 G40", "G97 S1500 M3", "G95 F0.2"]
    for diameter in range(98, 60, -2):
        out += [f"G0 X{diameter} Z2", "G1 Z-190", f"G1 X{diameter + 2}", "G0 Z2"]
    passes = 5
    points = (lines - len(out) - 1 - 3 * passes) // passes
    for k in range(passes):
        offset = 8 - 2 * k
        out.append(f"G0 X{58 + offset:.3f} Z2")
        out += [f"G1 X{58 + offset + 2 * math.sin(z / 3):.4f} Z{z:.4f}"
                for z in (-190 * n / (points - 1) for n in range(points))]
        out += ["G0 X102", "G0 Z2"]
    out.append("M30")
    path.write_text("\n".join(out) + "\n", encoding="ascii")
    return len(out)


def compare(commands: dict[str, list[str]], repeat: int, base: str, bound: int = 5) -> None:
    """Run the commands alternately, ``repeat`` rounds, and print each one's median times and its
    ratio to ``base``."""
    results = median_runs(commands, repeat)
    for name, (wall, cpu, peak) in results.items():
        print(f"{name:>18}: {wall:6.2f} s wall, {cpu:6.2f} s CPU, {peak:5.0f} MB peak")
    for name in commands:
        if name != base:
            print(f"{name} / {base}: {results[name][1] / results[base][1]:.1f}x in CPU time (bound: {bound}x)")


def turning(repeat: int) -> None:
    ini = Path(__file__).resolve().parents[1] / "examples" / "lathe" / "cnc.ini"
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        job, nose, insert = tmp / "turn.nc", tmp / "nose.toml", tmp / "insert.toml"
        count = write_turning(job)
        nose.write_text('[tool.1]\nshape = "insert"\nnose_radius = 0.4\norientation = 2\n', encoding="ascii")
        insert.write_text('[tool.1]\nshape = "insert"\nnose_radius = 0.4\norientation = 2\ninsert_angle = 55\n'
                          'insert_size = 15\nholder_width = 25\n', encoding="ascii")
        bar = ["sim", str(job), "--ini", str(ini), "--bar", "100,300", "--resolution", "0.1", "--tool", "1"]
        print(f"turning: {count:,} lines on a 100 x 300 bar at 0.1 mm")
        compare({"run --trace": ECNC + ["run", "--ini", str(ini), "--trace", str(tmp / "trace.csv"), str(job), "-q"],
                 "sim --bar (nose)": ECNC + [*bar, "--tools", str(nose)],
                 "sim --bar (holder)": ECNC + [*bar, "--tools", str(insert)]}, repeat, "run --trace")


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


def wrap(repeat: int, passes: int) -> None:
    """The wrapping job: ``ecnc sim --stock cylinder:`` and ``run --trace`` alternately."""
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        job, tools = tmp / "wrap.nc", tmp / "tools.toml"
        count = write_wrap(job, passes)
        tools.write_text('[tool.0]\nshape = "flat"\ndiameter = 3\nflute_length = 6\n', encoding="ascii")
        print(f"{count:,} lines (4-axis wrap)")
        compare({"run --trace": ECNC + ["run", "--trace", str(tmp / "trace.csv"), str(job), "-q"],
                 "ecnc sim": ECNC + ["sim", str(job), "--stock", "cylinder:40,100,20", "--resolution", "0.2",
                                     "--tools", str(tools), "--tool", "0"]}, repeat, "run --trace", bound=20)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--rows", type=int, default=200)
    parser.add_argument("--pure", action="store_true", help="also the simulation on the pure-Python core")
    parser.add_argument("--against", metavar="CHECKOUT", help="also the simulation of this checkout of the package")
    parser.add_argument("--only", choices=("raster", "turning", "wrap"))
    args = parser.parse_args()
    if args.only in (None, "turning"):
        turning(args.repeat)
    if args.only in (None, "wrap"):
        wrap(args.repeat, args.rows)
    if args.only in ("turning", "wrap"):
        return
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        job, tools = tmp / "finish.nc", tmp / "tools.toml"
        count = write_job(job, args.rows)
        tools.write_text('[tool.0]\nshape = "ball"\ndiameter = 6\nflute_length = 15\n', encoding="ascii")
        sim = ECNC + ["sim", str(job), "--stock", "-5,-5,-10,105,105,0", "--resolution", "0.2", "--tools", str(tools),
                      "--tool", "0"]
        commands = {"ecnc run": ECNC + ["run", str(job), "-q"],
                    "run --trace": ECNC + ["run", "--trace", str(tmp / "trace.csv"), str(job), "-q"],
                    "ecnc sim": sim}
        envs = {}
        if args.pure:
            commands["sim, pure"], envs["sim, pure"] = sim, PURE
        if args.against:
            commands["sim, against"], envs["sim, against"] = sim, {"PYTHONPATH": str(Path(args.against).resolve())}
        print(f"{count:,} lines, {args.rows * 1000:,} moves")
        results = median_runs(commands, args.repeat, envs)
        for name, (wall, cpu, peak) in results.items():
            print(f"{name:>12}: {wall:6.2f} s wall, {cpu:6.2f} s CPU, {peak:5.0f} MB peak")
        walls = {name: r[0] for name, r in results.items()}
        cpus = {name: r[1] for name, r in results.items()}
        for name in [n for n in commands if n.startswith(("ecnc sim", "sim, "))]:
            print(f"{name} / run: {cpus[name] / cpus['ecnc run']:.1f}x in CPU time, "
                  f"{walls[name] / walls['ecnc run']:.1f}x in wall time; / run --trace: "
                  f"{cpus[name] / cpus['run --trace']:.1f}x in CPU time, "
                  f"{walls[name] / walls['run --trace']:.1f}x in wall time (bound: 5x)")
    cells = round(1000 / 0.25) ** 2
    print(f"1 m x 1 m at 0.25 mm: {cells:,} cells, {cells * 4 / 2**20:.0f} MiB of heights "
          f"(float32; a stock read from STL keeps a second copy for the volumes)")


if __name__ == "__main__":
    main()
