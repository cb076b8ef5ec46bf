"""Time-true samples are made one move at a time as the sinks take them (issue 28, item 4): a
planning window of long moves is never held whole in memory."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from edingcnc_lang import RunOptions, run_string
from edingcnc_lang.motion.arc_table import ArcTable
from edingcnc_lang.motion.planner.profile import profiles, plan_nodes
from edingcnc_lang.motion.planner.samples import time_true_samples


def test_the_samples_of_a_window_come_one_move_at_a_time() -> None:
    starts = np.array([[0.0, 10.0, 20.0]] + [[0.0] * 3] * 5)
    ends = np.array([[10.0, 20.0, 30.0]] + [[0.0] * 3] * 5)
    length, accel = np.full(3, 10.0), np.full(3, 100.0)
    planned = profiles(length, np.full(3, 10.0), accel, plan_nodes(length, accel, np.zeros(4), 0.0))
    t_end = np.cumsum(planned.duration)
    calls: list[int] = []

    def joints_of(pos: np.ndarray) -> np.ndarray:
        calls.append(len(pos))
        return pos

    stream = time_true_samples(starts, ends, ArcTable(), np.arange(3), planned, t_end, planned.duration, 0.01, joints_of)
    assert calls == []  # nothing is made before it is asked for
    first = next(stream)
    assert first is not None and len(calls) == 1 and first.pos[-1][0] == 10.0
    rest = list(stream)
    assert len(rest) == 2 and len(calls) == 3 and rest[-1] is not None and rest[-1].pos[-1][0] == 30.0


def test_a_run_writes_the_same_samples_as_before(tmp_path: Path) -> None:
    out = tmp_path / "s.csv"
    run_string("G1 X10 F600\nG1 Y10\nG0 Z5\nM30\n", RunOptions(samples=out))
    rows = out.read_text().splitlines()
    times = [float(r.split(",")[0]) for r in rows[1:]]
    assert rows[0].startswith("t,x,y,z") and times == sorted(times) and len(times) > 100
    assert [float(v) for v in rows[-1].split(",")[1:4]] == [10.0, 10.0, 5.0]
