"""Speed and memory of parsing and running big jobs, side by side with LinuxCNC's rs274.

Generates the jobs deterministically in a temporary folder, runs ``ecnc`` (on the compiled core and,
with ``ECNC_PURE_PYTHON=1``, on the Python core) and ``rs274 -g`` alternately ``--repeat`` times and
prints medians of CPU and wall time, ratios and peak memory (max RSS of the child process) as a
table.  rs274 writes its canonical calls into a file, as ecnc writes its trace (issue 42's method), and, the
stricter figure in brackets, into /dev/null.  rs274 is optional: without it the reference column stays empty.

    python benchmarks/bench_run.py               # all benchmarks
    python benchmarks/bench_run.py --only parse  # one of: parse run run1m macro startup comp cam arcs ijarcs rarcs drill
"""
from __future__ import annotations

import argparse
import math
import os
import random
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

HERE = Path(__file__).resolve().parent


def write_g1_job(path: Path, lines: int, ngc: bool = False) -> None:
    """A 3D-surfacing style job: G1 X Y Z lines with three decimals (seeded, deterministic)."""
    rng = random.Random(1)
    with open(path, "w") as out:
        out.write("G21 G17 G90 G94 F1000\n")
        for _ in range(lines):
            out.write(f"G1 X{rng.uniform(0, 300):.3f} Y{rng.uniform(0, 200):.3f} Z{rng.uniform(-5, 0):.3f}\n")
        out.write("M2\n")


def write_comp_job(path: Path, lines: int) -> None:
    """A spiral contour cut with cutter compensation (G41.1, 2 mm tool): every corner is computed."""
    with open(path, "w") as out:
        out.write("G21 G17 G90 G94 F1000\nG0 X-10 Y0\nG41.1 D2\nG1 X0 Y0\n")
        for i in range(1, lines + 1):
            angle, grow = i * 0.01, 1 + i * 1e-5
            out.write(f"G1 X{100 * math.cos(angle) * grow:.3f} Y{100 * math.sin(angle) * grow:.3f}\n")
        out.write("G40\nG1 X0 Y0\nM2\n")


def write_cam_job(path: Path, lines: int, ngc: bool = False, arcs: float = 0.1) -> None:
    """A CAM finishing pass as post-processors write it: N words, CRLF (LF for rs274), a tool change,
    G1 XY moves with an occasional F, a share ``arcs`` of I/J arcs (a tenth; an adaptive clearing path has
    far more), now and then a lift (seeded, deterministic)."""
    rng = random.Random(9)
    out = ["G21 G17 G90 G94 G40 G49 G80", "T1 M6", "S12000 M3", "G0 X0 Y0 Z5", "G1 Z-1 F300"]
    number, x, y = 10, 0.0, 0.0
    while len(out) < lines:
        number = number + 2 if number < 99_990 else 10  # N words go up to N99999 (a longer job starts again)
        draw = rng.random()
        if draw < arcs:
            nx, ny = x + rng.uniform(-5, 5), y + rng.uniform(-5, 5)
            out.append(f"N{number} G{rng.choice([2, 3])} X{nx:.4f} Y{ny:.4f} I{(nx - x) / 2:.4f} J{(ny - y) / 2:.4f}")
            x, y = nx, ny
        elif draw < arcs + 0.02:
            out += [f"N{number} G0 Z5.", f"N{number + 1} X{x:.4f} Y{y:.4f}", f"N{number + 2} G1 Z-1. F300"]
            number += 2
        else:
            x, y = min(300.0, max(0.0, x + rng.uniform(-3, 3))), min(200.0, max(0.0, y + rng.uniform(-3, 3)))
            feed = f" F{rng.choice([800, 1200, 1500])}" if rng.random() < 0.05 else ""
            out.append(f"N{number} G1 X{x:.4f} Y{y:.4f}{feed}")
    out += ["G0 Z5", "M5", "M30"]
    with open(path, "w", newline="") as handle:
        handle.write(("%\n" + "\n".join(out) + "\n%\n") if ngc else "\r\n".join(out) + "\r\n")


