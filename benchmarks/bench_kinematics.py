"""Inverse-kinematics throughput of deltakins on 1,000,000 samples (the seed's robot, L = 250, R = 125).

Three ways the motion stage can evaluate a plug-in on the samples of a move:
- vectorised: one ``inverse_many`` call on the whole (N, 6) array (what deltakins offers);
- scalar plug-in path: the ``KinematicsPlugin.inverse_many`` fallback, one ``inverse`` call per
  sample (what a plug-in that only writes the scalar function gets), timed on the first
  SCALAR_SAMPLES poses only: it is three orders of magnitude slower;
- vectorised in moves of 200 samples (one second of motion at 5 ms), as a job evaluates it.

The poses are random points inside the reach (fixed seed).  Each case runs REPEAT times and the
best time is reported: on a shared machine the other runs measure the neighbours (the first run
also pays the page faults of fresh memory).  Prints a table of samples/s.

    PYTHONPATH=. python3 benchmarks/bench_kinematics.py [SAMPLES]
"""
from __future__ import annotations

import sys
import time
from collections.abc import Callable

import numpy as np

from edingcnc_lang.kinematics.base import KinematicsPlugin
from edingcnc_lang.kinematics.shipped import import_shipped

SEED = 20240501
MOVE = 200  # samples in one second of motion at the default 5 ms interpolation time
REPEAT = 3
SCALAR_SAMPLES = 20_000


def poses(count: int) -> np.ndarray:
    """Random reachable poses: within 90 mm of the centre, Z 0 .. 200."""
    rng = np.random.default_rng(SEED)
    radius, angle = 90.0 * np.sqrt(rng.random(count)), rng.random(count) * 2 * np.pi
    rows = np.zeros((count, 6))
    rows[:, 0], rows[:, 1], rows[:, 2] = radius * np.cos(angle), radius * np.sin(angle), rng.random(count) * 200
    return rows


def timed(run: Callable[[], np.ndarray]) -> tuple[float, np.ndarray]:
    """The best of REPEAT runs, and the result."""
    best = float("inf")
    for _ in range(REPEAT):
        start = time.perf_counter()
        result = run()
        best = min(best, time.perf_counter() - start)
    return best, result


def main(count: int) -> None:
    kins = import_shipped("deltakins").DeltaKins({"lindeltaradius": "125", "lindeltaarmlength": "250"})
    rows = poses(count)
    scalar_rows = rows[:SCALAR_SAMPLES]
    cases: list[tuple[str, np.ndarray, Callable[[], np.ndarray]]] = [
        ("vectorised (one call)", rows, lambda: kins.inverse_many(rows)),
        (f"vectorised ({MOVE} per move)", rows, lambda: np.concatenate([kins.inverse_many(rows[i:i + MOVE])
                                                                        for i in range(0, count, MOVE)])),
        ("scalar plug-in path", scalar_rows, lambda: KinematicsPlugin.inverse_many(kins, scalar_rows)),
    ]
    reference = None
    print(f"deltakins inverse kinematics, {count:,} samples (scalar path: the first {len(scalar_rows):,}); "
          f"best of {REPEAT}")
    print(f"{'path':<28}{'seconds':>10}{'samples/s':>16}")
    for label, batch, run in cases:
        seconds, joints = timed(run)
        if reference is None:
            reference = joints
        assert np.allclose(joints, reference[:len(batch)], rtol=0, atol=1e-9), label
        print(f"{label:<28}{seconds:>10.3f}{len(batch) / seconds:>16,.0f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
