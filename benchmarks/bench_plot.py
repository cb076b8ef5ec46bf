"""``ecnc plot`` and ``ecnc view`` on generated jobs of 10,000 and 200,000 moves (a tenth of them arcs).

Prints, for each size, the wall time of ``ecnc run --trace`` (the reference: the same job planned and
written out, without a picture), of ``ecnc plot`` and of ``ecnc view``, with their peak memory, and
the size of the HTML page (bounds: under 2 MB for a 10,000-move job, longer jobs thinned to
``--max-moves``; plot and view of 200,000 moves in at most 3 s each).

    python benchmarks/bench_plot.py [--repeat N] [--moves N ...]
"""
from __future__ import annotations

import argparse
import statistics
import tempfile
from pathlib import Path

from bench_run import ECNC, measure


def write_job(path: Path, moves: int) -> None:
    """A zigzag of short cuts, every tenth a half circle, with a tool change half way."""
    lines = ["G21 G90 G17", "T1 M6", "G0 X0 Y0 Z2", "G1 Z-1 F800"]
    for k in range(moves):
        x, y = 0.2 * k, 10.0 * (k % 2)
        if k == moves // 2:
            lines += ["G0 Z5", "T2 M6", f"G0 X{x:.3f} Y{10.0 * (1 - k % 2):.3f}", "G1 Z-1 F800"]
        if k % 10 == 5:
            lines.append(f"G{2 if y else 3} X{x:.3f} Y{y:.3f} R6")
        else:
            lines.append(f"G1 X{x:.3f} Y{y:.3f}")
    lines += ["G0 Z5", "M30"]
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--moves", type=int, nargs="+", default=[10_000, 200_000])
    args = parser.parse_args()
    print(f"{'moves':>8} | {'run --trace':>16} | {'ecnc plot (png)':>16} | {'ecnc view':>16} | {'page':>8}")
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        for moves in args.moves:
            job = tmp / f"zigzag_{moves}.nc"
            write_job(job, moves)
            commands = {"run": ECNC + ["run", "--trace", str(tmp / "t.csv"), str(job)],
                        "plot": ECNC + ["plot", str(job), "-o", str(tmp / "p.png")],
                        "view": ECNC + ["view", str(job), "-o", str(tmp / "v.html")]}
            cells = []
            for name, command in commands.items():
                runs = [measure(command) for _ in range(args.repeat)]
                wall = statistics.median(r[0] for r in runs)
                cells.append(f"{wall:6.2f} s {max(r[2] for r in runs):4.0f} MB")
            size = (tmp / "v.html").stat().st_size / 1e6
            print(f"{moves:>8,} | {cells[0]:>16} | {cells[1]:>16} | {cells[2]:>16} | {size:5.2f} MB")


if __name__ == "__main__":
    main()