def write_macro_loop(path: Path, iterations: int, ngc: bool) -> None:
    """The same arithmetic loop as an EdingCNC While and as a LinuxCNC O-word while."""
    body = ["#2 = [[#2 + #1 * 0.5] MOD 97]", "G1 X[#2] Y[#1 MOD 50] Z[-#2 / 10]", "#1 = [#1 + 1]"]
    if ngc:
        lines = ["G21 G90 F1000", "#1 = 0", "#2 = 0", f"o100 while [#1 LT {iterations}]", *body,
                 "o100 endwhile", "M2"]
    else:
        lines = ["G21 G90 F1000", "#1 = 0", "#2 = 0", f"While [#1 < {iterations}]", *body, "EndWhile", "M2"]
    path.write_text("\n".join(lines) + "\n")


# Commands run from a neutral folder, so ``python -m edingcnc_lang`` imports the installed package
# (from the repo root it would import the source tree next to it), and with bytecode caching on as
# in a normal install (some environments switch it off with PYTHONDONTWRITEBYTECODE).
NEUTRAL_CWD = tempfile.gettempdir()
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}


# rs274 -g prints its canonical calls: the reference writes them into this file, as ecnc writes its trace into
# one (issue 42's method: "rs274 writing into a file as ecnc writes its trace"); the same run into /dev/null is
# shown beside it, the stricter figure.
REF_OUT = os.path.join(NEUTRAL_CWD, f"bench-run-rs274-{os.getpid()}.txt")


def measure(cmd: list[str], env: dict[str, str] | None = None, out: str = os.devnull) -> tuple[float, float, float]:
    """Wall seconds, CPU seconds (user + sys) and peak RSS (MB) of one run of ``cmd``, its output into ``out``."""
    start = time.perf_counter()
    with open(out, "wb") as stdout:
        proc = subprocess.Popen(cmd, stdout=stdout, stderr=subprocess.PIPE, cwd=NEUTRAL_CWD,
                                env={**ENV, **(env or {})})
        _, _, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if proc.stderr:
        proc.stderr.close()
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024.0


PURE = {"ECNC_PURE_PYTHON": "1"}  # the pure-Python core (docs/performance.md)


def median_runs(cmds: dict[str, list[str]], repeat: int, envs: dict[str, dict[str, str]] | None = None,
                outs: dict[str, str] | None = None) -> dict[str, tuple[float, float, float]]:
    """Run the commands alternately; median wall and CPU time and max RSS for each."""
    results: dict[str, list[tuple[float, float, float]]] = {name: [] for name in cmds}
    for _ in range(repeat):
        for name, cmd in cmds.items():
            results[name].append(measure(cmd, (envs or {}).get(name), (outs or {}).get(name, os.devnull)))
    return {name: (statistics.median(w for w, _, _ in runs), statistics.median(c for _, c, _ in runs),
                   max(m for _, _, m in runs)) for name, runs in results.items()}


ECNC = [sys.executable, "-m", "edingcnc_lang"]
# The installed console script, as users start it (no runpy); -m where there is none.
_SCRIPT = Path(sys.executable).with_name("ecnc")
ECNC_SCRIPT = [str(_SCRIPT)] if _SCRIPT.exists() else ECNC


