"""The cost of the debugger: a 200,000-line job run under ``ecnc debug`` with a breakpoint that is
never hit, against ``ecnc run`` of the same job (issue 24's target: at most 2x); the time a
``pause`` takes to stop a 1,000,000-line job; and one step back near the end of the job (from a
breakpoint: a search re-run first; after a step: the way back only).

    python benchmarks/bench_debug.py [--lines 200000] [--repeat 3]

Each figure is the median of ``--repeat`` runs of a fresh process (start-up included on both sides).
"""
from __future__ import annotations

import argparse
import json
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


class Client:
    def __init__(self) -> None:
        self.proc = subprocess.Popen([sys.executable, "-m", "edingcnc_lang", "debug"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE)
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

    def close(self) -> None:
        self.send("disconnect")
        self.proc.communicate()


def timed_run(job: Path) -> float:
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "edingcnc_lang", "run", "-q", str(job)], check=True)
    return time.perf_counter() - start


def timed_debug(job: Path, never_line: int) -> float:
    start = time.perf_counter()
    client = Client()
    client.start(job, never_line)  # the breakpoint is in a sub nobody calls
    client.until("exited")
    elapsed = time.perf_counter() - start
    client.close()
    return elapsed


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
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        job = Path(tmp) / "job.nc"
        write_job(job, args.lines)
        total = sum(1 for _ in open(job))
        never = total - 1  # "#2 = 1" inside Sub never
        runs = [timed_run(job) for _ in range(args.repeat)]
        debugs = [timed_debug(job, never) for _ in range(args.repeat)]
        run, debug = statistics.median(runs), statistics.median(debugs)
        print(f"{args.lines:,} lines: ecnc run {run:.2f} s, ecnc debug (no breakpoint hit) {debug:.2f} s, "
              f"ratio {debug / run:.2f}")
        big = Path(tmp) / "big.nc"
        write_job(big, 1_000_000)
        print(f"pause in a 1,000,000-line job: stopped {pause_latency(big) * 1000:.0f} ms after the request")
        print(f"step back from line {total - 3:,} (M30, stopped at by a breakpoint) of the {args.lines:,}-line "
              f"job: {step_back(job, total - 3):.2f} s; after a next from line {total - 4:,}: "
              f"{step_back(job, total - 4, after_next=True):.2f} s")


if __name__ == "__main__":
    main()
