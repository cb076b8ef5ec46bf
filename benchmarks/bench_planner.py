"""What the motion planner adds to ``ecnc run``: a 200,000-move job, planning time against the rest.

The target (issue 13) is that planning adds at most 25 % to a run.  This times the planner stage's
own calls inside ``run_file`` (the wrapper costs less than a microsecond per call, and the fast path
calls it once per batch of lines) and reports them against everything else, as the median of
``--repeat`` runs in fresh processes; and, directly, the same run with ``RunOptions(plan=False)``
(no planner at all), the two alternating.  It also times the planner alone on the same moves.

    python benchmarks/bench_planner.py [--moves 200000] [--repeat 5]
"""
from __future__ import annotations

import argparse
import json
import random
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from bench_run import write_g1_job

CHILD = r"""
import json, sys, time
from edingcnc_lang.motion.planner import stage
from edingcnc_lang import RunOptions, run_file
spent = [0.0]
def timed(name):
    original = getattr(stage.Planner, name)
    def call(self, *args, **kwargs):
        start = time.perf_counter()
        try:
            return original(self, *args, **kwargs)
        finally:
            spent[0] += time.perf_counter() - start
    setattr(stage.Planner, name, call)
for name in ("move", "move_batch", "event", "flush", "close"):
    timed(name)
import numpy  # loaded by the first planned window in a normal run; loaded here so it is not counted
start = time.perf_counter()
result = run_file(sys.argv[1], RunOptions(plan=sys.argv[2] == "plan"))
total = time.perf_counter() - start
print(json.dumps({"total": total, "planner": spent[0], "seconds": result.estimate.seconds if result.estimate else 0}))
"""

ALONE = r"""
import random, sys, time
import numpy as np
from edingcnc_lang.canon import Batch
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.motion.stage import AxisLimits
from edingcnc_lang.motion.planner.overrides import Overrides
from edingcnc_lang.motion.planner.stage import Planner
count = int(sys.argv[1])
rng = random.Random(1)
limits = AxisLimits(np.full(6, 1000.0), np.full(6, 10000.0))
ends = [(rng.uniform(0, 300), rng.uniform(0, 200), rng.uniform(-5, 0), 0.0, 0.0, 0.0) for i in range(count)]
planner = Planner(MachineConfig.default(), [], Overrides())
start = time.perf_counter()
for first in range(0, count, 500):
    part = ends[first:first + 500]
    planner.move_batch(Batch("job", (0.0,) * 6 if not first else ends[first - 1], ["linear"] * len(part),
                                 list(range(first, first + len(part))), part, [1000.0] * len(part)),
                           {"rapid": limits, "linear": limits})
planner.close()
print(time.perf_counter() - start)
"""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--moves", type=int, default=200_000)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        job = Path(folder) / "job.nc"
        write_g1_job(job, args.moves)
        def child(mode: str) -> dict[str, float]:
            return json.loads(subprocess.run([sys.executable, "-c", CHILD, str(job), mode], capture_output=True,
                                             text=True, check=True).stdout)

        pairs = [(child("plan"), child("noplan")) for _ in range(args.repeat)]
        runs = [planned for planned, _ in pairs]
        unplanned = statistics.median(r["total"] for _, r in pairs)
        alone = [float(subprocess.run([sys.executable, "-c", ALONE, str(args.moves)], capture_output=True, text=True,
                                      check=True).stdout) for _ in range(args.repeat)]
    share = [r["planner"] / (r["total"] - r["planner"]) for r in runs]
    total = statistics.median(r["total"] for r in runs)
    planning = statistics.median(r["planner"] for r in runs)
    rows = [
        ("benchmark", "figure", "target"),
        (f"ecnc run, {args.moves:,} G1 moves (in process, median of {args.repeat})", f"{total:.2f} s", ""),
        ("  of which planning", f"{planning:.2f} s", ""),
        ("  planning added to the rest of the run", f"{statistics.median(share) * 100:.1f} % "
         f"({min(share) * 100:.1f}-{max(share) * 100:.1f} %)", "<= 25 %"),
        ("the same run with RunOptions(plan=False)", f"{unplanned:.2f} s", ""),
        ("  planned run over it", f"{(total / unplanned - 1) * 100:.1f} %", "<= 25 %"),
        ("planner alone, same moves", f"{args.moves / statistics.median(alone) / 1e6:.2f} M moves/s", ""),
        ("estimated job time", f"{runs[0]['seconds'] / 3600:.1f} h", ""),
    ]
    width = max(len(row[0]) for row in rows)
    for name, figure, target in rows:
        print(f"{name:<{width}}  {figure:<22} {target}")


if __name__ == "__main__":
    random.seed(0)
    main()
