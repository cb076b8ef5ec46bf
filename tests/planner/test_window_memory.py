"""A planning window holds two rows of joints per move, however long its moves are (issue 28, item 4):
the limits report needs only a move's extremes, so the motion stage's samples are reduced to them as
the move arrives.  Memory is measured with tracemalloc (numpy reports its arrays to it), never timed."""
from __future__ import annotations

import tracemalloc
from pathlib import Path

import numpy as np
import pytest

from edingcnc_lang import RunOptions, run_file
from edingcnc_lang.canon import Move
from edingcnc_lang.config.machine_config import MachineConfig
from edingcnc_lang.motion.planner.limits_report import LimitsReport
from edingcnc_lang.motion.planner.overrides import Overrides
from edingcnc_lang.motion.planner.stage import Planner
from edingcnc_lang.motion.stage import AxisLimits, Samples

pytestmark = pytest.mark.slow  # the whole module (pyproject's slow marker)

ROOT = Path(__file__).resolve().parents[2]
MOVES = 200
ROWS = 10_000  # samples per move: the window's moves hold 200 * 10,000 * 48 bytes = 96 MB of joints unreduced
BOUND = 8 << 20  # what feeding the whole window may add at its peak (one move's samples are 1.0 MB)


def test_a_window_of_long_sampled_moves_holds_their_extremes_only() -> None:
    config = MachineConfig.default()
    planner = Planner(config, [], Overrides())
    limits = AxisLimits(np.full(6, 100.0), np.full(6, 1000.0))
    low, high = np.full(6, np.inf), np.full(6, -np.inf)
    tracemalloc.start()
    try:
        start = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        for index in range(MOVES):
            x0, x1 = float(index), float(index + 1)
            pos = np.zeros((ROWS, 6))
            pos[:, 0] = np.linspace(x0, x1, ROWS)
            joints = pos + np.sin(np.arange(ROWS) * (index + 1))[:, None]  # joints that leave the straight line
            low, high = np.minimum(low, joints.min(axis=0)), np.maximum(high, joints.max(axis=0))
            move = Move("linear", "", index + 1, (x0, 0.0, 0.0, 0.0, 0.0, 0.0), (x1, 0.0, 0.0, 0.0, 0.0, 0.0),
                        feed=60.0)
            planner.move(move, tuple(joints[-1]), Samples(np.arange(ROWS) * 0.005, pos, joints), limits)  # type: ignore[arg-type]
            del pos, joints
        peak = tracemalloc.get_traced_memory()[1] - start
    finally:
        tracemalloc.stop()
    assert len(planner._joints) == MOVES  # all of them are still in the window, not yet committed
    assert peak < BOUND, f"feeding {MOVES} moves of {ROWS} samples held {peak / 1e6:.1f} MB"
    planner.close()
    assert planner.limits.joint_low == low.tolist() and planner.limits.joint_high == high.tolist()


ROTATE_JOB = """G17 G21 G90 G64
G0 X300 Y200 Z-10
KIN ON
#1 = 0
While [#1 < 360]
  G0 X300 Y200 C#1
  G1 X340 F1200
  G2 X360 Y220 R20
  G1 Y240 C[#1 + 20]
  G3 X300 Y240 R40
  G1 Y200
  #1 = [#1 + 45]
EndWhile
KIN OFF
G0 Z0
M30
"""


def _outputs(tmp_path: Path, name: str) -> tuple[object, ...]:
    folder = tmp_path / name
    folder.mkdir()
    job = tmp_path / "job.nc"  # one job for both runs: the trace names it
    job.write_text(ROTATE_JOB)
    result = run_file(job, RunOptions(ini=ROOT / "examples/rotate/cnc.ini", trace=folder / "trace.csv",
                                      samples=folder / "samples.csv"))
    return (result.limits, result.estimate.to_json() if result.estimate else None,
            (folder / "trace.csv").read_text(), (folder / "samples.csv").read_text())


def test_the_reduced_window_gives_the_same_outputs_as_every_sample(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    """A sampled kinematics job (rotate: the joints turn with C) gives the same trace, samples, limits
    report and times whether the window keeps every sample (as before) or their extremes."""
    reduced = _outputs(tmp_path, "reduced")
    monkeypatch.setattr(LimitsReport, "joint_extremes", staticmethod(lambda joints: joints))
    whole = _outputs(tmp_path, "whole")
    assert reduced == whole
    limits = reduced[0]
    assert isinstance(limits, dict) and limits["joints"]["x"]["max"] > 340  # the rotated arcs reach past X340
