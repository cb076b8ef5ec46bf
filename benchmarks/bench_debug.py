"""The cost of the debugger: a 200,000-line job run under ``ecnc debug`` with a breakpoint that is
never hit, against ``ecnc run -q`` of the same job (issue 42's target: at most 1.1x); the time a
``pause`` takes to stop a 1,000,000-line job; and one step back near the end of the job (from a
breakpoint: a search re-run first; after a step: the way back only).

    python benchmarks/bench_debug.py [--lines 200000] [--repeat 5]
    python benchmarks/bench_debug.py --before /tmp/old   # side by side with an older checkout (its
                                                         # extensions built in place), run alternately

``run`` and ``debug`` run alternately (``--repeat`` rounds, a fresh process each, start-up included,
byte-code cached); each figure is the median wall time (for ``debug``: from starting the adapter to
its ``exited`` event) and the median CPU time of the process (user + system, the whole session).
"""
from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, BinaryIO


def write_job(path: Path, lines: int) -> None:
    """CAM-style G1 lines with a tool change and a few macro lines in between (seeded)."""
    rng = random.Random(1)
    with open(path, "w") as out:
        out.write("G21 G90 G94 F1000\nT1 M6\n")
        for i in range(lines):
            if i % 50_000 == 25_000:
                out.write("#1 = [#1 + 1]\n")
            out.write(f"G1 X{rng.uniform(0, 300):.3f} Y{rng.uniform(0, 200):.3f} Z{rng.uniform(-5, 0):.3f}\n")
        out.write("#9 = 1\nM30\nSub never\n    #2 = 1\nEndSub\n")


# as bench_run.py: from a neutral folder (the installed package), byte-code cached
NEUTRAL_CWD = tempfile.gettempdir()
ENV = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
ECNC = [sys.executable, "-m", "edingcnc_lang"]


class Client:
    def __init__(self, env: dict[str, str] | None = None) -> None:
        self.proc = subprocess.Popen([*ECNC, "debug"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     cwd=NEUTRAL_CWD, env={**ENV, **(env or {})})
        self.seq = 0

    def send(self, command: str, **arguments: Any) -> None:
        self.seq += 1
        body = json.dumps({"seq": self.seq, "type": "request", "command": command, "arguments": arguments}).encode()
        stdin: BinaryIO = self.proc.stdin  # type: ignore[assignment]
        stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        stdin.flush()

    def until(self, event: str) -> dict[str, Any]:
        out: BinaryIO = self.proc.stdout  # type: ignore[assignment]
        while True:
            length = 0
            while (line := out.readline().strip()):
                length = int(line.split(b":")[1])
            message = json.loads(out.read(length))
            if message.get("event") == event:
                return message.get("body") or {}

    def start(self, job: Path, breakpoint_line: int) -> None:
        self.send("initialize", adapterID="ecnc")
        self.send("launch", program=str(job))
        self.until("initialized")
        self.send("setBreakpoints", source={"path": str(job)}, breakpoints=[{"line": breakpoint_line}])
        self.send("configurationDone")

    def close(self) -> float:
        """End the session; the CPU seconds (user + system) the adapter's process took."""
        self.send("disconnect")
        stdin: BinaryIO = self.proc.stdin  # type: ignore[assignment]
        stdin.close()
        out: BinaryIO = self.proc.stdout  # type: ignore[assignment]
        out.read()
        _, _, usage = os.wait4(self.proc.pid, 0)
        self.proc.returncode = 0
        return usage.ru_utime + usage.ru_stime


def timed_run(job: Path, env: dict[str, str] | None = None) -> tuple[float, float]:
    """Wall and CPU seconds of ``ecnc run -q``."""
    start = time.perf_counter()
    proc = subprocess.Popen([*ECNC, "run", "-q", str(job)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            cwd=NEUTRAL_CWD, env={**ENV, **(env or {})})
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = 0
    if status:
        raise SystemExit(f"ecnc run failed: status {status}")
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime


def timed_debug(job: Path, never_line: int, env: dict[str, str] | None = None) -> tuple[float, float]:
    """Wall seconds to ``exited`` and CPU seconds of the session, a breakpoint set that is never hit."""
    start = time.perf_counter()
    client = Client(env)
    client.start(job, never_line)  # the breakpoint is in a sub nobody calls
    client.until("exited")
    elapsed = time.perf_counter() - start
    return elapsed, client.close()


def pause_latency(job: Path) -> float:
    client = Client()
    client.start(job, 1)
    client.until("stopped")
    client.send("continue", threadId=1)
    time.sleep(0.5)
    return _timed(client, "pause")


def step_back(job: Path, line: int, after_next: bool = False) -> float:
    """Stop at ``line``, then time one stepBack (after a ``next``: back to the line seen on the way)."""
    client = Client()
    client.start(job, line)
    client.until("stopped")
    if after_next:
        client.send("next", threadId=1)
        client.until("stopped")
    return _timed(client, "stepBack")


def _timed(client: Client, command: str) -> float:
    """Seconds from sending ``command`` to the ``stopped`` event it leads to; then the session ends."""
    start = time.perf_counter()
    client.send(command, threadId=1)
    client.until("stopped")
    elapsed = time.perf_counter() - start
    client.close()
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--lines", type=int, default=200_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--before", type=Path, help="An older checkout to time alongside (PYTHONPATH).")
    parser.add_argument("--only-ratio", action="store_true", help="Leave out the pause and step-back figures.")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        job = Path(tmp) / "job.nc"
        write_job(job, args.lines)
        total = sum(1 for _ in open(job))
        never = total - 1  # "#2 = 1" inside Sub never
        sides: dict[str, dict[str, str] | None] = {"": None}
        if args.before:
            sides["before: "] = {"PYTHONPATH": str(args.before.resolve())}
        runs: dict[str, list[tuple[float, float]]] = {}
        for _ in range(args.repeat):  # alternately: the machine's load falls on both alike
            for side, env in sides.items():
                runs.setdefault(side + "run", []).append(timed_run(job, env))
                runs.setdefault(side + "debug", []).append(timed_debug(job, never, env))
        for side in sides:
            run, debug = runs[side + "run"], runs[side + "debug"]
            wall = [statistics.median(w for w, _ in r) for r in (run, debug)]
            cpu = [statistics.median(c for _, c in r) for r in (run, debug)]
            ratios = sorted(d[1] / r[1] for r, d in zip(run, debug))
            print(f"{side}{args.lines:,} lines (median of {args.repeat}): ecnc run -q {wall[0]:.2f} s wall, "
                  f"{cpu[0]:.3f} s CPU; ecnc debug (no breakpoint hit) {wall[1]:.2f} s wall, {cpu[1]:.3f} s CPU; "
                  f"ratio {wall[1] / wall[0]:.2f} wall, {cpu[1] / cpu[0]:.2f} CPU "
                  f"(CPU per round {ratios[0]:.2f}-{ratios[-1]:.2f})")
        if args.only_ratio:
            return
        big = Path(tmp) / "big.nc"
        write_job(big, 1_000_000)
        print(f"pause in a 1,000,000-line job: stopped {pause_latency(big) * 1000:.0f} ms after the request")
        print(f"step back from line {total - 3:,} (M30, stopped at by a breakpoint) of the {args.lines:,}-line "
              f"job: {step_back(job, total - 3):.2f} s; after a next from line {total - 4:,}: "
              f"{step_back(job, total - 4, after_next=True):.2f} s")


if __name__ == "__main__":
    main()