def bench_parse(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    job = tmp / "g1_200k.nc"
    write_g1_job(job, 200_000)
    tree = [sys.executable, "-c", "import sys; from edingcnc_lang.syntax.parser import read_statements\n"
            "for _ in read_statements(sys.argv[1]): pass", str(job)]
    res = median_runs({"check": ECNC + ["parse", str(job)], "tree": tree}, repeat)
    rows = []
    for key, label in (("check", "ecnc parse (syntax check), 200k G1 lines"),
                       ("tree", "AST for every line (read_statements), 200k G1 lines")):
        wall, _cpu, rss = res[key]
        rows.append((label, f"{wall:.2f} s ({200_000 / wall:,.0f} lines/s)", f"{rss:.0f} MB peak", ""))
    return rows


def _versus(label: str, ours: list[str], ref: list[str] | None, repeat: int) -> list[tuple[str, str, str, str]]:
    """``ours`` on the compiled core and on the Python core, and the reference (into a file, and into /dev/null),
    run in turn; CPU time ratios (on a shared machine the CPU time of a run varies less than its wall time)."""
    cmds = {"ecnc": ours, "pure": ours, **({"rs274": ref, "rs274-null": ref} if ref else {})}
    res = median_runs(cmds, repeat, {"pure": PURE}, {"rs274": REF_OUT})
    rows = []
    for name, core in (("ecnc", "compiled core"), ("pure", "Python core")):
        wall, cpu, rss = res[name]
        if ref:
            ref_wall, ref_cpu, ref_rss = res["rs274"]
            null_cpu = res["rs274-null"][1]
            rows.append((f"{label} ({core})", f"{cpu:.2f} s CPU, {wall:.2f} s wall, {rss:.0f} MB",
                         f"{ref_cpu:.2f} s CPU ({null_cpu:.2f} s into /dev/null), {ref_wall:.2f} s wall, {ref_rss:.0f} MB",
                         f"{cpu / ref_cpu:.2f}x CPU ({cpu / null_cpu:.2f}x), {wall / ref_wall:.2f}x wall"))
        else:
            rows.append((f"{label} ({core})", f"{cpu:.2f} s CPU, {wall:.2f} s wall, {rss:.0f} MB", "-", "-"))
    return rows


def bench_run(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    job, ngc = tmp / "g1_200k.nc", tmp / "g1_200k.ngc"
    write_g1_job(job, 200_000)
    write_g1_job(ngc, 200_000, ngc=True)
    rs274 = shutil.which("rs274")
    trace = tmp / "trace.csv"
    return _versus("run 200k G1 lines (--trace CSV) vs rs274 -g", ECNC_SCRIPT + ["run", str(job), "--trace", str(trace)],
                   [rs274, "-g", str(ngc)] if rs274 else None, repeat)


def bench_comp(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    job, ngc = tmp / "comp_50k.nc", tmp / "comp_50k.ngc"
    write_comp_job(job, 50_000)
    write_comp_job(ngc, 50_000)
    rs274 = shutil.which("rs274")
    return _versus("run a 50k-segment contour with G41.1 compensation (--trace CSV) vs rs274 -g",
                   ECNC_SCRIPT + ["run", str(job), "--trace", str(tmp / "trace.csv")],
                   [rs274, "-g", str(ngc)] if rs274 else None, repeat)


def _versus_cam(tmp: Path, repeat: int, arcs: float) -> list[tuple[str, str, str, str]]:
    """The 200k-line CAM job with a share ``arcs`` of arcs, with --trace, beside rs274 -g."""
    job, ngc = tmp / f"cam_{arcs:g}.nc", tmp / f"cam_{arcs:g}.ngc"
    write_cam_job(job, 200_000, arcs=arcs)
    write_cam_job(ngc, 200_000, ngc=True, arcs=arcs)
    rs274 = shutil.which("rs274")
    return _versus(f"run a 200k-line CAM job, {arcs:.0%} arcs (--trace CSV) vs rs274 -g",
                   ECNC_SCRIPT + ["run", str(job), "--trace", str(tmp / "trace.csv")],
                   [rs274, "-g", str(ngc)] if rs274 else None, repeat)


def bench_cam(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    return _versus_cam(tmp, repeat, 0.1)


def bench_arcs(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    return _versus_cam(tmp, repeat, 0.6)


def write_arc_job(path: Path, count: int, r_form: bool) -> None:
    """Arcs only, as a contour of small circles writes them: ``count`` half circles along X, with centre words
    or (``r_form``) R words, a third of those over half a circle (R negative) (the same text for rs274)."""
    lines = ["G21 G17 G90 G94", "G0 X0 Y0 Z5", "G1 Z-1 F600"]
    x = 0.0
    for i in range(count):
        if r_form:
            lines.append(f"G{2 if i % 2 else 3} X{x + 2:.4f} Y0 R{1.0 if i % 3 else -1.5}")
        else:
            lines.append(f"G{2 if i % 2 else 3} X{x + 2:.4f} Y0 I1.0 J0")
        x += 2.0
    path.write_text("\n".join([*lines, "M30"]) + "\n")


def write_drill_job(path: Path, holes: int) -> None:
    """A drilling job as CAM writes one: a G81 cycle, then one line of X Y per hole (seeded, deterministic)."""
    rng = random.Random(3)
    lines = ["G21 G17 G90 G94", "G0 X0 Y0 Z5", "S1000 M3", "G98 G81 X1 Y1 Z-2 R1 F300",
             *(f"X{rng.uniform(0, 200):.3f} Y{rng.uniform(0, 200):.3f}" for _ in range(holes)), "G80", "G0 Z5", "M30"]
    path.write_text("\n".join(lines) + "\n")


def _versus_written(tmp: Path, repeat: int, name: str, label: str, write: Callable[[Path], None]) -> list[tuple[str, str, str, str]]:
    """A job ``write`` makes (the same text for both programs), with --trace, beside rs274 -g."""
    job, ngc = tmp / f"{name}.nc", tmp / f"{name}.ngc"
    write(job)
    write(ngc)
    rs274 = shutil.which("rs274")
    return _versus(f"run {label} (--trace CSV) vs rs274 -g", ECNC_SCRIPT + ["run", str(job), "--trace", str(tmp / "trace.csv")],
                   [rs274, "-g", str(ngc)] if rs274 else None, repeat)


def bench_ijarcs(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    return _versus_written(tmp, repeat, "ij_arcs", "100,000 arcs with centre words", lambda p: write_arc_job(p, 100_000, False))


def bench_rarcs(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    return _versus_written(tmp, repeat, "r_arcs", "100,000 R arcs", lambda p: write_arc_job(p, 100_000, True))


def bench_drill(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    """The class as the issue names it, and ten times as many holes: what a hole costs once start-up is paid."""
    return (_versus_written(tmp, repeat, "drill", "20,000 G81 holes", lambda p: write_drill_job(p, 20_000))
            + _versus_written(tmp, repeat, "drill200k", "200,000 G81 holes", lambda p: write_drill_job(p, 200_000)))


def bench_run1m(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    job = tmp / "g1_1m.nc"
    write_g1_job(job, 1_000_000)
    res = median_runs({"ecnc": ECNC_SCRIPT + ["run", str(job), "--trace", str(tmp / "trace.csv")]}, 1)
    wall, cpu, rss = res["ecnc"]
    return [("run 1M G1 lines with --trace (memory)", f"{cpu:.2f} s CPU, {wall:.2f} s wall", f"{rss:.0f} MB peak", "")]


def bench_macro(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    job, ngc = tmp / "loop.nc", tmp / "loop.ngc"
    write_macro_loop(job, 200_000, ngc=False)
    write_macro_loop(ngc, 200_000, ngc=True)
    rs274 = shutil.which("rs274")
    return _versus("While loop, 200k iterations vs O-word while", ECNC + ["run", str(job), "--max-steps", "10000000"],
                   [rs274, "-g", str(ngc)] if rs274 else None, repeat)


def bench_startup(tmp: Path, repeat: int) -> list[tuple[str, str, str, str]]:
    """A three-line job from process start, and its lead over Python alone and Python importing click."""
    job = tmp / "three.nc"
    job.write_text("G0 X1\nG1 Y1 F100\nM30\n")
    trace = tmp / "three.csv"
    res = median_runs({"ecnc": ECNC_SCRIPT + ["run", str(job)], "python": [sys.executable, "-c", "pass"],
                       "click": [sys.executable, "-c", "import click"],
                       "planned": ECNC_SCRIPT + ["run", str(job), "--trace", str(trace)]}, max(repeat * 4, 21))
    ecnc, python, click, planned = (res[name][0] * 1000 for name in ("ecnc", "python", "click", "planned"))
    label = "ecnc run of a three-line job, from process start"
    return [(f"{label} (reference: python -c pass)", f"{ecnc:.0f} ms", f"{python:.0f} ms", f"lead {ecnc - python:.0f} ms"),
            (f"{label} (reference: python -c 'import click')", f"{ecnc:.0f} ms", f"{click:.0f} ms",
             f"lead {ecnc - click:.0f} ms"),
            ("the same with --trace FILE (the trace's t column: planned, in C; numpy on the Python core)", f"{planned:.0f} ms",
             f"{click:.0f} ms", f"lead {planned - click:.0f} ms")]


BENCHES: dict[str, Callable[[Path, int], list[tuple[str, str, str, str]]]] = {
    "parse": bench_parse, "run": bench_run, "run1m": bench_run1m, "macro": bench_macro, "startup": bench_startup,
    "comp": bench_comp, "cam": bench_cam, "arcs": bench_arcs, "ijarcs": bench_ijarcs, "rarcs": bench_rarcs,
    "drill": bench_drill,
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", choices=sorted(BENCHES), action="append")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    rows = [("benchmark", "ecnc", "reference", "ratio")]
    with tempfile.TemporaryDirectory() as folder:
        try:
            for name in args.only or list(BENCHES):
                rows += BENCHES[name](Path(folder), args.repeat)
        finally:
            if os.path.exists(REF_OUT):
                os.remove(REF_OUT)
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    for i, row in enumerate(rows):
        print(" | ".join(cell.ljust(w) for cell, w in zip(row, widths)))
        if i == 0:
            print("-+-".join("-" * w for w in widths))


if __name__ == "__main__":
    main()
